"""A bounded soak of every endpoint on 127.0.0.1: errors and memory growth.

``.venv/bin/python -m bench.soak [--seconds 60] [--connections 64] [--warmup W]``

The service as deployed (``pma-calculator serve --workers 1``, which applies app.server's
tune_allocator) pinned to CPU 0; wrk
pinned to CPU 1 cycles through a fixed, shuffled schedule of requests over every endpoint:
the five calculations, the design report, both sweeps, materials, reference, healthz, the
page's 201-point hysteresis and, 2 % of the time, a 100 000-point hysteresis (13 MB of
JSON). Before the soak every request of the mix is sent once and must answer 200.

wrk runs for ``--seconds`` and stops by itself. Meanwhile the server's RSS is read from
/proc/<pid>/status (VmRSS) every second. Targets: zero errors (socket errors, timeouts,
non-2xx answers, and tracebacks in the server's log), and RSS at the end (median of the last
``--window`` samples) no more than 5 % above RSS after warm-up (median of the ``--window``
samples from ``--warmup`` seconds on). Medians over windows, because each 100 000-point
answer lifts RSS by tens of MB for a moment. The growth of the windows' minima (the RSS
floor between big answers) is judged too: a leak lifts the floor, a transient does not.
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import tempfile
import threading
import time
import urllib.request
from pathlib import Path
from typing import Any

from bench._common import (
    PAPER_BRAID_BODY,
    PAPER_MUSCLE_BODY,
    Table,
    WrkResult,
    header,
    loop_and_http,
    post_json,
    rss_kib,
    run_wrk,
    uvicorn_server,
)

GROWTH_TARGET = 0.05
SERVER_CPU = "0"
WRK_CPU = "1"

_DIAMETER = {"theoretical_diameter_m": 0.031, "strand_diameter_m": 0.00025}
_MATERIAL = {"youngs_modulus_pa": 3e9, "poisson_ratio": 0.4}

_SWEPT_MUSCLE = {k: v for k, v in PAPER_MUSCLE_BODY.items() if k not in ("pressure_pa", "s_scale")}
_OPENSIM_FIELDS = ("strand_length_m", "turns", "strand_diameter_m", "strand_count")

#: (weight in %, method, path, body): the soak's mix, every endpoint.
MIX: list[tuple[int, str, str, dict[str, Any] | None]] = [
    (12, "POST", "/api/v1/min-braid-angle", PAPER_BRAID_BODY),
    (11, "POST", "/api/v1/gap-area", {**PAPER_BRAID_BODY, "parallel_strands": 3}),
    (
        11,
        "POST",
        "/api/v1/failure-strand-count",
        {**_DIAMETER, "pressure_pa": 500_000.0, "tensile_strength_pa": 75e6},
    ),
    (
        11,
        "POST",
        "/api/v1/s-scale",
        {"strand_diameter_m": 0.00025, "pressure_pa": 200_000.0, **_MATERIAL},
    ),
    (
        11,
        "POST",
        "/api/v1/design",
        {**PAPER_BRAID_BODY, "parallel_strands": 3, "pressure_pa": 200_000.0, "material": "nylon"},
    ),
    (
        8,
        "POST",
        "/api/v1/sweeps/strand-count",
        {**_DIAMETER, "parallel_strands": 3, "strand_count_min": 2, "strand_count_max": 480},
    ),
    (
        8,
        "POST",
        "/api/v1/sweeps/pressure",
        {
            **_DIAMETER,
            **_MATERIAL,
            "tensile_strength_pa": 75e6,
            "pressure_min_pa": 50_000.0,
            "pressure_max_pa": 600_000.0,
            "points": 60,
        },
    ),
    (8, "POST", "/api/v1/hysteresis", {**PAPER_MUSCLE_BODY, "points": 201}),
    (2, "POST", "/api/v1/hysteresis", {**PAPER_MUSCLE_BODY, "points": 100_000}),
    (1, "POST", "/api/v1/hysteresis?format=npy", {**PAPER_MUSCLE_BODY, "points": 100_000}),
    (1, "POST", "/api/v1/hysteresis?format=npy-record", {**PAPER_MUSCLE_BODY, "points": 100_000}),
    (2, "POST", "/api/v1/sweeps/hysteresis", {**_SWEPT_MUSCLE, "pressures_pa": [1e5, 3e5, 5e5]}),
    (2, "POST", "/api/v1/export/opensim", {k: PAPER_MUSCLE_BODY[k] for k in _OPENSIM_FIELDS}),
    (4, "GET", "/api/v1/materials", None),
    (4, "GET", "/api/v1/reference", None),
    (4, "GET", "/healthz", None),
]


def mix_lua(seed: int = 1) -> str:
    """A wrk script cycling through the mix in a fixed shuffled order of 100 requests."""
    formats = []
    for _, method, path, body in MIX:
        if body is None:
            formats.append(f'wrk.format("{method}", "{path}")')
        else:
            text = json.dumps(body)
            formats.append(
                f'wrk.format("{method}", "{path}", {{["Content-Type"] = "application/json"}},'
                f" [==[{text}]==])"
            )
    schedule = [i + 1 for i, (weight, *_) in enumerate(MIX) for _ in range(weight)]
    random.Random(seed).shuffle(schedule)
    return (
        "local reqs = {}\n"
        f"local schedule = {{{', '.join(map(str, schedule))}}}\n"
        "local counter = 0\n"
        "init = function(args)\n"
        + "".join(f"  reqs[{i + 1}] = {f}\n" for i, f in enumerate(formats))
        + "end\n"
        "request = function()\n"
        "  counter = counter + 1\n"
        "  return reqs[schedule[(counter - 1) % #schedule + 1]]\n"
        "end\n"
    )


def _preflight(url: str) -> None:
    for _, method, path, body in MIX:
        if body is None:
            with urllib.request.urlopen(url + path, timeout=30) as response:
                status = response.status
        else:
            status, answer = post_json(url + path, body, timeout=60)
            if status != 200:
                raise SystemExit(f"preflight: {method} {path} answered {status}: {answer[:300]!r}")
        if status != 200:
            raise SystemExit(f"preflight: {method} {path} answered {status}")


class RssSampler(threading.Thread):
    """Reads a process's VmRSS once a second until stopped."""

    def __init__(self, pid: int) -> None:
        super().__init__(daemon=True)
        self.pid = pid
        self.samples: list[tuple[float, int]] = []
        self._stop_event = threading.Event()

    def run(self) -> None:
        start = time.monotonic()
        while not self._stop_event.is_set():
            rss = rss_kib(self.pid)
            if rss is not None:
                self.samples.append((time.monotonic() - start, rss))
            self._stop_event.wait(1.0)

    def stop(self) -> None:
        """Stop sampling and wait for the thread."""
        self._stop_event.set()
        self.join()


def main(argv: list[str] | None = None) -> int:
    """Soak, then print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.soak", description=__doc__)
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--connections", type=int, default=64)
    parser.add_argument("--warmup", type=float, default=None, help="default: seconds / 6")
    parser.add_argument("--window", type=int, default=10, help="RSS samples per median")
    args = parser.parse_args(argv)
    warmup = args.warmup if args.warmup is not None else args.seconds / 6
    window = args.window
    if args.seconds < warmup + 2 * window:
        raise SystemExit(f"--seconds must be at least warm-up + 2 x --window ({2 * window} s)")
    loop, http = loop_and_http()
    weights = ", ".join(f"{path.removeprefix('/api/v1/')} {w}%" for w, _, path, _ in MIX)
    header(
        f"soak: {args.seconds:g} s at {args.connections} connections over every endpoint",
        f"pma-calculator serve --workers 1 (loop {loop}, http {http}) pinned to CPU {SERVER_CPU};"
        f" wrk -t1 pinned to CPU {WRK_CPU}",
        f"mix (per 100 requests): {weights}; the 2 % and 1 % hysteresis requests are"
        " 100 000 points",
        f"RSS: VmRSS every 1 s; after warm-up = median of {window} samples from {warmup:g} s,"
        f" end = median of the last {window}",
    )
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "server.log"
        with uvicorn_server("app.main:app", cpus=SERVER_CPU, log=log) as server:
            _preflight(server.url)
            print(f"server: {' '.join(server.command)}")
            sampler = RssSampler(server.pid)
            sampler.start()
            try:
                result: WrkResult = run_wrk(
                    server.url,
                    mix_lua(),
                    connections=args.connections,
                    seconds=args.seconds,
                    cpus=WRK_CPU,
                    timeout_s=30,
                )
            finally:
                sampler.stop()
            alive = server.process.poll() is None
            with urllib.request.urlopen(server.url + "/healthz", timeout=10) as response:
                healthy = response.status == 200
            print(f"wrk: {' '.join(result.command)}")
        server_log = log.read_text(encoding="utf-8", errors="replace")
    tracebacks = server_log.count("Traceback")
    # The server runs at --log-level warning: any line is a warning or an error.
    log_lines = len(server_log.strip().splitlines())
    print()

    samples = sampler.samples
    after = [kib for t, kib in samples if t >= warmup][:window]
    end = [kib for _, kib in samples[-window:]]
    rss_after, rss_end = statistics.median(after), statistics.median(end)
    growth = rss_end / rss_after - 1.0
    errors = result.error_count + tracebacks + (0 if alive and healthy else 1)
    table = Table()
    table.add("requests", f"{result.requests:,} in {result.seconds:.1f} s ({result.rps:,.0f}/s)")
    table.add(
        "latency p50 / p99 / max",
        f"{result.p50_ms:.1f} / {result.p99_ms:.1f} / {result.max_ms:.0f} ms",
    )
    wrk_errors = " ".join(f"{k} {v}" for k, v in result.errors.items())
    table.add("errors", str(errors), "0", errors == 0)
    table.add("  of which", f"wrk: {wrk_errors}; tracebacks in server log {tracebacks}")
    table.add("server log lines (warnings, errors)", str(log_lines), "0", log_lines == 0)
    table.add("server alive, healthz 200 after the soak", f"{alive}, {healthy}")
    table.add("RSS at start of soak", f"{samples[0][1] / 1024:.1f} MiB")
    table.add("RSS after warm-up", f"{rss_after / 1024:.1f} MiB")
    table.add("RSS at end", f"{rss_end / 1024:.1f} MiB")
    table.add(
        "RSS window minima (after warm-up, end)",
        f"{min(after) / 1024:.1f}, {min(end) / 1024:.1f} MiB",
    )
    floor_growth = min(end) / min(after) - 1.0
    table.add("RSS max", f"{max(kib for _, kib in samples) / 1024:.1f} MiB")
    table.add(
        "RSS growth end / after warm-up",
        f"{growth * 100:+.1f} %",
        f"<= +{GROWTH_TARGET * 100:g} %",
        growth <= GROWTH_TARGET,
    )
    table.add(
        "RSS floor growth (window minima)",
        f"{floor_growth * 100:+.1f} %",
        f"<= +{GROWTH_TARGET * 100:g} %",
        floor_growth <= GROWTH_TARGET,
    )
    table.print()
    trace = ", ".join(
        f"{t:.0f}s {kib / 1024:.0f}" for t, kib in samples[:: max(1, len(samples) // 12)]
    )
    print(f"RSS samples [MiB]: {trace}")
    if server_log.strip():
        print("server log (last 20 lines):")
        print("\n".join(server_log.strip().splitlines()[-20:]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
