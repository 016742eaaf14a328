"""Friction scaling: eqs 29-34 against the paper's S_scale of 18.1, 15.8 and 14.3."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pma_core import friction
from tests.published import DavisCaldwell2006


@pytest.mark.parametrize("pressure_pa", [200e3, 300e3])
def test_s_scale_reproduces_eq_34(
    davis_caldwell_2006: DavisCaldwell2006, pressure_pa: float
) -> None:
    paper = davis_caldwell_2006
    scale = friction.s_scale(
        pressure_pa, paper.strand_diameter_m, paper.youngs_modulus_pa, paper.poisson_ratio
    )
    assert scale == pytest.approx(paper.s_scale[pressure_pa], abs=0.05)


def test_s_scale_at_400_kpa_is_printed_truncated(davis_caldwell_2006: DavisCaldwell2006) -> None:
    paper = davis_caldwell_2006
    scale = float(friction.s_scale(400e3, 0.25e-3, 3e9, 0.4))
    assert scale == pytest.approx(14.39, abs=0.005)
    # The paper prints 14.3: it truncates rather than rounds.
    assert math.floor(scale * 10) / 10 == paper.s_scale[400e3]


def test_hertz_coefficient_is_the_rounded_exact_value() -> None:
    assert friction.HERTZ_COEFFICIENT == pytest.approx((3 / 8) ** (1 / 3), abs=5e-4)


def test_contact_area_at_min_angle_is_the_dilated_surface() -> None:
    b, n = 0.65, 4.7
    theta_min = np.radians(12.856)
    d_o = b / (n * np.pi)
    surface = np.pi * d_o * np.sin(theta_min) * b * np.cos(theta_min)
    assert friction.contact_area(b, n, theta_min, theta_min) == pytest.approx(surface)


def test_friction_force_is_eq_30() -> None:
    assert friction.friction_force(0.2, 0.03, 18.1, 200e3) == pytest.approx(0.2 * 0.03 / 18.1 * 2e5)


def test_refuses_zero_pressure_for_s_scale() -> None:
    with pytest.raises(ValueError, match="pressure_pa must be greater than 0, got 0"):
        friction.s_scale(0.0, 0.25e-3, 3e9, 0.4)


def test_refuses_poisson_ratio_of_half() -> None:
    with pytest.raises(ValueError, match=r"poisson_ratio must lie in \[0, 0.5\)"):
        friction.s_scale(200e3, 0.25e-3, 3e9, 0.5)


@given(st.floats(1e3, 1e7), st.floats(1.001, 10.0))
def test_s_scale_falls_with_pressure(p: float, factor: float) -> None:
    low, high = friction.s_scale(np.array([p, p * factor]), 0.25e-3, 3e9, 0.4)
    assert high < low
    assert high / low == pytest.approx(factor ** (-1 / 3), rel=1e-9)
