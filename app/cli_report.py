"""``pma-calculator report``: the full design report of one actuator, as a table or JSON."""

from __future__ import annotations

import argparse
import json
import sys
import types
import typing
from pathlib import Path
from typing import Any

from fastapi.exceptions import RequestValidationError
from pydantic import ValidationError

from app.report import design_json
from app.schemas import DesignIn

# (label, JSON key, unit, scale from SI to the shown unit, format)
_ROWS: tuple[tuple[str, str, str, float, str], ...] = (
    ("theoretical diameter D_o", "theoretical_diameter_m", "mm", 1e3, ".3f"),
    ("minimum braid angle θ_min (eq 8)", "min_braid_angle_deg", "°", 1.0, ".2f"),
    ("jamming angle 90° − θ_min", "jamming_angle_deg", "°", 1.0, ".2f"),
    ("maximum braid angle θ_max", "max_braid_angle_deg", "°", 1.0, ".2f"),
    ("maximum contraction", "max_contraction", "%", 100.0, ".2f"),
    ("maximum length L_max (eq 9)", "max_length_m", "mm", 1e3, ".1f"),
    ("minimum length L_min", "min_length_m", "mm", 1e3, ".1f"),
    ("stroke", "stroke_m", "mm", 1e3, ".1f"),
    ("peak static force (eq 10)", "peak_static_force_n", "N", 1.0, ".1f"),
    ("maximum gap width at 45° (eq 14)", "max_gap_width_m", "mm", 1e3, ".3f"),
    ("maximum gap area at 45° (eq 15)", "max_gap_area_m2", "mm²", 1e6, ".3f"),
    ("strand stress at 45° (eq 17)", "worst_case_strand_stress_pa", "MPa", 1e-6, ".1f"),
    ("S_scale used", "s_scale", "-", 1.0, ".2f"),
    ("S_scale of eq 34", "s_scale_computed", "-", 1.0, ".2f"),
)


def add_report_parser(commands: Any) -> None:
    """Add the ``report`` sub-command, one flag per field of ``POST /api/v1/design``."""
    report = commands.add_parser(
        "report",
        help="print the design report of one actuator",
        description="Design report (every quantity and its warnings) for one actuator. Give"
        " the design as flags, as a JSON file (--json FILE, or - for stdin) with the fields"
        " of POST /api/v1/design, or both: flags override the file.",
    )
    report.add_argument("--json", dest="json_file", metavar="FILE", help="design as JSON")
    report.add_argument("--format", choices=("table", "json"), default="table")
    for name, info in DesignIn.model_fields.items():
        report.add_argument(
            "--" + name.replace("_", "-"),
            dest=name,
            type=_flag_type(info.annotation),
            help=info.description,
        )
    report.set_defaults(handler=run_report)


def _flag_type(annotation: Any) -> type:
    if isinstance(annotation, types.UnionType) or typing.get_origin(annotation) is typing.Union:
        annotation = next(a for a in typing.get_args(annotation) if a is not type(None))
    base = typing.get_args(annotation)[0] if typing.get_origin(annotation) else annotation
    return base if base in (int, float, str) else str


def run_report(args: argparse.Namespace) -> int:
    """Print the report; exit status 2 with the field's message when the design is refused."""
    body: dict[str, Any] = _read_json(args.json_file) if args.json_file else {}
    body.update(
        {
            name: getattr(args, name)
            for name in DesignIn.model_fields
            if getattr(args, name) is not None
        }
    )
    try:
        result = design_json(DesignIn.model_validate(body))
    except (ValidationError, RequestValidationError) as error:
        for detail in error.errors():
            field = ".".join(str(part) for part in detail["loc"] if part != "body") or "design"
            message = str(detail["msg"])
            print(f"error: {_prefixed(field, message)}", file=sys.stderr)
        return 2
    print(json.dumps(result, indent=2) if args.format == "json" else format_table(result))
    return 0


def _prefixed(field: str, message: str) -> str:
    return message if message.startswith(field) else f"{field}: {message}"


def _read_json(path: str) -> dict[str, Any]:
    text = sys.stdin.read() if path == "-" else Path(path).read_text(encoding="utf-8")
    data = json.loads(text)
    if not isinstance(data, dict):
        raise SystemExit(f"error: {path}: the design must be a JSON object")
    return data


def format_table(result: dict[str, Any]) -> str:
    """The report as an aligned text table with units, then the warnings."""
    lines = []
    for label, key, unit, scale, fmt in _ROWS:
        value = result[key]
        shown = "—" if value is None else format(value * scale, fmt)
        lines.append(f"{label:<36} {shown:>12} {unit}")
    fail = result["failure_strand_count"]
    lines.append(f"{'fewest strands, fully contracted':<36} {fail['min_strand_count']:>12} (eq 20)")
    lines.append(
        f"{'fewest strands, 45° worst case':<36} {fail['worst_case_min_strand_count']:>12} (eq 20)"
    )
    warnings = result["warnings"]
    lines.append("")
    lines.extend(f"warning [{w['code']}]: {w['message']}" for w in warnings)
    if not warnings:
        lines.append("no warnings")
    return "\n".join(lines)
