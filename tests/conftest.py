"""Shared fixtures: a client on a fresh app, and the two precisions."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app.geometry.precision import Float64, MultiPrecision
from app.main import create_app
from app.settings import Settings


@pytest.fixture
def client() -> TestClient:
    return TestClient(create_app(Settings()))


@pytest.fixture
def float64() -> Float64:
    return Float64()


@pytest.fixture
def mp40() -> MultiPrecision:
    return MultiPrecision(40)
