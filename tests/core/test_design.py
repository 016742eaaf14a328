"""The design report and its warnings."""

from __future__ import annotations

import numpy as np
import pytest

from pma_core.design import Design, design_report
from pma_core.materials import MATERIALS, NYLON

PAPER = Design(0.25e-3, 240, 3, 0.031, 500e3, 3e9, 0.4, 75e6, strand_length_m=None)


def _codes(design: Design) -> list[str]:
    return [w.code for w in design_report(design).warnings]


def test_paper_braid_at_500_kpa_is_safe_and_closed() -> None:
    r = design_report(PAPER)
    assert np.degrees(r.min_braid_angle_rad) == pytest.approx(19.0, abs=0.05)
    assert (r.failure_strand_count, r.worst_case_failure_strand_count) == (97, 103)
    assert r.max_gap_area_m2 * 1e6 == pytest.approx(0.22, abs=0.005)
    assert r.max_length_m is None
    assert r.warnings == ()


def test_lengths_when_strand_length_is_given() -> None:
    r = design_report(Design(0.25e-3, 240, 3, 0.031, 200e3, 3e9, 0.4, 75e6, strand_length_m=0.65))
    assert r.max_length_m == pytest.approx(0.65 * np.cos(r.min_braid_angle_rad))
    assert r.stroke_m == pytest.approx(r.max_length_m - 0.65 / np.sqrt(3))


def test_warns_below_the_failure_count() -> None:
    design = Design(0.25e-3, 90, 3, 0.031, 500e3, 3e9, 0.4, 75e6)
    report = design_report(design)
    assert _codes(design) == ["below_failure_count", "gap_admits_bladder"]
    assert "fewer than the 97 needed" in report.warnings[0].message


def test_warns_between_full_contraction_and_worst_case() -> None:
    design = Design(0.25e-3, 100, 2, 0.031, 500e3, 3e9, 0.4, 75e6)
    assert _codes(design)[0] == "below_worst_case_failure_count"


def test_warns_when_the_gap_admits_the_bladder() -> None:
    assert "gap_admits_bladder" in _codes(Design(0.25e-3, 120, 3, 0.031, 200e3, 3e9, 0.4, 75e6))


def test_warns_when_the_braid_jams_before_the_neutral_angle() -> None:
    report = design_report(Design(0.25e-3, 384, 3, 0.031, 200e3, 3e9, 0.4, 75e6))
    assert [w.code for w in report.warnings] == ["jams_before_neutral_angle"]
    assert "jams at 49.8°" in report.warnings[0].message


def test_warns_when_strands_do_not_split_into_paths() -> None:
    assert _codes(Design(0.25e-3, 241, 3, 0.031, 200e3, 3e9, 0.4, 75e6)) == [
        "strand_count_not_braidable"
    ]


def test_measured_s_scale_is_reported_beside_eq_34() -> None:
    r = design_report(Design(0.25e-3, 240, 3, 0.031, 200e3, 3e9, 0.4, 75e6, s_scale=20.0))
    assert r.s_scale == 20.0
    assert r.s_scale_computed == pytest.approx(18.1, abs=0.05)


def test_refuses_braid_that_cannot_exist() -> None:
    with pytest.raises(ValueError, match="cannot fit around a 10 mm braid"):
        design_report(Design(0.25e-3, 240, 3, 0.010, 200e3, 3e9, 0.4, 75e6))


def test_material_presets_are_sourced_and_nylon_is_the_papers() -> None:
    assert (NYLON.youngs_modulus_pa, NYLON.poisson_ratio) == (3e9, 0.4)
    assert (NYLON.tensile_strength_pa, NYLON.friction_coefficient) == (75e6, 0.2)
    fields = {"youngs_modulus_pa", "poisson_ratio", "tensile_strength_pa", "friction_coefficient"}
    for material in MATERIALS.values():
        assert set(material.sources) == fields, material.id
        assert 0 <= material.poisson_ratio < 0.5
