"""GET /relations: the matrix against an independent high-precision computation, cell by cell."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.geometry import relations
from app.main import create_app
from app.registry import DISCRETIZATIONS
from app.schemas.relations import RelationsResponse
from app.settings import Settings
from tests.reference import (
    curvature as reference_curvature,
    d1 as reference_d1,
    d2a as reference_d2a,
    d3 as reference_d3,
    d4a as reference_d4a,
    d4b as reference_d4b,
    relations as reference,
)
from tests.svg_reading import parse

CONDITIONS = ("d1", "d3", "equation-2", "equation-7")
POSITIVE = {"d1", "d3", "equation-2"}


def reference_polygon(row: dict[str, Any], given: dict[str, Any]) -> dict:
    """The row's polygon from the independent references (tests/reference).

    r is passed only when the request gave it (else each reference uses its own r*: the row
    shows r* rounded to float64).
    """
    q = row["parameters"]
    r = repr(float(given[f"{row['id']}.r"])) if f"{row['id']}.r" in given else None
    if row["id"] == "d4b":
        beta0 = None if q["beta0"] == 1.5707963267948966 else repr(q["beta0"])
        return reference_d4b.construct(repr(q["h"]), repr(q["d"]), beta0, q["i_min"], q["i_max"])[0]
    if row["id"] == "d2a-quad":
        return reference_d2a.quad(repr(q["f0"]), repr(q["f1"]), r, q["i_min"], q["i_max"])[0]
    if row["id"] == "d2a-hex":
        return reference_d2a.hexagonal(
            repr(q["a"]), repr(q["b"]), repr(q["lambda"]), r, q["i_min"], q["i_max"]
        )[0]
    if row["id"] == "d1":
        args = [repr(q[k]) for k in ("c", "delta", "y0", "y1")]
        return reference_d1.construct(*args, q["i_min"], q["i_max"])
    if row["id"] == "d3":
        args = [repr(q[k]) for k in ("c", "delta", "y0")]
        return reference_d3.construct(*args, q["branch"], q["i_min"], q["i_max"])
    if row["id"] == "d4a":
        beta0 = None if q["beta0"] == 1.5707963267948966 else repr(q["beta0"])
        return reference_d4a.construct(repr(q["h"]), repr(q["s"]), beta0, q["i_min"], q["i_max"])[0]
    if row["id"] == "d2b" and q["sequence"] == "example-12":
        ctx = reference_curvature.context()
        j = ctx.mpf(q["j"])
        s = {i: 4 * ctx.mpf(i) ** 2 / (j * j + 4 * ctx.mpf(i) ** 2) for i in range(q["i_max"] + 1)}
        return reference_curvature.d2b(ctx, s)[0]
    raise AssertionError(f"no reference for {row['id']}: add one in tests/reference")


def reference_surfaces(row: dict[str, Any], given: dict[str, Any]) -> dict[str, Any]:
    """The reference's expected curvature cells of a row: {"H": (a, residual), "K": ...}.

    The Gauss images come from tests/reference as well: d2a's φ, d2b's n, d4b's circumscribed m
    (tangents at the contact points, ``lu_solve``) and inscribed n (second intersections with
    the circle); rows without a Gauss image get the circumscribed one built from p.
    """
    q = row["parameters"]
    ctx = reference_curvature.context()
    if row["id"] == "d4b":
        beta0 = None if q["beta0"] == 1.5707963267948966 else repr(q["beta0"])
        i_min, i_max = q["i_min"], q["i_max"]
        lo, hi = min(0, i_min - 1), max(0, i_max + 1)
        p, tractrix, axis = reference_d4b.construct(repr(q["h"]), repr(q["d"]), beta0, lo, hi)
        stick = (tractrix[0][0] - axis[0][0], tractrix[0][1] - axis[0][1])
        length = ctx.sqrt(stick[0] ** 2 + stick[1] ** 2)
        n = reference_curvature.inscribed(ctx, tractrix, 0, (stick[1] / length, -stick[0] / length))
        m = reference_curvature.circumscribed(ctx, reference_curvature.contact_points(ctx, p))
        keep = range(i_min, i_max + 1)
        return {
            "H": reference.mean_curvature_cell({i: p[i] for i in keep}, {i: m[i] for i in keep}),
            "K": reference.gaussian_curvature_cell(
                {i: tractrix[i] for i in keep}, {i: n[i] for i in keep}
            ),
        }
    polygon = reference_polygon(row, given)
    gauss = None
    if row["id"] in ("d2a-quad", "d2a-hex"):
        r = repr(float(given[f"{row['id']}.r"])) if f"{row['id']}.r" in given else None
        if row["id"] == "d2a-quad":
            _, gauss, _ = reference_d2a.quad(
                repr(q["f0"]), repr(q["f1"]), r, q["i_min"], q["i_max"]
            )
        else:
            _, gauss, _ = reference_d2a.hexagonal(
                repr(q["a"]), repr(q["b"]), repr(q["lambda"]), r, q["i_min"], q["i_max"]
            )
    elif row["id"] == "d2b":
        j = ctx.mpf(q["j"])
        s = {i: 4 * ctx.mpf(i) ** 2 / (j * j + 4 * ctx.mpf(i) ** 2) for i in range(q["i_max"] + 1)}
        gauss = reference_curvature.d2b(ctx, s)[1]
    return {"H": reference.mean_curvature_cell(polygon, gauss), "K": None}


def assert_curvature_cells_agree(
    row: dict[str, Any], expected: dict[str, Any], constant_tol: float, residual_tol: float
) -> None:
    cells = {c["property"]: c for c in row["cells"]}
    for key, name, column in (
        ("H", "a", "mean-curvature-zero"),
        ("K", "K", "gaussian-curvature-constant"),
    ):
        cell = cells[column]
        if expected[key] is None:
            assert cell["holds"] is None and cell["residual"] is None, (row["id"], column)
            assert cell["note"].startswith("not applicable"), (row["id"], column)
            continue
        constant, residual = expected[key]
        if constant is None:
            assert name not in cell["constants"], (row["id"], column)
        else:
            got = float(cell["constants"][name])
            assert got == pytest.approx(float(constant), rel=constant_tol), (row["id"], column)
        ref = float(residual)
        # mp: an upper bound rounded up to 10 digits, a decimal string (as the tolerance)
        slack = max(residual_tol * ref, 4 * math.ulp(ref), 1e-9 * ref)
        got, tolerance = float(cell["residual"]), float(cell["tolerance"])
        assert abs(got - ref) <= tolerance + slack, (row["id"], column, got, ref)
        assert cell["holds"] is (ref <= tolerance), (row["id"], column)


def assert_cells_agree(
    body: dict[str, Any], constant_tol: float, residual_tol: float, given: dict | None = None
) -> None:
    for row in body["rows"]:
        assert_curvature_cells_agree(
            row, reference_surfaces(row, given or {}), constant_tol, residual_tol
        )
        expected = reference.conditions(reference_polygon(row, given or {}))
        cells = {c["property"]: c for c in row["cells"]}
        for key in CONDITIONS:
            cell, (constants, residual) = cells[key], expected[key]
            names = ["c"] if len(constants) == 1 else ["c1", "c2"]
            for name, value in zip(names, constants, strict=True):
                got = float(cell["constants"][name])
                assert got == pytest.approx(float(value), rel=constant_tol), (row["id"], key, name)
            ref = float(residual)
            # residuals at rounding level agree within the tolerance; real misfits relatively
            # (in mp a residual is a rigorous upper bound rounded up to a float: 4 ulp)
            # (mp: decimal strings, the residual rounded up to 10 digits)
            slack = max(residual_tol * ref, 4 * math.ulp(ref), 1e-9 * ref)
            got, tolerance = float(cell["residual"]), float(cell["tolerance"])
            assert abs(got - ref) <= tolerance + slack, (row["id"], key)
            verdict = ref <= tolerance and (key not in POSITIVE or float(constants[0]) > 0)
            assert cell["holds"] is verdict, (row["id"], key)


def test_default_matrix_agrees_with_the_reference_cell_by_cell(client: TestClient) -> None:
    response = client.get("/relations")
    assert response.status_code == 200
    body = response.json()
    RelationsResponse.model_validate(body)
    assert [r["id"] for r in body["rows"]] == list(DISCRETIZATIONS)
    assert [c["id"] for c in body["columns"]] == [p.id for p in relations.PROPERTIES]
    assert_cells_agree(body, 1e-12, 1e-9)


def test_matrix_at_40_digits_agrees_with_the_reference(client: TestClient) -> None:
    body = client.get("/relations", params={"precision": "mp", "digits": 40}).json()
    assert body["precision"] == {"mode": "mp", "digits": 40}
    assert isinstance(body["rows"][0]["cells"][0]["constants"]["c"], str)
    assert_cells_agree(body, 1e-35, 1e-30)


def test_verdicts_of_section_4(client: TestClient) -> None:
    body = client.get("/relations").json()
    table = {r["id"]: {c["property"]: c["holds"] for c in r["cells"]} for r in body["rows"]}
    assert table["d4b"] == {
        "d1": True,
        "d3": True,
        "equation-2": True,
        "equation-7": True,
        "mean-curvature-zero": True,
        "gaussian-curvature-constant": True,
    }
    assert [table["d2a-quad"][k] for k in CONDITIONS] == [False, False, True, True]
    assert [table["d2a-hex"][k] for k in CONDITIONS] == [False, False, False, True]
    # Section 5: which rows generate discrete minimal surfaces (H = 0), and which a surface of
    # constant K (only (D4b)'s pseudosphere has one with a Gauss image)
    minimal = {k: v["mean-curvature-zero"] for k, v in table.items()}
    assert minimal == {
        "d1": True,  # the default (D1) polygon has offset C = 0 (y0 = δ/(2c))
        "d2a-quad": True,  # the Christoffel dual at r*
        "d2a-hex": False,  # the hexagonal meridian as a quad surface of revolution
        "d2b": True,
        "d3": True,
        "d4a": True,
        "d4b": True,
    }
    constant = {k: v["gaussian-curvature-constant"] for k, v in table.items()}
    assert constant == {k: (True if k == "d4b" else None) for k in table}


def test_rows_take_their_own_parameters(client: TestClient) -> None:
    params = {
        "d4b.h": 2.0,
        "d4b.d": 0.7,
        "d4b.beta0": 0.9,
        "d4b.i_min": -4,
        "d2a-quad.r": 0.0,  # off r*: Theorem 1 fails
        "d2a-hex.lambda": 0.3,
        "d2a-hex.b": 2.1,
        "d2a-hex.a": 1.3,
        "d1.c": 0.2,  # offset C = −0.225: (D1) only
        "d1.delta": 0.5,
        "d1.y1": 1.1,
        "d4a.s": 0.3,
        "d4a.beta0": 2.0,
    }
    body = client.get("/relations", params=params).json()
    rows = {r["id"]: r for r in body["rows"]}
    assert rows["d4b"]["parameters"]["d"] == 0.7 and rows["d4b"]["parameters"]["i_min"] == -4
    assert rows["d2a-hex"]["parameters"]["lambda"] == 0.3
    quad = {c["property"]: c["holds"] for c in rows["d2a-quad"]["cells"]}
    assert quad["equation-2"] is False
    assert quad["mean-curvature-zero"] is False  # the Christoffel dual needs r = r*
    d1 = {c["property"]: c["holds"] for c in rows["d1"]["cells"]}
    assert d1["d1"] is True and d1["d3"] is False and d1["mean-curvature-zero"] is False
    d4a = {c["property"]: c for c in rows["d4a"]["cells"]}["mean-curvature-zero"]
    assert d4a["holds"] is True and float(d4a["constants"]["a"]) == pytest.approx(0.85)  # h − s/2
    K = {c["property"]: c for c in rows["d4b"]["cells"]}["gaussian-curvature-constant"]
    assert K["holds"] is True and float(K["constants"]["K"]) == pytest.approx(-0.25)  # −1/h²
    assert_cells_agree(body, 1e-12, 1e-9, params)
    # the row's url serves the same polygon
    curve = client.get(rows["d4b"]["url"]).json()
    assert curve["parameters"] == rows["d4b"]["parameters"]


@pytest.mark.parametrize(
    ("params", "parameter", "constraint"),
    [
        ({"d4b.d": 2.0}, "d4b.d", "0 < d < h"),
        ({"d4b.h": -1}, "d4b.h", "d4b.h > 0"),
        ({"d2a-quad.f1": 0.5}, "d2a-quad.f1", "0 < f0 < f1"),
        ({"d2a-hex.lambda": 1.5}, "d2a-hex.lambda", "d2a-hex.lambda < 1"),
        ({"d4b.zeta": 1}, "d4b.zeta", "not a parameter of this endpoint"),
        ({"d4b.i_max": 200_000}, "d4b.i_max", "<= 100001"),
        ({"d4b.i_max": -20}, "d4b.i_max", "i_min <= i_max"),
        ({"precision": "mp", "digits": 5000}, "digits", "1 <= digits <= 1000"),
        ({"format": "png"}, "format", "format is one of"),
    ],
)
def test_invalid_parameters_are_422_naming_the_parameter(
    client: TestClient, params: dict, parameter: str, constraint: str
) -> None:
    response = client.get("/relations", params=params)
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    (error,) = response.json()["errors"]
    assert error["parameter"] == parameter
    assert constraint in error["constraint"]


def test_row_limit_comes_from_the_settings() -> None:
    client = TestClient(create_app(Settings(max_relation_vertices=50)))
    response = client.get("/relations", params={"d2a-hex.i_max": 45})
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == "d2a-hex.i_max"
    assert client.get("/relations", params={"d2a-hex.i_max": 39}).status_code == 200


def test_html_and_svg_tables_show_every_cell(client: TestClient) -> None:
    body = client.get("/relations").json()
    states = [
        "none" if c["holds"] is None else "holds" if c["holds"] else "fails"
        for r in body["rows"]
        for c in r["cells"]
    ]
    html = client.get("/relations", params={"format": "html"})
    assert html.status_code == 200 and html.headers["content-type"].startswith("text/html")
    assert "default-src 'none'" in html.headers["content-security-policy"]
    assert "<script" not in html.text
    found = [
        state for chunk in html.text.split("<td class=")[1:] for state in [chunk.split('"')[1]]
    ]
    assert found == states
    svg = client.get("/relations", params={"format": "svg"})
    assert svg.headers["content-type"] == "image/svg+xml"
    root = parse(svg.content)
    drawn = [
        g.get("class", "").split()[1]
        for g in root.iter("{http://www.w3.org/2000/svg}g")
        if g.get("class", "").startswith("cell ")
    ]
    assert drawn == states
    residual = body["rows"][1]["cells"][0]["residual"]
    assert f"residual {residual:.2e}" in svg.text and f"residual {residual:.2e}" in html.text


def test_relations_are_cached_with_an_etag(client: TestClient) -> None:
    first = client.get("/relations", params={"d4b.d": 0.2})
    etag = first.headers["etag"]
    again = client.get("/relations", params={"d4b.d": 0.2}, headers={"If-None-Match": etag})
    assert again.status_code == 304
    other = client.get("/relations", params={"d4b.d": 0.3})
    assert other.headers["etag"] != etag
