"""Throughput of POST /api/v1/min-braid-angle with uvicorn --workers 1 against --workers 2.

``.venv/bin/python -m bench.scale_workers [--seconds S] [--rounds R] [--connections C]``

The service as deployed, ``pma-calculator serve --workers 1`` against ``--workers 2``
(app.server's TCP_NODELAY fix and fair-accept loop for workers > 1, and tune_allocator);
nothing is pinned.
wrk (two threads, ``--connections`` connections) runs unpinned too, alternately
against the two servers, ``--rounds`` rounds of ``--seconds`` each after a warm-up; figures
are medians over the rounds.

The limit of this measurement: the machine has 2 cores and wrk needs one of them. With one
worker the server gets about a core and wrk the other; with two workers the two workers and
wrk share two cores, so the second worker can add at most what wrk leaves free. The ratio
is therefore a lower bound of what a second worker gives on a machine where the load comes
from elsewhere; on a 2-core box with a local load generator, about 1.2-1.5x is all there is
to get. Reported, not judged: there is no target.

What this found before the fix: with stock uvicorn, ``--workers 2`` is *slower* than one
worker, because uvicorn binds the multi-worker listener with ``proto`` 0, asyncio then
leaves Nagle on for every connection, and each keep-alive response waits ~40 ms for wrk's
delayed ACK (uvicorn issue #3149; the single-request keep-alive latency row shows it).
``pma-calculator serve`` now re-wraps the listener as IPPROTO_TCP (app.server, F1).

The second finding: wrk opens its keep-alive connections in one burst, and asyncio accepts
up to 2048 waiting connections per wake-up, so in about half the rounds one worker took all
64 and kept them (busiest worker 100 %, 0.9-1.0x). ``pma-calculator serve`` now runs
several workers on ``app.server.FairAcceptEventLoop``, which accepts one connection per
wake-up (F10); the busiest-worker row shows the split.

``--stock-uvicorn`` runs both servers with plain ``python -m uvicorn`` (no F1, F3 or F10)
to reproduce the figures before the fixes.
"""

from __future__ import annotations

import argparse
import contextlib
import http.client
import json
import statistics
import time
from pathlib import Path
from urllib.parse import urlsplit

from bench._common import (
    PAPER_BRAID_BODY,
    Server,
    Table,
    WrkResult,
    children,
    cpu_seconds,
    header,
    loop_and_http,
    post_json,
    post_lua,
    run_wrk,
    uvicorn_server,
)

PATH = "/api/v1/min-braid-angle"


def worker_pids(server: Server) -> list[int]:
    """uvicorn's worker processes (its multiprocessing children, not the resource tracker)."""
    found = []
    for pid in children(server.pid):
        with contextlib.suppress(OSError):
            if b"spawn_main" in Path(f"/proc/{pid}/cmdline").read_bytes():
                found.append(pid)
    return found or [server.pid]


def keepalive_latency_ms(url: str, requests: int = 21) -> float:
    """Median latency of sequential requests on one keep-alive connection [ms].

    One request at a time, so this is the server's answer time plus any transport delay:
    a Nagle / delayed-ACK stall shows as ~40 ms here.
    """
    parts = urlsplit(url)
    connection = http.client.HTTPConnection(parts.hostname or "127.0.0.1", parts.port, timeout=10)
    body = json.dumps(PAPER_BRAID_BODY)
    times = []
    try:
        for _ in range(requests):
            start = time.perf_counter()
            connection.request("POST", parts.path, body, {"Content-Type": "application/json"})
            response = connection.getresponse()
            response.read()
            times.append(time.perf_counter() - start)
            if response.status != 200:
                raise SystemExit(f"{url} answered {response.status}")
    finally:
        connection.close()
    return statistics.median(times) * 1e3


def _wait_workers(server: Server, workers: int, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while workers > 1 and len(worker_pids(server)) < workers:
        if time.monotonic() > deadline:
            raise SystemExit(f"uvicorn did not start {workers} workers in {timeout:g} s")
        time.sleep(0.2)
    time.sleep(1.0)  # the workers import the app after they appear


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.scale_workers", description=__doc__)
    parser.add_argument("--seconds", type=float, default=10.0, help="per round and server")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--connections", type=int, default=64)
    parser.add_argument("--warmup", type=float, default=3.0)
    parser.add_argument(
        "--stock-uvicorn",
        action="store_true",
        help="run both servers with plain uvicorn, without app.server's fixes (the before)",
    )
    args = parser.parse_args(argv)
    launcher = "uvicorn" if args.stock_uvicorn else "serve"
    loop, http = loop_and_http()
    header(
        f"scale workers: POST {PATH}, uvicorn --workers 1 vs --workers 2",
        f"loop {loop}, http {http}, log level warning, no access log; unpinned",
        f"wrk -t2 -c{args.connections} unpinned, {args.rounds} alternating rounds of"
        f" {args.seconds:g} s after {args.warmup:g} s warm-up; medians over rounds",
        "2 cores shared by the workers and wrk: the ratio is a lower bound (see --help)",
        "server launched as "
        + ("stock python -m uvicorn" if args.stock_uvicorn else "pma-calculator serve"),
    )
    lua = post_lua(PAPER_BRAID_BODY)
    results: dict[int, list[WrkResult]] = {1: [], 2: []}
    latency: dict[int, float] = {}
    split: list[list[float]] = []  # CPU seconds of each worker, per 2-worker round
    with (
        uvicorn_server("app.main:app", workers=1, launcher=launcher) as one,
        uvicorn_server("app.main:app", workers=2, launcher=launcher) as two,
    ):
        servers = {1: one, 2: two}
        for workers, server in servers.items():
            _wait_workers(server, workers)
            status, body = post_json(server.url + PATH, PAPER_BRAID_BODY)
            if status != 200:
                raise SystemExit(f"{server.url}{PATH} answered {status}: {body[:300]!r}")
            print(f"--workers {workers}: {' '.join(server.command)}")
            latency[workers] = keepalive_latency_ms(server.url + PATH)
            run_wrk(server.url + PATH, lua, connections=args.connections, seconds=args.warmup)
        for round_ in range(args.rounds):
            for workers, server in servers.items():
                pids = worker_pids(server)
                before = [cpu_seconds([pid]) for pid in pids]
                results[workers].append(
                    run_wrk(
                        server.url + PATH,
                        lua,
                        threads=2,
                        connections=args.connections,
                        seconds=args.seconds,
                        server=server,
                    )
                )
                if workers == 2:
                    split.append([cpu_seconds([p]) - b for p, b in zip(pids, before, strict=True)])
            print(
                f"round {round_ + 1}: 1 worker {results[1][-1].rps:,.0f} req/s,"
                f" 2 workers {results[2][-1].rps:,.0f} req/s (busiest worker"
                f" {max(split[-1]) / max(sum(split[-1]), 1e-9) * 100:.0f} % of their CPU)"
            )
        print(f"wrk: {' '.join(results[2][-1].command)}")
    print()

    rps = {w: statistics.median(r.rps for r in results[w]) for w in results}
    table = Table()
    for workers in (1, 2):
        p50 = statistics.median(r.p50_ms for r in results[workers])
        p99 = statistics.median(r.p99_ms for r in results[workers])
        cpu = statistics.median(r.cpu_us_per_request or 0.0 for r in results[workers])
        table.add(
            f"--workers {workers}",
            f"{rps[workers]:,.0f} req/s (p50 {p50:.1f} ms, p99 {p99:.1f} ms,"
            f" server CPU {cpu:.0f} us/req)",
        )
    for workers in (1, 2):
        wrk_share = statistics.median(r.wrk_cpu_s / r.seconds for r in results[workers])
        idle = statistics.median(r.machine_idle or 0.0 for r in results[workers])
        table.add(
            f"  while --workers {workers} ran",
            f"wrk used {wrk_share:.2f} of a core; machine idle {idle * 100:.0f} %",
        )
    for workers in (1, 2):
        table.add(
            f"  keep-alive latency, 1 request at a time, --workers {workers}",
            f"{latency[workers]:.1f} ms",
        )
    shares = [max(cpu) / sum(cpu) for cpu in split if sum(cpu) > 0]
    table.add(
        "  busiest worker's share of server CPU",
        f"{statistics.median(shares) * 100:.0f} % (50 % = balanced)" if shares else "n/a",
    )
    ratios = [b.rps / a.rps for a, b in zip(results[1], results[2], strict=True)]
    table.add(
        "ratio 2 workers / 1 worker",
        f"{rps[2] / rps[1]:.2f}x (rounds {min(ratios):.2f}-{max(ratios):.2f})",
        "none (lower bound)",
    )
    errors = sum(r.error_count for rs in results.values() for r in rs)
    table.add("errors (socket, timeout, non-2xx)", str(errors), "0", errors == 0)
    table.print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
