"""The fast lane: small computed curve (and theorem) GETs answered without the middleware chain
or a thread.

A GET of ``/discretizations/{id}`` goes through seven middlewares, Starlette's routing,
FastAPI's dependency solving and a hop to the thread pool before ``compute`` runs, and the
answer back through the same wrappers; for a 100-vertex curve that is several times the
computation itself (docs/performance.md). ``FastLane``, an ASGI middleware right inside
``BoundedIO`` (which has handed out the request's admission ticket), answers the common case
directly:

- a GET (not HEAD) of a discretization's path, no ``Origin`` (CORS), no ``If-None-Match``
  (conditional requests), no ``root_path``, no parameter given twice, ``digits`` within
  ``DCOSH_MAX_DIGITS``, and an ``Accept`` that is absent or chooses the default format
  (``app.negotiation``; a ``format`` in the query wins as there);
- the raw request seen before: answered from the response cache (as ``FastPath``);
- otherwise the query is parsed once with the endpoint's request model, as FastAPI reads it
  (one value per parameter; a sequence field gets its value as a one-item list), and a float64
  request whose estimated cost (``app.limits.curve_cost``) is at most ``DCOSH_FAST_LANE_SECONDS``
  (and at most ``MAX_STEPS`` construction steps, whatever the estimate says) is computed here,
  on the event loop, by the same ``compute`` and ``curve_response`` as the route, charged to
  admission by the same budget check, kept in the response cache under the same key and
  answered by the same ``reply``.

A GET of ``/theorems/{id}`` whose statement is checked on a discretization's curve (by default,
or on the one ``discretization`` names) takes the same way with the theorem route's own reading
of its parameters (the statement's defaults under the query, the curve's model, the route's
``detail`` and ``digits`` only in their plain spellings, no ``study``) and its document
(``app.routers.theorems.theorem_response``); ``Accept`` plays no part there (one format).

Everything else, and every request whose parsing, computation or admission raises, goes on to
the full chain, which answers it as before (an error is computed again there: errors are
rare, and so their answers stay those of the exception handlers); but a heavier (or mp) curve
GET that the worker would refuse now gets the chain's 503 from here (``FastLane._refusal``),
without the hop to a request thread that queued a burst's refusals. The response's headers are
those the chain adds to a computed 200 (``Vary`` from negotiation and CORS, the security
headers; gzip is negotiated by ``reply`` exactly as the chain's ``Compress`` would leave it):
tests/api/test_fast_lane.py compares status, headers and body with the full chain's. A reply
without gzip refills the headers of the last reply of its kind (``_Template``: only the ETag and
the Content-Length differ), a JSON curve answer is sent straight from its encoded bytes and a
query with nothing to unquote is split without ``parse_qsl`` (``split_query``): each the same
bytes, fewer steps on a path that runs mostly cold. A computed answer is kept (its body
compacted as ``entry_of`` keeps one, the cache's entry and the raw request's alias) and its
curve let go only once the answer is sent (``FastLane._keep``): that work overlaps the
client's reading instead of delaying it.

A request computed here holds the event loop while it runs, so only requests estimated at a
few milliseconds take the lane; the watchdog (which stops computations long past their
deadline) has nothing to watch in them, and a longer one goes to the thread pool as before.
"""

from __future__ import annotations

import functools
import types
from collections.abc import Container, Sequence
from dataclasses import dataclass
from typing import Annotated, Any, Union, get_args, get_origin
from urllib.parse import parse_qsl

from starlette.types import ASGIApp, Receive, Scope, Send

from app.admission import (
    PROBLEM_MEDIA_TYPE,
    Admission,
    OverloadedError,
    current,
    dry_run,
    overloaded_headers,
    problem_bytes,
)
from app.limits import curve_cost
from app.negotiation import choose, endpoint_of, with_accept
from app.registry import DISCRETIZATIONS, STATEMENTS, Discretization, StatementEntry
from app.response_cache import (
    COMPACT_BELOW,
    Entry,
    ResponseCache,
    entry_of,
    etag_for,
    get_reply,
)
from app.responses import canonical_key, curve_document, encode_json
from app.routers.caching import JSONBytesResponse
from app.routers.common import admit_curve, compute, curve_response
from app.routers.theorems import theorem_response
from app.security import with_defaults
from app.services import theorems
from app.settings import Settings

#: Most construction steps (or vertices) of a request computed on the event loop, whatever its
#: estimate: a wrong estimate must not hold the loop for long.
MAX_STEPS = 5_000

#: Request headers that send a request to the full chain.
_UNUSUAL = frozenset({b"origin", b"if-none-match"})


def is_sequence(annotation: Any) -> bool:
    """Whether FastAPI reads a query field of this annotation as a list (every value of the
    parameter): a list, tuple or set, also inside ``Optional`` or ``Annotated``."""
    origin = get_origin(annotation)
    if origin in (Union, types.UnionType):
        return any(is_sequence(a) for a in get_args(annotation) if a is not type(None))
    if origin is Annotated:
        return is_sequence(get_args(annotation)[0])
    kind = origin or annotation
    if not isinstance(kind, type) or issubclass(kind, str | bytes):
        return False
    return issubclass(kind, list | tuple | set | frozenset | Sequence)


class _Route:
    """One GET path as the lane serves it: a discretization's curve, or a statement's check
    (``statement``; computed on a discretization's curve, its default one or the one asked)."""

    __slots__ = ("entry", "sequences", "statement")

    def __init__(self, entry: Discretization, statement: StatementEntry | None = None) -> None:
        self.entry = entry
        self.statement = statement
        self.sequences = frozenset(
            name
            for name, field in entry.query.model_fields.items()
            if is_sequence(field.annotation)
        )


def _theorem_routes() -> dict[str, _Route]:
    """The statements whose default source is a discretization's curve."""
    routes = {}
    for identifier, statement in STATEMENTS.items():
        kind, owner = theorems.default_source(identifier, statement)
        if kind == "discretization":
            routes[f"/theorems/{identifier}"] = _Route(DISCRETIZATIONS[owner], statement)
    return routes


#: The values the theorem route's own ``detail`` parameter takes here (FastAPI reads more
#: spellings of a bool: those go to the chain).
_DETAIL = frozenset({"true", "false"})


def _plain_digits(value: str) -> bool:
    """Whether ``digits`` is a plain decimal integer within the theorem route's own bounds."""
    return value.isascii() and value.isdigit() and 1 <= int(value) <= 100_000


@functools.lru_cache(maxsize=16)
def _vary(value: bytes, negotiable: bool) -> bytes:
    """The Vary of a reply as the chain sends it: negotiation's (on a path with formats), then
    CORS's for a request without Origin (the cache's replies have one or two values)."""
    present = value.decode("latin-1")
    return ((with_accept(present) if negotiable else present) + ", Origin").encode("latin-1")


def _json_entry() -> Entry:
    """The kept form of a JSON answer with an empty body: its status, headers and media type
    are those of every JSON curve answer (what ``entry_of(curve_response(curve, "json"))``
    keeps)."""
    entry = entry_of(JSONBytesResponse(b""))
    if entry is None:  # a 200 with a bytes body always has one
        raise RuntimeError("no entry for an empty JSON answer")
    return entry


_JSON_ENTRY = _json_entry()


class _Computed:
    """An answer the lane found kept (``curve`` None) or computed now; a computed one is kept
    once it is sent (``FastLane._keep``), its body compacted then if ``compact``."""

    __slots__ = ("compact", "curve", "entry", "key")

    def __init__(self, key: str, entry: Entry, curve: Any, compact: bool = False) -> None:
        self.key, self.entry, self.curve, self.compact = key, entry, curve, compact


#: Most reply templates a lane keeps (one per kind of answer: status, kept headers and whether
#: the path negotiates formats; a few in practice).
_TEMPLATES = 64


class _Template:
    """The raw headers of a reply without gzip, all fixed by the entry's status and headers
    (and the path) but the ETag (from the canonical key) and the Content-Length (the body's)."""

    __slots__ = ("etag", "headers", "length")

    def __init__(self, headers: list[tuple[bytes, bytes]], etag: int, length: int) -> None:
        self.headers, self.etag, self.length = headers, etag, length

    @classmethod
    def of(cls, headers: list[tuple[bytes, bytes]]) -> _Template | None:
        """The template of a reply's headers, None unless it has one ETag and one length."""
        names = [name for name, _ in headers]
        if names.count(b"etag") != 1 or names.count(b"content-length") != 1:
            return None
        return cls(list(headers), names.index(b"etag"), names.index(b"content-length"))

    def fill(self, key: str, body: bytes) -> list[tuple[bytes, bytes]]:
        """The headers of the reply to ``key`` with ``body`` (as ``get_reply`` builds them)."""
        headers = self.headers.copy()
        headers[self.etag] = (b"etag", etag_for(key).encode("latin-1"))
        headers[self.length] = (b"content-length", str(len(body)).encode("latin-1"))
        return headers


def split_query(query: str) -> list[tuple[str, str]]:
    """``parse_qsl(query, keep_blank_values=True)`` for a query without ``%`` or ``+`` (nothing
    to unquote): the ``&``-separated pairs, empty ones skipped, split at the first ``=``."""
    if "%" in query or "+" in query:
        return parse_qsl(query, keep_blank_values=True)
    pairs = []
    for part in query.split("&"):
        if part:
            name, _, value = part.partition("=")
            pairs.append((name, value))
    return pairs


@dataclass(frozen=True)
class Refusal:
    """A 503 with Retry-After answered by the lane (``FastLane._refusal``)."""

    headers: list[tuple[bytes, bytes]]
    body: bytes


class FastLane:
    """ASGI middleware: small computed curve GETs (see the module doc)."""

    def __init__(
        self,
        app: ASGIApp,
        cache: ResponseCache,
        settings: Settings,
        admission: Admission,
        flights: Container[tuple[str, bytes]] = (),
    ) -> None:
        self.app = app
        self.cache = cache
        self.settings = settings
        self.admission = admission
        self.flights = flights
        """The raw GETs ``FastPath`` is computing now (identical ones wait for them there)."""
        self.routes = {
            f"/discretizations/{identifier}": _Route(entry)
            for identifier, entry in DISCRETIZATIONS.items()
        }
        self.routes.update(_theorem_routes())
        self.served = 0
        """Requests answered here (computed or from the cache)."""
        self.templates: dict[tuple[int, tuple[tuple[str, str], ...], bool], _Template] = {}
        """Reply headers without gzip by kind of answer (``_Template``)."""

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        answer = None
        if scope["type"] == "http" and scope["method"] == "GET":
            route = self.routes.get(scope["path"])
            if route is not None and not scope.get("root_path"):
                answer = self._answer(scope, route)
        if answer is None:
            await self.app(scope, receive, send)
            return
        self.served += 1
        status, headers, body, later = answer
        try:
            await send({"type": "http.response.start", "status": status, "headers": headers})
            await send({"type": "http.response.body", "body": body})
        finally:
            if later is not None:  # the client has its answer: keep it now
                self._keep(scope, later)

    def _answer(
        self, scope: Scope, route: _Route
    ) -> tuple[int, list[tuple[bytes, bytes]], bytes, _Computed | None] | None:
        """Status, raw headers, body and what to keep once they are sent (a computed answer),
        or None for the full chain."""
        accept = accept_encoding = None
        for name, value in scope["headers"]:
            name = name.lower()
            if name in _UNUSUAL:
                return None
            if name == b"accept" and route.statement is None:  # a statement has one format
                if accept is not None:
                    return None  # given twice: the chain's middlewares disagree on which
                accept = value
            elif name == b"accept-encoding":
                if accept_encoding is not None:
                    return None
                accept_encoding = value
        query_string: bytes = scope["query_string"]
        raw = (scope["path"], query_string)
        # a raw request answered before passed every check below (only Accept may send the
        # same raw request elsewhere)
        found = self.cache.lookup(raw) if accept is None else None
        later = None
        if found is None:
            pairs = split_query(query_string.decode("latin-1"))
            values: dict[str, Any] = dict(pairs)
            if len(values) != len(pairs):
                return None  # a repeated parameter: the chain's 422
            if accept is not None and "format" not in values:
                endpoint = endpoint_of(scope)
                if endpoint is None:
                    return None
                chosen = choose(accept.decode("latin-1"), endpoint.formats)
                if chosen != next(iter(endpoint.formats)):
                    return None  # another format, or a 406
            if not self._digits_allowed(values):
                return None
            if accept is not None:
                found = self.cache.lookup(raw)
        if found is None:
            if self.cache.max_bytes and raw in self.flights:
                return None  # an identical request is computing: the chain waits for it
            computed = self._compute(scope, route, values)
            if computed is None:
                return None
            if isinstance(computed, Refusal):
                return 503, computed.headers, computed.body, None
            if computed.curve is not None:
                later = computed
            found = computed.key, computed.entry
        key, entry = found
        negotiable = route.statement is None
        if accept_encoding is None:  # no gzip: the headers of the last such reply, refilled
            template = self.templates.get((entry.status, entry.headers, negotiable))
            if template is not None:
                return entry.status, template.fill(key, entry.body), entry.body, later
        answer = get_reply(self.cache, key, entry, self.settings, accept_encoding)
        headers = answer.raw_headers()
        for index, (name, value) in enumerate(headers):
            if name == b"vary":
                headers[index] = (name, _vary(value, negotiable))
        headers = with_defaults(headers)
        if accept_encoding is None and len(self.templates) < _TEMPLATES:
            made = _Template.of(headers)
            if made is not None:
                self.templates[(entry.status, entry.headers, negotiable)] = made
        return answer.status, headers, answer.body, later

    def _digits_allowed(self, values: dict[str, Any]) -> bool:
        """Whether ``digits`` (if given) passes the app-wide limit without a doubt."""
        digits = values.get("digits")
        if digits is None:
            return True
        try:
            return float(digits) <= self.settings.max_digits
        except ValueError:
            return False

    def _refusal(self, scope: Scope, entry: Discretization, query: Any) -> Refusal | None:
        """The chain's 503 for a request it would refuse now, answered here (None: the chain
        computes it, charged there).

        A burst of heavy requests against a worker that has admitted its share: each refusal
        took the chain's way, a hop to a request thread and back, where the thread hops of the
        burst's other requests and the GIL queue behind them, and the last refusals of a burst
        came after 100 ms (docs/reliability.md). The same limits and charge as the route
        (``admit_curve``), as a dry run (``admission.dry_run``): an error of the limits goes on
        to the chain, which answers it, as does a request the worker admits (charged there)
        and one whose answer the cache holds."""
        if canonical_key(scope["path"], query.model_dump()) in self.cache:
            return None
        try:
            with dry_run():
                admit_curve(entry, query, self.settings)
        except OverloadedError as exc:
            detail = f"Not admitted now: {exc.reason}; retry later."
            body = problem_bytes(503, "overloaded", "Overloaded", detail)
            headers = [
                (b"content-length", str(len(body)).encode()),
                (b"content-type", PROBLEM_MEDIA_TYPE.encode()),
                *overloaded_headers(exc.retry_after),
                (b"vary", b"Accept, Origin"),
            ]
            return Refusal(with_defaults(headers), body)
        return None

    def _compute(
        self, scope: Scope, route: _Route, values: dict[str, Any]
    ) -> _Computed | Refusal | None:
        """Parse, price and compute a small request (or find its kept answer), or refuse it
        as the chain would (``_refusal``); None for the chain. A computed answer is kept by
        ``_keep`` once it is sent."""
        entry = route.entry
        statement = route.statement
        fixed: dict[str, Any] = {}
        if statement is None:
            for name in route.sequences.intersection(values):
                values[name] = [values[name]]
        else:
            # the theorem route's own parameters, read as it reads them (the rest goes to the
            # discretization's model with the statement's defaults under it)
            if "study" in values or values.get("detail", "false") not in _DETAIL:
                return None
            if "digits" in values and not _plain_digits(values["digits"]):
                return None
            asked = values.pop("discretization", None)
            identifier = statement.statement.id
            try:
                kind, owner = theorems.resolve_source(identifier, statement, asked, None)
            except Exception:  # the chain's 404 or 422
                return None
            if kind != "discretization":
                return None
            entry = DISCRETIZATIONS[owner]
            values = {**dict(statement.statement.defaults), **values}
            fixed = {"discretization": owner}
        admission = self.admission
        settings = self.settings
        ticket = current()
        if ticket is None or admission.draining:
            return None
        if admission.in_flight >= settings.compute_threads + settings.admission_queue:
            return None  # the gate's 503
        try:
            query = entry.query.model_validate(values)
            if query.precision != "float64":
                return self._refusal(scope, entry, query) if statement is None else None
            arguments = query.core_arguments()
            i_min, i_max = arguments["i_min"], arguments["i_max"]
            vertices = max(0, i_max - i_min + 1)
            steps = vertices
            if arguments.get("method", "construction") == "construction":
                steps = max(abs(i_min), abs(i_max), vertices) + 1
            seconds, _ = curve_cost(vertices, steps, "float64", query.digits, entry.info.id)
            if seconds > settings.fast_lane_seconds or steps > MAX_STEPS:
                return self._refusal(scope, entry, query) if statement is None else None
            key = canonical_key(scope["path"], {**fixed, **query.model_dump()})
            kept = self.cache.get(key)
            if kept is not None:
                self.cache.alias((scope["path"], scope["query_string"]), key)
                return _Computed(key, kept, None)
            compact = False
            curve = compute(entry, query, settings, arguments)
            made: Entry | None
            if statement is None and query.format == "json":
                # the encoder's bytes go out as they are; ``_keep`` compacts what it keeps
                body = encode_json(curve_document(curve))
                made = Entry(_JSON_ENTRY.status, _JSON_ENTRY.headers, body, _JSON_ENTRY.media_type)
                compact = True
            elif statement is None:
                made = entry_of(curve_response(curve, query.format))
            else:
                owner = fixed["discretization"]
                made = entry_of(theorem_response(statement, owner, curve, query.checks))
            if made is None:
                return None
        except Exception:  # the chain answers every error as it always has
            admission.release(ticket)
            return None
        return _Computed(key, made, curve, compact)

    def _keep(self, scope: Scope, computed: _Computed) -> None:
        """Keep a computed answer (sent already) as the chain keeps it, and remember its raw
        request for the cache's fast path. The answer and its curve are let go here too, after
        the send: their bookkeeping, copy and deallocation are off the client's wait."""
        entry = computed.entry
        if computed.compact and len(entry.body) < COMPACT_BELOW:
            # as ``entry_of`` keeps a body: a short one copied out of the encoder's buffer
            entry.body = bytes(memoryview(entry.body))
        key = computed.key
        self.cache.put(key, entry)
        if key in self.cache:
            self.cache.alias((scope["path"], scope["query_string"]), key)
        computed.curve = None
