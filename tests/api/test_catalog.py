"""GET /health, /discretizations, /theorems and /theorems/{id}."""

from __future__ import annotations

import inspect

import pytest
from fastapi.testclient import TestClient

from app import __version__
from app.geometry.d4b import discretization as d4b
from app.registry import DISCRETIZATIONS
from app.schemas.catalog import StatementInfo, TheoremResponse
from app.schemas.surfaces import SurfaceQuery


def test_health(client: TestClient) -> None:
    assert client.get("/health").json() == {"status": "ok", "version": __version__}


def test_catalog_lists_d4b_with_domains_and_defaults(client: TestClient) -> None:
    (entry,) = [e for e in client.get("/discretizations").json() if e["id"] == "d4b"]
    parameters = {p["name"]: p for p in entry["parameters"]}
    assert parameters["d"]["domain"] == "0 < d < h"
    assert parameters["d"]["default"] == 0.1 and parameters["d"]["kind"] == "paper"
    assert parameters["precision"]["kind"] == "common"
    assert parameters["h"]["json_schema"]["exclusiveMinimum"] == 0
    assert entry["default_range"] == [-10, 10]
    assert entry["statements"] == [s.id for s in d4b.STATEMENTS]
    assert entry["url"] == "/discretizations/d4b"


def test_theorem_catalog_lists_every_statement(client: TestClient) -> None:
    statements = client.get("/theorems").json()
    ids = [s["id"] for s in statements]
    assert set(ids) >= {s.id for s in d4b.STATEMENTS}
    assert all(s["url"] == f"/theorems/{s['id']}" for s in statements)


def test_one_theorem_checked_with_parameters(client: TestClient) -> None:
    response = client.get("/theorems/theorem-6", params={"d": 0.4, "beta0": 0.6, "detail": True})
    assert response.status_code == 200
    body = TheoremResponse.model_validate(response.json())
    assert body.discretization == "d4b"
    assert body.parameters["d"] == 0.4
    assert body.check.holds is True
    assert body.check.per_index is not None and len(body.check.per_index.indices) == 21


def test_theorem_with_erratum_shows_printed_and_corrected(client: TestClient) -> None:
    body = client.get("/theorems/recursion-13-two-step").json()
    erratum = body["check"]["erratum"]
    assert erratum["id"] == "E3"
    assert erratum["printed_residual"] > 1e6 * body["check"]["tolerance"]
    assert erratum["link"] == "/errata/E3"
    assert body["check"]["holds"] is True


def test_theorem_rejects_unknown_parameters(client: TestClient) -> None:
    response = client.get("/theorems/theorem-5", params={"zeta": 1})
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == "zeta"


def test_catalog_lists_the_stick_and_chain_family_with_domains(client: TestClient) -> None:
    entries = {e["id"]: e for e in client.get("/discretizations").json()}
    domains = {
        "d1": {"c": "0 < c < 1", "delta": "delta > 0"},
        "d3": {"c": "c > 0", "delta": "0 < delta < 2c", "y0": "y0 >= √(c² − delta²/4)"},
        "d4a": {"h": "h > 0", "s": "0 < s < h", "beta0": "0 < beta0 < π"},
    }
    for identifier, expected in domains.items():
        entry = entries[identifier]
        parameters = {p["name"]: p for p in entry["parameters"]}
        assert {k: parameters[k]["domain"] for k in expected} == expected
        assert entry["methods"] == ["construction", "closed-form"]
        assert entry["url"] == f"/discretizations/{identifier}"
    assert entries["d4a"]["statements"][:2] == ["d4a-sticks", "d4a-arc-length"]
    assert set(entries["d1"]["constants"]) == {"d1", "d3", "eq2", "equilibrium"}


def test_every_statement_lists_parameters_an_example_and_its_source(client: TestClient) -> None:
    from app.registry import SMOOTH, STATEMENTS, STUDIES

    statements = client.get("/theorems").json()
    assert [s["id"] for s in statements] == list(STATEMENTS)
    for entry in statements:
        StatementInfo.model_validate(entry)
        sources = entry["discretizations"] + entry["studies"] + entry["smooth"]
        names = {p["name"]: p for p in entry["parameters"]}
        if not sources:  # a statement about meshes: checked on a surface
            assert entry["surfaces"], entry["id"]
            assert set(names) == set(SurfaceQuery.model_fields)
            assert entry["example_url"].startswith(f"/theorems/{entry['id']}?discretization=d4b&")
            continue
        if not entry["discretizations"] and not entry["studies"]:
            assert set(names) == set(SMOOTH[entry["smooth"][0]].query.model_fields)
            assert entry["example_url"].startswith(f"/theorems/{entry['id']}?h=1.0&")
            continue
        on_study = entry["id"] in entry["studies"] or not entry["discretizations"]
        if not on_study:
            assert entry["example_url"].startswith(
                f"/theorems/{entry['id']}?discretization={entry['discretizations'][0]}&"
            )
        else:
            study = STUDIES[entry["id"] if entry["id"] in STUDIES else entry["studies"][0]]
            assert set(names) == set(study.query.model_fields)
            default = names["j0"]["default"] if "j0" in names else names["d0"]["default"]
            assert default == (4 if "j0" in names else 0.2)
            if entry["discretizations"]:  # both check it: the example names the study
                assert entry["example_url"].startswith(
                    f"/theorems/{entry['id']}?study={study.info.id}&"
                )
        assert "precision" in names and names["precision"]["kind"] == "common"


def test_every_example_url_checks_its_statement_with_the_defaults(client: TestClient) -> None:
    fails_by_design = {  # Section 4: the (D2a) polygons do not satisfy these
        ("d2a-quad", "d1"),
        ("d2a-quad", "d3"),
        ("d2a-hex", "d1"),
        ("d2a-hex", "d3"),
        ("d2a-hex", "equation-2"),
    }
    for entry in client.get("/theorems").json():
        response = client.get(entry["example_url"])
        assert response.status_code == 200, entry["id"]
        body = TheoremResponse.model_validate(response.json())
        assert body.id == entry["id"]
        expected = (body.discretization, entry["id"]) not in fails_by_design
        assert body.check.holds is expected, entry["id"]
        erratum = body.check.erratum
        assert ([erratum.id] if erratum else []) == entry["errata"], entry["id"]
        assert body.conditions == entry["conditions"]


def test_implicit_conditions_are_listed(client: TestClient) -> None:
    statements = {s["id"]: s for s in client.get("/theorems").json()}
    assert "stated needlessly" in statements["theorem-4-hypothesis"]["conditions"][0].lower()
    assert "vertical first stick" in statements["theorem-5"]["conditions"][0]
    assert "r* = " in statements["theorem-1"]["conditions"][0]
    assert any("compact sets" in c for c in statements["theorem-14"]["conditions"])
    assert any("pointwise" in c for c in statements["inequality-22"]["conditions"])
    assert statements["theorem-15-proof-y"]["errata"] == ["E80"]
    assert statements["theorem-15-proof-x"]["errata"] == ["E81"]
    assert any("0 < c < 1" in c for c in statements["d1"]["conditions"])
    assert any("cusp stick" in c for c in statements["d4a-sticks"]["conditions"])
    assert any("H = −A(f,n)/A(f)" in c for c in statements["equation-17"]["conditions"])
    assert any("i >= 0" in c for c in statements["example-12"]["conditions"])
    assert any("bounded g' does not" in c for c in statements["theorem-11"]["conditions"])
    assert any("E45" in c for c in statements["equation-2"]["conditions"])
    assert statements["theorem-2"]["errata"] == ["E45"]
    # every statement says what the text leaves implicit about it
    assert [s for s, entry in statements.items() if not entry["conditions"]] == []


def test_convergence_statements_are_checked_on_their_study(client: TestClient) -> None:
    response = client.get(
        "/theorems/theorem-15", params={"d0": 0.1, "levels": 3, "samples": 11, "x_max": 1.0}
    )
    assert response.status_code == 200
    body = TheoremResponse.model_validate(response.json())
    assert body.study == "theorem-15" and body.discretization is None
    assert body.parameters["d0"] == 0.1
    assert body.check.holds is True and body.check.tolerance == pytest.approx(2**-0.5)
    assert "observed order parametric: 1.0" in (body.check.note or "")
    proof = client.get("/theorems/theorem-15-proof-y", params={"levels": 3, "samples": 11})
    assert proof.json()["check"]["erratum"]["printed_residual"] > 0.1


@pytest.mark.parametrize(
    ("params", "parameter"),
    [
        ({"discretization": "d4b"}, "discretization"),
        ({"d0": 2.0}, "d0"),
        ({"levels": 99}, "levels"),
        ({"h": 1, "d": 0.1}, "d"),
    ],
)
def test_convergence_statements_reject_foreign_or_invalid_parameters(
    client: TestClient, params: dict, parameter: str
) -> None:
    response = client.get("/theorems/theorem-14", params=params)
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == parameter


def test_statements_of_theorem_11_are_checked_on_the_study_or_the_curve(
    client: TestClient,
) -> None:
    small = {"levels": 3}
    body = client.get("/theorems/theorem-11", params=small).json()
    assert body["study"] == "theorem-11" and body["discretization"] is None
    assert body["check"]["holds"] is True and body["check"]["tolerance"] == pytest.approx(2**-0.5)
    curve = client.get("/theorems/theorem-11", params={"discretization": "d2b", "j": 4}).json()
    assert curve["discretization"] == "d2b" and curve["check"]["tolerance"] == 1.0
    lemma = client.get("/theorems/lemma-10", params={"study": "theorem-11", **small}).json()
    assert lemma["study"] == "theorem-11" and lemma["check"]["erratum"]["id"] == "E64"
    remark = client.get("/theorems/remark-13", params={"study": "theorem-11", **small}).json()
    assert remark["check"]["holds"] is True and "every vertex" in remark["check"]["note"]
    on_curve = client.get("/theorems/remark-13").json()  # the statement's default sequence
    assert on_curve["parameters"]["sequence"] == "remark-13"
    uniform = client.get("/theorems/remark-13-uniform", params=small).json()
    assert uniform["check"]["erratum"]["id"] == "E66"
    assert uniform["check"]["erratum"]["printed_residual"] > uniform["check"]["tolerance"]


@pytest.mark.parametrize(
    ("statement", "params", "status", "parameter"),
    [
        ("theorem-11", {"study": "theorem-11", "discretization": "d2b"}, 422, "study"),
        ("theorem-5", {"study": "theorem-11"}, 422, "study"),
        ("lemma-10", {"study": "theorem-14"}, 404, "id"),
        ("lemma-10", {"study": "theorem-11", "j": 5}, 422, "j"),
    ],
)
def test_the_source_of_a_statement_is_validated(
    client: TestClient, statement: str, params: dict, status: int, parameter: str
) -> None:
    response = client.get(f"/theorems/{statement}", params=params)
    assert response.status_code == status
    assert response.json()["errors"][0]["parameter"] == parameter


def test_statements_of_section_2_are_checked_on_the_smooth_tractrix(client: TestClient) -> None:
    statements = {s["id"]: s for s in client.get("/theorems").json()}
    for key in ("tractrix-s4", "evolute-s4", "nikolaides-s4"):
        assert statements[key]["smooth"] == ["tractrix"], key
    body = client.get("/theorems/nikolaides-s4", params={"h": 2.0, "count": 11}).json()
    TheoremResponse.model_validate(body)
    assert body["smooth"] == "tractrix" and body["discretization"] is None
    assert body["parameters"]["h"] == 2.0 and body["check"]["holds"] is True
    assert client.get("/theorems/evolute-s4", params={"count": 1}).status_code == 422
    wrong = client.get("/theorems/evolute-s4", params={"discretization": "d4b"})
    assert wrong.status_code == 422 and "GET /smooth/tractrix" in wrong.text


@pytest.mark.parametrize("identifier", sorted(DISCRETIZATIONS))
def test_each_request_model_matches_its_compute_function(identifier: str) -> None:
    """Every field the core takes is a parameter of compute, and every parameter of compute
    (but the arithmetic and the selection) is a field of the request model."""
    entry = DISCRETIZATIONS[identifier]
    parameters = inspect.signature(entry.compute).parameters
    taken = set(entry.query.model_validate({}).core_arguments())
    assert taken == set(parameters) - {"ar", "selection"}
    assert next(iter(parameters)) == "ar" and "selection" in parameters
