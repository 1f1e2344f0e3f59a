"""GET /convergence (catalog) and GET /convergence/{id} (one refinement study of Section 6)."""

from typing import Annotated, Any

from fastapi import APIRouter, Depends, Query, Request, Response

from app import compute_pool
from app.errors import UnknownIdError
from app.geometry.studies.common import Study
from app.registry import STUDIES, ConvergenceStudy
from app.rendering.convergence import study_svg
from app.rendering.curves import SVG_MEDIA_TYPE
from app.responses import CSV_MEDIA_TYPE, canonical_key, encode_json, study_csv, study_document
from app.routers.caching import JSONBytesResponse, cached
from app.routers.common import (
    SVG_HEADERS,
    in_child,
    prepare_study,
    reject_repeated_parameters,
    settings_of,
)
from app.routers.discretizations import parameter_infos
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES
from app.schemas.convergence import ConvergenceResponse, MeasureInfo, StudyEntry, StudyQuery
from app.settings import Settings

router = APIRouter(prefix="/convergence", tags=["convergence"])

STUDY_RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {
            "text/csv": {
                "schema": {"type": "string"},
                "example": "level,d,measure,error,resolved\n0,0.2,parametric,0.0225,true\n",
            },
            "image/svg+xml": {"schema": {"type": "string"}},
        },
        "description": "The study as JSON (default), CSV (`format=csv`) or a log-log SVG plot "
        "(`format=svg`). GET responses carry an ETag and Cache-Control; a matching "
        "If-None-Match gets 304.",
    },
    304: {"description": "Not modified (the If-None-Match ETag matches)."},
    **PROBLEM_RESPONSES,
}


@router.get(
    "",
    summary="List the refinement studies",
    description="Every convergence statement of Section 6 the service studies under "
    "refinement, with its parameters (domains, defaults), error measures (and the orders the "
    "analysis predicts) and the statements it checks.",
    response_model=list[StudyEntry],
)
def list_studies() -> list[StudyEntry]:
    return [
        StudyEntry(
            id=entry.info.id,
            title=entry.info.title,
            reference=entry.info.reference,
            summary=entry.info.summary,
            url=f"/convergence/{entry.info.id}",
            refinement=entry.info.refinement,
            parameters=parameter_infos(entry.query),
            measures=[
                MeasureInfo(id=m.id, description=m.description, expected_order=m.expected_order)
                for m in entry.info.measures
            ],
            statements=[s.id for s in entry.info.statements],
        )
        for entry in STUDIES.values()
    ]


def study_response(entry: ConvergenceStudy, query: StudyQuery, request: Request) -> Response:
    settings = settings_of(request)
    run = prepare_study(entry, query, settings)

    def build() -> Response:
        pool = compute_pool.offload()  # heavy: computed and rendered in a child process
        if pool is not None:
            values = dict(query)
            fields = query.model_fields_set
            return in_child(pool, render_study, entry.info.id, values, fields, settings)
        return study_answer(run(), query.format)

    return cached(request, canonical_key(request.url.path, query.model_dump()), settings, build)


def study_answer(study: Study, response_format: str) -> Response:
    if response_format == "csv":
        return Response(study_csv(study), media_type=CSV_MEDIA_TYPE)
    if response_format == "svg":
        return Response(study_svg(study), media_type=SVG_MEDIA_TYPE, headers=SVG_HEADERS)
    return JSONBytesResponse(encode_json(study_document(study)))


def render_study(
    identifier: str, values: dict[str, Any], fields_set: set[str], settings: Settings
) -> Response:
    """What a pool child runs for ``study_response`` (its charge is a no-op there)."""
    entry = STUDIES[identifier]
    query = entry.query.model_construct(fields_set, **values)
    return study_answer(prepare_study(entry, query, settings)(), query.format)


def _register(entry: ConvergenceStudy) -> None:
    """Add GET /convergence/{id} for one study."""
    model = entry.query

    def get_study(request: Request, query: Annotated[model, Query()]) -> Response:  # type: ignore[valid-type]
        return study_response(entry, query, request)

    router.add_api_route(
        f"/{entry.info.id}",
        get_study,
        methods=["GET"],
        summary=entry.info.title,
        description=entry.description,
        operation_id=f"get_convergence_{entry.info.id.replace('-', '_')}",
        response_model=ConvergenceResponse,
        responses=STUDY_RESPONSES,
        dependencies=[Depends(reject_repeated_parameters)],
    )


for _entry in STUDIES.values():
    _register(_entry)


@router.get("/{identifier}", include_in_schema=False, responses=NOT_FOUND_RESPONSE)
def unknown_study(identifier: str) -> Response:
    raise UnknownIdError("study", identifier, sorted(STUDIES))
