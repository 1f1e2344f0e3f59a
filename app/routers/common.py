"""What the curve and theorem endpoints share: parsing, limits, computing, encoding."""

from collections.abc import Mapping
from typing import Any, TypeVar

from fastapi import Request, Response
from fastapi.exceptions import RequestValidationError
from pydantic import BaseModel, ValidationError

from app.errors import UnknownIdError
from app.geometry.curve import Curve
from app.geometry.precision import arithmetic
from app.limits import enforce_drawing, enforce_range
from app.registry import DISCRETIZATIONS, Discretization
from app.rendering.curves import SVG_MEDIA_TYPE, curve_svg
from app.responses import CSV_MEDIA_TYPE, JSONBytesResponse, curve_csv, curve_document, encode_json
from app.schemas.common import CurveQuery
from app.settings import Settings

#: An SVG opened on its own is a document: it may style itself but load and run nothing.
SVG_HEADERS = {"Content-Security-Policy": "default-src 'none'; style-src 'unsafe-inline'"}


def settings_of(request: Request) -> Settings:
    settings: Settings = request.app.state.settings
    return settings


def reject_repeated_parameters(request: Request) -> None:
    """A parameter given twice is ambiguous: 422 instead of silently taking one."""
    seen: set[str] = set()
    for key, value in request.query_params.multi_items():
        if key in seen:
            raise RequestValidationError(
                [
                    {
                        "type": "repeated",
                        "loc": ("query", key),
                        "msg": "given more than once",
                        "input": value,
                    }
                ]
            )
        seen.add(key)


def discretization(identifier: str) -> Discretization:
    try:
        return DISCRETIZATIONS[identifier]
    except KeyError:
        raise UnknownIdError("discretization", identifier, sorted(DISCRETIZATIONS)) from None


Model = TypeVar("Model", bound=BaseModel)


def parse_query(model: type[Model], values: Mapping[str, Any]) -> Model:
    """Validate raw query values against a request model, as FastAPI would."""
    try:
        return model.model_validate(dict(values))
    except ValidationError as exc:
        errors = [{**e, "loc": ("query", *e["loc"])} for e in exc.errors()]
        raise RequestValidationError(errors) from None


def compute(entry: Discretization, query: CurveQuery, settings: Settings) -> Curve:
    """Check the work budget, then run the core."""
    arguments = query.core_arguments()
    enforce_range(
        settings,
        arguments["i_min"],
        arguments["i_max"],
        arguments.get("method", "construction"),
        query.precision,
        query.digits,
    )
    if query.format == "svg":
        enforce_drawing(settings, arguments["i_min"], arguments["i_max"])
    ar = arithmetic(query.precision, query.digits)
    return entry.compute(ar, **arguments)


def curve_response(curve: Curve, response_format: str) -> Response:
    if response_format == "csv":
        return Response(curve_csv(curve), media_type=CSV_MEDIA_TYPE)
    if response_format == "svg":
        return Response(curve_svg(curve), media_type=SVG_MEDIA_TYPE, headers=SVG_HEADERS)
    return JSONBytesResponse(encode_json(curve_document(curve)))
