"""GET /smooth/catenary and GET /smooth/tractrix: the smooth references of Section 2."""

from collections.abc import Callable
from typing import Annotated, Any

from fastapi import APIRouter, Depends, Query, Request, Response

from app import compute_pool
from app.errors import UnknownIdError
from app.geometry.curve import Curve
from app.geometry.precision import Float64
from app.limits import (
    MP_OVERHEAD_DIGITS,
    LimitExceededError,
    admit,
    curve_cost,
    enforce_digits,
    timed_arithmetic,
)
from app.registry import SMOOTH
from app.responses import canonical_key
from app.routers.caching import cached
from app.routers.common import (
    CURVE_RESPONSES,
    curve_response,
    example_of,
    in_child,
    reject_repeated_parameters,
    selection_of,
    settings_of,
    with_example,
)
from app.schemas.common import NOT_FOUND_RESPONSE
from app.schemas.curve import CurveResponse
from app.schemas.smooth import SmoothQuery
from app.settings import Settings

router = APIRouter(prefix="/smooth", tags=["smooth"])

CURVES: dict[str, tuple[Callable[..., Curve], str, str]] = {
    key: (entry.compute, entry.info.title, entry.description) for key, entry in SMOOTH.items()
}


def example_document(compute: Callable[..., Curve]) -> Any:
    """A real response (default parameters, three samples) to show in /docs."""
    return example_of(compute(Float64(), count=3))


def enforce_samples(settings: Settings, query: SmoothQuery) -> None:
    """Refuse more samples, or more mp work, than the settings allow."""
    if query.count > settings.max_vertices:
        raise LimitExceededError("count", f"count <= {settings.max_vertices}", query.count)
    if query.precision == "mp":
        enforce_digits(settings, query.digits)
        if (query.digits + MP_OVERHEAD_DIGITS) * query.count > settings.max_mp_work:
            raise LimitExceededError(
                "digits",
                f"(digits + {MP_OVERHEAD_DIGITS}) × count <= {settings.max_mp_work} in "
                "precision=mp",
                query.digits,
            )
    seconds, nbytes = curve_cost(query.count, query.count, query.precision, query.digits, "smooth")
    admit(settings, seconds, nbytes, "count", query.count)


def _register(name: str, compute: Callable[..., Curve], title: str, description: str) -> None:
    def get_curve(request: Request, query: Annotated[SmoothQuery, Query()]) -> Response:
        settings = settings_of(request)

        def build() -> Response:
            enforce_samples(settings, query)
            pool = compute_pool.offload()
            if pool is not None:
                values = dict(query)
                return in_child(pool, smooth_answer, name, values, query.model_fields_set, settings)
            return smooth_answer(name, dict(query), query.model_fields_set, settings)

        return cached(request, canonical_key(request.url.path, query.model_dump()), settings, build)

    router.add_api_route(
        f"/{name}",
        get_curve,
        methods=["GET"],
        summary=title,
        description=description,
        operation_id=f"get_smooth_{name}",
        response_model=CurveResponse,
        responses=with_example(CURVE_RESPONSES, example_document(compute)),
        dependencies=[Depends(reject_repeated_parameters)],
    )


def smooth_answer(
    name: str, values: dict[str, Any], fields_set: set[str], settings: Settings
) -> Response:
    """The smooth curve for validated query values (already charged): in the worker, or what a
    compute process runs (app/compute_pool.py) when its estimate is heavy."""
    compute = CURVES[name][0]
    query = SmoothQuery.model_construct(fields_set, **values)
    ar = timed_arithmetic(settings, query.precision, query.digits)
    curve = compute(ar, **query.core_arguments())
    statements = (check.id for check in curve.checks)
    selection = selection_of(query, statements, curve.companions)
    return curve_response(curve.selected(selection), query.format)


for _name, (_compute, _title, _description) in CURVES.items():
    _register(_name, _compute, _title, _description)


@router.get("/{curve}", include_in_schema=False, responses=NOT_FOUND_RESPONSE)
def unknown_curve(curve: str) -> Response:
    raise UnknownIdError("smooth curve", curve, sorted(CURVES))
