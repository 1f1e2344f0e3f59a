"""/docs (Swagger UI), /redoc (ReDoc) and /openapi.json, served like a CDN origin.

The libraries come from the npm registry through the asset build (app/static/vendor/), so the
documentation pages work without any CDN and under a same-origin Content-Security-Policy. The
pages load them from fingerprinted addresses, ``/assets/<sha256 prefix>/<file>``: such an address
never changes content, so it is cached for a year (``immutable``), and each file is gzipped once
at start-up (level 9) for clients that accept it. ReDoc's bundle links its side-menu logo to
cdn.redoc.ly; that address is replaced by an empty ``data:`` image (the logo then hides itself),
so the page asks nothing of another host. ``/openapi.json`` carries a strong ETag (304 on
If-None-Match) and is gzipped once.
"""

from __future__ import annotations

import functools
import gzip
import hashlib
import json
from dataclasses import dataclass
from pathlib import Path

from fastapi import FastAPI, Request, Response
from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html

from app.errors import UnknownIdError
from app.response_cache import accepts_gzip, gzip_etag, matches
from app.security import page_policy

STATIC = Path(__file__).resolve().parents[1] / "static"
VENDOR = "vendor"
ASSETS_PATH = "/assets"
IMMUTABLE = "public, max-age=31536000, immutable"
REDOC_LOGO = b"https://cdn.redoc.ly/redoc/logo-mini.svg"
MEDIA_TYPES = {
    ".js": "text/javascript; charset=utf-8",
    ".css": "text/css; charset=utf-8",
    ".png": "image/png",
}
FILES = (
    "swagger-ui/swagger-ui-bundle.js",
    "swagger-ui/swagger-ui.css",
    "swagger-ui/favicon-32x32.png",
    "redoc/bundles/redoc.standalone.js",
)


@dataclass(frozen=True)
class Asset:
    """One vendor file as served: its bytes, gzip variant, media type and fingerprinted URL."""

    body: bytes
    gzipped: bytes | None
    media_type: str
    url: str
    etag: str
    """Strong ETag of the identity body (the gzip variant's ends in ``-gzip``)."""

    def response(self, request: Request, cache_control: str = IMMUTABLE) -> Response:
        """200 (gzip if accepted) or 304 for a matching If-None-Match."""
        zipped = self.gzipped is not None and accepts_gzip(request.headers.get("accept-encoding"))
        etag = gzip_etag(self.etag) if zipped else self.etag
        headers = {"Cache-Control": cache_control, "Vary": "Accept-Encoding", "ETag": etag}
        if_none_match = request.headers.get("if-none-match")
        for tag in (self.etag, gzip_etag(self.etag)):  # either variant: the content is the same
            if matches(if_none_match, tag):
                return Response(status_code=304, headers={**headers, "ETag": tag})
        if zipped:
            headers["Content-Encoding"] = "gzip"
        body = self.gzipped if zipped and self.gzipped is not None else self.body
        return Response(body, media_type=self.media_type, headers=headers)


def load_asset(relative: str) -> Asset | None:
    """The vendor file ``relative`` (under app/static/vendor/), or None before `make assets`."""
    path = STATIC / VENDOR / relative
    if not path.is_file():
        return None
    found = path.stat()
    return _asset(relative, found.st_mtime_ns, found.st_size)


@functools.lru_cache(maxsize=32)
def _asset(relative: str, mtime_ns: int, size: int) -> Asset:
    """``load_asset`` of the file as it is at (``mtime_ns``, ``size``): compressed once per
    process (gzip at level 9 of the vendor scripts costs ≈ 0.2 s, and every app loads them)."""
    path = STATIC / VENDOR / relative
    body = path.read_bytes().replace(REDOC_LOGO, b"data:,")
    fingerprint = hashlib.sha256(body).hexdigest()[:16]
    media_type = MEDIA_TYPES.get(path.suffix, "application/octet-stream")
    textual = media_type.startswith("text/")
    gzipped = gzip.compress(body, compresslevel=9, mtime=0) if textual else None
    url = f"{ASSETS_PATH}/{fingerprint}/{relative}"
    return Asset(body, gzipped, media_type, url, f'"{fingerprint}"')


def install(app: FastAPI) -> None:
    """Add GET /docs, /redoc and /assets/…, and serve /openapi.json with an ETag (the app is
    created with docs_url=redoc_url=None)."""
    assets = {relative: load_asset(relative) for relative in FILES}
    by_url = {asset.url: asset for asset in assets.values() if asset is not None}

    def url(relative: str) -> str:
        asset = assets[relative]
        return asset.url if asset is not None else f"/static/{VENDOR}/{relative}"

    title = f"{app.title} — API documentation"
    openapi_url = app.openapi_url or "/openapi.json"
    swagger = get_swagger_ui_html(
        openapi_url=openapi_url,
        title=title,
        swagger_js_url=url("swagger-ui/swagger-ui-bundle.js"),
        swagger_css_url=url("swagger-ui/swagger-ui.css"),
        swagger_favicon_url=url("swagger-ui/favicon-32x32.png"),
    )
    redoc = get_redoc_html(
        openapi_url=openapi_url,
        title=title,
        redoc_js_url=url("redoc/bundles/redoc.standalone.js"),
        redoc_favicon_url=url("swagger-ui/favicon-32x32.png"),
        with_google_fonts=False,
    )
    swagger_html, redoc_html = bytes(swagger.body).decode(), bytes(redoc.body).decode()
    pages = {
        "/docs": (swagger_html, page_policy(swagger_html, inline_styles=True)),
        "/redoc": (redoc_html, page_policy(redoc_html, inline_styles=True, workers=True)),
    }
    for path, (html, policy) in pages.items():
        headers = {"Content-Security-Policy": policy, "Cache-Control": "no-cache"}

        def page(html: str = html, headers: dict[str, str] = headers) -> Response:
            return Response(html, media_type="text/html; charset=utf-8", headers=headers)

        app.add_api_route(path, page, methods=["GET"], include_in_schema=False)

    def asset(request: Request, fingerprint: str, path: str) -> Response:
        found = by_url.get(f"{ASSETS_PATH}/{fingerprint}/{path}")
        if found is None:
            raise UnknownIdError("asset", f"{fingerprint}/{path}", sorted(by_url))
        return found.response(request)

    app.add_api_route(
        ASSETS_PATH + "/{fingerprint}/{path:path}", asset, methods=["GET"], include_in_schema=False
    )

    # /openapi.json: FastAPI's route replaced by one with an ETag and a gzip variant
    app.router.routes[:] = [r for r in app.router.routes if getattr(r, "path", "") != openapi_url]
    document: dict[str, Asset] = {}

    def openapi(request: Request) -> Response:
        if not document:
            body = json.dumps(app.openapi(), ensure_ascii=False, separators=(",", ":")).encode()
            tag = hashlib.sha256(body).hexdigest()[:16]
            gzipped = gzip.compress(body, compresslevel=9, mtime=0)
            document["json"] = Asset(body, gzipped, "application/json", openapi_url, f'"{tag}"')
        return document["json"].response(request, cache_control="no-cache")

    app.add_api_route(openapi_url, openapi, methods=["GET"], include_in_schema=False)
