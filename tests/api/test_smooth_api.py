"""GET /smooth/catenary and /smooth/tractrix: samples, checks, caching and every 422."""

from __future__ import annotations

import math

import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.schemas.curve import CurveResponse
from app.settings import Settings
from tests.api.test_errors import problem


def test_catenary_samples(client: TestClient) -> None:
    response = client.get(
        "/smooth/catenary", params={"h": 2.0, "x_min": -2, "x_max": 2, "count": 5}
    )
    assert response.status_code == 200 and "etag" in response.headers
    body = response.json()
    CurveResponse.model_validate(body)
    assert body["indices"] == [0, 1, 2, 3, 4]
    assert [x for x, _ in body["vertices"]] == [-2.0, -1.0, 0.0, 1.0, 2.0]
    assert body["vertices"][4][1] == pytest.approx(2 * math.cosh(1.0), rel=1e-15)
    assert body["checks"] == [] and body["parameters"]["count"] == 5


def test_tractrix_with_evolute_and_checks(client: TestClient) -> None:
    body = client.get(
        "/smooth/tractrix", params={"count": 11, "precision": "mp", "digits": 30}
    ).json()
    CurveResponse.model_validate(body)
    assert set(body["companions"]) == {"evolute", "catenary", "axis_points"}
    assert {c["id"]: c["holds"] for c in body["checks"]} == {
        "tractrix-s4": True,
        "evolute-s4": True,
        "nikolaides-s4": True,
    }
    assert isinstance(body["vertices"][0][0], str)


def test_csv(client: TestClient) -> None:
    text = client.get("/smooth/tractrix", params={"count": 2, "format": "csv"}).text
    assert text.splitlines()[0] == "curve,index,x,y"
    assert len(text.splitlines()) == 1 + 2 * 4


@pytest.mark.parametrize(
    ("url", "parameter", "constraint"),
    [
        ("/smooth/catenary?h=0", "h", "h > 0"),
        ("/smooth/catenary?x_min=1&x_max=1", "x_max", "x_min < x_max"),
        ("/smooth/tractrix?count=1", "count", "count >= 2"),
        ("/smooth/tractrix?x_max=1000", "x_max", "|x_max|/h <= 346"),
        ("/smooth/catenary?x_min=nan", "x_min", "x_min is a finite number"),
        ("/smooth/catenary?count=2000000", "count", "count <= 1000001"),
        ("/smooth/catenary?i_max=3", "i_max", "not a parameter of this endpoint"),
        ("/smooth/tractrix?precision=mp&digits=1000&count=5000", "digits", "× count <="),
        ("/smooth/tractrix?h=1&h=2", "h", "given more than once"),
    ],
)
def test_bad_query_is_a_422(client: TestClient, url: str, parameter: str, constraint: str) -> None:
    body = problem(client.get(url), 422)
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body


def test_unknown_curve_is_a_404_and_limits_come_from_settings(client: TestClient) -> None:
    body = problem(client.get("/smooth/pseudosphere"), 404)
    assert body["valid"] == ["catenary", "tractrix"]
    small = TestClient(create_app(Settings(max_vertices=10)))
    assert problem(small.get("/smooth/catenary?count=11"), 422)["errors"][0]["parameter"] == "count"
    assert small.get("/smooth/catenary?count=10").status_code == 200
