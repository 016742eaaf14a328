"""Braid gaps: eqs 12-15 against the paper's 0.22 and 2.84 mm²."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pma_core import braid, gap
from tests.published import DavisCaldwell2006


@pytest.mark.parametrize("strand_count", [240, 120])
def test_max_gap_area_reproduces_eq_15(
    davis_caldwell_2006: DavisCaldwell2006, strand_count: int
) -> None:
    paper = davis_caldwell_2006
    area = gap.max_gap_area(
        paper.theoretical_diameter_m, paper.strand_diameter_m, strand_count, paper.parallel_strands
    )
    assert area * 1e6 == pytest.approx(paper.max_gap_area_mm2[strand_count], abs=0.005)


def test_node_spacing_and_width_follow_eqs_12_and_14() -> None:
    theta = np.radians(30.0)
    g = gap.node_spacing(0.031, 120, 3, theta)
    assert g == pytest.approx(2 * 3 * np.pi * 0.031 * 0.5 / 120)
    z = gap.gap_width(0.031, 0.25e-3, 120, 3, theta)
    assert z == pytest.approx(g - 0.25e-3 * 3 / np.cos(theta))


def test_gap_closes_at_both_ends_of_the_reachable_range() -> None:
    theta_min = braid.min_braid_angle(0.25e-3, 240, 0.031)
    ends = np.array([theta_min, np.pi / 2 - theta_min])
    assert gap.gap_width(0.031, 0.25e-3, 240, 3, ends) == pytest.approx([0.0, 0.0], abs=1e-12)


def test_refuses_angle_outside_reachable_range() -> None:
    with pytest.raises(ValueError, match="braid_angle_deg: 10° is outside the reachable range"):
        gap.gap_area(0.031, 0.25e-3, 240, 3, np.radians(10.0))


def test_refuses_zero_parallel_strands() -> None:
    with pytest.raises(ValueError, match="parallel_strands must be at least 1"):
        gap.max_gap_area(0.031, 0.25e-3, 240, 0)


@given(st.integers(2, 380), st.integers(1, 4), st.floats(0.02, 0.98))
def test_gap_area_peaks_at_45_degrees(strand_count: int, parallel: int, where: float) -> None:
    theta_min = float(braid.min_braid_angle(0.25e-3, strand_count, 0.031))
    theta = theta_min + where * (np.pi / 2 - 2 * theta_min)
    args = (0.031, 0.25e-3, strand_count, parallel)
    assert gap.gap_area(*args, theta) <= gap.max_gap_area(*args) * (1 + 1e-12)


def test_max_gap_area_equals_dense_numerical_maximum() -> None:
    args = (0.031, 0.25e-3, 120, 3)
    theta_min = float(braid.min_braid_angle(0.25e-3, 120, 0.031))
    theta = np.linspace(theta_min, np.pi / 2 - theta_min, 200_001)
    areas = gap.gap_area(*args, theta)
    assert theta[np.argmax(areas)] == pytest.approx(np.pi / 4, abs=1e-4)
    assert areas.max() == pytest.approx(gap.max_gap_area(*args), rel=1e-9)
