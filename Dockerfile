# The service image: the pinned install of `make run` (requirements/runtime.txt), the app run from
# its source tree (installed once: no second copy in site-packages), docs/ beside it (the errata
# pages read it), the limits and the graceful shutdown of `make run` (app/server.py), a non-root
# user. Build: docker build -t dcosh .   Run: docker run -p 8000:8000 -e WORKERS=2 dcosh
# (works with --read-only: nothing is written; the numba kernels compiled at build time are
# read from /srv/.numba-cache). Stop with at least 30 s of grace (docker stop -t 30,
# compose's stop_grace_period): uvicorn drains for up to 25 s after SIGTERM.
#
# Base images: tags by default, to be pinned by digest on a machine with registry access (none
# was verifiable where this file was written, and a digest is never written from memory):
#   docker buildx imagetools inspect python:3.11-slim-bookworm --format '{{json .Manifest.Digest}}'
#   docker buildx imagetools inspect node:24-bookworm-slim --format '{{json .Manifest.Digest}}'
# print each tag's multi-platform index digest ("sha256:<64 hex>"); then either pass them,
#   docker build --build-arg PYTHON_IMAGE=python:3.11-slim-bookworm@sha256:<64 hex> \
#                --build-arg NODE_IMAGE=node:24-bookworm-slim@sha256:<64 hex> .
# or write them into the two ARG defaults below (tests/deploy/test_dockerfile.py checks the form).
ARG PYTHON_IMAGE=python:3.11-slim-bookworm
# Node 24: the active LTS line (Node 20 reached its end of life in April 2026)
ARG NODE_IMAGE=node:24-bookworm-slim

# The explorer's three.js files: npm ci from the pinned lock file, then copied into
# app/static/vendor (what `make assets` does).
FROM ${NODE_IMAGE} AS assets
WORKDIR /build
COPY package.json package-lock.json ./
COPY scripts/build-assets.mjs scripts/
RUN npm ci --no-audit --no-fund && npm run build

FROM ${PYTHON_IMAGE}

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1 \
    VIRTUAL_ENV=/opt/venv \
    PATH=/opt/venv/bin:$PATH \
    PYTHONPATH=/srv \
    HOST=0.0.0.0 \
    PORT=8000 \
    WORKERS=2 \
    NUMBA_CACHE_DIR=/srv/.numba-cache \
    MALLOC_ARENA_MAX=2 \
    MALLOC_MMAP_THRESHOLD_=131072 \
    MALLOC_TRIM_THRESHOLD_=8388608

WORKDIR /srv
COPY requirements/runtime.txt requirements/runtime.txt
RUN python -m venv /opt/venv \
    && /opt/venv/bin/python -m pip install -r requirements/runtime.txt
COPY app ./app
COPY docs ./docs
COPY --from=assets /build/app/static/vendor ./app/static/vendor
RUN /opt/venv/bin/python -m compileall -q /opt/venv /srv/app \
    && /opt/venv/bin/python -m app.geometry.warm \
    && useradd --system --uid 10001 --no-create-home --shell /usr/sbin/nologin dcosh

USER 10001
EXPOSE 8000
STOPSIGNAL SIGTERM
HEALTHCHECK --interval=30s --timeout=3s --start-period=10s --retries=3 \
    CMD ["python", "-c", "import os, urllib.request; urllib.request.urlopen('http://127.0.0.1:' + os.environ['PORT'] + '/health', timeout=2)"]
# app.server (PID 1) starts $WORKERS uvicorn workers, each on its own SO_REUSEPORT socket, with
# the limits of `make run`, restarts a worker that dies and forwards SIGTERM to them
CMD ["python", "-m", "app.server"]
