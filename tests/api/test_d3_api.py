"""GET/POST /discretizations/d3: bodies, branches, theorems, and every 422."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry.d3 import discretization as d3
from app.schemas.curve import CurveResponse
from tests.api.test_errors import problem


def test_default_curve_and_the_branch_down_is_the_d1_default(client: TestClient) -> None:
    response = client.get("/discretizations/d3")
    assert response.status_code == 200
    body = response.json()
    CurveResponse.model_validate(body)
    assert body["parameters"]["branch"] == "up"
    assert [c["id"] for c in body["checks"]] == [s.id for s in d3.STATEMENTS]
    assert all(c["holds"] for c in body["checks"])
    down = client.get("/discretizations/d3", params={"branch": "down"}).json()
    chain = client.get("/discretizations/d1").json()
    np.testing.assert_allclose(down["vertices"], chain["vertices"], rtol=1e-13)
    # up and down are the two roots at p_0: p_1 of one is p_{−1} of the other
    assert body["vertices"][11] == pytest.approx([0.2, down["vertices"][9][1]], rel=1e-15)


def test_constants_of_the_implied_conditions(client: TestClient) -> None:
    body = client.get("/discretizations/d3", params={"c": 2.0, "delta": 1.0, "y0": 5.0}).json()
    assert {k: float(v) for k, v in body["constants"].items()} == pytest.approx(
        {"d3": 2.0, "d1": 0.25, "eq2": 0.125, "equilibrium": 0.25}, rel=1e-12
    )


def test_theorem_d3_defaults_to_the_d3_discretization(client: TestClient) -> None:
    body = client.get("/theorems/d3").json()
    assert body["discretization"] == "d3" and body["check"]["holds"] is True
    listed = {s["id"]: s for s in client.get("/theorems").json()}
    assert listed["d3"]["discretizations"][0] == "d3"
    assert {"d1", "d3", "d4a", "d2a-quad"} <= set(listed["d3"]["discretizations"])


@pytest.mark.parametrize(
    ("query", "parameter", "constraint"),
    [
        ("c=0", "c", "c > 0"),
        ("delta=0", "delta", "delta > 0"),
        ("delta=2", "delta", "0 < delta < 2c"),
        ("c=0.5&delta=1.5", "delta", "0 < delta < 2c"),
        ("y0=0.5", "y0", "y0 >= √(c² − delta²/4)"),
        ("y0=-3", "y0", "y0 >= √(c² − delta²/4)"),
        ("branch=left", "branch", "branch is one of"),
        ("delta=1.9&i_max=300", "i_max", "in float64"),
        ("i_min=1&i_max=0", "i_max", "i_min <= i_max"),
    ],
)
def test_bad_query_is_a_422_naming_the_parameter(
    client: TestClient, query: str, parameter: str, constraint: str
) -> None:
    body = problem(client.get(f"/discretizations/d3?{query}"), 422)
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body
