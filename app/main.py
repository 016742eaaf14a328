"""The PMA calculator service: ``uvicorn app.main:app``."""

from __future__ import annotations

from pathlib import Path

from fastapi import FastAPI
from starlette.middleware.cors import CORSMiddleware
from starlette.middleware.gzip import DEFAULT_EXCLUDED_CONTENT_TYPES

from app.docs import install_docs
from app.errors import install_error_handlers
from app.middleware import MAX_BODY_BYTES, ServiceMiddleware
from app.responses import JSONResponse
from app.routes import calculations, design, export, reference
from app.settings import Settings
from app.web import SECURITY_HEADERS, install_web

_PACKAGED_STATIC = Path(__file__).parent / "static"
#: The page's files: packaged in the wheel as app/static, the repo's static/ in development.
STATIC_DIR = (
    _PACKAGED_STATIC if _PACKAGED_STATIC.is_dir() else Path(__file__).parent.parent / "static"
)

DESCRIPTION = """
Braided pneumatic muscle (McKibben) calculator implementing S. Davis and D. G. Caldwell,
"Braid Effects on Contractile Range and Friction Modeling in Pneumatic Muscle Actuators",
IJRR 25(4) 2006, doi:10.1177/0278364906063227.

SI units everywhere (`_m`, `_m2`, `_pa`, `_n`); angles in degrees (`_deg`). Bad input is a
422 whose `detail` names the field. Examples use the paper's braid: D_o = 31 mm,
D_s = 0.25 mm, N = 240, S = 3.
"""


#: Level 1: the 13 MB of a 100 000-point curve compress in ~0.1 s instead of ~1.7 s at
#: Starlette's default 9, for 6 % more bytes. .npy is raw float64: gzip would spend its time
#: for little gain.
GZIP_OPTIONS = {
    "minimum_size": 1024,
    "compresslevel": 1,
    "exclude_content_types": (*DEFAULT_EXCLUDED_CONTENT_TYPES, "application/x-npy"),
}


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the application from ``settings`` (default: the ``PMA_*`` environment)."""
    settings = settings or Settings.from_env()
    app = FastAPI(
        title="PMA Calculator",
        version="1.0.0",
        summary="Braid limits, strength, friction and hysteresis of pneumatic muscles",
        description=DESCRIPTION,
        default_response_class=JSONResponse,
        docs_url=None,
        redoc_url=None,
    )
    install_error_handlers(app)
    app.include_router(calculations.router)
    app.include_router(design.router)
    app.include_router(export.router)
    app.include_router(reference.router)
    install_docs(app)
    install_web(app, STATIC_DIR)
    _add_middleware(app, settings)
    return app


def _add_middleware(app: FastAPI, settings: Settings) -> None:
    if settings.cors_origins:
        app.add_middleware(
            CORSMiddleware,
            allow_origins=list(settings.cors_origins),
            allow_methods=["GET", "POST"],
            allow_headers=["Content-Type", "Accept"],
        )
    # Outermost, so every response, a 413 or a 500 included, gets its headers and an id.
    app.add_middleware(
        ServiceMiddleware,
        headers=SECURITY_HEADERS,
        max_body_bytes=MAX_BODY_BYTES,
        gzip_options=GZIP_OPTIONS,
    )


app = create_app()
