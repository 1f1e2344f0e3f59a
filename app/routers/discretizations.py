"""GET /discretizations (catalog) and GET/POST /discretizations/{id} (one curve)."""

from typing import Annotated, Any

from fastapi import APIRouter, Depends, Query, Request, Response

from app.errors import UnknownIdError
from app.geometry.precision import Float64
from app.geometry.statement_tex import CONSTANT_TEX, PARAMETER_TEX
from app.registry import DISCRETIZATIONS, Discretization
from app.responses import canonical_key
from app.routers.caching import cached
from app.routers.common import (
    CURVE_RESPONSES,
    ExactJSONRoute,
    curve_answer,
    example_of,
    reject_repeated_parameters,
    settings_of,
    with_example,
)
from app.schemas.catalog import DiscretizationEntry, ParameterInfo
from app.schemas.common import NOT_FOUND_RESPONSE, CurveQuery, StrictModel
from app.schemas.curve import CurveResponse

router = APIRouter(prefix="/discretizations", tags=["discretizations"], route_class=ExactJSONRoute)

COMMON_FIELDS = frozenset(CurveQuery.model_fields)


def parameter_infos(model: type[StrictModel]) -> list[ParameterInfo]:
    """The catalog's parameter list, read from the request model's JSON schema."""
    properties: dict[str, Any] = model.model_json_schema()["properties"]
    infos = []
    for name, schema in properties.items():
        schema = dict(schema)
        description = schema.pop("description", "")
        domain = schema.pop("x-domain", None)
        schema.pop("title", None)
        infos.append(
            ParameterInfo(
                name=name,
                description=description,
                kind="common" if name in COMMON_FIELDS else "paper",
                domain=domain,
                default=schema.get("default"),
                json_schema=schema,
                domain_tex=PARAMETER_TEX.get(domain) if domain else None,
            )
        )
    return infos


def catalog_entry(entry: Discretization) -> DiscretizationEntry:
    info = entry.info
    return DiscretizationEntry(
        id=info.id,
        title=info.title,
        reference=info.reference,
        summary=info.summary,
        url=f"/discretizations/{info.id}",
        default_range=info.default_range,
        methods=list(info.methods),
        parameters=parameter_infos(entry.query),
        companions=info.companions,
        constants=info.constants,
        constants_tex={k: CONSTANT_TEX[k] for k in info.constants if k in CONSTANT_TEX},
        statements=[s.id for s in info.statements],
    )


@router.get(
    "",
    summary="List the discretizations",
    description="Every discretization of the paper the service computes, with its paper "
    "reference, parameters (domains, defaults), companions, constants and checked statements.",
    response_model=list[DiscretizationEntry],
)
def list_discretizations() -> list[DiscretizationEntry]:
    return [catalog_entry(entry) for entry in DISCRETIZATIONS.values()]


def example_document(entry: Discretization) -> Any:
    """A real response (default parameters, three vertices from index 0) to show in /docs."""
    query = entry.query.model_validate({})
    arguments = query.core_arguments()
    first = 0 if arguments["i_min"] <= 0 <= arguments["i_max"] else arguments["i_min"]
    arguments.update(i_min=first, i_max=first + 2)
    return example_of(entry.compute(Float64(), **arguments))


def _register(entry: Discretization) -> None:
    """Add GET and POST /discretizations/{id} for one discretization."""
    model, body = entry.query, entry.body
    identifier = entry.info.id

    def get_curve(request: Request, query: Annotated[model, Query()]) -> Response:  # type: ignore[valid-type]
        parsed: CurveQuery = query
        settings = settings_of(request)
        return cached(
            request,
            canonical_key(request.url.path, parsed.model_dump()),
            settings,
            lambda: curve_answer(entry, parsed, settings),
        )

    def post_curve(request: Request, query: body) -> Response:  # type: ignore[valid-type]
        parsed: CurveQuery = query
        settings = settings_of(request)
        return cached(
            request,
            canonical_key(request.url.path, parsed.model_dump()),
            settings,
            lambda: curve_answer(entry, parsed, settings),
        )

    common = {
        "response_model": CurveResponse,
        "responses": with_example(CURVE_RESPONSES, example_document(entry)),
        "description": entry.description,
    }
    router.add_api_route(
        f"/{identifier}",
        get_curve,
        methods=["GET"],
        summary=f"{entry.info.title}",
        operation_id=f"get_{identifier.replace('-', '_')}",
        dependencies=[Depends(reject_repeated_parameters)],
        **common,  # type: ignore[arg-type]
    )
    router.add_api_route(
        f"/{identifier}",
        post_curve,
        methods=["POST"],
        summary=f"{entry.info.title} (JSON body)",
        operation_id=f"post_{identifier.replace('-', '_')}",
        **common,  # type: ignore[arg-type]
    )


for _entry in DISCRETIZATIONS.values():
    _register(_entry)


@router.api_route(
    "/{identifier}", methods=["GET", "POST"], include_in_schema=False, responses=NOT_FOUND_RESPONSE
)
def unknown_discretization(identifier: str) -> Response:
    raise UnknownIdError("discretization", identifier, sorted(DISCRETIZATIONS))
