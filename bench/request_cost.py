"""Where a scalar request's time goes, in-process: the diagnosis behind bench.service_scalar.

``.venv/bin/python -m bench.request_cost [--calls N] [--repeat R]``

Microseconds per POST /api/v1/min-braid-angle (the paper's braid), driven straight into the
ASGI app (no socket, no uvicorn, no HTTP parsing), against the same for the baseline app's
constant endpoint, and the parts on their own:

- the full calculator app (all middleware);
- the calculations router alone in a bare FastAPI app (no middleware);
- body parsing and validation (pydantic ``model_validate_json``);
- the pma_core call the endpoint makes (``braid.braid_limits``, theta_min validated once);
- the same numbers from one validated ``min_braid_angle`` call and ``math`` (the floor).

Best of ``--repeat`` runs of ``--calls`` calls. No target: this explains the HTTP figure.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import math
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from fastapi import FastAPI

from bench._common import PAPER_BRAID_BODY, Table, asgi_request, best_of, header
from pma_core import braid
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD

BODY = json.dumps(PAPER_BRAID_BODY).encode()
HEADERS = [("content-type", "application/json")]
ARGS = (
    PAPER_BRAID_BODY["strand_diameter_m"],
    PAPER_BRAID_BODY["strand_count"],
    PAPER_BRAID_BODY["theoretical_diameter_m"],
)


def core_as_the_route_does() -> dict[str, float]:
    """The endpoint's pma_core work, call for call (one ``braid_limits``, no strand length)."""
    limits = braid.braid_limits(*ARGS, None)
    return {
        "min_braid_angle_deg": float(np.degrees(limits.min_braid_angle_rad)),
        "max_braid_angle_deg": float(np.degrees(limits.max_braid_angle_rad)),
        "jamming_angle_deg": float(np.degrees(limits.jamming_angle_rad)),
        "max_contraction": float(limits.max_contraction),
    }


def core_once() -> dict[str, float]:
    """The same numbers from one validated theta_min and ``math``: the floor of that work."""
    theta_min = float(braid.min_braid_angle(*ARGS))
    jamming = math.pi / 2 - theta_min
    theta_max = min(NEUTRAL_BRAID_ANGLE_RAD, jamming)
    return {
        "min_braid_angle_deg": math.degrees(theta_min),
        "max_braid_angle_deg": math.degrees(theta_max),
        "jamming_angle_deg": math.degrees(jamming),
        "max_contraction": 1.0 - math.cos(theta_max) / math.cos(theta_min),
    }


def _router_only_app() -> FastAPI:
    from app.errors import install_error_handlers
    from app.responses import JSONResponse
    from app.routes import calculations

    app = FastAPI(default_response_class=JSONResponse, docs_url=None, redoc_url=None)
    install_error_handlers(app)
    app.include_router(calculations.router)
    return app


def _asgi_us(app: Any, path: str, calls: int, repeat: int) -> float:
    async def run() -> float:
        first = await asgi_request(app, "POST", path, BODY, HEADERS)
        if first.status != 200:
            raise SystemExit(f"{path} answered {first.status}: {first.body[:200]!r}")
        best = math.inf
        for _ in range(repeat):
            start = time.perf_counter()
            for _ in range(calls):
                await asgi_request(app, "POST", path, BODY, HEADERS)
            best = min(best, (time.perf_counter() - start) / calls)
        return best

    return asyncio.run(run()) * 1e6


def _us(fn: Callable[[], object], calls: int, repeat: int) -> float:
    return best_of(fn, number=calls, repeat=repeat) * 1e6


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.request_cost", description=__doc__)
    parser.add_argument("--calls", type=int, default=2000)
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args(argv)
    calls, repeat = args.calls, args.repeat
    header(
        "request cost: POST /api/v1/min-braid-angle in-process, by part",
        f"best of {repeat} runs of {calls} calls; ASGI app called directly (no socket)",
    )
    from app.main import app
    from app.schemas import MinBraidAngleIn
    from bench.baseline_app import app as baseline

    route, once = core_as_the_route_does(), core_once()
    for key, value in route.items():
        if not math.isclose(value, once[key], rel_tol=1e-12):
            raise SystemExit(f"core_once differs from the route on {key}: {once[key]} {value}")

    base = _asgi_us(baseline, "/baseline", calls, repeat)
    full = _asgi_us(app, "/api/v1/min-braid-angle", calls, repeat)
    bare = _asgi_us(_router_only_app(), "/api/v1/min-braid-angle", calls, repeat)
    parse = _us(lambda: MinBraidAngleIn.model_validate_json(BODY), calls, repeat)
    core = _us(core_as_the_route_does, calls, repeat)
    core1 = _us(core_once, calls, repeat)

    table = Table()
    table.add("baseline app, constant endpoint", f"{base:.0f} us")
    table.add("calculator app, full", f"{full:.0f} us ({full / base:.1f}x baseline)")
    table.add("calculations router alone, no middleware", f"{bare:.0f} us")
    table.add("  -> middleware stack", f"{full - bare:.0f} us")
    table.add("body parse + validation (pydantic)", f"{parse:.1f} us")
    table.add("pma_core call as the route makes it (braid_limits)", f"{core:.0f} us")
    table.add(
        "same numbers from one min_braid_angle + math",
        f"{core1:.0f} us (would save {core - core1:.0f} us)",
    )
    table.print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
