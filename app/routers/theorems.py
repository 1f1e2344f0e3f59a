"""GET /theorems (statement catalog) and GET /theorems/{id} (one statement checked)."""

from typing import Annotated, Any, Literal

from fastapi import APIRouter, Depends, Path, Query, Request, Response

from app import compute_pool
from app.errors import UnknownIdError
from app.geometry import balls
from app.geometry.checks import Check
from app.geometry.curve import Curve
from app.geometry.errors import DomainError
from app.geometry.precision import arithmetic
from app.geometry.statement_tex import CLAIM_TEX, ERRATUM_TEX
from app.geometry.studies.common import Study
from app.registry import SMOOTH, STATEMENTS, StatementEntry
from app.responses import canonical_key, encode_json
from app.routers import surfaces
from app.routers.caching import JSONBytesResponse, cached
from app.routers.common import (
    admit_curve,
    compute,
    computed,
    discretization,
    in_child,
    parse_query,
    prepare_study,
    reject_repeated_parameters,
    settings_of,
    study,
)
from app.routers.discretizations import parameter_infos
from app.routers.smooth import enforce_samples
from app.schemas.catalog import ErratumTeX, StatementInfo, TheoremResponse
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES
from app.services import surfaces as surface_service, theorems
from app.settings import Settings

router = APIRouter(prefix="/theorems", tags=["theorems"])


@router.get(
    "",
    summary="List the checkable statements",
    description="Every statement of the paper the service checks (theorems, their parts and "
    "hypotheses, recursions, printed formulas of the proofs, limits, named properties), with "
    "its reference, the claim in words and how its residual is measured, the parameters it "
    "accepts with their defaults, a ready-to-use example request, the hypotheses the text "
    "leaves implicit, and the errata its check carries at the default parameters.",
    response_model=list[StatementInfo],
)
def list_statements() -> list[StatementInfo]:
    out = []
    for identifier, entry in STATEMENTS.items():
        fixed, model, defaults = theorems.source_model(identifier, entry)
        parameters = parameter_infos(model)
        out.append(
            StatementInfo(
                id=identifier,
                reference=entry.statement.reference,
                claim=entry.statement.claim,
                claim_tex=CLAIM_TEX.get(identifier, ""),
                discretizations=list(entry.discretizations),
                studies=list(entry.studies),
                smooth=list(entry.smooth),
                surfaces=list(entry.surfaces),
                url=f"/theorems/{identifier}",
                example_url=theorems.example_url(identifier, fixed, parameters, defaults),
                parameters=parameters,
                conditions=list(entry.statement.conditions),
                errata=list(entry.statement.errata),
                errata_tex=[
                    ErratumTeX(id=e, printed_tex=ERRATUM_TEX[e][0], corrected_tex=ERRATUM_TEX[e][1])
                    for e in entry.statement.errata
                    if e in ERRATUM_TEX
                ],
            )
        )
    return out


@router.get(
    "/{statement_id}",
    summary="Check one statement",
    description="Computes what the statement is about and returns its check: residual, "
    "tolerance, verdict and, where the printed formula is wrong, the erratum. A statement about "
    "a discretization is checked on the polygon of `discretization` (default: the first that "
    "checks it), and every parameter of that discretization is accepted (GET "
    "/discretizations). A statement of Section 6 (limits, the proofs of Theorems 11, 14 and "
    "15) is checked on its refinement study, and accepts the study's parameters (GET "
    "/convergence; `detail` does not apply there). Statements that both check (theorem-11, "
    "lemma-10, example-12, remark-13) take `study=theorem-11` or `discretization=d2b`; "
    "theorem-11 defaults to its study, the others to the curve. Unknown parameters are "
    "rejected; GET /theorems lists each statement's parameters and an example. The (S4) "
    "statements of Section 2 are checked on the smooth tractrix (GET /smooth/tractrix) and "
    "accept its parameters.",
    response_model=TheoremResponse,
    responses={**PROBLEM_RESPONSES, **NOT_FOUND_RESPONSE, 304: {"description": "Not modified."}},
    dependencies=[Depends(reject_repeated_parameters)],
)
def check_statement(
    request: Request,
    statement_id: Annotated[str, Path(description="Statement id, e.g. `theorem-5`.")],
    discretization_id: Annotated[
        str | None,
        Query(alias="discretization", description="Discretization to check it on."),
    ] = None,
    study_id: Annotated[
        str | None,
        Query(alias="study", description="Refinement study to check it on (GET /convergence)."),
    ] = None,
    precision: Annotated[Literal["float64", "mp"], Query(description="Arithmetic.")] = "float64",
    digits: Annotated[int, Query(ge=1, le=100_000, description="Digits for mp.")] = 30,
    detail: Annotated[bool, Query(description="Residual per index (curves only).")] = False,
) -> Response:
    entry = STATEMENTS.get(statement_id)
    if entry is None:
        raise UnknownIdError("statement", statement_id, sorted(STATEMENTS))
    kind, owner = theorems.resolve_source(statement_id, entry, discretization_id, study_id)
    values: dict[str, Any] = dict(request.query_params)
    values.pop("discretization", None)
    values.pop("study", None)
    settings = settings_of(request)

    if kind == "study":
        source = study(owner)
        values.pop("detail", None)
        study_query = parse_query(source.query, values)
        run = prepare_study(source, study_query, settings)

        def build_study() -> Response:
            pool = compute_pool.offload()  # heavy: computed and rendered in a child process
            if pool is not None:
                job = (dict(study_query), study_query.model_fields_set)
                return in_child(pool, render_study, statement_id, owner, *job, settings)
            result = run()
            return answer(statement_id, kind, owner, result)

        key = canonical_key(request.url.path, {"study": owner, **study_query.model_dump()})
        return cached(request, key, settings, build_study)

    if kind == "smooth":
        reference = SMOOTH[owner]
        smooth_query = parse_query(reference.query, values)

        def build_smooth() -> Response:
            enforce_samples(settings, smooth_query)
            ar = arithmetic(smooth_query.precision, smooth_query.digits)
            curve = reference.compute(ar, **smooth_query.core_arguments())
            return answer(statement_id, kind, owner, curve)

        key = canonical_key(request.url.path, {"smooth": owner, **smooth_query.model_dump()})
        return cached(request, key, settings, build_smooth)

    if kind == "surface":
        values.pop("detail", None)
        if discretization_id is not None:
            values["discretization"] = discretization_id
        surface_kind, surface_query, curve_query = surfaces.parse(owner, values)

        def build_surface() -> Response:
            plan = surface_service.admit(surface_kind, surface_query, curve_query, settings)
            pool = compute_pool.offload()  # heavy: computed and rendered in a child process
            if pool is not None:
                job = surfaces.portable(surface_kind, surface_query, curve_query)
                return in_child(pool, render_surface, statement_id, *job, settings)
            result = surface_service.build(plan, settings)
            return surface_respond(statement_id, result)

        key = canonical_key(
            request.url.path,
            {"surface": owner, **surface_query.model_dump(), **curve_query.model_dump()},
        )
        return cached(request, key, settings, build_surface)

    target = discretization(owner)
    query = parse_query(target.query, {**dict(entry.statement.defaults), **values})

    def build() -> Response:
        chosen, arguments = admit_curve(target, query, settings)
        # heavy or on balls (mp): computed and rendered in a child process
        pool = compute_pool.offload(balls=query.precision == "mp")
        if pool is not None:
            job = (dict(query), query.model_fields_set)
            return in_child(pool, render_curve_check, statement_id, owner, *job, settings)
        curve = computed(target, query, settings, chosen, arguments)
        return theorem_response(entry, owner, curve, query.checks)

    key = canonical_key(request.url.path, {"discretization": owner, **query.model_dump()})
    return cached(request, key, settings, build)


def respond(
    statement_id: str,
    kind: str,
    owner: str,
    checks: list[Check],
    parameters: dict[str, Any],
    ar: Any,
) -> Response:
    """The statement's check as its JSON document."""
    certified = balls.certificate(ar) is not None  # mp curves: on rigorous balls
    document = theorems.document(
        STATEMENTS[statement_id], kind, owner, checks, parameters, ar.describe(), certified
    )
    return JSONBytesResponse(encode_json(document))


def answer(statement_id: str, kind: str, owner: str, source: Curve | Study) -> Response:
    """The statement's check on a computed curve or study."""
    return respond(statement_id, kind, owner, source.checks, source.parameters, source.arithmetic)


def theorem_response(entry: StatementEntry, owner: str, curve: Curve, checks: str) -> Response:
    """The statement checked on the curve of discretization ``owner`` (also the fast lane's).

    ``checks`` is the request's: one that leaves this statement's check out (``none``, a list
    without it, ``failed`` when it holds) is a 422 naming it, not a missing check."""
    identifier = entry.statement.id
    if all(check.id != identifier for check in curve.checks):
        raise DomainError(
            "checks",
            f"all, or a list naming {identifier} (the statement checked here)",
            checks,
            f"the check of {identifier} is not in the selection",
        )
    return answer(identifier, "discretization", owner, curve)


def surface_respond(statement_id: str, result: surface_service.SurfaceResult) -> Response:
    owner = result.kind.id
    built = result.surface
    return respond(
        statement_id, "surface", owner, built.checks, result.parameters, built.arithmetic
    )


# What a pool child runs for ``check_statement`` (the charges are no-ops there).


def render_curve_check(
    statement_id: str, owner: str, values: dict[str, Any], fields: set[str], settings: Settings
) -> Response:
    target = discretization(owner)
    query = target.query.model_construct(fields, **values)
    curve = compute(target, query, settings)
    return theorem_response(STATEMENTS[statement_id], owner, curve, query.checks)


def render_study(
    statement_id: str, owner: str, values: dict[str, Any], fields: set[str], settings: Settings
) -> Response:
    source = study(owner)
    result = prepare_study(source, source.query.model_construct(fields, **values), settings)()
    return answer(statement_id, "study", owner, result)


def render_surface(statement_id: str, *job: Any) -> Response:
    *request, settings = job
    kind, surface_query, curve_query = surfaces.rebuilt(*request)
    result = surface_service.compute(kind, surface_query, curve_query, settings)
    return surface_respond(statement_id, result)
