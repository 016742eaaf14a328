"""The sync and async clients: the same methods, made from the endpoint descriptions."""

from __future__ import annotations

import inspect
import json
from collections.abc import Callable, Coroutine
from importlib import metadata
from types import TracebackType
from typing import Any, Concatenate, ParamSpec, Self, TypeVar

import httpx
import numpy as np

from pma_client import _endpoints as endpoints
from pma_client._endpoints import Call
from pma_client._errors import error_for

P = ParamSpec("P")
T = TypeVar("T")

#: Where ``pma-calculator serve`` listens by default.
DEFAULT_BASE_URL = "http://127.0.0.1:8000"
#: Timeout of every request the client makes, unless another is given.
DEFAULT_TIMEOUT = httpx.Timeout(30.0)


def _version() -> str:
    try:
        return metadata.version("pma-calculator")
    except metadata.PackageNotFoundError:
        return "0+unknown"


_HEADERS = {"accept": "application/json", "user-agent": f"pma-client/{_version()}"}
_JSON_HEADERS = {**_HEADERS, "content-type": "application/json"}


def _json_default(value: object) -> object:
    # numpy scalars (np.int64 from np.arange, np.float32, 0-d arrays) as plain numbers.
    if isinstance(value, np.generic) or (isinstance(value, np.ndarray) and value.ndim == 0):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not a JSON number, string or boolean")


def _encode(body: object) -> bytes:
    # NaN and infinities are written as such (not valid JSON, but Python's and the service's
    # parser read them), so the service refuses them with a 422 naming the field.
    return json.dumps(body, default=_json_default, separators=(",", ":")).encode()


def _parse(call: Call[T], response: httpx.Response) -> T:
    """The result of ``call`` from ``response``, or the exception its status calls for."""
    if not response.is_success:
        raise error_for(response)
    try:
        content = response.json() if call.decode is None else call.decode(response.content)
        return call.parse(content)
    except (ValueError, KeyError, TypeError) as problem:
        raise error_for(response, f"unexpected response ({problem!r})") from problem


class _Base:
    """What both clients share: the base URL, the requests, reading the responses."""

    _http: httpx.Client | httpx.AsyncClient
    _owns_http: bool

    def __init__(
        self,
        base_url: str,
        timeout: float | httpx.Timeout | None,
        client: object | None,
        transport: object | None,
    ) -> None:
        if client is not None and (transport is not None or timeout is not DEFAULT_TIMEOUT):
            raise ValueError(
                "give timeout and transport to the httpx client you pass, not to the PMA client"
            )
        self.base_url = base_url.rstrip("/")

    def _request(self, call: Call[Any]) -> httpx.Request:
        url = self.base_url + call.path
        if call.body is None:
            return self._http.build_request(call.method, url, headers=_HEADERS)
        content = _encode(call.body)
        return self._http.build_request(call.method, url, content=content, headers=_JSON_HEADERS)

    @property
    def is_closed(self) -> bool:
        """Whether the underlying httpx client is closed."""
        return self._http.is_closed

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.base_url!r})"


def _signature(build: Callable[..., Any]) -> inspect.Signature:
    """``build``'s keyword parameters after ``self``, for ``help()`` and ``inspect``."""
    signature = inspect.signature(build)
    first = inspect.Parameter("self", inspect.Parameter.POSITIONAL_ONLY)
    return signature.replace(
        parameters=[first, *signature.parameters.values()],
        return_annotation=inspect.Signature.empty,
    )


def _describe(method: Callable[..., Any], build: Callable[..., Any], owner: str) -> None:
    method.__name__ = build.__name__
    method.__qualname__ = f"{owner}.{build.__name__}"
    method.__doc__ = build.__doc__
    method.__module__ = "pma_client"
    method.__signature__ = _signature(build)  # type: ignore[attr-defined]


def _sync(build: Callable[P, Call[T]]) -> Callable[Concatenate[PMAClient, P], T]:
    """A :class:`PMAClient` method that makes the call ``build`` describes."""

    def method(self: PMAClient, /, *args: P.args, **kwargs: P.kwargs) -> T:
        return self._send(build(*args, **kwargs))

    _describe(method, build, "PMAClient")
    return method


def _async(
    build: Callable[P, Call[T]],
) -> Callable[Concatenate[AsyncPMAClient, P], Coroutine[Any, Any, T]]:
    """An :class:`AsyncPMAClient` coroutine method that makes the call ``build`` describes."""

    async def method(self: AsyncPMAClient, /, *args: P.args, **kwargs: P.kwargs) -> T:
        return await self._send(build(*args, **kwargs))

    _describe(method, build, "AsyncPMAClient")
    return method


class PMAClient(_Base):
    """Blocking client of the PMA calculator's HTTP API, over :class:`httpx.Client`.

    One method per endpoint; its keyword arguments are the JSON fields, in SI units.

    Parameters
    ----------
    base_url : str
        The service's root URL, including any path prefix it is served under.
    timeout : float or httpx.Timeout or None
        Timeout of each request [s]; None waits forever. Default 30 s.
    client : httpx.Client, optional
        An httpx client to send the requests with (its headers, proxies, timeout and
        transport apply); the caller keeps it and closes it. Not with ``timeout`` or
        ``transport``.
    transport : httpx.BaseTransport, optional
        Transport for the client made here, e.g. :class:`httpx.MockTransport` in tests.

    Raises
    ------
    ValueError
        ``client`` was given with ``timeout`` or ``transport``.

    Notes
    -----
    Network failures and timeouts raise httpx's exceptions (:class:`httpx.TransportError`);
    a refusal raises :class:`PMAValidationError`, any other error status :class:`PMAError`.
    """

    _http: httpx.Client

    def __init__(
        self,
        base_url: str = DEFAULT_BASE_URL,
        *,
        timeout: float | httpx.Timeout | None = DEFAULT_TIMEOUT,
        client: httpx.Client | None = None,
        transport: httpx.BaseTransport | None = None,
    ) -> None:
        super().__init__(base_url, timeout, client, transport)
        self._owns_http = client is None
        self._http = (
            httpx.Client(timeout=timeout, transport=transport) if client is None else client
        )

    def _send(self, call: Call[T]) -> T:
        return _parse(call, self._http.send(self._request(call)))

    def close(self) -> None:
        """Close the connections, unless the httpx client was passed in."""
        if self._owns_http:
            self._http.close()

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()

    health = _sync(endpoints.health)
    min_braid_angle = _sync(endpoints.min_braid_angle)
    gap_area = _sync(endpoints.gap_area)
    failure_strand_count = _sync(endpoints.failure_strand_count)
    s_scale = _sync(endpoints.s_scale)
    hysteresis = _sync(endpoints.hysteresis)
    design = _sync(endpoints.design)
    strand_count_sweep = _sync(endpoints.strand_count_sweep)
    pressure_sweep = _sync(endpoints.pressure_sweep)
    opensim_export = _sync(endpoints.opensim_export)
    hysteresis_sweep = _sync(endpoints.hysteresis_sweep)
    materials = _sync(endpoints.materials)
    reference = _sync(endpoints.reference)


class AsyncPMAClient(_Base):
    """Asynchronous client of the PMA calculator's HTTP API, over :class:`httpx.AsyncClient`.

    The methods of :class:`PMAClient`, as coroutines.

    Parameters
    ----------
    base_url : str
        The service's root URL, including any path prefix it is served under.
    timeout : float or httpx.Timeout or None
        Timeout of each request [s]; None waits forever. Default 30 s.
    client : httpx.AsyncClient, optional
        An httpx client to send the requests with; the caller keeps it and closes it.
        Not with ``timeout`` or ``transport``.
    transport : httpx.AsyncBaseTransport, optional
        Transport for the client made here, e.g. :class:`httpx.MockTransport` in tests.

    Raises
    ------
    ValueError
        ``client`` was given with ``timeout`` or ``transport``.
    """

    _http: httpx.AsyncClient

    def __init__(
        self,
        base_url: str = DEFAULT_BASE_URL,
        *,
        timeout: float | httpx.Timeout | None = DEFAULT_TIMEOUT,
        client: httpx.AsyncClient | None = None,
        transport: httpx.AsyncBaseTransport | None = None,
    ) -> None:
        super().__init__(base_url, timeout, client, transport)
        self._owns_http = client is None
        self._http = (
            httpx.AsyncClient(timeout=timeout, transport=transport) if client is None else client
        )

    async def _send(self, call: Call[T]) -> T:
        return _parse(call, await self._http.send(self._request(call)))

    async def close(self) -> None:
        """Close the connections, unless the httpx client was passed in."""
        if self._owns_http:
            await self._http.aclose()

    aclose = close

    async def __aenter__(self) -> Self:
        return self

    async def __aexit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        await self.close()

    health = _async(endpoints.health)
    min_braid_angle = _async(endpoints.min_braid_angle)
    gap_area = _async(endpoints.gap_area)
    failure_strand_count = _async(endpoints.failure_strand_count)
    s_scale = _async(endpoints.s_scale)
    hysteresis = _async(endpoints.hysteresis)
    design = _async(endpoints.design)
    strand_count_sweep = _async(endpoints.strand_count_sweep)
    pressure_sweep = _async(endpoints.pressure_sweep)
    opensim_export = _async(endpoints.opensim_export)
    hysteresis_sweep = _async(endpoints.hysteresis_sweep)
    materials = _async(endpoints.materials)
    reference = _async(endpoints.reference)
