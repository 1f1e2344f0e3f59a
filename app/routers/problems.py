"""GET /problems and GET /problems/{slug}: the page behind every problem ``type`` URI.

An error response's ``type`` (e.g. ``/problems/invalid-parameters``) resolves here, as HTML for
a browser and as JSON otherwise (see app.problem_types.PROBLEM_TYPES: one title per type).
"""

from __future__ import annotations

import html
from typing import Annotated

from fastapi import APIRouter, Path, Query, Request, Response
from pydantic import BaseModel, Field

from app.problem_types import PROBLEM_TYPES, PROBLEMS_PATH, ProblemType, UnknownIdError
from app.routers.errata import DOCUMENT_RESPONSES, STYLE, DocumentQuery, negotiated
from app.schemas.common import NOT_FOUND_RESPONSE

router = APIRouter(prefix=PROBLEMS_PATH, tags=["service"])


class ProblemTypeInfo(BaseModel):
    """One problem type: what a problem+json response with this ``type`` means."""

    type: str = Field(description="The `type` member of such responses (this page's path).")
    status: int = Field(description="The HTTP status it comes with.")
    title: str = Field(description="The `title` member of such responses.")
    description: str = Field(description="When it happens and what `errors` holds.")


def info(kind: ProblemType) -> ProblemTypeInfo:
    return ProblemTypeInfo(
        type=kind.uri, status=kind.status, title=kind.title, description=kind.description
    )


def _section(kind: ProblemType) -> str:
    return (
        f'<h2 id="{kind.slug}"><a href="{kind.uri}">{html.escape(kind.title)}</a></h2>'
        f"<p>HTTP {kind.status}. {html.escape(kind.description)}</p>"
    )


def _page(title: str, body: str) -> str:
    return (
        '<!doctype html><html lang="en"><head><meta charset="utf-8">'
        f"<title>{html.escape(title)}</title><style>{STYLE}</style></head><body>"
        f'<nav><a href="{PROBLEMS_PATH}">Problem types</a> · <a href="/docs">API</a></nav>'
        f"<h1>{html.escape(title)}</h1>{body}</body></html>"
    )


@router.get(
    "",
    summary="The problem types",
    description="Every `type` an error response (application/problem+json, RFC 9457) can carry, "
    "with its status and title.",
    response_model=list[ProblemTypeInfo],
    responses=DOCUMENT_RESPONSES,
)
def list_problem_types(request: Request, query: Annotated[DocumentQuery, Query()]) -> Response:
    kinds = list(PROBLEM_TYPES.values())
    page = _page("Problem types", "".join(_section(k) for k in kinds))
    return negotiated(request, query.format, page, [info(k).model_dump() for k in kinds])


@router.get(
    "/{slug}",
    summary="One problem type",
    description="The page an error's `type` URI points to.",
    response_model=ProblemTypeInfo,
    responses={**DOCUMENT_RESPONSES, **NOT_FOUND_RESPONSE},
)
def get_problem_type(
    request: Request,
    slug: Annotated[str, Path(description="Problem type, e.g. `invalid-parameters`.")],
    query: Annotated[DocumentQuery, Query()],
) -> Response:
    kind = PROBLEM_TYPES.get(slug)
    if kind is None:
        raise UnknownIdError("problem type", slug, list(PROBLEM_TYPES))
    page = _page(kind.title, f"<p>HTTP {kind.status}. {html.escape(kind.description)}</p>")
    return negotiated(request, query.format, page, info(kind).model_dump())
