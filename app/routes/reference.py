"""Reference data: health, material presets."""

from __future__ import annotations

from dataclasses import asdict

from fastapi import APIRouter

from app.responses import JSONResponse
from app.schemas import HealthOut, MaterialsOut, ReferenceOut
from pma_core import reference
from pma_core.materials import MATERIALS

router = APIRouter(default_response_class=JSONResponse)


@router.get("/healthz", tags=["service"], response_model=HealthOut)
async def healthz() -> JSONResponse:
    """Liveness: 200 while the service answers."""
    return JSONResponse({"status": "ok"})


@router.get("/api/v1/materials", tags=["reference"], response_model=MaterialsOut)
async def materials() -> JSONResponse:
    """Braid material presets with the source of every number."""
    return JSONResponse({"materials": [asdict(m) for m in MATERIALS.values()]})


@router.get("/api/v1/reference", tags=["reference"], response_model=ReferenceOut)
async def published_values() -> JSONResponse:
    """The paper's measured data: its braid, Table 1 and the fitted S_scale values."""
    return JSONResponse(
        {
            "braid_sample": reference.BRAID_SAMPLE,
            "test_muscle": reference.TEST_MUSCLE,
            "min_braid_angle_table1": [asdict(row) for row in reference.TABLE_1],
            "s_scale_fitted": [asdict(fit) for fit in reference.S_SCALE_FITS],
        }
    )
