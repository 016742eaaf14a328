"""Helpers of the API tests: call an endpoint, and check a success or a refusal.

Every response the API tests receive also passes :func:`check_every_response` (an httpx
event hook installed by ``conftest.client``): no 5xx, no NaN or Infinity in a JSON body, and
every 422 in the shape API.md promises.
"""

from __future__ import annotations

import json
from typing import Any

import httpx
from fastapi.testclient import TestClient

#: The keys of one error object in a 422 ``detail`` list: exactly these (no ``input``, no
#: ``ctx``, which may hold NaN or a large body).
ERROR_KEYS = frozenset({"loc", "msg", "type"})

#: Where a request value comes from, the first element of an error's ``loc``.
LOCATIONS = frozenset({"body", "query", "header", "path"})

JSON = {"content-type": "application/json"}


def _refuse_constant(token: str) -> Any:
    raise AssertionError(f"response body holds the non-JSON number {token}")


def strict_json(body: bytes) -> Any:
    """Parse ``body`` as standard JSON: NaN, Infinity and -Infinity are an error."""
    return json.loads(body, parse_constant=_refuse_constant)


def check_error_body(body: Any) -> list[dict[str, Any]]:
    """Assert ``body`` is ``{"detail": [{"loc", "msg", "type"}, ...]}`` and return the list."""
    assert isinstance(body, dict), body
    assert set(body) == {"detail"}, body
    detail = body["detail"]
    assert isinstance(detail, list), detail
    assert detail, "a 422 must say what is wrong"
    for error in detail:
        assert isinstance(error, dict), error
        assert set(error) == ERROR_KEYS, error
        assert isinstance(error["loc"], list), error
        assert error["loc"], error
        assert error["loc"][0] in LOCATIONS, error
        assert all(isinstance(part, str | int) for part in error["loc"]), error
        assert isinstance(error["msg"], str), error
        assert error["msg"].strip(), error
        assert isinstance(error["type"], str), error
        assert error["type"], error
    return detail


def check_every_response(response: httpx.Response) -> None:
    """httpx response hook: the invariants every API response keeps, whatever was sent."""
    response.read()
    request = response.request
    assert response.status_code < 500, (
        f"{request.method} {request.url.path} answered {response.status_code}: {response.text}"
    )
    if response.headers.get("content-type", "").startswith("application/json"):
        body = strict_json(response.content)
        if request.url.path.startswith("/api/"):
            assert b"NaN" not in response.content, response.text
            assert b"Infinity" not in response.content, response.text
        if response.status_code == 422:
            check_error_body(body)


def install_checks(client: TestClient) -> TestClient:
    """Add :func:`check_every_response` to ``client``'s response hooks."""
    hooks = client.event_hooks
    client.event_hooks = {**hooks, "response": [*hooks.get("response", []), check_every_response]}
    return client


def ok(client: TestClient, path: str, body: dict[str, Any]) -> dict[str, Any]:
    """POST ``body`` to ``path``, assert a 200 and return the JSON object."""
    response = client.post(path, json=body)
    assert response.status_code == 200, response.text
    assert response.headers["content-type"].startswith("application/json")
    data = response.json()
    assert isinstance(data, dict), data
    return data


def errors(response: httpx.Response) -> list[dict[str, Any]]:
    """Assert ``response`` is a well-formed 422 and return its ``detail`` list."""
    assert response.status_code == 422, f"{response.status_code}: {response.text}"
    return check_error_body(response.json())


def only_error(response: httpx.Response) -> dict[str, Any]:
    """Assert ``response`` is a 422 with exactly one error and return that error."""
    detail = errors(response)
    assert len(detail) == 1, detail
    return detail[0]


def error_at(response: httpx.Response, *loc: str | int) -> dict[str, Any]:
    """Assert ``response`` is a 422 with an error at ``("body", *loc)`` and return it."""
    detail = errors(response)
    wanted = ["body", *loc]
    found = [error for error in detail if error["loc"] == wanted]
    assert found, f"no error at {wanted}: {detail}"
    return found[0]


#: Every calculation endpoint (POST, JSON body).
POST_PATHS = (
    "/api/v1/min-braid-angle",
    "/api/v1/gap-area",
    "/api/v1/failure-strand-count",
    "/api/v1/s-scale",
    "/api/v1/hysteresis",
    "/api/v1/design",
    "/api/v1/sweeps/strand-count",
    "/api/v1/sweeps/pressure",
    "/api/v1/export/opensim",
    "/api/v1/sweeps/hysteresis",
)
#: Those that take the braid's geometry (D_o, or b with n).
GEOMETRY_PATHS = tuple(path for path in POST_PATHS if path != "/api/v1/s-scale")
