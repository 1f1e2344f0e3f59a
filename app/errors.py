"""One place that turns every error into RFC 9457 problem+json.

- request validation (types, bounds, unknown parameters)  -> 422, each parameter named
- core ``GeometryError`` (domain, representability)        -> 422
- ``LimitExceededError`` (work budget)                           -> 422
- ``TimeLimitError``, ``HardStopError`` (the computation overran)      -> 422, type time-limit
- ``OverloadedError`` (admission control, app/admission.py)      -> 503 with Retry-After
- ``UnknownIdError``                                             -> 404 with the valid ids
- a POST body that is not JSON                              -> 415
- a GET whose Accept no format satisfies (app.negotiation)   -> 406 with the available ones
- Starlette HTTP errors (unknown path, wrong method)        -> their status
- anything else                                             -> 500 without internals

Each problem's ``type`` is a path on this service (``/problems/{slug}``, served by
app.routers.problems) naming one of ``PROBLEM_TYPES`` (app.problem_types, with the response
builder ``problem``); each type has one title. Besides the handlers: the app-wide request guards
(undeclared query parameters, the digits limit) and ``HeadAsGet``.
"""

from __future__ import annotations

import logging
import math
import warnings
from typing import Any

from fastapi import FastAPI, Request, Response
from fastapi.dependencies.models import Dependant
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.routing import Match
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.admission import (
    HardStopError,
    OverloadedError,
    current,
    overloaded_headers,
    stopped_inside,
)
from app.geometry.errors import DomainError, GeometryError, TimeLimitError
from app.limits import LimitExceededError
from app.problem_types import (
    ECHO_ITEMS,
    PROBLEM_MEDIA_TYPE,
    PROBLEM_TYPES,
    PROBLEMS_PATH,
    ProblemType,
    UnknownIdError,
    json_safe,
    problem,
)

__all__ = [
    "PROBLEMS_PATH",
    "PROBLEM_MEDIA_TYPE",
    "PROBLEM_TYPES",
    "ProblemType",
    "UnknownIdError",
    "install",
    "json_safe",
    "problem",
]
logger = logging.getLogger("app.errors")
#: ``request.state`` attribute: the ``precision`` member of a JSON body (the numerical-warning
#: handler names it; its own request object no longer holds the body).
BODY_PRECISION = "body_precision"


_BOUNDS = {
    "greater_than": ">",
    "greater_than_equal": ">=",
    "less_than": "<",
    "less_than_equal": "<=",
}


def _constraint(error: dict[str, Any], parameter: str) -> str:
    """The violated condition of one pydantic error, in a form like ``h > 0``."""
    kind = error.get("type", "")
    ctx = error.get("ctx") or {}
    if kind in _BOUNDS:
        bound = next(iter(ctx.values()), "?")
        return f"{parameter} {_BOUNDS[kind]} {bound}"
    if kind == "extra_forbidden":
        return "not a parameter of this endpoint"
    if kind == "missing":
        return "required"
    if kind == "finite_number":
        return f"{parameter} is a finite number"
    if kind == "json_invalid":
        position = error.get("loc", ("body", "?"))[-1]
        reason = (ctx.get("error") or "invalid JSON").rstrip(".")
        return f"a JSON object (invalid JSON at character offset {position}: {reason})"
    if kind == "literal_error":
        return f"{parameter} is one of {ctx.get('expected', '?')}"
    return str(error.get("msg", "invalid"))


def _parameter(loc: tuple[Any, ...] | list[Any], kind: str = "") -> str:
    if kind == "json_invalid":  # loc is ("body", position): the body is at fault, not field "12"
        return "body"
    parts = [str(p) or "(empty name)" for p in loc if p not in ("query", "body", "path", "header")]
    return ".".join(parts) if parts else "body"


def validation_errors(errors: list[Any]) -> list[dict[str, Any]]:
    """pydantic errors as ``{"parameter", "constraint", "value"}`` entries."""
    out = []
    for error in errors:
        parameter = _parameter(error.get("loc", ()), error.get("type", ""))
        value = None if error.get("type") == "json_invalid" else error.get("input")
        out.append(
            {
                "parameter": parameter,
                "constraint": _constraint(error, parameter),
                "value": json_safe(value),
            }
        )
    return out


async def _validation_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, RequestValidationError)
    if request.method == "POST" and not _is_json(request.headers.get("content-type")):
        received = request.headers.get("content-type") or "none"
        return problem(
            415,
            "Unsupported media type",
            f"The body must be JSON (Content-Type: application/json), not {received}.",
            [{"parameter": "Content-Type", "constraint": "application/json", "value": received}],
        )
    found = list(exc.errors())
    errors = validation_errors(found[:ECHO_ITEMS])  # the first few: never a huge answer
    names = ", ".join(e["parameter"] for e in errors) or "request"
    more = (
        f" ({len(found)} errors, the first {ECHO_ITEMS} listed)" if len(found) > ECHO_ITEMS else ""
    )
    return problem(422, "Invalid parameters", f"Invalid value for: {names}.{more}", errors)


def _is_json(content_type: str | None) -> bool:
    """Whether a Content-Type names JSON (``application/json`` or ``application/…+json``)."""
    if not content_type:
        return False
    media = content_type.split(";", 1)[0].strip().lower()
    return media == "application/json" or (
        media.startswith("application/") and media.endswith("+json")
    )


async def _domain_handler(request: Request, exc: Exception) -> Response:
    if isinstance(exc, TimeLimitError):
        entry = {"parameter": exc.parameter, "constraint": exc.constraint, "value": None}
        return problem(422, "Over the time limit", str(exc), [entry], kind="time-limit")
    if isinstance(exc, DomainError | LimitExceededError):
        entry = {
            "parameter": exc.parameter,
            "constraint": exc.constraint,
            "value": json_safe(exc.value),
        }
        title = "Over the limits" if isinstance(exc, LimitExceededError) else "Outside the domain"
        return problem(422, title, str(exc), [entry])
    return problem(422, "Outside the domain", str(exc))


async def _overloaded_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, OverloadedError)
    response = problem(
        503, "Overloaded", f"Not admitted now: {exc.reason}; retry later.", kind="overloaded"
    )
    for key, value in overloaded_headers(exc.retry_after):
        response.headers[key.decode()] = value.decode()
    return response


async def _hard_stop_handler(request: Request, exc: Exception) -> Response:
    limit = request.app.state.settings.time_limit
    constraint = f"the computation finishes within {limit:g} s (DCOSH_TIME_LIMIT)"
    ticket = current()
    return problem(
        422,
        "Over the time limit",
        f"The computation was stopped past its deadline: {constraint}.",
        [
            {
                "parameter": "request" if ticket is None else ticket.parameter,
                "constraint": constraint,
                "value": None,
            }
        ],
        kind="time-limit",
    )


async def _unknown_id_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, UnknownIdError)
    return problem(
        404,
        "Unknown id",
        f"There is no {exc.kind} {exc.value!r}. Valid: {', '.join(exc.valid)}.",
        [{"parameter": "id", "constraint": f"one of {', '.join(exc.valid)}", "value": exc.value}],
        valid=exc.valid,
    )


async def _http_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, StarletteHTTPException)
    if exc.status_code == 400:  # a body that is not even text: the same 422 as invalid JSON
        return problem(
            422,
            "Invalid parameters",
            f"The request body could not be read: {exc.detail}.",
            [{"parameter": "body", "constraint": "a JSON object in UTF-8", "value": None}],
        )
    titles = {404: "Not found", 405: "Method not allowed"}
    response = problem(
        exc.status_code,
        titles.get(exc.status_code, "HTTP error"),
        str(exc.detail) if exc.status_code != 404 else f"No resource at {request.url.path}.",
    )
    for key, value in (exc.headers or {}).items():
        response.headers[key] = value
    if exc.status_code == 405:
        response.headers["Allow"] = ", ".join(allowed_methods(request))
    return response


def allowed_methods(request: Request) -> list[str]:
    """The methods of every route at this path (GET and POST are separate routes), with HEAD
    wherever GET is served (``HeadAsGet``).

    FastAPI 0.163 wraps each included router in one route without ``methods``; its effective
    routes (``effective_candidates``) carry them, so the wrappers are walked.
    """
    methods: set[str] = set()
    path = request.scope["path"]

    def visit(routes: Any) -> None:
        for route in routes:
            candidates = getattr(route, "effective_candidates", None)
            if callable(candidates):
                visit(candidates())
                visit(route.effective_low_priority_routes())
                continue
            regex = getattr(route, "path_regex", None)
            if regex is not None and regex.match(path):
                methods.update(getattr(route, "methods", None) or ())
            elif regex is None and hasattr(route, "matches"):
                match, _ = route.matches(request.scope)
                if match != Match.NONE:
                    methods.update(getattr(route, "methods", None) or ())

    visit(request.app.router.routes)
    if "GET" in methods:
        methods.add("HEAD")
    return sorted(methods)


async def _unexpected_handler(request: Request, exc: Exception) -> Response:
    if stopped_inside(exc):
        return await _hard_stop_handler(request, exc)
    logger.exception("unexpected error on %s", request.url.path)
    return problem(500, "Internal error", "The service failed on this request; it was logged.")


async def _numerical_handler(request: Request, exc: Exception) -> Response:
    """A numerical warning of the core (overflow, 0/0), raised as an error: a 422, never a
    result computed from infinities (the tests turn the same warnings into errors)."""
    precision = _request_precision(request)
    entry = {
        "parameter": "precision",
        "constraint": "values representable in the chosen precision",
        "value": precision,
    }
    advice = "a shorter range" if precision == "mp" else "precision=mp or a shorter range"
    return problem(
        422,
        "Outside the domain",
        f"A value of this computation cannot be represented ({exc}); use {advice}.",
        [entry],
    )


def _request_precision(request: Request) -> Any:
    """The ``precision`` the request carried, in its query or its JSON body (noted by
    `enforce_digits_limit`, which reads the body), or the default ``float64`` when it gave none."""
    given = request.query_params.get("precision")
    if given is None:
        given = getattr(request.state, BODY_PRECISION, None)
    return "float64" if given is None else json_safe(given)


async def refuse_undeclared_query(request: Request) -> None:
    """App-wide dependency: an endpoint that declares no query parameter refuses any.

    Endpoints with parameters refuse unknown ones through their request models (``extra=
    "forbid"``) or their own parsing; this covers the rest (catalogs, /health, /errata, …) the
    same way: a 422 naming each parameter as "not a parameter of this endpoint".

    Asynchronous although it never waits: FastAPI runs a synchronous dependency in the thread
    pool, a thread hop on every request (it halved the requests/s of /health).
    """
    if not request.query_params:
        return
    route = request.scope.get("route")
    dependant = getattr(route, "dependant", None)
    if dependant is None or not getattr(route, "include_in_schema", False):
        return
    if _declares_query(dependant) or "parameters" in (getattr(route, "openapi_extra", None) or {}):
        return  # checked by the endpoint's model, or the route parses and documents its own
    raise RequestValidationError(
        [
            {"type": "extra_forbidden", "loc": ("query", key), "msg": "unknown", "input": value}
            for key, value in request.query_params.multi_items()
        ]
    )


async def enforce_digits_limit(request: Request) -> None:
    """App-wide dependency: ``digits`` is at most ``DCOSH_MAX_DIGITS`` whatever the precision.

    The OpenAPI document gives that maximum (app.schemas.openapi_document), so the server holds
    it everywhere, also where float64 ignores the value; the same 422 as the mp check.
    """
    limit: int = request.app.state.settings.max_digits
    values: list[Any] = [
        value
        for key, value in request.query_params.multi_items()
        if key == "digits" or key.endswith(".digits")
    ]
    if request.method == "POST" and _is_json(request.headers.get("content-type")):
        try:
            body = await request.json()
        except ValueError:
            body = None
        if isinstance(body, dict) and "digits" in body:
            values.append(body["digits"])
        if isinstance(body, dict) and "precision" in body:
            setattr(request.state, BODY_PRECISION, body["precision"])
    for value in values:
        try:
            number = float(value)
        except (TypeError, ValueError):
            continue  # not a number: the request model names it
        if isinstance(value, bool) or not math.isfinite(number):
            continue
        if number > limit:
            raise LimitExceededError("digits", f"1 <= digits <= {limit}", json_safe(value))


def _declares_query(dependant: Dependant) -> bool:
    return bool(dependant.query_params) or any(map(_declares_query, dependant.dependencies))


class HeadAsGet:
    """ASGI middleware: HEAD is answered as GET without the body (same status and headers,
    Content-Length included), wherever GET is served."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] != "HEAD":
            await self.app(scope, receive, send)
            return

        async def without_body(message: Message) -> None:
            if message["type"] == "http.response.body":
                if message.get("more_body", False):
                    return
                message = {"type": "http.response.body", "body": b"", "more_body": False}
            await send(message)

        await self.app({**scope, "method": "GET"}, receive, without_body)


def install(app: FastAPI) -> None:
    """Register every handler on ``app``; numerical warnings of the core become errors."""
    warnings.filterwarnings("error", category=RuntimeWarning, module=r"app(\.|$)")
    app.add_exception_handler(RuntimeWarning, _numerical_handler)
    app.add_exception_handler(FloatingPointError, _numerical_handler)
    app.add_exception_handler(RequestValidationError, _validation_handler)
    app.add_exception_handler(GeometryError, _domain_handler)
    app.add_exception_handler(LimitExceededError, _domain_handler)
    app.add_exception_handler(UnknownIdError, _unknown_id_handler)
    app.add_exception_handler(OverloadedError, _overloaded_handler)
    app.add_exception_handler(HardStopError, _hard_stop_handler)
    app.add_exception_handler(StarletteHTTPException, _http_handler)
    app.add_exception_handler(Exception, _unexpected_handler)
