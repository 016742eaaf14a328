"""Process tuning of pma-calculator serve: TCP_NODELAY with workers, allocator settings."""

from __future__ import annotations

import os
import socket

import pytest
import uvicorn.config

from app import server


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
