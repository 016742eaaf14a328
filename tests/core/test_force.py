"""Static force, eq 10: the paper's 1.16 ratio and the virtual-work cross-check."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pma_core.force import static_force
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD
from tests.published import DavisCaldwell2006


def test_force_ratio_at_10_and_20_degrees(davis_caldwell_2006: DavisCaldwell2006) -> None:
    f10, f20 = static_force(200e3, 0.031, np.radians([10.0, 20.0]))
    assert f10 / f20 == pytest.approx(davis_caldwell_2006.force_ratio_10_20, abs=0.005)


def test_ratio_at_exact_min_braid_angles_is_1_146() -> None:
    f = static_force(200e3, 0.031, np.radians([8.9706, 19.0154]))
    assert f[0] / f[1] == pytest.approx(1.146, abs=5e-4)


def test_force_vanishes_at_the_neutral_angle() -> None:
    assert static_force(500e3, 0.031, NEUTRAL_BRAID_ANGLE_RAD) == pytest.approx(0.0, abs=1e-9)


@given(st.floats(0.05, 1.5), st.floats(1e3, 1e6))
def test_static_force_is_minus_p_dv_dl(theta: float, p: float) -> None:
    # Virtual work: F = -P dV/dL with V = π D² L / 4, D = D_o sin θ, L = b cos θ.
    b, d_o = 0.65, 0.65 / (4.7 * np.pi)

    def volume(t: float) -> float:
        return float(np.pi * (d_o * np.sin(t)) ** 2 * b * np.cos(t) / 4)

    h = 1e-6
    dv = volume(theta + h) - volume(theta - h)
    dl = b * (np.cos(theta + h) - np.cos(theta - h))
    assert static_force(p, d_o, theta) == pytest.approx(-p * dv / dl, rel=1e-5, abs=1e-6)


def test_refuses_negative_pressure() -> None:
    with pytest.raises(ValueError, match="pressure_pa must be at least 0"):
        static_force(-1.0, 0.031, 0.3)
