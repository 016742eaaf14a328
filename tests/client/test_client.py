"""The typed client against a real uvicorn: the paper's numbers, refusals, both clients.

Tests taking ``pma`` run with :class:`PMAClient` and with :class:`AsyncPMAClient`. Those
at the end use :class:`httpx.MockTransport` for what a real server does not do (malformed
answers) and to see the exact requests the client sends.
"""

from __future__ import annotations

import asyncio
import dataclasses
import inspect
import io
import json
from typing import Any

import httpx
import numpy as np
import pytest

from pma_client import (
    AsyncPMAClient,
    DesignReport,
    DesignWarning,
    FailureStrandCount,
    GapArea,
    Hysteresis,
    HysteresisSweep,
    MinBraidAngle,
    OpenSimActuator,
    PMAClient,
    PMAError,
    PMAValidationError,
    PressureSweep,
    SScale,
    StrandCountSweep,
)
from pma_client import _endpoints as endpoints
from tests.published import DavisCaldwell2006

MM2 = 1e-6
# The paper's test muscle (§3.3) at 200 kPa, in the nylon of the paper.
MUSCLE: dict[str, Any] = {
    "strand_length_m": 0.65,
    "turns": 4.7,
    "strand_diameter_m": 0.25e-3,
    "strand_count": 240,
    "pressure_pa": 200e3,
    "friction_coefficient": 0.2,
    "youngs_modulus_pa": 3e9,
    "poisson_ratio": 0.4,
}
IMPOSSIBLE_BRAID = (
    "strand_count: 240 strands of 0.25 mm cannot fit around a 10 mm braid: side by side"
    " they need 60 mm of circumference and a 10 mm braid has 31.4 mm"
)
# method name -> (path, result type, response schema) of the endpoints with a JSON body.
POST_ENDPOINTS: dict[str, tuple[str, type, str]] = {
    "min_braid_angle": ("/api/v1/min-braid-angle", MinBraidAngle, "MinBraidAngleOut"),
    "gap_area": ("/api/v1/gap-area", GapArea, "GapAreaOut"),
    "failure_strand_count": (
        "/api/v1/failure-strand-count",
        FailureStrandCount,
        "FailureStrandCountOut",
    ),
    "s_scale": ("/api/v1/s-scale", SScale, "SScaleOut"),
    "hysteresis": ("/api/v1/hysteresis", Hysteresis, "HysteresisOut"),
    "design": ("/api/v1/design", DesignReport, "DesignOut"),
    "strand_count_sweep": ("/api/v1/sweeps/strand-count", StrandCountSweep, "StrandCountSweepOut"),
    "pressure_sweep": ("/api/v1/sweeps/pressure", PressureSweep, "PressureSweepOut"),
    "opensim_export": ("/api/v1/export/opensim", OpenSimActuator, "OpenSimOut"),
    "hysteresis_sweep": ("/api/v1/sweeps/hysteresis", HysteresisSweep, "HysteresisSweepOut"),
}


def _npy(array: np.ndarray[Any, Any]) -> bytes:
    saved = io.BytesIO()
    np.save(saved, array)
    return saved.getvalue()


def _npz(array: np.ndarray[Any, Any]) -> bytes:
    saved = io.BytesIO()
    np.savez(saved, array)
    return saved.getvalue()


def _mm2(area_m2: float) -> float:
    return round(area_m2 / MM2, 2)


# --- every endpoint, against the real server ------------------------------------------


def test_health(pma: PMAClient) -> None:
    assert pma.health().status == "ok"


@pytest.mark.parametrize("strand_count", [240, 160, 120])
def test_min_braid_angle_is_table_1(
    pma: PMAClient, paper: DavisCaldwell2006, strand_count: int
) -> None:
    result = pma.min_braid_angle(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count=strand_count,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    assert isinstance(result, MinBraidAngle)
    assert round(result.min_braid_angle_deg, 1) == paper.min_braid_angle_deg[strand_count]
    assert result.jamming_angle_deg == pytest.approx(90.0 - result.min_braid_angle_deg)
    assert result.theoretical_diameter_m == paper.theoretical_diameter_m
    # Without b the lengths are unknown: null in the JSON, None here.
    assert (result.max_length_m, result.min_length_m, result.stroke_m) == (None, None, None)


def test_min_braid_angle_from_strand_length_and_turns(
    pma: PMAClient, paper: DavisCaldwell2006
) -> None:
    result = pma.min_braid_angle(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count=240,
        strand_length_m=paper.strand_length_m,
        turns=paper.turns,
    )
    assert result.theoretical_diameter_m == pytest.approx(0.65 / (4.7 * np.pi))
    assert result.max_length_m is not None
    assert result.min_length_m is not None
    assert result.stroke_m == pytest.approx(result.max_length_m - result.min_length_m)


@pytest.mark.parametrize("strand_count", [240, 120])
def test_max_gap_area_is_eq_15(pma: PMAClient, paper: DavisCaldwell2006, strand_count: int) -> None:
    result = pma.gap_area(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count=strand_count,
        parallel_strands=paper.parallel_strands,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    assert _mm2(result.max_gap_area_m2) == paper.max_gap_area_mm2[strand_count]
    assert result.braid_angle_deg == 45.0  # the service's default, not sent by the client
    assert result.gap_area_m2 == pytest.approx(result.max_gap_area_m2)


def test_gap_area_at_a_braid_angle(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.gap_area(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count=120,
        parallel_strands=3,
        braid_angle_deg=30.0,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    assert result.braid_angle_deg == 30.0
    assert result.gap_area_m2 == pytest.approx(result.gap_width_m**2 / (2 * np.tan(np.pi / 6)))
    assert result.gap_area_m2 < result.max_gap_area_m2


def test_failure_strand_count_is_eq_20(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.failure_strand_count(
        pressure_pa=paper.failure_pressure_pa,
        strand_diameter_m=paper.strand_diameter_m,
        tensile_strength_pa=paper.tensile_strength_pa,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    assert result.min_strand_count == paper.failure_strand_count == 97
    assert result.worst_case_min_strand_count == paper.worst_case_failure_strand_count == 103
    assert isinstance(result.min_strand_count, int)
    assert result.worst_case_braid_angle_deg == 45.0
    assert result.braid_angle_deg == pytest.approx(54.7356)


def test_failure_strand_count_with_a_safety_factor(
    pma: PMAClient, paper: DavisCaldwell2006
) -> None:
    result = pma.failure_strand_count(
        pressure_pa=paper.failure_pressure_pa,
        strand_diameter_m=paper.strand_diameter_m,
        tensile_strength_pa=paper.tensile_strength_pa,
        safety_factor=2.0,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    assert result.min_strand_count_exact == pytest.approx(2 * 96.644, rel=1e-4)


# The paper's 14.3 at 400 kPa is the formula's 14.39 truncated (MODEL.md): not rounded here.
@pytest.mark.parametrize("pressure_pa", [200e3, 300e3])
def test_s_scale_is_eq_34(pma: PMAClient, paper: DavisCaldwell2006, pressure_pa: float) -> None:
    result = pma.s_scale(
        strand_diameter_m=paper.strand_diameter_m,
        pressure_pa=pressure_pa,
        youngs_modulus_pa=paper.youngs_modulus_pa,
        poisson_ratio=paper.poisson_ratio,
    )
    assert round(result.s_scale, 1) == paper.s_scale[pressure_pa]
    assert result.flat_contact_radius_m == paper.strand_diameter_m / 2
    assert result.compressive_force_n == pytest.approx(pressure_pa * paper.strand_diameter_m**2)


def test_hysteresis_arrays_are_numpy_arrays_of_length_points(
    pma: PMAClient, paper: DavisCaldwell2006
) -> None:
    result = pma.hysteresis(**MUSCLE, points=51)
    arrays = {
        "braid_angle_deg": result.braid_angle_deg,
        "length_m": result.length_m,
        "contraction": result.contraction,
        "force_static_n": result.force_static_n,
        "friction_force_n": result.friction_force_n,
        "force_contracting_n": result.force_contracting_n,
        "force_extending_n": result.force_extending_n,
    }
    for name, array in arrays.items():
        assert isinstance(array, np.ndarray), name
        assert array.dtype == np.float64, name
        assert array.shape == (51,), name
        assert not array.flags.writeable, name
    assert round(result.s_scale, 1) == paper.s_scale[200e3]
    assert result.contraction[0] == 0.0
    assert np.all(np.diff(result.contraction) > 0)
    assert np.all(result.force_contracting_n >= 0)
    assert np.all(result.force_extending_n >= result.force_contracting_n)
    assert result.braid_angle_deg[0] == pytest.approx(result.min_braid_angle_deg)
    assert result.braid_angle_deg[-1] == pytest.approx(result.max_braid_angle_deg)


def test_hysteresis_defaults_are_the_services(pma: PMAClient) -> None:
    # points and s_scale left as None are not sent: the service's 201 points and eq 34.
    result = pma.hysteresis(**MUSCLE)
    assert result.force_static_n.shape == (201,)
    assert round(result.s_scale, 1) == 18.1


def test_hysteresis_with_a_measured_s_scale(pma: PMAClient) -> None:
    result = pma.hysteresis(**MUSCLE, s_scale=20.0, points=5)
    assert result.s_scale == 20.0


def test_hysteresis_comes_as_npy_and_equals_the_json_answer(
    pma: PMAClient, server_url: str
) -> None:
    result = pma.hysteresis(**MUSCLE, points=1001)
    as_json = httpx.post(f"{server_url}/api/v1/hysteresis", json={**MUSCLE, "points": 1001})
    for name, value in as_json.json().items():
        assert np.asarray(getattr(result, name)).tolist() == value, name


def test_hysteresis_call_asks_for_npy() -> None:
    call = endpoints.hysteresis(**MUSCLE)
    assert call.path == "/api/v1/hysteresis?format=npy-record"
    assert call.decode is endpoints.npy_record


@pytest.mark.parametrize(
    "content",
    [
        b"",
        b"not numpy",
        _npy(np.arange(3.0)),
        _npy(np.zeros(2, dtype=[("a", "<f8")])),
        _npz(np.arange(3.0)),
    ],
    ids=["empty", "garbage", "plain array", "records", "npz archive"],
)
def test_npy_record_refuses_anything_but_one_record(content: bytes) -> None:
    with pytest.raises(ValueError, match=r"^the \.npy answer is not"):
        endpoints.npy_record(content)


def test_design_reports_warnings_as_dataclasses(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.design(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count=120,
        parallel_strands=paper.parallel_strands,
        theoretical_diameter_m=paper.theoretical_diameter_m,
        pressure_pa=paper.failure_pressure_pa,
        material="nylon",
    )
    assert isinstance(result, DesignReport)
    assert isinstance(result.warnings, tuple)
    assert all(isinstance(w, DesignWarning) for w in result.warnings)
    gap = next(w for w in result.warnings if w.code == "gap_admits_bladder")
    assert "2.84 mm²" in gap.message
    assert _mm2(result.max_gap_area_m2) == 2.84
    assert result.failure_strand_count.min_strand_count == 97
    assert result.failure_strand_count.worst_case_min_strand_count == 103
    assert round(result.min_braid_angle_deg, 1) == paper.min_braid_angle_deg[120]
    assert result.material.youngs_modulus_pa == paper.youngs_modulus_pa
    assert result.material.tensile_strength_pa == paper.tensile_strength_pa
    assert (result.strand_length_m, result.turns) == (None, None)


def test_design_of_the_paper_braid_has_no_warnings(
    pma: PMAClient, paper: DavisCaldwell2006
) -> None:
    result = pma.design(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count=240,
        parallel_strands=paper.parallel_strands,
        strand_length_m=paper.strand_length_m,
        turns=paper.turns,
        pressure_pa=200e3,
        youngs_modulus_pa=paper.youngs_modulus_pa,
        poisson_ratio=paper.poisson_ratio,
        tensile_strength_pa=paper.tensile_strength_pa,
        friction_coefficient=paper.friction_coefficient,
    )
    assert result.warnings == ()
    assert result.strand_length_m == paper.strand_length_m
    assert result.turns == pytest.approx(paper.turns)
    assert round(result.s_scale, 1) == paper.s_scale[200e3]


def test_strand_count_sweep(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.strand_count_sweep(
        strand_diameter_m=paper.strand_diameter_m,
        strand_count_min=100,
        strand_count_max=1000,
        parallel_strands=paper.parallel_strands,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    # N·D_s < π·D_o: 389 strands of 0.25 mm fit around 31 mm, so the range is cut there.
    assert result.strand_count_limit == 389
    assert result.strand_count.dtype == np.int64
    assert result.strand_count[0] == 100
    assert result.strand_count[-1] == 389
    for array in (result.min_braid_angle_deg, result.max_contraction, result.max_gap_area_m2):
        assert array.dtype == np.float64
        assert array.shape == result.strand_count.shape
    by_count = dict(zip(result.strand_count.tolist(), result.min_braid_angle_deg, strict=True))
    for count, angle in paper.min_braid_angle_deg.items():
        assert round(by_count[count], 1) == angle
    assert _mm2(result.max_gap_area_m2[result.strand_count == 120][0]) == 2.84


def test_pressure_sweep(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.pressure_sweep(
        strand_diameter_m=paper.strand_diameter_m,
        tensile_strength_pa=paper.tensile_strength_pa,
        youngs_modulus_pa=paper.youngs_modulus_pa,
        poisson_ratio=paper.poisson_ratio,
        pressure_min_pa=100e3,
        pressure_max_pa=500e3,
        points=5,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    np.testing.assert_allclose(result.pressure_pa, [100e3, 200e3, 300e3, 400e3, 500e3])
    assert result.pressure_pa.dtype == np.float64
    assert round(result.s_scale[1], 1) == paper.s_scale[200e3]
    assert round(result.s_scale[2], 1) == paper.s_scale[300e3]
    assert result.min_strand_count.dtype == np.int64
    assert result.min_strand_count[-1] == paper.failure_strand_count
    assert result.worst_case_min_strand_count[-1] == paper.worst_case_failure_strand_count
    assert np.all(np.diff(result.min_strand_count_exact) > 0)


def test_pressure_sweep_default_points(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.pressure_sweep(
        strand_diameter_m=paper.strand_diameter_m,
        tensile_strength_pa=paper.tensile_strength_pa,
        youngs_modulus_pa=paper.youngs_modulus_pa,
        poisson_ratio=paper.poisson_ratio,
        pressure_min_pa=50e3,
        pressure_max_pa=600e3,
        theoretical_diameter_m=paper.theoretical_diameter_m,
    )
    assert result.pressure_pa.shape == (101,)


def test_materials(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    materials = {m.id: m for m in pma.materials()}
    nylon = materials["nylon"]
    assert nylon.youngs_modulus_pa == paper.youngs_modulus_pa
    assert nylon.poisson_ratio == paper.poisson_ratio
    assert nylon.tensile_strength_pa == paper.tensile_strength_pa
    assert nylon.friction_coefficient == paper.friction_coefficient
    assert "Brydson" in nylon.sources["youngs_modulus_pa"]
    with pytest.raises(TypeError):
        nylon.sources["youngs_modulus_pa"] = "changed"  # type: ignore[index]


def test_hysteresis_sweep_has_a_row_per_pressure(pma: PMAClient) -> None:
    family = pma.hysteresis_sweep(
        strand_length_m=0.65,
        turns=4.7,
        strand_diameter_m=0.25e-3,
        strand_count=240,
        pressures_pa=[200e3, 300e3],
        friction_coefficient=0.2,
        youngs_modulus_pa=3e9,
        poisson_ratio=0.4,
        points=11,
    )
    assert family.force_extending_n.shape == (2, 11)
    assert family.s_scale.round(1).tolist() == [18.1, 15.8]
    assert np.all(family.force_contracting_n <= family.force_extending_n)


def test_opensim_export(pma: PMAClient) -> None:
    actuator = pma.opensim_export(
        strand_length_m=0.65, turns=4.7, strand_diameter_m=0.25e-3, strand_count=240
    )
    assert (actuator.thread_length, actuator.number_of_turns) == (0.65, 4.7)
    assert "<number_of_turns>4.7</number_of_turns>" in actuator.xml
    assert actuator.min_length_m == pytest.approx(0.65 / 3**0.5)


def test_reference(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    reference = pma.reference()
    assert reference.braid_sample.theoretical_diameter_m == paper.theoretical_diameter_m
    assert reference.braid_sample.strand_count == 240
    assert reference.test_muscle.turns == paper.turns
    table = {row.strand_count: row.calculated_deg for row in reference.min_braid_angle_table1}
    assert table == paper.min_braid_angle_deg
    assert [fit.s_scale for fit in reference.s_scale_fitted][:2] == [20.0, 16.0]


def test_numpy_scalars_are_sent_as_numbers(pma: PMAClient, paper: DavisCaldwell2006) -> None:
    result = pma.min_braid_angle(
        strand_diameter_m=np.float64(paper.strand_diameter_m),
        strand_count=np.arange(240, 241)[0],  # an np.int64
        theoretical_diameter_m=np.float32(paper.theoretical_diameter_m),  # type: ignore[arg-type]
    )
    assert round(result.min_braid_angle_deg, 1) == 19.0


# --- refusals ----------------------------------------------------------------------


def test_impossible_braid_raises_validation_error(pma: PMAClient) -> None:
    with pytest.raises(PMAValidationError) as caught:
        pma.min_braid_angle(
            strand_diameter_m=0.25e-3, strand_count=240, theoretical_diameter_m=0.01
        )
    error = caught.value
    assert isinstance(error, PMAError)
    assert error.status_code == 422
    assert str(error).startswith(IMPOSSIBLE_BRAID)
    assert len(error.detail) == 1
    assert error.detail[0]["loc"] == ["body", "strand_count"]
    assert error.detail[0]["msg"].startswith(IMPOSSIBLE_BRAID)
    assert error.detail[0]["type"] == "value_error"
    assert error.fields == ("strand_count",)
    assert json.loads(error.body) == {"detail": error.detail}


def test_each_refused_field_is_named(pma: PMAClient) -> None:
    with pytest.raises(PMAValidationError) as caught:
        pma.s_scale(
            strand_diameter_m=float("nan"),
            pressure_pa=200e3,
            youngs_modulus_pa=3e9,
            poisson_ratio=0.5,
        )
    error = caught.value
    assert set(error.fields) == {"strand_diameter_m", "poisson_ratio"}
    # One "field: msg" per problem, the field not repeated where the msg starts with it.
    parts = str(error).split("; ")
    assert len(parts) == len(error.detail)
    for part, problem in zip(parts, error.detail, strict=True):
        field = problem["loc"][-1]
        assert part in (problem["msg"], f"{field}: {problem['msg']}")
        assert part.startswith(field)


def test_missing_geometry_is_refused(pma: PMAClient) -> None:
    with pytest.raises(PMAValidationError, match=r"^theoretical_diameter_m: give the braid's size"):
        pma.min_braid_angle(strand_diameter_m=0.25e-3, strand_count=240)


def test_hysteresis_needs_the_strand_length(pma: PMAClient) -> None:
    muscle = {**MUSCLE, "strand_length_m": None, "turns": None, "theoretical_diameter_m": 0.031}
    with pytest.raises(PMAValidationError) as caught:
        pma.hysteresis(**muscle)
    assert caught.value.fields == ("strand_length_m",)


def test_unknown_material_is_refused(pma: PMAClient) -> None:
    with pytest.raises(PMAValidationError, match=r"^material: unknown material 'unobtainium'"):
        pma.design(
            strand_diameter_m=0.25e-3,
            strand_count=240,
            theoretical_diameter_m=0.031,
            pressure_pa=200e3,
            material="unobtainium",
        )


def test_other_error_status_raises_pma_error(server_url: str) -> None:
    with PMAClient(f"{server_url}/no-such-prefix") as lost, pytest.raises(PMAError) as caught:
        lost.health()
    error = caught.value
    assert not isinstance(error, PMAValidationError)
    assert error.status_code == 404
    assert str(error).startswith(f"HTTP 404 Not Found from GET {server_url}/no-such-prefix/healthz")
    assert "Not Found" in error.body


# --- the client mirrors the API ------------------------------------------------------


@pytest.fixture(scope="module")
def openapi(server_url: str) -> dict[str, Any]:
    """The running service's OpenAPI document."""
    document: dict[str, Any] = httpx.get(f"{server_url}/openapi.json").json()
    return document


def _schema(openapi: dict[str, Any], schema: dict[str, Any]) -> dict[str, Any]:
    name = schema["$ref"].rsplit("/", 1)[-1]
    resolved: dict[str, Any] = openapi["components"]["schemas"][name]
    return resolved


@pytest.mark.parametrize("client_class", [PMAClient, AsyncPMAClient])
@pytest.mark.parametrize("name", POST_ENDPOINTS)
def test_method_parameters_are_the_body_fields(
    openapi: dict[str, Any], name: str, client_class: type[PMAClient | AsyncPMAClient]
) -> None:
    path, _, _ = POST_ENDPOINTS[name]
    body = openapi["paths"][path]["post"]["requestBody"]["content"]["application/json"]
    schema = _schema(openapi, body["schema"])
    parameters = list(inspect.signature(getattr(client_class, name)).parameters.values())[1:]
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in parameters)
    assert {p.name for p in parameters} == set(schema["properties"])
    required = {p.name for p in parameters if p.default is inspect.Parameter.empty}
    assert required == set(schema.get("required", ()))
    assert all(p.default is None for p in parameters if p.name not in required)


@pytest.mark.parametrize("name", POST_ENDPOINTS)
def test_result_fields_are_the_response_fields(openapi: dict[str, Any], name: str) -> None:
    path, result_type, model = POST_ENDPOINTS[name]
    content = openapi["paths"][path]["post"]["responses"]["200"]["content"]
    schema = _schema(openapi, content["application/json"]["schema"])
    assert schema == openapi["components"]["schemas"][model]
    assert {f.name for f in dataclasses.fields(result_type)} == set(schema["properties"])


def test_sync_and_async_clients_have_the_same_methods() -> None:
    def public(cls: type) -> set[str]:
        return {name for name in vars(cls) if not name.startswith("_")} - {"aclose"}

    assert public(PMAClient) == public(AsyncPMAClient)
    for name in [*POST_ENDPOINTS, "health", "materials", "reference"]:
        assert inspect.iscoroutinefunction(getattr(AsyncPMAClient, name)), name
        assert getattr(PMAClient, name).__doc__ == getattr(AsyncPMAClient, name).__doc__


# --- the async client, natively --------------------------------------------------------


@pytest.mark.anyio
async def test_async_client_runs_calls_concurrently(
    server_url: str, paper: DavisCaldwell2006
) -> None:
    async with AsyncPMAClient(server_url) as pma:
        braid, scale, curves = await asyncio.gather(
            pma.min_braid_angle(
                strand_diameter_m=paper.strand_diameter_m,
                strand_count=240,
                theoretical_diameter_m=paper.theoretical_diameter_m,
            ),
            pma.s_scale(
                strand_diameter_m=paper.strand_diameter_m,
                pressure_pa=200e3,
                youngs_modulus_pa=paper.youngs_modulus_pa,
                poisson_ratio=paper.poisson_ratio,
            ),
            pma.hysteresis(**MUSCLE, points=11),
        )
    assert pma.is_closed
    assert round(braid.min_braid_angle_deg, 1) == 19.0
    assert round(scale.s_scale, 1) == 18.1
    assert curves.force_extending_n.shape == (11,)


@pytest.mark.anyio
async def test_async_client_raises_validation_error(server_url: str) -> None:
    async with AsyncPMAClient(server_url) as pma:
        with pytest.raises(PMAValidationError) as caught:
            await pma.min_braid_angle(
                strand_diameter_m=0.25e-3, strand_count=240, theoretical_diameter_m=0.01
            )
    assert str(caught.value).startswith(IMPOSSIBLE_BRAID)
    assert caught.value.detail[0]["loc"] == ["body", "strand_count"]


# --- requests and malformed answers, with a mock transport ----------------------------


class Recorder:
    """A mock service: records each request and answers with ``status`` and ``content``."""

    def __init__(self, status: int = 200, content: bytes = b'{"status": "ok"}') -> None:
        self.status = status
        self.content = content
        self.requests: list[httpx.Request] = []

    def __call__(self, request: httpx.Request) -> httpx.Response:
        self.requests.append(request)
        return httpx.Response(self.status, content=self.content)

    def body(self) -> Any:
        return json.loads(self.requests[-1].content)


def test_none_arguments_are_not_sent() -> None:
    service = Recorder(content=b"{}")
    with (
        PMAClient("http://pma.test", transport=httpx.MockTransport(service)) as pma,
        pytest.raises(PMAError, match="unexpected response"),
    ):
        pma.gap_area(strand_diameter_m=0.25e-3, strand_count=120, theoretical_diameter_m=0.031)
    request = service.requests[-1]
    assert request.method == "POST"
    assert request.url == "http://pma.test/api/v1/gap-area"
    assert request.headers["content-type"] == "application/json"
    assert request.headers["accept"] == "application/json"
    assert service.body() == {
        "strand_diameter_m": 0.25e-3,
        "strand_count": 120,
        "theoretical_diameter_m": 0.031,
    }


def test_base_url_keeps_its_path_prefix() -> None:
    service = Recorder()
    with PMAClient("http://proxy.test/pma/", transport=httpx.MockTransport(service)) as pma:
        assert pma.health().status == "ok"
    assert service.requests[-1].url == "http://proxy.test/pma/healthz"
    assert service.requests[-1].content == b""


@pytest.mark.parametrize(
    "content",
    [b"not json", b"[]", b'{"status": 1}', b'{"detail": "ok"}'],
    ids=["not-json", "not-an-object", "wrong-type", "missing-field"],
)
def test_unexpected_success_body_raises_pma_error(content: bytes) -> None:
    service = Recorder(content=content)
    with (
        PMAClient("http://pma.test", transport=httpx.MockTransport(service)) as pma,
        pytest.raises(PMAError, match=r"^unexpected response") as caught,
    ):
        pma.health()
    assert not isinstance(caught.value, PMAValidationError)
    assert caught.value.status_code == 200


def test_unexpected_array_raises_pma_error() -> None:
    content = json.dumps(
        {
            "strand_count_limit": 389,
            "strand_count": [1.5],
            "min_braid_angle_deg": [1.0],
            "max_contraction": [0.1],
            "max_gap_area_m2": [1e-6],
        }
    ).encode()
    service = Recorder(content=content)
    with (
        PMAClient("http://pma.test", transport=httpx.MockTransport(service)) as pma,
        pytest.raises(PMAError, match="strand_count should be a list of numbers"),
    ):
        pma.strand_count_sweep(
            strand_diameter_m=0.25e-3,
            strand_count_min=1,
            strand_count_max=2,
            theoretical_diameter_m=0.031,
        )


def test_a_422_not_in_the_api_shape_is_a_pma_error() -> None:
    service = Recorder(status=422, content=b"<html>refused by the proxy</html>")
    with (
        PMAClient("http://pma.test", transport=httpx.MockTransport(service)) as pma,
        pytest.raises(PMAError) as caught,
    ):
        pma.health()
    assert not isinstance(caught.value, PMAValidationError)
    assert caught.value.status_code == 422
    assert "refused by the proxy" in str(caught.value)


def test_a_gateway_error_is_a_pma_error_with_the_body() -> None:
    service = Recorder(status=502, content=b"bad gateway" * 100)
    with (
        PMAClient("http://pma.test", transport=httpx.MockTransport(service)) as pma,
        pytest.raises(PMAError, match=r"^HTTP 502 Bad Gateway from GET") as caught,
    ):
        pma.materials()
    assert caught.value.body == "bad gateway" * 100
    assert len(str(caught.value)) < 600


def test_an_injected_client_is_used_and_left_open() -> None:
    service = Recorder()
    http = httpx.Client(transport=httpx.MockTransport(service), headers={"x-team": "pma"})
    with PMAClient("http://pma.test", client=http) as pma:
        pma.health()
    assert service.requests[-1].headers["x-team"] == "pma"
    assert not http.is_closed
    http.close()


def test_an_own_client_is_closed() -> None:
    pma = PMAClient("http://pma.test", transport=httpx.MockTransport(Recorder()))
    pma.close()
    assert pma.is_closed


def test_an_injected_client_excludes_timeout_and_transport() -> None:
    with httpx.Client() as http:
        with pytest.raises(ValueError, match="give timeout and transport to the httpx client"):
            PMAClient(client=http, timeout=1.0)
        with pytest.raises(ValueError, match="give timeout and transport to the httpx client"):
            PMAClient(client=http, transport=httpx.MockTransport(Recorder()))


@pytest.mark.anyio
async def test_async_client_with_a_mock_transport() -> None:
    service = Recorder(content=b"{}")
    transport = httpx.MockTransport(service)
    async with AsyncPMAClient("http://pma.test", transport=transport) as pma:
        with pytest.raises(PMAError, match="unexpected response"):
            await pma.design(
                strand_diameter_m=0.25e-3,
                strand_count=240,
                theoretical_diameter_m=0.031,
                pressure_pa=2e5,
                material="nylon",
            )
    assert service.body() == {
        "strand_diameter_m": 0.25e-3,
        "strand_count": 240,
        "theoretical_diameter_m": 0.031,
        "pressure_pa": 2e5,
        "material": "nylon",
    }
    assert pma.is_closed
