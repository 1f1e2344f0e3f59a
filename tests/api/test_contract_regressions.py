"""Contract defects found by fuzzing (issue 16), each pinned: every 422 names a request parameter,
its value as the request carried it, and a constraint printed properly."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.services import surfaces as surface_service

SURFACE = {"i_min": -3, "i_max": 3, "m": 3, "checks": "none"}


def problem(response: Any) -> dict[str, Any]:
    assert response.status_code == 422, response.text
    assert response.headers["content-type"] == "application/problem+json"
    body: dict[str, Any] = response.json()
    assert len(body["errors"]) == 1
    return body


@pytest.mark.parametrize(
    ("start", "face", "edge"),
    [
        ({"y0": 0, "y1": 0}, 18, "p_0 p_1"),  # both ends on the axis
        ({"y0": 1, "y1": -1}, 18, "p_0 p_1"),  # the edge crosses the axis: a crossed quad
    ],
)
@pytest.mark.parametrize("method", ["GET", "POST"])
def test_a_degenerate_meridian_names_the_start_heights(
    client: TestClient, start: dict[str, float], face: int, edge: str, method: str
) -> None:
    parameters = {**SURFACE, **start}
    if method == "GET":
        response = client.get("/surfaces/catenoid/d1", params=parameters)
    else:
        response = client.post("/surfaces/catenoid/d1", json=parameters)
    body = problem(response)
    [error] = body["errors"]
    assert error["parameter"] == "y0"  # was "meridian", not a parameter of the request
    assert error["value"] == start["y0"]
    assert error["constraint"] == surface_service.DEGENERATE_MERIDIAN["d1"]
    assert f"face {face}, the meridian edge {edge} revolved, has no area" in body["detail"]
    # the older spelling names it the same way
    old = client.get("/surfaces/catenoid", params={**parameters, "discretization": "d1"})
    assert problem(old)["errors"] == body["errors"]


def test_the_meridian_constraint_is_documented_where_y0_is_a_surface_parameter(
    client: TestClient,
) -> None:
    document = client.get("/openapi.json").json()
    for method in ("get", "post"):
        operation = document["paths"]["/surfaces/{surface_id}/d1"][method]
        if method == "get":
            schemas = {p["name"]: p["schema"] for p in operation["parameters"]}
        else:
            body = operation["requestBody"]["content"]["application/json"]["schema"]
            schemas = body["properties"]
        assert schemas["y0"]["x-domain"] == surface_service.DEGENERATE_MERIDIAN["d1"]


def _overflowing(*args: Any, **kwargs: Any) -> Any:
    raise RuntimeWarning("overflow encountered in multiply")


@pytest.mark.parametrize(
    ("given", "named", "advice"),
    [
        ({"precision": "mp"}, "mp", "use a shorter range."),
        ({"precision": "float64"}, "float64", "use precision=mp or a shorter range."),
        ({}, "float64", "use precision=mp or a shorter range."),  # the default in force
    ],
)
def test_a_numerical_warning_names_the_precision_of_a_post_body(
    client: TestClient,
    monkeypatch: pytest.MonkeyPatch,
    given: dict[str, str],
    named: str,
    advice: str,
) -> None:
    monkeypatch.setattr(surface_service, "build", _overflowing)
    posted = problem(client.post("/surfaces/catenoid", json={**SURFACE, **given}))
    assert posted["errors"] == [
        {
            "parameter": "precision",
            "constraint": "values representable in the chosen precision",
            "value": named,  # was null on every POST: only the query string was read
        }
    ]
    assert posted["detail"].endswith(advice)
    got = problem(client.get("/surfaces/catenoid", params={**SURFACE, **given}))
    assert got["errors"] == posted["errors"]


@pytest.mark.parametrize("precision", ["float64", "mp"])
def test_glb_beyond_float32_names_format_not_an_overflow(
    client: TestClient, precision: str
) -> None:
    """beta0 = 1e-100 puts the catenoid's far rings beyond float32: format=glb is what cannot
    hold them (the float64 normals overflowed first: a 422 naming precision, value null)."""
    body = {"beta0": 1e-100, "format": "glb", "precision": precision, "digits": 20}
    for response in (
        client.post("/surfaces/catenoid/d4b", json=body),
        client.get("/surfaces/catenoid/d4b", params=body),
    ):
        error = problem(response)["errors"][0]
        assert error == {
            "parameter": "format",
            "constraint": "values within float32 for format=glb",
            "value": "glb",
        }
    as_json = client.get("/surfaces/catenoid/d4b", params={**body, "format": "ply"})
    assert as_json.status_code == 200


@pytest.mark.parametrize(
    ("digits", "bound"), [(1, "1"), (2, "0.1"), (3, "0.1"), (4, "0.01"), (30, "1e-15")]
)
def test_d4a_step_bound_is_printed_as_a_number(client: TestClient, digits: int, bound: str) -> None:
    query = {"s": 1e-90, "precision": "mp", "digits": digits}
    error = problem(client.get("/discretizations/d4a", params=query))["errors"][0]
    assert error["parameter"] == "s"
    assert error["constraint"] == f"s/h >= {bound} with digits={digits}"  # was "1e-0" at 1


@pytest.mark.parametrize("digits", [1, 2, 3])
@pytest.mark.parametrize(
    ("path", "query"),
    [
        ("/discretizations/d4b", {"d": 1e-90}),
        ("/discretizations/d2a-quad", {"f1": 1.0 + 1e-15}),
    ],
)
def test_precision_bounds_print_numbers_at_few_digits(
    client: TestClient, path: str, query: dict[str, float], digits: int
) -> None:
    response = client.get(path, params={**query, "precision": "mp", "digits": digits})
    constraint = problem(response)["errors"][0]["constraint"]
    assert "e-0 " not in constraint and not constraint.endswith("e-0"), constraint
    assert f"in mp with {digits} digits" in constraint


@pytest.mark.parametrize(
    ("surface", "foreign"),
    [("catenoid", "theorem-7"), ("pseudosphere", "vanishing-mean-curvature")],
)
@pytest.mark.parametrize("method", ["GET", "POST"])
def test_surface_checks_of_another_surface_are_refused_on_both_spellings(
    client: TestClient, surface: str, foreign: str, method: str
) -> None:
    query = {**SURFACE, "checks": foreign}
    answers = []
    for path in (f"/surfaces/{surface}", f"/surfaces/{surface}/d4b"):
        if method == "GET":
            answers.append(problem(client.get(path, params=query)))
        else:
            answers.append(problem(client.post(path, json=query)))
    older, newer = answers
    assert older["errors"] == newer["errors"] and older["detail"] == newer["detail"]
    [error] = older["errors"]
    assert error["parameter"] == "checks" and error["value"] == foreign
    assert foreign not in error["constraint"]
    own = client.get(f"/surfaces/{surface}", params={**SURFACE, "i_min": 1, "checks": "all"})
    assert own.status_code == 200
    assert foreign not in {check["id"] for check in own.json()["checks"]}


def test_the_surface_checks_coupling_is_documented(client: TestClient) -> None:
    """Where one path serves both claims, ``checks`` carries the coupling with ``surface_id`` in
    ``x-domain`` (a query parameter's schema cannot depend on the path)."""
    paths = client.get("/openapi.json").json()["paths"]
    for path, coupled in [
        ("/surfaces/{surface_id}", True),
        ("/surfaces/{surface_id}/d4b", True),
        ("/surfaces/{surface_id}/d1", False),
    ]:
        checks = next(p for p in paths[path]["get"]["parameters"] if p["name"] == "checks")
        assert ("x-domain" in checks["schema"]) is coupled, path
        body = paths[path]["post"]["requestBody"]["content"]["application/json"]["schema"]
        assert ("x-domain" in body["properties"]["checks"]) is coupled, path
