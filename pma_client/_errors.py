"""Exceptions: the service refused the request, or answered with something unexpected."""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import Any

import httpx

_BODY_EXCERPT = 500


class PMAError(Exception):
    """A request the service did not answer with a result.

    Raised for a non-2xx status (other than 422, see :class:`PMAValidationError`) and for
    a 2xx response whose body is not the JSON the API documents. Network failures and
    timeouts are not wrapped: they raise :class:`httpx.TransportError` as usual.

    Attributes
    ----------
    status_code : int
        HTTP status of the response.
    body : str
        Response body as text.
    request_id : str or None
        The ``X-Request-ID`` the service gave the request, to find it in the service's log.
    """

    def __init__(
        self, message: str, *, status_code: int, body: str, request_id: str | None = None
    ) -> None:
        super().__init__(message)
        self.status_code = status_code
        self.body = body
        self.request_id = request_id


class PMAValidationError(PMAError):
    """A 422: the service refused the input, naming each field and saying why.

    ``str(error)`` is one ``field: message`` per problem, joined by ``"; "``.

    Attributes
    ----------
    detail : list of dict
        The API's ``detail``: one ``{"loc": [...], "msg": str, "type": str}`` per problem,
        ``loc`` ending with the field name (just ``["body"]`` for the body as a whole).
    """

    def __init__(
        self,
        detail: list[dict[str, Any]],
        *,
        status_code: int = 422,
        body: str = "",
        request_id: str | None = None,
    ) -> None:
        super().__init__(
            describe(detail), status_code=status_code, body=body, request_id=request_id
        )
        self.detail = detail

    @property
    def fields(self) -> tuple[str, ...]:
        """The names of the fields refused, in the order of ``detail`` (``""``: the body)."""
        return tuple(_field(problem) for problem in self.detail)


def _field(problem: Mapping[str, Any]) -> str:
    loc = problem.get("loc")
    if isinstance(loc, Sequence) and not isinstance(loc, str) and len(loc) > 1:
        return str(loc[-1])
    return ""


def describe(detail: Sequence[Mapping[str, Any]]) -> str:
    """``field: message`` for each problem of a 422 ``detail``, joined by ``"; "``.

    The field is the last element of ``loc``; it is not repeated where the message
    already starts with it.

    Examples
    --------
    >>> describe([{"loc": ["body", "strand_count"], "msg": "Field required"}])
    'strand_count: Field required'
    >>> describe([{"loc": ["body", "turns"], "msg": "turns is needed with strand_length_m"}])
    'turns is needed with strand_length_m'
    >>> describe([{"loc": ["body"], "msg": "JSON decode error"}])
    'JSON decode error'
    """
    parts = []
    for problem in detail:
        message = str(problem.get("msg", "invalid value"))
        field = _field(problem)
        if field and not re.match(rf"{re.escape(field)}\b", message):
            message = f"{field}: {message}"
        parts.append(message)
    return "; ".join(parts) or "invalid input"


def error_for(response: httpx.Response, problem: str | None = None) -> PMAError:
    """The exception for a ``response`` that is not a result.

    A 422 in the API's shape gives a :class:`PMAValidationError`; anything else a
    :class:`PMAError` saying ``problem`` (default: the status) with an excerpt of the body.
    """
    text = response.text
    request_id = response.headers.get("x-request-id")
    if problem is None and response.status_code == 422:
        detail = _validation_detail(response)
        if detail is not None:
            return PMAValidationError(detail, body=text, request_id=request_id)
    request = response.request
    what = problem or f"HTTP {response.status_code} {response.reason_phrase}"
    excerpt = text if len(text) <= _BODY_EXCERPT else text[:_BODY_EXCERPT] + "…"
    return PMAError(
        f"{what} from {request.method} {request.url}: {excerpt}",
        status_code=response.status_code,
        body=text,
        request_id=request_id,
    )


def _validation_detail(response: httpx.Response) -> list[dict[str, Any]] | None:
    try:
        payload = response.json()
    except ValueError:
        return None
    detail = payload.get("detail") if isinstance(payload, dict) else None
    if isinstance(detail, list) and detail and all(isinstance(p, dict) for p in detail):
        return detail
    return None
