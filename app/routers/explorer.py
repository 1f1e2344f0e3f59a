"""GET / (the explorer page), /static (its scripts, styles and the built vendor files) and
three.js at a fingerprinted address.

The page uses the public API only. Its Content-Security-Policy allows scripts, styles and
connections from this origin alone, plus the one inline import map (by its hash).

three.js (app/static/vendor/three/, built by scripts/build-assets.mjs) is served at
``/assets/three-<fingerprint>/…``, the fingerprint being a SHA-256 prefix of every file of the
directory (names and bytes): the address changes whenever any file does, so it is cached for a
year as ``immutable``, like the documentation bundles (app.routers.docs). One fingerprint for the
whole directory keeps three's relative imports (``./three.core.js``, ``../utils/…``) inside
it. The page's import map points there; text files are gzipped by app.compression.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from fastapi import FastAPI, Response
from fastapi.staticfiles import StaticFiles
from starlette.types import Scope

from app.routers.docs import ASSETS_PATH, IMMUTABLE
from app.security import page_policy

STATIC = Path(__file__).resolve().parents[1] / "static"
INDEX = STATIC / "explorer" / "index.html"
VENDOR = STATIC / "vendor"
THREE = VENDOR / "three"
#: The unfingerprinted address of three.js in index.html's import map.
THREE_STATIC = "/static/vendor/three/"


def directory_fingerprint(directory: Path) -> str | None:
    """A SHA-256 prefix over every file under ``directory`` (relative name and bytes, in name
    order), or None if there is no such directory (before `make assets`)."""
    if not directory.is_dir():
        return None
    digest = hashlib.sha256()
    for path in sorted(p for p in directory.rglob("*") if p.is_file()):
        digest.update(path.relative_to(directory).as_posix().encode() + b"\0")
        digest.update(hashlib.sha256(path.read_bytes()).digest())
    return digest.hexdigest()[:16]


class ImmutableFiles(StaticFiles):
    """Static files whose address carries their fingerprint: cached for a year."""

    def file_response(self, *args: object, **kwargs: object) -> Response:
        response = super().file_response(*args, **kwargs)  # type: ignore[arg-type]
        response.headers["Cache-Control"] = IMMUTABLE
        return response

    async def get_response(self, path: str, scope: Scope) -> Response:
        response = await super().get_response(path, scope)
        if response.status_code != 200:
            response.headers["Cache-Control"] = "no-cache"
        return response


def three_url(fingerprint: str) -> str:
    return f"{ASSETS_PATH}/three-{fingerprint}/"


def install(app: FastAPI) -> None:
    """Serve the explorer at /, three.js at its fingerprinted address and /static."""
    html = INDEX.read_text(encoding="utf-8")
    fingerprint = directory_fingerprint(THREE)
    if fingerprint is not None:
        html = html.replace(THREE_STATIC, three_url(fingerprint))
        app.mount(
            three_url(fingerprint).rstrip("/"),
            ImmutableFiles(directory=THREE),
            name="three",
        )
    headers = {
        "Content-Security-Policy": page_policy(html, workers=True),
        "Cache-Control": "no-cache",
    }

    @app.api_route("/", methods=["GET", "HEAD"], include_in_schema=False)
    def explorer() -> Response:
        return Response(html, media_type="text/html; charset=utf-8", headers=headers)

    app.mount("/static", StaticFiles(directory=STATIC), name="static")
