"""One place that turns every error into RFC 9457 problem+json.

- request validation (types, bounds, unknown parameters)  -> 422, each parameter named
- core ``GeometryError`` (domain, representability)        -> 422
- ``LimitExceededError`` (work budget)                           -> 422
- ``UnknownIdError``                                             -> 404 with the valid ids
- Starlette HTTP errors (unknown path, wrong method)        -> their status
- anything else                                             -> 500 without internals
"""

from __future__ import annotations

import logging
import math
import warnings
from typing import Any

import orjson
from fastapi import FastAPI, Request, Response
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.routing import Match

from app.geometry.errors import DomainError, GeometryError
from app.geometry.precision import ExactReal
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
    **extra: Any,
) -> Response:
    """A problem+json response."""
    body = {
        "type": f"https://dcosh.example/problems/{status}",
        "title": title,
        "status": status,
        "detail": detail,
        "errors": errors or [],
        **extra,
    }
    return Response(
        orjson.dumps(body, default=_exact_number),
        status_code=status,
        media_type=PROBLEM_MEDIA_TYPE,
    )


def _exact_number(value: Any) -> Any:
    """A precision=mp parameter (``ExactReal``) as the JSON number the client wrote."""
    if isinstance(value, ExactReal):
        return orjson.Fragment(value.text)
    raise TypeError(f"{type(value).__name__} is not JSON serializable")


def json_safe(value: Any) -> Any:
    """A received value as it can appear in JSON (non-finite floats as strings, bytes decoded)."""
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, int) and not isinstance(value, bool) and not -(2**63) <= value < 2**63:
        return str(value)  # JSON encoders stop at 64 bits
    if isinstance(value, str | int | float | bool) or value is None:
        return value
    if isinstance(value, list | tuple):
        return [json_safe(v) for v in value]
    if isinstance(value, dict):
        return {str(k): json_safe(v) for k, v in value.items()}
    return str(value)


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
    errors = validation_errors(list(exc.errors()))
    names = ", ".join(e["parameter"] for e in errors) or "request"
    return problem(422, "Invalid parameters", f"Invalid value for: {names}.", errors)


async def _domain_handler(request: Request, exc: Exception) -> Response:
    if isinstance(exc, DomainError | LimitExceededError):
        entry = {
            "parameter": exc.parameter,
            "constraint": exc.constraint,
            "value": json_safe(exc.value),
        }
        title = "Over the limits" if isinstance(exc, LimitExceededError) else "Outside the domain"
        return problem(422, title, str(exc), [entry])
    return problem(422, "Outside the domain", str(exc))


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


async def _numerical_handler(request: Request, exc: Exception) -> Response:
    """A numerical warning of the core (overflow, 0/0), raised as an error: a 422, never a
    result computed from infinities (the tests turn the same warnings into errors)."""
    entry = {
        "parameter": "precision",
        "constraint": "values representable in the chosen precision",
        "value": request.query_params.get("precision"),
    }
    return problem(
        422,
        "Outside the domain",
        f"A value of this computation cannot be represented ({exc}); use precision=mp or a "
        "shorter range.",
        [entry],
    )


def install(app: FastAPI) -> None:
    """Register every handler on ``app``; numerical warnings of the core become errors."""
    warnings.filterwarnings("error", category=RuntimeWarning, module=r"app(\.|$)")
    app.add_exception_handler(RuntimeWarning, _numerical_handler)
    app.add_exception_handler(FloatingPointError, _numerical_handler)
    app.add_exception_handler(RequestValidationError, _validation_handler)
    app.add_exception_handler(GeometryError, _domain_handler)
    app.add_exception_handler(LimitExceededError, _domain_handler)
    app.add_exception_handler(UnknownIdError, _unknown_id_handler)
    app.add_exception_handler(StarletteHTTPException, _http_handler)
    app.add_exception_handler(Exception, _unexpected_handler)
