r"""One actuator design, every quantity of the model, and the risks it runs.

:func:`design_report` gathers the braid limits (eqs 8-9), force (eq 10), gaps (eq 15),
strength (eq 20) and friction scaling (eq 34) of one design, and turns the paper's design
rules into warnings with stable codes.

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pma_core import braid, friction, gap, strength
from pma_core._validation import Floats
from pma_core.force import static_force
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD

#: Default largest acceptable braid gap [m²]: 1 mm², between the paper's closed 240-strand
#: braid (0.22 mm²) and its open 120-strand braid (2.84 mm²), which the paper says greatly
#: increases the chance of the bladder passing through (§2.2). The paper gives no failure
#: criterion; users should set their own from bladder tests.
DEFAULT_GAP_AREA_LIMIT_M2: float = 1.0e-6


@dataclass(frozen=True)
class DesignWarning:
    """A risk in a design: a stable machine-readable ``code`` and a sentence."""

    code: str
    message: str


@dataclass(frozen=True)
class DesignReport:
    """Every scalar quantity of one design, SI units and radians."""

    theoretical_diameter_m: float
    min_braid_angle_rad: float
    jamming_angle_rad: float
    max_braid_angle_rad: float
    max_contraction: float
    max_length_m: float | None
    min_length_m: float | None
    stroke_m: float | None
    peak_static_force_n: float
    max_gap_width_m: float
    max_gap_area_m2: float
    failure_strand_count_exact: float
    failure_strand_count: int
    worst_case_failure_strand_count_exact: float
    worst_case_failure_strand_count: int
    worst_case_strand_stress_pa: float
    s_scale: float
    s_scale_computed: float
    warnings: tuple[DesignWarning, ...]


@dataclass(frozen=True)
class Design:
    """An actuator design, SI units. ``strand_length_m`` is optional (lengths need it)."""

    strand_diameter_m: float
    strand_count: int
    parallel_strands: int
    theoretical_diameter_m: float
    pressure_pa: float
    youngs_modulus_pa: float
    poisson_ratio: float
    tensile_strength_pa: float
    friction_coefficient: float = 0.2
    safety_factor: float = 1.0
    strand_length_m: float | None = None
    s_scale: float | None = None
    gap_area_limit_m2: float = DEFAULT_GAP_AREA_LIMIT_M2


def design_report(design: Design) -> DesignReport:
    """Compute every quantity of ``design`` and the warnings that apply.

    Parameters
    ----------
    design : Design
        The actuator; see :class:`Design`.

    Returns
    -------
    DesignReport

    Raises
    ------
    ValueError
        For an impossible design, naming the parameter and the physical reason.

    References
    ----------
    Davis & Caldwell 2006, eqs 8-10, 15, 20, 34. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's braid at 500 kPa: 97 strands needed, 103 at the 45° worst case:

    >>> r = design_report(Design(0.25e-3, 240, 3, 0.031, 500e3, 3e9, 0.4, 75e6))
    >>> round(float(np.degrees(r.min_braid_angle_rad)), 1), r.failure_strand_count
    (19.0, 97)
    >>> r.worst_case_failure_strand_count, [w.code for w in r.warnings]
    (103, [])
    """
    d = design
    geometry = (d.strand_diameter_m, d.strand_count, d.theoretical_diameter_m)
    limits = braid.braid_limits(*geometry, d.strand_length_m)
    theta_min = float(limits.min_braid_angle_rad)
    gap_args = (d.theoretical_diameter_m, d.strand_diameter_m, d.strand_count, d.parallel_strands)
    strength_args = (d.pressure_pa, d.theoretical_diameter_m, d.strand_diameter_m)
    fail = float(
        strength.failure_strand_count(
            *strength_args, d.tensile_strength_pa, NEUTRAL_BRAID_ANGLE_RAD, d.safety_factor
        )
    )
    worst = float(
        strength.failure_strand_count(
            *strength_args,
            d.tensile_strength_pa,
            strength.WORST_CASE_BRAID_ANGLE_RAD,
            d.safety_factor,
        )
    )
    computed_scale = float(
        friction.s_scale(d.pressure_pa, d.strand_diameter_m, d.youngs_modulus_pa, d.poisson_ratio)
    )
    report = DesignReport(
        theoretical_diameter_m=d.theoretical_diameter_m,
        min_braid_angle_rad=theta_min,
        jamming_angle_rad=float(limits.jamming_angle_rad),
        max_braid_angle_rad=float(limits.max_braid_angle_rad),
        max_contraction=float(limits.max_contraction),
        max_length_m=_float_or_none(limits.max_length_m),
        min_length_m=_float_or_none(limits.min_length_m),
        stroke_m=_float_or_none(limits.stroke_m),
        peak_static_force_n=float(static_force(d.pressure_pa, d.theoretical_diameter_m, theta_min)),
        max_gap_width_m=float(gap.gap_width(*gap_args, gap.MAX_GAP_BRAID_ANGLE_RAD)),
        max_gap_area_m2=float(gap.max_gap_area(*gap_args)),
        failure_strand_count_exact=fail,
        failure_strand_count=int(strength.min_strand_count(fail)),
        worst_case_failure_strand_count_exact=worst,
        worst_case_failure_strand_count=int(strength.min_strand_count(worst)),
        worst_case_strand_stress_pa=float(
            strength.strand_stress(
                *strength_args, d.strand_count, strength.WORST_CASE_BRAID_ANGLE_RAD
            )
        ),
        s_scale=computed_scale if d.s_scale is None else float(d.s_scale),
        s_scale_computed=computed_scale,
        warnings=(),
    )
    return _with_warnings(report, d)


def _float_or_none(value: Floats | None) -> float | None:
    return None if value is None else float(value)


def _with_warnings(report: DesignReport, d: Design) -> DesignReport:
    found = [
        w
        for check in (_strength_warning, _gap_warning, _jam_warning, _weave_warning)
        if (w := check(report, d)) is not None
    ]
    return DesignReport(**{**report.__dict__, "warnings": tuple(found)})


def _strength_warning(r: DesignReport, d: Design) -> DesignWarning | None:
    stress_mpa = r.worst_case_strand_stress_pa / 1e6
    allowed_mpa = d.tensile_strength_pa / d.safety_factor / 1e6
    if d.strand_count < r.failure_strand_count:
        return DesignWarning(
            "below_failure_count",
            f"{d.strand_count} strands are fewer than the {r.failure_strand_count} needed at"
            f" {d.pressure_pa / 1e3:g} kPa even fully contracted (eq 20): the braid will burst.",
        )
    if d.strand_count < r.worst_case_failure_strand_count:
        return DesignWarning(
            "below_worst_case_failure_count",
            f"{d.strand_count} strands are fewer than the {r.worst_case_failure_strand_count}"
            f" needed at the 45° worst case (eq 20): passing 45° on its stroke the strand stress"
            f" reaches {stress_mpa:.1f} MPa, above the allowed {allowed_mpa:.1f} MPa.",
        )
    return None


def _gap_warning(r: DesignReport, d: Design) -> DesignWarning | None:
    if r.max_gap_area_m2 <= d.gap_area_limit_m2:
        return None
    return DesignWarning(
        "gap_admits_bladder",
        f"The largest braid gap is {r.max_gap_area_m2 * 1e6:.2f} mm² at 45° (eq 15), above"
        f" {d.gap_area_limit_m2 * 1e6:.2f} mm²: the bladder may push through the braid and"
        " rupture. Use more strands, thicker strands or a tougher bladder.",
    )


def _jam_warning(r: DesignReport, d: Design) -> DesignWarning | None:
    if r.jamming_angle_rad >= NEUTRAL_BRAID_ANGLE_RAD:
        return None
    return DesignWarning(
        "jams_before_neutral_angle",
        f"The braid jams at {np.degrees(r.jamming_angle_rad):.1f}°, before the neutral angle"
        f" 54.7°: it stops contracting while it still pulls"
        f" {static_force(d.pressure_pa, d.theoretical_diameter_m, r.jamming_angle_rad):.0f} N.",
    )


def _weave_warning(r: DesignReport, d: Design) -> DesignWarning | None:
    if d.strand_count % (2 * d.parallel_strands) == 0:
        return None
    return DesignWarning(
        "strand_count_not_braidable",
        f"{d.strand_count} strands cannot be split into two helices of {d.parallel_strands}"
        f" parallel strands per path: N should be a multiple of 2·S = {2 * d.parallel_strands}"
        " (eq 7).",
    )
