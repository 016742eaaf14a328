"""Numbers the paper prints, typed in from the paper, never from the code under test.

Source: S. Davis and D. G. Caldwell, IJRR 25(4) 2006, doi:10.1177/0278364906063227, as
listed in shared/design/MODEL.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class DavisCaldwell2006:
    """Inputs and printed results of the paper."""

    theoretical_diameter_m: float = 0.031
    strand_diameter_m: float = 0.25e-3
    parallel_strands: int = 3
    # Table 1, calculated column: N -> θ_min [deg], printed to 0.1°.
    min_braid_angle_deg: dict[int, float] = field(
        default_factory=lambda: {240: 19.0, 160: 12.1, 120: 9.0}
    )
    # Eq 15: N -> max gap area [mm²], printed to 0.01 mm².
    max_gap_area_mm2: dict[int, float] = field(default_factory=lambda: {240: 0.22, 120: 2.84})
    # Eq 20 at 500 kPa, σ_u = 75 MPa.
    failure_pressure_pa: float = 500e3
    tensile_strength_pa: float = 75e6
    failure_strand_count: int = 97
    worst_case_failure_strand_count: int = 103  # MODEL.md: 102.5 at 45°
    # Eq 34, E = 3 GPa, ν = 0.4: pressure [Pa] -> S_scale, printed to 0.1.
    youngs_modulus_pa: float = 3e9
    poisson_ratio: float = 0.4
    s_scale: dict[float, float] = field(
        default_factory=lambda: {200e3: 18.1, 300e3: 15.8, 400e3: 14.3}
    )
    # Eq 10: F(10°)/F(20°), printed to 0.01.
    force_ratio_10_20: float = 1.16
    # §2.1: contractile range gain N 240 -> 120, "approximately 7 %".
    contraction_gain: float = 0.07
    # §3.3 test muscle.
    strand_length_m: float = 0.65
    turns: float = 4.7
    friction_coefficient: float = 0.2
