# Two commands do all the set-up: `make run` and `make test` (see README.md).
SHELL := /bin/bash
# numba's on-disk cache of the compiled float64 kernels (app/geometry/compiled.py); not committed
export NUMBA_CACHE_DIR ?= $(CURDIR)/.numba-cache
PYTHON ?= $(shell command -v python3.11 2>/dev/null || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
HOST ?= 127.0.0.1
PORT ?= 8000
WORKERS ?= 1
PYTEST_ARGS ?=
# the whole suite takes 2-3 minutes here; a run still going after this many seconds has hung
TEST_TIME_LIMIT ?= 1500
VENDOR := app/static/vendor
CHROMIUM ?= /usr/bin/chromium
# root installs system packages directly; anyone else through sudo
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: run test lint openapi paper-map contract bench fuzz load install install-dev assets browser warm nginx clean

# The runtime install: a virtual environment with every package pinned in requirements/runtime.txt.
$(BIN)/.runtime-installed: requirements/runtime.txt pyproject.toml
	@$(PYTHON) -c 'import sys; assert sys.version_info[:2] == (3, 11), "Python 3.11 is required, found " + sys.version' 
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -r requirements/runtime.txt
	$(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps -e .
	touch $@

# The test install: the runtime set plus the pinned test and lint tools.
$(BIN)/.dev-installed: $(BIN)/.runtime-installed requirements/dev.txt
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -r requirements/dev.txt
	touch $@

install: $(BIN)/.runtime-installed
install-dev: $(BIN)/.dev-installed

# Every compiled kernel into the cache before the server or the tests start (2-3 s once; again
# when app/geometry changes), so that no request and no test worker compiles one. numba checks a
# cached kernel against its own file only, so the kernels of the modules that import a changed
# file go first (scripts/stale_kernels.py): they hold its code or constants compiled in.
$(NUMBA_CACHE_DIR)/.warm: $(BIN)/.runtime-installed $(shell find app/geometry -name '*.py')
	$(BIN)/python scripts/stale_kernels.py $?
	$(BIN)/python -m app.geometry.warm
	touch $@

warm: $(NUMBA_CACHE_DIR)/.warm

# The explorer's front-end files: three.js from the npm registry, pinned in package-lock.json,
# copied into app/static/vendor/ (not committed). Debian's nodejs and npm if node is missing.
$(VENDOR)/.built: package.json package-lock.json scripts/build-assets.mjs
	command -v npm >/dev/null 2>&1 || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq nodejs npm; }
	npm ci --no-audit --no-fund
	npm run build
	touch $@

assets: $(VENDOR)/.built

# The contract tools (tools/contract/package.json and its lock: Redocly CLI, openapi-typescript,
# TypeScript), kept apart from the explorer's packages.
CONTRACT := tools/contract
NPM_QUIET := REDOCLY_TELEMETRY=off REDOCLY_SUPPRESS_UPDATE_NOTICE=true NO_UPDATE_NOTIFIER=1
$(CONTRACT)/node_modules/.installed: $(CONTRACT)/package.json $(CONTRACT)/package-lock.json
	command -v npm >/dev/null 2>&1 || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq nodejs npm; }
	cd $(CONTRACT) && npm ci --no-audit --no-fund
	touch $@

# The OpenAPI document the app serves now: linted (no error allowed), turned into TypeScript
# types, and the typed client and the README's embedding snippet compiled with tsc --strict.
contract: $(BIN)/.runtime-installed $(CONTRACT)/node_modules/.installed
	mkdir -p $(CONTRACT)/build
	$(BIN)/python -m app.openapi_export $(CONTRACT)/build/openapi.json
	cd $(CONTRACT) && $(NPM_QUIET) npm run --silent lint && $(NPM_QUIET) npm run --silent types \
	  && npm run --silent tsc

# The browser tests drive Debian's Chromium (never a browser download of a test tool).
browser:
	test -x $(CHROMIUM) || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq chromium; }

# The deployment tests put Debian's nginx in front of two instances (tests/deploy/test_nginx.py).
nginx:
	command -v nginx >/dev/null 2>&1 || test -x /usr/sbin/nginx || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq nginx; }

# glibc malloc: few arenas and a fixed 128 KiB mmap threshold, so that the large numpy buffers
# of big requests go back to the system after each request; a trim threshold of 8 MiB keeps the
# 64 KiB block temporaries on the heap. Measured against larger thresholds (bench/malloc.py,
# make load; docs/performance.md): a 32 MiB mmap threshold is 1.5-5.5x faster on 10^5-vertex
# checks but keeps about 2x the memory under make load's concurrent traffic, so it is not used.
SERVER_ENV := MALLOC_ARENA_MAX=2 MALLOC_MMAP_THRESHOLD_=131072 MALLOC_TRIM_THRESHOLD_=8388608

# app/server.py starts WORKERS uvicorn workers, each on its own SO_REUSEPORT socket (the kernel
# spreads connections over them), with uvicorn's limits: h11 with a 64 KiB header block, 5 s
# keep-alive, a 25 s graceful shutdown, at most 1024 connections per worker (docs/reliability.md).
run: $(BIN)/.runtime-installed $(VENDOR)/.built warm
	$(SERVER_ENV) $(BIN)/python -m app.server --host $(HOST) --port $(PORT) --workers $(WORKERS)

test: $(BIN)/.dev-installed $(VENDOR)/.built browser warm contract nginx
	DCOSH_CHROMIUM=$(CHROMIUM) timeout -k 30 $(TEST_TIME_LIMIT) $(BIN)/python -m pytest -n auto $(PYTEST_ARGS)

lint: $(BIN)/.dev-installed
	$(BIN)/ruff check app tests bench examples
	$(BIN)/ruff format --check app tests bench examples
	$(BIN)/mypy app bench

openapi: $(BIN)/.runtime-installed
	$(BIN)/python -m app.openapi_export openapi/openapi.json

# docs/paper-map.md from the statement catalog and the source (a test fails on drift).
paper-map: $(BIN)/.runtime-installed
	$(BIN)/python scripts/paper_map.py docs/paper-map.md

# A long schema-fuzzing run: thousands of generated requests per operation, new ones each run;
# then the verdict property test (random valid parameters, both precisions) with many examples.
fuzz: $(BIN)/.dev-installed
	FUZZ_EXAMPLES=$${FUZZ_EXAMPLES:-1000} HYPOTHESIS_PROFILE=$${HYPOTHESIS_PROFILE:-random} \
	  $(BIN)/python -m pytest -q -n auto tests/api/test_fuzz.py
	PROPERTY_EXAMPLES=$${PROPERTY_EXAMPLES:-200} HYPOTHESIS_PROFILE=$${HYPOTHESIS_PROFILE:-random} \
	  $(BIN)/python -m pytest -q -n auto tests/geometry/test_verdicts_property.py

# A bounded load run on 127.0.0.1: errors, latency percentiles, server memory.
load: $(BIN)/.dev-installed warm
	$(BIN)/python bench/load.py

# Ratios measured side by side (docs/performance.md): kernels, constructions, D4b as served, mp,
# and HTTP on 127.0.0.1 with wrk (Debian's package, installed here when missing), in the
# server's malloc settings. Under five minutes.
bench: $(BIN)/.dev-installed warm
	command -v wrk >/dev/null 2>&1 || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq wrk; }
	$(SERVER_ENV) $(BIN)/python bench/run.py

clean:
	rm -rf $(VENV) $(NUMBA_CACHE_DIR) .pytest_cache .mypy_cache .ruff_cache node_modules $(VENDOR) test-output
