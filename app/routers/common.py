"""What the curve and theorem endpoints share: parsing, limits, computing, encoding."""

import contextlib
import json
from collections.abc import Callable, Coroutine, Iterable, Mapping
from typing import Any, TypeVar

import orjson
from fastapi import Request, Response
from fastapi.exceptions import RequestValidationError
from fastapi.routing import APIRoute
from pydantic import BaseModel, ValidationError

from app import compute_pool
from app.errors import UnknownIdError
from app.geometry import balls
from app.geometry.curve import Curve, Selection
from app.geometry.precision import ExactReal
from app.geometry.studies.common import Study
from app.limits import enforce_drawing, enforce_range, enforce_study, timed_arithmetic
from app.registry import DISCRETIZATIONS, STUDIES, ConvergenceStudy, Discretization
from app.rendering.curves import SVG_MEDIA_TYPE, curve_svg
from app.responses import (
    CSV_MEDIA_TYPE,
    NPY_MEDIA_TYPE,
    NPZ_MEDIA_TYPE,
    checks_csv,
    curve_csv,
    curve_document,
    curve_npy,
    curve_npz,
    encode_json,
)
from app.routers.caching import JSONBytesResponse
from app.schemas.common import PROBLEM_RESPONSES, CurveQuery
from app.schemas.convergence import StudyQuery
from app.services.selection import selection
from app.settings import Settings

#: An SVG opened on its own is a document: it may style itself but load and run nothing.
SVG_HEADERS = {"Content-Security-Policy": "default-src 'none'; style-src 'unsafe-inline'"}


CURVE_RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {
            "text/csv": {
                "schema": {"type": "string"},
                "example": "curve,index,x,y\np,0,-0.1,1.0\np,1,0.1,1.0\n",
            },
            "image/svg+xml": {"schema": {"type": "string"}},
            NPY_MEDIA_TYPE: {"schema": {"type": "string", "format": "binary"}},
            NPZ_MEDIA_TYPE: {"schema": {"type": "string", "format": "binary"}},
        },
        "description": "The curve as JSON (default), CSV (`format=csv`), SVG (`format=svg`: p "
        "and its companions with axes, legend and equal scales) or NumPy .npy (`format=npy`: "
        "the vertices of p as an (n, 2) little-endian float64 array; the header "
        "`X-First-Index` gives the index of row 0, rows are consecutive; about 16 bytes per "
        "vertex against about 40 in JSON, read with `numpy.load` or as a Float64Array after "
        "the .npy header). GET responses carry an ETag and Cache-Control; a matching "
        "If-None-Match gets 304. Text bodies are gzip-compressed for clients that accept it "
        "(`Vary: Accept-Encoding`; the gzip variant's ETag ends in `-gzip`).",
        "headers": {
            "X-First-Index": {
                "description": "format=npy: the index of the first row.",
                "schema": {"type": "integer"},
            }
        },
    },
    304: {"description": "Not modified (the If-None-Match ETag matches)."},
    **PROBLEM_RESPONSES,
}


class ExactJSONRoute(APIRoute):
    """A route whose JSON body keeps every number with a fraction or exponent as written.

    Such a number arrives as an ``ExactReal``: a float (so validation and float64 are as
    before) that remembers its text, which precision=mp computes with (issue 15: a POST body's
    ``"d": 0.12345678901234567890123`` is that decimal, not its nearest double).
    """

    def get_route_handler(self) -> Callable[[Request], Coroutine[Any, Any, Response]]:
        handler = super().get_route_handler()

        async def exact_handler(request: Request) -> Response:
            if request.method == "POST":
                body = await request.body()
                with contextlib.suppress(ValueError):  # FastAPI reports a malformed body
                    parsed = json.loads(body, parse_float=ExactReal)
                    if isinstance(parsed, dict):  # anything else is refused as FastAPI refuses it
                        request._json = parsed
            return await handler(request)

        return exact_handler


def example_of(curve: Curve) -> Any:
    """A curve's JSON document to show in /docs, numbers rounded to 12 digits (so that the stored
    OpenAPI document does not depend on the last bits of a CPU's exp and log)."""
    return _rounded(orjson.loads(encode_json(curve_document(curve))))


def _rounded(value: Any) -> Any:
    if isinstance(value, float):
        return float(f"{value:.12g}")
    if isinstance(value, list):
        return [_rounded(v) for v in value]
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    return value


def with_example(responses: dict[int | str, dict[str, Any]], example: Any) -> dict[int | str, Any]:
    """``responses`` with a JSON example for the 200."""
    ok = dict(responses[200])
    ok["content"] = {"application/json": {"example": example}, **ok["content"]}
    return {**responses, 200: ok}


def settings_of(request: Request) -> Settings:
    settings: Settings = request.app.state.settings
    return settings


async def reject_repeated_parameters(request: Request) -> None:
    """A parameter given twice is ambiguous: 422 instead of silently taking one.

    Asynchronous (it never waits) so that FastAPI does not hop to a thread to run it."""
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


Model = TypeVar("Model", bound=BaseModel)


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
    return lambda: entry.run(timed_arithmetic(settings, query.precision, query.digits), **arguments)


def selection_of(
    query: CurveQuery, statements: Iterable[str], companions: Iterable[str]
) -> Selection:
    """The checks and companions a curve request asks for (``app.services.selection``)."""
    return selection(query.checks, query.companions, statements, companions, query.format)


def admit_curve(
    entry: Discretization,
    query: CurveQuery,
    settings: Settings,
    arguments: dict[str, Any] | None = None,
) -> tuple[Selection, dict[str, Any]]:
    """Check the request's limits and charge its estimated cost; its selection and arguments."""
    selection = selection_of(query, (s.id for s in entry.info.statements), entry.info.companions)
    if arguments is None:
        arguments = query.core_arguments()
    enforce_range(
        settings,
        arguments["i_min"],
        arguments["i_max"],
        arguments.get("method", "construction"),
        query.precision,
        query.digits,
        kind=entry.info.id,
        extra_digits=balls.extra_digits(entry.info.id, arguments)
        if query.precision == "mp"
        else None,
    )
    if query.format == "svg":
        enforce_drawing(settings, arguments["i_min"], arguments["i_max"])
    return selection, arguments


def computed(
    entry: Discretization,
    query: CurveQuery,
    settings: Settings,
    selection: Selection,
    arguments: dict[str, Any],
) -> Curve:
    ar = timed_arithmetic(settings, query.precision, query.digits)
    # precision=mp on rigorous balls where the discretization is served on them (issue 15)
    return balls.serve(
        entry.info.id, ar, lambda a: entry.compute(a, **arguments, selection=selection), arguments
    )


def compute(
    entry: Discretization,
    query: CurveQuery,
    settings: Settings,
    arguments: dict[str, Any] | None = None,
) -> Curve:
    """Check the work budget, then run the core on what the request selects (``arguments``:
    the query's ``core_arguments()`` when the caller has them already)."""
    return computed(entry, query, settings, *admit_curve(entry, query, settings, arguments))


def curve_answer(entry: Discretization, query: CurveQuery, settings: Settings) -> Response:
    """The curve rendered in the request's format: computed here, or in a child process of
    the worker's pool when its estimate is heavy (app/compute_pool.py)."""
    selection, arguments = admit_curve(entry, query, settings)
    pool = compute_pool.offload(balls=query.precision == "mp")
    if pool is not None:
        # the validated values travel (a POST's body model is built at run time: no pickling)
        values = dict(query)
        return in_child(pool, render_curve, entry.info.id, values, query.model_fields_set, settings)
    return curve_response(computed(entry, query, settings, selection, arguments), query.format)


def in_child(pool: compute_pool.ComputePool, function: Callable[..., Any], *args: Any) -> Response:
    """``function(*args)``, a module-level function rendering a response, run in a child."""
    rendered = pool.run(function, *args)
    return Response(rendered.body, rendered.status, rendered.headers, rendered.media_type)


def render_curve(
    identifier: str, values: dict[str, Any], fields_set: set[str], settings: Settings
) -> Response:
    """What a pool child runs for ``curve_answer`` (its charge is a no-op there)."""
    entry = discretization(identifier)
    query = entry.query.model_construct(fields_set, **values)
    return curve_response(compute(entry, query, settings), query.format)


def curve_response(curve: Curve, response_format: str) -> Response:
    if response_format == "csv":
        return Response(curve_csv(curve), media_type=CSV_MEDIA_TYPE)
    if response_format == "npy":
        body, first = curve_npy(curve)
        return Response(body, media_type=NPY_MEDIA_TYPE, headers={"X-First-Index": str(first)})
    if response_format == "svg":
        return Response(curve_svg(curve), media_type=SVG_MEDIA_TYPE, headers=SVG_HEADERS)
    if response_format == "npz":
        return Response(curve_npz(curve), media_type=NPZ_MEDIA_TYPE)
    if response_format == "checks-csv":
        return Response(checks_csv(curve.checks), media_type=CSV_MEDIA_TYPE)
    return JSONBytesResponse(encode_json(curve_document(curve)))
