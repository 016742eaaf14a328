"""Process tuning of pma-calculator serve: the listener with workers, the allocator."""

from __future__ import annotations

import asyncio
import os
import socket

import pytest
import uvicorn
import uvicorn.config

from app import cli, server
from app.cli import FAIR_ACCEPT_LOOP


def test_multi_worker_listener_is_tcp_so_connections_get_nodelay(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(uvicorn.config.Config, "bind_socket", uvicorn.config.Config.bind_socket)
    server.enable_tcp_nodelay_for_workers()
    config = uvicorn.config.Config("app.main:app", host="127.0.0.1", port=0, workers=2)
    sock = config.bind_socket()
    try:
        assert sock.proto == socket.IPPROTO_TCP
    finally:
        sock.close()


def test_allocator_settings_reach_worker_processes(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in server.MALLOC_SETTINGS:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("MALLOC_TOP_PAD_", "1234")
    server.tune_allocator()
    assert os.environ["MALLOC_MMAP_THRESHOLD_"] == str(32 << 20)
    assert os.environ["MALLOC_TOP_PAD_"] == "1234"  # a setting of the operator's wins


def _pending_after_one_wakeup(loop: asyncio.AbstractEventLoop, waiting: int) -> int:
    """Connections left in the listener's queue after the loop handles one readiness."""
    with socket.create_server(("127.0.0.1", 0)) as listener:
        clients = [socket.create_connection(listener.getsockname()) for _ in range(waiting)]
        try:
            listener.setblocking(False)
            loop._accept_connection(asyncio.Protocol, listener, None, None, 100)  # type: ignore[attr-defined]
            left = 0
            while True:
                try:
                    conn, _ = listener.accept()
                except BlockingIOError:
                    return left
                conn.close()
                left += 1
        finally:
            for client in clients:
                client.close()
            loop.run_until_complete(asyncio.sleep(0))  # let the accepted one's task finish
            loop.close()


def test_fair_accept_loop_takes_one_connection_per_wakeup() -> None:
    assert _pending_after_one_wakeup(server.FairAcceptEventLoop(), waiting=5) == 4
    # asyncio's own loop takes the whole burst: what let one worker take every connection.
    assert _pending_after_one_wakeup(asyncio.SelectorEventLoop(), waiting=5) == 0


def test_uvicorn_loads_the_fair_accept_loop_by_its_import_string() -> None:
    config = uvicorn.config.Config("app.main:app", loop=FAIR_ACCEPT_LOOP)
    factory = config.get_loop_factory()
    assert factory is server.FairAcceptEventLoop
    loop = factory()
    try:
        assert loop.run_until_complete(asyncio.sleep(0, result=42)) == 42
    finally:
        loop.close()


@pytest.mark.parametrize(
    ("arguments", "loop", "workers"),
    [
        (["--workers", "1"], "auto", 1),
        (["--workers", "2"], FAIR_ACCEPT_LOOP, 2),
        (["--workers", "2", "--reload"], "auto", None),  # reload runs one process
    ],
)
def test_serve_uses_the_fair_accept_loop_with_several_workers(
    monkeypatch: pytest.MonkeyPatch, arguments: list[str], loop: str, workers: int | None
) -> None:
    calls: list[dict[str, object]] = []
    monkeypatch.setattr(uvicorn.config.Config, "bind_socket", uvicorn.config.Config.bind_socket)
    monkeypatch.setattr(cli, "tune_allocator", lambda: None)  # keep this process untouched
    monkeypatch.setattr(uvicorn, "run", lambda app, **kwargs: calls.append(kwargs))
    assert cli.main(["serve", *arguments]) == 0
    assert calls[0]["loop"] == loop
    assert calls[0]["workers"] == workers
