"""GET /surfaces (catalog) and GET/POST /surfaces/{id} (one mesh, in JSON, OBJ, PLY or GLB)."""

from typing import Annotated, Any

from fastapi import APIRouter, Body, Depends, Path, Request, Response
from fastapi.exceptions import RequestValidationError

from app import compute_pool
from app.geometry.surfaces import rotational
from app.registry import DISCRETIZATIONS
from app.responses import canonical_key
from app.routers.caching import cached
from app.routers.common import (
    discretization,
    in_child,
    parse_query,
    reject_repeated_parameters,
    settings_of,
)
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES, CurveQuery, strict_body
from app.schemas.openapi_document import selection_schema
from app.schemas.surfaces import (
    SURFACES_DESCRIPTION,
    SurfaceEntry,
    SurfaceQuery,
    SurfaceResponse,
)
from app.services import surfaces as surface_service
from app.services.selection import chosen
from app.settings import Settings

router = APIRouter(prefix="/surfaces", tags=["surfaces"])

SURFACE_FIELDS = frozenset(SurfaceQuery.model_fields)


DEFAULT_DISCRETIZATION = SurfaceQuery.model_fields["discretization"].default


def surfaces_of(identifier: str) -> list[str]:
    """The surfaces a discretization gives: the catenoids always (their meridian is p), the
    pseudospheres when it has a tractrix and its Gauss image (d4b)."""
    companions = DISCRETIZATIONS[identifier].info.companions
    has_tractrix = {"tractrix", "tractrix_gauss_image"} <= set(companions)
    return [k for k, kind in surface_service.KINDS.items() if kind.meridian == "p" or has_tractrix]


def checks_of(kinds: list[str]) -> list[str]:
    """The statement ids the surfaces ``kinds`` check (a catenoid's, a pseudosphere's)."""
    claims = {
        "constant-curvature" if surface_service.KINDS[k].meridian == "tractrix" else "minimal"
        for k in kinds
    }
    ids: list[str] = []
    for claim in sorted(claims, reverse=True):  # the catenoids' first
        ids += [s.id for s in rotational.STATEMENTS[claim] if s.id not in ids]
    return ids


#: ``x-domain`` of ``checks`` where the path serves both claims (a JSON Schema of a query
#: parameter cannot depend on the path's ``surface_id``).
CHECKS_BY_SURFACE = (
    "ids of surface_id's own statements: vanishing-mean-curvature only on catenoid and "
    "catenoid-gauss-image, theorem-7 only on pseudosphere and pseudosphere-gauss-image"
)


def documented_parameters(identifier: str, in_path: bool) -> list[dict[str, Any]]:
    """Query parameters for OpenAPI: the surface's own, then the discretization's.

    One discretization per path, so that every documented parameter is one the endpoint takes
    (a union over discretizations would declare ``y1`` of D1 where D4b refuses it). On
    ``/surfaces/{surface_id}/{discretization}`` the path names it; on ``/surfaces/{surface_id}``
    the query parameter ``discretization`` is documented with the default alone.
    """
    parameters: list[dict[str, Any]] = []
    seen: set[str] = set()
    models: list[tuple[str, Any]] = [("surface", SurfaceQuery)]
    models.append((identifier, DISCRETIZATIONS[identifier].query))
    for owner, model in models:
        for name, schema in model.model_json_schema(by_alias=True)["properties"].items():
            if name in seen or (owner != "surface" and name in {"format", "detail"}):
                continue
            seen.add(name)
            if name == "discretization" and in_path:
                continue
            schema = dict(schema)
            description = schema.pop("description", "")
            schema.pop("title", None)
            if name == "checks" and owner == "surface":
                kinds = surfaces_of(identifier)
                schema = selection_schema(schema, "checks", checks_of(kinds))
                if len(checks_of(kinds)) > len(checks_of(kinds[:1])):
                    # one path for both claims: which ids apply depends on surface_id
                    schema["x-domain"] = CHECKS_BY_SURFACE
            if owner != "surface" and surface_service.MERIDIAN_PARAMETERS.get(owner) == name:
                schema["x-domain"] = surface_service.DEGENERATE_MERIDIAN[owner]
                description += f" On a surface, {schema['x-domain']}."
            if name == "companions" and owner != "surface":
                # the discretization's own names, as on /discretizations/{id} (a bare string
                # declared `companions=` valid, which the server refuses)
                companions = list(DISCRETIZATIONS[identifier].info.companions)
                schema = selection_schema(schema, "companions", companions)
            if name == "i_max" and owner != "surface":
                # a mesh needs a meridian edge: one more vertex than a polygon
                description += " On a surface, i_max >= i_min + 1 (at least one meridian edge)."
                schema["x-domain"] = "i_min + 1 <= i_max"
            if name == "discretization":
                schema["enum"] = [identifier]
                description = (
                    f"Discretization giving the meridian: `{identifier}` on this path. Every "
                    "discretization has its own path, `/surfaces/{surface_id}/{discretization}`, "
                    "with its parameters (this path still takes the other ids, with their "
                    "parameters, for older links)."
                )
            elif owner != "surface":
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


def documented_body(identifier: str, in_path: bool) -> dict[str, Any]:
    """The POST body for OpenAPI: an object of the same parameters, no other member."""
    properties = {
        p["name"]: {**p["schema"], "description": p["description"]}
        for p in documented_parameters(identifier, in_path)
    }
    schema = {
        "type": "object",
        "title": f"Surface{identifier.replace('-', '').title()}Body",
        "description": "Surface and discretization parameters.",
        "properties": properties,
        "additionalProperties": False,
    }
    return {"requestBody": {"required": True, "content": {"application/json": {"schema": schema}}}}


RESPONSES: dict[int | str, dict[str, Any]] = {
    200: {
        "content": {
            "model/obj": {"schema": {"type": "string"}},
            "application/octet-stream": {"schema": {"type": "string", "format": "binary"}},
            "model/gltf-binary": {"schema": {"type": "string", "format": "binary"}},
            "application/xml": {"schema": {"type": "string"}},
        },
        "description": "The mesh as JSON (default), OBJ, PLY (application/octet-stream), VTU "
        "(application/xml) or GLB (`format`); files carry a "
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


#: The strict JSON-body variant of ``SurfaceQuery`` (POST: `false` is not an integer there).
SURFACE_BODY = strict_body(SurfaceQuery)  # type: ignore[arg-type]


def _split(values: dict[str, Any], strict: bool) -> tuple[SurfaceQuery, dict[str, Any]]:
    """The surface's own parameters, and the rest (the discretization's)."""
    own = {k: v for k, v in values.items() if k in SURFACE_FIELDS}
    rest = {k: v for k, v in values.items() if k not in SURFACE_FIELDS}
    model: type[SurfaceQuery] = SURFACE_BODY if strict else SurfaceQuery  # type: ignore[assignment]
    return parse_query(model, own), rest


def parse(
    identifier: str, values: dict[str, Any], strict: bool = False
) -> tuple[surface_service.SurfaceKind, SurfaceQuery, CurveQuery]:
    """The surface kind, the surface's own parameters and its discretization's, validated (a
    JSON body strictly, as POST /discretizations/{id} validates it)."""
    kind = surface_service.kind_of(identifier)
    surface, rest = _split(values, strict)
    entry = discretization(surface.discretization)
    curve_query = parse_query(entry.body if strict else entry.query, rest)
    # a mesh uses no companion, but the names are the discretization's, as documented: an
    # unknown one is refused here as on /discretizations/{id} (it was ignored)
    chosen("companions", curve_query.companions, entry.info.companions)
    return kind, surface, curve_query


def _build(identifier: str, values: dict[str, Any], request: Request) -> tuple[Any, Any]:
    kind, surface, curve_query = parse(identifier, values, strict=request.method == "POST")
    return kind, (surface, curve_query)


def _file(result: surface_service.SurfaceResult, file_format: str) -> Response:
    body, media_type, headers = surface_service.encoded(result, file_format)
    return Response(body, media_type=media_type, headers=headers)


def surface_answer(
    kind: surface_service.SurfaceKind,
    surface: SurfaceQuery,
    curve_query: CurveQuery,
    settings: Settings,
) -> Response:
    """The surface in its format: checked and charged here, then computed here or, when its
    estimate is heavy, in a child process of the worker's pool (app/compute_pool.py)."""
    plan = surface_service.admit(kind, surface, curve_query, settings)
    pool = compute_pool.offload()
    if pool is not None:
        return in_child(pool, render_surface, *portable(kind, surface, curve_query), settings)
    return _file(surface_service.build(plan, settings), surface.format)


def portable(
    kind: surface_service.SurfaceKind, surface: SurfaceQuery, curve_query: CurveQuery
) -> tuple[str, dict[str, Any], set[str], dict[str, Any], set[str]]:
    """A surface request as values a child process can receive (the models are rebuilt)."""
    return (
        kind.id,
        dict(surface),
        surface.model_fields_set,
        dict(curve_query),
        curve_query.model_fields_set,
    )


def rebuilt(
    identifier: str,
    surface_values: dict[str, Any],
    surface_fields: set[str],
    curve_values: dict[str, Any],
    curve_fields: set[str],
) -> tuple[surface_service.SurfaceKind, SurfaceQuery, CurveQuery]:
    """The request ``_portable`` sent, as the models it was validated into."""
    surface = SurfaceQuery.model_construct(surface_fields, **surface_values)
    entry = discretization(surface.discretization)
    curve_query = entry.query.model_construct(curve_fields, **curve_values)
    return surface_service.kind_of(identifier), surface, curve_query


def render_surface(
    identifier: str,
    surface_values: dict[str, Any],
    surface_fields: set[str],
    curve_values: dict[str, Any],
    curve_fields: set[str],
    settings: Settings,
) -> Response:
    """What a pool child runs for ``surface_answer`` (its charge is a no-op there)."""
    kind, surface, curve_query = rebuilt(
        identifier, surface_values, surface_fields, curve_values, curve_fields
    )
    return _file(surface_service.compute(kind, surface, curve_query, settings), surface.format)


def _get(request: Request, surface_id: str, values: dict[str, Any]) -> Response:
    kind, (surface, curve_query) = _build(surface_id, values, request)
    settings = settings_of(request)
    # one key for every path of the same surface: /surfaces/catenoid?discretization=d1 and
    # /surfaces/catenoid/d1 are one answer with one ETag
    key = canonical_key(
        f"/surfaces/{surface_id}",
        {"surface": surface.model_dump(), "curve": curve_query.model_dump()},
    )
    return cached(
        request, key, settings, lambda: surface_answer(kind, surface, curve_query, settings)
    )


SURFACE_ID_DESCRIPTION = "`catenoid`, `pseudosphere`, or either's `-gauss-image`."


@router.get(
    "/{surface_id}",
    summary="One discrete surface of revolution",
    description=SURFACES_DESCRIPTION,
    response_model=SurfaceResponse,
    responses=RESPONSES,
    dependencies=[Depends(reject_repeated_parameters)],
    openapi_extra={"parameters": documented_parameters(DEFAULT_DISCRETIZATION, in_path=False)},
)
def get_surface(
    request: Request,
    surface_id: Annotated[
        str,
        Path(
            description=SURFACE_ID_DESCRIPTION,
            json_schema_extra={"enum": surfaces_of(DEFAULT_DISCRETIZATION)},
        ),
    ],
) -> Response:
    return _get(request, surface_id, dict(request.query_params))


@router.post(
    "/{surface_id}",
    summary="One discrete surface of revolution (JSON body)",
    description="As GET, with the parameters in a JSON object (needed for long inputs such as "
    "a custom (D2b) sequence `s`).",
    response_model=SurfaceResponse,
    responses=RESPONSES,
    openapi_extra=documented_body(DEFAULT_DISCRETIZATION, in_path=False),
)
def post_surface(
    request: Request,
    surface_id: Annotated[str, Path(description="Surface id.")],
    body: Annotated[dict[str, Any], Body(description="Surface and discretization parameters.")],
) -> Response:
    return _get(request, surface_id, body)


def _with_discretization(identifier: str, values: dict[str, Any]) -> dict[str, Any]:
    """The parameters with the discretization the path names; it is not a parameter here."""
    if "discretization" in values:
        raise RequestValidationError(
            [
                {
                    "type": "extra_forbidden",
                    "loc": ("query", "discretization"),
                    "msg": "the path names the discretization",
                    "input": values["discretization"],
                }
            ]
        )
    return {**values, "discretization": identifier}


def _add_discretization_routes(identifier: str) -> None:
    """GET and POST /surfaces/{surface_id}/{identifier}: the surfaces of one discretization,
    documented with exactly its parameters."""
    path = f"/{{surface_id}}/{identifier}"
    kinds = surfaces_of(identifier)
    surface_path = Path(description=SURFACE_ID_DESCRIPTION, json_schema_extra={"enum": kinds})

    def get(request: Request, surface_id: Annotated[str, surface_path]) -> Response:
        return _get(
            request, surface_id, _with_discretization(identifier, dict(request.query_params))
        )

    def post(
        request: Request,
        surface_id: Annotated[str, surface_path],
        body: Annotated[dict[str, Any], Body(description="Surface and discretization parameters.")],
    ) -> Response:
        return _get(request, surface_id, _with_discretization(identifier, body))

    meridian = f"One discrete surface of revolution with a {identifier} meridian"
    routes: list[tuple[str, Any, str, str, dict[str, Any], list[Any]]] = [
        (
            "GET",
            get,
            meridian,
            f"As `GET /surfaces/{{surface_id}}` with `discretization={identifier}`; the query "
            f"takes the surface's parameters and those of {identifier}.",
            {"parameters": documented_parameters(identifier, in_path=True)},
            [Depends(reject_repeated_parameters)],
        ),
        (
            "POST",
            post,
            f"{meridian} (JSON body)",
            f"As GET /surfaces/{{surface_id}}/{identifier}, with the parameters in a JSON object.",
            documented_body(identifier, in_path=True),
            [],
        ),
    ]
    for method, endpoint, summary, description, extra, dependencies in routes:
        router.add_api_route(
            path,
            endpoint,
            methods=[method],
            name=f"{method.lower()}_surface_{identifier}",
            summary=summary,
            description=description,
            response_model=SurfaceResponse,
            responses=RESPONSES,
            dependencies=dependencies,
            openapi_extra=extra,
        )


for _identifier in DISCRETIZATIONS:
    _add_discretization_routes(_identifier)
