"""GET/POST /discretizations/d4b: bodies, formats, precisions, caching."""

from __future__ import annotations

import csv
import io
from decimal import Decimal

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.geometry.d4b import discretization as d4b
from app.geometry.precision import Float64
from app.schemas.curve import CurveResponse


def test_default_curve_matches_the_core_and_the_schema(client: TestClient) -> None:
    response = client.get("/discretizations/d4b")
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/json"
    body = response.json()
    CurveResponse.model_validate(body)
    assert body["parameters"] == {
        "h": 1.0,
        "d": 0.1,
        "beta0": np.pi / 2,
        "i_min": -10,
        "i_max": 10,
        "method": "construction",
    }
    assert body["indices"] == list(range(-10, 11))
    core = d4b.compute(Float64(), 1.0, 0.1, None, -10, 10)
    np.testing.assert_array_equal(np.array(body["vertices"]), core.polygon.vertices)
    assert set(body["companions"]) == {
        "tractrix",
        "axis_points",
        "darboux",
        "tractrix_gauss_image",
        "contact_points",
        "gauss_image",
    }
    assert body["vertices"][10] == [-0.1, 1.0]  # p_0 = (−d, h)
    assert body["vertices"][11] == [0.1, 1.0]  # p_1 = (d, h)
    assert all(check["holds"] for check in body["checks"])
    assert body["constants"]["d1"] == pytest.approx(0.1, rel=1e-12)


def test_post_body_gives_the_same_curve_as_get(client: TestClient) -> None:
    params = {"h": 2.0, "d": 0.3, "beta0": 1.0, "i_min": -4, "i_max": 7}
    got = client.get("/discretizations/d4b", params=params).json()
    posted = client.post("/discretizations/d4b", json=params)
    assert posted.status_code == 200
    assert posted.json() == got
    assert "etag" not in posted.headers


def test_mp_coordinates_are_decimal_strings_with_the_requested_digits(client: TestClient) -> None:
    body = client.get(
        "/discretizations/d4b", params={"precision": "mp", "digits": 40, "d": 0.3, "i_max": 3}
    ).json()
    assert body["precision"] == {"mode": "mp", "digits": 40}
    x, y = body["vertices"][-1]  # p_3 = (5d, ...)
    assert isinstance(y, str) and Decimal(x) == Decimal("1.5")
    digits = len(y.replace(".", "").lstrip("0"))
    assert 35 <= digits <= 40
    # p_3^y = √(h² − d²)·cosh(5L/2), L = ln((h+d)/(h−d)), from (14) at 50 digits
    import mpmath

    mpmath.mp.dps = 50
    L = mpmath.log(mpmath.mpf("1.3") / mpmath.mpf("0.7"))
    exact = mpmath.sqrt(1 - mpmath.mpf("0.09")) * mpmath.cosh(5 * L / 2)
    assert abs(mpmath.mpf(y) - exact) / exact < mpmath.mpf("1e-38")
    # residuals and tolerances are decimal strings too: rigorous bounds beyond the float range
    assert all(isinstance(c["residual"], str) for c in body["checks"])
    assert all(float(c["residual"]) <= float(c["tolerance"]) for c in body["checks"])
    assert isinstance(body["constants"]["d3"], str)


def test_csv_lists_the_polygon_then_the_companions(client: TestClient) -> None:
    response = client.get("/discretizations/d4b", params={"format": "csv", "i_min": 0, "i_max": 2})
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/csv")
    rows = list(csv.DictReader(io.StringIO(response.text)))
    names = ["p", "tractrix", "axis_points", "darboux"]
    names += ["tractrix_gauss_image", "contact_points", "gauss_image"]
    assert [r["curve"] for r in rows] == [name for name in names for _ in range(3)]
    assert (float(rows[1]["x"]), float(rows[1]["y"])) == (0.1, 1.0)
    assert (float(rows[3]["x"]), float(rows[3]["y"])) == (0.0, 1.0)  # d_0 = (0, h)


def test_closed_form_method_serves_long_ranges(client: TestClient) -> None:
    body = client.get(
        "/discretizations/d4b",
        params={"method": "closed-form", "d": 0.001, "i_min": -50000, "i_max": 50000},
    ).json()
    assert len(body["vertices"]) == 100001
    checks = {c["id"]: c for c in body["checks"]}
    assert checks["theorem-5"]["holds"] is None and "closed-form" in checks["theorem-5"]["note"]
    assert checks["recursion-13"]["holds"] is True


def test_detail_fills_per_index_residuals(client: TestClient) -> None:
    body = client.get(
        "/discretizations/d4b", params={"detail": True, "i_min": -3, "i_max": 3}
    ).json()
    check = next(c for c in body["checks"] if c["id"] == "theorem-5")
    assert check["per_index"]["indices"] == list(range(-3, 4))
    assert max(check["per_index"]["residuals"]) == check["residual"]


def test_etag_and_304(client: TestClient) -> None:
    first = client.get("/discretizations/d4b", params={"d": 0.2})
    etag = first.headers["etag"]
    assert first.headers["cache-control"].startswith("public, max-age=")
    again = client.get("/discretizations/d4b", params={"d": 0.2}, headers={"If-None-Match": etag})
    assert again.status_code == 304 and again.content == b""
    assert again.headers["etag"] == etag
    # same query spelled differently: same answer, same ETag
    spelled = client.get("/discretizations/d4b?d=0.20&h=1")
    assert spelled.headers["etag"] == etag
    other = client.get("/discretizations/d4b", params={"d": 0.3}, headers={"If-None-Match": etag})
    assert other.status_code == 200 and other.headers["etag"] != etag
