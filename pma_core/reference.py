"""Values the paper publishes as data: its test braid, Table 1 and the fitted S_scale.

These are measurements and designs, not model output: the calculator plots them beside the
model. Model numbers the paper prints are reproduced by the functions' doctests and tests.

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
.. [2] B. Tondu and P. Lopez, "Modeling and control of McKibben artificial muscle robot
   actuators", IEEE Control Systems Magazine 20(2), 2000. :doi:`10.1109/37.833638`
"""

from __future__ import annotations

from dataclasses import dataclass

PAPER = "Davis & Caldwell 2006"
TONDU_LOPEZ = "Tondu & Lopez 2000"


@dataclass(frozen=True)
class MinBraidAngleMeasurement:
    """One row of the paper's Table 1 [deg]."""

    strand_count: int
    measured_deg: float
    std_deg: float
    calculated_deg: float


@dataclass(frozen=True)
class SScaleFit:
    """An S_scale fitted to measured hysteresis at one pressure."""

    pressure_pa: float
    s_scale: float
    source: str


#: The braid sample of §2.1 (Table 1, eq 15).
BRAID_SAMPLE = {
    "theoretical_diameter_m": 0.031,
    "strand_diameter_m": 0.25e-3,
    "strand_count": 240,
    "parallel_strands": 3,
}

#: The hysteresis test muscle of §3.3 (its D_o = b/(n·π) is 44 mm).
TEST_MUSCLE = {
    "strand_length_m": 0.65,
    "turns": 4.7,
    "strand_diameter_m": 0.25e-3,
    "strand_count": 240,
    "friction_coefficient": 0.2,
}

#: Table 1: measured and calculated minimum braid angles (D_o = 31 mm, D_s = 0.25 mm).
TABLE_1 = (
    MinBraidAngleMeasurement(240, 18.9, 0.57, 19.0),
    MinBraidAngleMeasurement(160, 13.7, 1.16, 12.1),
    MinBraidAngleMeasurement(120, 9.6, 0.97, 9.0),
)

#: S_scale fitted to experiments: the paper's (§3.3) and Tondu & Lopez's (at 400 kPa).
S_SCALE_FITS = (
    SScaleFit(200e3, 20.0, PAPER),
    SScaleFit(300e3, 16.0, PAPER),
    SScaleFit(400e3, 13.0, TONDU_LOPEZ),
)
