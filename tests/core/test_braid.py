"""Braid limits: eqs 8-9 against Table 1 and the paper's contraction gain."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pma_core import braid
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD
from tests.published import DavisCaldwell2006

D_S, D_O = 0.25e-3, 0.031


@pytest.mark.parametrize("strand_count", [240, 160, 120])
def test_min_braid_angle_reproduces_table_1(
    davis_caldwell_2006: DavisCaldwell2006, strand_count: int
) -> None:
    paper = davis_caldwell_2006
    theta = np.degrees(
        braid.min_braid_angle(paper.strand_diameter_m, strand_count, paper.theoretical_diameter_m)
    )
    assert theta == pytest.approx(paper.min_braid_angle_deg[strand_count], abs=0.05)


def test_min_braid_angle_broadcasts_over_arrays() -> None:
    counts = np.array([[240], [120]])
    diameters = np.array([0.2e-3, 0.25e-3])
    theta = braid.min_braid_angle(diameters, counts, D_O)
    assert theta.shape == (2, 2)
    assert np.degrees(theta[1, 1]) == pytest.approx(8.9706, abs=1e-4)


def test_contraction_gain_is_about_seven_percent(davis_caldwell_2006: DavisCaldwell2006) -> None:
    eps_240, eps_120 = braid.max_contraction(D_S, np.array([240, 120]), D_O)
    assert eps_240 == pytest.approx(0.3893, abs=5e-5)
    assert eps_120 == pytest.approx(0.4155, abs=5e-5)
    assert eps_120 / eps_240 - 1 == pytest.approx(davis_caldwell_2006.contraction_gain, abs=0.005)


def test_jamming_angle_mirrors_min_braid_angle() -> None:
    theta_min = braid.min_braid_angle(D_S, 240, D_O)
    assert braid.jamming_angle(D_S, 240, D_O) == pytest.approx(np.pi / 2 - theta_min)


def test_max_braid_angle_is_neutral_angle_unless_braid_jams_first() -> None:
    assert braid.max_braid_angle(D_S, 240, D_O) == pytest.approx(NEUTRAL_BRAID_ANGLE_RAD)
    # 380 strands fill 97.5 % of the circumference: θ_min 38.6°, jams at 51.4°.
    jammed = braid.max_braid_angle(D_S, 380, D_O)
    assert np.degrees(jammed) == pytest.approx(
        90 - np.degrees(braid.min_braid_angle(D_S, 380, D_O))
    )
    assert jammed < NEUTRAL_BRAID_ANGLE_RAD


def test_lengths_and_stroke_of_the_test_muscle() -> None:
    args = (0.65, 4.7, D_S, 240)
    l_max, l_min = braid.max_length(*args), braid.min_length(*args)
    assert l_max == pytest.approx(0.65 * np.cos(np.radians(12.855948)), rel=1e-7)
    assert l_min == pytest.approx(0.65 / np.sqrt(3), rel=1e-9)
    assert braid.stroke(*args) == pytest.approx(l_max - l_min)


def test_max_strand_count_is_the_fit_limit() -> None:
    limit = int(braid.max_strand_count(D_S, D_O))
    assert limit == 389
    braid.min_braid_angle(D_S, limit, D_O)
    with pytest.raises(ValueError, match="390 strands of 0.25 mm cannot fit around a 31 mm braid"):
        braid.min_braid_angle(D_S, limit + 1, D_O)


def test_refuses_strands_that_cannot_fit() -> None:
    with pytest.raises(ValueError, match="240 strands of 0.25 mm cannot fit around a 10 mm braid"):
        braid.min_braid_angle(D_S, 240, 0.010)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((0.0, 240, D_O), "strand_diameter_m must be greater than 0, got 0"),
        ((D_S, 1, D_O), "strand_count must be at least 2"),
        ((D_S, 240, -0.031), "theoretical_diameter_m must be greater than 0, got -0.031"),
        ((np.nan, 240, D_O), "strand_diameter_m must be a finite number, got nan"),
    ],
)
def test_refuses_impossible_parameters(args: tuple[float, float, float], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        braid.min_braid_angle(*args)


def test_refuses_unreachable_braid_angle() -> None:
    with pytest.raises(ValueError, match="outside the reachable range 19.02° to 70.98°"):
        braid.check_reachable_angle(np.radians(75.0), D_S, 240, D_O)


fits = st.tuples(st.floats(1e-5, 1e-3), st.integers(2, 2000), st.floats(1e-3, 0.2)).filter(
    lambda a: a[0] * a[1] < 0.99 * np.pi * a[2]
)


@given(fits, st.floats(1.001, 1.5))
def test_min_braid_angle_grows_with_strand_count_and_diameter(
    design: tuple[float, int, float], factor: float
) -> None:
    d_s, n, d_o = design
    theta = braid.min_braid_angle(d_s, n, d_o)
    if d_s * n * factor < 0.99 * np.pi * d_o:
        assert braid.min_braid_angle(d_s * factor, n, d_o) > theta
        assert braid.min_braid_angle(d_s, n * factor, d_o) > theta
    assert braid.min_braid_angle(d_s, n, d_o * factor) < theta
    assert 0 < theta < np.pi / 4


@given(fits)
def test_lengths_and_contraction_stay_consistent(design: tuple[float, int, float]) -> None:
    d_s, n, d_o = design
    b = 0.5
    turns = b / (np.pi * d_o)
    l_max = braid.max_length(b, turns, d_s, n)
    l_min = braid.min_length(b, turns, d_s, n)
    eps = braid.max_contraction(d_s, n, d_o)
    assert 0 < l_min < l_max <= b
    assert 1 - l_min / l_max == pytest.approx(eps, rel=1e-9, abs=1e-12)
    assert braid.stroke(b, turns, d_s, n) == pytest.approx(l_max - l_min)
