"""GET/POST /discretizations/d2b: bodies, custom sequences, errors."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry.d2b import discretization as d2b
from app.geometry.precision import Float64
from app.schemas.curve import CurveResponse


def test_default_curve_matches_the_core_and_the_schema(client: TestClient) -> None:
    response = client.get("/discretizations/d2b")
    assert response.status_code == 200
    body = response.json()
    CurveResponse.model_validate(body)
    assert body["parameters"] == {"sequence": "example-12", "j": 5, "i_min": 0, "i_max": 10}
    core = d2b.compute(Float64(), "example-12", 5, None, 0, 10)
    np.testing.assert_array_equal(np.array(body["vertices"]), core.polygon.vertices)
    assert body["vertices"][0] == [0.0, 1.0]
    assert body["companions"]["gauss_image"]["vertices"][0] == [0.0, 1.0]
    assert all(c["holds"] is not False for c in body["checks"])
    theorem = next(c for c in body["checks"] if c["id"] == "theorem-11")
    assert theorem["holds"] is True and "observed order" in theorem["note"]


def test_custom_sequence_by_post_and_by_comma_separated_get(client: TestClient) -> None:
    values = [-0.4, 0.0, 0.25, 0.5, 0.75]
    posted = client.post(
        "/discretizations/d2b", json={"sequence": "custom", "s": values, "i_min": -1}
    )
    assert posted.status_code == 200, posted.text
    body = posted.json()
    assert body["indices"] == [-1, 0, 1, 2, 3]
    assert body["parameters"]["s"] == values
    got = client.get("/discretizations/d2b?sequence=custom&i_min=-1&s=-0.4,0,0.25,0.5,0.75")
    assert got.json() == body
    lemma = next(c for c in body["checks"] if c["id"] == "lemma-10")
    assert lemma["erratum"]["id"] == "E64" and lemma["erratum"]["printed_residual"] > 0.1


def test_mp_returns_decimal_strings(client: TestClient) -> None:
    body = client.get("/discretizations/d2b?precision=mp&digits=40&j=2&i_max=3").json()
    x, y = body["vertices"][1]
    # p_1^y = 1/√(1 − s_1²), s_1 = 4/8 = 1/2: 2/√3
    import mpmath

    mpmath.mp.dps = 50
    assert abs(mpmath.mpf(y) - 2 / mpmath.sqrt(3)) < mpmath.mpf("1e-38")
    assert isinstance(x, str)


@pytest.mark.parametrize(
    ("query", "parameter", "constraint"),
    [
        ("sequence=example-12&i_min=-2", "i_min", "i_min >= 0 for sequence=example-12"),
        ("sequence=remark-13&j=4&i_min=-2", "i_min", "i_min > −j/2"),
        ("j=0", "j", "j >= 1"),
        ("sequence=custom", "s", "required for sequence=custom"),
        ("sequence=custom&s=0", "s", "at least two values"),
        ("sequence=custom&s=0,0.5,0.4", "s", "strictly increasing"),
        ("sequence=custom&s=0,1.5", "s", "|s_i| < 1"),
        ("sequence=custom&s=0.1,0.5", "s", "s_0 = 0"),
        ("sequence=custom&s=0,abc", "s.1", "number"),
        ("sequence=custom&s=0,0.5&j=3", "j", "not used with sequence=custom"),
        ("s=0,0.5", "s", "only used with sequence=custom"),
        ("sequence=custom&s=0,0.5&i_max=7", "i_max", "i_max = i_min + len(s) − 1"),
        ("sequence=fibonacci", "sequence", "sequence is one of"),
        ("sequence=custom&s=0,nan", "s.1", "finite"),
    ],
)
def test_bad_input_is_a_422(
    client: TestClient, query: str, parameter: str, constraint: str
) -> None:
    response = client.get(f"/discretizations/d2b?{query}")
    assert response.status_code == 422, response.text
    assert response.headers["content-type"] == "application/problem+json"
    named = {e["parameter"]: e["constraint"] for e in response.json()["errors"]}
    assert parameter in named, named
    assert constraint in named[parameter], named


def test_too_long_custom_sequence_is_refused(client: TestClient) -> None:
    values = [0.0] + [k / 200_002 for k in range(1, 100_001)]
    response = client.post("/discretizations/d2b", json={"sequence": "custom", "s": values})
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == "s"


def test_theorem_endpoint_checks_d2b_statements(client: TestClient) -> None:
    body = client.get("/theorems/theorem-11?discretization=d2b&sequence=remark-13&j=12").json()
    assert body["discretization"] == "d2b" and body["check"]["holds"] is True
    body = client.get("/theorems/equation-17?discretization=d2b").json()
    assert body["check"]["holds"] is True
