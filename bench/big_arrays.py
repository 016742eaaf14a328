"""A 100 000-point hysteresis request end to end, in-process, against pma_core alone.

``.venv/bin/python -m bench.big_arrays [--points N] [--repeat R]``

The request is driven straight into the ASGI app (no socket, no HTTP client): the time is
from the request to the last response byte, i.e. body parsing and validation, the model,
orjson, the middleware (GZip when the client accepts it) and nothing of the client. The
baseline computes the same arrays with ``hysteresis_curves`` (and the degrees conversion
the endpoint does). Target: end to end within 3x of the baseline, for each form of the
answer: JSON, JSON with ``Accept-Encoding: gzip``, and the binary ``.npy`` forms
(``?format=npy``, a table of rows; ``?format=npy-record``, a record of whole curves).

Subject and baseline are timed in pairs: each of ``--rounds`` rounds takes the best of
``--repeat`` runs of the baseline and then of each request, and the figure is the median
over rounds of the per-round ratio, so a slow stretch of the machine hits both sides of a
ratio alike (the gzip request, seconds long, is timed in fewer rounds).

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
import statistics
import time
from collections.abc import Awaitable, Callable, Sequence
from typing import Any

import numpy as np
import orjson

from app.responses import npy_record, npy_table
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
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        await call()
        times.append(time.perf_counter() - start)
    return min(times)


def _gzip_seconds(raw: bytes, level: int, repeat: int) -> tuple[float, int]:
    size = len(gzip.compress(raw, compresslevel=level))
    return best_of(lambda: gzip.compress(raw, compresslevel=level), number=1, repeat=repeat), size


async def _measure(app: Any, points: int, rounds: int, repeat: int) -> dict[str, Any]:
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
    npy_path = PATH + "?format=npy-record"
    table_path = PATH + "?format=npy"
    npy = await asgi_request(app, "POST", npy_path, body, gzipped)
    curves = np.load(io.BytesIO(npy.body)) if npy.status == 200 else None
    if curves is None or curves["force_static_n"].tolist() != decoded["force_static_n"]:
        raise SystemExit(f"{npy_path} answered {npy.status} or the wrong number of rows")
    requests: dict[str, Callable[[], Awaitable[AsgiResponse]]] = {
        "npy": lambda: asgi_request(app, "POST", npy_path, body, gzipped),
        "table": lambda: asgi_request(app, "POST", table_path, body, gzipped),
        "raw": lambda: asgi_request(app, "POST", PATH, body, plain),
        "gzip": lambda: asgi_request(app, "POST", PATH, body, gzipped),
    }
    times: dict[str, list[float]] = {name: [] for name in ("core", *requests)}
    ratios: dict[str, list[float]] = {name: [] for name in requests}
    for round_ in range(rounds):
        core = best_of(lambda: compute(points), number=1, repeat=repeat)
        times["core"].append(core)
        for name, call in requests.items():
            if name == "gzip" and round_ % 3:
                continue  # seconds per run: one round in three
            await call()
            seconds = await _best(call, repeat if name != "gzip" else 2)
            times[name].append(seconds)
            ratios[name].append(seconds / core)
    return {"raw": raw, "packed": packed, "npy": npy, "times": times, "ratios": ratios}


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.big_arrays", description=__doc__)
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument("--repeat", type=int, default=7, help="runs per round; best taken")
    parser.add_argument(
        "--default-allocator",
        action="store_true",
        help="do not apply app.server.tune_allocator() (the service applies it)",
    )
    args = parser.parse_args(argv)
    points, rounds, repeat = args.points, args.rounds, args.repeat
    if not args.default_allocator:
        tune_allocator()
    header(
        f"big arrays: POST {PATH} with {points:,} points, in-process (ASGI, no socket)",
        "server side only: request in -> last response byte out; paired rounds: in each of"
        f" {rounds}, best of {repeat} runs of pma_core then of each request (gzip: best of 2,"
        " one round in three); medians over rounds of the per-round ratio",
        "allocator: "
        + (
            "glibc default (--default-allocator)"
            if args.default_allocator
            else "app.server.tune_allocator(), as pma-calculator serve"
        ),
    )
    from app.main import app

    compute(points)
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    for _ in range(5):
        compute(points)
    faults = (resource.getrusage(resource.RUSAGE_SELF).ru_minflt - faults) // 5
    content = {"s_scale": 18.1, "min_braid_angle_deg": 19.0, **compute(points)}
    t_orjson = best_of(
        lambda: orjson.dumps(content, option=orjson.OPT_SERIALIZE_NUMPY), number=1, repeat=repeat
    )
    columns = content_columns(content)
    t_npy_file = best_of(lambda: npy_record(columns), number=1, repeat=repeat)
    t_npy_table = best_of(lambda: npy_table(columns), number=1, repeat=repeat)
    measured = asyncio.run(_measure(app, points, rounds, repeat))
    raw: AsgiResponse = measured["raw"]
    packed: AsgiResponse = measured["packed"]
    npy: AsgiResponse = measured["npy"]
    times, ratios = measured["times"], measured["ratios"]
    levels = {level: _gzip_seconds(raw.body, level, max(3, repeat // 3)) for level in (1, 6, 9)}

    table = Table()
    table.add("pma_core alone (baseline)", f"{_ms(times['core'])} ({faults} page faults/call)")
    for name, label in (
        ("raw", "JSON"),
        ("gzip", "JSON, Accept-Encoding: gzip"),
        ("table", "?format=npy (table of rows)"),
        ("npy", "?format=npy-record"),
    ):
        ratio = statistics.median(ratios[name])
        table.add(f"end to end, {label}", _ms(times[name]))
        table.add(
            f"  {label} / baseline",
            f"{ratio:.{1 if ratio < 10 else 0}f}x (rounds {min(ratios[name]):.2f}"
            f"-{max(ratios[name]):.2f})",
            f"<= {TARGET:g}x",
            ratio <= TARGET,
        )
    table.add("response size, JSON", f"{len(raw.body) / 1e6:.2f} MB ({len(raw.body):,} B)")
    table.add("response size, npy", f"{len(npy.body) / 1e6:.2f} MB ({len(npy.body):,} B)")
    table.add(
        "response size, JSON gzip",
        f"{len(packed.body) / 1e6:.2f} MB ({len(packed.body):,} B),"
        f" {len(raw.body) / len(packed.body):.2f}x smaller",
    )
    table.add("bytes per number (JSON)", f"{len(raw.body) / (7 * points):.1f}")
    table.print()

    print("breakdown (each part alone, same data, best of runs):")
    parts = Table()
    parts.add("orjson.dumps of the 7 arrays", f"{t_orjson * 1e3:.1f} ms")
    parts.add("npy_record of the 7 arrays (header + buffers joined)", f"{t_npy_file * 1e3:.2f} ms")
    parts.add("npy_table of the 7 arrays (rows interleaved)", f"{t_npy_table * 1e3:.2f} ms")
    for level, (seconds, size) in levels.items():
        parts.add(
            f"gzip level {level} of the JSON body",
            f"{seconds * 1e3:.0f} ms -> {size / 1e6:.2f} MB",
        )
    parts.print()
    return 0


def content_columns(content: dict[str, Any]) -> dict[str, Any]:
    """The array entries of a hysteresis answer."""
    return {name: value for name, value in content.items() if isinstance(value, np.ndarray)}


def _ms(samples: list[float]) -> str:
    return f"{statistics.median(samples) * 1e3:.2f} ms (rounds {min(samples) * 1e3:.2f}-" + (
        f"{max(samples) * 1e3:.2f})"
    )


if __name__ == "__main__":
    raise SystemExit(main())
