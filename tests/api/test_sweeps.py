"""POST /api/v1/sweeps/strand-count and /sweeps/pressure: the curves the page plots."""

from __future__ import annotations

import itertools
import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.api.conftest import ModelMd
from tests.api.support import error_at, ok
from tests.published import DavisCaldwell2006

STRANDS = "/api/v1/sweeps/strand-count"
PRESSURES = "/api/v1/sweeps/pressure"
STRAND_ARRAYS = {"strand_count", "min_braid_angle_deg", "max_contraction", "max_gap_area_m2"}
PRESSURE_ARRAYS = {
    "pressure_pa",
    "s_scale",
    "min_strand_count_exact",
    "min_strand_count",
    "worst_case_min_strand_count_exact",
    "worst_case_min_strand_count",
}


def test_strand_count_sweep_reproduces_table_1_and_eq_15(
    client: TestClient,
    strand_sweep: dict[str, Any],
    davis_caldwell_2006: DavisCaldwell2006,
    model_md: ModelMd,
) -> None:
    data = ok(client, STRANDS, strand_sweep)
    assert set(data) == STRAND_ARRAYS | {"strand_count_limit"}
    assert data["strand_count"] == list(range(60, 301))
    assert {len(data[name]) for name in STRAND_ARRAYS} == {241}
    at = {n: i for i, n in enumerate(data["strand_count"])}
    for n, angle in davis_caldwell_2006.min_braid_angle_deg.items():
        assert round(data["min_braid_angle_deg"][at[n]], 1) == angle
    for n, area in davis_caldwell_2006.max_gap_area_mm2.items():
        assert round(data["max_gap_area_m2"][at[n]] * 1e6, 2) == area
    for n, contraction in model_md.max_contraction.items():
        assert round(data["max_contraction"][at[n]], 4) == contraction
    assert data["strand_count_limit"] == model_md.strand_count_limit


def test_strand_count_sweep_is_monotonic(client: TestClient, strand_sweep: dict[str, Any]) -> None:
    data = ok(client, STRANDS, {**strand_sweep, "strand_count_min": 2, "strand_count_max": 389})
    angles, eps, gaps = (
        data["min_braid_angle_deg"],
        data["max_contraction"],
        data["max_gap_area_m2"],
    )
    assert all(0 < a < b < 45 for a, b in itertools.pairwise(angles))
    assert all(a >= b for a, b in itertools.pairwise(eps))
    assert all(a >= b >= 0 for a, b in itertools.pairwise(gaps))


def test_strand_count_sweep_agrees_with_the_single_calculations(
    client: TestClient, strand_sweep: dict[str, Any]
) -> None:
    data = ok(client, STRANDS, {**strand_sweep, "strand_count_min": 97, "strand_count_max": 103})
    braid = {k: strand_sweep[k] for k in ("strand_diameter_m", "theoretical_diameter_m")}
    for i, n in enumerate(data["strand_count"]):
        single = ok(client, "/api/v1/min-braid-angle", {**braid, "strand_count": n})
        assert data["min_braid_angle_deg"][i] == pytest.approx(single["min_braid_angle_deg"])
        assert data["max_contraction"][i] == pytest.approx(single["max_contraction"])
        gap = ok(client, "/api/v1/gap-area", {**braid, "strand_count": n, "parallel_strands": 3})
        assert data["max_gap_area_m2"][i] == pytest.approx(gap["max_gap_area_m2"])


def test_strand_count_sweep_stops_where_strands_stop_fitting(
    client: TestClient, strand_sweep: dict[str, Any], model_md: ModelMd
) -> None:
    limit = model_md.strand_count_limit
    body = {**strand_sweep, "strand_count_min": 380, "strand_count_max": 400}
    data = ok(client, STRANDS, body)
    assert data["strand_count"] == list(range(380, limit + 1))
    assert data["strand_count_limit"] == limit
    # The limit is the largest N with N·D_s < π·D_o.
    d_s, d_o = strand_sweep["strand_diameter_m"], strand_sweep["theoretical_diameter_m"]
    assert limit * d_s < math.pi * d_o <= (limit + 1) * d_s


def test_a_single_strand_count(client: TestClient, strand_sweep: dict[str, Any]) -> None:
    body = {**strand_sweep, "strand_count_min": 240, "strand_count_max": 240}
    data = ok(client, STRANDS, body)
    assert data["strand_count"] == [240]
    assert {len(data[name]) for name in STRAND_ARRAYS} == {1}


def test_pressure_sweep(
    client: TestClient,
    pressure_sweep: dict[str, Any],
    davis_caldwell_2006: DavisCaldwell2006,
) -> None:
    data = ok(client, PRESSURES, pressure_sweep)
    assert set(data) == PRESSURE_ARRAYS
    assert data["pressure_pa"] == [100e3, 200e3, 300e3, 400e3, 500e3]
    s = dict(zip(data["pressure_pa"], data["s_scale"], strict=True))
    assert round(s[200e3], 1) == davis_caldwell_2006.s_scale[200e3]
    assert round(s[300e3], 1) == davis_caldwell_2006.s_scale[300e3]
    # The paper truncates the 400 kPa value (14.39 → 14.3).
    assert math.floor(10 * s[400e3]) / 10 == davis_caldwell_2006.s_scale[400e3]
    assert data["min_strand_count"][-1] == davis_caldwell_2006.failure_strand_count
    assert data["worst_case_min_strand_count"][-1] == (
        davis_caldwell_2006.worst_case_failure_strand_count
    )


def test_pressure_sweep_shapes(client: TestClient, pressure_sweep: dict[str, Any]) -> None:
    body = {**pressure_sweep, "pressure_min_pa": 50e3, "pressure_max_pa": 600e3, "points": 12}
    data = ok(client, PRESSURES, body)
    assert {len(data[name]) for name in PRESSURE_ARRAYS} == {12}
    p = data["pressure_pa"]
    assert p[0] == 50e3
    assert p[-1] == 600e3
    for i, value in enumerate(p):
        assert value == pytest.approx(50e3 + i * 50e3, rel=1e-12)
    assert all(a > b for a, b in zip(data["s_scale"], data["s_scale"][1:], strict=False))
    for exact, whole in zip(data["min_strand_count_exact"], data["min_strand_count"], strict=True):
        assert whole == math.ceil(exact)
        assert type(whole) is int
    for name in ("min_strand_count_exact", "worst_case_min_strand_count_exact"):
        # Eq 20 is proportional to the pressure.
        for pressure, count in zip(p, data[name], strict=True):
            assert count / pressure == pytest.approx(data[name][0] / p[0], rel=1e-12)
    assert all(
        a < b
        for a, b in zip(
            data["min_strand_count_exact"], data["worst_case_min_strand_count_exact"], strict=True
        )
    )


def test_pressure_sweep_default_points(client: TestClient, pressure_sweep: dict[str, Any]) -> None:
    body = {k: v for k, v in pressure_sweep.items() if k != "points"}
    data = ok(client, PRESSURES, body)
    assert {len(data[name]) for name in PRESSURE_ARRAYS} == {101}


def test_pressure_sweep_with_a_safety_factor(
    client: TestClient, pressure_sweep: dict[str, Any]
) -> None:
    plain = ok(client, PRESSURES, pressure_sweep)
    safe = ok(client, PRESSURES, {**pressure_sweep, "safety_factor": 2.0})
    for a, b in zip(plain["min_strand_count_exact"], safe["min_strand_count_exact"], strict=True):
        assert b == pytest.approx(2 * a, rel=1e-12)
    assert safe["s_scale"] == plain["s_scale"]


def test_a_range_wholly_beyond_the_fit_limit_is_refused(
    client: TestClient, strand_sweep: dict[str, Any]
) -> None:
    body = {**strand_sweep, "strand_count_min": 390, "strand_count_max": 400}
    response = client.post(STRANDS, json=body)
    assert response.status_code == 422
    error = response.json()["detail"][0]
    assert "cannot fit around" in error["msg"]
    assert "390 strands" in error["msg"]


def test_a_range_beyond_the_fit_limit_names_the_field(
    client: TestClient, strand_sweep: dict[str, Any]
) -> None:
    body = {**strand_sweep, "strand_count_min": 390, "strand_count_max": 400}
    error = error_at(client.post(STRANDS, json=body), "strand_count_min")
    assert "cannot fit around" in error["msg"]


# The sweep bodies are only read, never changed: sharing them between examples is safe.
@settings(
    max_examples=40,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(low=st.integers(2, 389), span=st.integers(0, 400))
def test_any_strand_range_is_cut_at_the_limit(
    client: TestClient, strand_sweep: dict[str, Any], low: int, span: int
) -> None:
    body = {**strand_sweep, "strand_count_min": low, "strand_count_max": low + span}
    data = ok(client, STRANDS, body)
    assert data["strand_count"] == list(range(low, min(low + span, 389) + 1))
    assert {len(data[name]) for name in STRAND_ARRAYS} == {len(data["strand_count"])}


def test_hysteresis_sweep_is_the_hysteresis_curve_at_each_pressure(
    client: TestClient, hysteresis_sweep: dict[str, Any]
) -> None:
    family = ok(client, "/api/v1/sweeps/hysteresis", {**hysteresis_sweep, "points": 21})
    assert family["pressure_pa"] == [100e3, 300e3, 500e3]
    single_body = {k: v for k, v in hysteresis_sweep.items() if k != "pressures_pa"}
    for row, pressure in enumerate(family["pressure_pa"]):
        single = ok(
            client, "/api/v1/hysteresis", {**single_body, "pressure_pa": pressure, "points": 21}
        )
        assert family["s_scale"][row] == single["s_scale"]
        assert family["contraction"] == single["contraction"]
        for name in ("force_static_n", "friction_force_n", "force_contracting_n"):
            assert family[name][row] == single[name], name
    assert round(family["s_scale"][1], 1) == 15.8


def test_hysteresis_sweep_caps_the_number_of_pressures(
    client: TestClient, hysteresis_sweep: dict[str, Any]
) -> None:
    response = client.post(
        "/api/v1/sweeps/hysteresis", json={**hysteresis_sweep, "pressures_pa": [1e5] * 17}
    )
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["body", "pressures_pa"]
