"""The baseline of the service benchmarks: a FastAPI app whose endpoint returns a constant.

``uvicorn bench.baseline_app:app``: ``POST /baseline`` answers the same keys and roughly the
same bytes as ``POST /api/v1/min-braid-angle`` without reading the body, validating or
computing anything. What the calculator costs on top of it is validation, the model and
its middleware (GZip, security headers).
"""

from __future__ import annotations

from fastapi import FastAPI

#: The min-braid-angle answer for the paper's braid, as a constant.
CONSTANT: dict[str, float | None] = {
    "min_braid_angle_deg": 19.015351269944116,
    "max_braid_angle_deg": 54.735610317245346,
    "jamming_angle_deg": 70.9846487300559,
    "max_contraction": 0.3893260549041445,
    "theoretical_diameter_m": 0.031,
    "max_length_m": None,
    "min_length_m": None,
    "stroke_m": None,
}

app = FastAPI(title="bench baseline", docs_url=None, redoc_url=None, openapi_url=None)


@app.post("/baseline")
async def baseline() -> dict[str, float | None]:
    """The constant dict."""
    return CONSTANT


@app.get("/healthz")
async def healthz() -> dict[str, str]:
    """Readiness for the benchmark's start-up wait."""
    return {"status": "ok"}
