"""Request and response models of the HTTP API (v1). Responses are documented, not revalidated."""

from __future__ import annotations

from typing import Annotated, Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from app.fields import (
    BraidAngle,
    FrictionCoefficient,
    MeasuredSScale,
    ParallelStrands,
    Points,
    PoissonRatio,
    Pressure,
    SafetyFactor,
    StrandCount,
    StrandDiameter,
    StrandLength,
    TensileStrength,
    TheoreticalDiameter,
    Turns,
    YoungsModulus,
)
from app.geometry import Geometry, resolve_geometry
from pma_core import reference
from pma_core.design import DEFAULT_GAP_AREA_LIMIT_M2
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD
from pma_core.materials import NYLON

_SAMPLE = reference.BRAID_SAMPLE
#: The paper's braid sample (§2.1) and test muscle (§3.3), the examples of the API docs.
PAPER_BRAID: dict[str, Any] = {
    "strand_diameter_m": _SAMPLE["strand_diameter_m"],
    "strand_count": _SAMPLE["strand_count"],
    "theoretical_diameter_m": _SAMPLE["theoretical_diameter_m"],
}
PAPER_MUSCLE: dict[str, Any] = {
    **reference.TEST_MUSCLE,
    "pressure_pa": 200_000.0,
    "youngs_modulus_pa": NYLON.youngs_modulus_pa,
    "poisson_ratio": NYLON.poisson_ratio,
}


class Strict(BaseModel):
    """No coercion (no ``true`` → 1.0, no ``"5"`` → 5), no unknown fields, no NaN/Infinity."""

    model_config = ConfigDict(strict=True, extra="forbid", allow_inf_nan=False)


class WithGeometry(Strict):
    """Bodies that give the braid's size: D_o, or any two of b, n and D_o."""

    theoretical_diameter_m: TheoreticalDiameter = None
    strand_length_m: StrandLength = None
    turns: Turns = None

    def geometry(self, *, need_length: bool = False) -> Geometry:
        """The resolved geometry, or a 422 naming the missing or extra field."""
        return resolve_geometry(
            self.theoretical_diameter_m, self.strand_length_m, self.turns, need_length=need_length
        )


def _examples(*bodies: dict[str, Any]) -> ConfigDict:
    return ConfigDict(json_schema_extra={"examples": list(bodies)})


class MinBraidAngleIn(WithGeometry):
    """Minimum braid angle (eq 8) and the contractile range it sets (eq 9)."""

    model_config = _examples(PAPER_BRAID, {**PAPER_BRAID, "strand_count": 120})
    strand_diameter_m: StrandDiameter
    strand_count: StrandCount


class MinBraidAngleOut(BaseModel):
    min_braid_angle_deg: float = Field(description="θ_min, eq 8 [deg]")
    max_braid_angle_deg: float = Field(description="θ_max = min(54.7356°, 90° − θ_min) [deg]")
    jamming_angle_deg: float = Field(description="90° − θ_min, where the braid locks [deg]")
    max_contraction: float = Field(description="1 − cos θ_max / cos θ_min [-]")
    theoretical_diameter_m: float = Field(description="D_o used [m]")
    max_length_m: float | None = Field(description="b·cos θ_min, eq 9 [m]; null without b")
    min_length_m: float | None = Field(description="b·cos θ_max, eq 19 [m]; null without b")
    stroke_m: float | None = Field(description="max_length_m − min_length_m [m]")


class GapAreaIn(WithGeometry):
    """Braid gap at a braid angle (eqs 12, 14) and its maximum (eq 15)."""

    model_config = _examples({**PAPER_BRAID, "parallel_strands": 3})
    strand_diameter_m: StrandDiameter
    strand_count: StrandCount
    parallel_strands: ParallelStrands = 1
    braid_angle_deg: BraidAngle = 45.0


class GapAreaOut(BaseModel):
    braid_angle_deg: float = Field(description="θ [deg]")
    node_spacing_m: float = Field(description="G, eq 12 [m]")
    gap_width_m: float = Field(description="Z, eq 14 [m]; 0 where the strands touch")
    gap_area_m2: float = Field(description="Z²/(2·tan θ) at θ [m²]")
    max_gap_area_m2: float = Field(description="Z²/2 at 45°, eq 15 [m²]")


class FailureStrandCountIn(WithGeometry):
    """Fewest strands that survive the pressure (eq 20)."""

    model_config = _examples(
        {
            "pressure_pa": 500_000.0,
            "strand_diameter_m": 0.00025,
            "tensile_strength_pa": 75e6,
            "theoretical_diameter_m": 0.031,
        }
    )
    pressure_pa: Pressure
    strand_diameter_m: StrandDiameter
    tensile_strength_pa: TensileStrength
    braid_angle_deg: BraidAngle = Field(
        default=round(float(np.degrees(NEUTRAL_BRAID_ANGLE_RAD)), 4),
        description="θ [deg] at which eq 20 is evaluated; default the neutral angle"
        " 54.7356°, the fully contracted state the paper uses.",
    )
    safety_factor: SafetyFactor = 1.0


class FailureStrandCountOut(BaseModel):
    braid_angle_deg: float = Field(description="θ used [deg]")
    min_strand_count_exact: float = Field(description="N of eq 20, a real number [-]")
    min_strand_count: int = Field(description="ceil(N): fewest whole strands that hold [-]")
    worst_case_braid_angle_deg: float = Field(description="45°, where strand stress peaks")
    worst_case_min_strand_count_exact: float = Field(description="N of eq 20 at 45° [-]")
    worst_case_min_strand_count: int = Field(description="ceil(N) at 45° [-]")


class SScaleIn(Strict):
    """Contact-area scale factor from Hertz contact (eqs 32-34)."""

    model_config = _examples(
        {
            "strand_diameter_m": 0.00025,
            "pressure_pa": 200_000.0,
            "youngs_modulus_pa": 3e9,
            "poisson_ratio": 0.4,
        }
    )
    strand_diameter_m: StrandDiameter
    pressure_pa: Pressure
    youngs_modulus_pa: YoungsModulus
    poisson_ratio: PoissonRatio


class SScaleOut(BaseModel):
    s_scale: float = Field(description="S_scale, eq 34 [-]")
    contact_radius_m: float = Field(description="a_c of the sphere contact, eq 33 [m]")
    flat_contact_radius_m: float = Field(description="a_c of flat strands, D_s/2 [m]")
    compressive_force_n: float = Field(description="F_comp = P·D_s² [N]")


class HysteresisIn(WithGeometry):
    """Force against contraction with friction hysteresis (eqs 10, 29-31)."""

    model_config = _examples(PAPER_MUSCLE)
    strand_diameter_m: StrandDiameter
    strand_count: StrandCount
    pressure_pa: Pressure
    friction_coefficient: FrictionCoefficient
    youngs_modulus_pa: YoungsModulus
    poisson_ratio: PoissonRatio
    s_scale: MeasuredSScale = None
    points: Points = 201


class HysteresisOut(BaseModel):
    s_scale: float = Field(description="S_scale used: measured, or eq 34 [-]")
    min_braid_angle_deg: float = Field(description="θ_min, eq 8 [deg]")
    max_braid_angle_deg: float = Field(description="θ_max [deg]")
    braid_angle_deg: list[float] = Field(description="θ at each point [deg]")
    length_m: list[float] = Field(description="L = b·cos θ, eq 19 [m]")
    contraction: list[float] = Field(description="1 − L/L_max, 0 to the maximum [-]")
    force_static_n: list[float] = Field(description="F_static, eq 10 [N]")
    friction_force_n: list[float] = Field(description="F_friction, eq 30 [N]")
    force_contracting_n: list[float] = Field(description="F_static − F_friction, eq 31 [N], ≥ 0")
    force_extending_n: list[float] = Field(description="F_static + F_friction, eq 31 [N]")


class DesignIn(WithGeometry):
    """One actuator: every quantity of the model and the warnings that apply.

    Material properties come from ``material`` (a preset id of /api/v1/materials) and
    may be overridden one by one; without a preset each must be given.
    """

    model_config = _examples(
        {**PAPER_BRAID, "parallel_strands": 3, "pressure_pa": 200_000.0, "material": "nylon"},
        {
            "strand_length_m": 0.65,
            "turns": 4.7,
            "strand_diameter_m": 0.00025,
            "strand_count": 120,
            "parallel_strands": 3,
            "pressure_pa": 500_000.0,
            "youngs_modulus_pa": 3e9,
            "poisson_ratio": 0.4,
            "tensile_strength_pa": 75e6,
            "friction_coefficient": 0.2,
            "safety_factor": 1.5,
        },
    )
    strand_diameter_m: StrandDiameter
    strand_count: StrandCount
    parallel_strands: ParallelStrands = 1
    pressure_pa: Pressure
    material: str | None = Field(
        default=None,
        description="Preset id from GET /api/v1/materials (e.g. 'nylon'); the fields below"
        " override its values.",
        examples=["nylon"],
    )
    youngs_modulus_pa: YoungsModulus | None = Field(
        default=None, description="E [Pa] (eq 33); default: the preset's"
    )
    poisson_ratio: PoissonRatio | None = Field(
        default=None, description="ν [-] (eq 33); default: the preset's"
    )
    tensile_strength_pa: TensileStrength | None = Field(
        default=None, description="σ_u [Pa] (eq 20); default: the preset's"
    )
    friction_coefficient: FrictionCoefficient | None = Field(
        default=None, description="f_s [-] (eq 30); default: the preset's"
    )
    safety_factor: SafetyFactor = 1.0
    s_scale: MeasuredSScale = None
    gap_area_limit_m2: float = Field(
        default=DEFAULT_GAP_AREA_LIMIT_M2,
        ge=1e-12,
        le=1e-2,
        description="Largest acceptable braid gap [m²] before warning that the bladder may"
        " pass through; default 1 mm², between the paper's 0.22 mm² (N 240) and 2.84 mm²"
        " (N 120). The paper gives no criterion: set your own from bladder tests.",
    )


class FailureCountOut(BaseModel):
    braid_angle_deg: float = Field(description="θ = 54.7356°, fully contracted [deg]")
    min_strand_count_exact: float = Field(description="N of eq 20 [-]")
    min_strand_count: int = Field(description="ceil(N) [-]")
    worst_case_braid_angle_deg: float = Field(description="45° [deg]")
    worst_case_min_strand_count_exact: float = Field(description="N of eq 20 at 45° [-]")
    worst_case_min_strand_count: int = Field(description="ceil(N) at 45° [-]")


class MaterialUsed(BaseModel):
    youngs_modulus_pa: float = Field(description="E [Pa]")
    poisson_ratio: float = Field(description="ν [-]")
    tensile_strength_pa: float = Field(description="σ_u [Pa]")
    friction_coefficient: float = Field(description="f_s [-]")


class WarningOut(BaseModel):
    code: str = Field(
        description="Stable code: below_failure_count, below_worst_case_failure_count,"
        " gap_admits_bladder, jams_before_neutral_angle, strand_count_not_braidable"
    )
    message: str = Field(description="What is wrong and why, in words")


class DesignOut(BaseModel):
    theoretical_diameter_m: float = Field(description="D_o [m]")
    strand_length_m: float | None = Field(description="b [m]; null when not known")
    turns: float | None = Field(description="n [-]; null when not known")
    min_braid_angle_deg: float = Field(description="θ_min, eq 8 [deg]")
    jamming_angle_deg: float = Field(description="90° − θ_min [deg]")
    max_braid_angle_deg: float = Field(description="θ_max [deg]")
    max_contraction: float = Field(description="ε_max [-]")
    max_length_m: float | None = Field(description="L_max, eq 9 [m]")
    min_length_m: float | None = Field(description="L_min [m]")
    stroke_m: float | None = Field(description="L_max − L_min [m]")
    peak_static_force_n: float = Field(description="F_static at θ_min, eq 10 [N]")
    max_gap_width_m: float = Field(description="Z at 45°, eq 14 [m]")
    max_gap_area_m2: float = Field(description="eq 15 [m²]")
    failure_strand_count: FailureCountOut = Field(description="Eq 20, fully contracted and at 45°")
    worst_case_strand_stress_pa: float = Field(description="σ at 45° with this N, eq 17 [Pa]")
    s_scale: float = Field(description="S_scale used [-]")
    s_scale_computed: float = Field(description="S_scale of eq 34 [-]")
    material: MaterialUsed = Field(description="The material properties used")
    warnings: list[WarningOut] = Field(description="Risks in this design; empty when none")


class StrandCountSweepIn(WithGeometry):
    """θ_min, contraction and gap area over a range of strand counts."""

    model_config = _examples(
        {
            **PAPER_BRAID,
            "parallel_strands": 3,
            "strand_count_min": 60,
            "strand_count_max": 300,
        }
    )
    strand_diameter_m: StrandDiameter
    parallel_strands: ParallelStrands = 1
    strand_count_min: StrandCount
    strand_count_max: StrandCount


class StrandCountSweepOut(BaseModel):
    strand_count_limit: int = Field(description="Largest N that fits around the braid [-]")
    strand_count: list[int] = Field(description="N, the feasible counts of the range [-]")
    min_braid_angle_deg: list[float] = Field(description="θ_min, eq 8 [deg]")
    max_contraction: list[float] = Field(description="ε_max [-]")
    max_gap_area_m2: list[float] = Field(description="eq 15 [m²]")


class PressureSweepIn(WithGeometry):
    """S_scale and failure strand counts over a range of pressures."""

    model_config = _examples(
        {
            "strand_diameter_m": 0.00025,
            "theoretical_diameter_m": 0.031,
            "tensile_strength_pa": 75e6,
            "youngs_modulus_pa": 3e9,
            "poisson_ratio": 0.4,
            "pressure_min_pa": 50_000.0,
            "pressure_max_pa": 600_000.0,
        }
    )
    strand_diameter_m: StrandDiameter
    tensile_strength_pa: TensileStrength
    youngs_modulus_pa: YoungsModulus
    poisson_ratio: PoissonRatio
    safety_factor: SafetyFactor = 1.0
    pressure_min_pa: Pressure
    pressure_max_pa: Pressure
    points: int = Field(default=101, ge=2, le=10_000, description="Number of pressures")


class PressureSweepOut(BaseModel):
    pressure_pa: list[float] = Field(description="P, evenly spaced [Pa]")
    s_scale: list[float] = Field(description="S_scale, eq 34 [-]")
    min_strand_count_exact: list[float] = Field(description="N of eq 20 at 54.7356° [-]")
    min_strand_count: list[int] = Field(description="ceil(N) [-]")
    worst_case_min_strand_count_exact: list[float] = Field(description="N at 45° [-]")
    worst_case_min_strand_count: list[int] = Field(description="ceil(N) at 45° [-]")


class OpenSimIn(WithGeometry):
    """A braid to express as an OpenSim McKibbenActuator (b and n, or D_o with one of them)."""

    model_config = _examples(
        {"strand_length_m": 0.65, "turns": 4.7, "strand_diameter_m": 0.00025, "strand_count": 240}
    )
    strand_diameter_m: StrandDiameter
    strand_count: StrandCount
    name: Annotated[
        str, Field(pattern=r"^[A-Za-z][A-Za-z0-9_]{0,63}$", description="Component name")
    ] = "pma"
    cord_length_m: float = Field(
        default=0.0, ge=0.0, le=100.0, description="Length of the end cords, not braided [m]"
    )


class OpenSimOut(BaseModel):
    thread_length: float = Field(description="OpenSim thread_length = b [m]")
    number_of_turns: float = Field(description="OpenSim number_of_turns = n [-]")
    cord_length: float = Field(description="OpenSim cord_length [m]")
    max_length_m: float = Field(description="Braided length at θ_min, eq 9 [m]")
    min_length_m: float = Field(description="Braided length at θ_max [m]")
    xml: str = Field(description="The <McKibbenActuator> element for an .osim model")


class HealthOut(BaseModel):
    status: str = Field(description='"ok" while the service answers')


class MaterialOut(BaseModel):
    id: str = Field(description="Preset id, for the material field of /design")
    name: str = Field(description="Human-readable name")
    youngs_modulus_pa: float = Field(description="E [Pa]")
    poisson_ratio: float = Field(description="ν [-]")
    tensile_strength_pa: float = Field(description="σ_u [Pa]")
    friction_coefficient: float = Field(description="f_s [-]")
    basis: str = Field(description="Bulk-polymer or fibre values")
    sources: dict[str, str] = Field(description="The source of each number, by field")


class MaterialsOut(BaseModel):
    materials: list[MaterialOut] = Field(description="The presets, nylon (the paper's) first")


class Table1Row(BaseModel):
    strand_count: int = Field(description="N [-]")
    measured_deg: float = Field(description="θ_min measured, mean of ten [deg]")
    std_deg: float = Field(description="Standard deviation of the measurement [deg]")
    calculated_deg: float = Field(description="θ_min of eq 8 as the paper prints it [deg]")


class SScaleFitOut(BaseModel):
    pressure_pa: float = Field(description="P [Pa]")
    s_scale: float = Field(description="S_scale fitted to measured hysteresis [-]")
    source: str = Field(description="Who fitted it")


class ReferenceOut(BaseModel):
    braid_sample: dict[str, float] = Field(description="The braid of the paper's §2.1")
    test_muscle: dict[str, float] = Field(description="The hysteresis test muscle of §3.3")
    min_braid_angle_table1: list[Table1Row] = Field(description="The paper's Table 1")
    s_scale_fitted: list[SScaleFitOut] = Field(description="S_scale fitted to experiments")


class HysteresisSweepIn(WithGeometry):
    """Hysteresis curves of one actuator at several pressures, S_scale from eq 34 at each."""

    model_config = _examples(
        {
            **{k: v for k, v in PAPER_MUSCLE.items() if k != "pressure_pa"},
            "pressures_pa": [100_000.0, 300_000.0, 500_000.0],
        }
    )
    strand_diameter_m: StrandDiameter
    strand_count: StrandCount
    pressures_pa: list[Pressure] = Field(
        min_length=1, max_length=16, description="P of each curve [Pa], 1 to 16 pressures"
    )
    friction_coefficient: FrictionCoefficient
    youngs_modulus_pa: YoungsModulus
    poisson_ratio: PoissonRatio
    points: int = Field(default=201, ge=2, le=10_000, description="Points per curve")


class HysteresisSweepOut(BaseModel):
    pressure_pa: list[float] = Field(description="P of each curve (rows below) [Pa]")
    s_scale: list[float] = Field(description="S_scale of eq 34 at each pressure [-]")
    min_braid_angle_deg: float = Field(description="θ_min, eq 8 [deg]")
    max_braid_angle_deg: float = Field(description="θ_max [deg]")
    braid_angle_deg: list[float] = Field(description="θ at each point, all curves [deg]")
    length_m: list[float] = Field(description="L = b·cos θ, eq 19 [m]")
    contraction: list[float] = Field(description="1 − L/L_max, 0 to the maximum [-]")
    force_static_n: list[list[float]] = Field(description="F_static, eq 10: a row per P [N]")
    friction_force_n: list[list[float]] = Field(description="F_friction, eq 30 [N]")
    force_contracting_n: list[list[float]] = Field(description="eq 31, clipped at 0 [N]")
    force_extending_n: list[list[float]] = Field(description="eq 31 [N]")
