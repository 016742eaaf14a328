"""JSON responses serialized by orjson, numpy arrays included, without per-element Python."""

from __future__ import annotations

from typing import Any

import orjson
from starlette.responses import Response

_OPTIONS = orjson.OPT_SERIALIZE_NUMPY | orjson.OPT_NON_STR_KEYS


class JSONResponse(Response):
    """``application/json`` rendered by orjson.

    numpy arrays are written straight from their buffers. orjson writes NaN and infinities
    as ``null``, so no response can contain a non-JSON number.
    """

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return orjson.dumps(content, option=_OPTIONS)
