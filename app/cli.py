"""Command-line entry point ``pma-calculator``."""

from __future__ import annotations

import argparse
from collections.abc import Sequence

import uvicorn

from app.cli_report import add_report_parser
from app.logs import log_config
from app.server import enable_tcp_nodelay_for_workers, tune_allocator
from app.settings import LOG_LEVELS, Settings

#: uvicorn's loop setting for several workers (an import string of a loop factory).
FAIR_ACCEPT_LOOP = "app.server:FairAcceptEventLoop"


def _serve(args: argparse.Namespace) -> int:
    tune_allocator()
    several = args.workers > 1 and not args.reload
    if several:
        enable_tcp_nodelay_for_workers()
    uvicorn.run(
        "app.main:app",
        host=args.host,
        port=args.port,
        workers=None if args.reload else args.workers,
        reload=args.reload,
        log_level=args.log_level,
        log_config=log_config(args.log_level),
        access_log=False,  # app.middleware logs each request as JSON, with its id
        root_path=args.root_path,
        proxy_headers=True,
        # Several workers share one listener: each takes one connection per wake-up.
        loop=FAIR_ACCEPT_LOOP if several else "auto",
    )
    return 0


def build_parser() -> argparse.ArgumentParser:
    """Return the argument parser; defaults come from the ``PMA_*`` environment."""
    env = Settings.from_env()
    parser = argparse.ArgumentParser(
        prog="pma-calculator",
        description="Braided pneumatic muscle calculator (Davis & Caldwell 2006).",
    )
    commands = parser.add_subparsers(dest="command", required=True)
    serve = commands.add_parser("serve", help="run the web calculator and HTTP API")
    serve.add_argument("--host", default=env.host, help="interface to bind (PMA_HOST)")
    serve.add_argument("--port", type=int, default=env.port, help="TCP port (PMA_PORT)")
    serve.add_argument("--workers", type=int, default=env.workers, help="processes (PMA_WORKERS)")
    serve.add_argument("--log-level", default=env.log_level, choices=LOG_LEVELS)
    serve.add_argument("--root-path", default=env.root_path, help="proxy prefix (PMA_ROOT_PATH)")
    serve.add_argument("--reload", action="store_true", help="restart on code changes (dev)")
    serve.set_defaults(handler=_serve)
    add_report_parser(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``pma-calculator``."""
    args = build_parser().parse_args(argv)
    handler = args.handler
    result: int = handler(args)
    return result
