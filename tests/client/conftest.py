"""Fixtures of the client tests: a real ``uvicorn app.main:app`` on a free loopback port.

``pma`` runs each test twice: with :class:`PMAClient`, and with :class:`AsyncPMAClient`
whose coroutines run on one asyncio event loop. Natively async tests use anyio's pytest
plugin (``@pytest.mark.anyio``), installed with httpx.
"""

from __future__ import annotations

import asyncio
import os
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import IO, Any, cast

import httpx
import pytest

from pma_client import AsyncPMAClient, PMAClient
from tests.published import DavisCaldwell2006

REPO_ROOT = Path(__file__).resolve().parents[2]
SERVER_HOST = "127.0.0.1"
STARTUP_TIMEOUT_S = 30.0
# Another process may take the free port before uvicorn binds it: try a few.
START_ATTEMPTS = 3


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind((SERVER_HOST, 0))
        port: int = sock.getsockname()[1]
        return port


def _server_env() -> dict[str, str]:
    # The tests expect the service's defaults: no root path, no CORS from the caller's shell.
    return {name: value for name, value in os.environ.items() if not name.startswith("PMA_")}


def _output(log: IO[bytes]) -> str:
    log.seek(0)
    return log.read().decode(errors="replace")[-4000:]


def _wait_until_healthy(url: str, server: subprocess.Popen[bytes]) -> bool:
    """True once ``/healthz`` answers; False if the server exited first."""
    deadline = time.monotonic() + STARTUP_TIMEOUT_S
    while time.monotonic() < deadline:
        if server.poll() is not None:
            return False
        try:
            if httpx.get(f"{url}/healthz", timeout=2).json() == {"status": "ok"}:
                return True
        except (httpx.TransportError, ValueError):
            pass
        time.sleep(0.1)
    return False


def _stop(server: subprocess.Popen[bytes]) -> None:
    server.terminate()
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.kill()
        server.wait()


@pytest.fixture(scope="session")
def server_url() -> Iterator[str]:
    """URL of a real ``uvicorn app.main:app`` on a free loopback port, for the session."""
    with tempfile.TemporaryFile() as log:
        for _ in range(START_ATTEMPTS):
            port = _free_port()
            command = [sys.executable, "-m", "uvicorn", "app.main:app"]
            command += ["--host", SERVER_HOST, "--port", str(port), "--log-level", "warning"]
            server = subprocess.Popen(
                command, cwd=REPO_ROOT, env=_server_env(), stdout=log, stderr=subprocess.STDOUT
            )
            url = f"http://{SERVER_HOST}:{port}"
            if _wait_until_healthy(url, server):
                break
            _stop(server)
        else:
            pytest.fail(f"uvicorn did not answer /healthz:\n{_output(log)}")
        try:
            yield url
        finally:
            _stop(server)


@pytest.fixture
def anyio_backend() -> str:
    """Run ``@pytest.mark.anyio`` tests on asyncio only (trio is not a dependency)."""
    return "asyncio"


@pytest.fixture
def paper(davis_caldwell_2006: DavisCaldwell2006) -> DavisCaldwell2006:
    """The paper's inputs and printed numbers (typed in from the paper)."""
    return davis_caldwell_2006


class _Blocking:
    """An :class:`AsyncPMAClient` behind the interface of :class:`PMAClient`.

    Each method call runs the client's coroutine to completion on ``runner``'s event loop,
    so one test body checks both clients.
    """

    def __init__(self, client: AsyncPMAClient, runner: asyncio.Runner) -> None:
        self._client = client
        self._runner = runner

    def __getattr__(self, name: str) -> Callable[..., Any]:
        method = getattr(self._client, name)

        def call(*args: Any, **kwargs: Any) -> Any:
            result = method(*args, **kwargs)
            if asyncio.iscoroutine(result):
                return self._runner.run(result)
            return result

        return call


@pytest.fixture(params=["sync", "async"])
def pma(request: pytest.FixtureRequest, server_url: str) -> Iterator[PMAClient]:
    """A client of the test server: :class:`PMAClient`, then :class:`AsyncPMAClient`."""
    if request.param == "sync":
        with PMAClient(server_url) as sync_client:
            yield sync_client
        return
    with asyncio.Runner() as runner:
        async_client = AsyncPMAClient(server_url)
        try:
            yield cast(PMAClient, _Blocking(async_client, runner))
        finally:
            runner.run(async_client.close())
