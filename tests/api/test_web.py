"""The calculator page, its assets, plotly.js and the security headers (app/web.py).

``client`` (tests/api/conftest.py) is the whole app in process.
"""

from __future__ import annotations

import re

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from starlette.responses import PlainTextResponse

from app.middleware import ServiceMiddleware
from app.web import CSP, SECURITY_HEADERS, plotly_js_path, plotly_url_path

HARDENING = {
    "x-content-type-options": "nosniff",
    "referrer-policy": "no-referrer",
    "x-frame-options": "DENY",
    "cross-origin-opener-policy": "same-origin",
}


@pytest.mark.parametrize(
    ("method", "path", "status"),
    [
        ("GET", "/", 200),
        ("GET", "/docs", 200),
        ("GET", "/healthz", 200),
        ("GET", "/api/v1/materials", 200),
        ("POST", "/api/v1/design", 422),
        ("GET", "/no/such/page", 404),
        ("GET", "/static/app.js", 200),
    ],
)
def test_every_response_carries_the_security_headers(
    client: TestClient, method: str, path: str, status: int
) -> None:
    response = client.request(method, path, json={} if method == "POST" else None)
    assert response.status_code == status
    assert response.headers["content-security-policy"] == CSP
    for name, value in HARDENING.items():
        assert response.headers[name] == value


def test_middleware_keeps_a_header_the_response_sets_itself() -> None:
    inner = FastAPI()

    @inner.get("/own")
    def own() -> PlainTextResponse:
        return PlainTextResponse("x", headers={"Referrer-Policy": "same-origin"})

    inner.add_middleware(ServiceMiddleware, headers=SECURITY_HEADERS)
    response = TestClient(inner).get("/own")
    assert response.headers.get_list("referrer-policy") == ["same-origin"]
    assert response.headers["content-security-policy"] == CSP


def test_index_is_html_revalidated_and_answers_head(client: TestClient) -> None:
    response = client.get("/")
    assert response.headers["content-type"].startswith("text/html")
    assert response.headers["cache-control"] == "no-cache"
    assert client.head("/").status_code == 200


def test_index_loads_nothing_from_other_hosts(client: TestClient) -> None:
    html = client.get("/").text
    assert "http://" not in html
    assert "https://" not in html
    references = re.findall(r'(?:src|href)="([^"]*)"', html)
    assert references, "the page references its assets"
    assert not [ref for ref in references if ref.startswith("//")]


def test_index_references_the_versioned_plotly(client: TestClient) -> None:
    html = client.get("/").text
    assert f'src="{plotly_url_path()}"' in html


def test_plotly_is_served_from_the_installed_package(client: TestClient) -> None:
    response = client.get("/" + plotly_url_path(), headers={"Accept-Encoding": "identity"})
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/javascript")
    assert "immutable" in response.headers["cache-control"]
    assert "max-age=31536000" in response.headers["cache-control"]
    assert "content-encoding" not in response.headers
    assert response.content == plotly_js_path().read_bytes()


def test_plotly_is_sent_gzip_compressed_when_accepted(client: TestClient) -> None:
    response = client.get("/" + plotly_url_path(), headers={"Accept-Encoding": "gzip"})
    assert response.headers["content-encoding"] == "gzip"
    assert response.headers["vary"] == "Accept-Encoding"
    assert int(response.headers["content-length"]) < plotly_js_path().stat().st_size / 2
    assert response.content == plotly_js_path().read_bytes()  # httpx decodes gzip


@pytest.mark.parametrize(
    ("path", "content_types"),
    [
        # Python's mimetypes says text/javascript (RFC 9239) or, on older tables,
        # application/javascript: browsers run module scripts served as either.
        ("/static/app.js", ("text/javascript", "application/javascript")),
        ("/static/style.css", ("text/css",)),
    ],
)
def test_page_assets_are_served_and_revalidated(
    client: TestClient, path: str, content_types: tuple[str, ...]
) -> None:
    response = client.get(path)
    assert response.status_code == 200
    assert response.headers["content-type"].startswith(content_types)
    assert response.headers["cache-control"] == "no-cache"
    etag = response.headers["etag"]
    assert client.get(path, headers={"If-None-Match": etag}).status_code == 304
