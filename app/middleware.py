"""Pure ASGI middleware: one layer for headers, request ids, logs, the body limit, gzip, 500s.

Pure ASGI (not ``@app.middleware("http")``), so the per-request cost stays a few
microseconds: the decorator form costs about two thirds of the throughput.
"""

from __future__ import annotations

import json
import logging
import os
import re
import sys
import time
from collections.abc import Mapping, Sequence
from typing import Any

from starlette.middleware.gzip import GZipMiddleware
from starlette.types import ASGIApp, Message, Receive, Scope, Send

#: Largest request body accepted [bytes]. Every calculation body is under 1 KiB.
MAX_BODY_BYTES = 64 * 1024

_REQUEST_ID = re.compile(r"^[A-Za-z0-9._:-]{1,128}$")

_INTERNAL = json.dumps({"detail": "internal error"}).encode()

access_log = logging.getLogger("pma.access")
error_log = logging.getLogger("pma.error")


class ServiceMiddleware:
    """The one layer around the app: what every HTTP request and response goes through.

    - ``headers`` (the security headers) on every response, except one the response sets
      itself;
    - an ``X-Request-ID``: the client's own (1-128 of ``A-Z a-z 0-9 . _ : -``), so a request
      can be traced through a proxy, or a new one;
    - a body over ``max_body_bytes`` refused with 413 before it is parsed: a declared
      ``Content-Length`` without reading the body, a chunked body as soon as it passes;
    - gzip (Starlette's GZipMiddleware, with ``gzip_options``) entered only by requests
      that accept it: most API clients never ask, and skip it entirely;
    - an unexpected exception becomes a bare 500, no stack trace or internal path (the
      exception goes to the ``pma.error`` log);
    - one JSON line in the ``pma.access`` log.

    One layer for all of it, reading the request headers once: each pure-ASGI layer costs
    every request a few microseconds.
    """

    def __init__(
        self,
        app: ASGIApp,
        headers: Sequence[tuple[bytes, bytes]] = (),
        max_body_bytes: int = MAX_BODY_BYTES,
        gzip_options: Mapping[str, Any] | None = None,
    ) -> None:
        self.app = app
        self.headers = tuple(headers)
        self.max_body_bytes = max_body_bytes
        self.gzip = GZipMiddleware(app, **(gzip_options or {}))

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        request = _RequestHeaders(scope)
        extra = (*self.headers, (b"x-request-id", request.request_id))
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
            if request.content_length > self.max_body_bytes:
                await _refuse(send_with_headers, self.max_body_bytes)
                return
            inner = self.gzip if request.accepts_gzip else self.app
            if request.content_length >= 0:
                # The server holds the body to its declared length: nothing left to count.
                await inner(scope, receive, send_with_headers)
            else:
                await _counting_body(inner, self.max_body_bytes, scope, receive, send_with_headers)
        except Exception:
            error_log.exception("unhandled error on %s %s", scope["method"], scope["path"])
            if not started:
                await _send_json(send_with_headers, 500, _INTERNAL)
        finally:
            if access_log.isEnabledFor(logging.INFO):
                _log(scope, status, request.request_id, time.perf_counter() - start)


class _RequestHeaders:
    """What the middleware needs from the request headers, read in one pass.

    ``content_length`` is -1 when the body must be counted as it arrives: no length
    declared (chunked), or a ``Transfer-Encoding`` beside it (h11 then reads the body as
    chunked and the declared length means nothing), or a length that is not a number.
    """

    __slots__ = ("accepts_gzip", "content_length", "request_id")

    def __init__(self, scope: Scope) -> None:
        declared, chunked = -1, False
        self.accepts_gzip = False
        request_id = b""
        for name, value in scope["headers"]:
            if name == b"content-length":
                declared = _length(value)
            elif name == b"transfer-encoding":
                chunked = True
            elif name == b"accept-encoding":
                self.accepts_gzip = self.accepts_gzip or _accepts_gzip(value)
            elif name == b"x-request-id" and _REQUEST_ID.match(value.decode("latin-1")):
                request_id = bytes(value)
        self.content_length = -1 if chunked else declared
        self.request_id = request_id or os.urandom(16).hex().encode()


def _length(value: bytes) -> int:
    if not value.isdigit():
        return -1
    # More digits than any body could have: too large, without int() of a huge string.
    return int(value) if len(value) <= 18 else sys.maxsize


def _accepts_gzip(value: bytes) -> bool:
    """Whether an ``Accept-Encoding`` value accepts gzip: listed, and not with ``q=0``."""
    for coding in value.lower().split(b","):
        name, _, parameters = coding.partition(b";")
        if name.strip() != b"gzip":
            continue
        for parameter in parameters.split(b";"):
            key, _, weight = parameter.partition(b"=")
            if key.strip() == b"q":
                try:
                    return float(weight) > 0
                except ValueError:
                    return False
        return True
    return False


async def _counting_body(
    app: ASGIApp, max_bytes: int, scope: Scope, receive: Receive, send: Send
) -> None:
    """Run ``app`` on a chunked body, answering 413 as soon as it passes ``max_bytes``."""
    received = 0
    responded = False

    async def counting_receive() -> Message:
        nonlocal received, responded
        message = await receive()
        if message["type"] == "http.request":
            received += len(message.get("body", b""))
            if received > max_bytes:
                # Answer now and tell the app the client left: it stops reading.
                if not responded:
                    responded = True
                    await _refuse(send, max_bytes)
                return {"type": "http.disconnect"}
        return message

    async def guarded_send(message: Message) -> None:
        nonlocal responded
        if message["type"] == "http.response.start":
            if responded:
                return
            responded = True
        elif responded and received > max_bytes:
            return
        await send(message)

    await app(scope, counting_receive, guarded_send)


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


async def _refuse(send: Send, max_bytes: int) -> None:
    detail = {"detail": f"request body larger than {max_bytes} bytes"}
    await _send_json(send, 413, json.dumps(detail).encode())


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
