"""precision=mp takes every real parameter as the decimal the client wrote (issue 15)."""

from __future__ import annotations

import json

import mpmath
from fastapi.testclient import TestClient

from app.registry import DISCRETIZATIONS
from app.schemas.common import real_fields
from tests.reference import d4b as reference

D = "0.12345678901234567890123"


def _exact(text: str) -> dict:  # type: ignore[type-arg]
    """A JSON document with its numbers kept as the decimal text."""
    document: dict = json.loads(text, parse_float=str, parse_int=str)  # type: ignore[type-arg]
    return document


def _largest_error(document: dict, centres: dict) -> mpmath.mpf:  # type: ignore[type-arg]
    ctx = mpmath.MPContext()
    ctx.dps = 60
    return max(
        abs(ctx.mpf(vertex[k]) - ctx.mpf(centres[int(i)][k]))
        for i, vertex in zip(document["indices"], document["vertices"], strict=True)
        for k in (0, 1)
    )


def test_a_23_digit_d_is_computed_as_written_and_echoed(client: TestClient) -> None:
    response = client.get(f"/discretizations/d4b?d={D}&precision=mp&digits=40")
    assert response.status_code == 200
    document = _exact(response.text)
    assert document["parameters"]["d"] == D
    centres, _, _ = reference.construct("1", D, None, -10, 10, dps=60)
    assert _largest_error(document, centres) < 1e-35


def test_post_takes_a_decimal_string_in_mp(client: TestClient) -> None:
    body = {"d": D, "beta0": "0.7000000000000000000000000000001", "precision": "mp"}
    response = client.post("/discretizations/d4b", json={**body, "digits": 40})
    assert response.status_code == 200
    document = _exact(response.text)
    assert document["parameters"]["d"] == D
    assert document["parameters"]["beta0"] == "0.7000000000000000000000000000001"
    centres, _, _ = reference.construct("1", D, body["beta0"], -10, 10, dps=60)
    assert _largest_error(document, centres) < 1e-35


def test_float64_keeps_the_nearest_double(client: TestClient) -> None:
    document = client.get(f"/discretizations/d4b?d={D}").json()
    assert document["parameters"]["d"] == float(D)
    refused = client.post("/discretizations/d4b", json={"d": "0.1"})
    assert refused.status_code == 422


def test_exact_decimals_differ_in_the_cache_key(client: TestClient) -> None:
    a = _exact(client.get("/discretizations/d4b?d=0.1&precision=mp&digits=40").text)
    query = "d=0.1000000000000000000001&precision=mp&digits=40"
    b = _exact(client.get(f"/discretizations/d4b?{query}").text)
    assert a["parameters"]["d"] == "0.1"
    assert b["parameters"]["d"] == "0.1000000000000000000001"
    assert a["vertices"] != b["vertices"]


def test_a_decimal_is_normalized_to_a_json_number(client: TestClient) -> None:
    document = _exact(client.get("/discretizations/d4b?d=%2B.1e0&precision=mp").text)
    assert document["parameters"]["d"] == "0.1"


def test_a_malformed_decimal_is_a_422_naming_it(client: TestClient) -> None:
    for value in ("0x10", "1_0", "0.1x", "nan", "inf"):
        response = client.post("/discretizations/d4b", json={"d": value, "precision": "mp"})
        assert response.status_code == 422, value
        assert response.json()["errors"][0]["parameter"] == "d"
    response = client.get("/discretizations/d1?c=abc&precision=mp")
    assert response.status_code == 422
    assert response.json()["errors"][0]["parameter"] == "c"


def test_every_discretization_echoes_its_real_parameters(client: TestClient) -> None:
    cases = {
        "d1": "c=0.5000000000000000000000001",
        "d3": "c=0.5000000000000000000000001",
        "d2a-quad": "f1=1.5000000000000000000000001",
        "d4a": "h=1.0000000000000000000000001",
    }
    for identifier, query in cases.items():
        name, value = query.split("=")
        response = client.get(f"/discretizations/{identifier}?{query}&precision=mp&digits=40")
        assert response.status_code == 200, (identifier, response.text[:300])
        assert _exact(response.text)["parameters"][name] == value


def test_post_takes_a_json_number_as_written_in_mp(client: TestClient) -> None:
    body = '{"d": 0.12345678901234567890123, "precision": "mp", "digits": 40}'
    headers = {"content-type": "application/json"}
    response = client.post("/discretizations/d4b", content=body, headers=headers)
    assert response.status_code == 200
    document = _exact(response.text)
    assert document["parameters"]["d"] == D
    centres, _, _ = reference.construct("1", D, None, -10, 10, dps=60)
    assert _largest_error(document, centres) < 1e-35
    plain = client.post(
        "/discretizations/d4b", content='{"d": 0.12345678901234567890123}', headers=headers
    )
    assert plain.json()["parameters"]["d"] == float(D)
    assert plain.text.count('"d":0.12345678901234568,') == 1


def test_an_optional_real_is_exact_too(client: TestClient) -> None:
    query = "r=-6.0000000000000000000001&precision=mp&digits=40"
    document = _exact(client.get(f"/discretizations/d2a-quad?{query}").text)
    assert document["parameters"]["r"] == "-6.0000000000000000000001"
    default = _exact(client.get("/discretizations/d2a-quad?precision=mp&digits=40").text)
    assert document["vertices"][10][1] != default["vertices"][10][1]  # p_0 = (0, r)
    assert document["vertices"][10][1] == "-6.0000000000000000000001"


def test_the_real_parameters_of_each_model_are_found_once() -> None:
    """``real_fields``: the fields whose decimal mp keeps (float, or float or None), per class."""
    assert real_fields(DISCRETIZATIONS["d4b"].query) == {"h", "d", "beta0"}
    assert real_fields(DISCRETIZATIONS["d1"].query) == {"c", "delta", "y0", "y1"}
    assert real_fields(DISCRETIZATIONS["d2b"].query) == frozenset()  # s is a list of floats
    assert real_fields(DISCRETIZATIONS["d4b"].query) is real_fields(DISCRETIZATIONS["d4b"].query)
