"""What the curve and theorem endpoints share: parsing, limits, computing, encoding."""

from collections.abc import Callable, Mapping
from typing import Any, TypeVar

from fastapi import Request, Response
from fastapi.exceptions import RequestValidationError
from pydantic import ValidationError

from app.errors import UnknownIdError
from app.geometry.convergence import Study
from app.geometry.curve import Curve
from app.geometry.precision import arithmetic
from app.limits import enforce_drawing, enforce_range, enforce_study
from app.registry import DISCRETIZATIONS, STUDIES, ConvergenceStudy, Discretization
from app.rendering.curves import SVG_MEDIA_TYPE, curve_svg
from app.responses import CSV_MEDIA_TYPE, JSONBytesResponse, curve_csv, curve_document, encode_json
from app.schemas.common import CurveQuery, StrictModel
from app.schemas.convergence import StudyQuery
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


def study(identifier: str) -> ConvergenceStudy:
    try:
        return STUDIES[identifier]
    except KeyError:
        raise UnknownIdError("study", identifier, sorted(STUDIES)) from None


Model = TypeVar("Model", bound=StrictModel)


def parse_query(model: type[Model], values: Mapping[str, Any], prefix: str = "") -> Model:
    """Validate raw query values against a request model, as FastAPI would.

    ``prefix`` is prepended to the parameter names in errors (``d4b.`` in GET /relations).
    """
    try:
        return model.model_validate(dict(values))
    except ValidationError as exc:
        errors = []
        for e in exc.errors():
            loc = tuple(e["loc"])
            if prefix and loc:
                loc = (f"{prefix}{loc[0]}", *loc[1:])
            errors.append({**e, "loc": ("query", *loc)})
        raise RequestValidationError(errors) from None


def prepare_study(
    entry: ConvergenceStudy, query: StudyQuery, settings: Settings
) -> Callable[[], Study]:
    """Validate the study's parameters and check its budget now; return the run for later."""
    arguments = query.core_arguments()
    size = entry.size(**arguments)  # validates first: domain errors before limits
    enforce_study(settings, arguments, size, entry.work(**arguments), query.precision, query.digits)
    ar = arithmetic(query.precision, query.digits)
    return lambda: entry.run(ar, **arguments)


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
