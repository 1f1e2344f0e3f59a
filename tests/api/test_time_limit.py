"""The time limit: sequential constructions and mp operations stop past DCOSH_TIME_LIMIT."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app.geometry.d4b import discretization as d4b
from app.geometry.errors import TimeLimitError
from app.geometry.precision import Float64, MultiPrecision
from app.main import create_app
from app.settings import Settings


def test_a_long_construction_stops_with_a_422_naming_the_range() -> None:
    client = TestClient(create_app(Settings(time_limit=0.001)))
    response = client.get("/discretizations/d4b", params={"d": 1e-4, "i_min": 0, "i_max": 200000})
    assert response.status_code == 422
    (error,) = response.json()["errors"]
    assert error["parameter"] == "i_max"
    assert "within 0.001 s (DCOSH_TIME_LIMIT)" in error["constraint"]


def test_an_mp_computation_stops_with_a_422_naming_digits() -> None:
    client = TestClient(create_app(Settings(time_limit=0.001)))
    response = client.get(
        "/discretizations/d2a-quad", params={"precision": "mp", "digits": 300, "i_max": 200}
    )
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == "digits"


def test_within_the_limit_nothing_changes() -> None:
    client = TestClient(create_app(Settings(time_limit=60)))
    assert client.get("/discretizations/d4b", params={"i_max": 5000, "d": 0.001}).status_code == 200


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(20)], ids=["float64", "mp"])
def test_the_core_checks_the_clock_in_its_loops(ar: Float64 | MultiPrecision) -> None:
    ar.start_clock(-1.0, "i_max")  # already past
    with pytest.raises(TimeLimitError, match="i_max must satisfy the computation finishes"):
        d4b.compute(ar, 1.0, 0.001, None, 0, 5000)
