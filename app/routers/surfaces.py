"""GET /surfaces (catalog) and GET/POST /surfaces/{id} (one mesh, in JSON, OBJ, PLY or GLB)."""

from typing import Annotated, Any

from fastapi import APIRouter, Body, Depends, Path, Request, Response

from app.registry import DISCRETIZATIONS
from app.responses import canonical_key
from app.routers.caching import cached
from app.routers.common import (
    discretization,
    parse_query,
    reject_repeated_parameters,
    settings_of,
)
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES, CurveQuery
from app.schemas.surfaces import (
    SURFACES_DESCRIPTION,
    SurfaceEntry,
    SurfaceQuery,
    SurfaceResponse,
)
from app.services import surfaces as surface_service

router = APIRouter(prefix="/surfaces", tags=["surfaces"])

SURFACE_FIELDS = frozenset(SurfaceQuery.model_fields)


def documented_parameters() -> list[dict[str, Any]]:
    """Query parameters for OpenAPI: the surface's own, then every discretization's.

    The endpoint validates the discretization's parameters against the chosen discretization's
    model; OpenAPI lists the union so that clients (the explorer) see the names.
    """
    parameters: list[dict[str, Any]] = []
    seen: set[str] = set()
    models: list[tuple[str, Any]] = [("surface", SurfaceQuery)]
    models += [(identifier, entry.query) for identifier, entry in DISCRETIZATIONS.items()]
    for owner, model in models:
        for name, schema in model.model_json_schema()["properties"].items():
            if name in seen or (owner != "surface" and name in {"format", "detail"}):
                continue
            seen.add(name)
            schema = dict(schema)
            description = schema.pop("description", "")
            schema.pop("title", None)
            schema.pop("x-domain", None)
            if owner != "surface":
                description = f"Parameter of the discretization ({owner}: {description})"
            parameters.append(
                {
                    "name": name,
                    "in": "query",
                    "required": False,
                    "description": description,
                    "schema": schema,
                }
            )
    return parameters


RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {
            "model/obj": {"schema": {"type": "string"}},
            "application/octet-stream": {"schema": {"type": "string", "format": "binary"}},
            "model/gltf-binary": {"schema": {"type": "string", "format": "binary"}},
        },
        "description": "The mesh as JSON (default), OBJ, PLY or GLB (`format`); files carry a "
        "Content-Disposition file name. GET responses carry an ETag and Cache-Control.",
    },
    304: {"description": "Not modified (the If-None-Match ETag matches)."},
    **PROBLEM_RESPONSES,
    **NOT_FOUND_RESPONSE,
}


@router.get(
    "",
    summary="List the surfaces",
    description="The rotational meshes the service builds: discrete catenoids, the discrete "
    "pseudosphere and their Gauss images.",
    response_model=list[SurfaceEntry],
)
def list_surfaces() -> list[SurfaceEntry]:
    return [
        SurfaceEntry(id=k.id, title=k.title, reference=k.reference, url=f"/surfaces/{k.id}")
        for k in surface_service.KINDS.values()
    ]


def _split(values: dict[str, Any]) -> tuple[SurfaceQuery, dict[str, Any]]:
    """The surface's own parameters, and the rest (the discretization's)."""
    own = {k: v for k, v in values.items() if k in SURFACE_FIELDS}
    rest = {k: v for k, v in values.items() if k not in SURFACE_FIELDS}
    return parse_query(SurfaceQuery, own), rest


def parse(
    identifier: str, values: dict[str, Any]
) -> tuple[surface_service.SurfaceKind, SurfaceQuery, CurveQuery]:
    """The surface kind, the surface's own parameters and its discretization's, validated."""
    kind = surface_service.kind_of(identifier)
    surface, rest = _split(values)
    entry = discretization(surface.discretization)
    return kind, surface, parse_query(entry.query, rest)


def _build(identifier: str, values: dict[str, Any], request: Request) -> tuple[Any, Any]:
    kind, surface, curve_query = parse(identifier, values)
    return kind, (surface, curve_query)


def _file(result: surface_service.SurfaceResult, file_format: str) -> Response:
    body, media_type, headers = surface_service.encoded(result, file_format)
    return Response(body, media_type=media_type, headers=headers)


@router.get(
    "/{surface_id}",
    summary="One discrete surface of revolution",
    description=SURFACES_DESCRIPTION,
    response_model=SurfaceResponse,
    responses=RESPONSES,
    dependencies=[Depends(reject_repeated_parameters)],
    openapi_extra={"parameters": documented_parameters()},
)
def get_surface(
    request: Request,
    surface_id: Annotated[
        str,
        Path(
            description="`catenoid`, `pseudosphere`, or either's `-gauss-image`.",
            json_schema_extra={"enum": list(surface_service.KINDS)},
        ),
    ],
) -> Response:
    kind, (surface, curve_query) = _build(surface_id, dict(request.query_params), request)
    settings = settings_of(request)
    key = canonical_key(
        request.url.path, {"surface": surface.model_dump(), "curve": curve_query.model_dump()}
    )
    return cached(
        request,
        key,
        settings,
        lambda: _file(
            surface_service.compute(kind, surface, curve_query, settings), surface.format
        ),
    )


@router.post(
    "/{surface_id}",
    summary="One discrete surface of revolution (JSON body)",
    description="As GET, with the parameters in a JSON object (needed for long inputs such as "
    "a custom (D2b) sequence `s`).",
    response_model=SurfaceResponse,
    responses=RESPONSES,
)
def post_surface(
    request: Request,
    surface_id: Annotated[str, Path(description="Surface id.")],
    body: Annotated[dict[str, Any], Body(description="Surface and discretization parameters.")],
) -> Response:
    kind, (surface, curve_query) = _build(surface_id, body, request)
    settings = settings_of(request)
    key = canonical_key(
        request.url.path, {"surface": surface.model_dump(), "curve": curve_query.model_dump()}
    )
    return cached(
        request,
        key,
        settings,
        lambda: _file(
            surface_service.compute(kind, surface, curve_query, settings), surface.format
        ),
    )
