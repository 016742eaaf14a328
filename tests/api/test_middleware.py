"""Request ids, JSON access logs and the body-size limit."""

from __future__ import annotations

import json
import logging
from collections.abc import Iterator

import pytest
from fastapi import FastAPI, Request
from fastapi.testclient import TestClient
from starlette.responses import Response

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
