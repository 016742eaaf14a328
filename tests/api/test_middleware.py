"""Request ids, JSON access logs and the body-size limit."""

from __future__ import annotations

import asyncio
import json
import logging
import socket
from collections.abc import Iterator

import pytest
from fastapi import FastAPI, Request
from fastapi.testclient import TestClient
from starlette.responses import Response
from starlette.types import Receive, Scope, Send

from app.main import app
from app.middleware import MAX_BODY_BYTES, ServiceMiddleware

client = TestClient(app)
BODY = {"strand_diameter_m": 0.00025, "strand_count": 240, "theoretical_diameter_m": 0.031}


def test_every_response_has_a_request_id() -> None:
    ids = {client.post("/api/v1/min-braid-angle", json=BODY).headers["x-request-id"] for _ in "ab"}
    assert len(ids) == 2
    assert all(len(i) == 32 for i in ids)
    assert client.get("/nowhere").headers["x-request-id"]


def test_a_valid_client_request_id_is_kept_and_a_bad_one_replaced() -> None:
    kept = client.get("/healthz", headers={"X-Request-ID": "trace-42.a:b"})
    assert kept.headers["x-request-id"] == "trace-42.a:b"
    replaced = client.get("/healthz", headers={"X-Request-ID": "x" * 200})
    assert len(replaced.headers["x-request-id"]) == 32


def test_access_log_is_one_json_line_per_request(caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.INFO, logger="pma.access"):
        response = client.post("/api/v1/min-braid-angle", json=BODY)
    (record,) = [r for r in caplog.records if r.name == "pma.access"]
    entry = record.msg
    assert isinstance(entry, dict)
    assert entry["path"] == "/api/v1/min-braid-angle"
    assert entry["status"] == 200
    assert entry["request_id"] == response.headers["x-request-id"]
    assert entry["duration_ms"] >= 0
    json.dumps(entry)


def test_body_over_the_limit_is_refused_with_413() -> None:
    response = client.post(
        "/api/v1/min-braid-angle",
        content=b" " * (MAX_BODY_BYTES + 1),
        headers={"content-type": "application/json"},
    )
    assert response.status_code == 413
    assert response.json() == {"detail": f"request body larger than {MAX_BODY_BYTES} bytes"}
    assert response.headers["x-content-type-options"] == "nosniff"
    assert response.headers["x-request-id"]


def test_chunked_body_over_the_limit_is_refused_with_413() -> None:
    def chunks() -> Iterator[bytes]:
        for _ in range(MAX_BODY_BYTES // 1024 + 2):
            yield b" " * 1024

    response = client.post(
        "/api/v1/min-braid-angle",
        content=chunks(),
        headers={"content-type": "application/json"},
    )
    assert response.status_code == 413


def test_body_under_the_limit_passes() -> None:
    padded = json.dumps(BODY) + " " * (MAX_BODY_BYTES - 200)
    response = client.post(
        "/api/v1/min-braid-angle", content=padded, headers={"content-type": "application/json"}
    )
    assert response.status_code == 200


def test_chunked_413_carries_the_headers_and_says_the_limit() -> None:
    response = client.post(
        "/api/v1/min-braid-angle",
        content=iter([b" " * (MAX_BODY_BYTES + 1)]),
        headers={"content-type": "application/json"},
    )
    assert response.status_code == 413
    assert response.json() == {"detail": f"request body larger than {MAX_BODY_BYTES} bytes"}
    assert response.headers["x-content-type-options"] == "nosniff"


def test_chunked_body_under_the_limit_passes() -> None:
    chunks = [json.dumps(BODY).encode()[:10], json.dumps(BODY).encode()[10:]]
    response = client.post(
        "/api/v1/min-braid-angle",
        content=iter(chunks),
        headers={"content-type": "application/json"},
    )
    assert response.status_code == 200
    assert response.json()["min_braid_angle_deg"] == pytest.approx(19.0, abs=0.05)


def _echo_app() -> FastAPI:
    echo = FastAPI()

    @echo.post("/echo")
    async def echo_body(request: Request) -> Response:
        return Response(await request.body(), media_type="text/plain")

    return echo


def test_the_limit_is_the_one_configured() -> None:
    small = ServiceMiddleware(_echo_app(), max_body_bytes=100)
    with TestClient(small) as limited:
        assert limited.post("/echo", content=b"x" * 100).status_code == 200
        refused = limited.post("/echo", content=b"x" * 101)
        assert refused.status_code == 413
        assert refused.json() == {"detail": "request body larger than 100 bytes"}
        chunked = limited.post("/echo", content=iter([b"x" * 60, b"x" * 60]))
        assert chunked.status_code == 413


@pytest.mark.parametrize(
    ("accept_encoding", "compressed"),
    [("gzip", True), ("gzip, deflate, br", True), ("identity", False), ("br", False)],
)
def test_gzip_only_for_clients_that_accept_it(accept_encoding: str, compressed: bool) -> None:
    gzipped = ServiceMiddleware(_echo_app(), gzip_options={"minimum_size": 10})
    with TestClient(gzipped) as echo:
        response = echo.post(
            "/echo", content=b"a" * 5000, headers={"accept-encoding": accept_encoding}
        )
    assert response.status_code == 200
    assert response.content == b"a" * 5000  # httpx decodes gzip
    assert (response.headers.get("content-encoding") == "gzip") is compressed


def test_small_answers_are_not_gzipped() -> None:
    response = client.post(
        "/api/v1/min-braid-angle", json=BODY, headers={"accept-encoding": "gzip"}
    )
    assert "content-encoding" not in response.headers


def test_a_chunked_body_cut_off_at_the_limit_logs_no_error(
    caplog: pytest.LogCaptureFixture,
) -> None:
    with caplog.at_level(logging.WARNING):
        response = client.post(
            "/api/v1/min-braid-angle",
            content=iter([b" " * 1024] * (MAX_BODY_BYTES // 1024 + 2)),
            headers={"content-type": "application/json"},
        )
    assert response.status_code == 413
    assert [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING] == []


def _raw_http(url: str, head: bytes, body: bytes) -> bytes:
    """Send ``head`` and ``body`` as they are over a socket; return the status line."""
    host, port = url.removeprefix("http://").split(":")
    with socket.create_connection((host, int(port)), timeout=10) as conn:
        conn.sendall(head + body)
        return conn.makefile("rb").readline()


def test_a_length_beside_chunked_transfer_does_not_lift_the_limit(live_server: str) -> None:
    # h11 reads such a body as chunked: the small declared length must not be trusted.
    payload = b" " * (MAX_BODY_BYTES + 1)
    body = b"%x\r\n%s\r\n0\r\n\r\n" % (len(payload), payload)
    head = (
        b"POST /api/v1/min-braid-angle HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
        b"Content-Length: 5\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n"
    )
    assert _raw_http(live_server, head, body).startswith(b"HTTP/1.1 413")


def _asgi_scope(headers: list[tuple[bytes, bytes]]) -> dict[str, object]:
    return {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": "POST",
        "scheme": "http",
        "path": "/echo",
        "raw_path": b"/echo",
        "root_path": "",
        "query_string": b"",
        "headers": headers,
        "client": ("127.0.0.1", 50000),
        "server": ("127.0.0.1", 80),
    }


@pytest.mark.parametrize(
    "headers",
    [
        [(b"content-length", b"5"), (b"transfer-encoding", b"chunked")],
        [(b"transfer-encoding", b"chunked"), (b"content-length", b"5")],
        [(b"content-length", b"not a number")],
    ],
    ids=["length then chunked", "chunked then length", "garbage length"],
)
def test_a_body_whose_length_cannot_be_trusted_is_counted(
    headers: list[tuple[bytes, bytes]],
) -> None:
    middleware = ServiceMiddleware(_echo_app(), max_body_bytes=100)
    sent = _run_asgi(middleware, _asgi_scope(headers), [b"x" * 60, b"x" * 60])
    assert sent[0]["status"] == 413


def test_a_content_length_of_5000_digits_is_refused_not_crashed() -> None:
    scope = _asgi_scope([(b"content-length", b"9" * 5000)])
    sent = _run_asgi(ServiceMiddleware(_echo_app()), scope, [b""])
    assert sent[0]["status"] == 413


def _run_asgi(
    app: ServiceMiddleware, scope: dict[str, object], chunks: list[bytes]
) -> list[dict[str, object]]:
    """Drive ``app`` with a body of ``chunks``; return the messages it sent."""
    sent: list[dict[str, object]] = []
    pending = list(chunks)

    async def receive() -> dict[str, object]:
        body = pending.pop(0) if pending else b""
        return {"type": "http.request", "body": body, "more_body": bool(pending)}

    async def send(message: dict[str, object]) -> None:
        sent.append(message)

    asyncio.run(app(scope, receive, send))  # type: ignore[arg-type]
    return sent


@pytest.mark.parametrize(
    ("accept_encoding", "gzip_entered"),
    [
        ("gzip", True),
        ("deflate, gzip", True),
        ("gzip;q=0.5", True),
        ("gzip;q=0", False),
        ("identity, gzip; q=0", False),
        ("br", False),
        ("x-gzip-like", False),
    ],
)
def test_gzip_is_entered_only_when_accepted(accept_encoding: str, gzip_entered: bool) -> None:
    entered: list[str] = []
    middleware = ServiceMiddleware(_echo_app(), gzip_options={"minimum_size": 10})
    gzip = middleware.gzip

    async def recording_gzip(scope: Scope, receive: Receive, send: Send) -> None:
        entered.append(accept_encoding)
        await gzip(scope, receive, send)

    middleware.gzip = recording_gzip  # type: ignore[assignment]
    with TestClient(middleware) as echo:
        response = echo.post(
            "/echo", content=b"a" * 5000, headers={"accept-encoding": accept_encoding}
        )
    assert response.status_code == 200
    assert bool(entered) is gzip_entered
    assert (response.headers.get("content-encoding") == "gzip") is gzip_entered
