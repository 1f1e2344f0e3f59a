"""The verdict misfires of issue 15, each on true data (holds) and on false data (fails)."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient

QUAD_FAR = "f0=1&f1=1.5&i_min=100&i_max=120"


def _checks(client: TestClient, url: str) -> dict[str, dict]:  # type: ignore[type-arg]
    response = client.get(url)
    assert response.status_code == 200, response.text[:300]
    return {check["id"]: check for check in response.json()["checks"]}


@pytest.mark.parametrize("precision", ["", "&precision=mp&digits=40"])
def test_d1_d3_with_a_negative_constant_do_not_hold(client: TestClient, precision: str) -> None:
    checks = _checks(client, f"/discretizations/d2a-quad?{QUAD_FAR}{precision}")
    relations = client.get(
        "/relations?d2a-quad.f0=1&d2a-quad.f1=1.5&d2a-quad.i_min=100&d2a-quad.i_max=120" + precision
    ).json()
    row = next(row for row in relations["rows"] if row["id"] == "d2a-quad")
    cells = {cell["property"]: cell for cell in row["cells"]}
    for statement in ("d1", "d3"):
        residual, tolerance = checks[statement]["residual"], checks[statement]["tolerance"]
        assert float(residual) < float(tolerance)  # the fit is exact (mp: decimal strings)
        assert checks[statement]["holds"] is False  # but c < 0
        assert "not > 0" in checks[statement]["note"]
        if not precision:
            assert cells[statement]["holds"] is False
        theorem = client.get(f"/theorems/{statement}?discretization=d2a-quad&{QUAD_FAR}{precision}")
        assert theorem.json()["check"]["holds"] is False


def test_d1_d3_with_a_positive_constant_hold(client: TestClient) -> None:
    checks = _checks(client, "/discretizations/d4b")
    assert checks["theorem-4-i"]["holds"] is True
    assert checks["theorem-4-ii"]["holds"] is True


def test_lemma_10_says_why_its_printed_residual_is_null(client: TestClient) -> None:
    default = _checks(client, "/discretizations/d2b")["lemma-10"]
    assert default["erratum"]["printed_residual"] is None
    assert "remark-13" in default["note"]
    shown = _checks(client, "/discretizations/d2b?sequence=remark-13")["lemma-10"]
    assert shown["holds"] is True
    assert shown["erratum"]["printed_residual"] > 1e3 * shown["tolerance"]


def test_the_catenoid_gauss_image_overflow_is_gone(client: TestClient) -> None:
    response = client.get("/surfaces/catenoid-gauss-image?method=construction&i_max=1675")
    assert response.status_code == 200
    checks = {check["id"]: check for check in response.json()["checks"]}
    assert checks["face-planarity"]["holds"] is True
    assert checks["face-planarity"]["residual"] < 1e-14


def test_a_numerical_warning_in_the_server_is_a_422() -> None:
    from app.main import create_app
    from app.settings import Settings

    application = create_app(Settings())

    @application.get("/overflow")
    def overflow() -> float:
        return float(np.float64(1e308) * 10)

    response = TestClient(application).get("/overflow")
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == "precision"
