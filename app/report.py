"""The design report as JSON: shared by ``POST /api/v1/design`` and ``pma-calculator report``."""

from __future__ import annotations

from dataclasses import asdict
from typing import Any

import numpy as np

from app.errors import core_errors, field_error
from app.schemas import DesignIn
from pma_core import strength
from pma_core.design import Design, DesignReport, design_report
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD
from pma_core.materials import MATERIALS, Material

_PROPERTIES = ("youngs_modulus_pa", "poisson_ratio", "tensile_strength_pa", "friction_coefficient")


def material_properties(body: DesignIn) -> dict[str, float]:
    """The strand material: the preset's values, overridden by those the body gives."""
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


def design_json(body: DesignIn) -> dict[str, Any]:
    """Every quantity of the design in ``body`` and its warnings, as the API returns them."""
    properties = material_properties(body)
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
    return {
        "theoretical_diameter_m": report.theoretical_diameter_m,
        "strand_length_m": geo.strand_length_m,
        "turns": geo.turns,
        **_angles(report),
        "max_contraction": report.max_contraction,
        "max_length_m": report.max_length_m,
        "min_length_m": report.min_length_m,
        "stroke_m": report.stroke_m,
        "peak_static_force_n": report.peak_static_force_n,
        "max_gap_width_m": report.max_gap_width_m,
        "max_gap_area_m2": report.max_gap_area_m2,
        "failure_strand_count": _failure(report),
        "worst_case_strand_stress_pa": report.worst_case_strand_stress_pa,
        "s_scale": report.s_scale,
        "s_scale_computed": report.s_scale_computed,
        "material": properties,
        "warnings": [asdict(w) for w in report.warnings],
    }


def _angles(r: DesignReport) -> dict[str, float]:
    return {
        "min_braid_angle_deg": float(np.degrees(r.min_braid_angle_rad)),
        "jamming_angle_deg": float(np.degrees(r.jamming_angle_rad)),
        "max_braid_angle_deg": float(np.degrees(r.max_braid_angle_rad)),
    }


def _failure(r: DesignReport) -> dict[str, float]:
    return {
        "braid_angle_deg": float(np.degrees(NEUTRAL_BRAID_ANGLE_RAD)),
        "min_strand_count_exact": r.failure_strand_count_exact,
        "min_strand_count": r.failure_strand_count,
        "worst_case_braid_angle_deg": float(np.degrees(strength.WORST_CASE_BRAID_ANGLE_RAD)),
        "worst_case_min_strand_count_exact": r.worst_case_failure_strand_count_exact,
        "worst_case_min_strand_count": r.worst_case_failure_strand_count,
    }
