"""Requests/s of POST /api/v1/min-braid-angle against a trivial FastAPI endpoint.

``.venv/bin/python -m bench.service_scalar [--seconds S] [--rounds R] [--connections C]``

Both apps run as deployed, with the same process settings: the calculator by
``pma-calculator serve --workers 1 --log-level warning`` (which applies app.server's
tune_allocator), the baseline by ``python -m bench._serve`` (the same tuning and uvicorn
settings), each pinned to CPU 0 with ``taskset -c 0``; wrk (one thread) is pinned to
CPU 1. The two are loaded in turn, A B A B ..., for ``--rounds`` rounds of ``--seconds``
each after a short warm-up, so slow drift of the machine hits both alike. Figures are
medians over the rounds; the ratio is the median of the rounds' calculator RPS / baseline
RPS. Target: ratio >= 0.7.

Pinning does not keep other processes off CPU 0, so on a shared machine the RPS of a round
can swing 2x. The server's CPU time per request (utime + stime from /proc/<pid>/stat over
each round) counts only the server's own cycles: the ratio of those is printed as the
noise-resistant estimate of the same figure.
"""

from __future__ import annotations

import argparse
import statistics

from bench._common import (
    PAPER_BRAID_BODY,
    Table,
    WrkResult,
    header,
    loop_and_http,
    post_json,
    post_lua,
    run_wrk,
    uvicorn_server,
)

TARGET = 0.7
SERVER_CPU = "0"
WRK_CPU = "1"


def _median(results: list[WrkResult], key: str) -> float:
    return statistics.median(float(getattr(r, key)) for r in results)


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.service_scalar", description=__doc__)
    parser.add_argument("--seconds", type=float, default=5.0, help="per round and app")
    parser.add_argument("--rounds", type=int, default=8)
    parser.add_argument("--connections", type=int, default=64)
    parser.add_argument("--warmup", type=float, default=3.0, help="seconds, per app")
    args = parser.parse_args(argv)
    loop, http = loop_and_http()
    header(
        "service scalar: POST /api/v1/min-braid-angle vs a constant FastAPI endpoint",
        "calculator: pma-calculator serve --workers 1; baseline: python -m bench._serve"
        f" (same process settings); loop {loop}, http {http}, log level warning, no access"
        f" log; pinned to CPU {SERVER_CPU} (taskset -c {SERVER_CPU})",
        f"wrk -t1 -c{args.connections} pinned to CPU {WRK_CPU} (taskset -c {WRK_CPU}),"
        f" {args.rounds} alternating rounds of {args.seconds:g} s per app after"
        f" {args.warmup:g} s warm-up; medians over rounds",
    )
    lua = post_lua(PAPER_BRAID_BODY)
    calc: list[WrkResult] = []
    base: list[WrkResult] = []
    with (
        uvicorn_server("app.main:app", cpus=SERVER_CPU) as calc_server,
        uvicorn_server("bench.baseline_app:app", cpus=SERVER_CPU) as base_server,
    ):
        calc_url = calc_server.url + "/api/v1/min-braid-angle"
        base_url = base_server.url + "/baseline"
        for url in (calc_url, base_url):
            status, body = post_json(url, PAPER_BRAID_BODY)
            if status != 200:
                raise SystemExit(f"{url} answered {status}: {body[:300]!r}")
        print(f"calculator: {' '.join(calc_server.command)}")
        print(f"baseline:   {' '.join(base_server.command)}")
        for url in (calc_url, base_url):
            run_wrk(url, lua, connections=args.connections, seconds=args.warmup, cpus=WRK_CPU)
        for round_ in range(args.rounds):
            for server, url, results in (
                (calc_server, calc_url, calc),
                (base_server, base_url, base),
            ):
                result = run_wrk(
                    url,
                    lua,
                    connections=args.connections,
                    seconds=args.seconds,
                    cpus=WRK_CPU,
                    server=server,
                )
                results.append(result)
            print(
                f"round {round_ + 1}: calculator {calc[-1].rps:,.0f} req/s"
                f" ({calc[-1].cpu_us_per_request or 0:.0f} us CPU/req), baseline"
                f" {base[-1].rps:,.0f} req/s ({base[-1].cpu_us_per_request or 0:.0f} us CPU/req),"
                f" ratio {calc[-1].rps / base[-1].rps:.2f}"
            )
        print(f"wrk: {' '.join(calc[-1].command)}")
    print()

    calc_rps, base_rps = _median(calc, "rps"), _median(base, "rps")
    ratios = [c.rps / b.rps for c, b in zip(calc, base, strict=True)]
    ratio = statistics.median(ratios)
    calc_cpu, base_cpu = _median(calc, "cpu_us_per_request"), _median(base, "cpu_us_per_request")
    errors = sum(r.error_count for r in calc + base)
    table = Table()
    table.add("calculator req/s", f"{calc_rps:,.0f}")
    table.add("baseline req/s", f"{base_rps:,.0f}")
    table.add(
        "ratio calculator / baseline",
        f"{ratio:.2f} (rounds {min(ratios):.2f}-{max(ratios):.2f})",
        f">= {TARGET:g}",
        ratio >= TARGET,
    )
    table.add("server CPU per request, calculator", f"{calc_cpu:.0f} us")
    table.add("server CPU per request, baseline", f"{base_cpu:.0f} us")
    table.add(
        "CPU-time ratio baseline / calculator", f"{base_cpu / calc_cpu:.2f}", f"(>= {TARGET:g})"
    )
    for name, results in (("calculator", calc), ("baseline", base)):
        table.add(
            f"{name} latency p50 / p99 @ {args.connections} conn",
            f"{_median(results, 'p50_ms'):.1f} / {_median(results, 'p99_ms'):.1f} ms",
        )
    table.add("errors (socket, timeout, non-2xx)", str(errors), "0", errors == 0)
    table.print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
