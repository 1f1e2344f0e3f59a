"""GET /figures and /figures/{id}.svg: every figure drawn from the same data as the JSON of the
curve endpoints (the drawn pixels mapped back through each panel's tick labels)."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.services.figures import FIGURES
from app.settings import Settings
from tests.svg_reading import (
    Inverse,
    circle_pixels,
    inverse_transform,
    panel,
    panel_names,
    parse,
    polygon_pixels,
    polyline_pixels,
    segment_pixels,
    series,
    series_names,
)


def test_catalog_lists_every_figure_with_its_parameters(client: TestClient) -> None:
    body = client.get("/figures").json()
    assert [f["id"] for f in body] == list(FIGURES)
    assert [f["id"] for f in body] == [f"figure-{k}" for k in (2, 3, 4, 5, 6, 7, 8)]
    figure = next(f for f in body if f["id"] == "figure-4")
    assert figure["url"] == "/figures/figure-4.svg"
    assert figure["discretizations"] == ["d4b"]
    names = {p["name"]: p for p in figure["parameters"]}
    assert set(names) == {"h", "d", "beta0", "i_min", "i_max"}
    assert names["d"]["domain"] == "0 < d < h" and names["i_min"]["default"] == -4
    # the figures share the curve endpoints' parameter definitions
    catalog = {e["id"]: e for e in client.get("/discretizations").json()}
    for entry in body:
        for identifier in entry["discretizations"]:
            own = {p["name"]: p for p in catalog[identifier]["parameters"]}
            for parameter in entry["parameters"]:
                name = parameter["name"]  # figure 8: named sequences only, several j
                if name in own and not name.startswith("i_") and name not in ("sequence", "j"):
                    assert parameter["domain"] == own[parameter["name"]]["domain"]
                    assert parameter["description"] == own[parameter["name"]]["description"]
    by_id = {f["id"]: f for f in body}
    assert by_id["figure-2"]["discretizations"] == []
    assert by_id["figure-8"]["discretizations"] == ["d2b"]


@pytest.mark.parametrize("identifier", sorted(FIGURES))
def test_every_figure_renders_with_its_defaults(client: TestClient, identifier: str) -> None:
    response = client.get(f"/figures/{identifier}.svg")
    assert response.status_code == 200
    assert response.headers["content-type"] == "image/svg+xml"
    root = parse(response.content)
    assert root.get("viewBox") and len(series_names(root)) >= 2
    # self-contained: no link leaves the document, every id is unique and every url(#…) is one
    text = response.text
    ids = re.findall(r'\bid="([^"]+)"', text)
    assert len(ids) == len(set(ids))
    assert set(re.findall(r"url\(#([^)]+)\)", text)) <= set(ids)
    assert "href" not in text and "<script" not in text and "@import" not in text
    for name in panel_names(root):  # each panel has axes of its own to read it by
        assert inverse_transform(panel(root, name)).resolution > 0


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


def drawn(part: object, name: str, inverse: Inverse) -> np.ndarray:
    """A line series of a panel (or plot) in data coordinates."""
    return inverse(polyline_pixels(series(part, name)))  # type: ignore[arg-type]


def vertices(body: dict, name: str | None = None) -> np.ndarray:  # type: ignore[type-arg]
    if name is None:
        return np.array(body["vertices"], dtype=float)
    return np.array(body["companions"][name]["vertices"], dtype=float)


@pytest.mark.parametrize(
    "params",
    [{}, {"h": 2.0, "x_min": -1.0, "x_max": 4.0, "count": 41, "triangles": 3}],
)
def test_figure_2_draws_the_smooth_tractrix_data(
    client: TestClient, params: dict[str, float]
) -> None:
    root = parse(client.get("/figures/figure-2.svg", params=params).content)
    query = {"x_min": -2.0, "x_max": 2.0, "count": 101, **params}
    query.pop("triangles", None)
    body = client.get("/smooth/tractrix", params=query).json()
    inverse = inverse_transform(root)
    tol = inverse.resolution
    assert inverse.bx == pytest.approx(inverse.by, rel=1e-5)
    np.testing.assert_allclose(drawn(root, "tractrix", inverse), vertices(body), atol=tol)
    np.testing.assert_allclose(drawn(root, "evolute", inverse), vertices(body, "evolute"), atol=tol)
    np.testing.assert_allclose(
        drawn(root, "catenary", inverse), vertices(body, "catenary"), atol=tol
    )
    # the triangles (x, 0), p(x), d(x) are drawn at samples of the JSON, right-angled at d(x)
    marks = inverse(circle_pixels(series(root, "axis_points")))
    assert len(marks) == params.get("triangles", 6)
    axis = vertices(body, "axis_points")
    chosen = [int(np.argmin(np.abs(axis[:, 0] - x))) for x in marks[:, 0]]
    np.testing.assert_allclose(marks, axis[chosen], atol=tol)
    sides = inverse(segment_pixels(series(root, "triangles")).reshape(-1, 2)).reshape(3, -1, 2, 2)
    np.testing.assert_allclose(sides[0, :, 1], vertices(body, "evolute")[chosen], atol=tol)
    np.testing.assert_allclose(sides[1, :, 1], vertices(body)[chosen], atol=tol)
    to_p = sides[1, :, 0] - sides[1, :, 1]  # from d(x) to p(x)
    to_x = sides[2, :, 1] - sides[2, :, 0]  # from d(x) to (x, 0)
    cosine = np.sum(to_p * to_x, axis=1) / np.hypot(*to_p.T) / np.hypot(*to_x.T)
    assert np.max(np.abs(cosine)) < 0.01


@pytest.mark.parametrize("params", [{}, {"h": 2.0, "s": 0.5, "i_min": -2, "i_max": 6}])
def test_figure_3_draws_the_d4a_data(client: TestClient, params: dict[str, float]) -> None:
    root = parse(client.get("/figures/figure-3.svg", params=params).content)
    query = {"s": 0.3, "i_min": -4, "i_max": 3, **params}
    body = client.get("/discretizations/d4a", params=query).json()
    inverse = inverse_transform(root)
    tol = inverse.resolution
    np.testing.assert_allclose(drawn(root, "p", inverse), vertices(body), atol=tol)
    tractrix = vertices(body, "tractrix")
    np.testing.assert_allclose(drawn(root, "tractrix", inverse), tractrix, atol=tol)
    np.testing.assert_allclose(drawn(root, "darboux", inverse), vertices(body, "darboux"), atol=tol)
    axis = vertices(body, "axis_points")
    np.testing.assert_allclose(inverse(circle_pixels(series(root, "axis_points"))), axis, atol=tol)
    sticks = inverse(segment_pixels(series(root, "sticks")).reshape(-1, 2)).reshape(-1, 2, 2)
    np.testing.assert_allclose(sticks[:, 1], tractrix, atol=tol)
    lengths = np.hypot(*(sticks[:, 1] - sticks[:, 0]).T)
    np.testing.assert_allclose(lengths, query.get("h", 1.0), atol=2 * tol)
    # the black points: e_i is x_i reflected in them, and they are midpoints of tractrix edges
    midpoints = inverse(circle_pixels(series(root, "midpoints")))
    np.testing.assert_allclose(2 * midpoints - axis, vertices(body, "darboux"), atol=2 * tol)
    edge_midpoints = (tractrix[1:] + tractrix[:-1]) / 2
    inner = midpoints[1:-1]
    gaps = np.min(np.hypot(*(inner[:, None, :] - edge_midpoints[None, :, :]).T), axis=0)
    assert np.max(gaps) < 2 * tol


def mesh_points(part: object, inverse: Inverse) -> np.ndarray:
    pairs = segment_pixels(series(part, "mesh"))  # type: ignore[arg-type]
    return inverse(pairs.reshape(-1, 2))


@pytest.mark.parametrize(
    "params", [{}, {"f0": 0.5, "f1": 1.2, "i_min": -2, "i_max": 5, "columns": 5}]
)
def test_figure_5_draws_the_d2a_quad_data_and_a_conformal_mesh(
    client: TestClient, params: dict[str, float]
) -> None:
    root = parse(client.get("/figures/figure-5.svg", params=params).content)
    assert panel_names(root) == ["left", "centre", "right"]
    query = {"i_min": -4, "i_max": 4, **{k: v for k, v in params.items() if k != "columns"}}
    body = client.get("/discretizations/d2a-quad", params=query).json()
    f0, f1 = params.get("f0", 1.0), params.get("f1", 1.5)
    for name, data in (("right", vertices(body)), ("centre", vertices(body, "gauss_image"))):
        part = panel(root, name)
        inverse = inverse_transform(part)
        series_name = "p" if name == "right" else "gauss_image"
        np.testing.assert_allclose(drawn(part, series_name, inverse), data, atol=inverse.resolution)
    left = panel(root, "left")
    inverse = inverse_transform(left)
    tol = inverse.resolution
    f = vertices(body, "conformal")
    np.testing.assert_allclose(inverse(circle_pixels(series(left, "conformal"))), f, atol=tol)
    # every mesh vertex lies on a ring of radius f_i, at a multiple of the conformal angle v
    points = mesh_points(left, inverse)
    radius, angle = np.hypot(*points.T), np.arctan2(points[:, 1], points[:, 0])
    angle[angle < -1e-3] += 2 * np.pi  # column 0 at angle 0, the others counter-clockwise
    assert np.max(np.min(np.abs(radius[:, None] - f[None, :, 0]), axis=1)) < 2 * tol
    v = 2 * math.asin((f1 - f0) / (2 * math.sqrt(f0 * f1)))
    steps = angle / v
    far = radius > 0.5  # directions are only sharp away from the centre
    np.testing.assert_allclose(steps[far], np.round(steps[far]), atol=2 * tol / 0.5 / v)
    columns = params.get("columns", math.floor(2 * math.pi / v))
    assert int(np.round(steps).max()) == columns
    assert (
        len(segment_pixels(series(left, "mesh"))) == (len(f) - 1) * (columns + 1) + len(f) * columns
    )


@pytest.mark.parametrize(
    "params", [{}, {"a": 0.5, "b": 3.0, "lambda": 0.3, "i_min": -1, "i_max": 5, "m": 5}]
)
def test_figure_6_draws_the_d2a_hex_data_and_a_hexagonal_mesh(
    client: TestClient, params: dict[str, float]
) -> None:
    root = parse(client.get("/figures/figure-6.svg", params=params).content)
    query = {"i_min": -4, "i_max": 4, **{k: v for k, v in params.items() if k != "m"}}
    body = client.get("/discretizations/d2a-hex", params=query).json()
    for name, series_name, data in (
        ("right", "p", vertices(body)),
        ("centre", "gauss_image", vertices(body, "gauss_image")),
    ):
        part = panel(root, name)
        inverse = inverse_transform(part)
        np.testing.assert_allclose(drawn(part, series_name, inverse), data, atol=inverse.resolution)
    left = panel(root, "left")
    inverse = inverse_transform(left)
    tol = inverse.resolution
    f = vertices(body, "conformal")[:, 0]
    np.testing.assert_allclose(inverse(circle_pixels(series(left, "conformal")))[:, 0], f, atol=tol)
    # rays π/m apart; even rays carry the f_i, odd ones √(a/b) f_{i+1} (f_{i_max+1} from the JSON
    # of one more index)
    a, b = params.get("a", 1.0), params.get("b", 2.5)
    m = params.get("m", 12)
    longer = client.get(
        "/discretizations/d2a-hex", params={**query, "i_max": query["i_max"] + 1}
    ).json()
    g = math.sqrt(a / b) * vertices(longer, "conformal")[1:, 0]
    points = mesh_points(left, inverse)
    radius, angle = np.hypot(*points.T), np.arctan2(points[:, 1], points[:, 0]) % (2 * np.pi)
    ray = np.round(angle / (math.pi / m)).astype(int) % (2 * m)
    far = radius > 0.5
    turn = (angle - ray * math.pi / m + math.pi) % (2 * math.pi) - math.pi
    np.testing.assert_allclose(turn[far], 0, atol=2 * tol / 0.5)
    rings = np.where(ray % 2 == 0, 0, 1)
    for parity, allowed in ((0, f), (1, g)):
        chosen = radius[rings == parity]
        assert np.max(np.min(np.abs(chosen[:, None] - allowed[None, :]), axis=1)) < 2 * tol
    assert len(set(ray.tolist())) == 2 * m


@pytest.mark.parametrize("params", [{}, {"h": 1.5, "d": 0.1, "i_min": -2, "i_max": 7}])
def test_figure_7_draws_the_d4b_gauss_images(client: TestClient, params: dict[str, float]) -> None:
    root = parse(client.get("/figures/figure-7.svg", params=params).content)
    query = {"d": 0.2, "i_min": -4, "i_max": 4, **params}
    body = client.get("/discretizations/d4b", params=query).json()
    checks = (
        ("left", "tractrix", "tractrix"),
        ("centre", "tractrix_gauss_image", "tractrix_gauss_image"),
        ("right", "gauss_image", "gauss_image"),
    )
    for name, series_name, companion in checks:
        part = panel(root, name)
        inverse = inverse_transform(part)
        np.testing.assert_allclose(
            drawn(part, series_name, inverse), vertices(body, companion), atol=inverse.resolution
        )
    right = panel(root, "right")
    inverse = inverse_transform(right)
    tol = inverse.resolution
    contact = vertices(body, "contact_points")
    np.testing.assert_allclose(
        inverse(circle_pixels(series(right, "contact_points"))), contact, atol=tol
    )
    # the caption: m_i is the midpoint of the drawn chord ñ_{i−1} ñ_i reflected in the circle
    m = drawn(right, "gauss_image", inverse)
    chords = inverse(segment_pixels(series(right, "chords")).reshape(-1, 2)).reshape(-1, 2, 2)
    middle = chords.mean(axis=1)
    np.testing.assert_allclose(middle / np.sum(middle**2, axis=1)[:, None], m[1:], atol=4 * tol)
    # the drawn m_i edges are tangent to the unit circle: their lines are 1 from the centre
    edge = m[1:] - m[:-1]
    distance = np.abs(m[:-1, 0] * edge[:, 1] - m[:-1, 1] * edge[:, 0]) / np.hypot(*edge.T)
    np.testing.assert_allclose(distance, 1, atol=4 * tol)
    # and the drawn n_i lie on it
    centre = panel(root, "centre")
    inverse = inverse_transform(centre)
    n = drawn(centre, "tractrix_gauss_image", inverse)
    np.testing.assert_allclose(np.hypot(*n.T), 1, atol=2 * inverse.resolution)


@pytest.mark.parametrize(
    "params", [{}, {"j": "2,3", "eps": 0.2}, {"sequence": "remark-13", "j": "1,4"}]
)
def test_figure_8_draws_the_d2b_sequence_and_the_band(
    client: TestClient, params: dict[str, object]
) -> None:
    root = parse(client.get("/figures/figure-8.svg", params=params).content)
    sequence = params.get("sequence", "example-12")
    js = [int(j) for j in str(params.get("j", "1,2,5")).split(",")]
    eps = float(params.get("eps", 0.1))  # type: ignore[arg-type]
    bodies = [
        client.get("/discretizations/d2b", params={"sequence": sequence, "j": j}).json() for j in js
    ]
    left = panel(root, "left")
    inverse = inverse_transform(left)
    np.testing.assert_allclose(
        drawn(left, "gauss_image", inverse),
        vertices(bodies[0], "gauss_image"),
        atol=inverse.resolution,
    )
    centre = panel(root, "centre")
    inverse = inverse_transform(centre)
    np.testing.assert_allclose(
        drawn(centre, "p", inverse), vertices(bodies[0]), atol=inverse.resolution
    )
    right = panel(root, "right")
    inverse = inverse_transform(right)
    tol = inverse.resolution
    for j, body in zip(js, bodies, strict=True):
        np.testing.assert_allclose(drawn(right, f"p-{j}", inverse), vertices(body), atol=tol)
    xs = np.concatenate([vertices(body)[:, 0] for body in bodies])
    catenary = client.get(
        "/smooth/catenary", params={"x_min": xs.min(), "x_max": xs.max(), "count": 201}
    ).json()
    np.testing.assert_allclose(drawn(right, "catenary", inverse), vertices(catenary), atol=tol)
    # the band's outline is at distance ε from C (C sampled densely near each outline point:
    # the nearest point of C is less than ε away horizontally)
    outline = inverse(polygon_pixels(series(right, "band")))
    t = outline[:, :1] + np.linspace(-1.5 * eps, 1.5 * eps, 3001)[None, :]
    nearest = np.min(np.hypot(t - outline[:, :1], np.cosh(t) - outline[:, 1:]), axis=1)
    np.testing.assert_allclose(nearest, eps, atol=3 * tol + 1e-6)


@pytest.mark.parametrize(
    ("path", "params", "parameter"),
    [
        ("figure-5", {"f1": 6.0}, "f1"),
        ("figure-5", {"columns": 0}, "columns"),
        ("figure-5", {"columns": 17}, "columns"),
        ("figure-5", {"i_max": 61}, "i_max"),
        ("figure-6", {"m": 1}, "m"),
        ("figure-6", {"lambda": 1.5}, "lambda"),
        ("figure-8", {"j": "1,0"}, "j.1"),
        ("figure-8", {"j": "1,2000"}, "j.1"),
        ("figure-8", {"eps": 1.0}, "eps"),
        ("figure-8", {"sequence": "custom"}, "sequence"),
        ("figure-2", {"x_min": 1.0, "x_max": 0.0}, "x_max"),
        ("figure-2", {"triangles": 51}, "triangles"),
        ("figure-3", {"s": 1.5}, "s"),
        ("figure-7", {"d": 1.0}, "d"),
    ],
)
def test_every_figure_refuses_bad_parameters_naming_them(
    client: TestClient, path: str, params: dict[str, object], parameter: str
) -> None:
    response = client.get(f"/figures/{path}.svg", params=params)
    assert response.status_code == 422, response.text
    assert response.headers["content-type"] == "application/problem+json"
    assert response.json()["errors"][0]["parameter"] == parameter
