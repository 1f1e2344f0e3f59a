"""`checks` and `companions`: responses hold what is asked for, and only that is computed."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.geometry.d4b import closed_forms, curvature, discretization as d4b
from app.registry import DISCRETIZATIONS

URL = "/discretizations/d4b?h=1&d=0.3&i_min=-5&i_max=5"


def _get(client: TestClient, query: str) -> dict[str, Any]:
    response = client.get(f"{URL}&{query}")
    assert response.status_code == 200, response.text
    body: dict[str, Any] = response.json()
    return body


def test_a_list_of_checks_returns_those_checks_as_in_the_full_answer(client: TestClient) -> None:
    full = _get(client, "checks=all")
    chosen = _get(client, "checks=theorem-6,theorem-5, recursion-13")
    assert [c["id"] for c in chosen["checks"]] == ["recursion-13", "theorem-5", "theorem-6"]
    by_id = {c["id"]: c for c in full["checks"]}
    assert all(c == by_id[c["id"]] for c in chosen["checks"])
    assert chosen["vertices"] == full["vertices"] and chosen["companions"] == full["companions"]


def test_nothing_selected_is_the_polygon_alone(client: TestClient) -> None:
    full = _get(client, "checks=all")
    bare = _get(client, "checks=none&companions=none")
    assert bare["checks"] == [] and bare["companions"] == {} and bare["constants"] == {}
    assert bare["vertices"] == full["vertices"] and bare["indices"] == full["indices"]


def test_failed_keeps_the_checks_that_fail(client: TestClient) -> None:
    full = client.get("/discretizations/d2a-quad").json()
    failed = client.get("/discretizations/d2a-quad?checks=failed").json()
    expected = [c["id"] for c in full["checks"] if c["holds"] is False]
    assert expected and [c["id"] for c in failed["checks"]] == expected


def test_a_list_of_companions(client: TestClient) -> None:
    chosen = _get(client, "companions=darboux,tractrix")
    assert set(chosen["companions"]) == {"darboux", "tractrix"}
    assert len(chosen["checks"]) == len(d4b.STATEMENTS)


@pytest.mark.parametrize(
    ("query", "parameter", "listed"),
    [
        ("checks=theorem-5,d7", "checks", "theorem-5"),
        ("checks=none,theorem-5", "checks", "stand alone"),
        ("companions=evolute", "companions", "tractrix"),
        ("checks=", "checks", "list of ids"),
    ],
)
def test_an_unknown_id_is_a_422_listing_the_valid_ones(
    client: TestClient, query: str, parameter: str, listed: str
) -> None:
    response = client.get(f"{URL}&{query}")
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    errors = response.json()["errors"]
    assert errors[0]["parameter"] == parameter and listed in errors[0]["constraint"]


def test_the_selection_is_part_of_the_etag_and_spelled_one_way(client: TestClient) -> None:
    tags = {
        q: client.get(f"{URL}&{q}").headers["etag"]
        for q in (
            "checks=all",
            "checks=none",
            "checks=theorem-5,theorem-6",
            "checks=theorem-6,theorem-5",
        )
    }
    assert len({tags["checks=all"], tags["checks=none"], tags["checks=theorem-5,theorem-6"]}) == 3
    assert tags["checks=theorem-5,theorem-6"] == tags["checks=theorem-6,theorem-5"]


def test_post_takes_a_list(client: TestClient) -> None:
    body = {"h": 1, "d": 0.3, "i_min": -5, "i_max": 5, "checks": ["theorem-5"], "companions": []}
    response = client.post("/discretizations/d4b", json=body)
    assert response.status_code == 422  # an empty list selects nothing: say `none`
    body["companions"] = "none"
    answer = client.post("/discretizations/d4b", json=body).json()
    assert [c["id"] for c in answer["checks"]] == ["theorem-5"] and answer["companions"] == {}


@pytest.mark.parametrize("identifier", sorted(DISCRETIZATIONS))
def test_every_discretization_takes_the_selection(client: TestClient, identifier: str) -> None:
    entry = DISCRETIZATIONS[identifier]
    first = entry.info.statements[-1].id
    answer = client.get(f"/discretizations/{identifier}?checks={first}&companions=none").json()
    assert [c["id"] for c in answer["checks"]] == [first] and answer["companions"] == {}


def test_what_is_not_selected_is_not_computed(
    client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    def refuse(*args: Any, **kwargs: Any) -> Any:
        raise AssertionError("computed although not selected")

    monkeypatch.setattr(curvature, "build", refuse)  # the Gauss images of Section 5
    monkeypatch.setattr(closed_forms, "tractrix", refuse)  # (16), only theorem-6 compares it
    answer = _get(client, "checks=theorem-5,theorem-4-i&companions=tractrix")
    assert [c["holds"] for c in answer["checks"]] == [True, True]
    assert client.get(f"{URL}&format=npy").status_code == 200
    monkeypatch.setattr(closed_forms, "hyperbolic_cosine", refuse)  # (14): theorem-5 only
    assert client.get(f"{URL}&checks=none&companions=none").status_code == 200


def test_surfaces_take_a_selection_of_checks(client: TestClient) -> None:
    answer = client.get("/surfaces/pseudosphere?checks=theorem-7").json()
    assert [c["id"] for c in answer["checks"]] == ["theorem-7"]
    refused = client.get("/surfaces/pseudosphere?checks=vanishing-mean-curvature")
    assert refused.status_code == 422 and refused.json()["errors"][0]["parameter"] == "checks"
