"""gzip for the responses the response cache does not see, with the same policy.

Computational answers are compressed by ``app.response_cache`` (once per kept entry). Everything
else that is text and sizeable (the catalogs such as GET /theorems, the explorer's scripts and
styles, three.js) goes through ``Compress``: a 200 with a Content-Length between
``DCOSH_GZIP_MIN_BYTES`` and ``DCOSH_GZIP_MAX_BYTES``, a compressible media type and no
Content-Encoding yet is gzipped at ``DCOSH_GZIP_LEVEL`` for a client that accepts it. Responses
with an ETag (static files) keep their compressed body in a small table, so that a file is
compressed once per process; their gzip variant gets its own ETag (``…-gzip"``).

Files under /static get ``Cache-Control: no-cache`` unless they have one: the browser keeps them
and revalidates with the ETag (they are not fingerprinted; the documentation's bundles are,
under /assets, see app.routers.docs).
"""

from __future__ import annotations

from collections import OrderedDict

from starlette.datastructures import MutableHeaders
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.response_cache import COMPRESSIBLE, accepts_gzip, compress, gzip_etag
from app.settings import Settings

#: Compressed bodies of ETag-carrying responses kept per process: (path, etag) -> gzip bytes.
KEPT = 64


class Compress:
    """ASGI middleware: gzip as the module doc says."""

    def __init__(self, app: ASGIApp, settings: Settings) -> None:
        self.app = app
        self.settings = settings
        self.kept: OrderedDict[tuple[str, str], bytes] = OrderedDict()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        path: str = scope["path"]
        request_headers = {k.lower(): v for k, v in scope["headers"]}
        accepts = self.settings.gzip_level > 0 and accepts_gzip(
            request_headers.get(b"accept-encoding", b"").decode("latin-1")
        )
        static = path.startswith("/static/")
        if not accepts and not static:  # nothing to do on the way out: no wrapper per message
            await self.app(scope, receive, send)
            return
        inm = request_headers.get(b"if-none-match")
        if static and inm and b'-gzip"' in inm:
            # StaticFiles knows the identity tag only: revalidate the gzip variant against it
            headers = [(k, v) for k, v in scope["headers"] if k.lower() != b"if-none-match"]
            headers.append((b"if-none-match", inm.replace(b'-gzip"', b'"')))
            scope = {**scope, "headers": headers}
        start: Message | None = None
        chunks: list[bytes] = []

        async def wrapped(message: Message) -> None:
            nonlocal start
            if message["type"] == "http.response.start":
                headers = MutableHeaders(scope=message)
                if static and "cache-control" not in headers:
                    headers["Cache-Control"] = "no-cache"
                if accepts and self._eligible(message["status"], headers):
                    start = message  # held until the whole body is here
                    return
                await send(message)
                return
            if start is None or message["type"] != "http.response.body":
                await send(message)
                return
            chunks.append(message.get("body", b""))
            if message.get("more_body", False):
                return
            await self._send_compressed(start, b"".join(chunks), path, send)

        await self.app(scope, receive, wrapped)

    def _eligible(self, status: int, headers: MutableHeaders) -> bool:
        length = headers.get("content-length")
        return (
            status == 200
            and "content-encoding" not in headers
            and headers.get("content-type", "").startswith(COMPRESSIBLE)
            and length is not None
            and self.settings.gzip_min_bytes <= int(length) <= self.settings.gzip_max_bytes
        )

    async def _send_compressed(self, start: Message, body: bytes, path: str, send: Send) -> None:
        headers = MutableHeaders(scope=start)
        etag = headers.get("etag")
        key = (path, etag) if etag else None
        compressed = self.kept.get(key) if key else None
        if compressed is None:
            compressed = compress(body, self.settings.gzip_level)
            if key:
                self.kept[key] = compressed
                while len(self.kept) > KEPT:
                    self.kept.popitem(last=False)
        headers["Content-Encoding"] = "gzip"
        headers["Content-Length"] = str(len(compressed))
        vary = headers.get("vary")
        headers["Vary"] = "Accept-Encoding" if not vary else f"{vary}, Accept-Encoding"
        if etag and not etag.startswith("W/"):
            headers["ETag"] = gzip_etag(etag)
        await send(start)
        await send({"type": "http.response.body", "body": compressed, "more_body": False})
