"""Content negotiation: the ``Accept`` header chooses the ``format`` a GET did not name.

Every computational endpoint chooses its representation with the query parameter ``format``
(JSON by default). A GET (or HEAD) without ``format`` whose ``Accept`` header prefers another
representation the endpoint has gets that one: ``Accept: text/csv`` on a curve is
``format=csv``. ``Negotiation``, an ASGI middleware outside the response cache, does this by
adding ``format=…`` to the query string, so everything inside (validation, the canonical cache
key and hence the ETag, the fast path's raw-request table) sees one request per representation.
``format`` in the query wins over ``Accept``. An ``Accept`` that no representation of the
endpoint satisfies is a 406 problem listing the available media types. These responses say
``Vary: Accept``.

The endpoints and their formats come from the app's own OpenAPI document: every GET operation
with a ``format`` query parameter, the formats of its enum whose media type names them alone
(``MEDIA_TYPES``). Two formats are left to ``format``: ``checks-csv`` (``text/csv`` is the curve's
CSV) and the meshes' ``ply`` and ``vtu``, served as ``application/octet-stream`` and
``application/xml``, types that name no format (browsers send ``application/xml;q=0.9`` when
they open a page: it must not turn a link into a VTU download).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any
from urllib.parse import parse_qsl, urlencode

from starlette.datastructures import MutableHeaders
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.problem_types import problem

#: The media type that stands for each format in ``Accept``.
MEDIA_TYPES = {
    "json": "application/json",
    "csv": "text/csv",
    "svg": "image/svg+xml",
    "npy": "application/x-npy",
    "npz": "application/x-npz",
    "html": "text/html",
    "obj": "model/obj",
    "glb": "model/gltf-binary",
}


def negotiable(operation: dict[str, Any]) -> dict[str, str]:
    """The formats of an OpenAPI GET operation that ``Accept`` can choose, default first, each
    with its media type (empty when the operation has no ``format`` parameter)."""
    for parameter in operation.get("parameters", []):
        if parameter.get("name") == "format" and parameter.get("in") == "query":
            schema = parameter.get("schema", {})
            formats = [f for f in schema.get("enum", []) if f in MEDIA_TYPES]
            default = schema.get("default")
            if default not in formats:
                return {}
            ordered = [default, *(f for f in formats if f != default)]
            return {f: MEDIA_TYPES[f] for f in ordered}
    return {}


def accept_description(formats: dict[str, str]) -> str:
    """The sentence the OpenAPI document adds to ``format`` where ``Accept`` chooses it."""
    listed = ", ".join(f"`{media}` ({name})" for name, media in formats.items())
    return (
        f" Without `format`, the `Accept` header chooses among {listed}; `format` wins over "
        "`Accept`, and an `Accept` none of them satisfies is a 406 (`Vary: Accept`)."
    )


@dataclass(frozen=True)
class Range:
    """One media range of an Accept header: ``type/subtype`` (either may be ``*``) and q."""

    type: str
    subtype: str
    q: float
    position: int

    def specificity(self, media_type: str) -> int:
        """How closely this range names ``media_type`` (-1: it does not)."""
        kind, _, sub = media_type.partition("/")
        if self.type == "*" and self.subtype == "*":
            return 0
        if self.type == kind and self.subtype == "*":
            return 1
        if self.type == kind and self.subtype == sub:
            return 2
        return -1


def parse_accept(header: str) -> list[Range]:
    """The media ranges of an Accept header (parameters other than q are ignored; a malformed
    q counts as 0, a range without ``/`` is skipped)."""
    ranges = []
    for position, item in enumerate(header.split(",")):
        media, *params = (part.strip() for part in item.split(";"))
        kind, slash, sub = media.lower().partition("/")
        if not slash or not kind or not sub:
            continue
        q = 1.0
        for param in params:
            name, _, value = param.partition("=")
            if name.strip().lower() == "q":
                try:
                    q = min(max(float(value), 0.0), 1.0)
                except ValueError:
                    q = 0.0
        ranges.append(Range(kind, sub, q, position))
    return ranges


def choose(header: str, formats: dict[str, str]) -> str | None:
    """The format ``Accept`` prefers among ``formats`` (default first), or None if it accepts
    none. Each format gets the q of the most specific range naming its media type; the highest
    q wins, then the default format, then the format whose range comes first in the header."""
    ranges = parse_accept(header)
    if not ranges:
        return next(iter(formats))  # nothing readable: as if Accept were absent
    best: tuple[float, int, int] | None = None
    chosen = None
    for index, (name, media) in enumerate(formats.items()):
        matching = [(r.specificity(media), r) for r in ranges if r.specificity(media) >= 0]
        if not matching:
            continue
        _, closest = max(matching, key=lambda pair: (pair[0], -pair[1].position))
        if closest.q <= 0:
            continue
        rank = (closest.q, 1 if index == 0 else 0, -closest.position)
        if best is None or rank > best:
            best, chosen = rank, name
    return chosen


@dataclass(frozen=True)
class Endpoint:
    pattern: re.Pattern[str]
    formats: dict[str, str]


def endpoints(spec: dict[str, Any]) -> list[Endpoint]:
    """Every GET path of ``spec`` whose format ``Accept`` can choose, as a path pattern."""
    found = []
    for path, operations in spec.get("paths", {}).items():
        formats = negotiable(operations.get("get", {}))
        if len(formats) > 1:
            regex = re.sub(r"\\\{[^}]*\\\}", "[^/]+", re.escape(path))
            found.append(Endpoint(re.compile(f"^{regex}$"), formats))
    return found


def endpoint_of(scope: Scope) -> Endpoint | None:
    """The negotiable endpoint of the request's path, or None (the table is read from the
    app's OpenAPI document once per app and kept on ``app.state``)."""
    state = scope["app"].state
    table: list[Endpoint] | None = getattr(state, "negotiable_endpoints", None)
    if table is None:
        table = endpoints(scope["app"].openapi())
        state.negotiable_endpoints = table
    path = scope["path"]
    return next((e for e in table if e.pattern.match(path)), None)


def with_accept(present: str | None) -> str:
    """The Vary value of a negotiated response whose Vary was ``present``."""
    if not present:
        return "Accept"
    if "accept" not in [v.strip().lower() for v in present.split(",")]:
        return f"Accept, {present}"
    return present


class Negotiation:
    """ASGI middleware: ``Accept`` → ``format`` on the GETs that have one (see the module doc)."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    @staticmethod
    def _endpoint(scope: Scope) -> Endpoint | None:
        return endpoint_of(scope)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] != "GET":
            await self.app(scope, receive, send)
            return
        endpoint = self._endpoint(scope)
        if endpoint is None:
            await self.app(scope, receive, send)
            return
        query = scope["query_string"]
        named = any(key == "format" for key, _ in parse_qsl(query.decode("latin-1"), True))
        accept = next((v for k, v in scope["headers"] if k.lower() == b"accept"), None)
        if not named and accept is not None:
            chosen = choose(accept.decode("latin-1"), endpoint.formats)
            if chosen is None:
                await self._not_acceptable(accept.decode("latin-1"), endpoint)(scope, receive, send)
                return
            if chosen != next(iter(endpoint.formats)):
                extra = urlencode({"format": chosen}).encode()
                scope = {**scope, "query_string": query + b"&" + extra if query else extra}

        async def vary(message: Message) -> None:
            if message["type"] == "http.response.start":
                headers = MutableHeaders(scope=message)
                present = headers.get("vary")
                vary = with_accept(present)
                if vary != present:
                    headers["Vary"] = vary
            await send(message)

        await self.app(scope, receive, vary)

    @staticmethod
    def _not_acceptable(header: str, endpoint: Endpoint) -> Any:
        available = [{"format": f, "media_type": m} for f, m in endpoint.formats.items()]
        media = ", ".join(endpoint.formats.values())
        response = problem(
            406,
            "Not acceptable",
            f"No representation here satisfies Accept: {header[:200]}. Available: {media} "
            "(or name one with the query parameter format).",
            [
                {
                    "parameter": "Accept",
                    "constraint": f"one of {media}",
                    "value": header[:200],
                }
            ],
            available=available,
        )
        response.headers["Vary"] = "Accept"
        return response
