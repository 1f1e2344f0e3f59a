"""GET/POST /discretizations/d2a-quad and d2a-hex: bodies, the `lambda` alias, errors."""

from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry.d2a import hex as d2a_hex, quad as d2a_quad
from app.geometry.precision import Float64
from app.schemas.curve import CurveResponse


def test_default_quad_matches_the_core_and_the_schema(client: TestClient) -> None:
    body = client.get("/discretizations/d2a-quad").json()
    CurveResponse.model_validate(body)
    assert body["parameters"] == {"f0": 1.0, "f1": 1.5, "r": -6.0, "i_min": -10, "i_max": 10}
    core = d2a_quad.compute(Float64(), 1.0, 1.5, None, -10, 10)
    np.testing.assert_array_equal(np.array(body["vertices"]), core.polygon.vertices)
    assert body["vertices"][10] == [0.0, -6.0]  # p_0 = (0, r*)
    assert set(body["companions"]) == {"conformal", "gauss_image"}
    assert body["companions"]["conformal"]["vertices"][10] == [1.0, 0.0]
    assert body["companions"]["gauss_image"]["vertices"][10] == [0.0, 1.0]
    checks = {c["id"]: c for c in body["checks"]}
    assert checks["theorem-1"]["holds"] is True and checks["d1"]["holds"] is False
    assert checks["theorem-1"]["erratum"]["id"] == "E42"
    assert body["constants"]["eq2"] == pytest.approx(0.032, rel=1e-12)


def test_hex_lambda_alias_in_get_post_and_catalog(client: TestClient) -> None:
    params = {"a": 1.3, "b": 2.1, "lambda": 0.3, "i_min": -4, "i_max": 5}
    got = client.get("/discretizations/d2a-hex", params=params)
    assert got.status_code == 200
    body = got.json()
    CurveResponse.model_validate(body)
    assert body["parameters"]["lambda"] == 0.3
    core = d2a_hex.compute(Float64(), 1.3, 2.1, 0.3, None, -4, 5)
    np.testing.assert_array_equal(np.array(body["vertices"]), core.polygon.vertices)
    assert client.post("/discretizations/d2a-hex", json=params).json() == body
    (entry,) = [e for e in client.get("/discretizations").json() if e["id"] == "d2a-hex"]
    names = {p["name"]: p for p in entry["parameters"]}
    assert names["lambda"]["domain"] == "0 < lambda < 1" and "lam" not in names
    assert entry["statements"] == [s.id for s in d2a_hex.STATEMENTS]


def test_mp_coordinates_and_constants_are_strings(client: TestClient) -> None:
    body = client.get(
        "/discretizations/d2a-quad",
        params={"precision": "mp", "digits": 40, "f0": 1, "f1": 2, "i_min": 0, "i_max": 3},
    ).json()
    x, y = body["vertices"][3]  # p_3 = (3d, −(8 + 1/8)) with d = 3/2
    assert Decimal(x) == Decimal("4.5") and Decimal(y) == Decimal("-8.125")
    assert isinstance(body["constants"]["r_theorem_1"], str)
    assert all(c["holds"] is True for c in body["checks"] if c["id"] not in {"d1", "d3"})


def test_theorem_endpoints(client: TestClient) -> None:
    body = client.get("/theorems/theorem-1", params={"r": 0}).json()
    assert body["discretization"] == "d2a-quad" and body["check"]["holds"] is False
    body = client.get("/theorems/theorem-3-even", params={"lambda": 0.7}).json()
    assert body["check"]["holds"] is True and body["check"]["erratum"]["id"] == "E43"
    body = client.get("/theorems/d1", params={"discretization": "d2a-hex"}).json()
    assert body["check"]["holds"] is False


def problem(response, status: int = 422) -> dict:  # type: ignore[no-untyped-def]
    assert response.status_code == status, response.text
    assert response.headers["content-type"] == "application/problem+json"
    return response.json()


@pytest.mark.parametrize(
    ("path", "query", "parameter", "constraint"),
    [
        ("d2a-quad", "f0=0", "f0", "f0 > 0"),
        ("d2a-quad", "f0=-1", "f0", "f0 > 0"),
        ("d2a-quad", "f1=1", "f1", "0 < f0 < f1"),
        ("d2a-quad", "f0=2&f1=1", "f1", "0 < f0 < f1"),
        ("d2a-quad", "f0=nan", "f0", "f0 is a finite number"),
        ("d2a-quad", "r=inf", "r", "r is a finite number"),
        ("d2a-quad", "r=1e200", "r", "r <= 1e+100"),
        ("d2a-quad", "f1=1.00001", "f1", "(f1 − f0)/f1 >= 0.0001 in float64"),
        ("d2a-quad", "f1=2&i_max=200", "i_max", "every f_i and 1/f_i <= 1e+50 in float64"),
        ("d2a-quad", "i_min=3&i_max=2", "i_max", "i_min <= i_max"),
        ("d2a-quad", "method=closed-form", "method", "not a parameter of this endpoint"),
        ("d2a-hex", "a=0", "a", "a > 0"),
        ("d2a-hex", "b=0.5", "b", "0 < a < b"),
        ("d2a-hex", "b=1", "b", "0 < a < b"),
        ("d2a-hex", "lambda=0", "lambda", "lambda > 0"),
        ("d2a-hex", "lambda=1", "lambda", "lambda < 1"),
        ("d2a-hex", "lambda=-0.5", "lambda", "lambda > 0"),
        ("d2a-hex", "lambda=0.0000001", "lambda", "in float64"),
        ("d2a-hex", "lam=0.5", "lam", "not a parameter of this endpoint"),
        ("d2a-hex", "lambda=0.5&lambda=0.6", "lambda", "given more than once"),
        ("d2a-hex", "b=1.00001", "b", "(b − a)/b >= 0.0001 in float64"),
    ],
)
def test_bad_input_is_a_422_naming_the_parameter(
    client: TestClient, path: str, query: str, parameter: str, constraint: str
) -> None:
    body = problem(client.get(f"/discretizations/{path}?{query}"))
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body


def test_edges_of_the_domain_work_in_mp(client: TestClient) -> None:
    response = client.get(
        "/discretizations/d2a-hex",
        params={"lambda": 1e-7, "precision": "mp", "digits": 30, "i_min": -3, "i_max": 3},
    )
    assert response.status_code == 200
    checks = {c["id"]: c["holds"] for c in response.json()["checks"]}
    assert checks["theorem-2"] is True and checks["theorem-3-odd"] is True
