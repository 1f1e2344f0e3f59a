"""Shared fixtures: a client on a fresh app, and the two precisions; Hypothesis profiles."""

from __future__ import annotations

import os

import pytest
from fastapi.testclient import TestClient
from hypothesis import settings

from app.geometry.precision import Float64, MultiPrecision
from app.main import create_app
from app.settings import Settings

# `make test` draws the same examples on every run and every machine, so that CI checks what was
# checked here; `make fuzz` (HYPOTHESIS_PROFILE=random) draws new ones each time.
settings.register_profile("deterministic", derandomize=True)
settings.register_profile("random", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "deterministic"))


@pytest.fixture
def client() -> TestClient:
    return TestClient(create_app(Settings()))


@pytest.fixture
def float64() -> Float64:
    return Float64()


@pytest.fixture
def mp40() -> MultiPrecision:
    return MultiPrecision(40)
