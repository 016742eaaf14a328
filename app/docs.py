"""OpenAPI documentation at ``/docs``, self-hosted: Swagger UI from the installed
``swagger-ui-bundle`` package, so the docs work offline and under a strict CSP (no CDN, no
inline script)."""

from __future__ import annotations

from fastapi import FastAPI, Request
from starlette.responses import HTMLResponse, Response
from starlette.staticfiles import StaticFiles
from swagger_ui_bundle import swagger_ui_path

# Relative URLs, so the docs also work behind a reverse-proxy prefix (PMA_ROOT_PATH).
_HTML = """<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>PMA Calculator API</title>
<link rel="stylesheet" href="docs/assets/swagger-ui.css">
<link rel="icon" type="image/png" href="docs/assets/favicon-32x32.png">
</head>
<body>
<div id="swagger-ui"></div>
<script src="docs/assets/swagger-ui-bundle.js"></script>
<script src="docs/init.js"></script>
</body>
</html>
"""

_INIT_JS = """window.ui = SwaggerUIBundle({
  url: "openapi.json",
  dom_id: "#swagger-ui",
  deepLinking: true,
  defaultModelsExpandDepth: 0,
  tryItOutEnabled: true,
});
"""


async def _docs(request: Request) -> Response:
    return HTMLResponse(_HTML)


async def _init_js(request: Request) -> Response:
    return Response(_INIT_JS, media_type="text/javascript")


def install_docs(app: FastAPI) -> None:
    """Serve Swagger UI for ``app``'s OpenAPI schema at ``/docs``."""
    app.add_route("/docs", _docs, methods=["GET"], include_in_schema=False)
    app.add_route("/docs/init.js", _init_js, methods=["GET"], include_in_schema=False)
    app.mount("/docs/assets", StaticFiles(directory=swagger_ui_path), name="docs-assets")
