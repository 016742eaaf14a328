"""A 100 000-point hysteresis request end to end, in-process, against pma_core alone.

``.venv/bin/python -m bench.big_arrays [--points N] [--repeat R]``

The request is driven straight into the ASGI app (no socket, no HTTP client): the time is
from the request to the last response byte, i.e. body parsing and validation, the model,
orjson, the middleware (GZip when the client accepts it) and nothing of the client. The
baseline computes the same arrays with ``hysteresis_curves`` (and the degrees conversion
the endpoint does). Target: end to end within 3x of the baseline, without and with
``Accept-Encoding: gzip``. Best of ``--repeat`` runs each.

The process is tuned like the service (``app.server.tune_allocator()``, which
``pma-calculator serve`` applies) before anything is measured, so subject and baseline run
with the deployed allocator settings; ``--default-allocator`` skips that (the before).

The breakdown rows time the response's parts on their own (orjson on the same dict; gzip of
the same bytes at levels 1, 6 and 9; the app's GZipMiddleware uses 1, Starlette's default
is 9) to show where the time goes. GZipMiddleware compresses bodies of 128 KiB and more in
a worker thread, so the event loop is not blocked, but a core is busy meanwhile.
"""

from __future__ import annotations

import argparse
import asyncio
import gzip
import io
import json
import resource
import time
from collections.abc import Awaitable, Callable, Sequence
from typing import Any

import numpy as np
import orjson

from app.routes.calculations import curve_columns
from app.server import tune_allocator
from bench._common import (
    PAPER_MUSCLE_ARGS,
    PAPER_MUSCLE_BODY,
    AsgiResponse,
    Table,
    asgi_request,
    best_of,
    header,
)
from pma_core.hysteresis import hysteresis_curves

TARGET = 3.0
PATH = "/api/v1/hysteresis"


def compute(points: int) -> dict[str, Any]:
    """The baseline: the arrays the endpoint returns, computed by pma_core alone."""
    return curve_columns(hysteresis_curves(*PAPER_MUSCLE_ARGS, points=points))


async def _best(call: Callable[[], Awaitable[AsgiResponse]], repeat: int) -> float:
    await call()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        await call()
        times.append(time.perf_counter() - start)
    return min(times)


def _gzip_seconds(raw: bytes, level: int, repeat: int) -> tuple[float, int]:
    size = len(gzip.compress(raw, compresslevel=level))
    return best_of(lambda: gzip.compress(raw, compresslevel=level), number=1, repeat=repeat), size


async def _measure(app: Any, points: int, repeat: int) -> dict[str, Any]:
    body = json.dumps({**PAPER_MUSCLE_BODY, "points": points}).encode()
    plain: Sequence[tuple[str, str]] = [("content-type", "application/json")]
    gzipped = [*plain, ("accept-encoding", "gzip")]
    raw = await asgi_request(app, "POST", PATH, body, plain)
    packed = await asgi_request(app, "POST", PATH, body, gzipped)
    if raw.status != 200 or packed.status != 200:
        raise SystemExit(f"{PATH} answered {raw.status}/{packed.status}: {raw.body[:300]!r}")
    if packed.headers.get("content-encoding") != "gzip":
        raise SystemExit("the gzip request was not compressed: is GZipMiddleware installed?")
    if gzip.decompress(packed.body) != raw.body:
        raise SystemExit("gzip body differs from the identity body")
    decoded = orjson.loads(raw.body)
    if len(decoded["force_static_n"]) != points:
        raise SystemExit(f"expected {points} points, got {len(decoded['force_static_n'])}")
    npy_path = PATH + "?format=npy"
    npy = await asgi_request(app, "POST", npy_path, body, gzipped)
    if npy.status != 200 or len(np.load(io.BytesIO(npy.body))) != points:
        raise SystemExit(f"{npy_path} answered {npy.status} or the wrong number of rows")
    # The gzip runs are slow (seconds): fewer of them.
    gzip_repeat = max(3, repeat // 3)
    return {
        "raw": raw,
        "packed": packed,
        "npy": npy,
        "t_npy": await _best(lambda: asgi_request(app, "POST", npy_path, body, gzipped), repeat),
        "t_raw": await _best(lambda: asgi_request(app, "POST", PATH, body, plain), repeat),
        "t_gzip": await _best(lambda: asgi_request(app, "POST", PATH, body, gzipped), gzip_repeat),
        "gzip_repeat": gzip_repeat,
    }


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.big_arrays", description=__doc__)
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument(
        "--default-allocator",
        action="store_true",
        help="do not apply app.server.tune_allocator() (the service applies it)",
    )
    args = parser.parse_args(argv)
    points, repeat = args.points, args.repeat
    if not args.default_allocator:
        tune_allocator()
    header(
        f"big arrays: POST {PATH} with {points:,} points, in-process (ASGI, no socket)",
        "server side only: request in -> last response byte out; best of"
        f" {repeat} runs (gzip: best of {max(3, repeat // 3)})",
        "allocator: "
        + (
            "glibc default (--default-allocator)"
            if args.default_allocator
            else "app.server.tune_allocator(), as pma-calculator serve"
        ),
    )
    from app.main import app

    t_core = best_of(lambda: compute(points), number=3, repeat=repeat)
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    for _ in range(5):
        compute(points)
    faults = (resource.getrusage(resource.RUSAGE_SELF).ru_minflt - faults) // 5
    content = {"s_scale": 18.1, "min_braid_angle_deg": 19.0, **compute(points)}
    t_orjson = best_of(
        lambda: orjson.dumps(content, option=orjson.OPT_SERIALIZE_NUMPY), number=1, repeat=repeat
    )
    measured = asyncio.run(_measure(app, points, repeat))
    raw: AsgiResponse = measured["raw"]
    packed: AsgiResponse = measured["packed"]
    t_raw, t_gzip = measured["t_raw"], measured["t_gzip"]
    levels = {level: _gzip_seconds(raw.body, level, max(3, repeat // 5)) for level in (1, 6, 9)}

    table = Table()
    table.add("pma_core alone (baseline)", f"{t_core * 1e3:.2f} ms ({faults} page faults/call)")
    table.add("end to end, identity", f"{t_raw * 1e3:.1f} ms")
    table.add("end to end, Accept-Encoding: gzip", f"{t_gzip * 1e3:.0f} ms")
    table.add(
        "identity / baseline", f"{t_raw / t_core:.1f}x", f"<= {TARGET:g}x", t_raw / t_core <= TARGET
    )
    table.add(
        "gzip / baseline", f"{t_gzip / t_core:.0f}x", f"<= {TARGET:g}x", t_gzip / t_core <= TARGET
    )
    t_npy, npy = measured["t_npy"], measured["npy"]
    table.add("end to end, ?format=npy (binary)", f"{t_npy * 1e3:.1f} ms")
    table.add(
        "npy / baseline", f"{t_npy / t_core:.1f}x", f"<= {TARGET:g}x", t_npy / t_core <= TARGET
    )
    table.add("response size, identity", f"{len(raw.body) / 1e6:.2f} MB ({len(raw.body):,} B)")
    table.add("response size, npy", f"{len(npy.body) / 1e6:.2f} MB ({len(npy.body):,} B)")
    table.add(
        "response size, gzip",
        f"{len(packed.body) / 1e6:.2f} MB ({len(packed.body):,} B),"
        f" {len(raw.body) / len(packed.body):.2f}x smaller",
    )
    table.add("bytes per number (identity)", f"{len(raw.body) / (7 * points):.1f}")
    table.print()

    print("breakdown (each part alone, same data):")
    parts = Table()
    parts.add("orjson.dumps of the 7 arrays", f"{t_orjson * 1e3:.1f} ms")
    for level, (seconds, size) in levels.items():
        parts.add(
            f"gzip level {level} of the identity body",
            f"{seconds * 1e3:.0f} ms -> {size / 1e6:.2f} MB",
        )
    parts.add(
        "rest of identity request",
        f"{(t_raw - t_core - t_orjson) * 1e3:.1f} ms (validation, routing, middleware, copies)",
    )
    parts.print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
