"""GET /convergence and /convergence/{id}: statuses, bodies, formats, limits and errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.registry import STUDIES
from app.schemas.convergence import ConvergenceResponse, StudyEntry
from app.settings import Settings
from tests.svg_reading import inverse_transform, parse, polyline_pixels, series, series_names

SMALL = {"levels": 4, "samples": 21, "x_max": 1.0}


def test_catalog_lists_every_study_with_parameters_and_measures(client: TestClient) -> None:
    body = client.get("/convergence").json()
    assert [s["id"] for s in body] == list(STUDIES) == ["theorem-11", "theorem-14", "theorem-15"]
    for entry in body:
        StudyEntry.model_validate(entry)
        parameters = {p["name"]: p for p in entry["parameters"]}
        assert entry["statements"][0] == entry["id"]
        if entry["id"] == "theorem-11":
            assert parameters["j0"]["domain"] == "j0 >= 1" and parameters["j0"]["default"] == 4
            assert parameters["levels"]["default"] == 7
            assert {m["id"] for m in entry["measures"]} >= {"example-12", "remark-13"}
            continue
        assert parameters["d0"]["domain"] == "0 < d0 < h" and parameters["d0"]["default"] == 0.2
        assert parameters["levels"]["default"] == 8
        assert {m["id"] for m in entry["measures"]} >= {"parametric", "distance", "vertices"}


def test_theorem_11_study_response(client: TestClient) -> None:
    params = {"j0": 4, "levels": 4, "i_min": -1, "i_max": 8}
    response = client.get("/convergence/theorem-11", params=params)
    assert response.status_code == 200
    body = ConvergenceResponse.model_validate(response.json())
    assert body.parameters == params
    assert body.step_name == "1/j"
    assert [level.step for level in body.levels] == [1 / 4, 1 / 8, 1 / 16, 1 / 32]
    assert all(check.holds is True for check in body.checks)
    orders = {m.id: m for m in body.measures}
    for key in ("example-12", "example-12-distance", "remark-13", "remark-13-distance"):
        assert orders[key].observed_order == pytest.approx(2, abs=0.15), key
    assert orders["remark-13-domain"].observed_order == pytest.approx(0, abs=0.15)
    checks = {c.id: c for c in body.checks}
    assert checks["remark-13-uniform"].erratum is not None
    assert checks["remark-13-uniform"].erratum.link == "/errata/E66"
    svg = client.get("/convergence/theorem-11", params={**params, "format": "svg"})
    assert svg.status_code == 200 and "log10 1/j" in svg.text
    csv = client.get("/convergence/theorem-11", params={**params, "format": "csv"})
    assert csv.text.startswith("level,1/j,measure,error,resolved\n")
    mp = client.get("/convergence/theorem-11", params={"levels": 2, "precision": "mp"})
    assert mp.status_code == 200 and all(c["holds"] for c in mp.json()["checks"])


@pytest.mark.parametrize(
    ("params", "parameter", "constraint"),
    [
        ({"j0": 0}, "j0", "j0 >= 1"),
        ({"i_min": -2}, "i_min", "i_min > −j0/2"),
        ({"i_max": 0}, "i_max", "i_max >= 1"),
        ({"levels": 17}, "levels", "levels <= 16"),
        ({"levels": 16}, "levels", "construction steps over all levels <= 500000"),
        ({"precision": "mp"}, "digits", "(digits + 200) × work <= 1000000"),
        ({"d0": 0.1}, "d0", "not a parameter of this endpoint"),
    ],
)
def test_theorem_11_study_refuses_bad_parameters(
    client: TestClient, params: dict, parameter: str, constraint: str
) -> None:
    response = client.get("/convergence/theorem-11", params=params)
    assert response.status_code == 422
    (error,) = response.json()["errors"]
    assert error["parameter"] == parameter
    assert constraint in error["constraint"]


@pytest.mark.parametrize("identifier", ["theorem-14", "theorem-15"])
def test_study_response_is_valid_and_consistent(client: TestClient, identifier: str) -> None:
    response = client.get(f"/convergence/{identifier}", params=SMALL)
    assert response.status_code == 200
    body = ConvergenceResponse.model_validate(response.json())
    assert body.parameters == {"h": 1.0, "d0": 0.2, "x_max": 1.0, "samples": 21, "levels": 4}
    assert [level.step for level in body.levels] == [0.2, 0.1, 0.05, 0.025]
    assert all(check.holds is True for check in body.checks)
    for measure in body.measures:
        errors = [level.errors[measure.id] for level in body.levels]
        assert all(e is not None and e > 0 for e in errors)
        # the reported order is the least-squares slope of the reported errors
        slope = np.polyfit(np.log([lv.step for lv in body.levels]), np.log(errors), 1)[0]
        assert measure.observed_order == pytest.approx(slope, rel=1e-9)
        assert measure.observed_order == pytest.approx(measure.expected_order, abs=0.1)


def test_tractrix_orders_one_and_two(client: TestClient) -> None:
    body = client.get("/convergence/theorem-15").json()
    orders = {m["id"]: m["observed_order"] for m in body["measures"]}
    assert orders["parametric"] == pytest.approx(1, abs=0.01)
    assert orders["distance"] == pytest.approx(2, abs=0.01)
    checks = {c["id"]: c for c in body["checks"]}
    assert checks["theorem-15-proof-y"]["erratum"]["id"] == "E80"
    assert checks["theorem-15-proof-x"]["erratum"]["link"] == "/errata/E81"


def test_mp_study_reports_numbers(client: TestClient) -> None:
    params = {**SMALL, "levels": 3, "samples": 5, "precision": "mp", "digits": 30}
    body = client.get("/convergence/theorem-14", params=params).json()
    assert body["precision"] == {"mode": "mp", "digits": 30}
    assert isinstance(body["levels"][0]["errors"]["parametric"], float)
    identities = [c for c in body["checks"] if c["tolerance"] < 1e-20]
    assert identities and all(c["residual"] < 1e-35 for c in identities)


def test_csv_lists_every_level_and_measure(client: TestClient) -> None:
    body = client.get("/convergence/theorem-14", params=SMALL).json()
    csv = client.get("/convergence/theorem-14", params={**SMALL, "format": "csv"})
    assert csv.headers["content-type"].startswith("text/csv")
    lines = csv.text.strip().split("\n")
    assert lines[0] == "level,d,measure,error,resolved"
    rows = [line.split(",") for line in lines[1:]]
    assert len(rows) == len(body["levels"]) * len(body["measures"])
    for level, step, measure, error, resolved in rows:
        expected = body["levels"][int(level)]
        assert float(step) == expected["step"]
        assert float(error) == expected["errors"][measure]
        assert (resolved == "true") is expected["resolved"][measure]


def test_svg_draws_log_errors_and_fitted_lines(client: TestClient) -> None:
    body = client.get("/convergence/theorem-15", params=SMALL).json()
    response = client.get("/convergence/theorem-15", params={**SMALL, "format": "svg"})
    assert response.headers["content-type"] == "image/svg+xml"
    root = parse(response.content)
    names = series_names(root)
    assert [m["id"] for m in body["measures"]] == [n for n in names if not n.endswith("-fit")]
    inverse = inverse_transform(root)
    steps = np.log10([level["step"] for level in body["levels"]])
    for measure in body["measures"]:
        errors = np.log10([level["errors"][measure["id"]] for level in body["levels"]])
        drawn = inverse(polyline_pixels(series(root, measure["id"])))
        np.testing.assert_allclose(drawn, np.stack([steps, errors], 1), atol=inverse.resolution)
        fit = inverse(polyline_pixels(series(root, f"{measure['id']}-fit")))
        line = math.log10(measure["constant"]) + measure["observed_order"] * fit[:, 0]
        np.testing.assert_allclose(fit[:, 1], line, atol=4 * inverse.resolution)


@pytest.mark.parametrize(
    ("params", "parameter", "constraint"),
    [
        ({"d0": 1.5}, "d0", "0 < d0 < h"),
        ({"x_max": 0.1}, "x_max", "d0 <= x_max"),
        ({"x_max": 30}, "x_max", "x_max <= 20·h"),
        ({"levels": 1}, "levels", "levels >= 2"),
        ({"levels": 17}, "levels", "levels <= 16"),
        ({"samples": 20_000}, "samples", "samples <= 10001"),
        ({"levels": 16}, "levels", "construction steps over all levels <= 500000"),
        ({"precision": "mp"}, "digits", "(digits + 200) × work <= 1000000"),
        ({"precision": "mp", "digits": 2000}, "digits", "1 <= digits <= 1000"),
        ({"h": "abc"}, "h", "valid number"),
        ({"zeta": 1}, "zeta", "not a parameter of this endpoint"),
    ],
)
def test_invalid_or_oversize_requests_are_422(
    client: TestClient, params: dict, parameter: str, constraint: str
) -> None:
    response = client.get("/convergence/theorem-14", params=params)
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    (error,) = response.json()["errors"]
    assert error["parameter"] == parameter
    assert constraint in error["constraint"]


def test_limits_come_from_the_settings() -> None:
    client = TestClient(create_app(Settings(max_convergence_steps=100, max_convergence_levels=3)))
    assert client.get("/convergence/theorem-15", params={"levels": 4}).status_code == 422
    response = client.get("/convergence/theorem-15", params={"levels": 3, "x_max": 20})
    assert response.status_code == 422
    assert "<= 100" in response.json()["errors"][0]["constraint"]
    assert client.get("/convergence/theorem-15", params={"levels": 3}).status_code == 200


def test_unknown_study_is_404_with_the_valid_ids(client: TestClient) -> None:
    response = client.get("/convergence/theorem-99")
    assert response.status_code == 404
    assert response.json()["valid"] == ["theorem-11", "theorem-14", "theorem-15"]


def test_studies_are_cached_with_an_etag(client: TestClient) -> None:
    first = client.get("/convergence/theorem-14", params=SMALL)
    again = client.get(
        "/convergence/theorem-14", params=SMALL, headers={"If-None-Match": first.headers["etag"]}
    )
    assert again.status_code == 304
    assert first.headers["cache-control"].startswith("public, max-age=")
