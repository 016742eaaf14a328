"""OpenSim export: McKibbenActuator's force law equals our static force (eq 10)."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import app

client = TestClient(app)
MUSCLE = {"strand_length_m": 0.65, "turns": 4.7, "strand_diameter_m": 0.00025, "strand_count": 240}


def _opensim_force(pressure_pa: float, length_m: np.ndarray, b: float, n: float) -> np.ndarray:
    # OpenSim's McKibbenActuator: F = P (3 L² − B²) / (4 π N²).
    return pressure_pa * (3 * length_m**2 - b**2) / (4 * np.pi * n**2)


def test_parameters_are_strand_length_and_turns() -> None:
    response = client.post("/api/v1/export/opensim", json=MUSCLE)
    assert response.status_code == 200
    body = response.json()
    assert (body["thread_length"], body["number_of_turns"], body["cord_length"]) == (0.65, 4.7, 0.0)
    assert "<thread_length>0.65</thread_length>" in body["xml"]
    assert "<number_of_turns>4.7</number_of_turns>" in body["xml"]
    assert body["min_length_m"] == pytest.approx(0.65 / np.sqrt(3))


def test_opensim_force_law_equals_the_static_force() -> None:
    exported = client.post("/api/v1/export/opensim", json=MUSCLE).json()
    curve = client.post(
        "/api/v1/hysteresis",
        json={
            **MUSCLE,
            "pressure_pa": 300_000.0,
            "friction_coefficient": 0.2,
            "youngs_modulus_pa": 3e9,
            "poisson_ratio": 0.4,
            "points": 51,
        },
    ).json()
    length = np.asarray(curve["length_m"])
    opensim = _opensim_force(
        300_000.0, length, exported["thread_length"], exported["number_of_turns"]
    )
    assert np.asarray(curve["force_static_n"]) == pytest.approx(opensim, rel=1e-9, abs=1e-9)


def test_needs_the_actuator_length() -> None:
    body = {"theoretical_diameter_m": 0.031, "strand_diameter_m": 0.00025, "strand_count": 240}
    response = client.post("/api/v1/export/opensim", json=body)
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["body", "strand_length_m"]


def test_refuses_a_name_that_is_not_an_identifier() -> None:
    response = client.post("/api/v1/export/opensim", json={**MUSCLE, "name": '"/><x'})
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["body", "name"]
