"""Turn bad input into 422s that name the field, in FastAPI's usual ``detail`` shape."""

from __future__ import annotations

import re
from collections.abc import Container, Iterator
from contextlib import contextmanager
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.responses import Response

from app.responses import JSONResponse

# pma_core names parameters in radians where the API takes degrees.
_CORE_TO_FIELD = {"braid_angle_rad": "braid_angle_deg"}
_UNPARSABLE_BODY = "There was an error parsing the body"
_LEADING_NAME = re.compile(r"^([a-z_][a-z0-9_]*)\b")


def field_error(field: str, message: str) -> RequestValidationError:
    """A 422 for one body ``field``, with ``message`` in words a user understands."""
    return RequestValidationError([{"loc": ("body", field), "msg": message, "type": "value_error"}])


@contextmanager
def core_errors(fields: Container[str]) -> Iterator[None]:
    """Re-raise a :class:`ValueError` from pma_core as a 422 on the field it names.

    pma_core messages start with the parameter's name; where that is not a body field
    (a derived quantity), the error is reported on the body as a whole.
    """
    try:
        yield
    except ValueError as error:
        message = str(error)
        match = _LEADING_NAME.match(message)
        name = _CORE_TO_FIELD.get(match.group(1), match.group(1)) if match else ""
        loc: tuple[str, ...] = ("body", name) if name in fields else ("body",)
        detail = [{"loc": loc, "msg": message, "type": "value_error"}]
        raise RequestValidationError(detail) from None


_BOUNDS = {
    "greater_than_equal": ("ge", "at least"),
    "greater_than": ("gt", "greater than"),
    "less_than_equal": ("le", "at most"),
    "less_than": ("lt", "less than"),
}
_UNITS = (("_m2", " m²"), ("_m", " m"), ("_pa", " Pa"), ("_deg", "°"), ("_n", " N"))


def _clean(error: dict[str, Any]) -> dict[str, Any]:
    # Only loc, msg and type: "input" may hold NaN (not JSON) or a large body, and "ctx"
    # may hold exception objects.
    loc = list(error.get("loc", ()))
    kind = str(error.get("type", "value_error"))
    msg = _bound_message(loc, kind, error) or str(error.get("msg", "invalid value"))
    return {"loc": loc, "msg": msg.removeprefix("Value error, "), "type": kind}


def _bound_message(loc: list[Any], kind: str, error: dict[str, Any]) -> str | None:
    """ "strand_diameter_m must be at least 1e-06 m, got 0" rather than pydantic's wording."""
    if kind not in _BOUNDS or not loc or not isinstance(loc[-1], str):
        return None
    key, words = _BOUNDS[kind]
    limit, value = error.get("ctx", {}).get(key), error.get("input")
    if not isinstance(limit, int | float) or not isinstance(value, int | float):
        return None
    field = loc[-1]
    unit = next((u for suffix, u in _UNITS if field.endswith(suffix)), "")
    return f"{field} must be {words} {limit:g}{unit}, got {value:g}{unit}"


async def _validation_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, RequestValidationError)
    return JSONResponse({"detail": [_clean(e) for e in exc.errors()]}, status_code=422)


async def _http_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, StarletteHTTPException)
    headers = getattr(exc, "headers", None)
    if exc.status_code == 400 and exc.detail == _UNPARSABLE_BODY:
        # FastAPI's 400 for a body it cannot decode (not UTF-8): bad input like any other.
        detail = [{"loc": ["body"], "msg": "the body is not UTF-8 JSON", "type": "json_invalid"}]
        return JSONResponse({"detail": detail}, status_code=422, headers=headers)
    if exc.status_code in (204, 304) or exc.status_code < 200:
        return Response(status_code=exc.status_code, headers=headers)
    return JSONResponse({"detail": exc.detail}, status_code=exc.status_code, headers=headers)


def install_error_handlers(app: FastAPI) -> None:
    """Register the 422 and HTTP error handlers on ``app``.

    Unexpected exceptions are answered by :class:`app.middleware.ServiceMiddleware`.
    """
    app.add_exception_handler(RequestValidationError, _validation_handler)
    app.add_exception_handler(StarletteHTTPException, _http_handler)
