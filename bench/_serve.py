"""Any ASGI app served with the process settings of ``pma-calculator serve``.

``python -m bench._serve MODULE:APP --port N [--workers W] [--log-level L] [--factory]``

``pma-calculator serve`` (app/cli.py) serves only ``app.main:app``. The benchmarks' other
apps (the constant-endpoint baseline, the page benchmark's app) run through this entry
point, so they get what the service gets before uvicorn starts: ``tune_allocator()``
always and ``enable_tcp_nodelay_for_workers()`` when ``--workers`` > 1 (app.server), and
the same ``uvicorn.run`` settings (JSON log config, no access log, proxy headers).
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

import uvicorn

from app.logs import log_config
from app.server import enable_tcp_nodelay_for_workers, tune_allocator
from app.settings import LOG_LEVELS


def main(argv: Sequence[str] | None = None) -> int:
    """Tune the process like ``pma-calculator serve`` does, then run uvicorn."""
    parser = argparse.ArgumentParser(prog="python -m bench._serve", description=__doc__)
    parser.add_argument("app", help="MODULE:ATTRIBUTE")
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, required=True)
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--log-level", default="warning", choices=LOG_LEVELS)
    parser.add_argument("--factory", action="store_true")
    args = parser.parse_args(argv)
    tune_allocator()
    if args.workers > 1:
        enable_tcp_nodelay_for_workers()
    uvicorn.run(
        args.app,
        host=args.host,
        port=args.port,
        workers=args.workers,
        factory=args.factory,
        log_level=args.log_level,
        log_config=log_config(args.log_level),
        access_log=False,
        proxy_headers=True,
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
