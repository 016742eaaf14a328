"""The pma-calculator command: report and serve's configuration."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.cli import build_parser, main
from app.settings import Settings

FLAGS = [
    "report",
    "--theoretical-diameter-m",
    "0.031",
    "--strand-diameter-m",
    "0.00025",
    "--strand-count",
    "120",
    "--parallel-strands",
    "3",
    "--pressure-pa",
    "500000",
    "--material",
    "nylon",
]


def test_report_table(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(FLAGS) == 0
    out = capsys.readouterr().out
    assert "minimum braid angle θ_min (eq 8)             8.97 °" in out
    assert "fewest strands, fully contracted               97 (eq 20)" in out
    assert "fewest strands, 45° worst case                103 (eq 20)" in out
    assert "warning [gap_admits_bladder]" in out


def test_report_json_from_a_file_with_flag_override(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    design = tmp_path / "design.json"
    design.write_text(
        json.dumps(
            {
                "theoretical_diameter_m": 0.031,
                "strand_diameter_m": 0.00025,
                "strand_count": 120,
                "pressure_pa": 200000,
                "material": "nylon",
            }
        )
    )
    assert main(["report", "--json", str(design), "--strand-count", "240", "--format", "json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert round(result["min_braid_angle_deg"], 1) == 19.0
    assert round(result["s_scale"], 1) == 18.1


def test_report_refuses_an_impossible_design(capsys: pytest.CaptureFixture[str]) -> None:
    flags = [*FLAGS, "--theoretical-diameter-m", "0.01", "--strand-count", "240"]
    assert main(flags) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: strand_count: 240 strands of 0.25 mm cannot fit around a 10 mm")


def test_report_names_a_missing_field(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["report", "--strand-count", "240"]) == 2
    assert "error: strand_diameter_m: Field required" in capsys.readouterr().err


def test_serve_defaults_come_from_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PMA_PORT", "9123")
    monkeypatch.setenv("PMA_WORKERS", "3")
    monkeypatch.setenv("PMA_CORS_ORIGINS", "https://a.example, https://b.example")
    args = build_parser().parse_args(["serve"])
    assert (args.port, args.workers) == (9123, 3)
    assert Settings.from_env().cors_origins == ("https://a.example", "https://b.example")


@pytest.mark.parametrize(
    ("name", "value", "message"),
    [
        ("PMA_PORT", "eighty", "PMA_PORT='eighty' is not a whole number"),
        ("PMA_WORKERS", "0", "PMA_WORKERS=0 must be at least 1"),
        ("PMA_LOG_LEVEL", "loud", "PMA_LOG_LEVEL='loud' is not one of"),
    ],
)
def test_bad_settings_are_refused(
    monkeypatch: pytest.MonkeyPatch, name: str, value: str, message: str
) -> None:
    monkeypatch.setenv(name, value)
    with pytest.raises(ValueError, match=message):
        Settings.from_env()
