"""JSON responses serialized by orjson, numpy arrays included, without per-element Python."""

from __future__ import annotations

import io
from collections.abc import Mapping
from typing import Any

import numpy as np
import numpy.typing as npt
import orjson
from starlette.responses import JSONResponse as StarletteJSONResponse
from starlette.responses import Response

_OPTIONS = orjson.OPT_SERIALIZE_NUMPY | orjson.OPT_NON_STR_KEYS


class JSONResponse(StarletteJSONResponse):
    """``application/json`` rendered by orjson.

    numpy arrays are written straight from their buffers. orjson writes NaN and infinities
    as ``null``, so no response can contain a non-JSON number.
    """

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return orjson.dumps(content, option=_OPTIONS)


class CSVResponse(Response):
    """``text/csv`` with a header row; see :func:`csv_bytes`."""

    media_type = "text/csv"


def csv_bytes(columns: Mapping[str, npt.NDArray[np.float64]]) -> bytes:
    """CSV of equal-length numeric columns, without per-element Python work.

    orjson writes the 2-D array as ``[[a,b],[c,d]]`` with shortest round-trip floats;
    the row brackets become line breaks. A number never contains ``[``, ``]`` or ``,``.
    """
    table = np.column_stack(list(columns.values()))
    body = orjson.dumps(table, option=orjson.OPT_SERIALIZE_NUMPY)[2:-2].replace(b"],[", b"\n")
    return ",".join(columns).encode() + b"\n" + body + b"\n"


class NPYResponse(Response):
    """``application/x-npy``: a NumPy ``.npy`` file; see :func:`npy_bytes`."""

    media_type = "application/x-npy"


def npy_bytes(columns: Mapping[str, npt.NDArray[np.float64]]) -> bytes:
    """A ``.npy`` file of one structured array with a float64 field per column.

    Binary, so no number is formatted: ``numpy.load(io.BytesIO(content))["contraction"]``.
    """
    names = list(columns)
    table = np.empty(len(columns[names[0]]), dtype=[(name, "<f8") for name in names])
    for name, column in columns.items():
        table[name] = column
    buffer = io.BytesIO()
    np.save(buffer, table, allow_pickle=False)
    return buffer.getvalue()
