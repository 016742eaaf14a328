"""POST /api/v1/hysteresis: static force and both friction branches along the stroke."""

from __future__ import annotations

import itertools
import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.api.conftest import ModelMd
from tests.api.support import ok
from tests.published import DavisCaldwell2006

PATH = "/api/v1/hysteresis"
SCALARS = {"s_scale", "min_braid_angle_deg", "max_braid_angle_deg"}
ARRAYS = {
    "braid_angle_deg",
    "length_m",
    "contraction",
    "force_static_n",
    "friction_force_n",
    "force_contracting_n",
    "force_extending_n",
}


def check_curves(data: dict[str, Any], points: int) -> None:
    """The invariants of every hysteresis response with ``points`` points."""
    assert set(data) == SCALARS | ARRAYS
    for name in ARRAYS:
        assert len(data[name]) == points, name
        assert all(isinstance(x, float | int) and math.isfinite(x) for x in data[name]), name
    eps = data["contraction"]
    # Evenly spaced from 0 to the maximum contraction, both ends included.
    assert eps[0] == 0.0
    step = eps[-1] / (points - 1)
    for i, value in enumerate(eps):
        assert value == pytest.approx(i * step, rel=1e-12, abs=1e-15)
    angles = data["braid_angle_deg"]
    assert angles[0] == pytest.approx(data["min_braid_angle_deg"], rel=1e-9, abs=1e-9)
    assert angles[-1] == pytest.approx(data["max_braid_angle_deg"], rel=1e-12)
    assert all(a < b for a, b in itertools.pairwise(angles))
    length = data["length_m"]
    for value, contraction in zip(length, eps, strict=True):
        assert value == pytest.approx(length[0] * (1 - contraction), rel=1e-12)
    static, friction = data["force_static_n"], data["friction_force_n"]
    pulling, stretched = data["force_contracting_n"], data["force_extending_n"]
    scale = max(abs(f) for f in static) + max(friction)
    tol = 1e-12 * scale
    for f_s, f_f, f_c, f_e in zip(static, friction, pulling, stretched, strict=True):
        assert f_f >= 0
        # A braided muscle only pulls: the contracting branch is clipped at 0 (eq 31).
        assert 0 <= f_c <= max(f_s, 0.0) + tol
        assert f_s <= f_e + tol
        assert f_e == pytest.approx(f_s + f_f, rel=1e-12, abs=tol)
        assert f_c == pytest.approx(max(f_s - f_f, 0.0), rel=1e-12, abs=tol)
    assert all(a >= b for a, b in itertools.pairwise(static))
    # The static force vanishes at the neutral angle (eq 10) when the braid reaches it.
    if data["max_braid_angle_deg"] == pytest.approx(54.7356103, abs=1e-6):
        assert static[-1] == pytest.approx(0.0, abs=tol)


def test_paper_test_muscle(
    client: TestClient, paper_muscle: dict[str, Any], davis_caldwell_2006: DavisCaldwell2006
) -> None:
    data = ok(client, PATH, paper_muscle)
    check_curves(data, 201)
    # S_scale from eq 34 at 200 kPa: the paper's 18.1.
    assert round(data["s_scale"], 1) == davis_caldwell_2006.s_scale[200e3]
    b, n = paper_muscle["strand_length_m"], paper_muscle["turns"]
    d_o = b / (n * math.pi)
    theta_min = math.radians(data["min_braid_angle_deg"])
    assert data["length_m"][0] == pytest.approx(b * math.cos(theta_min), rel=1e-12)
    # Eq 10 at θ_min is the peak static force.
    peak = math.pi * d_o**2 * paper_muscle["pressure_pa"] / 4 * (3 * math.cos(theta_min) ** 2 - 1)
    assert data["force_static_n"][0] == pytest.approx(peak, rel=1e-12)
    assert max(data["force_static_n"]) == data["force_static_n"][0]
    assert data["force_contracting_n"][0] < data["force_static_n"][0] < data["force_extending_n"][0]


def test_curves_agree_with_min_braid_angle(
    client: TestClient, paper_muscle: dict[str, Any], model_md: ModelMd
) -> None:
    data = ok(client, PATH, paper_muscle)
    braid = {k: paper_muscle[k] for k in ("strand_length_m", "turns", "strand_diameter_m")}
    limits = ok(client, "/api/v1/min-braid-angle", {**braid, "strand_count": 240})
    assert data["min_braid_angle_deg"] == pytest.approx(limits["min_braid_angle_deg"], rel=1e-12)
    assert data["max_braid_angle_deg"] == pytest.approx(limits["max_braid_angle_deg"], rel=1e-12)
    assert round(data["max_braid_angle_deg"], 4) == model_md.neutral_braid_angle_deg
    assert data["contraction"][-1] == pytest.approx(limits["max_contraction"], rel=1e-12)
    assert data["length_m"][0] == pytest.approx(limits["max_length_m"], rel=1e-12)
    assert data["length_m"][-1] == pytest.approx(limits["min_length_m"], rel=1e-12)


@pytest.mark.parametrize("points", [2, 3, 10, 201, 1000])
def test_arrays_have_the_requested_length(
    client: TestClient, paper_muscle: dict[str, Any], points: int
) -> None:
    check_curves(ok(client, PATH, {**paper_muscle, "points": points}), points)


def test_the_largest_curve(client: TestClient, paper_muscle: dict[str, Any]) -> None:
    # 13 MB of JSON: ask for it uncompressed, gzip would only slow the in-process client.
    body = {**paper_muscle, "points": 100_000}
    response = client.post(PATH, json=body, headers={"accept-encoding": "identity"})
    assert response.status_code == 200
    data = response.json()
    assert {len(data[name]) for name in ARRAYS} == {100_000}
    assert data["contraction"][-1] == pytest.approx(0.4078, abs=5e-5)


def test_a_measured_s_scale_overrides_eq_34(
    client: TestClient, paper_muscle: dict[str, Any]
) -> None:
    computed = ok(client, PATH, paper_muscle)
    # The paper fitted 20 at 200 kPa: friction scales with 1/S_scale (eq 30).
    measured = ok(client, PATH, {**paper_muscle, "s_scale": 20.0})
    assert measured["s_scale"] == 20.0
    ratio = computed["s_scale"] / 20.0
    for mine, theirs in zip(
        measured["friction_force_n"], computed["friction_force_n"], strict=True
    ):
        assert mine == pytest.approx(theirs * ratio, rel=1e-12)
    assert measured["force_static_n"] == computed["force_static_n"]
    check_curves(measured, 201)


def test_no_friction_collapses_the_loop(client: TestClient, paper_muscle: dict[str, Any]) -> None:
    data = ok(client, PATH, {**paper_muscle, "friction_coefficient": 0.0})
    check_curves(data, 201)
    assert data["friction_force_n"] == [0.0] * 201
    assert data["force_extending_n"] == data["force_static_n"]
    assert data["force_contracting_n"] == [max(f, 0.0) for f in data["force_static_n"]]


def test_friction_follows_eqs_29_and_30(client: TestClient, paper_muscle: dict[str, Any]) -> None:
    data = ok(client, PATH, {**paper_muscle, "points": 5})
    b, n = paper_muscle["strand_length_m"], paper_muscle["turns"]
    f_s, p = paper_muscle["friction_coefficient"], paper_muscle["pressure_pa"]
    t_min = math.radians(data["min_braid_angle_deg"])
    for angle, friction in zip(data["braid_angle_deg"], data["friction_force_n"], strict=True):
        t = math.radians(angle)
        contact = (b * math.sin(t_min) * math.cos(t_min)) ** 2 / (n * math.sin(t) * math.cos(t))
        assert friction == pytest.approx(f_s * contact / data["s_scale"] * p, rel=1e-9)


def test_pressure_scales_forces(client: TestClient, paper_muscle: dict[str, Any]) -> None:
    low = ok(client, PATH, {**paper_muscle, "s_scale": 18.0})
    high = ok(client, PATH, {**paper_muscle, "s_scale": 18.0, "pressure_pa": 400e3})
    for a, b in zip(low["force_static_n"], high["force_static_n"], strict=True):
        assert b == pytest.approx(2 * a, rel=1e-9, abs=1e-9)
    for a, b in zip(low["friction_force_n"], high["friction_force_n"], strict=True):
        assert b == pytest.approx(2 * a, rel=1e-12)


def test_diameter_with_strand_length_is_enough(
    client: TestClient, paper_muscle: dict[str, Any]
) -> None:
    b, n = paper_muscle["strand_length_m"], paper_muscle["turns"]
    body = {k: v for k, v in paper_muscle.items() if k != "turns"}
    by_diameter = ok(client, PATH, {**body, "theoretical_diameter_m": b / (n * math.pi)})
    by_turns = ok(client, PATH, paper_muscle)
    for name in ARRAYS:
        assert by_diameter[name] == pytest.approx(by_turns[name], rel=1e-9, abs=1e-9)


@st.composite
def muscles(draw: st.DrawFn) -> dict[str, Any]:
    """A muscle whose braid fits: D_o and b given, N·D_s below 99.9 % of π·D_o."""
    d_s = draw(st.floats(5e-5, 1e-3))
    d_o = draw(st.floats(max(2e-3, d_s), 0.1))
    limit = min(math.floor(0.999 * math.pi * d_o / d_s), 100_000)
    return {
        "theoretical_diameter_m": d_o,
        "strand_length_m": draw(st.floats(max(1e-3, 2 * d_o), 2.0)),
        "strand_diameter_m": d_s,
        "strand_count": draw(st.integers(2, limit)),
        "pressure_pa": draw(st.floats(1e3, 1e6)),
        "friction_coefficient": draw(st.floats(0.0, 1.0)),
        "youngs_modulus_pa": draw(st.floats(1e8, 1e11)),
        "poisson_ratio": draw(st.floats(0.0, 0.49)),
        "s_scale": draw(st.none() | st.floats(1.0, 100.0)),
        "points": draw(st.integers(2, 300)),
    }


@settings(max_examples=60, deadline=None, database=None)
@given(muscle=muscles())
def test_any_muscle_keeps_the_branch_order(client: TestClient, muscle: dict[str, Any]) -> None:
    data = ok(client, PATH, muscle)
    check_curves(data, muscle["points"])
    if muscle["s_scale"] is not None:
        assert data["s_scale"] == muscle["s_scale"]


def test_extreme_geometry_is_refused_or_finite(client: TestClient) -> None:
    # Every field is inside its documented bounds.
    body = {
        "strand_count": 2,
        "strand_length_m": 100.0,
        "turns": 0.01,
        "strand_diameter_m": 1e-6,
        "pressure_pa": 1.0,
        "friction_coefficient": 0.0,
        "youngs_modulus_pa": 3e9,
        "poisson_ratio": 0.4,
        "points": 2,
    }
    response = client.post(PATH, json=body)
    if response.status_code == 200:
        check_curves(response.json(), 2)
    else:
        assert response.status_code == 422
        assert response.json()["detail"][0]["loc"][1] in {"strand_length_m", "turns"}
