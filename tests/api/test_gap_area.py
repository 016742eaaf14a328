"""POST /api/v1/gap-area: node spacing, gap width and the eq 15 maximum gap (eqs 12-15)."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.api.support import ok
from tests.published import DavisCaldwell2006

PATH = "/api/v1/gap-area"
CONTRACT = {"braid_angle_deg", "node_spacing_m", "gap_width_m", "gap_area_m2", "max_gap_area_m2"}


def _limits(client: TestClient, body: dict[str, Any]) -> tuple[float, float]:
    """The reachable range [θ_min, 90° − θ_min] of ``body``'s braid, from the API [deg]."""
    braid = {k: v for k, v in body.items() if k not in ("parallel_strands", "braid_angle_deg")}
    data = ok(client, "/api/v1/min-braid-angle", braid)
    return data["min_braid_angle_deg"], data["jamming_angle_deg"]


@pytest.mark.parametrize("strand_count", [240, 120])
def test_eq_15_maximum_gap_areas(
    client: TestClient,
    paper_gap: dict[str, Any],
    davis_caldwell_2006: DavisCaldwell2006,
    strand_count: int,
) -> None:
    data = ok(client, PATH, {**paper_gap, "strand_count": strand_count})
    # The paper prints 0.22 mm² and 2.84 mm²: two decimals of mm².
    assert (
        round(data["max_gap_area_m2"] * 1e6, 2)
        == (davis_caldwell_2006.max_gap_area_mm2[strand_count])
    )


def test_response_fields_are_the_contract(client: TestClient, paper_gap: dict[str, Any]) -> None:
    assert set(ok(client, PATH, paper_gap)) == CONTRACT


def test_default_angle_is_45_where_the_gap_is_largest(
    client: TestClient, paper_gap: dict[str, Any]
) -> None:
    data = ok(client, PATH, paper_gap)
    assert data["braid_angle_deg"] == 45.0
    assert data["gap_area_m2"] == pytest.approx(data["max_gap_area_m2"], rel=1e-12)
    assert data["gap_area_m2"] == pytest.approx(data["gap_width_m"] ** 2 / 2, rel=1e-12)


@pytest.mark.parametrize("angle_deg", [25.0, 45.0, 60.0])
def test_spacing_width_and_area_follow_eqs_12_to_15(
    client: TestClient, paper_gap: dict[str, Any], angle_deg: float
) -> None:
    data = ok(client, PATH, {**paper_gap, "braid_angle_deg": angle_deg})
    s, n = paper_gap["parallel_strands"], paper_gap["strand_count"]
    d_o, d_s = paper_gap["theoretical_diameter_m"], paper_gap["strand_diameter_m"]
    theta = math.radians(angle_deg)
    spacing = 2 * s * math.pi * d_o * math.sin(theta) / n  # eq 12
    width = spacing - d_s * s / math.cos(theta)  # eq 14
    assert data["braid_angle_deg"] == angle_deg
    assert data["node_spacing_m"] == pytest.approx(spacing, rel=1e-12)
    assert data["gap_width_m"] == pytest.approx(width, rel=1e-9)
    assert data["gap_area_m2"] == pytest.approx(width**2 / (2 * math.tan(theta)), rel=1e-9)
    assert data["gap_area_m2"] <= data["max_gap_area_m2"]


def test_the_gap_closes_at_both_ends_of_the_reachable_range(
    client: TestClient, paper_gap: dict[str, Any]
) -> None:
    low, high = _limits(client, paper_gap)
    for angle in (low, high):
        data = ok(client, PATH, {**paper_gap, "braid_angle_deg": angle})
        assert data["node_spacing_m"] > 0
        assert data["gap_width_m"] == pytest.approx(0.0, abs=1e-12)
        assert data["gap_area_m2"] == pytest.approx(0.0, abs=1e-18)
        assert data["gap_width_m"] >= 0


def test_parallel_strands_default_to_one(client: TestClient, paper_gap: dict[str, Any]) -> None:
    single = {k: v for k, v in paper_gap.items() if k != "parallel_strands"}
    default = ok(client, PATH, single)
    explicit = ok(client, PATH, {**single, "parallel_strands": 1})
    triple = ok(client, PATH, paper_gap)
    assert default == explicit
    # G and Z both scale with S (eqs 12, 14), so the area scales with S².
    assert triple["node_spacing_m"] == pytest.approx(3 * default["node_spacing_m"], rel=1e-12)
    assert triple["gap_width_m"] == pytest.approx(3 * default["gap_width_m"], rel=1e-9)
    assert triple["max_gap_area_m2"] == pytest.approx(9 * default["max_gap_area_m2"], rel=1e-9)


def test_fewer_strands_open_the_braid(client: TestClient, paper_gap: dict[str, Any]) -> None:
    areas = [
        ok(client, PATH, {**paper_gap, "strand_count": n})["max_gap_area_m2"]
        for n in (300, 240, 160, 120, 60)
    ]
    assert areas == sorted(areas)
    assert len(set(areas)) == len(areas)


@settings(max_examples=60, deadline=None, database=None)
@given(
    strand_count=st.integers(2, 389),
    parallel_strands=st.integers(1, 6),
    where=st.floats(0.0, 1.0),
)
def test_any_reachable_angle_gives_a_gap_no_larger_than_at_45(
    client: TestClient, strand_count: int, parallel_strands: int, where: float
) -> None:
    braid: dict[str, Any] = {
        "strand_diameter_m": 0.25e-3,
        "strand_count": strand_count,
        "theoretical_diameter_m": 0.031,
    }
    low, high = _limits(client, braid)
    # Inside the range, away from the ends by a hair so rounding cannot leave it.
    angle = low + (high - low) * (1e-9 + where * (1 - 2e-9))
    body = {**braid, "parallel_strands": parallel_strands, "braid_angle_deg": angle}
    data = ok(client, PATH, body)
    assert data["node_spacing_m"] > 0
    assert 0 <= data["gap_width_m"] <= data["node_spacing_m"]
    assert 0 <= data["gap_area_m2"] <= data["max_gap_area_m2"] * (1 + 1e-12)
