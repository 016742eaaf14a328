"""POST /api/v1/min-braid-angle: Table 1, the contractile range gain, lengths (eqs 8-9)."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from tests.api.conftest import DavisCaldwell2006Measured, ModelMd
from tests.api.support import ok
from tests.published import DavisCaldwell2006

PATH = "/api/v1/min-braid-angle"
#: API.md's response fields, and the additions documented in the OpenAPI schema.
CONTRACT = {
    "min_braid_angle_deg",
    "max_braid_angle_deg",
    "max_contraction",
    "theoretical_diameter_m",
    "max_length_m",
    "min_length_m",
}
ADDITIONS = {"jamming_angle_deg", "stroke_m"}
NEUTRAL_DEG = math.degrees(math.acos(1 / math.sqrt(3)))


@pytest.mark.parametrize("strand_count", [240, 160, 120])
def test_table_1_minimum_braid_angles(
    client: TestClient,
    paper_braid: dict[str, Any],
    davis_caldwell_2006: DavisCaldwell2006,
    strand_count: int,
) -> None:
    data = ok(client, PATH, {**paper_braid, "strand_count": strand_count})
    # Table 1 prints the calculated angle to 0.1°.
    assert (
        round(data["min_braid_angle_deg"], 1)
        == (davis_caldwell_2006.min_braid_angle_deg[strand_count])
    )


@pytest.mark.parametrize("strand_count", [240, 160, 120])
def test_calculated_angle_lies_near_the_measured_one(
    client: TestClient,
    paper_braid: dict[str, Any],
    davis_caldwell_2006_measured: DavisCaldwell2006Measured,
    strand_count: int,
) -> None:
    # The paper: "the two values correspond closely"; within 2 standard deviations here.
    mean, std = davis_caldwell_2006_measured.min_braid_angle_measured_deg[strand_count]
    data = ok(client, PATH, {**paper_braid, "strand_count": strand_count})
    assert abs(data["min_braid_angle_deg"] - mean) <= 2 * std


def test_response_fields_are_the_contract(client: TestClient, paper_braid: dict[str, Any]) -> None:
    data = ok(client, PATH, paper_braid)
    assert set(data) == CONTRACT | ADDITIONS
    assert data["theoretical_diameter_m"] == paper_braid["theoretical_diameter_m"]
    # Without b the lengths are unknown: null, not 0 and not absent.
    assert data["max_length_m"] is None
    assert data["min_length_m"] is None
    assert data["stroke_m"] is None


def test_paper_braid_reaches_the_neutral_angle(
    client: TestClient, paper_braid: dict[str, Any], model_md: ModelMd
) -> None:
    data = ok(client, PATH, paper_braid)
    assert round(data["max_braid_angle_deg"], 4) == model_md.neutral_braid_angle_deg
    assert data["jamming_angle_deg"] == pytest.approx(90.0 - data["min_braid_angle_deg"])
    assert round(data["max_contraction"], 4) == model_md.max_contraction[240]


def test_halving_the_strands_gives_about_7_percent_more_range(
    client: TestClient, paper_braid: dict[str, Any], model_md: ModelMd
) -> None:
    dense = ok(client, PATH, {**paper_braid, "strand_count": 240})["max_contraction"]
    sparse = ok(client, PATH, {**paper_braid, "strand_count": 120})["max_contraction"]
    assert round(dense, 4) == model_md.max_contraction[240]
    assert round(sparse, 4) == model_md.max_contraction[120]
    gain = sparse / dense - 1
    assert round(gain, 3) == model_md.contraction_gain
    # The paper's words: "approximately 7 %".
    assert round(gain * 100) == 7


def test_lengths_from_strand_length_and_turns(
    client: TestClient, paper_braid: dict[str, Any], davis_caldwell_2006: DavisCaldwell2006
) -> None:
    b, n = davis_caldwell_2006.strand_length_m, davis_caldwell_2006.turns
    body = {k: v for k, v in paper_braid.items() if k != "theoretical_diameter_m"}
    data = ok(client, PATH, {**body, "strand_length_m": b, "turns": n})
    assert data["theoretical_diameter_m"] == pytest.approx(b / (n * math.pi), rel=1e-12)
    theta_min = math.radians(data["min_braid_angle_deg"])
    theta_max = math.radians(data["max_braid_angle_deg"])
    assert data["max_length_m"] == pytest.approx(b * math.cos(theta_min), rel=1e-12)
    assert data["min_length_m"] == pytest.approx(b * math.cos(theta_max), rel=1e-12)
    assert data["stroke_m"] == pytest.approx(data["max_length_m"] - data["min_length_m"])
    assert data["max_contraction"] == pytest.approx(1 - data["min_length_m"] / data["max_length_m"])


def test_both_geometry_forms_give_the_same_braid(
    client: TestClient, paper_braid: dict[str, Any]
) -> None:
    d_o = paper_braid["theoretical_diameter_m"]
    turns = 5.0
    by_diameter = ok(client, PATH, paper_braid)
    body = {k: v for k, v in paper_braid.items() if k != "theoretical_diameter_m"}
    by_length = ok(client, PATH, {**body, "strand_length_m": turns * math.pi * d_o, "turns": turns})
    for name in ("min_braid_angle_deg", "max_braid_angle_deg", "max_contraction"):
        assert by_length[name] == pytest.approx(by_diameter[name], rel=1e-12)


@pytest.mark.parametrize(
    ("other", "strand_length_m"),
    [({"strand_length_m": 0.4}, 0.4), ({"turns": 3.0}, 3.0 * math.pi * 0.031)],
)
def test_diameter_with_one_more_quantity_gives_the_lengths(
    client: TestClient, paper_braid: dict[str, Any], other: dict[str, float], strand_length_m: float
) -> None:
    # D_o with b gives n; D_o with n gives b = n·π·D_o (eq 1): either way the lengths are known.
    data = ok(client, PATH, {**paper_braid, **other})
    assert data["theoretical_diameter_m"] == paper_braid["theoretical_diameter_m"]
    theta_min = math.radians(data["min_braid_angle_deg"])
    assert data["max_length_m"] == pytest.approx(strand_length_m * math.cos(theta_min), rel=1e-12)
    assert data["min_length_m"] == pytest.approx(strand_length_m / math.sqrt(3), rel=1e-9)


def test_minimum_angle_does_not_depend_on_length(
    client: TestClient, paper_braid: dict[str, Any]
) -> None:
    short = ok(client, PATH, {**paper_braid, "strand_length_m": 0.1})
    long = ok(client, PATH, {**paper_braid, "strand_length_m": 2.0})
    assert short["min_braid_angle_deg"] == long["min_braid_angle_deg"]
    assert long["max_length_m"] == pytest.approx(20 * short["max_length_m"])


def test_dense_braid_jams_before_the_neutral_angle(
    client: TestClient, paper_braid: dict[str, Any], model_md: ModelMd
) -> None:
    # θ_min > 35.26° (strands fill > 94.3 % of the circumference): θ_max = 90° − θ_min.
    data = ok(client, PATH, {**paper_braid, "strand_count": 380})
    assert data["min_braid_angle_deg"] > 90.0 - NEUTRAL_DEG
    assert data["max_braid_angle_deg"] == pytest.approx(90.0 - data["min_braid_angle_deg"])
    assert data["max_braid_angle_deg"] < model_md.neutral_braid_angle_deg
    assert 0 < data["max_contraction"] < model_md.max_contraction[240]


def test_the_densest_braid_that_fits(
    client: TestClient, paper_braid: dict[str, Any], model_md: ModelMd
) -> None:
    data = ok(client, PATH, {**paper_braid, "strand_count": model_md.strand_count_limit})
    assert 40.0 < data["min_braid_angle_deg"] < 45.0
    assert data["max_braid_angle_deg"] > data["min_braid_angle_deg"]
    assert 0 < data["max_contraction"] < 0.1


@st.composite
def braids(draw: st.DrawFn) -> dict[str, Any]:
    """D_s, D_o and a strand count that fits: N·D_s < π·D_o, with 0.1 % to spare."""
    d_s = draw(st.floats(1e-5, 2e-3))
    d_o = draw(st.floats(max(1e-3, d_s), 0.3))
    # D_o ≥ D_s, so at least 3 strands fit.
    n = draw(st.integers(2, fit_limit(d_s, d_o)))
    return {"strand_diameter_m": d_s, "strand_count": n, "theoretical_diameter_m": d_o}


def fit_limit(strand_diameter_m: float, theoretical_diameter_m: float) -> int:
    """Largest N with N·D_s ≤ 0.999·π·D_o, capped at the API's 100 000."""
    return min(math.floor(0.999 * math.pi * theoretical_diameter_m / strand_diameter_m), 100_000)


@settings(max_examples=60, deadline=None, database=None)
@given(braid=braids())
def test_any_braid_that_fits_has_an_angle_between_0_and_45(
    client: TestClient, braid: dict[str, Any]
) -> None:
    data = ok(client, PATH, braid)
    theta_min = data["min_braid_angle_deg"]
    assert 0 < theta_min < 45
    fill = (
        braid["strand_diameter_m"]
        * braid["strand_count"]
        / (math.pi * braid["theoretical_diameter_m"])
    )
    assert theta_min == pytest.approx(math.degrees(0.5 * math.asin(fill)), rel=1e-9)
    assert data["jamming_angle_deg"] == pytest.approx(90 - theta_min, rel=1e-12)
    assert data["max_braid_angle_deg"] == pytest.approx(min(NEUTRAL_DEG, 90 - theta_min))
    assert theta_min < data["max_braid_angle_deg"] <= NEUTRAL_DEG + 1e-9
    expected = 1 - math.cos(math.radians(data["max_braid_angle_deg"])) / math.cos(
        math.radians(theta_min)
    )
    assert data["max_contraction"] == pytest.approx(expected, abs=1e-12)
    assert 0 < data["max_contraction"] < 1 - 1 / math.sqrt(3) + 1e-12


@settings(max_examples=40, deadline=None, database=None)
@given(braid=braids(), extra=st.integers(1, 50))
def test_more_strands_mean_a_larger_angle_and_less_range(
    client: TestClient, braid: dict[str, Any], extra: int
) -> None:
    limit = fit_limit(braid["strand_diameter_m"], braid["theoretical_diameter_m"])
    denser_count = min(braid["strand_count"] + extra, limit)
    assume(denser_count > braid["strand_count"])
    sparse = ok(client, PATH, braid)
    dense = ok(client, PATH, {**braid, "strand_count": denser_count})
    assert dense["min_braid_angle_deg"] > sparse["min_braid_angle_deg"]
    assert dense["max_contraction"] < sparse["max_contraction"]
