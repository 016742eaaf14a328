"""The hysteresis curves as tables: CSV (?format=csv, Accept: text/csv) and .npy."""

from __future__ import annotations

import csv
import io

import numpy as np
import pytest
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st

from app.main import app
from app.responses import npy_chunks, npy_record, npy_table

client = TestClient(app)
BODY = {
    "strand_length_m": 0.65,
    "turns": 4.7,
    "strand_diameter_m": 0.00025,
    "strand_count": 240,
    "pressure_pa": 200_000.0,
    "friction_coefficient": 0.2,
    "youngs_modulus_pa": 3e9,
    "poisson_ratio": 0.4,
    "points": 11,
}
COLUMNS = [
    "braid_angle_deg",
    "length_m",
    "contraction",
    "force_static_n",
    "friction_force_n",
    "force_contracting_n",
    "force_extending_n",
]


def _table(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize(
    ("path", "headers"),
    [
        ("/api/v1/hysteresis?format=csv", {}),
        ("/api/v1/hysteresis", {"Accept": "text/csv"}),
    ],
)
def test_csv_has_the_json_arrays(path: str, headers: dict[str, str]) -> None:
    as_json = client.post("/api/v1/hysteresis", json=BODY).json()
    response = client.post(path, json=BODY, headers=headers)
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/csv")
    rows = _table(response.text)
    assert list(rows[0]) == COLUMNS
    assert len(rows) == 11
    for column in COLUMNS:
        assert [float(row[column]) for row in rows] == as_json[column]


def test_format_json_wins_over_accept() -> None:
    response = client.post(
        "/api/v1/hysteresis?format=json", json=BODY, headers={"Accept": "text/csv"}
    )
    assert response.headers["content-type"] == "application/json"


def test_unknown_format_is_refused() -> None:
    response = client.post("/api/v1/hysteresis?format=xlsx", json=BODY)
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["query", "format"]


def test_large_csv_is_gzipped_when_accepted() -> None:
    response = client.post(
        "/api/v1/hysteresis?format=csv",
        json={**BODY, "points": 100_000},
        headers={"Accept-Encoding": "gzip"},
    )
    assert response.headers["content-encoding"] == "gzip"
    assert len(_table(response.text)) == 100_000


@pytest.mark.parametrize(
    ("path", "headers"),
    [
        ("/api/v1/hysteresis?format=npy", {}),
        ("/api/v1/hysteresis", {"Accept": "application/x-npy"}),
    ],
)
def test_npy_is_a_structured_array_of_the_json_arrays(path: str, headers: dict[str, str]) -> None:
    as_json = client.post("/api/v1/hysteresis", json=BODY).json()
    response = client.post(path, json=BODY, headers={**headers, "Accept-Encoding": "gzip"})
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/x-npy"
    assert "content-encoding" not in response.headers  # raw floats are not worth gzipping
    table = np.load(io.BytesIO(response.content), allow_pickle=False)
    assert table.dtype.names == tuple(COLUMNS)
    for column in COLUMNS:
        assert table[column].tolist() == as_json[column]


def test_npy_record_is_the_json_answer() -> None:
    as_json = client.post("/api/v1/hysteresis", json=BODY).json()
    response = client.post("/api/v1/hysteresis?format=npy-record", json=BODY)
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/x-npy"
    record = np.load(io.BytesIO(response.content), allow_pickle=False)
    assert record.shape == ()
    assert record.dtype.names == tuple(as_json)
    for name, value in as_json.items():
        assert record[name].tolist() == value, name


_NAMES = st.from_regex(r"[a-z_]{1,12}", fullmatch=True)


@settings(max_examples=40, deadline=None)
@given(rows=st.integers(0, 300), names=st.lists(_NAMES, min_size=1, max_size=8, unique=True))
def test_npy_table_is_the_file_np_save_writes(rows: int, names: list[str]) -> None:
    rng = np.random.default_rng(rows)
    columns = {name: rng.normal(size=rows) for name in names}
    table = np.empty(rows, dtype=[(name, "<f8") for name in names])
    for name, column in columns.items():
        table[name] = column
    saved = io.BytesIO()
    np.save(saved, table, allow_pickle=False)
    assert npy_table(columns) == saved.getvalue()


@settings(max_examples=40, deadline=None)
@given(
    shapes=st.dictionaries(
        _NAMES,
        st.sampled_from([(), (0,), (1,), (7,), (300,)]),
        min_size=1,
        max_size=8,
    ),
)
def test_npy_record_is_the_file_np_save_writes(shapes: dict[str, tuple[int, ...]]) -> None:
    rng = np.random.default_rng(len(shapes))
    fields = {name: rng.normal(size=shape) for name, shape in shapes.items()}
    record = np.zeros((), dtype=[(name, "<f8", shape) for name, shape in shapes.items()])
    for name, value in fields.items():
        record[name] = value
    saved = io.BytesIO()
    np.save(saved, record, allow_pickle=False)
    assert npy_record(fields) == saved.getvalue()


def test_npy_chunks_are_the_arrays_own_buffers() -> None:
    columns = {"a": np.arange(4.0), "b": np.linspace(0.0, 1.0, 4)}
    header, *buffers = npy_chunks(columns)
    assert isinstance(header, bytes)
    for buffer, column in zip(buffers, columns.values(), strict=True):
        assert isinstance(buffer, memoryview)
        assert len(buffer) == column.nbytes
        assert np.shares_memory(np.frombuffer(buffer, dtype="<f8"), column)
