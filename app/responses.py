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
    """``application/x-npy``: a NumPy ``.npy`` file; see :func:`npy_table`, :func:`npy_record`."""

    media_type = "application/x-npy"


def npy_table(columns: Mapping[str, npt.NDArray[np.float64]]) -> bytes:
    """A ``.npy`` file of one structured array: a row per point, a float64 field per column.

    ``numpy.load(io.BytesIO(content))["contraction"]``; byte for byte what ``np.save``
    writes for that table, but the columns are written once, straight into the file's
    buffer after its header (``np.save`` would build the table, then copy it twice).
    """
    names = list(columns)
    dtype = np.dtype([(name, "<f8") for name in names])
    rows = len(columns[names[0]])
    header = _npy_header(dtype, (rows,))
    # np.empty, not bytearray: every byte is written below, so none is zeroed first.
    buffer = np.empty(len(header) + dtype.itemsize * rows, dtype=np.uint8)
    buffer[: len(header)] = np.frombuffer(header, dtype=np.uint8)
    table = buffer[len(header) :].view(dtype)
    for name, column in columns.items():
        table[name] = column
    return buffer.tobytes()


def npy_record(fields: Mapping[str, float | npt.NDArray[np.float64]]) -> bytes:
    """A ``.npy`` file of one record (a 0-d structured array), a field per entry of ``fields``.

    A field is a number or a whole curve: ``numpy.load(io.BytesIO(content))["contraction"]``
    is the contraction curve. Column by column is how the model computes the curves, so the
    file is the header and each array's own buffer joined (:func:`npy_chunks`): one copy,
    no interleaving. One bytes body, sent at once: ASGI bodies are bytes, and a client that
    leaves mid-answer costs one failed write, not one per chunk.
    """
    return b"".join(npy_chunks(fields))


def npy_chunks(fields: Mapping[str, float | npt.NDArray[np.float64]]) -> list[bytes | memoryview]:
    """The file of :func:`npy_record` as its header, then one buffer per field.

    ``b"".join(npy_chunks(fields))`` is the file ``np.save`` writes for the 0-d record of
    dtype ``[(name, "<f8", shape), ...]`` holding ``fields`` (numbers and 1-D arrays).
    """
    # np.require keeps a 0-d array 0-d (np.ascontiguousarray would make it 1-D).
    arrays = [np.require(value, dtype="<f8", requirements="C") for value in fields.values()]
    if any(array.ndim > 1 for array in arrays):
        raise ValueError("npy fields must be numbers or 1-D arrays")
    dtype = np.dtype([(name, "<f8", a.shape) for name, a in zip(fields, arrays, strict=True)])
    return [_npy_header(dtype, ()), *(_raw_bytes(array) for array in arrays)]


def _npy_header(dtype: np.dtype[Any], shape: tuple[int, ...]) -> bytes:
    """The ``.npy`` magic and header of a C-ordered array of ``shape`` ``dtype`` items."""
    header = io.BytesIO()
    fields = {"descr": np.lib.format.dtype_to_descr(dtype), "fortran_order": False}
    np.lib.format.write_array_header_1_0(header, {**fields, "shape": shape})
    return header.getvalue()


def _raw_bytes(array: npt.NDArray[np.float64]) -> bytes | memoryview:
    # A number is 8 bytes, copied; a curve is its own buffer, cast so that len() counts
    # bytes.
    return array.tobytes() if array.ndim == 0 else array.data.cast("B")
