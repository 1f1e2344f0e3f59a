"""format=svg on every curve endpoint: the drawn polygons are the JSON's polygons."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.registry import DISCRETIZATIONS
from app.settings import Settings
from tests.svg_reading import (
    circle_pixels,
    inverse_transform,
    parse,
    polyline_pixels,
    series,
    series_names,
)


def polylines(body: dict[str, Any]) -> dict[str, np.ndarray]:
    """Every polygon of a JSON curve response, as floats."""
    out = {"p": np.array(body["vertices"], dtype=np.float64)}
    for name, companion in body["companions"].items():
        out[name] = np.array(companion["vertices"], dtype=np.float64)
    return out


@pytest.mark.parametrize("identifier", sorted(DISCRETIZATIONS))
def test_every_discretization_draws_its_polygon_and_companions(
    client: TestClient, identifier: str
) -> None:
    response = client.get(f"/discretizations/{identifier}", params={"format": "svg"})
    assert response.status_code == 200
    assert response.headers["content-type"] == "image/svg+xml"
    assert "default-src 'none'" in response.headers["content-security-policy"]
    root = parse(response.content)
    body = client.get(f"/discretizations/{identifier}").json()
    assert series_names(root) == ["p", *body["companions"]]
    inverse = inverse_transform(root)
    assert inverse.bx == pytest.approx(inverse.by, rel=1e-5)
    for name, vertices in polylines(body).items():
        drawn = inverse(polyline_pixels(series(root, name)))
        np.testing.assert_allclose(drawn, vertices, atol=inverse.resolution, err_msg=name)


def test_drawn_d4b_coordinates_match_the_json_for_given_parameters(client: TestClient) -> None:
    params = {"h": 2.0, "d": 0.5, "beta0": 1.2, "i_min": -3, "i_max": 6}
    root = parse(client.get("/discretizations/d4b", params={**params, "format": "svg"}).content)
    body = client.get("/discretizations/d4b", params=params).json()
    inverse = inverse_transform(root)
    drawn = polylines(body)
    for name, vertices in drawn.items():
        group = series(root, name)
        np.testing.assert_allclose(
            inverse(polyline_pixels(group)), vertices, atol=inverse.resolution
        )
        np.testing.assert_allclose(inverse(circle_pixels(group)), vertices, atol=inverse.resolution)
    # sharp enough to tell p from the same polygon with other parameters
    other = client.get("/discretizations/d4b", params={**params, "d": 0.51}).json()
    assert not np.allclose(
        inverse(polyline_pixels(series(root, "p"))),
        np.array(other["vertices"]),
        atol=inverse.resolution,
    )


def test_mp_curves_are_drawn_from_their_decimal_coordinates(client: TestClient) -> None:
    params = {"precision": "mp", "digits": 40, "d": 0.3, "i_min": -2, "i_max": 3}
    root = parse(client.get("/discretizations/d4b", params={**params, "format": "svg"}).content)
    body = client.get("/discretizations/d4b", params=params).json()
    inverse = inverse_transform(root)
    np.testing.assert_allclose(
        inverse(polyline_pixels(series(root, "p"))),
        np.array(body["vertices"], dtype=np.float64),
        atol=inverse.resolution,
    )


def test_post_draws_the_same_picture_as_get(client: TestClient) -> None:
    params = {"h": 1.5, "d": 0.2, "i_min": -2, "i_max": 2, "format": "svg"}
    assert client.post("/discretizations/d4b", json=params).content == (
        client.get("/discretizations/d4b", params=params).content
    )


def test_svg_responses_carry_an_etag(client: TestClient) -> None:
    first = client.get("/discretizations/d4b", params={"format": "svg"})
    again = client.get(
        "/discretizations/d4b",
        params={"format": "svg"},
        headers={"If-None-Match": first.headers["etag"]},
    )
    assert again.status_code == 304
    json_etag = client.get("/discretizations/d4b").headers["etag"]
    assert json_etag != first.headers["etag"]


def test_pictures_of_too_many_vertices_are_refused_before_any_work() -> None:
    client = TestClient(create_app(Settings(max_svg_vertices=11)))
    ok = client.get("/discretizations/d4b", params={"format": "svg", "i_min": 0, "i_max": 10})
    assert ok.status_code == 200
    response = client.get("/discretizations/d4b", params={"format": "svg", "i_min": 0, "i_max": 11})
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    error = response.json()["errors"][0]
    assert error["parameter"] == "i_max" and "<= 11" in error["constraint"]
    # the same range as JSON is fine
    assert client.get("/discretizations/d4b", params={"i_min": 0, "i_max": 11}).status_code == 200


def test_an_unknown_format_names_the_choices(client: TestClient) -> None:
    response = client.get("/discretizations/d4b", params={"format": "png"})
    assert response.status_code == 422
    error = response.json()["errors"][0]
    assert error["parameter"] == "format" and "'svg'" in error["constraint"]


def test_mp_coordinates_beyond_float64_cannot_be_drawn(client: TestClient) -> None:
    params = {"precision": "mp", "digits": 20, "d": 0.9, "i_min": 0, "i_max": 400}
    assert client.get("/discretizations/d4b", params=params).status_code == 200
    response = client.get("/discretizations/d4b", params={**params, "format": "svg"})
    assert response.status_code == 422
    error = response.json()["errors"][0]
    assert error["parameter"] == "format" and "float64" in error["constraint"]
