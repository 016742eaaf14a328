"""Process-level tuning for ``pma-calculator serve``: the allocator and uvicorn's listener.

Both were found by the benchmarks (BENCHMARKS.md): without them the 10^6-point chain spends
most of its time in page faults, and ``--workers 2`` is slower than one worker.
"""

from __future__ import annotations

import asyncio
import ctypes
import ctypes.util
import os
import socket
from typing import Any

import uvicorn.config

#: glibc malloc settings: keep freed numpy buffers (up to 32 MiB each) in the process
#: instead of unmapping them and faulting them back in, page by page, on the next call.
#: The cost: resident memory stays at its high-water mark (about 120 MiB in the soak).
MALLOC_SETTINGS = {
    "MALLOC_MMAP_THRESHOLD_": 32 << 20,
    "MALLOC_TRIM_THRESHOLD_": 256 << 20,
    "MALLOC_TOP_PAD_": 64 << 20,
}
_MALLOPT_PARAMS = {  # glibc's malloc.h
    "MALLOC_TRIM_THRESHOLD_": -1,
    "MALLOC_TOP_PAD_": -2,
    "MALLOC_MMAP_THRESHOLD_": -3,
}


def tune_allocator() -> None:
    """Apply :data:`MALLOC_SETTINGS` here (mallopt) and to worker processes (environment).

    A setting already in the environment wins. Does nothing where libc is not glibc.
    """
    for name, value in MALLOC_SETTINGS.items():
        os.environ.setdefault(name, str(value))
    path = ctypes.util.find_library("c")
    libc = ctypes.CDLL(path) if path else None
    mallopt = getattr(libc, "mallopt", None)
    if mallopt is None:
        return
    for name, param in _MALLOPT_PARAMS.items():
        mallopt(ctypes.c_int(param), ctypes.c_int(int(os.environ[name])))


_uvicorn_bind_socket = uvicorn.config.Config.bind_socket


def _bind_tcp_socket(self: uvicorn.config.Config) -> socket.socket:
    """uvicorn's listener re-wrapped as IPPROTO_TCP (same file descriptor).

    With ``workers > 1`` uvicorn binds the socket with ``proto`` 0; asyncio sets
    TCP_NODELAY only on IPPROTO_TCP sockets, so every keep-alive response would wait
    ~40 ms for the client's delayed ACK (uvicorn issue #3149).
    """
    sock = _uvicorn_bind_socket(self)
    if sock.family in (socket.AF_INET, socket.AF_INET6) and sock.proto == 0:
        sock = socket.socket(sock.family, sock.type, socket.IPPROTO_TCP, fileno=sock.detach())
    return sock


def enable_tcp_nodelay_for_workers() -> None:
    """Make uvicorn's multi-worker listener IPPROTO_TCP, so connections get TCP_NODELAY."""
    uvicorn.config.Config.bind_socket = _bind_tcp_socket  # type: ignore[method-assign]


class FairAcceptEventLoop(asyncio.SelectorEventLoop):
    """An asyncio loop that accepts one connection each time the listener is ready.

    asyncio accepts up to ``backlog`` (uvicorn: 2048) waiting connections per wake-up. With
    several workers on one listening socket, whichever wakes first takes a whole burst of
    connections and keeps them while they live: a client or proxy that opens its keep-alive
    pool at once lands on one worker, and ``--workers 2`` is no faster than one. Taking one
    connection per wake-up lets every worker take its turn, as nginx does by default
    (``multi_accept off``). Used by ``pma-calculator serve`` with more than one worker, in
    place of uvicorn's ``auto`` loop (so uvloop, if installed, is not used then).
    """

    def _accept_connection(
        self,
        protocol_factory: Any,
        sock: socket.socket,
        sslcontext: Any = None,
        server: Any = None,
        backlog: int = 100,
        *timeouts: Any,
        **options: Any,
    ) -> None:
        super()._accept_connection(  # type: ignore[misc]
            protocol_factory, sock, sslcontext, server, 1, *timeouts, **options
        )
