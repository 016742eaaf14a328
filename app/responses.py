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
    """``application/x-npy``: a NumPy ``.npy`` file of one record.

    The record (a 0-d structured array) has a float64 field per entry of ``fields``: a
    number, or a whole curve. ``numpy.load(io.BytesIO(content))["contraction"]`` is the
    contraction curve. Column by column is how the model computes the curves, so the body
    is the header and each array's own buffer joined: one copy, no number formatting, no
    interleaving.
    """

    media_type = "application/x-npy"

    def __init__(self, fields: Mapping[str, float | npt.NDArray[np.float64]]) -> None:
        # One bytes body, one send: ASGI bodies are bytes, and a client that leaves
        # mid-answer costs one failed write, not one per chunk.
        super().__init__(b"".join(npy_chunks(fields)))


def npy_chunks(fields: Mapping[str, float | npt.NDArray[np.float64]]) -> list[bytes | memoryview]:
    """The ``.npy`` file of :class:`NPYResponse`: its header, then one buffer per field.

    ``b"".join(npy_chunks(fields))`` is the file ``np.save`` writes for the 0-d record of
    dtype ``[(name, "<f8", shape), ...]`` holding ``fields`` (numbers and 1-D arrays).
    """
    # np.require keeps a 0-d array 0-d (np.ascontiguousarray would make it 1-D).
    arrays = [np.require(value, dtype="<f8", requirements="C") for value in fields.values()]
    if any(array.ndim > 1 for array in arrays):
        raise ValueError("npy fields must be numbers or 1-D arrays")
    dtype = np.dtype([(name, "<f8", a.shape) for name, a in zip(fields, arrays, strict=True)])
    header = io.BytesIO()
    descr = np.lib.format.dtype_to_descr(dtype)
    np.lib.format.write_array_header_1_0(
        header, {"descr": descr, "fortran_order": False, "shape": ()}
    )
    return [header.getvalue(), *(_raw_bytes(array) for array in arrays)]


def _raw_bytes(array: npt.NDArray[np.float64]) -> bytes | memoryview:
    # A number is 8 bytes, copied; a curve is its own buffer, cast so that len() counts
    # bytes, as the server counts the body.
    return array.tobytes() if array.ndim == 0 else array.data.cast("B")
