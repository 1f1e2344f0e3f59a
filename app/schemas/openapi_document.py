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
- array query parameters are comma-separated (``explode: false``), as the server reads them;
- recursive JSON values (``JSONValue``) in a form TypeScript generators can express;
- ``servers``, ``license``, ``contact``, and ``security: []`` (no authentication).
"""

from __future__ import annotations

from typing import Any

from app.negotiation import accept_description, negotiable
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
    for operations in spec["paths"].values():
        for method, operation in operations.items():
            _problem_responses(operation)
            _typed_bodies(operation)
            _curve_union(operation, schemas)
            if method == "get":
                _negotiated(operation)
            for parameter in operation.get("parameters", []):
                if parameter.get("schema", {}).get("type") == "array":
                    parameter["style"], parameter["explode"] = "form", False
            body = operation.get("requestBody", {}).get("content", {}).get("application/json")
            if method == "post" and body is not None:
                _closed(body.get("schema", {}), schemas)
                operation["responses"].setdefault("415", UNSUPPORTED_MEDIA_TYPE_RESPONSE)
    _limits(spec, settings)
    for operations in spec["paths"].values():
        for operation in operations.values():
            for response in operation.get("responses", {}).values():
                for media in response.get("content", {}).values():
                    if "example" in media and "schema" in media:
                        media["example"] = _complete(media["example"], media["schema"], schemas)
    return spec


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
