"""Hysteresis, eq 31: branch ordering and the paper's test muscle."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pma_core import braid, friction
from pma_core.force import static_force
from pma_core.hysteresis import friction_branches, hysteresis_curves

MUSCLE = (0.65, 4.7, 0.25e-3, 240)


def test_curves_match_the_closed_forms_pointwise() -> None:
    c = hysteresis_curves(*MUSCLE, 200e3, 0.2, 3e9, 0.4, points=101)
    d_o = 0.65 / (4.7 * np.pi)
    assert c.force_static_n == pytest.approx(static_force(200e3, d_o, c.braid_angle_rad))
    area = friction.contact_area(0.65, 4.7, c.min_braid_angle_rad, c.braid_angle_rad)
    assert c.friction_force_n == pytest.approx(0.2 * area / c.s_scale * 200e3)
    assert c.length_m == pytest.approx(0.65 * np.cos(c.braid_angle_rad))
    assert c.contraction[-1] == pytest.approx(braid.max_contraction(0.25e-3, 240, d_o))
    assert np.diff(c.contraction) == pytest.approx(np.full(100, c.contraction[-1] / 100))


def test_measured_s_scale_overrides_eq_34() -> None:
    fitted = hysteresis_curves(*MUSCLE, 200e3, 0.2, 3e9, 0.4, s_scale=20.0, points=3)
    computed = hysteresis_curves(*MUSCLE, 200e3, 0.2, 3e9, 0.4, points=3)
    assert fitted.s_scale == 20.0
    assert computed.s_scale == pytest.approx(18.1, abs=0.05)
    assert fitted.friction_force_n == pytest.approx(computed.friction_force_n * 18.126 / 20, 1e-3)


def test_contracting_branch_is_clipped_at_zero() -> None:
    contracting, extending = friction_branches(np.array([5.0, 50.0]), np.array([10.0, 10.0]))
    assert contracting.tolist() == [0.0, 40.0]
    assert extending.tolist() == [15.0, 60.0]


def test_refuses_too_few_points() -> None:
    with pytest.raises(ValueError, match="points must be at least 2"):
        hysteresis_curves(*MUSCLE, 200e3, 0.2, 3e9, 0.4, points=1)


def test_refuses_zero_pressure() -> None:
    with pytest.raises(ValueError, match="pressure_pa must be greater than 0"):
        hysteresis_curves(*MUSCLE, 0.0, 0.2, 3e9, 0.4)


@given(st.floats(1e4, 1e6), st.floats(0.0, 1.0), st.integers(20, 380))
def test_contracting_below_static_below_extending(p: float, f_s: float, n: int) -> None:
    c = hysteresis_curves(0.65, 4.7, 0.25e-3, n, p, f_s, 3e9, 0.4, points=50)
    assert np.all(c.force_contracting_n >= 0)
    assert np.all(c.force_contracting_n <= np.maximum(c.force_static_n, 0) + 1e-9)
    assert np.all(c.force_static_n <= c.force_extending_n)
    assert np.all(np.diff(c.length_m) < 0)
