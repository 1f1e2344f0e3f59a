"""Every bad input gets problem+json naming the parameter and the constraint; never a 500."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.registry import DISCRETIZATIONS
from app.settings import Settings


def problem(response, status: int) -> dict:
    assert response.status_code == status, response.text
    assert response.headers["content-type"] == "application/problem+json"
    body = response.json()
    assert body["status"] == status
    assert {"type", "title", "detail", "errors"} <= set(body)
    return body


@pytest.mark.parametrize(
    ("query", "parameter", "constraint"),
    [
        ("d=1", "d", "0 < d < h"),
        ("d=1.5&h=1", "d", "0 < d < h"),
        ("d=0", "d", "d > 0"),
        ("d=-0.2", "d", "d > 0"),
        ("h=0", "h", "h > 0"),
        ("h=-1", "h", "h > 0"),
        ("h=nan", "h", "h is a finite number"),
        ("d=inf", "d", "d is a finite number"),
        ("h=-inf", "h", "h is a finite number"),
        ("beta0=0", "beta0", "beta0 > 0"),
        ("beta0=3.2", "beta0", "beta0 < 3.14159"),
        ("i_min=5&i_max=4", "i_max", "i_min <= i_max"),
        ("i_max=20000000", "i_max", "i_max <= 10000000"),
        ("d=0.5&i_max=400", "i_max", "|i_max| <= 312 in float64"),
        ("d=1e-9", "d", "d/h >= 1.5e-06 in float64"),
        ("d=1e-30&precision=mp&digits=30", "d", "d/h >= 1e-18 in mp with 30 digits"),
        ("=1", "(empty name)", "not a parameter of this endpoint"),
        ("precision=quad", "precision", "precision is one of 'float64' or 'mp'"),
        ("method=guess", "method", "method is one of"),
        ("format=xml", "format", "format is one of"),
        ("digits=0&precision=mp", "digits", "digits >= 1"),
        ("digits=5000&precision=mp", "digits", "1 <= digits <= 1000"),
        (
            "precision=mp&digits=1000&i_min=-500&i_max=500",
            "digits",
            "(digits + 200) × steps <= 1000000",
        ),
        ("i_min=-600000&i_max=600000", "i_max", "i_max − i_min + 1 <= 1000001"),
        ("method=construction&i_min=3000000&i_max=3000001", "i_max", "method=construction"),
        ("color=red", "color", "not a parameter of this endpoint"),
        ("h=1&h=2", "h", "given more than once"),
        ("h=abc", "h", "number"),
        ("i_min=1.5", "i_min", "integer"),
    ],
)
def test_bad_query_is_a_422_naming_parameter_and_constraint(
    client: TestClient, query: str, parameter: str, constraint: str
) -> None:
    body = problem(client.get(f"/discretizations/d4b?{query}"), 422)
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body
    assert parameter in body["detail"]


def test_bad_post_body_is_a_422(client: TestClient) -> None:
    body = problem(client.post("/discretizations/d4b", json={"d": 2.0, "extra": 1}), 422)
    assert {e["parameter"] for e in body["errors"]} == {"extra"}
    body = problem(client.post("/discretizations/d4b", json={"d": 2.0}), 422)
    assert body["errors"] == [{"parameter": "d", "constraint": "0 < d < h", "value": 2.0}]
    problem(
        client.post(
            "/discretizations/d4b",
            content=b"{not json",
            headers={"content-type": "application/json"},
        ),
        422,
    )


def test_unreadable_bodies_and_huge_integers_are_422(client: TestClient) -> None:
    headers = {"content-type": "application/json"}
    body = problem(
        client.post("/discretizations/d4b", content=b"o\xdf\x87\xff", headers=headers), 422
    )
    assert body["errors"][0]["parameter"] == "body"
    body = problem(client.post("/discretizations/d4b", json={"digits": 2**64}), 422)
    assert body["errors"][0] == {
        "parameter": "digits",
        "constraint": "1 <= digits <= 1000",
        "value": str(2**64),
    }


def test_unknown_ids_are_404_listing_the_valid_ones(client: TestClient) -> None:
    body = problem(client.get("/discretizations/d9"), 404)
    assert body["valid"] == sorted(DISCRETIZATIONS)
    assert {"d1", "d3", "d4a", "d4b"} <= set(body["valid"])
    assert "d4b" in body["detail"]
    body = problem(client.get("/theorems/theorem-99"), 404)
    assert "theorem-5" in body["valid"]
    problem(client.get("/no/such/path"), 404)
    problem(client.get("/theorems/theorem-5?discretization=d1"), 404)


def test_limits_come_from_settings() -> None:
    small = TestClient(create_app(Settings(max_vertices=11, max_digits=20)))
    body = problem(small.get("/discretizations/d4b"), 422)  # 21 vertices by default
    assert body["errors"][0]["constraint"] == "i_max − i_min + 1 <= 11 (vertices)"
    assert small.get("/discretizations/d4b?i_min=-5&i_max=5").status_code == 200
    body = problem(small.get("/discretizations/d4b?precision=mp&digits=21&i_max=-5&i_min=-5"), 422)
    assert body["errors"][0]["parameter"] == "digits"


def test_wrong_method_is_a_405_problem(client: TestClient) -> None:
    problem(client.delete("/discretizations/d4b"), 405)
