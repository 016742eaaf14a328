"""Fixtures of the client tests: a real ``uvicorn app.main:app`` on a free loopback port.

``pma`` runs each test twice: with :class:`PMAClient`, and with :class:`AsyncPMAClient`
whose coroutines run on one asyncio event loop. Natively async tests use anyio's pytest
plugin (``@pytest.mark.anyio``), installed with httpx.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Iterator
from typing import Any, cast

import pytest

from pma_client import AsyncPMAClient, PMAClient
from tests.published import DavisCaldwell2006


@pytest.fixture(scope="session")
def server_url(live_server: str) -> str:
    """URL of the session's real uvicorn (see ``tests/conftest.py``)."""
    return live_server


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
