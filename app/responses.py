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
from starlette.types import Receive, Scope, Send

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
    """``application/x-npy``: a NumPy ``.npy`` file of curves, sent without copying them.

    The file holds one record (a 0-d structured array) whose fields are the whole curves,
    float64, one after the other: ``numpy.load(io.BytesIO(content))["contraction"]`` is the
    contraction curve. Column by column is how the model computes them, so the body is the
    header and then each array's own buffer, sent as it is: no number formatting, no
    interleaving, no copy.
    """

    media_type = "application/x-npy"

    def __init__(self, columns: Mapping[str, npt.NDArray[np.float64]]) -> None:
        self.chunks = npy_chunks(columns)
        super().__init__(b"")
        self.headers["content-length"] = str(sum(len(chunk) for chunk in self.chunks))

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        await send(
            {"type": "http.response.start", "status": self.status_code, "headers": self.raw_headers}
        )
        last = len(self.chunks) - 1
        for index, chunk in enumerate(self.chunks):
            await send({"type": "http.response.body", "body": chunk, "more_body": index < last})


def npy_chunks(columns: Mapping[str, npt.NDArray[np.float64]]) -> list[bytes | memoryview]:
    """The ``.npy`` file of :class:`NPYResponse`, as its header and one buffer per column.

    ``b"".join(npy_chunks(columns))`` is the file ``np.save`` writes for the 0-d array of
    dtype ``[(name, "<f8", (rows,)), ...]`` holding the columns.
    """
    arrays = [np.ascontiguousarray(column, dtype="<f8") for column in columns.values()]
    rows = len(arrays[0]) if arrays else 0
    if any(array.shape != (rows,) for array in arrays):
        raise ValueError("npy columns must be 1-D and of equal length")
    dtype = np.dtype([(name, "<f8", (rows,)) for name in columns])
    header = io.BytesIO()
    fields = {"descr": np.lib.format.dtype_to_descr(dtype), "fortran_order": False, "shape": ()}
    np.lib.format.write_array_header_1_0(header, fields)
    # Cast to bytes: a memoryview's len() must count bytes, as the server counts the body.
    return [header.getvalue(), *(array.data.cast("B") for array in arrays)]
