"""Fixtures shared by every test folder: the paper's numbers and a live server."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import IO

import httpx
import pytest

from tests.published import DavisCaldwell2006


@pytest.fixture(scope="session")
def davis_caldwell_2006() -> DavisCaldwell2006:
    """The paper's inputs and the numbers it prints."""
    return DavisCaldwell2006()


REPO_ROOT = Path(__file__).resolve().parents[1]
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
def live_server() -> Iterator[str]:
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
