"""Whole-design report and the parameter sweeps the page plots."""

from __future__ import annotations

from dataclasses import asdict

import numpy as np
from fastapi import APIRouter

from app.errors import core_errors, field_error
from app.responses import JSONResponse
from app.schemas import (
    DesignIn,
    DesignOut,
    PressureSweepIn,
    PressureSweepOut,
    StrandCountSweepIn,
    StrandCountSweepOut,
)
from pma_core import braid, friction, gap, strength
from pma_core.design import Design, DesignReport, design_report
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD
from pma_core.materials import MATERIALS, Material

router = APIRouter(prefix="/api/v1", tags=["design"], default_response_class=JSONResponse)

_PROPERTIES = ("youngs_modulus_pa", "poisson_ratio", "tensile_strength_pa", "friction_coefficient")


def _material(body: DesignIn) -> dict[str, float]:
    preset: Material | None = None
    if body.material is not None:
        preset = MATERIALS.get(body.material)
        if preset is None:
            known = ", ".join(MATERIALS)
            raise field_error("material", f"unknown material {body.material!r}; presets: {known}")
    values: dict[str, float] = {}
    for name in _PROPERTIES:
        value = getattr(body, name)
        if value is None and preset is None:
            raise field_error(name, f"{name} is required when no material preset is given")
        values[name] = value if value is not None else getattr(preset, name)
    return values


@router.post("/design", response_model=DesignOut)
async def design(body: DesignIn) -> JSONResponse:
    """Every quantity of one actuator, with warnings (stable codes and sentences)."""
    properties = _material(body)
    with core_errors(DesignIn.model_fields):
        geo = body.geometry()
        report = design_report(
            Design(
                strand_diameter_m=body.strand_diameter_m,
                strand_count=body.strand_count,
                parallel_strands=body.parallel_strands,
                theoretical_diameter_m=geo.theoretical_diameter_m,
                pressure_pa=body.pressure_pa,
                safety_factor=body.safety_factor,
                strand_length_m=geo.strand_length_m,
                s_scale=body.s_scale,
                gap_area_limit_m2=body.gap_area_limit_m2,
                **properties,
            )
        )
    return JSONResponse(_report_json(report, geo.strand_length_m, geo.turns, properties))


def _report_json(
    r: DesignReport, b: float | None, n: float | None, properties: dict[str, float]
) -> dict[str, object]:
    return {
        "theoretical_diameter_m": r.theoretical_diameter_m,
        "strand_length_m": b,
        "turns": n,
        "min_braid_angle_deg": float(np.degrees(r.min_braid_angle_rad)),
        "jamming_angle_deg": float(np.degrees(r.jamming_angle_rad)),
        "max_braid_angle_deg": float(np.degrees(r.max_braid_angle_rad)),
        "max_contraction": r.max_contraction,
        "max_length_m": r.max_length_m,
        "min_length_m": r.min_length_m,
        "stroke_m": r.stroke_m,
        "peak_static_force_n": r.peak_static_force_n,
        "max_gap_width_m": r.max_gap_width_m,
        "max_gap_area_m2": r.max_gap_area_m2,
        "failure_strand_count": {
            "braid_angle_deg": float(np.degrees(NEUTRAL_BRAID_ANGLE_RAD)),
            "min_strand_count_exact": r.failure_strand_count_exact,
            "min_strand_count": r.failure_strand_count,
            "worst_case_braid_angle_deg": 45.0,
            "worst_case_min_strand_count_exact": r.worst_case_failure_strand_count_exact,
            "worst_case_min_strand_count": r.worst_case_failure_strand_count,
        },
        "worst_case_strand_stress_pa": r.worst_case_strand_stress_pa,
        "s_scale": r.s_scale,
        "s_scale_computed": r.s_scale_computed,
        "material": properties,
        "warnings": [asdict(w) for w in r.warnings],
    }


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
        with core_errors(fields):
            braid.strand_fill_ratio(body.strand_diameter_m, body.strand_count_min, d_o)
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
