"""Fixtures of the API tests: an in-process client and request bodies built from the paper.

The numbers the paper prints come from ``davis_caldwell_2006`` (tests/conftest.py, typed in
from the paper). This file adds what the API tests also need, typed in from their source,
never imported from the code under test:

- ``davis_caldwell_2006_measured``: the paper's measurements (Table 1's measured column,
  the S_scale values fitted to its hysteresis tests and Tondu & Lopez's);
- ``model_md``: the numbers shared/design/MODEL.md derives where the paper leaves something
  open (exact values behind a rounded print, the neutral angle, the contraction gain).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.main import app
from tests.api.support import install_checks
from tests.published import DavisCaldwell2006


@dataclass(frozen=True)
class DavisCaldwell2006Measured:
    """What the paper measured, as printed (Table 1 and §3.3-3.4)."""

    # Table 1, "measured" column: N -> (mean θ_min [deg], standard deviation [deg]).
    min_braid_angle_measured_deg: dict[int, tuple[float, float]] = field(
        default_factory=lambda: {240: (18.9, 0.57), 160: (13.7, 1.16), 120: (9.6, 0.97)}
    )
    # §3.3: S_scale fitted to the test muscle's hysteresis, pressure [Pa] -> S_scale.
    s_scale_fitted: dict[float, float] = field(default_factory=lambda: {200e3: 20.0, 300e3: 16.0})
    # §3.3/3.4: Tondu & Lopez's S_scale, matching their data at 400 kPa.
    s_scale_tondu_lopez: float = 13.0
    s_scale_tondu_lopez_pressure_pa: float = 400e3
    # §3.4: eq 34 "match[es] the values obtained experimentally to better than 10%".
    s_scale_agreement: float = 0.10


@dataclass(frozen=True)
class ModelMd:
    """Numbers shared/design/MODEL.md states where the paper rounds or leaves a choice."""

    # θ_n = acos(1/√3), where the static force vanishes [deg].
    neutral_braid_angle_deg: float = 54.7356
    # ε_max = 1 - cos θ_max / cos θ_min at N = 240 and 120 (D_o 31 mm, D_s 0.25 mm), to 4 dp.
    max_contraction: dict[int, float] = field(default_factory=lambda: {240: 0.3893, 120: 0.4155})
    # Their relative change: the paper's "about 7 %".
    contraction_gain: float = 0.067
    # Eq 20 before rounding up: 96.64 at θ_n (the paper's 97) and 102.5 at 45° (103).
    failure_strand_count_exact: float = 96.64
    worst_case_failure_strand_count_exact: float = 102.5
    worst_case_braid_angle_deg: float = 45.0
    # Eq 34 at 400 kPa, which the paper prints truncated as 14.3.
    s_scale_400_kpa_exact: float = 14.39
    # Eq 10 peak forces at the exact θ_min of N 120 (8.97°) and N 240 (19.02°).
    peak_force_ratio_exact_angles: float = 1.146
    # Largest N that fits around the paper's braid: N·D_s < π·D_o (97.39 mm / 0.25 mm).
    strand_count_limit: int = 389
    # The stable warning codes of the design report (app/schemas.py WarningOut).
    warning_codes: frozenset[str] = frozenset(
        {
            "below_failure_count",
            "below_worst_case_failure_count",
            "gap_admits_bladder",
            "jams_before_neutral_angle",
            "strand_count_not_braidable",
        }
    )


@pytest.fixture(scope="session")
def client() -> Iterator[TestClient]:
    """The app in process; every response is checked by ``support.check_every_response``."""
    with TestClient(app) as test_client:
        yield install_checks(test_client)


@pytest.fixture(scope="session")
def davis_caldwell_2006_measured() -> DavisCaldwell2006Measured:
    return DavisCaldwell2006Measured()


@pytest.fixture(scope="session")
def model_md() -> ModelMd:
    return ModelMd()


@pytest.fixture
def paper_braid(davis_caldwell_2006: DavisCaldwell2006) -> dict[str, Any]:
    """The Table 1 braid (D_o 31 mm, D_s 0.25 mm, N 240) as a /min-braid-angle body."""
    p = davis_caldwell_2006
    return {
        "strand_diameter_m": p.strand_diameter_m,
        "strand_count": 240,
        "theoretical_diameter_m": p.theoretical_diameter_m,
    }


@pytest.fixture
def paper_gap(
    paper_braid: dict[str, Any], davis_caldwell_2006: DavisCaldwell2006
) -> dict[str, Any]:
    """The eq 15 braid: Table 1's with S = 3 parallel strands."""
    return {**paper_braid, "parallel_strands": davis_caldwell_2006.parallel_strands}


@pytest.fixture
def paper_failure(davis_caldwell_2006: DavisCaldwell2006) -> dict[str, Any]:
    """Eq 20's case: the Table 1 braid at 500 kPa, nylon σ_u = 75 MPa."""
    p = davis_caldwell_2006
    return {
        "pressure_pa": p.failure_pressure_pa,
        "strand_diameter_m": p.strand_diameter_m,
        "tensile_strength_pa": p.tensile_strength_pa,
        "theoretical_diameter_m": p.theoretical_diameter_m,
    }


@pytest.fixture
def paper_contact(davis_caldwell_2006: DavisCaldwell2006) -> dict[str, Any]:
    """Eq 34's case at 200 kPa: nylon strands of 0.25 mm."""
    p = davis_caldwell_2006
    return {
        "strand_diameter_m": p.strand_diameter_m,
        "pressure_pa": 200e3,
        "youngs_modulus_pa": p.youngs_modulus_pa,
        "poisson_ratio": p.poisson_ratio,
    }


@pytest.fixture
def paper_muscle(davis_caldwell_2006: DavisCaldwell2006) -> dict[str, Any]:
    """The §3.3 test muscle at 200 kPa (b 0.65 m, n 4.7, N 240, f_s 0.2)."""
    p = davis_caldwell_2006
    return {
        "strand_length_m": p.strand_length_m,
        "turns": p.turns,
        "strand_diameter_m": p.strand_diameter_m,
        "strand_count": 240,
        "pressure_pa": 200e3,
        "friction_coefficient": p.friction_coefficient,
        "youngs_modulus_pa": p.youngs_modulus_pa,
        "poisson_ratio": p.poisson_ratio,
    }


@pytest.fixture
def paper_design(
    paper_gap: dict[str, Any], davis_caldwell_2006: DavisCaldwell2006
) -> dict[str, Any]:
    """The eq 15 braid at eq 20's 500 kPa, nylon properties given one by one."""
    p = davis_caldwell_2006
    return {
        **paper_gap,
        "pressure_pa": p.failure_pressure_pa,
        "youngs_modulus_pa": p.youngs_modulus_pa,
        "poisson_ratio": p.poisson_ratio,
        "tensile_strength_pa": p.tensile_strength_pa,
        "friction_coefficient": p.friction_coefficient,
    }


@pytest.fixture
def strand_sweep(paper_gap: dict[str, Any]) -> dict[str, Any]:
    """N from 60 to 300 on the eq 15 braid."""
    body = {k: v for k, v in paper_gap.items() if k != "strand_count"}
    return {**body, "strand_count_min": 60, "strand_count_max": 300}


@pytest.fixture
def pressure_sweep(davis_caldwell_2006: DavisCaldwell2006) -> dict[str, Any]:
    """100 to 500 kPa in 100 kPa steps on the Table 1 braid, nylon."""
    p = davis_caldwell_2006
    return {
        "strand_diameter_m": p.strand_diameter_m,
        "theoretical_diameter_m": p.theoretical_diameter_m,
        "tensile_strength_pa": p.tensile_strength_pa,
        "youngs_modulus_pa": p.youngs_modulus_pa,
        "poisson_ratio": p.poisson_ratio,
        "pressure_min_pa": 100e3,
        "pressure_max_pa": 500e3,
        "points": 5,
    }


@pytest.fixture
def opensim_export(paper_muscle: dict[str, Any]) -> dict[str, Any]:
    """The §3.3 test muscle's braid as an OpenSim McKibbenActuator."""
    names = ("strand_length_m", "turns", "strand_diameter_m", "strand_count")
    return {name: paper_muscle[name] for name in names}


@pytest.fixture
def hysteresis_sweep(paper_muscle: dict[str, Any]) -> dict[str, Any]:
    """The §3.3 test muscle at 100, 300 and 500 kPa."""
    body = {k: v for k, v in paper_muscle.items() if k not in ("pressure_pa", "s_scale")}
    return {**body, "pressures_pa": [100e3, 300e3, 500e3]}


@pytest.fixture
def valid_bodies(
    paper_braid: dict[str, Any],
    paper_gap: dict[str, Any],
    paper_failure: dict[str, Any],
    paper_contact: dict[str, Any],
    paper_muscle: dict[str, Any],
    paper_design: dict[str, Any],
    strand_sweep: dict[str, Any],
    pressure_sweep: dict[str, Any],
    opensim_export: dict[str, Any],
    hysteresis_sweep: dict[str, Any],
) -> dict[str, dict[str, Any]]:
    """A body each POST endpoint accepts, by path."""
    return {
        "/api/v1/min-braid-angle": paper_braid,
        "/api/v1/gap-area": paper_gap,
        "/api/v1/failure-strand-count": paper_failure,
        "/api/v1/s-scale": paper_contact,
        "/api/v1/hysteresis": paper_muscle,
        "/api/v1/design": paper_design,
        "/api/v1/sweeps/strand-count": strand_sweep,
        "/api/v1/sweeps/pressure": pressure_sweep,
        "/api/v1/export/opensim": opensim_export,
        "/api/v1/sweeps/hysteresis": hysteresis_sweep,
    }
