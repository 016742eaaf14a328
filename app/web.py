"""The browser calculator: the static page, its assets, plotly.js and security headers.

:func:`install_web` wires everything onto the API's :class:`~fastapi.FastAPI` app:

- ``GET /`` serves ``index.html`` (revalidated on every visit);
- ``/static/...`` serves the page's own CSS and JavaScript (revalidated with ETags);
- ``/vendor/plotly-<version>.min.js`` serves plotly.js from the installed ``plotly`` package,
  gzip-compressed once and cached by browsers for a year (the version in the path changes
  whenever the package does, so a stale copy is never used);
- :class:`SecurityHeadersMiddleware` adds CSP and the other hardening headers to every
  HTTP response, API routes and errors included.

Every URL the page uses is relative, so it also works behind a reverse-proxy prefix.
"""

from __future__ import annotations

import gzip
import importlib.metadata
import importlib.resources
import os
from functools import cache
from pathlib import Path

from fastapi import FastAPI, Request
from fastapi.staticfiles import StaticFiles
from starlette.responses import HTMLResponse, Response
from starlette.staticfiles import PathLike
from starlette.types import Scope

PLOTLY_PLACEHOLDER = "vendor/plotly.min.js"
"""The script path written in ``index.html``; replaced by the versioned path when served."""

CSP = (
    "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
    "img-src 'self' data: blob:; connect-src 'self'; font-src 'self'; object-src 'none'; "
    "base-uri 'none'; frame-ancestors 'none'; form-action 'self'"
)
"""Policy for every response: the page, the API and the self-hosted ``/docs``. Plotly
injects ``<style>`` elements, hence ``'unsafe-inline'`` for styles only; its PNG export
draws through ``data:`` images."""

SECURITY_HEADERS = (
    (b"content-security-policy", CSP.encode()),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"no-referrer"),
    (b"x-frame-options", b"DENY"),
    (b"cross-origin-opener-policy", b"same-origin"),
)

YEAR_CACHE = "public, max-age=31536000, immutable"


class _RevalidatedStaticFiles(StaticFiles):
    """Static files that browsers revalidate (ETag / Last-Modified) before each reuse."""

    def file_response(
        self,
        full_path: PathLike,
        stat_result: os.stat_result,
        scope: Scope,
        status_code: int = 200,
    ) -> Response:
        response = super().file_response(full_path, stat_result, scope, status_code)
        response.headers["Cache-Control"] = "no-cache"
        return response


def plotly_js_path() -> Path:
    """Path of ``plotly.min.js`` inside the installed ``plotly`` package."""
    resource = importlib.resources.files("plotly") / "package_data" / "plotly.min.js"
    return Path(str(resource))


def plotly_url_path() -> str:
    """URL path (relative to the app root) of plotly.js, versioned for long caching."""
    return f"vendor/plotly-{importlib.metadata.version('plotly')}.min.js"


@cache
def _plotly_js() -> tuple[bytes, bytes]:
    """plotly.min.js as (raw, gzip) bytes, read and compressed on first use."""
    raw = plotly_js_path().read_bytes()
    return raw, gzip.compress(raw, compresslevel=6, mtime=0)


def _plotly_response(request: Request) -> Response:
    raw, compressed = _plotly_js()
    headers = {"Cache-Control": YEAR_CACHE, "Vary": "Accept-Encoding"}
    if "gzip" in request.headers.get("accept-encoding", ""):
        headers["Content-Encoding"] = "gzip"
        return Response(compressed, media_type="text/javascript", headers=headers)
    return Response(raw, media_type="text/javascript", headers=headers)


def install_web(app: FastAPI, static_dir: Path) -> None:
    """Serve the calculator page from ``static_dir``.

    Every response's security headers (:data:`SECURITY_HEADERS`) are added by
    :class:`app.middleware.ServiceMiddleware`.

    ``index.html`` is read once, here: restart the server after editing it.
    """
    index_html = (static_dir / "index.html").read_text(encoding="utf-8")
    index_html = index_html.replace(PLOTLY_PLACEHOLDER, plotly_url_path())

    async def index(request: Request) -> Response:
        return HTMLResponse(index_html, headers={"Cache-Control": "no-cache"})

    app.add_route("/", index, methods=["GET"], include_in_schema=False)
    app.add_route(
        "/" + plotly_url_path(), _plotly_response, methods=["GET"], include_in_schema=False
    )
    app.mount("/static", _RevalidatedStaticFiles(directory=static_dir), name="static")
