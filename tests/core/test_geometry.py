"""Kinematics, eqs 1, 18, 19."""

from __future__ import annotations

import numpy as np
import pytest

from pma_core import geometry


def test_theoretical_diameter_of_the_test_muscle() -> None:
    assert geometry.theoretical_diameter(0.65, 4.7) == pytest.approx(0.65 / (4.7 * np.pi))


def test_eq_1_round_trips() -> None:
    d_o = geometry.theoretical_diameter(0.65, 4.7)
    assert geometry.turns(0.65, d_o) == pytest.approx(4.7)
    assert geometry.strand_length(4.7, d_o) == pytest.approx(0.65)


def test_diameter_and_length_at_an_angle() -> None:
    theta = np.radians(30.0)
    assert geometry.actuator_diameter(0.031, theta) == pytest.approx(0.0155)
    assert geometry.actuator_length(0.65, theta) == pytest.approx(0.65 * np.sqrt(3) / 2)


def test_neutral_angle() -> None:
    assert np.degrees(geometry.NEUTRAL_BRAID_ANGLE_RAD) == pytest.approx(54.7356, abs=5e-5)


def test_braid_angle_at_contraction_inverts_the_length() -> None:
    theta_min = np.radians(19.0)
    theta = geometry.braid_angle_at_contraction(np.array([0.0, 0.2]), theta_min)
    assert np.cos(theta) / np.cos(theta_min) == pytest.approx([1.0, 0.8])


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: geometry.theoretical_diameter(0.65, 0.0), "turns must be greater than 0"),
        (lambda: geometry.actuator_length(-1.0, 0.3), "strand_length_m must be greater than 0"),
        (
            lambda: geometry.braid_angle_at_contraction(1.0, 0.3),
            r"contraction must lie in \[0, 1\)",
        ),
        (lambda: geometry.actuator_diameter(0.031, 2.0), "braid_angle_rad must lie strictly"),
    ],
)
def test_refusals(call: object, message: str) -> None:
    assert callable(call)
    with pytest.raises(ValueError, match=message):
        call()
