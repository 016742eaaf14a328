"""Security: CORS closed unless configured, no internals in any error."""

from __future__ import annotations

from fastapi import FastAPI
from fastapi.testclient import TestClient

from app.main import create_app
from app.settings import Settings

PREFLIGHT = {
    "Origin": "https://lab.example",
    "Access-Control-Request-Method": "POST",
    "Access-Control-Request-Headers": "content-type",
}


def test_cors_is_closed_by_default() -> None:
    client = TestClient(create_app(Settings()))
    response = client.get("/healthz", headers={"Origin": "https://lab.example"})
    assert "access-control-allow-origin" not in response.headers
    assert client.options("/api/v1/s-scale", headers=PREFLIGHT).status_code == 405


def test_cors_opens_only_for_configured_origins() -> None:
    client = TestClient(create_app(Settings(cors_origins=("https://lab.example",))))
    allowed = client.options("/api/v1/s-scale", headers=PREFLIGHT)
    assert allowed.status_code == 200
    assert allowed.headers["access-control-allow-origin"] == "https://lab.example"
    other = client.get("/healthz", headers={"Origin": "https://evil.example"})
    assert "access-control-allow-origin" not in other.headers


def _broken_app() -> FastAPI:
    app = create_app(Settings())

    @app.get("/boom")
    async def boom() -> None:
        raise RuntimeError("secret at /work/main/app/internal.py line 3")

    return app


def test_unexpected_errors_reveal_nothing() -> None:
    client = TestClient(_broken_app(), raise_server_exceptions=False)
    response = client.get("/boom")
    assert response.status_code == 500
    assert response.json() == {"detail": "internal error"}
    assert "secret" not in response.text
    assert response.headers["x-request-id"]
    assert response.headers["content-security-policy"].startswith("default-src 'self'")
