"""Every kind of bad input is a 422 that names the field and says what is wrong.

Every response here also passes ``support.check_every_response`` (the client's hook): no
5xx, no NaN or Infinity, and ``detail`` a list of objects with exactly ``loc``, ``msg`` and
``type``.
"""

from __future__ import annotations

import json
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.api.support import (
    GEOMETRY_PATHS,
    JSON,
    POST_PATHS,
    error_at,
    errors,
    only_error,
)

GEOMETRY = ("theoretical_diameter_m", "strand_length_m", "turns")
#: Endpoints whose body carries a strand count N.
STRAND_COUNT_PATHS = (
    "/api/v1/min-braid-angle",
    "/api/v1/gap-area",
    "/api/v1/hysteresis",
    "/api/v1/design",
    "/api/v1/export/opensim",
    "/api/v1/sweeps/hysteresis",
)
#: Endpoints that need the actuator's length, not only D_o.
LENGTH_PATHS = ("/api/v1/hysteresis", "/api/v1/export/opensim", "/api/v1/sweeps/hysteresis")
MARK = 123456.789
"""A number placed in a body and replaced by raw JSON text (NaN, Infinity, ...)."""


def _without_geometry(body: dict[str, Any]) -> dict[str, Any]:
    return {k: v for k, v in body.items() if k not in GEOMETRY}


def _raw(body: dict[str, Any], field: str, token: bytes) -> bytes:
    """``body`` as JSON text with ``field``'s value replaced by ``token``, verbatim."""
    text = json.dumps({**body, field: MARK}).encode()
    assert text.count(str(MARK).encode()) == 1
    return text.replace(str(MARK).encode(), token)


# -- unknown and missing fields -------------------------------------------------------------


@pytest.mark.parametrize("path", POST_PATHS)
def test_an_unknown_field_is_refused_by_name(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str
) -> None:
    # A misspelt field must never fall back silently to a default.
    body = {**valid_bodies[path], "strand_diamter_m": 0.00025}
    error = only_error(client.post(path, json=body))
    assert error["loc"] == ["body", "strand_diamter_m"]
    assert error["type"] == "extra_forbidden"
    assert error["msg"] == "Extra inputs are not permitted"


@pytest.mark.parametrize(
    ("path", "misspelt"),
    [
        ("/api/v1/gap-area", "parallel_strand"),
        ("/api/v1/gap-area", "braid_angle"),
        ("/api/v1/failure-strand-count", "safety"),
        ("/api/v1/hysteresis", "point"),
        ("/api/v1/design", "materials"),
        ("/api/v1/design", "gap_area_limit"),
    ],
)
def test_a_misspelt_optional_field_is_not_ignored(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str, misspelt: str
) -> None:
    body = {**valid_bodies[path], misspelt: 1}
    error = error_at(client.post(path, json=body), misspelt)
    assert error["type"] == "extra_forbidden"


@pytest.mark.parametrize("path", POST_PATHS)
def test_a_missing_required_field_is_named(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str
) -> None:
    body = {k: v for k, v in valid_bodies[path].items() if k != "strand_diameter_m"}
    error = only_error(client.post(path, json=body))
    assert error["loc"] == ["body", "strand_diameter_m"]
    assert error["type"] == "missing"
    assert error["msg"] == "Field required"


def test_every_missing_field_is_named_at_once(client: TestClient) -> None:
    detail = errors(client.post("/api/v1/s-scale", json={}))
    assert {tuple(e["loc"]) for e in detail} == {
        ("body", "strand_diameter_m"),
        ("body", "pressure_pa"),
        ("body", "youngs_modulus_pa"),
        ("body", "poisson_ratio"),
    }
    assert {e["type"] for e in detail} == {"missing"}


# -- strict types ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("path", "field", "value", "kind"),
    [
        ("/api/v1/min-braid-angle", "strand_diameter_m", True, "float_type"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", False, "float_type"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", "5", "float_type"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", "0.00025", "float_type"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", None, "float_type"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", [0.00025], "float_type"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", {"value": 0.00025}, "float_type"),
        ("/api/v1/min-braid-angle", "strand_count", 240.0, "int_type"),
        ("/api/v1/min-braid-angle", "strand_count", 240.5, "int_type"),
        ("/api/v1/min-braid-angle", "strand_count", "240", "int_type"),
        ("/api/v1/min-braid-angle", "strand_count", True, "int_type"),
        ("/api/v1/gap-area", "parallel_strands", 3.0, "int_type"),
        ("/api/v1/gap-area", "braid_angle_deg", "45", "float_type"),
        ("/api/v1/s-scale", "pressure_pa", "200000", "float_type"),
        ("/api/v1/hysteresis", "points", 201.0, "int_type"),
        ("/api/v1/hysteresis", "turns", "4.7", "float_type"),
        ("/api/v1/design", "material", 1, "string_type"),
        ("/api/v1/design", "material", True, "string_type"),
        ("/api/v1/sweeps/strand-count", "strand_count_max", 300.0, "int_type"),
        ("/api/v1/sweeps/pressure", "points", True, "int_type"),
    ],
)
def test_no_coercion(
    client: TestClient,
    valid_bodies: dict[str, dict[str, Any]],
    path: str,
    field: str,
    value: Any,
    kind: str,
) -> None:
    # Strict: no true → 1.0, no "5" → 5, no 240.0 → 240.
    error = only_error(client.post(path, json={**valid_bodies[path], field: value}))
    assert error["loc"] == ["body", field]
    assert error["type"] == kind


# -- non-finite numbers, sent as raw JSON text ----------------------------------------------


@pytest.mark.parametrize("token", [b"NaN", b"Infinity", b"-Infinity", b"1e400", b"-1e400"])
@pytest.mark.parametrize(
    ("path", "field"),
    [
        ("/api/v1/min-braid-angle", "strand_diameter_m"),
        ("/api/v1/min-braid-angle", "theoretical_diameter_m"),
        ("/api/v1/gap-area", "braid_angle_deg"),
        ("/api/v1/failure-strand-count", "safety_factor"),
        ("/api/v1/s-scale", "pressure_pa"),
        ("/api/v1/hysteresis", "s_scale"),
        ("/api/v1/design", "gap_area_limit_m2"),
        ("/api/v1/sweeps/pressure", "pressure_max_pa"),
    ],
)
def test_non_finite_numbers_are_refused(
    client: TestClient,
    valid_bodies: dict[str, dict[str, Any]],
    path: str,
    field: str,
    token: bytes,
) -> None:
    response = client.post(path, content=_raw(valid_bodies[path], field, token), headers=JSON)
    error = only_error(response)
    assert error["loc"] == ["body", field]
    assert error["type"] == "finite_number"
    assert error["msg"] == "Input should be a finite number"


@pytest.mark.parametrize("token", [b"NaN", b"Infinity", b"1e400"])
def test_non_finite_numbers_are_no_whole_numbers(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], token: bytes
) -> None:
    path = "/api/v1/min-braid-angle"
    response = client.post(
        path, content=_raw(valid_bodies[path], "strand_count", token), headers=JSON
    )
    error = only_error(response)
    assert error["loc"] == ["body", "strand_count"]
    assert error["type"] == "int_type"


# -- numbers out of bounds ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("path", "field", "value", "kind", "words"),
    [
        (
            "/api/v1/min-braid-angle",
            "strand_diameter_m",
            -0.00025,
            "greater_than_equal",
            "at least",
        ),
        ("/api/v1/min-braid-angle", "strand_diameter_m", 0.0, "greater_than_equal", "at least"),
        ("/api/v1/min-braid-angle", "strand_diameter_m", 0.5, "less_than_equal", "at most"),
        (
            "/api/v1/min-braid-angle",
            "theoretical_diameter_m",
            -1.0,
            "greater_than_equal",
            "at least",
        ),
        ("/api/v1/min-braid-angle", "strand_count", 1, "greater_than_equal", "at least 2"),
        ("/api/v1/min-braid-angle", "strand_count", 100_001, "less_than_equal", "at most 100000"),
        ("/api/v1/gap-area", "parallel_strands", 0, "greater_than_equal", "at least 1"),
        ("/api/v1/gap-area", "braid_angle_deg", 0.0, "greater_than", "greater than 0°"),
        ("/api/v1/gap-area", "braid_angle_deg", 90.0, "less_than", "less than 90°"),
        ("/api/v1/failure-strand-count", "pressure_pa", 0.0, "greater_than_equal", "at least 1 Pa"),
        ("/api/v1/failure-strand-count", "safety_factor", 0.5, "greater_than_equal", "at least 1"),
        ("/api/v1/failure-strand-count", "tensile_strength_pa", -75e6, "greater_than_equal", "Pa"),
        ("/api/v1/s-scale", "poisson_ratio", 0.5, "less_than", "less than 0.5"),
        ("/api/v1/s-scale", "poisson_ratio", -0.1, "greater_than_equal", "at least 0"),
        ("/api/v1/s-scale", "youngs_modulus_pa", 0.0, "greater_than_equal", "at least"),
        ("/api/v1/hysteresis", "points", 1, "greater_than_equal", "at least 2"),
        ("/api/v1/hysteresis", "points", 100_001, "less_than_equal", "at most 100000"),
        ("/api/v1/hysteresis", "friction_coefficient", -0.1, "greater_than_equal", "at least 0"),
        ("/api/v1/hysteresis", "s_scale", 0.0, "greater_than_equal", "at least"),
        ("/api/v1/hysteresis", "turns", 0.0, "greater_than_equal", "at least"),
        ("/api/v1/design", "safety_factor", 0.5, "greater_than_equal", "at least 1"),
        ("/api/v1/design", "gap_area_limit_m2", 0.0, "greater_than_equal", "m²"),
        ("/api/v1/sweeps/pressure", "safety_factor", 0.5, "greater_than_equal", "at least 1"),
        ("/api/v1/sweeps/pressure", "points", 1, "greater_than_equal", "at least 2"),
        ("/api/v1/sweeps/pressure", "points", 10_001, "less_than_equal", "at most 10000"),
    ],
)
def test_numbers_out_of_bounds_are_refused_by_name(
    client: TestClient,
    valid_bodies: dict[str, dict[str, Any]],
    path: str,
    field: str,
    value: float,
    kind: str,
    words: str,
) -> None:
    error = only_error(client.post(path, json={**valid_bodies[path], field: value}))
    assert error["loc"] == ["body", field]
    assert error["type"] == kind
    # The message names the field, the limit and what was sent.
    assert error["msg"].startswith(f"{field} must be")
    assert words in error["msg"]
    assert f"got {value:g}" in error["msg"]


# -- physically impossible designs ----------------------------------------------------------


@pytest.mark.parametrize("path", STRAND_COUNT_PATHS)
def test_strands_that_cannot_fit_are_refused_with_the_reason(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str
) -> None:
    body = {**valid_bodies[path], "strand_count": 100_000}
    error = only_error(client.post(path, json=body))
    assert error["loc"] == ["body", "strand_count"]
    assert "cannot fit around" in error["msg"]
    assert "100000 strands" in error["msg"]
    assert "N·D_s must be less than π·D_o" in error["msg"]


def test_one_strand_too_many_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]]
) -> None:
    # 389 strands of 0.25 mm fit around 31 mm (97.4 mm of circumference), 390 do not.
    path = "/api/v1/min-braid-angle"
    assert client.post(path, json={**valid_bodies[path], "strand_count": 389}).status_code == 200
    error = only_error(client.post(path, json={**valid_bodies[path], "strand_count": 390}))
    assert "cannot fit around a 31 mm braid" in error["msg"]


@pytest.mark.parametrize("angle_deg", [10.0, 19.0, 71.0, 80.0])
def test_an_unreachable_braid_angle_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], angle_deg: float
) -> None:
    path = "/api/v1/gap-area"
    error = only_error(client.post(path, json={**valid_bodies[path], "braid_angle_deg": angle_deg}))
    assert error["loc"] == ["body", "braid_angle_deg"]
    assert "reachable range" in error["msg"]
    assert "19.02° to 70.98°" in error["msg"]


# -- geometry: D_o, or b with n -------------------------------------------------------------


@pytest.mark.parametrize("path", GEOMETRY_PATHS)
def test_both_geometry_forms_are_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str
) -> None:
    body = {
        **_without_geometry(valid_bodies[path]),
        "theoretical_diameter_m": 0.031,
        "strand_length_m": 0.65,
        "turns": 4.7,
    }
    error = only_error(client.post(path, json=body))
    assert error["loc"] == ["body", "theoretical_diameter_m"]
    assert "not both" in error["msg"]


@pytest.mark.parametrize("path", GEOMETRY_PATHS)
def test_no_geometry_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str
) -> None:
    error = only_error(client.post(path, json=_without_geometry(valid_bodies[path])))
    assert error["loc"] == ["body", "theoretical_diameter_m"]
    assert "give the braid's size" in error["msg"]


@pytest.mark.parametrize("path", GEOMETRY_PATHS)
@pytest.mark.parametrize(
    ("given", "value", "missing"),
    [("strand_length_m", 0.65, "turns"), ("turns", 4.7, "strand_length_m")],
)
def test_half_of_the_length_form_is_refused(
    client: TestClient,
    valid_bodies: dict[str, dict[str, Any]],
    path: str,
    given: str,
    value: float,
    missing: str,
) -> None:
    body = {**_without_geometry(valid_bodies[path]), given: value}
    error = only_error(client.post(path, json=body))
    assert error["loc"] == ["body", missing]
    assert error["msg"].startswith(f"{missing} is needed with {given}")


@pytest.mark.parametrize("path", LENGTH_PATHS)
def test_a_length_calculation_without_a_length_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str
) -> None:
    body = {**_without_geometry(valid_bodies[path]), "theoretical_diameter_m": 0.044}
    error = only_error(client.post(path, json=body))
    assert error["loc"] == ["body", "strand_length_m"]
    assert "needs the actuator's size" in error["msg"]


# -- materials ------------------------------------------------------------------------------


def test_an_unknown_material_preset_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]]
) -> None:
    body = {**valid_bodies["/api/v1/design"], "material": "unobtainium"}
    error = only_error(client.post("/api/v1/design", json=body))
    assert error["loc"] == ["body", "material"]
    assert "unknown material 'unobtainium'" in error["msg"]
    # It lists what exists.
    presets = [m["id"] for m in client.get("/api/v1/materials").json()["materials"]]
    for preset in presets:
        assert preset in error["msg"]


@pytest.mark.parametrize(
    "missing", ["youngs_modulus_pa", "poisson_ratio", "tensile_strength_pa", "friction_coefficient"]
)
def test_a_property_is_required_without_a_preset(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], missing: str
) -> None:
    body = {k: v for k, v in valid_bodies["/api/v1/design"].items() if k != missing}
    error = only_error(client.post("/api/v1/design", json=body))
    assert error["loc"] == ["body", missing]
    assert error["msg"] == f"{missing} is required when no material preset is given"


# -- sweeps ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("path", "low", "high"),
    [
        ("/api/v1/sweeps/strand-count", "strand_count_min", "strand_count_max"),
        ("/api/v1/sweeps/pressure", "pressure_min_pa", "pressure_max_pa"),
    ],
)
def test_a_sweep_whose_max_is_below_its_min_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], path: str, low: str, high: str
) -> None:
    body = valid_bodies[path]
    error = only_error(client.post(path, json={**body, low: body[high], high: body[low]}))
    assert error["loc"] == ["body", high]
    assert error["msg"] == f"{high} must be at least {low}"


# -- bodies that are not a JSON object ------------------------------------------------------


@pytest.mark.parametrize("path", POST_PATHS)
def test_malformed_json_is_refused(client: TestClient, path: str) -> None:
    content = b'{"strand_diameter_m": 0.00025, "strand_count": 240'
    error = only_error(client.post(path, content=content, headers=JSON))
    assert error["type"] == "json_invalid"
    assert error["msg"] == "JSON decode error"
    assert error["loc"] == ["body", len(content)]


@pytest.mark.parametrize(
    "content", [b"[]", b'[{"strand_diameter_m": 0.00025}]', b"null", b"42", b'"text"', b"true"]
)
@pytest.mark.parametrize("path", POST_PATHS)
def test_a_body_that_is_not_an_object_is_refused(
    client: TestClient, path: str, content: bytes
) -> None:
    error = only_error(client.post(path, content=content, headers=JSON))
    assert error["loc"] == ["body"]
    assert error["type"] == "model_attributes_type"


@pytest.mark.parametrize("path", POST_PATHS)
def test_an_empty_body_is_refused(client: TestClient, path: str) -> None:
    error = only_error(client.post(path, content=b"", headers=JSON))
    assert error["loc"] == ["body"]
    assert error["type"] == "missing"


@pytest.mark.parametrize("path", POST_PATHS)
def test_no_body_at_all_is_refused(client: TestClient, path: str) -> None:
    error = only_error(client.post(path))
    assert error["loc"] == ["body"]
    assert error["type"] == "missing"


@pytest.mark.parametrize(
    "content_type", ["text/plain", "application/x-www-form-urlencoded", "application/xml"]
)
def test_a_body_that_is_not_json_is_refused(
    client: TestClient, valid_bodies: dict[str, dict[str, Any]], content_type: str
) -> None:
    path = "/api/v1/s-scale"
    content = json.dumps(valid_bodies[path]).encode()
    response = client.post(path, content=content, headers={"content-type": content_type})
    assert only_error(response)["loc"] == ["body"]


@pytest.mark.parametrize("content", [b"\xff", b"\x80{}", b'{"strand_diameter_m": "\xe9"}'])
def test_a_body_that_is_not_utf8_is_a_422(client: TestClient, content: bytes) -> None:
    error = only_error(client.post("/api/v1/s-scale", content=content, headers=JSON))
    assert error["loc"][0] == "body"


@pytest.mark.parametrize("path", POST_PATHS)
def test_get_on_a_calculation_is_405(client: TestClient, path: str) -> None:
    response = client.get(path)
    assert response.status_code == 405
    assert response.headers["allow"] == "POST"


@pytest.mark.parametrize("path", ["/healthz", "/api/v1/materials", "/api/v1/reference"])
def test_post_on_reference_data_is_405(client: TestClient, path: str) -> None:
    assert client.post(path, json={}).status_code == 405


# -- anything at all ------------------------------------------------------------------------

_FIELD_NAMES = sorted(
    {
        "strand_diameter_m",
        "strand_count",
        "theoretical_diameter_m",
        "strand_length_m",
        "turns",
        "parallel_strands",
        "braid_angle_deg",
        "pressure_pa",
        "tensile_strength_pa",
        "safety_factor",
        "youngs_modulus_pa",
        "poisson_ratio",
        "friction_coefficient",
        "s_scale",
        "points",
        "material",
        "gap_area_limit_m2",
        "strand_count_min",
        "strand_count_max",
        "pressure_min_pa",
        "pressure_max_pa",
        "name",
        "cord_length_m",
    }
)
_JSON_VALUES = st.recursive(
    st.none()
    | st.booleans()
    | st.integers(-(10**20), 10**20)
    | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(max_size=10),
    lambda children: (
        st.lists(children, max_size=3) | st.dictionaries(st.text(max_size=5), children, max_size=3)
    ),
    max_leaves=8,
)


# valid_bodies is only read, never changed: sharing it between examples is safe.
@settings(
    max_examples=150,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(
    path=st.sampled_from(POST_PATHS),
    changes=st.dictionaries(
        st.sampled_from(_FIELD_NAMES) | st.text(max_size=8), _JSON_VALUES, max_size=4
    ),
    drop=st.sets(st.sampled_from(_FIELD_NAMES), max_size=3),
)
def test_anything_sent_is_answered_200_or_422(
    client: TestClient,
    valid_bodies: dict[str, dict[str, Any]],
    path: str,
    changes: dict[str, Any],
    drop: set[str],
) -> None:
    body = {k: v for k, v in {**valid_bodies[path], **changes}.items() if k not in drop}
    response = client.post(path, json=body)
    # The client's hook has already checked: no 5xx, no NaN, a well-formed 422.
    assert response.status_code in (200, 422), response.text
    if response.status_code == 422:
        for error in errors(response):
            assert error["loc"][0] == "body"
