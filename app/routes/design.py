"""Whole-design report and the parameter sweeps the page plots."""

from __future__ import annotations

import numpy as np
from fastapi import APIRouter

from app.errors import core_errors, field_error
from app.report import design_json
from app.responses import JSONResponse
from app.routing import JSONBodyRoute
from app.schemas import (
    DesignIn,
    DesignOut,
    HysteresisSweepIn,
    HysteresisSweepOut,
    PressureSweepIn,
    PressureSweepOut,
    StrandCountSweepIn,
    StrandCountSweepOut,
)
from pma_core import braid, friction, gap, strength
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD
from pma_core.hysteresis import hysteresis_curves

router = APIRouter(
    prefix="/api/v1",
    tags=["design"],
    default_response_class=JSONResponse,
    route_class=JSONBodyRoute,
)


@router.post("/design", response_model=DesignOut)
async def design(body: DesignIn) -> JSONResponse:
    """Every quantity of one actuator, with warnings (stable codes and sentences)."""
    return JSONResponse(design_json(body))


@router.post("/sweeps/strand-count", response_model=StrandCountSweepOut)
async def strand_count_sweep(body: StrandCountSweepIn) -> JSONResponse:
    """θ_min (eq 8), ε_max and the maximum gap area (eq 15) for each N of a range.

    Only counts that fit around the braid are returned; ``strand_count_limit`` says where
    the range was cut.
    """
    if body.strand_count_max < body.strand_count_min:
        raise field_error("strand_count_max", "strand_count_max must be at least strand_count_min")
    fields = StrandCountSweepIn.model_fields
    with core_errors(fields):
        d_o = body.geometry().theoretical_diameter_m
        limit = int(braid.max_strand_count(body.strand_diameter_m, d_o))
    if body.strand_count_min > limit:
        try:
            braid.strand_fill_ratio(body.strand_diameter_m, body.strand_count_min, d_o)
        except ValueError as error:
            raise field_error("strand_count_min", str(error)) from None
    counts = np.arange(body.strand_count_min, min(body.strand_count_max, limit) + 1)
    args = (body.strand_diameter_m, counts, d_o)
    return JSONResponse(
        {
            "strand_count_limit": limit,
            "strand_count": counts,
            "min_braid_angle_deg": np.degrees(braid.min_braid_angle(*args)),
            "max_contraction": braid.max_contraction(*args),
            "max_gap_area_m2": gap.max_gap_area(
                d_o, body.strand_diameter_m, counts, body.parallel_strands
            ),
        }
    )


@router.post("/sweeps/pressure", response_model=PressureSweepOut)
async def pressure_sweep(body: PressureSweepIn) -> JSONResponse:
    """S_scale (eq 34) and the failure strand counts (eq 20) over a range of pressures."""
    if body.pressure_max_pa < body.pressure_min_pa:
        raise field_error("pressure_max_pa", "pressure_max_pa must be at least pressure_min_pa")
    with core_errors(PressureSweepIn.model_fields):
        d_o = body.geometry().theoretical_diameter_m
        p = np.linspace(body.pressure_min_pa, body.pressure_max_pa, body.points)
        args = (p, d_o, body.strand_diameter_m, body.tensile_strength_pa)
        angles = (NEUTRAL_BRAID_ANGLE_RAD, strength.WORST_CASE_BRAID_ANGLE_RAD)
        full, worst = (strength.failure_strand_count(*args, a, body.safety_factor) for a in angles)
        scale = friction.s_scale(
            p, body.strand_diameter_m, body.youngs_modulus_pa, body.poisson_ratio
        )
    return JSONResponse(
        {
            "pressure_pa": p,
            "s_scale": scale,
            "min_strand_count_exact": full,
            "min_strand_count": strength.min_strand_count(full).astype(np.int64),
            "worst_case_min_strand_count_exact": worst,
            "worst_case_min_strand_count": strength.min_strand_count(worst).astype(np.int64),
        }
    )


@router.post("/sweeps/hysteresis", response_model=HysteresisSweepOut)
async def hysteresis_sweep(body: HysteresisSweepIn) -> JSONResponse:
    """The hysteresis curves (eqs 10, 29-31) at each of several pressures, in one request.

    The contraction grid is the same for every pressure (θ_min does not depend on P); each
    force array has a row per pressure.
    """
    with core_errors(HysteresisSweepIn.model_fields):
        geo = body.geometry(need_length=True)
        assert geo.strand_length_m is not None
        assert geo.turns is not None
        design = (geo.strand_length_m, geo.turns, body.strand_diameter_m, body.strand_count)
        material = (body.friction_coefficient, body.youngs_modulus_pa, body.poisson_ratio)
        curves = [
            hysteresis_curves(*design, p, *material, points=body.points) for p in body.pressures_pa
        ]
    first = curves[0]
    return JSONResponse(
        {
            "pressure_pa": body.pressures_pa,
            "s_scale": [c.s_scale for c in curves],
            "min_braid_angle_deg": float(np.degrees(first.min_braid_angle_rad)),
            "max_braid_angle_deg": float(np.degrees(first.max_braid_angle_rad)),
            "braid_angle_deg": np.degrees(first.braid_angle_rad),
            "length_m": first.length_m,
            "contraction": first.contraction,
            **{
                name: np.stack([getattr(c, name) for c in curves])
                for name in (
                    "force_static_n",
                    "friction_force_n",
                    "force_contracting_n",
                    "force_extending_n",
                )
            },
        }
    )
