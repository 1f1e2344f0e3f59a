"""GET /figures (catalog) and GET /figures/{id}.svg (one of the paper's figures, redrawn)."""

from typing import Annotated, Any

from fastapi import APIRouter, Depends, Query, Request, Response

from app import compute_pool
from app.errors import UnknownIdError
from app.limits import charge_figure, enforce_drawing
from app.rendering.curves import SVG_MEDIA_TYPE
from app.responses import canonical_key
from app.routers.caching import cached
from app.routers.common import SVG_HEADERS, in_child, reject_repeated_parameters, settings_of
from app.routers.discretizations import parameter_infos
from app.schemas.catalog import FigureEntry
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES
from app.schemas.figures import FigureQuery
from app.services.figures import FIGURES, Figure, render

router = APIRouter(prefix="/figures", tags=["figures"])

FIGURE_RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {"image/svg+xml": {"schema": {"type": "string"}}},
        "description": "A self-contained SVG (viewBox, no external resources) with axes, tick "
        "labels and a legend. Carries an ETag and Cache-Control; If-None-Match gets 304.",
    },
    304: {"description": "Not modified (the If-None-Match ETag matches)."},
    **PROBLEM_RESPONSES,
}


@router.get(
    "",
    summary="List the figures",
    description="The paper's figures this service redraws from computed data, with their "
    "adjustable parameters (domains, defaults).",
    response_model=list[FigureEntry],
)
def list_figures() -> list[FigureEntry]:
    return [
        FigureEntry(
            id=figure.id,
            title=figure.title,
            reference=figure.reference,
            description=figure.description,
            url=f"/figures/{figure.id}.svg",
            parameters=parameter_infos(figure.query),
            discretizations=list(figure.discretizations),
        )
        for figure in FIGURES.values()
    ]


def _register(figure: Figure) -> None:
    """Add GET /figures/{id}.svg for one figure."""
    model = figure.query

    def get_figure(request: Request, query: Annotated[model, Query()]) -> Response:  # type: ignore[valid-type]
        parsed: FigureQuery = query
        settings = settings_of(request)
        enforce_drawing(settings, *parsed.vertex_range())

        def build() -> Response:
            charge_figure(settings, *parsed.vertex_range())  # a cached answer is not charged
            pool = compute_pool.offload()
            if pool is not None:
                values = dict(parsed)
                return in_child(pool, figure_answer, figure.id, values, parsed.model_fields_set)
            return figure_answer(figure.id, dict(parsed), parsed.model_fields_set)

        return cached(
            request, canonical_key(request.url.path, parsed.model_dump()), settings, build
        )

    router.add_api_route(
        f"/{figure.id}.svg",
        get_figure,
        methods=["GET"],
        summary=figure.title,
        description=f"{figure.description}\n\nPaper: {figure.reference}.",
        operation_id=f"get_{figure.id.replace('-', '_')}_svg",
        response_class=Response,
        responses=FIGURE_RESPONSES,
        dependencies=[Depends(reject_repeated_parameters)],
    )


def figure_answer(identifier: str, values: dict[str, Any], fields_set: set[str]) -> Response:
    """The figure drawn for validated query values: in the worker, or what a compute process
    runs (app/compute_pool.py) when its estimate is heavy."""
    figure = FIGURES[identifier]
    query = figure.query.model_construct(fields_set, **values)
    return Response(render(figure, query), media_type=SVG_MEDIA_TYPE, headers=SVG_HEADERS)


for _figure in FIGURES.values():
    _register(_figure)


@router.get("/{name}", include_in_schema=False, responses=NOT_FOUND_RESPONSE)
def unknown_figure(name: str) -> Response:
    raise UnknownIdError("figure", name.removesuffix(".svg"), sorted(FIGURES))
