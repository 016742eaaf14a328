"""GET /healthz, /api/v1/materials and /api/v1/reference; the OpenAPI schema of the contract."""

from __future__ import annotations

import math
from typing import Any

from fastapi.testclient import TestClient

from app.main import app
from tests.api.conftest import DavisCaldwell2006Measured
from tests.api.support import POST_PATHS, ok
from tests.published import DavisCaldwell2006

PROPERTIES = ("youngs_modulus_pa", "poisson_ratio", "tensile_strength_pa", "friction_coefficient")
#: Each property's range in the request schemas (app/fields.py as documented in OpenAPI).
BOUNDS = {
    "youngs_modulus_pa": (1e6, 1e12),
    "poisson_ratio": (0.0, 0.5),
    "tensile_strength_pa": (1e5, 1e11),
    "friction_coefficient": (0.0, 2.0),
}


def _get(client: TestClient, path: str) -> dict[str, Any]:
    response = client.get(path)
    assert response.status_code == 200, response.text
    assert response.headers["content-type"].startswith("application/json")
    data = response.json()
    assert isinstance(data, dict)
    return data


def test_healthz(client: TestClient) -> None:
    assert _get(client, "/healthz") == {"status": "ok"}


def test_materials_carry_a_source_for_every_number(client: TestClient) -> None:
    materials = _get(client, "/api/v1/materials")["materials"]
    assert isinstance(materials, list)
    ids = [m["id"] for m in materials]
    assert len(ids) == len(set(ids))
    assert "nylon" in ids
    for material in materials:
        assert set(material) == {"id", "name", "basis", "sources", *PROPERTIES}
        assert material["name"].strip()
        assert material["basis"].strip()
        assert set(material["sources"]) == set(PROPERTIES), material["id"]
        for name in PROPERTIES:
            assert material["sources"][name].strip(), (material["id"], name)
            low, high = BOUNDS[name]
            assert low <= material[name] <= high, (material["id"], name)
        assert material["poisson_ratio"] < 0.5


def test_nylon_is_the_papers_nylon(
    client: TestClient, davis_caldwell_2006: DavisCaldwell2006
) -> None:
    materials = {m["id"]: m for m in _get(client, "/api/v1/materials")["materials"]}
    nylon = materials["nylon"]
    p = davis_caldwell_2006
    assert nylon["youngs_modulus_pa"] == p.youngs_modulus_pa
    assert nylon["poisson_ratio"] == p.poisson_ratio
    assert nylon["tensile_strength_pa"] == p.tensile_strength_pa
    assert nylon["friction_coefficient"] == p.friction_coefficient
    assert "Brydson" in nylon["sources"]["tensile_strength_pa"]


def test_reference_holds_the_papers_braid_and_muscle(
    client: TestClient, davis_caldwell_2006: DavisCaldwell2006
) -> None:
    data = _get(client, "/api/v1/reference")
    assert set(data) == {"braid_sample", "test_muscle", "min_braid_angle_table1", "s_scale_fitted"}
    p = davis_caldwell_2006
    assert data["braid_sample"] == {
        "theoretical_diameter_m": p.theoretical_diameter_m,
        "strand_diameter_m": p.strand_diameter_m,
        "strand_count": 240,
        "parallel_strands": p.parallel_strands,
    }
    assert data["test_muscle"] == {
        "strand_length_m": p.strand_length_m,
        "turns": p.turns,
        "strand_diameter_m": p.strand_diameter_m,
        "strand_count": 240,
        "friction_coefficient": p.friction_coefficient,
    }


def test_reference_table_1(
    client: TestClient,
    davis_caldwell_2006: DavisCaldwell2006,
    davis_caldwell_2006_measured: DavisCaldwell2006Measured,
) -> None:
    rows = _get(client, "/api/v1/reference")["min_braid_angle_table1"]
    assert [row["strand_count"] for row in rows] == [240, 160, 120]
    measured = davis_caldwell_2006_measured.min_braid_angle_measured_deg
    for row in rows:
        n = row["strand_count"]
        assert set(row) == {"strand_count", "measured_deg", "std_deg", "calculated_deg"}
        assert (row["measured_deg"], row["std_deg"]) == measured[n]
        assert row["calculated_deg"] == davis_caldwell_2006.min_braid_angle_deg[n]


def test_reference_table_1_matches_the_calculator(
    client: TestClient, davis_caldwell_2006: DavisCaldwell2006
) -> None:
    data = _get(client, "/api/v1/reference")
    braid = data["braid_sample"]
    for row in data["min_braid_angle_table1"]:
        body = {
            "strand_diameter_m": braid["strand_diameter_m"],
            "strand_count": row["strand_count"],
            "theoretical_diameter_m": braid["theoretical_diameter_m"],
        }
        angle = ok(client, "/api/v1/min-braid-angle", body)["min_braid_angle_deg"]
        assert round(angle, 1) == row["calculated_deg"]


def test_reference_fitted_s_scale(
    client: TestClient, davis_caldwell_2006_measured: DavisCaldwell2006Measured
) -> None:
    fits = _get(client, "/api/v1/reference")["s_scale_fitted"]
    m = davis_caldwell_2006_measured
    expected = {
        (pressure, value, "Davis & Caldwell 2006") for pressure, value in m.s_scale_fitted.items()
    }
    expected.add((m.s_scale_tondu_lopez_pressure_pa, m.s_scale_tondu_lopez, "Tondu & Lopez 2000"))
    assert {(f["pressure_pa"], f["s_scale"], f["source"]) for f in fits} == expected
    assert len(fits) == len(expected)


def test_openapi_lists_the_v1_contract(client: TestClient) -> None:
    schema = _get(client, "/openapi.json")
    paths = schema["paths"]
    for path in POST_PATHS:
        assert "post" in paths[path], path
        assert "422" in paths[path]["post"]["responses"], path
    for path in ("/healthz", "/api/v1/materials", "/api/v1/reference"):
        assert "get" in paths[path], path


def _response_schema(schema: dict[str, Any], path: str) -> dict[str, Any]:
    content = schema["paths"][path]["post"]["responses"]["200"]["content"]
    found: dict[str, Any] = content["application/json"]["schema"]
    if "$ref" in found:
        name = found["$ref"].rsplit("/", 1)[-1]
        found = schema["components"]["schemas"][name]
    return found


def test_openapi_documents_each_response_model(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]]
) -> None:
    # Regression: the 200s were documented as {"type": "string"} until app.responses.JSONResponse
    # subclassed Starlette's JSONResponse.
    schema = _get(client, "/openapi.json")
    for path in POST_PATHS:
        documented = _response_schema(schema, path)
        assert documented.get("type") == "object", (path, documented)
        answer = ok(client, path, valid_bodies[path])
        assert set(documented["properties"]) == set(answer), path


def test_no_reference_number_is_non_finite(client: TestClient) -> None:
    def walk(value: Any) -> None:
        if isinstance(value, float):
            assert math.isfinite(value)
        elif isinstance(value, dict):
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)

    for path in ("/api/v1/materials", "/api/v1/reference"):
        walk(_get(client, path))


def test_every_field_of_the_api_is_described() -> None:
    schemas = app.openapi()["components"]["schemas"]
    fastapi_own = {"HTTPValidationError", "ValidationError"}
    undescribed = [
        f"{name}.{prop}"
        for name, schema in schemas.items()
        if name not in fastapi_own
        for prop, spec in schema.get("properties", {}).items()
        if not spec.get("description")
    ]
    assert undescribed == []
