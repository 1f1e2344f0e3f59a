"""GET/POST /discretizations/d4a: bodies, companions, errata, theorems, and every 422."""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry.d4a import discretization as d4a
from app.geometry.precision import Float64
from app.schemas.curve import CurveResponse
from tests.api.test_errors import problem


def test_default_curve_matches_the_core_and_the_schema(client: TestClient) -> None:
    body = client.get("/discretizations/d4a").json()
    CurveResponse.model_validate(body)
    assert body["parameters"] == {
        "h": 1.0,
        "s": 0.1,
        "beta0": math.pi / 2,
        "i_min": -10,
        "i_max": 10,
        "method": "construction",
    }
    core = d4a.compute(Float64())
    np.testing.assert_array_equal(np.array(body["vertices"]), core.polygon.vertices)
    assert set(body["companions"]) == {"tractrix", "axis_points", "darboux"}
    assert body["companions"]["tractrix"]["vertices"][10] == [0.0, 1.0]  # d_0 = (0, h)
    checks = {c["id"]: c for c in body["checks"]}
    assert [c["id"] for c in body["checks"]] == [s.id for s in d4a.STATEMENTS]
    assert {k for k, c in checks.items() if not c["holds"]} == {
        "d1",
        "d3",
        "equation-2",
        "hanging-sticks",
    }
    erratum = checks["darboux-d4a-distance"]["erratum"]
    assert erratum["id"] == "E21" and erratum["link"] == "/errata/E21"
    assert erratum["printed_residual"] > 1e6 * checks["darboux-d4a-distance"]["tolerance"]


def test_csv_and_closed_form(client: TestClient) -> None:
    text = client.get("/discretizations/d4a", params={"format": "csv", "i_min": 0, "i_max": 1}).text
    rows = list(csv.DictReader(io.StringIO(text)))
    assert [r["curve"] for r in rows] == [
        "p",
        "p",
        "tractrix",
        "tractrix",
        "axis_points",
        "axis_points",
        "darboux",
        "darboux",
    ]
    body = client.get(
        "/discretizations/d4a",
        params={"method": "closed-form", "i_min": -3000, "i_max": 3000, "s": 0.01},
    ).json()
    assert len(body["vertices"]) == 6001
    checks = {c["id"]: c for c in body["checks"]}
    assert checks["d4a-closed-form"]["holds"] is None
    assert checks["rotation-centre-d4a"]["holds"] is True


def test_theorem_rotation_centre_with_a_tilted_start(client: TestClient) -> None:
    body = client.get(
        "/theorems/rotation-centre-d4a", params={"beta0": 0.7, "s": 0.3, "detail": True}
    ).json()
    assert body["discretization"] == "d4a" and body["check"]["holds"] is True
    assert len(body["check"]["per_index"]["indices"]) == 21


@pytest.mark.parametrize(
    ("query", "parameter", "constraint"),
    [
        ("h=0", "h", "h > 0"),
        ("s=0", "s", "s > 0"),
        ("s=1", "s", "0 < s < h"),
        ("s=2&h=1.5", "s", "0 < s < h"),
        ("beta0=0", "beta0", "beta0 > 0"),
        ("beta0=3.2", "beta0", "beta0 < 3.14159"),
        ("s=0.0001", "s", "s/h >= 0.001 in float64"),
        ("s=1e-28&precision=mp&digits=30", "s", "s/h >= 1e-15 with digits=30"),
        ("s=0.5&i_max=700", "i_max", "in float64"),
        ("d=0.1", "d", "not a parameter of this endpoint"),
        ("i_min=3&i_max=2", "i_max", "i_min <= i_max"),
    ],
)
def test_bad_query_is_a_422_naming_the_parameter(
    client: TestClient, query: str, parameter: str, constraint: str
) -> None:
    body = problem(client.get(f"/discretizations/d4a?{query}"), 422)
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body


def test_a_step_at_the_mp_resolution_is_answered_at_once(client: TestClient) -> None:
    # the cusp lies ~10^32 sticks from stick 0; finding it walked a float64 rounding error of
    # ~10^16 sticks one by one, and the request never returned
    response = client.get(
        "/discretizations/d4a?s=1e-30&beta0=1e-50&precision=mp&digits=60&i_min=-2&i_max=2"
    )
    assert response.status_code == 200, response.text
    checks = {c["id"]: c["holds"] for c in response.json()["checks"]}
    assert checks["d4a-sticks"] is True and checks["d4a-closed-form"] is True
