"""GET / (the explorer page) and /static (its scripts, styles and the built three.js files).

The page uses the public API only. Its Content-Security-Policy allows scripts, styles and
connections from this origin alone, plus the one inline import map (by its hash).
"""

from __future__ import annotations

from pathlib import Path

from fastapi import FastAPI, Response
from fastapi.staticfiles import StaticFiles

from app.security import page_policy

STATIC = Path(__file__).resolve().parents[1] / "static"
INDEX = STATIC / "explorer" / "index.html"
VENDOR = STATIC / "vendor"


def install(app: FastAPI) -> None:
    """Serve the explorer at / and the static files at /static."""
    html = INDEX.read_text(encoding="utf-8")
    headers = {
        "Content-Security-Policy": page_policy(html, workers=True),
        "Cache-Control": "no-cache",
    }

    @app.api_route("/", methods=["GET", "HEAD"], include_in_schema=False)
    def explorer() -> Response:
        return Response(html, media_type="text/html; charset=utf-8", headers=headers)

    app.mount("/static", StaticFiles(directory=STATIC), name="static")
