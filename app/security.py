"""Security headers: a strict default for every response, and page policies with script hashes.

API responses (JSON, CSV, SVG, meshes) get `Content-Security-Policy: default-src 'none';
frame-ancestors 'none'` unless a route set its own, plus `X-Content-Type-Options: nosniff` and
`Referrer-Policy: no-referrer`. HTML pages (the explorer, /docs, /redoc) set their own policy:
same-origin resources only and their inline scripts allowed by hash, never 'unsafe-eval'.
"""

from __future__ import annotations

import base64
import hashlib
import re

from starlette.types import ASGIApp, Message, Receive, Scope, Send

API_POLICY = "default-src 'none'; frame-ancestors 'none'"
_INLINE_SCRIPT = re.compile(r"<script(?![^>]*\bsrc=)[^>]*>(.*?)</script>", re.S)


def inline_script_hashes(html: str) -> str:
    """The CSP source list allowing exactly the page's inline scripts: "'sha256-…' …"."""
    return " ".join(
        "'sha256-" + base64.b64encode(hashlib.sha256(body.encode()).digest()).decode() + "'"
        for body in _INLINE_SCRIPT.findall(html)
    )


def page_policy(html: str, *, inline_styles: bool = False, workers: bool = False) -> str:
    """A same-origin CSP for an HTML page whose inline scripts are allowed by their hashes.

    ``inline_styles`` is for libraries that set style attributes at run time (Swagger UI, ReDoc);
    ``workers`` allows blob: workers (ReDoc's search, three.js loaders).
    """
    directives = [
        "default-src 'self'",
        f"script-src 'self' {inline_script_hashes(html)}".strip(),
        "style-src 'self' 'unsafe-inline'" if inline_styles else "style-src 'self'",
        "img-src 'self' data: blob:",
        "connect-src 'self'",
        "worker-src 'self' blob:" if workers else "worker-src 'self'",
        "object-src 'none'",
        "base-uri 'none'",
        "form-action 'self'",
        "frame-ancestors 'none'",
    ]
    return "; ".join(directives)


_DEFAULTS = (
    (b"content-security-policy", API_POLICY.encode()),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"no-referrer"),
)


def with_defaults(headers: list[tuple[bytes, bytes]]) -> list[tuple[bytes, bytes]]:
    """``headers`` (raw ASGI pairs) plus each default header they do not set, in place."""
    names = {name.lower() for name, _ in headers}
    headers.extend(pair for pair in _DEFAULTS if pair[0] not in names)
    return headers


class SecurityHeaders:
    """ASGI middleware adding the default headers to every HTTP response (cheap: no body copy)."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return

        async def with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                message["headers"] = with_defaults(list(message.get("headers", [])))
            await send(message)

        await self.app(scope, receive, with_headers)
