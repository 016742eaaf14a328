"""Shared helpers of the benchmarks: machine description, timing, uvicorn servers and wrk.

Nothing here talks to anything but 127.0.0.1, and every server or load generator it starts
is bounded in time and stopped on exit.
"""

from __future__ import annotations

import asyncio
import contextlib
import datetime as dt
import importlib.metadata
import importlib.util
import json
import os
import platform
import resource
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import timeit
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from app.schemas import PAPER_BRAID, PAPER_MUSCLE

HOST = "127.0.0.1"
REPO_ROOT = Path(__file__).resolve().parent.parent
STARTUP_TIMEOUT_S = 30.0

#: The paper's test muscle (§3.3) and braid (Table 1, N = 240) as API bodies: the examples
#: of the API's own documentation.
PAPER_MUSCLE_BODY: dict[str, Any] = PAPER_MUSCLE
PAPER_BRAID_BODY: dict[str, Any] = PAPER_BRAID
#: The same muscle, positional for hysteresis_curves: b, n, D_s, N, P, f_s, E, nu.
PAPER_MUSCLE_ARGS: tuple[float, float, float, int, float, float, float, float] = tuple(
    PAPER_MUSCLE[name]
    for name in (
        "strand_length_m",
        "turns",
        "strand_diameter_m",
        "strand_count",
        "pressure_pa",
        "friction_coefficient",
        "youngs_modulus_pa",
        "poisson_ratio",
    )
)


# ---------------------------------------------------------------- reporting


def machine() -> dict[str, str]:
    """The machine and software the figures were measured on."""
    import numpy as np

    cpu = platform.processor() or platform.machine()
    with contextlib.suppress(OSError):
        for line in Path("/proc/cpuinfo").read_text(encoding="utf-8").splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    versions = ", ".join(
        f"{name} {_version(name)}" for name in ("fastapi", "starlette", "uvicorn", "orjson")
    )
    blas = os.environ.get("OPENBLAS_CORETYPE")
    return {
        "date": dt.datetime.now(dt.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "cpu": f"{cpu}, {os.cpu_count()} cores ({platform.machine()})",
        "os": f"{platform.system()} {platform.release()}",
        "python": platform.python_version(),
        "numpy": np.__version__,
        "packages": versions,
        "env": f"OPENBLAS_CORETYPE={blas}" if blas else "OPENBLAS_CORETYPE unset",
        "load": load_average(),
        "commit": git_commit(),
    }


def git_commit() -> str:
    """The repository's HEAD, with ``-dirty`` when the working tree has changes."""
    try:
        done = subprocess.run(
            ["git", "describe", "--always", "--dirty"],
            cwd=REPO_ROOT,
            capture_output=True,
            text=True,
            check=False,
            timeout=10,
        )
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"
    return done.stdout.strip() or "unknown"


def load_average() -> str:
    """The 1, 5 and 15 minute load averages: other work on the machine adds noise."""
    try:
        one, five, fifteen = os.getloadavg()
    except OSError:
        return "unknown"
    return f"{one:.2f} {five:.2f} {fifteen:.2f} (1/5/15 min; >0.5 means other work ran)"


def _version(name: str) -> str:
    try:
        return importlib.metadata.version(name)
    except importlib.metadata.PackageNotFoundError:
        return "absent"


def header(title: str, *notes: str) -> None:
    """Print the benchmark's title, the machine, and how it measures."""
    print(f"== {title}")
    for key, value in machine().items():
        print(f"   {key:9s} {value}")
    for note in notes:
        print(f"   note      {note}")
    print()


def verdict(ok: bool) -> str:
    """PASS or MISS."""
    return "PASS" if ok else "MISS"


@dataclass
class Table:
    """Rows of (figure, value, target, verdict), printed aligned."""

    rows: list[tuple[str, str, str, str]] = field(default_factory=list)

    def add(self, figure: str, value: str, target: str = "", ok: bool | None = None) -> None:
        """Add a row; ``ok`` None for an informative figure without a target."""
        self.rows.append((figure, value, target, "" if ok is None else verdict(ok)))

    def print(self) -> None:
        """Print the table."""
        titles = ("figure", "value", "target", "result")
        widths = [max(len(r[i]) for r in [titles, *self.rows]) for i in range(4)]
        for row in [titles, *self.rows]:
            print("  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)))
        print()


# ---------------------------------------------------------------- timing


def best_of(fn: Callable[[], object], *, number: int, repeat: int) -> float:
    """Best (smallest) mean seconds per call over ``repeat`` runs of ``number`` calls."""
    fn()  # warm-up: imports, caches, first-touch of memory
    return min(timeit.repeat(fn, number=number, repeat=repeat)) / number


def spread(samples: Sequence[float], fmt: str = ".3g") -> str:
    """``median [min-max]`` of samples."""
    low, mid, high = (
        format(v, fmt) for v in (min(samples), statistics.median(samples), max(samples))
    )
    return f"median {mid} [{low}-{high}]"


# ---------------------------------------------------------------- servers


def free_port() -> int:
    """A TCP port free on 127.0.0.1 now."""
    with socket.socket() as sock:
        sock.bind((HOST, 0))
        port: int = sock.getsockname()[1]
        return port


def loop_and_http() -> tuple[str, str]:
    """The uvicorn loop and HTTP implementations installed: uvloop/httptools or stdlib."""
    loop = "uvloop" if importlib.util.find_spec("uvloop") else "asyncio"
    http = "httptools" if importlib.util.find_spec("httptools") else "h11"
    return loop, http


@dataclass
class Server:
    """A running uvicorn server."""

    process: subprocess.Popen[bytes]
    url: str
    command: list[str]

    @property
    def pid(self) -> int:
        """Process id of uvicorn (the supervisor when there are several workers)."""
        return self.process.pid

    def pids(self) -> list[int]:
        """uvicorn and its worker processes, if any."""
        return [self.pid, *children(self.pid)]


#: How the benchmarks start a server: "serve" as deployed (``pma-calculator serve`` for the
#: calculator, ``bench._serve`` with the same process settings for the other apps), or
#: "uvicorn", the stock uvicorn command without the fixes of app.server (F1, F3).
LAUNCHERS = ("serve", "uvicorn")
SERVICE_APP = "app.main:app"


def pma_calculator() -> str:
    """The ``pma-calculator`` console script of this interpreter's environment."""
    path = Path(sys.executable).with_name("pma-calculator")
    if not path.exists():
        sys.exit(f"{path} not found: install the project into this environment (pip install -e .)")
    return str(path)


def uvicorn_command(
    app: str,
    port: int,
    *,
    workers: int = 1,
    cpus: str | None = None,
    factory: bool = False,
    launcher: str = "serve",
) -> list[str]:
    """The server command line every benchmark uses (only the app and workers vary).

    ``launcher`` "serve": the calculator exactly as deployed, ``pma-calculator serve``
    (tune_allocator, and TCP_NODELAY for workers > 1); any other app through
    ``bench._serve``, which applies the same process settings. "uvicorn": stock uvicorn.
    Both use the loop and HTTP implementation uvicorn picks by default (:func:`loop_and_http`).
    """
    where = ["--host", HOST, "--port", str(port), "--workers", str(workers)]
    if launcher == "serve" and app == SERVICE_APP and not factory:
        command = [pma_calculator(), "serve", *where, "--log-level", "warning"]
    elif launcher == "serve":
        command = [sys.executable, "-m", "bench._serve", app, *where, "--log-level", "warning"]
        if factory:
            command.append("--factory")
    elif launcher == "uvicorn":
        loop, http = loop_and_http()
        command = [sys.executable, "-m", "uvicorn", app, *where, "--log-level", "warning"]
        command += ["--no-access-log", "--loop", loop, "--http", http]
        if factory:
            command.append("--factory")
    else:
        raise ValueError(f"launcher must be one of {LAUNCHERS}, not {launcher!r}")
    if cpus is not None:
        command = ["taskset", "-c", cpus, *command]
    return command


@contextlib.contextmanager
def uvicorn_server(
    app: str,
    *,
    workers: int = 1,
    cpus: str | None = None,
    factory: bool = False,
    ready_path: str = "/healthz",
    log: Path | None = None,
    launcher: str = "serve",
) -> Iterator[Server]:
    """Run ``app`` on a free port of 127.0.0.1 until the block ends (:func:`uvicorn_command`).

    ``cpus`` pins it with ``taskset -c`` (taskset execs, so the pid is the server's own).
    ``log``: a file for the server's stdout and stderr, else they go to this console.
    ``launcher``: "serve" as deployed (default) or "uvicorn", stock uvicorn without F1/F3.
    """
    port = free_port()
    command = uvicorn_command(
        app, port, workers=workers, cpus=cpus, factory=factory, launcher=launcher
    )
    with contextlib.ExitStack() as stack:
        output = stack.enter_context(log.open("wb")) if log is not None else None
        process = subprocess.Popen(
            command, cwd=REPO_ROOT, stdin=subprocess.DEVNULL, stdout=output, stderr=output
        )
        server = Server(process, f"http://{HOST}:{port}", command)
        try:
            _wait_ready(server, ready_path)
            yield server
        finally:
            _stop(process)


def _wait_ready(server: Server, path: str) -> None:
    deadline = time.monotonic() + STARTUP_TIMEOUT_S
    while time.monotonic() < deadline:
        if server.process.poll() is not None:
            raise RuntimeError(f"uvicorn exited with {server.process.returncode}: {server.command}")
        try:
            with urllib.request.urlopen(server.url + path, timeout=2) as response:
                if response.status == 200:
                    return
        except (urllib.error.URLError, ConnectionError):
            time.sleep(0.1)
    raise RuntimeError(f"{server.url}{path} did not answer within {STARTUP_TIMEOUT_S} s")


def _stop(process: subprocess.Popen[bytes]) -> None:
    if process.poll() is None:
        process.send_signal(signal.SIGTERM)
        try:
            process.wait(timeout=15)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(timeout=5)


def children(pid: int) -> list[int]:
    """Process ids of the direct children of ``pid``."""
    found: list[int] = []
    with contextlib.suppress(OSError):
        for task in Path(f"/proc/{pid}/task").iterdir():
            text = (task / "children").read_text(encoding="ascii")
            found += [int(child) for child in text.split()]
    return found


def cpu_seconds(pids: Sequence[int]) -> float:
    """User + system CPU time the processes have used so far [s], from /proc/<pid>/stat.

    CPU time per request is far less sensitive than throughput to other work on the
    machine: it counts only this server's cycles, not the time it waited for a core.
    """
    ticks = os.sysconf("SC_CLK_TCK")
    total = 0.0
    for pid in pids:
        with contextlib.suppress(OSError, ValueError, IndexError):
            fields = Path(f"/proc/{pid}/stat").read_text(encoding="ascii").rsplit(")", 1)[1].split()
            total += (int(fields[11]) + int(fields[12])) / ticks
    return total


def rss_kib(pid: int) -> int | None:
    """Resident set size of a process [KiB] from /proc/<pid>/status, None once it is gone."""
    try:
        for line in Path(f"/proc/{pid}/status").read_text(encoding="utf-8").splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    except (OSError, ValueError):
        return None
    return None


def post_json(url: str, body: dict[str, Any], timeout: float = 30.0) -> tuple[int, bytes]:
    """POST a JSON body with urllib; (status, body bytes), errors included."""
    request = urllib.request.Request(
        url,
        data=json.dumps(body).encode(),
        headers={"Content-Type": "application/json"},
        method="POST",
    )
    try:
        with urllib.request.urlopen(request, timeout=timeout) as response:
            status: int = response.status
            return status, response.read()
    except urllib.error.HTTPError as error:
        return error.code, error.read()


# ---------------------------------------------------------------- wrk

_WRK_DONE = r"""
done = function(summary, latency, requests)
  local e = summary.errors
  io.write(string.format(
    "WRKJSON {\"requests\":%d,\"duration_us\":%d,\"bytes\":%d,\"connect\":%d,\"read\":%d,"
    .. "\"write\":%d,\"status\":%d,\"timeout\":%d,\"p50_us\":%d,\"p90_us\":%d,"
    .. "\"p99_us\":%d,\"max_us\":%d,\"mean_us\":%.1f}\n",
    summary.requests, summary.duration, summary.bytes, e.connect, e.read, e.write, e.status,
    e.timeout, latency:percentile(50), latency:percentile(90), latency:percentile(99),
    latency.max, latency.mean))
end
"""


@dataclass(frozen=True)
class WrkResult:
    """What one wrk run measured."""

    requests: int
    seconds: float
    bytes_read: int
    p50_ms: float
    p90_ms: float
    p99_ms: float
    max_ms: float
    errors: dict[str, int]
    command: list[str]
    server_cpu_s: float | None = None
    wrk_cpu_s: float = 0.0
    machine_idle: float | None = None

    @property
    def cpu_us_per_request(self) -> float | None:
        """Server CPU time per completed request [us], when it was measured."""
        if self.server_cpu_s is None or not self.requests:
            return None
        return self.server_cpu_s / self.requests * 1e6

    @property
    def rps(self) -> float:
        """Completed requests per second."""
        return self.requests / self.seconds

    @property
    def error_count(self) -> int:
        """Socket errors, timeouts and non-2xx/3xx responses."""
        return sum(self.errors.values())


def wrk_path() -> str:
    """Path of wrk; exits with a hint when it is not installed."""
    path = shutil.which("wrk")
    if path is None:
        sys.exit(
            "wrk not found: apt-get -o DPkg::Lock::Timeout=600 install -y wrk "
            "(this benchmark needs it; hey is not supported by these scripts)"
        )
    return path


def post_lua(path_body: dict[str, Any]) -> str:
    """A wrk script that POSTs one JSON body."""
    body = json.dumps(path_body)
    return (
        'wrk.method = "POST"\n'
        f"wrk.body = [==[{body}]==]\n"
        'wrk.headers["Content-Type"] = "application/json"\n'
    )


def run_wrk(
    url: str,
    lua: str,
    *,
    connections: int,
    seconds: float,
    threads: int = 1,
    cpus: str | None = None,
    timeout_s: float = 10.0,
    server: Server | None = None,
) -> WrkResult:
    """Run wrk against ``url`` with ``lua`` (its own ``done`` is appended).

    With ``server``, also measure the CPU time its processes used during the run.
    """
    with tempfile.NamedTemporaryFile("w", suffix=".lua", delete=False) as script:
        script.write(lua + _WRK_DONE)
    try:
        command = [wrk_path(), "-t", str(threads), "-c", str(connections)]
        command += ["-d", f"{seconds:g}s", "--timeout", f"{timeout_s:g}s", "-s", script.name, url]
        if cpus is not None:
            command = ["taskset", "-c", cpus, *command]
        pids = server.pids() if server is not None else []
        cpu_before = cpu_seconds(pids)
        wrk_before = _children_cpu()
        idle_before = _idle_and_total()
        done = subprocess.run(
            command, capture_output=True, text=True, check=False, timeout=seconds + 60
        )
        idle_after = _idle_and_total()
        wrk_cpu = _children_cpu() - wrk_before
        cpu_used = cpu_seconds(pids) - cpu_before if server is not None else None
    finally:
        os.unlink(script.name)
    lines = [line for line in done.stdout.splitlines() if line.startswith("WRKJSON ")]
    if done.returncode != 0 or not lines:
        raise RuntimeError(f"wrk failed ({done.returncode}): {done.stdout}\n{done.stderr}")
    data = json.loads(lines[-1].removeprefix("WRKJSON "))
    return WrkResult(
        requests=data["requests"],
        seconds=data["duration_us"] / 1e6,
        bytes_read=data["bytes"],
        p50_ms=data["p50_us"] / 1e3,
        p90_ms=data["p90_us"] / 1e3,
        p99_ms=data["p99_us"] / 1e3,
        max_ms=data["max_us"] / 1e3,
        errors={k: data[k] for k in ("connect", "read", "write", "status", "timeout")},
        command=command,
        server_cpu_s=cpu_used,
        wrk_cpu_s=wrk_cpu,
        machine_idle=_fraction(idle_before, idle_after),
    )


def _children_cpu() -> float:
    """CPU time of the waited-for child processes (wrk, once it has exited) [s]."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _idle_and_total() -> tuple[int, int]:
    """Machine-wide idle and total jiffies from /proc/stat."""
    try:
        fields = [int(v) for v in Path("/proc/stat").read_text(encoding="ascii").split()[1:9]]
    except (OSError, ValueError):
        return 0, 0
    return fields[3] + fields[4], sum(fields)


def _fraction(before: tuple[int, int], after: tuple[int, int]) -> float | None:
    total = after[1] - before[1]
    return (after[0] - before[0]) / total if total > 0 else None


# ---------------------------------------------------------------- in-process ASGI


@dataclass(frozen=True)
class AsgiResponse:
    """Status, headers and the complete body bytes an ASGI app sent."""

    status: int
    headers: dict[str, str]
    body: bytes


async def asgi_request(
    app: Any,
    method: str,
    path: str,
    body: bytes = b"",
    headers: Sequence[tuple[str, str]] = (),
) -> AsgiResponse:
    """Drive an ASGI app directly: the request in, every response byte out.

    No client, no socket: what is timed around this call is the server's own work.
    """
    path, _, query = path.partition("?")
    raw_headers = [(b"host", b"127.0.0.1"), (b"content-length", str(len(body)).encode())]
    raw_headers += [(k.lower().encode(), v.encode()) for k, v in headers]
    scope = {
        "type": "http",
        "asgi": {"version": "3.0", "spec_version": "2.3"},
        "http_version": "1.1",
        "method": method,
        "scheme": "http",
        "path": path,
        "raw_path": path.encode(),
        "root_path": "",
        "query_string": query.encode(),
        "headers": raw_headers,
        "client": (HOST, 50000),
        "server": (HOST, 80),
        "state": {},
    }
    request_sent = False
    status = 0
    response_headers: dict[str, str] = {}
    chunks: list[bytes] = []

    async def receive() -> dict[str, Any]:
        nonlocal request_sent
        if not request_sent:
            request_sent = True
            return {"type": "http.request", "body": body, "more_body": False}
        await asyncio.Event().wait()  # the client stays connected until the response ends
        return {"type": "http.disconnect"}

    async def send(message: dict[str, Any]) -> None:
        nonlocal status
        if message["type"] == "http.response.start":
            status = message["status"]
            for name, value in message.get("headers", ()):
                response_headers[name.decode("latin-1")] = value.decode("latin-1")
        elif message["type"] == "http.response.body":
            chunks.append(message.get("body", b""))

    await app(scope, receive, send)
    return AsgiResponse(status, response_headers, b"".join(chunks))
