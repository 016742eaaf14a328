# PMA calculator: container image of the FastAPI service (`python -m app`).
#
#   docker build -t pma-calculator .
#   docker run --rm -p 8000:8000 pma-calculator
#
# BASE must be a Debian-like image that has python3 (>= 3.11) with the venv module; the
# default is the official slim image. CI builds with a Debian-built base instead
# (debootstrap bookworm + python3, python3-venv, python3-pip), where only `python3`
# exists: the venv is therefore created with `python3`, and since /opt/venv/bin comes
# first on PATH, every later `python` / `pip` is the venv's own with either base.
# Both stages use the same BASE on purpose: the venv's interpreter is a symlink to the
# base image's python3, so the venv is only valid on the image it was built on.
ARG BASE=python:3.11-slim-bookworm

# ---------------------------------------------------------------------------- build
FROM ${BASE} AS build

# PYTHONSAFEPATH: `python -c` / `python -m` do not put the working directory on sys.path,
# so the checks below import the installed wheel, never the source tree in /src.
ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PYTHONSAFEPATH=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1 \
    PIP_NO_CACHE_DIR=1 \
    VIRTUAL_ENV=/opt/venv \
    PATH=/opt/venv/bin:${PATH}

RUN python3 -m venv /opt/venv

WORKDIR /src

# Dependencies first, read from the project's own pyproject.toml (no second list to
# keep in sync), so that this layer is rebuilt only when pyproject.toml changes.
# constraints.txt pins them to the versions the tests passed with.
COPY pyproject.toml constraints.txt ./
RUN python -c "import tomllib; deps = tomllib.load(open('pyproject.toml', 'rb'))['project']['dependencies']; open('/tmp/requirements.txt', 'w').write('\n'.join(deps) + '\n')" \
    && pip install --no-cache-dir --constraint constraints.txt --requirement /tmp/requirements.txt

# Then the project itself: pip builds its wheel with the pyproject's build backend
# (hatchling, which also force-includes static/ as app/static) and installs it.
# .dockerignore keeps the build context to the files the wheel is made of.
# Last, pip and setuptools leave the venv: the service never needs them at run time,
# and they are 23 MB that image scanners would report on.
COPY . .
RUN pip install --no-cache-dir --no-deps . \
    && pip check \
    && python -c "import importlib.resources as res, app.cli, pma_core; assert res.files('app').joinpath('static').is_dir(), 'static/ missing from the wheel'" \
    && pip uninstall --yes pip setuptools

# -------------------------------------------------------------------------- runtime
FROM ${BASE}

LABEL org.opencontainers.image.title="pma-calculator" \
      org.opencontainers.image.description="Braided pneumatic muscle actuator calculator (Davis & Caldwell 2006): web page and HTTP API" \
      org.opencontainers.image.licenses="MIT"

# PMA_* are read by app/settings.py; the container listens on all interfaces.
# PYTHONSAFEPATH: the working directory never shadows the installed packages.
ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PYTHONSAFEPATH=1 \
    VIRTUAL_ENV=/opt/venv \
    PATH=/opt/venv/bin:${PATH} \
    PMA_HOST=0.0.0.0 \
    PMA_PORT=8000 \
    PMA_WORKERS=1 \
    PMA_LOG_LEVEL=info \
    PMA_CORS_ORIGINS="" \
    PMA_ROOT_PATH=""

# An unprivileged user with a fixed numeric id (Kubernetes runAsNonRoot can verify it).
# --no-log-init: a high uid would otherwise grow /var/log/lastlog and faillog to GBs.
RUN groupadd --gid 10001 pma \
    && useradd --uid 10001 --gid 10001 --no-create-home --no-log-init \
       --home-dir /nonexistent --shell /usr/sbin/nologin pma

# Only the venv crosses over: no compiler, no pip cache, no source tree. It stays
# owned by root, so the service cannot modify its own code.
COPY --from=build /opt/venv /opt/venv

WORKDIR /srv
USER 10001:10001
EXPOSE 8000

# Exit status 0 only on HTTP 2xx from /healthz (urlopen raises on errors and refusals).
HEALTHCHECK --interval=30s --timeout=5s --start-period=15s --retries=3 \
    CMD ["python", "-c", "import os, urllib.request; urllib.request.urlopen('http://127.0.0.1:%s/healthz' % os.environ.get('PMA_PORT', '8000'), timeout=4)"]

CMD ["python", "-m", "app"]
