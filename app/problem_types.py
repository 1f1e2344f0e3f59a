"""Problem types and problem+json responses (RFC 9457): what every error answer is made of.

``PROBLEM_TYPES`` is the catalog of the kinds of problem this service answers with, one title
each; a problem's ``type`` is the page of its kind on this service (``/problems/{slug}``, served
by app.routers.problems). ``problem`` builds the response; ``json_safe`` cuts a received value
down to what an error may echo. The handlers that choose a problem for each exception live in
app.errors.
"""

from __future__ import annotations

import math
from typing import Any

import orjson
from starlette.responses import Response

from app.geometry.precision import ExactReal

PROBLEM_MEDIA_TYPE = "application/problem+json"


class UnknownIdError(LookupError):
    """An id that is not in a catalog."""

    def __init__(self, kind: str, value: str, valid: list[str]) -> None:
        self.kind, self.value, self.valid = kind, value, valid
        super().__init__(f"unknown {kind} {value!r}")


class ProblemType:
    """One kind of problem: its slug (the last part of its ``type`` URI), status and title."""

    def __init__(self, slug: str, status: int, title: str, description: str) -> None:
        self.slug, self.status, self.title, self.description = slug, status, title, description

    @property
    def uri(self) -> str:
        """The ``type`` member: a path on this service, resolved against the request's URL."""
        return f"{PROBLEMS_PATH}/{self.slug}"


PROBLEMS_PATH = "/problems"

PROBLEM_TYPES: dict[str, ProblemType] = {
    t.slug: t
    for t in (
        ProblemType(
            "invalid-parameters",
            422,
            "Invalid parameters",
            "A query parameter or body field has the wrong type, breaks a bound of the "
            "schema, is given twice, or is not a parameter of the endpoint; or the body is not "
            "valid JSON. `errors` names each parameter with its constraint and the value sent.",
        ),
        ProblemType(
            "outside-domain",
            422,
            "Outside the domain",
            "The parameters are each valid but the construction is not defined for them (for "
            "example d >= h), or the result is not representable in the chosen precision. "
            "`errors` names the parameter and the condition it must satisfy.",
        ),
        ProblemType(
            "over-limits",
            422,
            "Over the limits",
            "The request would exceed a work limit of this deployment (vertices, digits, "
            "mp work, samples, computation time). The limits are settings (DCOSH_MAX_…); the "
            "constraint gives the bound in force.",
        ),
        ProblemType(
            "unknown-id",
            404,
            "Unknown id",
            "The path names a discretization, study, statement, figure, surface, erratum or "
            "problem type that does not exist; `valid` lists those that do.",
        ),
        ProblemType("not-found", 404, "Not found", "No resource lives at this path."),
        ProblemType(
            "method-not-allowed",
            405,
            "Method not allowed",
            "The resource exists but not with this method; the `Allow` header lists the ones "
            "it has (HEAD wherever GET is served).",
        ),
        ProblemType(
            "not-acceptable",
            406,
            "Not acceptable",
            "No representation of the resource satisfies the `Accept` header; `available` lists "
            "the formats and media types it has (name one with the query parameter `format`, "
            "which wins over `Accept`).",
        ),
        ProblemType(
            "unsupported-media-type",
            415,
            "Unsupported media type",
            "A POST body must be JSON: `Content-Type: application/json` (or a `+json` type).",
        ),
        ProblemType(
            "bad-request",
            400,
            "Bad request",
            "The request could not be read to its end (the client went away).",
        ),
        ProblemType(
            "request-timeout",
            408,
            "Request timeout",
            "The request body did not arrive within DCOSH_BODY_TIMEOUT seconds.",
        ),
        ProblemType(
            "content-too-large",
            413,
            "Content too large",
            "The request body is larger than DCOSH_MAX_BODY_BYTES (declared or, chunked, as it "
            "arrives); nothing of it is kept.",
        ),
        ProblemType(
            "time-limit",
            422,
            "Over the time limit",
            "The computation could not finish within DCOSH_TIME_LIMIT seconds from the request's "
            "arrival (waiting counts) and was stopped; ask for a shorter range or fewer digits.",
        ),
        ProblemType(
            "overloaded",
            503,
            "Overloaded",
            "The worker admits no more work now (its budget of concurrent work is spent, the "
            "request could not finish by its deadline, or the worker is shutting down); retry "
            "after the `Retry-After` seconds, on this or another replica.",
        ),
        ProblemType(
            "internal-error",
            500,
            "Internal error",
            "The service failed on this request. It was logged; no internals are shown.",
        ),
    )
}
_BY_TITLE = {t.title: t for t in PROBLEM_TYPES.values()}


def problem(
    status: int,
    title: str,
    detail: str,
    errors: list[dict[str, Any]] | None = None,
    kind: str | None = None,
    **extra: Any,
) -> Response:
    """A problem+json response; ``type`` is the page of the problem type ``kind`` (its slug), or
    of the type with this title (``about:blank`` for a title that has none, as RFC 9457 allows)."""
    known = PROBLEM_TYPES.get(kind) if kind is not None else _BY_TITLE.get(title)
    body = {
        "type": known.uri if known is not None and known.status == status else "about:blank",
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
