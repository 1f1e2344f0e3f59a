"""The OpenAPI document as clients need it, from what FastAPI generates.

FastAPI's document is adjusted in one pass, after generation:

- errors: every problem response has the ``Problem`` schema under ``application/problem+json``
  (FastAPI puts a response model under ``application/json``), and every operation documents the
  422 that unknown parameters get;
- examples: FastAPI drops ``null`` members from examples; required nullable members are put
  back, so that each example validates against its own schema;
- limits: ``digits`` carries the maximum of the settings in force (``DCOSH_MAX_DIGITS``);
- curves: the 200 of a curve endpoint is ``CurveResponse`` (float64: coordinates are
  JSON numbers) and ``CurveResponseMP`` (decimal strings);
- content negotiation: where ``Accept`` can choose the ``format`` (app.negotiation), the
  ``format`` parameter says so and the operation documents its 406;
- request bodies refuse unknown members (``additionalProperties: false``), as the server does;
- array query parameters (also nullable ones) are comma-separated (``explode: false``), as the
  server reads them;
- ``checks`` and ``companions``: a keyword or the resource's own ids (enums), where its example
  lists them;
- every real parameter is 0 or at least 1e-100 in magnitude, as the request models check;
- the runtime limits in force (settings) listed in the description;
- recursive JSON values (``JSONValue``) in a form TypeScript generators can express;
- ``servers``, ``license``, ``contact``, and ``security: []`` (no authentication).
"""

from __future__ import annotations

import re
from typing import Any

from app.negotiation import accept_description, negotiable
from app.schemas.common import SMALLEST_MAGNITUDE
from app.schemas.curve import CurveResponseMP
from app.settings import Settings

LICENSE = {"name": "MIT", "identifier": "MIT"}
CONTACT = {"name": "dcosh maintainers (see the repository's README)"}
PROBLEM_REF = "#/components/schemas/Problem"
PROBLEM_MEDIA_TYPE = "application/problem+json"

UNKNOWN_PARAMETER_RESPONSE = {
    "description": "Invalid parameters (here: a query parameter the endpoint does not have).",
    "content": {PROBLEM_MEDIA_TYPE: {"schema": {"$ref": PROBLEM_REF}}},
}


_SCALARS: list[dict[str, Any]] = [
    {"type": "boolean"},
    {"type": "number"},
    {"type": "string"},
    {"type": "null"},
]
_OBJECT = {"type": "object", "additionalProperties": {"$ref": "#/components/schemas/JSONValue"}}
#: Any JSON value, written so that TypeScript generators can express it: an array's items are a
#: scalar, an object or an array of anything (a type that refers to itself through an array
#: element is circular in TypeScript; through an object member it is not).
JSON_VALUE: dict[str, Any] = {
    "description": "Any JSON value.",
    "anyOf": [
        *_SCALARS,
        {"type": "array", "items": {"anyOf": [*_SCALARS, _OBJECT, {"type": "array"}]}},
        _OBJECT,
    ],
}


NOT_ACCEPTABLE_RESPONSE = {
    "description": "Not acceptable: no representation satisfies the `Accept` header and the "
    "query names no `format`; `available` lists the formats and media types.",
    "content": {PROBLEM_MEDIA_TYPE: {"schema": {"$ref": PROBLEM_REF}}},
}


UNSUPPORTED_MEDIA_TYPE_RESPONSE = {
    "description": "The body is not JSON (Content-Type must be application/json).",
    "content": {PROBLEM_MEDIA_TYPE: {"schema": {"$ref": PROBLEM_REF}}},
}


def refine(spec: dict[str, Any], settings: Settings) -> dict[str, Any]:
    """``spec`` (FastAPI's document) adjusted as the module doc says; changed in place."""
    spec["servers"] = [{"url": "/", "description": "This service (paths are relative)."}]
    spec["security"] = []
    spec["info"]["license"] = LICENSE
    spec["info"]["contact"] = CONTACT
    schemas: dict[str, Any] = spec.setdefault("components", {}).setdefault("schemas", {})
    _add_mp_curve(schemas)
    if "JSONValue" in schemas:
        schemas["JSONValue"] = JSON_VALUE
    spec["info"]["description"] = spec["info"].get("description", "") + runtime_limits(settings)
    bodies: set[int] = set()
    for operations in spec["paths"].values():
        _selections(operations, schemas)
    for operations in spec["paths"].values():
        for method, operation in operations.items():
            _problem_responses(operation)
            _typed_bodies(operation)
            _curve_union(operation, schemas)
            if method == "get":
                _negotiated(operation)
            for parameter in operation.get("parameters", []):
                schema = parameter.get("schema", {})
                if "array" in _types(schema):
                    parameter["style"], parameter["explode"] = "form", False
                if parameter.get("in") == "query":
                    _no_null(schema)
                    _smallest_magnitude(schema)
            body = operation.get("requestBody", {}).get("content", {}).get("application/json")
            if method == "post" and body is not None:
                _closed(body.get("schema", {}), schemas)
                target = _resolve(body.get("schema", {}), schemas)
                if id(target) not in bodies:
                    bodies.add(id(target))
                    for field in target.get("properties", {}).values():
                        _smallest_magnitude(field)
                operation["responses"].setdefault("415", UNSUPPORTED_MEDIA_TYPE_RESPONSE)
    _limits(spec, settings)
    for operations in spec["paths"].values():
        for operation in operations.values():
            for response in operation.get("responses", {}).values():
                for media in response.get("content", {}).values():
                    if "example" in media and "schema" in media:
                        media["example"] = _complete(media["example"], media["schema"], schemas)
    return spec


#: The keywords of ``checks`` and ``companions`` (app.services.selection).
SELECTION_WORDS = {"checks": ["all", "none", "failed"], "companions": ["all", "none"]}


def _selections(operations: dict[str, Any], schemas: dict[str, Any]) -> None:
    """``checks`` and ``companions`` as the server reads them: a keyword, or ids of this resource
    (comma-separated; a body may also give a list); the ids are those of the GET's
    JSON example, computed with everything selected. Without an example (the surfaces, whose
    checks depend on the surface) the schema stays a string."""
    example = (
        operations.get("get", {})
        .get("responses", {})
        .get("200", {})
        .get("content", {})
        .get("application/json", {})
        .get("example")
    )
    if not isinstance(example, dict) or not {"checks", "companions"} <= set(example):
        return
    ids = {
        "checks": [check["id"] for check in example["checks"]],
        "companions": list(example["companions"]),
    }
    for method, operation in operations.items():
        for parameter in operation.get("parameters", []):
            if parameter.get("in") == "query" and parameter["name"] in ids:
                name = parameter["name"]
                parameter["schema"] = selection_schema(parameter["schema"], name, ids[name])
        body = operation.get("requestBody", {}).get("content", {}).get("application/json")
        if method == "post" and body is not None:
            properties = _resolve(body.get("schema", {}), schemas).get("properties", {})
            for name in ids:
                if name in properties:
                    properties[name] = selection_schema(properties[name], name, ids[name])


def selection_schema(schema: dict[str, Any], name: str, ids: list[str]) -> dict[str, Any]:
    """A keyword alone, or a comma-separated list of this resource's ids: a pattern (a string
    schema, so that generated clients and fuzzers send it as the server reads it)."""
    kept: dict[str, Any] = {
        k: schema[k] for k in ("title", "description", "default") if k in schema
    }
    words = SELECTION_WORDS[name]
    if not ids:
        return {**kept, "type": "string", "enum": words}
    assert all(re.fullmatch(r"[A-Za-z0-9_-]+", i) for i in ids), ids  # nothing to escape
    one = "|".join(ids)
    pattern = f"^(?:{'|'.join(words)}|(?:{one})(?:,(?:{one}))*)$"
    length = schema.get("maxLength", 4096)
    return {**kept, "type": "string", "maxLength": length, "pattern": pattern}


#: A real parameter is 0 or at least ``SMALLEST_MAGNITUDE`` in magnitude (app.schemas.common):
#: the same rule in JSON Schema, added to every number a request takes. Each range names its type:
#: an option without one is `unknown` to generated TypeScript (and `number | unknown` is `unknown`).
MAGNITUDE: list[dict[str, Any]] = [
    {"const": 0},
    {"type": "number", "minimum": SMALLEST_MAGNITUDE},
    {"type": "number", "maximum": -SMALLEST_MAGNITUDE},
]


def _no_null(schema: dict[str, Any]) -> None:
    """A query parameter cannot be null (absent is its default): ``anyOf [X, null]`` is X, so
    that tools apply the parameter's style to X (schemathesis explodes an array under anyOf)."""
    options = [o for o in schema.get("anyOf", []) if o.get("type") != "null"]
    if len(options) == 1 and len(schema["anyOf"]) == 2:
        del schema["anyOf"]
        schema.update(options[0])


def _types(schema: dict[str, Any]) -> set[str]:
    """The types a parameter's schema allows (its own and its anyOf options')."""
    found = {schema["type"]} if isinstance(schema.get("type"), str) else set()
    for option in schema.get("anyOf", []):
        found |= _types(option)
    return found


def _smallest_magnitude(schema: dict[str, Any]) -> None:
    """Add ``MAGNITUDE`` to a number schema (or its number option)."""
    if schema.get("type") == "number" and "anyOf" not in schema:
        schema["anyOf"] = [dict(option) for option in MAGNITUDE]
        return
    for option in schema.get("anyOf", []):
        if option.get("type") == "number" and "anyOf" not in option:
            option["anyOf"] = [dict(o) for o in MAGNITUDE]


#: The settings that bound one request (app/limits.py), in the order the text lists them.
RUNTIME_LIMITS = (
    "max_vertices",
    "max_construction_steps",
    "max_digits",
    "max_mp_work",
    "max_svg_vertices",
    "max_mesh_vertices",
    "max_convergence_levels",
    "max_convergence_samples",
    "max_convergence_steps",
    "max_relation_vertices",
    "time_limit",
    "max_body_bytes",
)


def runtime_limits(settings: Settings) -> str:
    """The document's section on the limits in force: a schema-valid request beyond one is a
    422 of type over-limits (time-limit for the time), naming the parameter and the bound."""
    rows = []
    for name in RUNTIME_LIMITS:
        field = Settings.model_fields[name]
        value = getattr(settings, name)
        shown = f"{value:,}".replace(",", " ") if isinstance(value, int) else f"{value:g}"
        rows.append(f"| `DCOSH_{name.upper()}` | {shown} | {field.description} |")
    return (
        "\n\n## Runtime limits\n\n"
        "Besides its schema, a request is bounded by the limits of this deployment (settings, "
        "checked before any computation starts). A schema-valid request beyond one is a 422 of "
        "type `/problems/over-limits` (`/problems/time-limit` for the time) naming the parameter "
        "and the bound in force; `digits` carries its maximum in the schema. Parameters coupled "
        "by a domain (such as 0 < d < h, or i_min <= i_max) are given in each parameter's "
        "description and `x-domain`; a request outside it is a 422 of type "
        "`/problems/outside-domain`.\n\n"
        "| setting | in force | bounds |\n|---|---|---|\n" + "\n".join(rows) + "\n"
    )


def _problem_responses(operation: dict[str, Any]) -> None:
    responses = operation.setdefault("responses", {})
    for status, response in responses.items():
        content = response.get("content", {})
        if PROBLEM_MEDIA_TYPE in content or status.startswith(("4", "5")):
            response["content"] = {PROBLEM_MEDIA_TYPE: {"schema": {"$ref": PROBLEM_REF}}}
    responses.setdefault("422", UNKNOWN_PARAMETER_RESPONSE)


def _negotiated(operation: dict[str, Any]) -> None:
    """Where ``Accept`` chooses the format (app.negotiation): say so, and document the 406."""
    formats = negotiable(operation)
    if len(formats) < 2:
        return
    for parameter in operation["parameters"]:
        if parameter["name"] == "format":
            parameter["description"] = parameter.get("description", "") + accept_description(
                formats
            )
    operation["responses"].setdefault("406", NOT_ACCEPTABLE_RESPONSE)


def _typed_bodies(operation: dict[str, Any]) -> None:
    """A schema for every documented body: text and SVG are strings, the rest binary."""
    for response in operation.get("responses", {}).values():
        for media_type, media in response.get("content", {}).items():
            if not media.get("schema"):
                textual = media_type.startswith("text/") or media_type in ("image/svg+xml",)
                media["schema"] = (
                    {"type": "string"}
                    if textual
                    else {
                        "type": "string",
                        "format": "binary",
                    }
                )


def _add_mp_curve(schemas: dict[str, Any]) -> None:
    generated = CurveResponseMP.model_json_schema(ref_template="#/components/schemas/{model}")
    for name, schema in generated.pop("$defs", {}).items():
        schemas.setdefault(name, schema)
    schemas["CurveResponseMP"] = generated


def _curve_union(operation: dict[str, Any], schemas: dict[str, Any]) -> None:
    media = operation.get("responses", {}).get("200", {}).get("content", {}).get("application/json")
    if media is not None and media.get("schema") == {"$ref": "#/components/schemas/CurveResponse"}:
        media["schema"] = {
            "anyOf": [
                {"$ref": "#/components/schemas/CurveResponse"},
                {"$ref": "#/components/schemas/CurveResponseMP"},
            ]
        }


def _closed(schema: dict[str, Any], schemas: dict[str, Any]) -> None:
    ref = schema.get("$ref", "")
    target = schemas.get(ref.rsplit("/", 1)[-1]) if ref else schema
    if target is not None and target.get("type") == "object" and "properties" in target:
        target["additionalProperties"] = False


def _limits(spec: dict[str, Any], settings: Settings) -> None:
    """``digits`` at most the settings' ``max_digits``, wherever it is a parameter or field."""

    def visit(node: Any) -> None:
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "digits" and isinstance(value, dict) and "maximum" in value:
                    value["maximum"] = settings.max_digits
                visit(value)
            if node.get("name") == "digits" and "maximum" in node.get("schema", {}):
                node["schema"]["maximum"] = settings.max_digits
        elif isinstance(node, list):
            for item in node:
                visit(item)

    visit(spec)


def _resolve(schema: dict[str, Any], schemas: dict[str, Any]) -> dict[str, Any]:
    while "$ref" in schema:
        schema = schemas.get(schema["$ref"].rsplit("/", 1)[-1], {})
    return schema


def _nullable(schema: dict[str, Any], schemas: dict[str, Any]) -> bool:
    schema = _resolve(schema, schemas)
    options = schema.get("anyOf", []) + schema.get("oneOf", [])
    return schema.get("type") == "null" or any(_nullable(o, schemas) for o in options)


def _complete(example: Any, schema: dict[str, Any], schemas: dict[str, Any]) -> Any:
    """``example`` with the required nullable members FastAPI dropped put back as null."""
    schema = _resolve(schema, schemas)
    if isinstance(example, dict):
        for option in schema.get("oneOf", []) + schema.get("anyOf", []):
            if _resolve(option, schemas).get("type") == "object":
                return _complete(example, option, schemas)
        properties = schema.get("properties", {})
        for name in schema.get("required", []):
            if name not in example and name in properties and _nullable(properties[name], schemas):
                example[name] = None
        extra = schema.get("additionalProperties")
        for name, value in example.items():
            sub = properties.get(name, extra if isinstance(extra, dict) else None)
            if sub is not None:
                example[name] = _complete(value, sub, schemas)
        return example
    if isinstance(example, list):
        items = schema.get("items")
        for option in schema.get("anyOf", []):
            if _resolve(option, schemas).get("type") == "array":
                items = _resolve(option, schemas).get("items")
        if isinstance(items, dict):
            return [_complete(value, items, schemas) for value in example]
    return example
