"""Braid strength: eq 20 against the paper's 97 strands, and 103 at the 45° worst case."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pma_core import strength
from tests.published import DavisCaldwell2006


def _counts(paper: DavisCaldwell2006, angle: float) -> tuple[float, float]:
    exact = strength.failure_strand_count(
        paper.failure_pressure_pa,
        paper.theoretical_diameter_m,
        paper.strand_diameter_m,
        paper.tensile_strength_pa,
        angle,
    )
    return float(exact), float(strength.min_strand_count(exact))


def test_failure_strand_count_reproduces_97(davis_caldwell_2006: DavisCaldwell2006) -> None:
    exact, whole = _counts(davis_caldwell_2006, float(np.arccos(1 / np.sqrt(3))))
    assert exact == pytest.approx(96.64, abs=0.005)
    assert whole == davis_caldwell_2006.failure_strand_count


def test_worst_case_at_45_degrees_needs_103(davis_caldwell_2006: DavisCaldwell2006) -> None:
    exact, whole = _counts(davis_caldwell_2006, strength.WORST_CASE_BRAID_ANGLE_RAD)
    assert exact == pytest.approx(102.5, abs=0.01)
    assert whole == davis_caldwell_2006.worst_case_failure_strand_count


def test_stress_at_the_failure_count_is_the_tensile_strength() -> None:
    n = strength.failure_strand_count(500e3, 0.031, 0.25e-3, 75e6, np.pi / 4)
    assert strength.strand_stress(500e3, 0.031, 0.25e-3, n, np.pi / 4) == pytest.approx(75e6)


def test_safety_factor_divides_the_strength() -> None:
    plain = strength.failure_strand_count(500e3, 0.031, 0.25e-3, 75e6)
    assert strength.failure_strand_count(500e3, 0.031, 0.25e-3, 75e6, safety_factor=2.0) == (
        pytest.approx(2 * plain)
    )


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"safety_factor": 0.5}, "safety_factor must be at least 1"),
        ({"tensile_strength_pa": 0.0}, "tensile_strength_pa must be greater than 0"),
        ({"pressure_pa": -1.0}, "pressure_pa must be greater than 0, got -1"),
        ({"braid_angle_rad": np.pi / 2}, "braid_angle_rad must lie strictly between 0 and 90°"),
    ],
)
def test_refusals(kwargs: dict[str, float], message: str) -> None:
    args: dict[str, float] = {
        "pressure_pa": 500e3,
        "theoretical_diameter_m": 0.031,
        "strand_diameter_m": 0.25e-3,
        "tensile_strength_pa": 75e6,
    }
    with pytest.raises(ValueError, match=message):
        strength.failure_strand_count(**{**args, **kwargs})


@given(st.floats(1e3, 1e7), st.floats(1.01, 10.0), st.floats(0.05, 1.5))
def test_failure_count_is_proportional_to_pressure(p: float, k: float, theta: float) -> None:
    n1 = strength.failure_strand_count(p, 0.031, 0.25e-3, 75e6, theta)
    nk = strength.failure_strand_count(p * k, 0.031, 0.25e-3, 75e6, theta)
    assert nk == pytest.approx(k * n1, rel=1e-12)
    assert n1 <= strength.failure_strand_count(p, 0.031, 0.25e-3, 75e6, np.pi / 4) * (1 + 1e-12)


def test_min_strand_count_rounds_up_but_not_float_noise() -> None:
    assert strength.min_strand_count(np.array([96.01, 97.0, 97.0 * (1 + 1e-15)])).tolist() == [
        97.0,
        97.0,
        97.0,
    ]
