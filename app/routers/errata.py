"""GET /errata and GET /errata/{id}: docs/errata.md served as HTML and as JSON.

Every check that carries an erratum links here (``Erratum.link`` in app/geometry/checks.py is
``/errata/E3``). Both pages negotiate: HTML for a browser (``Accept: text/html``) or
``format=html``, JSON otherwise. The document is read and rendered once per process.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path as FilePath
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Path, Query, Request, Response
from markdown_it import MarkdownIt
from markdown_it.token import Token
from pydantic import BaseModel, Field

from app.errors import UnknownIdError
from app.responses import encode_json
from app.routers.caching import JSONBytesResponse
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES, StrictModel

ROOT = FilePath(__file__).resolve().parents[2]
DOCUMENT = ROOT / "docs" / "errata.md"
ERRATA_PATH = "/errata"

#: HTML pages here carry no script: an inline style sheet and same-origin links only.
PAGE_POLICY = (
    "default-src 'none'; style-src 'unsafe-inline'; img-src 'self' data:; base-uri 'none'; "
    "form-action 'none'; frame-ancestors 'none'"
)
PAGE_HEADERS = {"Content-Security-Policy": PAGE_POLICY, "Cache-Control": "public, max-age=3600"}
STYLE = (
    "body{font:16px/1.5 system-ui,sans-serif;max-width:60rem;margin:2rem auto;padding:0 1rem}"
    "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.2rem .5rem}"
    "code{background:#f4f4f4;padding:0 .2rem}"
)

router = APIRouter(prefix=ERRATA_PATH, tags=["errata"])


class DocumentQuery(StrictModel):
    """How a documentation page is wanted."""

    format: Literal["json", "html"] | None = Field(
        None,
        description="`json` or `html`; without it, HTML when the Accept header prefers "
        "text/html (a browser) and JSON otherwise.",
    )


class ErratumEntry(BaseModel):
    """One entry of docs/errata.md."""

    id: str = Field(description="Stable id, e.g. `E3`.")
    where: str = Field(description="Where the paper prints the formula (Markdown).")
    what: str = Field(description="What is wrong as printed (Markdown).")
    checks: list[str] = Field(description="The checks whose responses carry this erratum.")
    url: str = Field(description="This entry's page on the service.")
    markdown: str = Field(description="The entry's full text: where, printed, corrected, evidence.")


class ErrataResponse(BaseModel):
    """The errata document: its entries, and the whole text as Markdown."""

    title: str = Field(description="The document's title.")
    entries: list[ErratumEntry] = Field(description="Every erratum, in the document's order.")
    markdown: str = Field(description="The whole document (docs/errata.md).")


def github_slug(heading: str) -> str:
    """The anchor GitHub gives a heading (so links written for the repository work here too)."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


@dataclass(frozen=True)
class Errata:
    title: str
    markdown: str
    html: str
    entries: dict[str, ErratumEntry]
    entry_html: dict[str, str]


def _renderer() -> MarkdownIt:
    md = MarkdownIt("commonmark", {"html": False}).enable("table")
    seen: dict[str, int] = {}

    def heading_open(renderer: Any, tokens: list[Token], idx: int, options: Any, env: Any) -> str:
        inline = tokens[idx + 1]
        slug = github_slug(inline.content)
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        anchor = slug if count == 0 else f"{slug}-{count}"
        return f'<{tokens[idx].tag} id="{html.escape(anchor)}">'

    def link_open(renderer: Any, tokens: list[Token], idx: int, options: Any, env: Any) -> str:
        href = str(tokens[idx].attrGet("href") or "")
        if href.startswith("#"):
            href = f"{env.get('base', '')}{href}"
        elif not href.startswith(("/", "http://", "https://")):
            href = f"{ERRATA_PATH}#related-documents"  # a repository file: named, not served
        return f'<a href="{html.escape(href)}">'

    md.add_render_rule("heading_open", heading_open)
    md.add_render_rule("link_open", link_open)
    return md


def _page(title: str, body: str) -> str:
    return (
        '<!doctype html><html lang="en"><head><meta charset="utf-8">'
        f"<title>{html.escape(title)}</title><style>{STYLE}</style></head><body>"
        f'<nav><a href="{ERRATA_PATH}">Errata</a> · <a href="/docs">API</a> · '
        f'<a href="/">Explorer</a></nav>{body}</body></html>'
    )


def _cells(row: str) -> list[str]:
    return [cell.strip() for cell in row.strip().strip("|").split("|")]


@lru_cache(maxsize=1)
def errata() -> Errata:
    """docs/errata.md parsed into entries and rendered (once)."""
    text = DOCUMENT.read_text(encoding="utf-8")
    title = text.splitlines()[0].lstrip("# ").strip()
    sections = {
        m.group(1): m.group(0).rstrip() + "\n"
        for m in re.finditer(r"(?ms)^### (E\d+)\n.*?(?=^#{2,3} |\Z)", text)
    }
    entries: dict[str, ErratumEntry] = {}
    for line in re.findall(r"(?m)^\| \[E\d+\]\(#e\d+\) \|.*$", text):
        link, where, what, checks = [*_cells(line), "", "", ""][:4]
        identifier = link[1 : link.index("]")]
        entries[identifier] = ErratumEntry(
            id=identifier,
            where=where,
            what=what,
            checks=re.findall(r"`([^`]+)`", checks),
            url=f"{ERRATA_PATH}/{identifier}",
            markdown=sections.get(identifier, ""),
        )
    related = (
        "\n## Related documents\n\nThe repository's docs/checks.md explains how each check "
        "measures its residual; GET /theorems lists every statement with its check.\n"
    )
    document_html = _renderer().render(text + related, {"base": ""})
    entry_html = {
        identifier: _page(
            f"{identifier} — {title}",
            f'<p><a href="{ERRATA_PATH}#{identifier.lower()}">{identifier} in the full document'
            "</a></p>" + _renderer().render(entry.markdown, {"base": ERRATA_PATH}),
        )
        for identifier, entry in entries.items()
    }
    return Errata(title, text, _page(title, document_html), entries, entry_html)


def wants_html(request: Request, requested: str | None) -> bool:
    """``format`` if given, else whether Accept ranks text/html above application/json."""
    if requested is not None:
        return requested == "html"
    accept = request.headers.get("accept", "").lower()
    if "text/html" not in accept:
        return False
    return "application/json" not in accept or accept.index("text/html") < accept.index(
        "application/json"
    )


def negotiated(request: Request, requested: str | None, page: str, document: Any) -> Response:
    headers = {**PAGE_HEADERS, "Vary": "Accept"}
    if wants_html(request, requested):
        return Response(page, media_type="text/html; charset=utf-8", headers=headers)
    return JSONBytesResponse(encode_json(document), headers=headers)


DOCUMENT_RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {"text/html": {"schema": {"type": "string"}}},
        "description": "JSON, or an HTML page for `format=html` or a browser's Accept.",
    },
    **PROBLEM_RESPONSES,
}


@router.get(
    "",
    summary="The errata of the paper's transcription",
    description="docs/errata.md: every printed formula found wrong, with the corrected form the "
    "service implements and the evidence. JSON (entries and the Markdown text) or HTML.",
    response_model=ErrataResponse,
    responses=DOCUMENT_RESPONSES,
)
def list_errata(request: Request, query: Annotated[DocumentQuery, Query()]) -> Response:
    document = errata()
    body = {
        "title": document.title,
        "entries": [e.model_dump() for e in document.entries.values()],
        "markdown": document.markdown,
    }
    return negotiated(request, query.format, document.html, body)


@router.get(
    "/{erratum_id}",
    summary="One erratum",
    description="One entry of docs/errata.md (the page every `erratum.link` points to).",
    response_model=ErratumEntry,
    responses={**DOCUMENT_RESPONSES, **NOT_FOUND_RESPONSE},
)
def get_erratum(
    request: Request,
    erratum_id: Annotated[str, Path(description="Erratum id, e.g. `E3` (any case).")],
    query: Annotated[DocumentQuery, Query()],
) -> Response:
    document = errata()
    identifier = erratum_id.upper()
    entry = document.entries.get(identifier)
    if entry is None:
        raise UnknownIdError("erratum", erratum_id, list(document.entries))
    return negotiated(request, query.format, document.entry_html[identifier], entry.model_dump())
