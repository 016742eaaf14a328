"""Build the container image from the Dockerfile with buildah, run it and talk to it.

No container registry is reachable from CI, so the base image is made from Debian's
own packages: ``debootstrap`` lays out a minimal bookworm with python3, python3-venv,
python3-pip and ca-certificates (cached under ``$PMA_CI_CACHE``, default
``/var/cache/pma-ci``), buildah imports it as ``localhost/pma-ci-base:…``, and the
Dockerfile is built on it with ``--build-arg BASE=…``. With ``PMA_CONTAINER_BASE`` set,
that image is used instead (e.g. ``docker.io/library/python:3.11-slim-bookworm`` where
a registry is reachable).

The container then runs under ``buildah run --isolation chroot --network host`` (podman
and the OCI runtimes cannot start containers in this sandbox) on a free port of
127.0.0.1, and the tests check ``/healthz``, one calculation, the HTML page, the image
configuration and the image's own HEALTHCHECK command.

Needs root, ``buildah`` and ``debootstrap`` (``.ci/container`` installs them). Where they
cannot run, the tests skip with the reason, unless ``PMA_CONTAINER_REQUIRED=1`` (set by
``.ci/container``), which turns that skip into a failure.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import urllib.error
import urllib.request
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NoReturn

import pytest

pytestmark = pytest.mark.container

ROOT = Path(__file__).resolve().parents[2]
CACHE = Path(os.environ.get("PMA_CI_CACHE", "/var/cache/pma-ci"))
MIRROR = os.environ.get("PMA_DEBIAN_MIRROR", "http://deb.debian.org/debian")
KEYRING = Path("/usr/share/keyrings/debian-archive-keyring.gpg")
SUITE = "bookworm"
BASE_PACKAGES = ("python3", "python3-venv", "python3-pip", "ca-certificates")
# Bump when the way the rootfs is made changes, to rebuild the cached one.
ROOTFS_RECIPE = f"{SUITE} minbase {' '.join(BASE_PACKAGES)} v1"
ROOTFS_KEY = hashlib.sha256(ROOTFS_RECIPE.encode()).hexdigest()[:12]
BASE_IMAGE = f"localhost/pma-ci-base:{SUITE}-{ROOTFS_KEY}"
IMAGE = "localhost/pma-calculator:test"
# The host's CA bundle: where outbound TLS is re-signed by a local CA, pip inside the
# build needs it. It is mounted for the RUN steps only (with a pip.conf naming it), never
# copied into the image, and nothing else of the host's pip configuration goes in.
HOST_CA_BUNDLE = Path("/etc/ssl/certs/ca-certificates.crt")
REQUIRED = os.environ.get("PMA_CONTAINER_REQUIRED", "") == "1"
KEEP_IMAGE = os.environ.get("PMA_KEEP_IMAGE", "") == "1"

DEBOOTSTRAP_TIMEOUT_S = 900
BUILD_TIMEOUT_S = 1200
START_TIMEOUT_S = 60
STOP_TIMEOUT_S = 20


@dataclass(frozen=True)
class Image:
    """The built image and its configuration as ``buildah inspect`` reports it."""

    name: str
    config: dict[str, Any]


@dataclass(frozen=True)
class Server:
    """A running container of the image, reachable on 127.0.0.1."""

    container: str
    port: int
    base_url: str


def _unavailable(reason: str) -> NoReturn:
    message = f"buildah not available: {reason}"
    if REQUIRED:
        pytest.fail(f"{message} (PMA_CONTAINER_REQUIRED=1)", pytrace=False)
    pytest.skip(message)


def _run(
    argv: Sequence[str], *, timeout: float = 120, check: bool = True
) -> subprocess.CompletedProcess[str]:
    result = subprocess.run(
        list(argv), capture_output=True, text=True, timeout=timeout, check=False
    )
    if check and result.returncode != 0:
        pytest.fail(
            f"{' '.join(argv)} exited {result.returncode}:\n{result.stdout[-4000:]}"
            f"\n{result.stderr[-4000:]}",
            pytrace=False,
        )
    return result


def _report(config: pytest.Config, line: str) -> None:
    """Print past pytest's output capture (timings are part of what CI should show)."""
    reporter = config.pluginmanager.get_plugin("terminalreporter")
    capture = config.pluginmanager.get_plugin("capturemanager")
    if reporter is None or capture is None:
        return
    with capture.global_and_fixture_disabled():
        reporter.write(f"\n[container] {line}\n")


def _check_tools() -> None:
    if os.geteuid() != 0:
        _unavailable("needs root (debootstrap, and buildah's chroot isolation and overlay)")
    for tool in ("buildah", "debootstrap"):
        if shutil.which(tool) is None:
            _unavailable(f"{tool} is not installed (apt-get install buildah debootstrap)")
    probe = _run(["buildah", "info"], check=False)
    if probe.returncode != 0:
        _unavailable(f"'buildah info' failed: {probe.stderr.strip()[-500:]}")
    scratch = _run(["buildah", "from", "scratch"], check=False)
    if scratch.returncode != 0:
        _unavailable(f"'buildah from scratch' failed: {scratch.stderr.strip()[-500:]}")
    container = scratch.stdout.strip()
    mounted = _run(["buildah", "mount", container], check=False)
    _run(["buildah", "rm", container], check=False)
    if mounted.returncode != 0:
        _unavailable(f"'buildah mount' failed: {mounted.stderr.strip()[-500:]}")


def _image_exists(name: str) -> bool:
    return _run(["buildah", "inspect", "--type", "image", name], check=False).returncode == 0


def _unmount_under(path: Path) -> None:
    """Unmount whatever a failed debootstrap left mounted inside ``path`` (proc, sys)."""
    prefix = str(path.resolve()) + "/"
    with open("/proc/self/mounts", encoding="utf-8") as mounts:
        targets = [line.split()[1] for line in mounts if line.split()[1].startswith(prefix)]
    for target in sorted(targets, key=len, reverse=True):
        subprocess.run(["umount", "--lazy", target], check=False, timeout=60)


def _debootstrap_rootfs(config: pytest.Config) -> Path:
    """A minimal bookworm with python3, cached; made once per machine (about a minute)."""
    rootfs = CACHE / f"rootfs-{ROOTFS_KEY}"
    if (rootfs / "usr/bin/python3").exists():
        return rootfs
    CACHE.mkdir(parents=True, exist_ok=True)
    scratch = Path(tempfile.mkdtemp(prefix="rootfs-tmp-", dir=CACHE))
    started = time.monotonic()
    try:
        argv = ["debootstrap", "--variant=minbase", f"--include={','.join(BASE_PACKAGES)}"]
        if KEYRING.exists():
            argv.append(f"--keyring={KEYRING}")
        _run([*argv, SUITE, str(scratch), MIRROR], timeout=DEBOOTSTRAP_TIMEOUT_S)
        # What official Debian images drop too: package caches and lists, the build
        # host's resolver. buildah provides /etc/resolv.conf and /etc/hosts at run time.
        _run(["chroot", str(scratch), "apt-get", "clean"])
        for leftover in (scratch / "var/lib/apt/lists").iterdir():
            if leftover.is_file():
                leftover.unlink()
        (scratch / "etc/resolv.conf").write_text("", encoding="utf-8")
        (scratch / "etc/hostname").write_text("localhost\n", encoding="utf-8")
        _unmount_under(scratch)
        try:
            scratch.rename(rootfs)
        except OSError:
            if not (rootfs / "usr/bin/python3").exists():  # not a concurrent run's win
                raise
    finally:
        if scratch.exists():
            _unmount_under(scratch)
            shutil.rmtree(scratch, ignore_errors=True)
    _report(config, f"debootstrap {SUITE} rootfs: {time.monotonic() - started:.1f} s")
    return rootfs


def _base_image(config: pytest.Config) -> str:
    override = os.environ.get("PMA_CONTAINER_BASE", "").strip()
    if override:
        return override
    if _image_exists(BASE_IMAGE):
        return BASE_IMAGE
    rootfs = _debootstrap_rootfs(config)
    started = time.monotonic()
    container = _run(["buildah", "from", "scratch"]).stdout.strip()
    try:
        mountpoint = _run(["buildah", "mount", container]).stdout.strip()
        _run(["cp", "-a", f"{rootfs}/.", f"{mountpoint}/"], timeout=600)
        _run(["buildah", "umount", container])
        _run(
            [
                "buildah", "config",
                "--env", "PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin",
                "--env", "LANG=C.UTF-8",
                "--cmd", "python3",
                container,
            ]
        )  # fmt: skip
        _run(["buildah", "commit", "--format", "docker", container, BASE_IMAGE], timeout=600)
    finally:
        _run(["buildah", "rm", container], check=False)
    _report(config, f"import rootfs as {BASE_IMAGE}: {time.monotonic() - started:.1f} s")
    return BASE_IMAGE


@pytest.fixture(scope="module")
def image(pytestconfig: pytest.Config, tmp_path_factory: pytest.TempPathFactory) -> Iterator[Image]:
    """Build ``pma-calculator:test`` from the repo's Dockerfile; remove it afterwards."""
    _check_tools()
    base = _base_image(pytestconfig)
    argv = [
        "buildah", "bud",
        "--isolation", "chroot",
        "--network", "host",
        "--format", "docker",  # OCI images have no HEALTHCHECK
        "--layers",  # reuse the dependency layer while pyproject.toml is unchanged
        "--pull=false",  # pull BASE only if it is not in local storage
        "--build-arg", f"BASE={base}",
        "--tag", IMAGE,
        "--file", str(ROOT / "Dockerfile"),
    ]  # fmt: skip
    work = tmp_path_factory.mktemp("buildah")
    if HOST_CA_BUNDLE.is_file():
        # Debian's pip reads the system bundle; a pip that carries its own (certifi, as
        # in the official python images) is pointed at it by this pip.conf.
        pip_conf = work / "pip.conf"
        pip_conf.write_text(f"[global]\ncert = {HOST_CA_BUNDLE}\n", encoding="utf-8")
        argv += [
            "--volume", f"{HOST_CA_BUNDLE}:{HOST_CA_BUNDLE}:ro",
            "--volume", f"{pip_conf}:/etc/pip.conf:ro",
        ]  # fmt: skip
    log = work / "build.log"
    started = time.monotonic()
    with log.open("w", encoding="utf-8") as out:
        built = subprocess.run(
            [*argv, str(ROOT)],
            stdout=out,
            stderr=subprocess.STDOUT,
            timeout=BUILD_TIMEOUT_S,
            check=False,
        )
    elapsed = time.monotonic() - started
    if built.returncode != 0:
        tail = log.read_text(encoding="utf-8", errors="replace")[-6000:]
        pytest.fail(f"buildah bud exited {built.returncode} ({log}):\n{tail}", pytrace=False)
    _report(pytestconfig, f"buildah bud {IMAGE} on {base}: {elapsed:.1f} s")
    inspected = json.loads(_run(["buildah", "inspect", "--type", "image", IMAGE]).stdout)
    try:
        yield Image(name=IMAGE, config=inspected["Docker"]["config"])
    finally:
        if not KEEP_IMAGE:
            _run(["buildah", "rmi", IMAGE], check=False)


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


def _get(url: str, timeout: float = 10) -> tuple[int, str, str]:
    with urllib.request.urlopen(url, timeout=timeout) as response:
        body = response.read().decode("utf-8")
        return response.status, response.headers.get("content-type", ""), body


def _post_json(url: str, payload: dict[str, Any]) -> tuple[int, Any]:
    request = urllib.request.Request(
        url,
        data=json.dumps(payload).encode("utf-8"),
        headers={"content-type": "application/json"},
        method="POST",
    )
    with urllib.request.urlopen(request, timeout=10) as response:
        return response.status, json.loads(response.read())


def _stop(process: subprocess.Popen[bytes]) -> None:
    """SIGTERM the session we started (buildah run and the server in it), then SIGKILL."""
    for sig in (signal.SIGTERM, signal.SIGKILL):
        if process.poll() is not None:
            return
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, sig)
        with contextlib.suppress(subprocess.TimeoutExpired):
            process.wait(timeout=STOP_TIMEOUT_S)


@pytest.fixture(scope="module")
def server(
    pytestconfig: pytest.Config, image: Image, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[Server]:
    """Run the image's own command (``python -m app``) on a free port of 127.0.0.1."""
    container = _run(["buildah", "from", "--pull=never", image.name]).stdout.strip()
    port = _free_port()
    log = tmp_path_factory.mktemp("server") / "server.log"
    base_url = f"http://127.0.0.1:{port}"
    started = time.monotonic()
    with log.open("wb") as out:
        process = subprocess.Popen(
            [
                "buildah", "run",
                "--isolation", "chroot",
                "--network", "host",
                "--env", f"PMA_PORT={port}",
                container, "--", *image.config["Cmd"],
            ],
            stdout=out,
            stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL,
            start_new_session=True,  # its own process group, stopped by its id below
        )  # fmt: skip
    try:
        deadline = started + START_TIMEOUT_S
        while True:
            if process.poll() is not None:
                output = log.read_text(encoding="utf-8", errors="replace")[-4000:]
                pytest.fail(f"the container exited {process.returncode}:\n{output}", pytrace=False)
            try:
                if _get(f"{base_url}/healthz", timeout=2)[0] == 200:
                    break
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                pass
            if time.monotonic() > deadline:
                output = log.read_text(encoding="utf-8", errors="replace")[-4000:]
                pytest.fail(f"no /healthz within {START_TIMEOUT_S} s:\n{output}", pytrace=False)
            time.sleep(0.25)
        up = time.monotonic() - started
        _report(pytestconfig, f"container up (first 200 from /healthz): {up:.1f} s")
        yield Server(container=container, port=port, base_url=base_url)
    finally:
        _stop(process)
        _run(["buildah", "rm", container], check=False)


def test_image_config_is_deployable(image: Image) -> None:
    config = image.config
    user = str(config.get("User", ""))
    uid = user.split(":", 1)[0]
    assert uid.isdigit(), f"USER must be numeric (runAsNonRoot checks it), got {user!r}"
    assert int(uid) != 0, "the image must not run as root"
    assert "8000/tcp" in (config.get("ExposedPorts") or {})
    healthcheck = config.get("Healthcheck") or {}
    test = healthcheck.get("Test") or []
    assert test[:1] == ["CMD"], f"HEALTHCHECK must be in exec (JSON) form: {test}"
    assert "/healthz" in " ".join(test)
    assert config.get("Cmd") == ["python", "-m", "app"]
    env = dict(item.split("=", 1) for item in config.get("Env") or [])
    assert env.get("PMA_HOST") == "0.0.0.0"
    assert env.get("PMA_PORT") == "8000"
    assert env.get("PATH", "").startswith("/opt/venv/bin:")


def test_healthz(server: Server) -> None:
    status, content_type, body = _get(f"{server.base_url}/healthz")
    assert status == 200
    assert "json" in content_type
    assert json.loads(body)["status"] == "ok"


def test_min_braid_angle(server: Server) -> None:
    status, result = _post_json(
        f"{server.base_url}/api/v1/min-braid-angle",
        {"strand_diameter_m": 0.00025, "strand_count": 240, "theoretical_diameter_m": 0.031},
    )
    assert status == 200
    assert round(result["min_braid_angle_deg"], 1) == 19.0


def test_page_is_served(server: Server) -> None:
    status, content_type, body = _get(f"{server.base_url}/")
    assert status == 200
    assert content_type.startswith("text/html")
    assert "<html" in body.lower()


def test_process_runs_unprivileged(server: Server) -> None:
    result = _run(
        ["buildah", "run", "--isolation", "chroot", server.container, "--",
         "python", "-c", "import os; print(os.getuid(), os.getgid())"]
    )  # fmt: skip
    assert result.stdout.split() == ["10001", "10001"]


def test_healthcheck_command(image: Image, server: Server) -> None:
    """The image's own HEALTHCHECK passes against the live server, fails on a dead port."""
    command = image.config["Healthcheck"]["Test"][1:]

    def probe(port: int) -> int:
        return _run(
            ["buildah", "run", "--isolation", "chroot", "--network", "host",
             "--env", f"PMA_PORT={port}", server.container, "--", *command],
            check=False,
        ).returncode  # fmt: skip

    assert probe(server.port) == 0
    assert probe(_free_port()) != 0
