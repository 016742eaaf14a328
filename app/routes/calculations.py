"""The five v1 calculations of API.md: JSON in, pma_core, JSON out."""

from __future__ import annotations

from typing import Annotated, Any, Literal

import numpy as np
import numpy.typing as npt
from fastapi import APIRouter, Header, Query
from starlette.responses import Response

from app.errors import core_errors
from app.responses import (
    CSVResponse,
    JSONResponse,
    NPYResponse,
    csv_bytes,
    npy_record,
    npy_table,
)
from app.routing import JSONBodyRoute
from app.schemas import (
    FailureStrandCountIn,
    FailureStrandCountOut,
    GapAreaIn,
    GapAreaOut,
    HysteresisIn,
    HysteresisOut,
    MinBraidAngleIn,
    MinBraidAngleOut,
    SScaleIn,
    SScaleOut,
)
from pma_core import braid, friction, gap, strength
from pma_core.hysteresis import HysteresisCurves, hysteresis_curves

router = APIRouter(
    prefix="/api/v1",
    tags=["calculations"],
    default_response_class=JSONResponse,
    route_class=JSONBodyRoute,
)


def _deg(rad: Any) -> float:
    return float(np.degrees(rad))


@router.post("/min-braid-angle", response_model=MinBraidAngleOut)
async def min_braid_angle(body: MinBraidAngleIn) -> JSONResponse:
    """Minimum braid angle θ_min (eq 8), the angle range and the contractile range (eq 9)."""
    with core_errors(MinBraidAngleIn.model_fields):
        geo = body.geometry()
        limits = braid.braid_limits(
            body.strand_diameter_m,
            body.strand_count,
            geo.theoretical_diameter_m,
            geo.strand_length_m,
        )
    return JSONResponse(
        {
            "min_braid_angle_deg": _deg(limits.min_braid_angle_rad),
            "max_braid_angle_deg": _deg(limits.max_braid_angle_rad),
            "jamming_angle_deg": _deg(limits.jamming_angle_rad),
            "max_contraction": float(limits.max_contraction),
            "theoretical_diameter_m": geo.theoretical_diameter_m,
            "max_length_m": _float_or_none(limits.max_length_m),
            "min_length_m": _float_or_none(limits.min_length_m),
            "stroke_m": _float_or_none(limits.stroke_m),
        }
    )


def _float_or_none(value: Any) -> float | None:
    return None if value is None else float(value)


@router.post("/gap-area", response_model=GapAreaOut)
async def gap_area(body: GapAreaIn) -> JSONResponse:
    """Node spacing G (eq 12), gap width Z (eq 14) and gap area at θ, and the 45° maximum."""
    with core_errors(GapAreaIn.model_fields):
        d_o = body.geometry().theoretical_diameter_m
        args = (d_o, body.strand_diameter_m, body.strand_count, body.parallel_strands)
        theta = np.radians(body.braid_angle_deg)
        width = float(gap.gap_width(*args, theta))
        area = float(gap.gap_area(*args, theta))
        spacing = float(gap.node_spacing(d_o, body.strand_count, body.parallel_strands, theta))
        max_area = float(gap.max_gap_area(*args))
    return JSONResponse(
        {
            "braid_angle_deg": body.braid_angle_deg,
            "node_spacing_m": spacing,
            "gap_width_m": width,
            "gap_area_m2": area,
            "max_gap_area_m2": max_area,
        }
    )


@router.post("/failure-strand-count", response_model=FailureStrandCountOut)
async def failure_strand_count(body: FailureStrandCountIn) -> JSONResponse:
    """Fewest strands that hold the pressure (eq 20), at θ and at the 45° worst case."""
    with core_errors(FailureStrandCountIn.model_fields):
        d_o = body.geometry().theoretical_diameter_m
        args = (body.pressure_pa, d_o, body.strand_diameter_m, body.tensile_strength_pa)
        angles = [np.radians(body.braid_angle_deg), strength.WORST_CASE_BRAID_ANGLE_RAD]
        exact = strength.failure_strand_count(*args, angles, body.safety_factor)
        whole = strength.min_strand_count(exact)
    return JSONResponse(
        {
            "braid_angle_deg": body.braid_angle_deg,
            "min_strand_count_exact": float(exact[0]),
            "min_strand_count": int(whole[0]),
            "worst_case_braid_angle_deg": _deg(strength.WORST_CASE_BRAID_ANGLE_RAD),
            "worst_case_min_strand_count_exact": float(exact[1]),
            "worst_case_min_strand_count": int(whole[1]),
        }
    )


@router.post("/s-scale", response_model=SScaleOut)
async def s_scale(body: SScaleIn) -> JSONResponse:
    """Contact scale factor S_scale (eq 34) from the Hertz radius of two spheres (eq 33)."""
    with core_errors(SScaleIn.model_fields):
        args = (body.pressure_pa, body.strand_diameter_m, body.youngs_modulus_pa)
        radius = float(friction.hertz_contact_radius(*args, body.poisson_ratio))
        scale = float(friction.s_scale(*args, body.poisson_ratio))
        force = float(friction.compressive_force(body.pressure_pa, body.strand_diameter_m))
    return JSONResponse(
        {
            "s_scale": scale,
            "contact_radius_m": radius,
            "flat_contact_radius_m": float(friction.flat_contact_radius(body.strand_diameter_m)),
            "compressive_force_n": force,
        }
    )


_TABLES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {
            "text/csv": {"example": "braid_angle_deg,length_m,...\n12.86,0.6337,...\n"},
            "application/x-npy": {"schema": {"type": "string", "format": "binary"}},
        }
    }
}


@router.post("/hysteresis", response_model=HysteresisOut, responses=_TABLES)
async def hysteresis(
    body: HysteresisIn,
    format: Annotated[
        Literal["json", "csv", "npy", "npy-record"] | None,
        Query(
            description="csv: the arrays as a CSV table (or Accept: text/csv); npy: a NumPy"
            " .npy file of one structured array, a row per point and a field per array (or"
            " Accept: application/x-npy); npy-record: a .npy file of one record with the"
            " JSON answer's fields, numbers and whole arrays, the fastest for large curves"
        ),
    ] = None,
    accept: Annotated[str | None, Header(include_in_schema=False)] = None,
) -> Response:
    """Static force and both friction branches along the stroke (eqs 10, 29-31).

    JSON by default; the arrays as a CSV table (``?format=csv`` or ``Accept: text/csv``), as
    a NumPy ``.npy`` table of rows (``?format=npy`` or ``Accept: application/x-npy``), or
    as a ``.npy`` record of the JSON answer's fields (``?format=npy-record``).
    """
    with core_errors(HysteresisIn.model_fields):
        geo = body.geometry(need_length=True)
        assert geo.strand_length_m is not None
        assert geo.turns is not None
        curves = hysteresis_curves(
            geo.strand_length_m,
            geo.turns,
            body.strand_diameter_m,
            body.strand_count,
            body.pressure_pa,
            body.friction_coefficient,
            body.youngs_modulus_pa,
            body.poisson_ratio,
            s_scale=body.s_scale,
            points=body.points,
        )
    arrays = curve_columns(curves)
    table = format or _table_format(accept)
    if table == "csv":
        return CSVResponse(csv_bytes(arrays))
    scalars = {
        "s_scale": curves.s_scale,
        "min_braid_angle_deg": _deg(curves.min_braid_angle_rad),
        "max_braid_angle_deg": _deg(curves.max_braid_angle_rad),
    }
    if table == "npy":
        return NPYResponse(npy_table(arrays))
    if table == "npy-record":
        return NPYResponse(npy_record({**scalars, **arrays}))
    return JSONResponse({**scalars, **arrays})


def _table_format(accept: str | None) -> str:
    if accept and "text/csv" in accept:
        return "csv"
    if accept and "application/x-npy" in accept:
        return "npy"
    return "json"


def curve_columns(curves: HysteresisCurves) -> dict[str, npt.NDArray[np.float64]]:
    """The arrays of a hysteresis response, by JSON field name (angles in degrees)."""
    return {
        "braid_angle_deg": np.degrees(curves.braid_angle_rad),
        "length_m": curves.length_m,
        "contraction": curves.contraction,
        "force_static_n": curves.force_static_n,
        "friction_force_n": curves.friction_force_n,
        "force_contracting_n": curves.force_contracting_n,
        "force_extending_n": curves.force_extending_n,
    }
