"""A bounded in-process cache of encoded responses, and gzip content negotiation.

Every computational GET (and the POST of the same resource) is a pure function of its validated
parameters, so its encoded body can be kept under the canonical key of ``responses.canonical_key``
(path plus the validated parameters with defaults, keys sorted: two spellings of one query share
one entry, and GET and POST share it too). The cache is

- bounded in bytes (``DCOSH_RESPONSE_CACHE_BYTES``, 0 disables it) with least-recently-used
  eviction; bodies larger than ``DCOSH_RESPONSE_CACHE_ENTRY_BYTES`` are served but not kept;
- per process (each uvicorn worker has its own) and thread-safe (sync endpoints run in a thread
  pool): one lock guards the table, and no computation or compression runs under it.

gzip: a client that accepts it (``Accept-Encoding``) gets text bodies (JSON, CSV, SVG, OBJ)
between ``DCOSH_GZIP_MIN_BYTES`` and ``DCOSH_GZIP_MAX_BYTES`` compressed at
``DCOSH_GZIP_LEVEL``; the compressed variant is kept next to the identity body, so it is
compressed once. Level 1 is the default: it already shrinks JSON curves about 2.5–3.3×, and
higher levels gain under 15 % for 2–5× the time (docs/performance.md). Bigger bodies go out
uncompressed: compressing 45 MB of JSON takes about 0.5 s, far longer than sending it (the
binary ``format=npy`` is the way to fetch big curves). The gzip variant has its own strong ETag
(the identity tag with ``-gzip``), and every response says ``Vary: Accept-Encoding``.

The fast path (``FastPath``, an ASGI middleware inside CORS and the security headers): a GET
whose path and raw query string were answered before from a kept entry is answered again from
that entry at once, without routing, validation or the thread pool. The raw query string
determines the validated query and hence the canonical key, so this is the same answer; the
alias table (raw request → canonical key) is bounded by ``ALIASES`` and only ever points at
keys whose computation succeeded.

Identical requests in flight are computed once: a GET to a computational path whose raw path
and query string are being computed for an earlier request waits for that request to finish
(on the event loop: no thread, no admission charge, no place in the gate's queue), bounded by
its own deadline, and is then answered from the entry the first one kept. When the first one
kept nothing (an error, a refusal, a body over ``DCOSH_RESPONSE_CACHE_ENTRY_BYTES``) or the
deadline passes first, the waiting request goes on as if it had arrived alone.
"""

from __future__ import annotations

import gzip
import hashlib
import threading
import time
from collections import OrderedDict
from dataclasses import dataclass, field

import anyio
from starlette.responses import Response
from starlette.types import ASGIApp, Receive, Scope, Send

from app import __version__
from app.admission import current, is_computing
from app.settings import Settings

#: Media types worth compressing (everything else here is binary float data or a GLB).
COMPRESSIBLE = ("application/json", "text/", "image/svg+xml", "model/obj")

#: Bytes charged per entry beyond its bodies and key: the entry object, its headers and media
#: type, the table's node (measured with tracemalloc: about 700-900 bytes for the service's
#: responses; tests/api/test_response_cache_memory.py checks that the charge covers them).
ENTRY_OVERHEAD = 1024

#: Bytes charged per remembered raw request beyond its path, query string and key (the tuple,
#: the table's node). The fast path's table of raw requests counts in the cache's bound, and
#: takes at most ``ALIAS_SHARE`` of it.
ALIAS_OVERHEAD = 256
ALIAS_SHARE = 1 / 16

#: Bodies shorter than this are copied before they are kept (``entry_of``). Longer ones come
#: from the mmap threshold's separate mappings (MALLOC_MMAP_THRESHOLD_, 128 KiB), where the
#: pages of an encoder's unused capacity are never touched, so never resident.
COMPACT_BELOW = 1 << 20

#: Headers a cached response does not repeat (recomputed for each reply).
_DROPPED = {"content-length", "content-encoding", "etag", "cache-control", "vary"}

#: Most raw requests (path and query string) remembered by the fast path, and the longest raw
#: query string it remembers.
ALIASES = 4096
ALIAS_QUERY_BYTES = 2048


@dataclass(slots=True)
class Entry:
    """One encoded response: status, headers (content type included) and body."""

    status: int
    headers: tuple[tuple[str, str], ...]
    body: bytes
    media_type: str
    gzipped: bytes | None = None
    size: int = field(default=0)

    def compressible(self, minimum: int, maximum: int) -> bool:
        """Whether gzip may be offered for this body."""
        return minimum <= len(self.body) <= maximum and self.media_type.startswith(COMPRESSIBLE)


def entry_of(response: Response) -> Entry | None:
    """The cacheable parts of a finished 200 response (None for other responses)."""
    body = getattr(response, "body", None)
    if response.status_code != 200 or not isinstance(body, bytes):
        return None
    headers = tuple((k, v) for k, v in response.headers.items() if k.lower() not in _DROPPED)
    media_type = response.headers.get("content-type", "")
    if len(body) < COMPACT_BELOW:
        # orjson leaves its whole growth buffer behind the bytes it returns (a 14 kB body can
        # hold 30-120 kB): a kept body is copied into an object of its own size
        body = bytes(memoryview(body))
    return Entry(200, headers, body, media_type)


class ResponseCache:
    """Least-recently-used table of ``Entry`` bounded in bytes; safe to share between threads."""

    def __init__(self, max_bytes: int, max_entry_bytes: int) -> None:
        self.max_bytes = max_bytes
        self.max_entry_bytes = min(max_entry_bytes, max_bytes)
        self._entries: OrderedDict[str, Entry] = OrderedDict()
        self._aliases: OrderedDict[tuple[str, bytes], tuple[str, int]] = OrderedDict()
        self.alias_bytes = 0
        """Bytes charged for the fast path's raw requests (``alias``); ``bytes`` plus this
        stays within ``max_bytes``."""
        self._lock = threading.Lock()
        self.bytes = 0
        self.hits = 0
        """Entries found by ``get`` (after validation) or ``lookup`` (the fast path)."""
        self.fast_hits = 0
        """Of those, found by ``lookup``."""
        self.misses = 0
        self.evictions = 0
        self.coalesced = 0
        """Requests answered with the entry of an identical request they waited for."""

    def __len__(self) -> int:
        return len(self._entries)

    def __contains__(self, key: str) -> bool:
        return key in self._entries

    def get(self, key: str) -> Entry | None:
        """The entry for ``key`` (now the most recently used), or None."""
        with self._lock:
            entry = self._entries.get(key)
            if entry is None:
                self.misses += 1
                return None
            self._entries.move_to_end(key)
            self.hits += 1
            return entry

    def put(self, key: str, entry: Entry) -> None:
        """Keep ``entry`` under ``key`` if it fits, evicting the least recently used."""
        entry.size = len(entry.body) + len(entry.gzipped or b"") + len(key) + ENTRY_OVERHEAD
        if entry.size > self.max_entry_bytes:
            return
        with self._lock:
            previous = self._entries.pop(key, None)
            if previous is not None:
                self.bytes -= previous.size
            self._entries[key] = entry
            self.bytes += entry.size
            self._evict()

    def add_gzip(self, key: str, entry: Entry, compressed: bytes) -> None:
        """Attach the gzip variant to a kept entry (and charge its size)."""
        with self._lock:
            if entry.gzipped is not None:
                return
            entry.gzipped = compressed
            if self._entries.get(key) is entry:
                entry.size += len(compressed)
                self.bytes += len(compressed)
                if entry.size > self.max_entry_bytes:
                    del self._entries[key]
                    self.bytes -= entry.size
                self._evict()

    def alias(self, raw: tuple[str, bytes], key: str) -> None:
        """Remember that the raw GET ``(path, query string)`` has the canonical ``key``."""
        if len(raw[1]) > ALIAS_QUERY_BYTES:
            return
        size = len(raw[0]) + len(raw[1]) + len(key) + ALIAS_OVERHEAD
        with self._lock:
            previous = self._aliases.pop(raw, None)
            if previous is not None:
                self.alias_bytes -= previous[1]
            self._aliases[raw] = (key, size)
            self.alias_bytes += size
            share = self.max_bytes * ALIAS_SHARE
            while self._aliases and (len(self._aliases) > ALIASES or self.alias_bytes > share):
                _, (_, old) = self._aliases.popitem(last=False)
                self.alias_bytes -= old
            self._evict()

    def lookup(self, raw: tuple[str, bytes]) -> tuple[str, Entry] | None:
        """The canonical key and kept entry of a raw GET seen before, or None."""
        with self._lock:
            alias = self._aliases.get(raw)
            entry = None if alias is None else self._entries.get(alias[0])
            if alias is None or entry is None:
                return None
            key = alias[0]
            self._entries.move_to_end(key)
            self.hits += 1
            self.fast_hits += 1
            return key, entry

    def clear(self) -> None:
        with self._lock:
            self._entries.clear()
            self._aliases.clear()
            self.bytes = 0
            self.alias_bytes = 0

    def _evict(self) -> None:
        while self.bytes + self.alias_bytes > self.max_bytes and self._entries:
            _, old = self._entries.popitem(last=False)
            self.bytes -= old.size
            self.evictions += 1


def accepts_gzip(header: str | None) -> bool:
    """Whether an Accept-Encoding header allows gzip (``gzip`` or ``*`` with q > 0)."""
    if not header:
        return False
    allowed: dict[str, bool] = {}
    for item in header.split(","):
        token, _, params = item.strip().partition(";")
        quality = 1.0
        for param in params.split(";"):
            name, _, value = param.strip().partition("=")
            if name.strip().lower() == "q":
                try:
                    quality = float(value)
                except ValueError:
                    quality = 0.0
        allowed[token.strip().lower()] = quality > 0
    if "gzip" in allowed:
        return allowed["gzip"]
    return allowed.get("*", False)


def compress(body: bytes, level: int) -> bytes:
    """gzip bytes of ``body`` (mtime 0: the same body always gives the same bytes)."""
    return gzip.compress(body, compresslevel=level, mtime=0)


def etag_for(key: str) -> str:
    """A strong ETag for a canonical request key (version-scoped)."""
    digest = hashlib.sha256(f"{__version__}\n{key}".encode()).hexdigest()[:32]
    return f'"{digest}"'


def gzip_etag(etag: str) -> str:
    """The strong ETag of the gzip variant of the representation tagged ``etag``."""
    return etag[:-1] + '-gzip"'


def matches(header: str | None, etag: str) -> bool:
    """Whether an If-None-Match header matches ``etag`` (weak comparison, or ``*``)."""
    if not header:
        return False
    if header.strip() == "*":
        return True
    tags = [tag.strip().removeprefix("W/") for tag in header.split(",")]
    return etag in tags


@dataclass(frozen=True)
class Reply:
    """What to send: status, headers (without Content-Length) and body."""

    status: int
    headers: dict[str, str]
    body: bytes

    def response(self) -> Response:
        return Response(self.body, status_code=self.status, headers=self.headers)

    def raw_headers(self) -> list[tuple[bytes, bytes]]:
        """The raw ASGI headers of ``response()`` (the same pairs in the same order: lower-case
        names, then Content-Length), without building the Response."""
        headers = [
            (name.lower().encode("latin-1"), value.encode("latin-1"))
            for name, value in self.headers.items()
        ]
        if (
            self.status >= 200
            and self.status not in (204, 304)
            and all(name != b"content-length" for name, _ in headers)
        ):
            headers.append((b"content-length", str(len(self.body)).encode("latin-1")))
        return headers


def caching_headers(settings: Settings) -> dict[str, str]:
    return {"Cache-Control": f"public, max-age={settings.cache_max_age}", "Vary": "Accept-Encoding"}


def not_modified(etag: str, if_none_match: str | None, settings: Settings) -> Reply | None:
    """304 when If-None-Match names the identity or the gzip tag of this representation."""
    for tag in (etag, gzip_etag(etag)):
        if matches(if_none_match, tag):
            return Reply(304, {"ETag": tag, **caching_headers(settings)}, b"")
    return None


def reply(
    cache: ResponseCache,
    key: str,
    entry: Entry,
    settings: Settings,
    is_get: bool,
    accept_encoding: str | None,
) -> Reply:
    """The answer from a kept (or just built) entry: gzip if accepted, ETag on GET."""
    body, headers = entry.body, dict(entry.headers)
    etag = etag_for(key)
    level = settings.gzip_level
    if (
        level
        and accepts_gzip(accept_encoding)
        and entry.compressible(settings.gzip_min_bytes, settings.gzip_max_bytes)
    ):
        body = entry.gzipped if entry.gzipped is not None else compress(entry.body, level)
        cache.add_gzip(key, entry, body)
        headers["Content-Encoding"] = "gzip"
        etag = gzip_etag(etag)
    if is_get:
        headers.update({"ETag": etag, **caching_headers(settings)})
    else:
        headers["Vary"] = "Accept-Encoding"
    return Reply(entry.status, headers, body)


def get_reply(
    cache: ResponseCache,
    key: str,
    entry: Entry,
    settings: Settings,
    accept_encoding: bytes | None,
) -> Reply:
    """``reply`` to a GET from a kept entry, given the request's raw Accept-Encoding header
    (``FastPath`` and ``app.fast_lane.FastLane``)."""
    encodings = None if accept_encoding is None else accept_encoding.decode("latin-1")
    return reply(cache, key, entry, settings, True, encodings)


class FastPath:
    """ASGI middleware: repeated GETs answered from the response cache (see the module doc)."""

    def __init__(
        self,
        app: ASGIApp,
        cache: ResponseCache,
        settings: Settings,
        flights: dict[tuple[str, bytes], anyio.Event] | None = None,
    ) -> None:
        self.app = app
        self.cache = cache
        self.settings = settings
        self._flights = {} if flights is None else flights
        """The raw GETs being computed now, each with the event set when it is answered (only
        touched on the event loop; shared with ``app.fast_lane.FastLane``, which leaves a raw
        GET in flight to this middleware)."""

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] != "GET":
            await self.app(scope, receive, send)
            return
        raw = (scope["path"], scope["query_string"])
        found = self.cache.lookup(raw)
        if found is None and self.cache.max_bytes and is_computing(raw[0]):
            flight = self._flights.get(raw)
            if flight is None:
                await self._lead(raw, scope, receive, send)
                return
            found = await self._follow(raw, flight)
        if found is None:
            await self.app(scope, receive, send)
            return
        key, entry = found
        request_headers = {k.lower(): v for k, v in scope["headers"]}
        inm = request_headers.get(b"if-none-match")
        answer = not_modified(
            etag_for(key), None if inm is None else inm.decode("latin-1"), self.settings
        )
        if answer is None:
            answer = get_reply(
                self.cache, key, entry, self.settings, request_headers.get(b"accept-encoding")
            )
        await answer.response()(scope, receive, send)

    async def _lead(
        self, raw: tuple[str, bytes], scope: Scope, receive: Receive, send: Send
    ) -> None:
        """Compute ``raw`` while identical requests arriving meanwhile wait for the result."""
        done = anyio.Event()
        self._flights[raw] = done
        try:
            await self.app(scope, receive, send)
        finally:
            del self._flights[raw]
            done.set()

    async def _follow(
        self, raw: tuple[str, bytes], flight: anyio.Event
    ) -> tuple[str, Entry] | None:
        """Wait for the identical request in flight (until this request's deadline), then its
        kept entry (None when it kept none)."""
        ticket = current()
        timeout = self.settings.time_limit if ticket is None else ticket.deadline - time.monotonic()
        with anyio.move_on_after(max(timeout, 0.0)):
            await flight.wait()
        found = self.cache.lookup(raw)
        if found is not None:
            self.cache.coalesced += 1  # only ever counted on the event loop
        return found
