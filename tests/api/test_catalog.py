"""GET /health, /discretizations, /theorems and /theorems/{id}."""

from __future__ import annotations

from fastapi.testclient import TestClient

from app import __version__
from app.geometry.discretizations import d4b
from app.schemas.catalog import TheoremResponse


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
    assert erratum["link"] == "docs/errata.md#e3"
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
