"""The OpenAPI document says what the server does: problem responses, typed curves, limits from
the settings, closed POST bodies, examples that fit their schemas. (`make contract`, run by
`make test`, lints the same document with Redocly CLI and compiles TypeScript against it.)"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.openapi_export import document
from app.settings import Settings

ROOT = Path(__file__).resolve().parents[2]
SPEC = json.loads(document())
SCHEMAS = SPEC["components"]["schemas"]


def operations() -> list[tuple[str, str, dict[str, Any]]]:
    return [(p, m, op) for p, ops in SPEC["paths"].items() for m, op in ops.items()]


def test_every_error_response_is_a_problem_under_its_media_type() -> None:
    for path, method, operation in operations():
        responses = operation["responses"]
        assert "422" in responses, (method, path)
        for status, response in responses.items():
            if status.startswith(("4", "5")):
                assert response["content"] == {
                    "application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}
                }, (method, path, status)


def test_no_non_standard_keywords() -> None:
    text = json.dumps(SPEC)
    assert '"domain": "' not in text
    assert '"x-domain": "0 < d < h"' in text


def test_servers_license_contact() -> None:
    assert SPEC["servers"] and SPEC["info"]["license"]["identifier"] == "MIT"
    assert SPEC["info"]["contact"]["name"]
    assert SPEC["security"] == []


def test_digits_maximum_is_the_setting_in_force() -> None:
    def digits_maxima(spec: dict[str, Any]) -> set[int]:
        found = set()
        for _, _, operation in [
            (p, m, op) for p, ops in spec["paths"].items() for m, op in ops.items()
        ]:
            for parameter in operation.get("parameters", []):
                if parameter["name"] == "digits":
                    found.add(parameter["schema"]["maximum"])
        return found

    assert digits_maxima(SPEC) == {Settings().max_digits}
    assert SCHEMAS["D4bBody"]["properties"]["digits"]["maximum"] == Settings().max_digits
    small = create_app(Settings(max_digits=50)).openapi()
    assert digits_maxima(small) == {50}


def test_float64_and_mp_curves_are_typed_apart() -> None:
    ok = SPEC["paths"]["/discretizations/d4b"]["get"]["responses"]["200"]["content"]
    refs = [s["$ref"].rsplit("/", 1)[1] for s in ok["application/json"]["schema"]["anyOf"]]
    assert refs == ["CurveResponse", "CurveResponseMP"]
    float64 = SCHEMAS["CurveResponse"]["properties"]["vertices"]["items"]["prefixItems"]
    mp = SCHEMAS["CurveResponseMP"]["properties"]["vertices"]["items"]["prefixItems"]
    assert [c["type"] for c in float64] == ["number", "number"]
    assert [c["type"] for c in mp] == ["string", "string"]


def test_post_bodies_are_closed_like_the_server() -> None:
    for path, method, operation in operations():
        if method != "post":
            continue
        schema = operation["requestBody"]["content"]["application/json"]["schema"]
        if "$ref" in schema:
            assert SCHEMAS[schema["$ref"].rsplit("/", 1)[1]]["additionalProperties"] is False, path


def test_array_parameters_are_comma_separated_as_the_server_reads_them(
    client: TestClient,
) -> None:
    parameters = SPEC["paths"]["/figures/figure-8.svg"]["get"]["parameters"]
    j = next(p for p in parameters if p["name"] == "j")
    assert (j["style"], j["explode"]) == ("form", False)
    assert client.get("/figures/figure-8.svg?j=1,2,5").status_code == 200


def test_an_integral_float_is_an_integer_in_a_json_body(client: TestClient) -> None:
    float_digits = client.post("/discretizations/d4b", json={"precision": "mp", "digits": 20.0})
    int_digits = client.post("/discretizations/d4b", json={"precision": "mp", "digits": 20})
    assert float_digits.status_code == 200, float_digits.text
    assert float_digits.json() == int_digits.json()
    refused = client.post("/discretizations/d4b", json={"digits": 20.5})
    assert refused.status_code == 422
    assert client.post("/discretizations/d4b", json={"i_max": True}).status_code == 422


def _validate(instance: Any, schema: dict[str, Any], where: str) -> None:
    """A small JSON Schema check of the keywords the document uses."""
    while "$ref" in schema:
        schema = SCHEMAS[schema["$ref"].rsplit("/", 1)[1]]
    options = schema.get("anyOf") or schema.get("oneOf")
    if options:
        errors = []
        for option in options:
            try:
                _validate(instance, option, where)
                return
            except AssertionError as error:
                errors.append(str(error))
        raise AssertionError(f"{where}: no option fits: {errors[:2]}")
    kind = schema.get("type")
    checks = {
        "object": lambda v: isinstance(v, dict),
        "array": lambda v: isinstance(v, list),
        "string": lambda v: isinstance(v, str),
        "number": lambda v: isinstance(v, int | float) and not isinstance(v, bool),
        "integer": lambda v: isinstance(v, int) and not isinstance(v, bool),
        "boolean": lambda v: isinstance(v, bool),
        "null": lambda v: v is None,
    }
    if kind is not None:
        assert checks[kind](instance), f"{where}: {instance!r} is not {kind}"
    if isinstance(instance, dict):
        for name in schema.get("required", []):
            assert name in instance, f"{where}: {name} missing"
        extra = schema.get("additionalProperties")
        for name, value in instance.items():
            sub = schema.get("properties", {}).get(name, extra if isinstance(extra, dict) else None)
            if sub is not None:
                _validate(value, sub, f"{where}.{name}")
    if isinstance(instance, list):
        prefix = schema.get("prefixItems")
        for k, value in enumerate(instance):
            sub = prefix[k] if prefix and k < len(prefix) else schema.get("items")
            if isinstance(sub, dict):
                _validate(value, sub, f"{where}[{k}]")


@pytest.mark.parametrize(
    ("path", "method", "operation"),
    [o for o in operations() if "example" in json.dumps(o[2])],
    ids=lambda v: v if isinstance(v, str) else "",
)
def test_every_example_fits_its_schema(path: str, method: str, operation: dict[str, Any]) -> None:
    for status, response in operation["responses"].items():
        for media in response.get("content", {}).values():
            if "example" in media:
                _validate(media["example"], media["schema"], f"{method} {path} {status}")


def test_the_readme_embedding_snippet_is_the_type_checked_one() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    script = readme.split('<script type="module">\n', 1)[1].split("</script>", 1)[0]
    assert script == (ROOT / "tools" / "contract" / "embed.js").read_text(encoding="utf-8")


def test_the_digits_maximum_holds_in_every_precision() -> None:
    small = TestClient(create_app(Settings(max_digits=50)))
    for response in (
        small.get("/discretizations/d4b?digits=51"),
        small.post("/discretizations/d4b", json={"digits": 51}),
        small.get("/theorems/theorem-5?digits=51"),
    ):
        assert response.status_code == 422, response.text
        assert response.json()["errors"][0]["constraint"] == "1 <= digits <= 50"
    assert small.get("/discretizations/d4b?digits=50").status_code == 200


def test_post_documents_415(client: TestClient) -> None:
    responses = SPEC["paths"]["/discretizations/d4b"]["post"]["responses"]
    assert "415" in responses
    assert client.post("/discretizations/d4b", content=b"x").status_code == 415


def _query_names(path: str) -> set[str]:
    return {p["name"] for p in SPEC["paths"][path]["get"]["parameters"] if p["in"] == "query"}


def test_each_surface_path_documents_exactly_the_parameters_it_takes(client: TestClient) -> None:
    from app.registry import DISCRETIZATIONS

    surface = {"m", "steps", "gauss_image", "format", "checks"}
    default = _query_names("/surfaces/{surface_id}")
    assert "y1" not in default and default >= surface | {"discretization", "h", "d"}
    for identifier, entry in DISCRETIZATIONS.items():
        own = {f.alias or name for name, f in entry.query.model_fields.items()}
        path = f"/surfaces/{{surface_id}}/{identifier}"
        assert _query_names(path) == surface | (own - {"detail"}), identifier
        body = SPEC["paths"][path]["post"]["requestBody"]["content"]["application/json"]
        assert body["schema"]["additionalProperties"] is False
    # D1's y1: documented on D1's path, taken there; one answer (and ETag) with the old spelling
    ok = client.get("/surfaces/catenoid-gauss-image/d1?y1=1.5&m=3&i_min=-2&i_max=2")
    assert ok.status_code == 200, ok.text
    old = client.get("/surfaces/catenoid-gauss-image?discretization=d1&y1=1.5&m=3&i_min=-2&i_max=2")
    assert old.json() == ok.json() and old.headers["etag"] == ok.headers["etag"]
    posted = client.post(
        "/surfaces/catenoid-gauss-image/d1", json={"y1": 1.5, "m": 3, "i_min": -2, "i_max": 2}
    )
    assert posted.json() == ok.json()
    # the path names the discretization; the default path's y1 stays refused, as documented
    for refused in (
        client.get("/surfaces/catenoid/d1?discretization=d1"),
        client.get("/surfaces/catenoid?y1=1.0"),
    ):
        assert refused.status_code == 422
        assert refused.json()["errors"][0]["constraint"] == "not a parameter of this endpoint"
    pseudo = SPEC["paths"]["/surfaces/{surface_id}/d1"]["get"]["parameters"][0]["schema"]["enum"]
    assert pseudo == ["catenoid", "catenoid-gauss-image"]


def _parameter(path: str, name: str) -> dict[str, Any]:
    found = [p for p in SPEC["paths"][path]["get"]["parameters"] if p["name"] == name]
    assert len(found) == 1, (path, name)
    return found[0]


def test_a_surface_takes_the_companions_and_range_its_schema_declares(client: TestClient) -> None:
    """Found by `make fuzz`: `companions=` (a string, so schema-valid) was refused on every
    surface path, and i_max = i_min (valid for a polygon) is refused for a mesh."""
    from app.registry import DISCRETIZATIONS

    for identifier in DISCRETIZATIONS:
        own = _parameter(f"/discretizations/{identifier}", "companions")["schema"]
        for path in (f"/surfaces/{{surface_id}}/{identifier}",) + (
            ("/surfaces/{surface_id}",) if identifier == "d4b" else ()
        ):
            schema = _parameter(path, "companions")["schema"]
            assert {k: schema.get(k) for k in ("enum", "pattern")} == {
                k: own.get(k) for k in ("enum", "pattern")
            }, path
            i_max = _parameter(path, "i_max")
            assert i_max["schema"]["x-domain"] == "i_min + 1 <= i_max", path
            assert "i_max >= i_min + 1" in i_max["description"], path
    refused = client.get("/surfaces/catenoid?companions=")
    assert refused.status_code == 422
    pattern = _parameter("/surfaces/{surface_id}", "companions")["schema"]["pattern"]
    assert re.fullmatch(pattern, "") is None and re.fullmatch(pattern, "tractrix,darboux")
    assert client.get("/surfaces/catenoid?companions=tractrix,darboux&m=3").status_code == 200
    # an unknown name, schema-invalid now, is refused as on /discretizations (it was ignored)
    for unknown in (
        client.get("/surfaces/catenoid/d4a?companions=xyz&m=3"),
        client.post("/surfaces/catenoid/d1", json={"companions": "tractrix", "m": 3}),
    ):
        assert unknown.status_code == 422, unknown.text
        assert unknown.json()["errors"][0]["parameter"] == "companions"
    mesh = client.get("/surfaces/catenoid?i_min=2&i_max=2")
    assert mesh.status_code == 422 and mesh.json()["errors"][0]["parameter"] == "i_max"


def test_the_float64_resolution_bounds_stated_are_the_servers(client: TestClient) -> None:
    """Found by `make fuzz`: D4b's text said d/h ≥ 1e-6 and D2a's a relative gap of 1e-6 while
    the server refuses below 100·√ε ≈ 1.49e-6 and 1e-4; a value between was documented valid."""
    from app.geometry.d2a.common import FLOAT64_MIN_GAP
    from app.geometry.tolerances import RESOLUTION_MARGIN

    d4b = SPEC["paths"]["/discretizations/d4b"]["get"]["description"]
    assert "d/h ≥ 1.5e-6" in d4b
    assert f"{RESOLUTION_MARGIN * (2.0**-52) ** 0.5:.2g}" == "1.5e-06"
    assert client.get("/discretizations/d4b?d=1.4e-6&checks=none").status_code == 422
    assert client.get("/discretizations/d4b?d=1.5e-6&checks=none").status_code == 200
    for path in ("/discretizations/d2a-quad", "/discretizations/d2a-hex"):
        assert "a relative 1e-4" in SPEC["paths"][path]["get"]["description"], path
    assert FLOAT64_MIN_GAP == 1e-4
    assert client.get("/discretizations/d2a-quad?f0=1&f1=1.00009").status_code == 422
    assert client.get("/discretizations/d2a-quad?f0=1&f1=1.00011&checks=none").status_code == 200


def test_a_bound_of_one_parameter_is_in_its_schema(client: TestClient) -> None:
    """Found by `make fuzz`: theorem-11's `i_max >= 1` was only an x-domain (schema minimum
    -10^6), so schema-valid values were refused; a bound on one parameter belongs in the schema."""
    i_max = _parameter("/convergence/theorem-11", "i_max")["schema"]
    assert i_max["minimum"] == 1 and i_max["x-domain"] == "i_max >= 1"
    refused = client.get("/convergence/theorem-11?i_max=0")
    assert refused.status_code == 422 and refused.json()["errors"][0]["parameter"] == "i_max"


def test_every_explorer_module_is_type_checked() -> None:
    """`make contract` compiles every module of the explorer with tsc --strict --checkJs against
    the generated types: a new module, or a check switched off, fails here."""
    explorer = ROOT / "app" / "static" / "explorer"
    config = json.loads((ROOT / "tools" / "contract" / "tsconfig.explorer.json").read_text())
    assert config["compilerOptions"]["strict"] and config["compilerOptions"]["checkJs"]
    listed = {Path(f).name for f in config["files"] if f.startswith("../../app/static/explorer/")}
    assert listed == {p.name for p in explorer.glob("*.js")}
    for module in explorer.glob("*.js"):
        text = module.read_text(encoding="utf-8")
        assert "// @ts-check" in text, module.name
        assert "@ts-nocheck" not in text and "@ts-ignore" not in text, module.name


def test_every_schema_option_has_a_type() -> None:
    """A JSON Schema option without a `type` (say `{"minimum": 1e-100}` under `anyOf`) is
    `unknown` for openapi-typescript, and `number | unknown` is `unknown`: a typed client could
    then send any value. Every option of every parameter and body field names its type."""

    def untyped(schema: Any, where: str) -> list[str]:
        found: list[str] = []
        if isinstance(schema, dict):
            for option in schema.get("anyOf", []):
                if not ({"type", "$ref", "const", "enum", "anyOf"} & option.keys()):
                    found.append(f"{where}: {option}")
            for key, value in schema.items():
                found += untyped(value, f"{where}.{key}")
        elif isinstance(schema, list):
            for k, value in enumerate(schema):
                found += untyped(value, f"{where}[{k}]")
        return found

    assert untyped(SPEC["paths"], "paths") == []
    assert untyped(SCHEMAS, "schemas") == []


def test_every_real_parameter_documents_and_gets_the_smallest_magnitude(client: TestClient) -> None:
    """The schema's rule (0 or at least 1e-100 in magnitude) is the server's, on every endpoint."""
    checked = 0
    for path, method, operation in operations():
        if method != "get":
            continue
        url = path.replace("{surface_id}", "catenoid").replace("{statement_id}", "theorem-5")
        for parameter in operation.get("parameters", []):
            schema = parameter["schema"]
            numbers = [schema, *schema.get("anyOf", [])]
            if not any(s.get("type") == "number" for s in numbers):
                continue
            assert any(
                s.get("anyOf")
                == [
                    {"const": 0},
                    {"type": "number", "minimum": 1e-100},
                    {"type": "number", "maximum": -1e-100},
                ]
                for s in numbers
            ), (path, parameter["name"])
            if "{" in url:
                continue
            response = client.get(url, params={parameter["name"]: "1e-200"})
            assert response.status_code == 422, (url, parameter["name"])
            named = [e["parameter"] for e in response.json()["errors"]]
            assert parameter["name"] in named, (url, parameter["name"], response.json())
            checked += 1
    assert checked > 50


def test_nullable_array_parameters_are_comma_separated_too(client: TestClient) -> None:
    parameters = SPEC["paths"]["/discretizations/d2b"]["get"]["parameters"]
    s = next(p for p in parameters if p["name"] == "s")
    assert (s["style"], s["explode"]) == ("form", False)
    url = "/discretizations/d2b?sequence=custom&s=0,0.25,0.5&i_min=0&i_max=2"
    assert client.get(url).status_code == 200


def test_an_integral_float_is_an_integer_also_in_an_annotated_optional_field(
    client: TestClient,
) -> None:
    as_float = client.post("/discretizations/d2b", json={"j": 6.0, "i_max": 6.0})
    as_int = client.post("/discretizations/d2b", json={"j": 6, "i_max": 6})
    assert as_float.status_code == 200, as_float.text
    assert as_float.json() == as_int.json()
    assert client.post("/discretizations/d2b", json={"j": 6.5}).status_code == 422


def test_the_runtime_limits_in_force_are_listed_in_the_document() -> None:
    text = SPEC["info"]["description"]
    assert "## Runtime limits" in text
    for name in ("MAX_VERTICES", "MAX_MP_WORK", "MAX_MESH_VERTICES", "TIME_LIMIT"):
        assert f"`DCOSH_{name}`" in text
    small = create_app(Settings(max_convergence_levels=6)).openapi()["info"]["description"]
    assert "| `DCOSH_MAX_CONVERGENCE_LEVELS` | 6 |" in small
