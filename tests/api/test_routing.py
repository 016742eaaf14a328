"""JSONBodyRoute: its short path answers exactly what FastAPI's own handler answers.

Each calculation endpoint is mounted a second time with FastAPI's plain ``APIRoute`` in a
reference app with the same error handlers; the same request, valid or not, must get the
same status and the same body from both.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator
from typing import Annotated, Any

import pytest
from fastapi import BackgroundTasks, Body, FastAPI, Request
from fastapi.routing import APIRoute
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pydantic import AfterValidator, BaseModel
from starlette.responses import PlainTextResponse, Response

import app.routing
from app.errors import install_error_handlers
from app.main import app as calculator
from app.responses import JSONResponse
from app.routes import calculations, design, export
from app.routing import JSONBodyRoute
from tests.api.support import JSON, POST_PATHS

#: Endpoints whose only parameter is the body: the short path serves them.
SHORT_PATH_PATHS = tuple(path for path in POST_PATHS if path != "/api/v1/hysteresis")

CONTENT_TYPES = (
    "application/json",
    "application/json; charset=utf-8",
    "Application/JSON",
    "application/vnd.api+json",
    "text/plain",
    "",
)


def _body_routes() -> list[APIRoute]:
    routers = (calculations.router, design.router, export.router)
    return [route for router in routers for route in router.routes if isinstance(route, APIRoute)]


def _reference_app() -> FastAPI:
    """The calculator's body routes again, each as FastAPI's plain APIRoute."""
    reference = FastAPI(default_response_class=JSONResponse)
    install_error_handlers(reference)
    for route in _body_routes():
        if isinstance(route, JSONBodyRoute):
            reference.router.add_api_route(
                route.path,
                route.endpoint,
                methods=sorted(route.methods or ()),
                response_model=route.response_model,
                route_class_override=APIRoute,
            )
    return reference


@pytest.fixture(scope="module")
def both() -> Iterator[tuple[TestClient, TestClient]]:
    with TestClient(calculator) as subject, TestClient(_reference_app()) as reference:
        yield subject, reference


def _post(client: TestClient, path: str, content: bytes, content_type: str) -> tuple[int, Any]:
    headers = {"content-type": content_type} if content_type else {}
    response = client.post(path, content=content, headers=headers)
    return response.status_code, response.json()


def test_the_calculation_routes_use_the_short_path() -> None:
    routes = {route.path: route for route in _body_routes()}
    for path in POST_PATHS:
        assert isinstance(routes[path], JSONBodyRoute), path


@pytest.mark.parametrize("path", SHORT_PATH_PATHS)
def test_a_valid_body_skips_fastapis_body_handling(
    path: str,
    valid_bodies: dict[str, dict[str, Any]],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    calls: list[object] = []
    original = APIRoute.get_route_handler

    def counting(route: APIRoute) -> Any:
        handler = original(route)

        async def counted(request: Any) -> Any:
            calls.append(request)
            return await handler(request)

        return counted

    monkeypatch.setattr(APIRoute, "get_route_handler", counting)
    endpoint = next(r.endpoint for r in _body_routes() if r.path == path)
    probe = FastAPI()
    install_error_handlers(probe)
    probe.router.routes.append(JSONBodyRoute(path, endpoint, methods=["POST"]))
    with TestClient(probe) as client:
        valid = client.post(path, content=json.dumps(valid_bodies[path]), headers=JSON)
        assert valid.status_code == 200, valid.text
        assert calls == [], "a valid JSON body went through FastAPI's handler"
        refused = client.post(path, content=b"{}", headers=JSON)
        assert refused.status_code == 422
        assert len(calls) == 1, "an invalid body must be reported by FastAPI's handler"


def test_a_route_with_query_parameters_keeps_fastapis_handler() -> None:
    hysteresis = next(r for r in _body_routes() if r.path == "/api/v1/hysteresis")
    assert isinstance(hysteresis, JSONBodyRoute)
    assert app.routing._sole_body_model(hysteresis.dependant) is None


@pytest.mark.parametrize("path", SHORT_PATH_PATHS)
@pytest.mark.parametrize("content_type", CONTENT_TYPES)
def test_a_valid_body_gets_the_same_answer_as_from_fastapi(
    path: str,
    content_type: str,
    valid_bodies: dict[str, dict[str, Any]],
    both: tuple[TestClient, TestClient],
) -> None:
    subject, reference = both
    content = json.dumps(valid_bodies[path]).encode()
    assert _post(subject, path, content, content_type) == _post(
        reference, path, content, content_type
    )


_JSON_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(),
    lambda children: st.lists(children, max_size=3) | st.dictionaries(st.text(), children),
    max_leaves=5,
)
_RAW_NUMBERS = ("NaN", "Infinity", "-Infinity", "1e400", "-0", "1E-400", '"3"', "true")


@settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_any_body_gets_the_same_answer_as_from_fastapi(
    data: st.DataObject,
    valid_bodies: dict[str, dict[str, Any]],
    both: tuple[TestClient, TestClient],
) -> None:
    path = data.draw(st.sampled_from(SHORT_PATH_PATHS), label="path")
    body = dict(valid_bodies[path])
    key = data.draw(st.sampled_from([*body, "unknown_field"]), label="key")
    change = data.draw(st.sampled_from(["value", "raw", "drop", "bytes"]), label="change")
    if change == "drop":
        body.pop(key, None)
        content = json.dumps(body).encode()
    elif change == "value":
        body[key] = data.draw(_JSON_VALUES, label="value")
        content = json.dumps(body).encode()
    elif change == "raw":
        body[key] = 123456.789
        raw = data.draw(st.sampled_from(_RAW_NUMBERS), label="raw")
        content = json.dumps(body).replace("123456.789", raw).encode()
    else:
        content = data.draw(st.binary(max_size=64), label="bytes")
    content_type = data.draw(st.sampled_from(CONTENT_TYPES), label="content_type")
    subject, reference = both
    assert _post(subject, path, content, content_type) == _post(
        reference, path, content, content_type
    )


class _Model(BaseModel):
    x: int


def _positive(model: _Model) -> _Model:
    if model.x <= 0:
        raise ValueError("x must be positive")
    return model


async def _with_request(body: _Model, request: Request) -> Response:
    return PlainTextResponse(f"{body.x} {request.url.path}")


async def _with_background(body: _Model, tasks: BackgroundTasks) -> Response:
    return PlainTextResponse(str(body.x))


async def _with_validator(body: Annotated[_Model, AfterValidator(_positive)]) -> Response:
    return PlainTextResponse(str(body.x))


async def _embedded(body: Annotated[_Model, Body(embed=True)]) -> Response:
    return PlainTextResponse(str(body.x))


async def _returns_dict(body: _Model) -> dict[str, int]:
    return {"x": body.x}


def _sync(body: _Model) -> Response:
    return PlainTextResponse(str(body.x))


ENDPOINTS_FASTAPI_KEEPS: dict[str, tuple[Callable[..., Any], dict[str, Any]]] = {
    "request": (_with_request, {"x": 1}),
    "background tasks": (_with_background, {"x": 1}),
    "own validator": (_with_validator, {"x": -1}),
    "embedded body": (_embedded, {"body": {"x": 1}}),
    "dict result": (_returns_dict, {"x": 1}),
    "sync endpoint": (_sync, {"x": 1}),
}


@pytest.mark.parametrize("case", ENDPOINTS_FASTAPI_KEEPS)
def test_endpoints_the_short_path_cannot_serve_keep_fastapis_handler(case: str) -> None:
    endpoint, body = ENDPOINTS_FASTAPI_KEEPS[case]
    answers = []
    for route_class in (APIRoute, JSONBodyRoute):
        probe = FastAPI()
        probe.router.add_api_route(
            "/p", endpoint, methods=["POST"], route_class_override=route_class
        )
        with TestClient(probe) as client:
            response = client.post("/p", json=body)
        answers.append((response.status_code, response.text))
    assert answers[0] == answers[1]
