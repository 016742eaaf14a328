"""Pure ASGI middleware: headers, request ids, logs, the 500 of last resort, the body limit.

Pure ASGI (not ``@app.middleware("http")``), so the per-request cost stays a few
microseconds: the decorator form costs about two thirds of the throughput.
"""

from __future__ import annotations

import json
import logging
import os
import re
import time
from collections.abc import Sequence

from starlette.middleware.gzip import DEFAULT_EXCLUDED_CONTENT_TYPES, GZipMiddleware
from starlette.types import ASGIApp, Message, Receive, Scope, Send

#: Largest request body accepted [bytes]. Every calculation body is under 1 KiB.
MAX_BODY_BYTES = 64 * 1024

_REQUEST_ID = re.compile(r"^[A-Za-z0-9._:-]{1,128}$")
_TOO_LARGE = json.dumps({"detail": f"request body larger than {MAX_BODY_BYTES} bytes"}).encode()

_INTERNAL = json.dumps({"detail": "internal error"}).encode()

access_log = logging.getLogger("pma.access")
error_log = logging.getLogger("pma.error")


class ServiceMiddleware:
    """The outermost layer: what every HTTP response carries, whatever produced it.

    - ``headers`` (the security headers), except one the response sets itself;
    - an ``X-Request-ID``: the client's own (1-128 of ``A-Z a-z 0-9 . _ : -``), so a request
      can be traced through a proxy, or a new one;
    - an unexpected exception becomes a bare 500, no stack trace or internal path (the
      exception goes to the ``pma.error`` log);
    - one JSON line in the ``pma.access`` log.

    One layer for all four: each pure-ASGI layer costs every request a few microseconds.
    """

    def __init__(self, app: ASGIApp, headers: Sequence[tuple[bytes, bytes]] = ()) -> None:
        self.app = app
        self.headers = tuple(headers)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        request_id = _request_id(scope)
        extra = (*self.headers, (b"x-request-id", request_id))
        start = time.perf_counter()
        status = 500
        started = False

        async def send_with_headers(message: Message) -> None:
            nonlocal status, started
            if message["type"] == "http.response.start":
                status, started = message["status"], True
                headers = list(message.get("headers", ()))
                present = {name for name, _ in headers}
                headers.extend(header for header in extra if header[0] not in present)
                message["headers"] = headers
            await send(message)

        try:
            await self.app(scope, receive, send_with_headers)
        except Exception:
            error_log.exception("unhandled error on %s %s", scope["method"], scope["path"])
            if not started:
                await _send_json(send_with_headers, 500, _INTERNAL)
        finally:
            if access_log.isEnabledFor(logging.INFO):
                _log(scope, status, request_id, time.perf_counter() - start)


def _request_id(scope: Scope) -> bytes:
    for name, value in scope["headers"]:
        if name == b"x-request-id" and _REQUEST_ID.match(value.decode("latin-1")):
            return bytes(value)
    return os.urandom(16).hex().encode()


def _log(scope: Scope, status: int, request_id: bytes, seconds: float) -> None:
    client = scope.get("client")
    access_log.info(
        {
            "event": "request",
            "method": scope["method"],
            "path": scope["path"],
            "status": status,
            "duration_ms": round(seconds * 1e3, 3),
            "request_id": request_id.decode(),
            "client": f"{client[0]}:{client[1]}" if client else None,
        }
    )


class BodyLimitMiddleware:
    """Refuse request bodies over :data:`MAX_BODY_BYTES` with 413, before they are parsed.

    A declared ``Content-Length`` over the limit is refused without reading the body; a
    chunked body is counted as it arrives and refused as soon as it passes the limit.
    """

    def __init__(self, app: ASGIApp, max_bytes: int = MAX_BODY_BYTES) -> None:
        self.app = app
        self.max_bytes = max_bytes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        declared = _declared_length(scope)
        if declared > self.max_bytes:
            await _refuse(send)
            return
        if declared >= 0:
            # The server holds the body to its declared length: nothing left to count.
            await self.app(scope, receive, send)
            return
        received = 0
        responded = False

        async def counting_receive() -> Message:
            nonlocal received, responded
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.max_bytes:
                    # Answer now and tell the app the client left: it stops reading.
                    if not responded:
                        responded = True
                        await _refuse(send)
                    return {"type": "http.disconnect"}
            return message

        async def guarded_send(message: Message) -> None:
            nonlocal responded
            if message["type"] == "http.response.start":
                if responded:
                    return
                responded = True
            elif responded and received > self.max_bytes:
                return
            await send(message)

        await self.app(scope, counting_receive, guarded_send)


def _declared_length(scope: Scope) -> int:
    """The request's Content-Length, or -1 when it declares none (chunked)."""
    for name, value in scope["headers"]:
        if name == b"content-length":
            return int(value) if value.isdigit() else -1
    return -1


async def _refuse(send: Send) -> None:
    await _send_json(send, 413, _TOO_LARGE)


async def _send_json(send: Send, status: int, body: bytes) -> None:
    await send(
        {
            "type": "http.response.start",
            "status": status,
            "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(body)).encode()),
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})


class GzipWhenAcceptedMiddleware:
    """Starlette's GZipMiddleware, entered only by requests that accept gzip.

    Starlette wraps every response, gzip or not; most API clients never ask for gzip, so
    their requests skip that layer entirely.
    """

    def __init__(
        self,
        app: ASGIApp,
        minimum_size: int = 1024,
        compresslevel: int = 1,
        exclude_content_types: tuple[str, ...] = DEFAULT_EXCLUDED_CONTENT_TYPES,
    ) -> None:
        self.app = app
        self.gzip = GZipMiddleware(
            app,
            minimum_size=minimum_size,
            compresslevel=compresslevel,
            exclude_content_types=exclude_content_types,
        )

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http" and _accepts_gzip(scope):
            await self.gzip(scope, receive, send)
        else:
            await self.app(scope, receive, send)


def _accepts_gzip(scope: Scope) -> bool:
    return any(name == b"accept-encoding" and b"gzip" in value for name, value in scope["headers"])
