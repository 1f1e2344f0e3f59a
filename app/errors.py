"""One place that turns every error into RFC 9457 problem+json.

- request validation (types, bounds, unknown parameters)  -> 422, each parameter named
- core ``GeometryError`` (domain, representability)        -> 422
- ``LimitExceededError`` (work budget)                           -> 422
- ``TimeLimitError``, ``HardStopError`` (the computation overran)      -> 422, type time-limit
- ``OverloadedError`` (admission control, app/admission.py)      -> 503 with Retry-After
- ``UnknownIdError``                                             -> 404 with the valid ids
- Starlette HTTP errors (unknown path, wrong method)        -> their status
- anything else                                             -> 500 without internals
"""

from __future__ import annotations

import logging
import math
from typing import Any

import orjson
from fastapi import FastAPI, Request, Response
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.routing import Match

from app.admission import HardStopError, OverloadedError, current, overloaded_headers
from app.geometry.errors import DomainError, GeometryError, TimeLimitError
from app.limits import LimitExceededError

PROBLEM_MEDIA_TYPE = "application/problem+json"
logger = logging.getLogger("app.errors")


class UnknownIdError(LookupError):
    """An id that is not in a catalog."""

    def __init__(self, kind: str, value: str, valid: list[str]) -> None:
        self.kind, self.value, self.valid = kind, value, valid
        super().__init__(f"unknown {kind} {value!r}")


def problem(
    status: int,
    title: str,
    detail: str,
    errors: list[dict[str, Any]] | None = None,
    kind: str | None = None,
    **extra: Any,
) -> Response:
    """A problem+json response (``kind``: the type's last segment, default the status)."""
    body = {
        "type": f"https://dcosh.example/problems/{kind or status}",
        "title": title,
        "status": status,
        "detail": detail,
        "errors": errors or [],
        **extra,
    }
    return Response(orjson.dumps(body), status_code=status, media_type=PROBLEM_MEDIA_TYPE)


#: An error echoes at most this many characters of a received string, and this many items of a
#: received list or object (the rest is cut off and counted), so a large input never comes back.
ECHO_CHARS = 200
ECHO_ITEMS = 20


def _short(text: str) -> str:
    if len(text) <= ECHO_CHARS:
        return text
    return f"{text[:ECHO_CHARS]}… ({len(text)} characters)"


def json_safe(value: Any, depth: int = 0) -> Any:
    """A received value as it can appear in JSON (non-finite floats as strings, bytes decoded),
    cut to ``ECHO_CHARS`` characters and ``ECHO_ITEMS`` items per level, 4 levels deep."""
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, bytes):
        return _short(value[: 4 * ECHO_CHARS].decode("utf-8", "replace"))
    if isinstance(value, int) and not isinstance(value, bool) and not -(2**63) <= value < 2**63:
        return _short(str(value))  # JSON encoders stop at 64 bits
    if isinstance(value, str):
        return _short(value)
    if isinstance(value, int | float | bool) or value is None:
        return value
    if depth >= 4:
        return _short(str(type(value).__name__))
    if isinstance(value, list | tuple):
        items = [json_safe(v, depth + 1) for v in value[:ECHO_ITEMS]]
        if len(value) > ECHO_ITEMS:
            items.append(f"… ({len(value)} items)")
        return items
    if isinstance(value, dict):
        out = {_short(str(k)): json_safe(v, depth + 1) for k, v in list(value.items())[:ECHO_ITEMS]}
        if len(value) > ECHO_ITEMS:
            out["…"] = f"({len(value)} items)"
        return out
    return _short(str(value))


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
    if kind == "literal_error":
        return f"{parameter} is one of {ctx.get('expected', '?')}"
    return str(error.get("msg", "invalid"))


def _parameter(loc: tuple[Any, ...] | list[Any]) -> str:
    parts = [str(p) or "(empty name)" for p in loc if p not in ("query", "body", "path", "header")]
    return ".".join(parts) if parts else "body"


def validation_errors(errors: list[Any]) -> list[dict[str, Any]]:
    """pydantic errors as ``{"parameter", "constraint", "value"}`` entries."""
    out = []
    for error in errors:
        parameter = _parameter(error.get("loc", ()))
        out.append(
            {
                "parameter": parameter,
                "constraint": _constraint(error, parameter),
                "value": json_safe(error.get("input")),
            }
        )
    return out


async def _validation_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, RequestValidationError)
    found = list(exc.errors())
    errors = validation_errors(found[:ECHO_ITEMS])  # the first few: never a huge answer
    names = ", ".join(e["parameter"] for e in errors) or "request"
    more = (
        f" ({len(found)} errors, the first {ECHO_ITEMS} listed)" if len(found) > ECHO_ITEMS else ""
    )
    return problem(422, "Invalid parameters", f"Invalid value for: {names}.{more}", errors)


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
        f"Unknown {exc.kind}",
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
    """The documented methods of every route at this path (GET and POST are separate routes)."""
    methods: set[str] = set()
    for route in request.app.router.routes:
        match, _ = route.matches(request.scope)
        if match != Match.NONE:
            methods.update(getattr(route, "methods", None) or ())
    return sorted(methods - {"HEAD"})


async def _unexpected_handler(request: Request, exc: Exception) -> Response:
    logger.exception("unexpected error on %s", request.url.path)
    return problem(500, "Internal error", "The service failed on this request; it was logged.")


def install(app: FastAPI) -> None:
    """Register every handler on ``app``."""
    app.add_exception_handler(RequestValidationError, _validation_handler)
    app.add_exception_handler(GeometryError, _domain_handler)
    app.add_exception_handler(LimitExceededError, _domain_handler)
    app.add_exception_handler(UnknownIdError, _unknown_id_handler)
    app.add_exception_handler(OverloadedError, _overloaded_handler)
    app.add_exception_handler(HardStopError, _hard_stop_handler)
    app.add_exception_handler(StarletteHTTPException, _http_handler)
    app.add_exception_handler(Exception, _unexpected_handler)
