"""The pinned dependencies (constraints.txt) carry no known advisory, by pip-audit.

Skipped, saying so, when pip-audit's vulnerability database cannot be reached.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

AUDIT = Path(sys.executable).with_name("pip-audit")
CONSTRAINTS = Path(__file__).resolve().parent.parent / "constraints.txt"


def test_installed_dependencies_have_no_known_vulnerability() -> None:
    if not AUDIT.exists():
        pytest.skip("pip-audit not installed: dependency audit skipped")
    result = subprocess.run(
        [
            str(AUDIT),
            *("--requirement", str(CONSTRAINTS), "--no-deps", "--disable-pip"),
            *("--format", "json", "--progress-spinner", "off"),
        ],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    try:
        report = json.loads(result.stdout)
    except json.JSONDecodeError:
        pytest.skip(f"pip-audit could not reach its database: {result.stderr.strip()[-300:]}")
    dependencies = report["dependencies"]
    audited = [d for d in dependencies if "skip_reason" not in d]
    if not audited:
        pytest.skip(
            "pip-audit's vulnerability database is unreachable: no package could be audited"
        )
    vulnerable = {d["name"]: [v["id"] for v in d["vulns"]] for d in audited if d["vulns"]}
    assert vulnerable == {}
