# The service image: the same pinned install as `make run` (requirements/runtime.txt, then the
# package without dependencies), run by a non-root user. Build: docker build -t dcosh .
# Run: docker run -p 8000:8000 -e WORKERS=2 dcosh   (works with --read-only: nothing is written;
# the numba kernels compiled at build time are read from /srv/.numba-cache)
# The explorer's three.js files: npm ci from the pinned lock file, then copied into
# app/static/vendor (what `make assets` does).
FROM node:20-bookworm-slim AS assets
WORKDIR /build
COPY package.json package-lock.json ./
COPY scripts/build-assets.mjs scripts/
RUN npm ci --no-audit --no-fund && npm run build

FROM python:3.11-slim

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1 \
    VIRTUAL_ENV=/opt/venv \
    PATH=/opt/venv/bin:$PATH \
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
COPY pyproject.toml README.md ./
COPY app ./app
COPY --from=assets /build/app/static/vendor ./app/static/vendor
RUN /opt/venv/bin/python -m pip install --no-deps . \
    && /opt/venv/bin/python -m compileall -q /opt/venv /srv/app \
    && /opt/venv/bin/python -m app.geometry.warm \
    && useradd --system --uid 10001 --no-create-home --shell /usr/sbin/nologin dcosh

USER 10001
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=3s --start-period=10s --retries=3 \
    CMD ["python", "-c", "import os, urllib.request; urllib.request.urlopen('http://127.0.0.1:' + os.environ['PORT'] + '/health', timeout=2)"]
CMD ["sh", "-c", "exec uvicorn app.main:app --host \"$HOST\" --port \"$PORT\" --workers \"$WORKERS\""]
