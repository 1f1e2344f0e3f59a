"""GET /figures and /figures/{id}.svg: Figure 4 drawn from the same data as the curve JSON."""

from __future__ import annotations

import math

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.rendering.figures import FIGURES
from app.settings import Settings
from tests.svg_reading import (
    circle_pixels,
    inverse_transform,
    parse,
    polyline_pixels,
    segment_pixels,
    series,
    series_names,
)


def test_catalog_lists_every_figure_with_its_parameters(client: TestClient) -> None:
    body = client.get("/figures").json()
    assert [f["id"] for f in body] == list(FIGURES)
    figure = body[0]
    assert figure["url"] == "/figures/figure-4.svg"
    names = {p["name"]: p for p in figure["parameters"]}
    assert set(names) == {"h", "d", "beta0", "i_min", "i_max"}
    assert names["d"]["domain"] == "0 < d < h" and names["i_min"]["default"] == -4


@pytest.mark.parametrize("identifier", sorted(FIGURES))
def test_every_figure_renders_with_its_defaults(client: TestClient, identifier: str) -> None:
    response = client.get(f"/figures/{identifier}.svg")
    assert response.status_code == 200
    assert response.headers["content-type"] == "image/svg+xml"
    root = parse(response.content)
    assert root.get("viewBox") and len(series_names(root)) >= 2


@pytest.mark.parametrize(
    "params",
    [{}, {"h": 2.0, "d": 0.7, "i_min": -2, "i_max": 5}, {"d": 0.3, "beta0": 1.1}],
)
def test_figure_4_draws_the_d4b_data(client: TestClient, params: dict[str, float]) -> None:
    root = parse(client.get("/figures/figure-4.svg", params=params).content)
    query = {"i_min": -4, "i_max": 4, "d": 0.2, **params}
    body = client.get("/discretizations/d4b", params=query).json()
    p = np.array(body["vertices"])
    tractrix = np.array(body["companions"]["tractrix"]["vertices"])
    axis = np.array(body["companions"]["axis_points"]["vertices"])
    darboux = np.array(body["companions"]["darboux"]["vertices"])
    inverse = inverse_transform(root)
    assert inverse.bx == pytest.approx(inverse.by, rel=1e-5)
    tol = inverse.resolution
    np.testing.assert_allclose(inverse(polyline_pixels(series(root, "p"))), p, atol=tol)
    np.testing.assert_allclose(
        inverse(polyline_pixels(series(root, "tractrix"))), tractrix, atol=tol
    )
    np.testing.assert_allclose(inverse(polyline_pixels(series(root, "darboux"))), darboux, atol=tol)
    np.testing.assert_allclose(inverse(circle_pixels(series(root, "axis_points"))), axis, atol=tol)
    sticks = segment_pixels(series(root, "sticks"))
    np.testing.assert_allclose(inverse(sticks[:, 0]), axis, atol=tol)
    np.testing.assert_allclose(inverse(sticks[:, 1]), tractrix, atol=tol)
    # every drawn stick has the length h
    drawn = inverse(sticks[:, 1]) - inverse(sticks[:, 0])
    h = query.get("h", 1.0)
    np.testing.assert_allclose(np.hypot(drawn[:, 0], drawn[:, 1]), h, atol=2 * tol)
    rotations = segment_pixels(series(root, "rotations"))
    np.testing.assert_allclose(inverse(rotations[0::2, 0]), p[1:], atol=tol)
    np.testing.assert_allclose(inverse(rotations[0::2, 1]), axis[:-1], atol=tol)
    np.testing.assert_allclose(inverse(rotations[1::2, 1]), axis[1:], atol=tol)


def test_figure_4_names_its_data_source_and_parameters(client: TestClient) -> None:
    text = client.get("/figures/figure-4.svg", params={"h": 2, "d": 0.5}).text
    assert "Data: GET /discretizations/d4b?h=2.0&amp;d=0.5&amp;beta0=" in text
    assert "h = 2, d = 0.5" in text
    assert f"beta0 = {math.pi / 2:.6g}" in text


def test_figure_parameters_outside_the_domain_are_422_naming_them(client: TestClient) -> None:
    response = client.get("/figures/figure-4.svg", params={"d": 1.5})
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    assert response.json()["errors"] == [
        {"parameter": "d", "constraint": "0 < d < h", "value": 1.5}
    ]
    invalid = client.get("/figures/figure-4.svg", params={"h": "long"})
    assert invalid.status_code == 422 and invalid.json()["errors"][0]["parameter"] == "h"
    unknown = client.get("/figures/figure-4.svg", params={"q": 1})
    assert unknown.json()["errors"][0] == {
        "parameter": "q",
        "constraint": "not a parameter of this endpoint",
        "value": "1",
    }
    repeated = client.get("/figures/figure-4.svg?d=0.1&d=0.2")
    assert repeated.status_code == 422 and repeated.json()["errors"][0]["parameter"] == "d"
    backwards = client.get("/figures/figure-4.svg", params={"i_min": 3, "i_max": 2})
    assert backwards.status_code == 422 and backwards.json()["errors"][0]["parameter"] == "i_max"


def test_unknown_figures_are_404_listing_the_valid_ones(client: TestClient) -> None:
    for path in ("/figures/figure-99.svg", "/figures/figure-4", "/figures/nothing"):
        response = client.get(path)
        assert response.status_code == 404, path
        body = response.json()
        assert body["valid"] == sorted(FIGURES) and "figure-4" in body["detail"]


def test_figures_over_the_picture_limit_are_refused() -> None:
    client = TestClient(create_app(Settings(max_svg_vertices=9)))
    assert client.get("/figures/figure-4.svg").status_code == 200  # -4 .. 4: 9 vertices
    response = client.get("/figures/figure-4.svg", params={"i_max": 5})
    assert response.status_code == 422 and response.json()["errors"][0]["parameter"] == "i_max"


def test_figures_carry_an_etag_and_answer_304(client: TestClient) -> None:
    first = client.get("/figures/figure-4.svg", params={"d": 0.3})
    again = client.get(
        "/figures/figure-4.svg",
        params={"d": 0.30},
        headers={"If-None-Match": first.headers["etag"]},
    )
    assert again.status_code == 304
