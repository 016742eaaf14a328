"""Field types of the API: each with its symbol, unit, equation and physical bounds."""

from __future__ import annotations

from typing import Annotated

from pydantic import Field

#: Bounds of the braid's size, given or worked out from eq 1 [m, m, -].
THEORETICAL_DIAMETER_RANGE_M = (1e-4, 1.0)
STRAND_LENGTH_RANGE_M = (1e-3, 100.0)
TURNS_RANGE = (0.01, 10_000.0)

StrandDiameter = Annotated[
    float,
    Field(
        ge=1e-6,
        le=0.01,
        description="D_s, diameter of one braid strand [m], 1 µm to 10 mm.",
        examples=[0.00025],
    ),
]
StrandCount = Annotated[
    int,
    Field(
        ge=2,
        le=100_000,
        description="N, total number of strands in the braid [-], 2 to 100 000.",
        examples=[240],
    ),
]
ParallelStrands = Annotated[
    int,
    Field(
        ge=1,
        le=1000,
        description="S, parallel strands following each path of the weave [-].",
        examples=[3],
    ),
]
TheoreticalDiameter = Annotated[
    float | None,
    Field(
        ge=THEORETICAL_DIAMETER_RANGE_M[0],
        le=THEORETICAL_DIAMETER_RANGE_M[1],
        description="D_o, braid diameter at a 90° braid angle [m], eq 1: b/(n·π)."
        " Give it, or strand_length_m with turns.",
        examples=[0.031],
    ),
]
StrandLength = Annotated[
    float | None,
    Field(
        ge=STRAND_LENGTH_RANGE_M[0],
        le=STRAND_LENGTH_RANGE_M[1],
        description="b, length of one braid strand [m]. With turns, gives D_o = b/(n·π).",
        examples=[0.65],
    ),
]
Turns = Annotated[
    float | None,
    Field(
        ge=TURNS_RANGE[0],
        le=TURNS_RANGE[1],
        description="n, turns one strand makes around the actuator [-].",
        examples=[4.7],
    ),
]
Pressure = Annotated[
    float,
    Field(
        ge=1.0,
        le=1e8,
        description="P, gauge pressure [Pa], 1 Pa to 100 MPa.",
        examples=[200_000.0],
    ),
]
TensileStrength = Annotated[
    float,
    Field(
        ge=1e5,
        le=1e11,
        description="σ_u, tensile strength of the strand material [Pa].",
        examples=[75e6],
    ),
]
YoungsModulus = Annotated[
    float,
    Field(
        ge=1e6,
        le=1e12,
        description="E, Young's modulus of the strand material [Pa] (eq 33).",
        examples=[3e9],
    ),
]
PoissonRatio = Annotated[
    float,
    Field(
        ge=0.0,
        lt=0.5,
        description="ν, Poisson ratio of the strand material [-], 0 ≤ ν < 0.5 (eq 33).",
        examples=[0.4],
    ),
]
FrictionCoefficient = Annotated[
    float,
    Field(
        ge=0.0,
        le=2.0,
        description="f_s, strand-on-strand friction coefficient [-] (eq 30).",
        examples=[0.2],
    ),
]
SafetyFactor = Annotated[
    float,
    Field(
        ge=1.0,
        le=100.0,
        description="k, safety factor dividing the tensile strength [-], at least 1.",
        examples=[1.0],
    ),
]
MeasuredSScale = Annotated[
    float | None,
    Field(
        ge=1e-3,
        le=1e6,
        description="Measured S_scale [-]; overrides eq 34 (Tondu & Lopez used 13;"
        " the paper fitted 20 at 200 kPa and 16 at 300 kPa).",
        examples=[None],
    ),
]
BraidAngle = Annotated[
    float,
    Field(
        gt=0.0,
        lt=90.0,
        description="θ, braid angle between strand and actuator axis [deg].",
    ),
]
Points = Annotated[
    int,
    Field(ge=2, le=100_000, description="Number of points along the curve, 2 to 100 000."),
]
