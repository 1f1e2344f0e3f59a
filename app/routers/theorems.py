"""GET /theorems (statement catalog) and GET /theorems/{id} (one statement checked)."""

from functools import lru_cache
from typing import Annotated, Any, Literal
from urllib.parse import urlencode

from fastapi import APIRouter, Depends, Path, Query, Request, Response

from app.errors import UnknownIdError
from app.geometry.checks import Check
from app.geometry.errors import DomainError
from app.geometry.precision import Float64, arithmetic
from app.geometry.statement_tex import CLAIM_TEX, ERRATUM_TEX
from app.registry import DISCRETIZATIONS, SMOOTH, STATEMENTS, STUDIES, StatementEntry
from app.responses import JSONBytesResponse, cached, canonical_key, check_document, encode_json
from app.routers.common import (
    compute,
    discretization,
    parse_query,
    prepare_study,
    reject_repeated_parameters,
    settings_of,
    study,
)
from app.routers.discretizations import parameter_infos
from app.routers.smooth import enforce_samples
from app.schemas.catalog import ErratumTeX, ParameterInfo, StatementInfo, TheoremResponse
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES, StrictModel

router = APIRouter(prefix="/theorems", tags=["theorems"])


def default_source(identifier: str, entry: StatementEntry) -> tuple[str, str]:
    """(kind, id) of the source a statement is checked on by default; kind is
    ``discretization``, ``study`` or ``smooth``.

    A statement named like a study (theorem-11, theorem-14, theorem-15) is a limit claim: its
    study checks it. Otherwise its first discretization, else its first study, else its smooth
    reference.
    """
    if identifier in entry.studies:
        return "study", identifier
    if entry.discretizations:
        return "discretization", entry.discretizations[0]
    if entry.studies:
        return "study", entry.studies[0]
    return "smooth", entry.smooth[0]


def _source_model(
    identifier: str, entry: StatementEntry
) -> tuple[dict[str, str], type[StrictModel], tuple[tuple[str, str], ...]]:
    """The fixed query, request model and statement defaults of a statement's default source.

    The fixed query names the source (``discretization=...`` or, for a statement that curves
    check too, ``study=...``); the statement's defaults apply to curves only.
    """
    kind, owner = default_source(identifier, entry)
    if kind == "discretization":
        return {"discretization": owner}, DISCRETIZATIONS[owner].query, entry.statement.defaults
    if kind == "smooth":
        return {}, SMOOTH[owner].query, ()
    fixed = {"study": owner} if entry.discretizations else {}
    return fixed, STUDIES[owner].query, ()


def _resolve_source(
    identifier: str, entry: StatementEntry, discretization_id: str | None, study_id: str | None
) -> tuple[str, str]:
    """(kind, id) of the source asked for (or the default), validated against the statement."""
    if discretization_id is not None and study_id is not None:
        raise DomainError(
            "study",
            "at most one of discretization and study",
            study_id,
            f"discretization = {discretization_id}",
        )
    kind, owner = default_source(identifier, entry)
    elsewhere = (
        f"discretization={entry.discretizations[0]}"
        if entry.discretizations
        else f"GET /convergence/{entry.studies[0]}"
        if entry.studies
        else f"GET /smooth/{entry.smooth[0]}"
    )
    if study_id is not None:
        if not entry.studies:
            raise DomainError(
                "study", f"a study that checks this statement: none ({elsewhere})", study_id
            )
        if study_id not in entry.studies:
            raise UnknownIdError("study for this statement", study_id, list(entry.studies))
        return "study", study_id
    if discretization_id is not None:
        if not entry.discretizations:
            raise DomainError(
                "discretization",
                f"a discretization that checks this statement: none ({elsewhere})",
                discretization_id,
            )
        if discretization_id not in entry.discretizations:
            raise UnknownIdError(
                "discretization for this statement",
                discretization_id,
                list(entry.discretizations),
            )
        return "discretization", discretization_id
    return kind, owner


def example_url(
    identifier: str,
    fixed: dict[str, str],
    parameters: list[ParameterInfo],
    defaults: tuple[tuple[str, str], ...] = (),
) -> str:
    """/theorems/{id} with every paper parameter at its default (the statement's own first)."""
    values: dict[str, Any] = dict(fixed)
    values.update(
        {p.name: p.default for p in parameters if p.kind == "paper" and p.default is not None}
    )
    values.update(dict(defaults))
    return f"/theorems/{identifier}?{urlencode(values)}"


@lru_cache(maxsize=1)
def default_errata() -> dict[str, tuple[str, ...]]:
    """Statement id -> ids of the errata its check carries at the default parameters (float64).

    Computed once per process from every discretization and study at its defaults.
    """
    found: dict[str, set[str]] = {}

    def collect(checks: list[Check]) -> None:
        for check in checks:
            if check.erratum is not None:
                found.setdefault(check.id, set()).add(check.erratum.id)

    for entry in DISCRETIZATIONS.values():
        collect(entry.compute(Float64(), **entry.query.model_validate({}).core_arguments()).checks)
    for source in STUDIES.values():
        collect(source.run(Float64(), **source.query.model_validate({}).core_arguments()).checks)
    return {k: tuple(sorted(v, key=lambda e: int(e[1:]))) for k, v in found.items()}


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
    errata = default_errata()
    out = []
    for identifier, entry in STATEMENTS.items():
        fixed, model, defaults = _source_model(identifier, entry)
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
                url=f"/theorems/{identifier}",
                example_url=example_url(identifier, fixed, parameters, defaults),
                parameters=parameters,
                conditions=list(entry.statement.conditions),
                errata=list(errata.get(identifier, ())),
                errata_tex=[
                    ErratumTeX(id=e, printed_tex=ERRATUM_TEX[e][0], corrected_tex=ERRATUM_TEX[e][1])
                    for e in errata.get(identifier, ())
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
    kind, owner = _resolve_source(statement_id, entry, discretization_id, study_id)
    values: dict[str, Any] = dict(request.query_params)
    values.pop("discretization", None)
    values.pop("study", None)
    settings = settings_of(request)

    def respond(checks: list[Check], parameters: dict[str, Any], ar: Any) -> Response:
        check = next(c for c in checks if c.id == statement_id)
        document = {
            "id": statement_id,
            "reference": check.reference,
            "claim": check.claim,
            "discretization": owner if kind == "discretization" else None,
            "study": owner if kind == "study" else None,
            "smooth": owner if kind == "smooth" else None,
            "parameters": parameters,
            "precision": ar.describe(),
            "conditions": list(entry.statement.conditions),
            "check": check_document(check),
        }
        return JSONBytesResponse(encode_json(document))

    if kind == "study":
        source = study(owner)
        values.pop("detail", None)
        study_query = parse_query(source.query, values)
        run = prepare_study(source, study_query, settings)

        def build_study() -> Response:
            result = run()
            return respond(result.checks, result.parameters, result.arithmetic)

        key = canonical_key(request.url.path, {"study": owner, **study_query.model_dump()})
        return cached(request, key, settings, build_study)

    if kind == "smooth":
        reference = SMOOTH[owner]
        smooth_query = parse_query(reference.query, values)

        def build_smooth() -> Response:
            enforce_samples(settings, smooth_query)
            ar = arithmetic(smooth_query.precision, smooth_query.digits)
            curve = reference.compute(ar, **smooth_query.core_arguments())
            return respond(curve.checks, curve.parameters, curve.arithmetic)

        key = canonical_key(request.url.path, {"smooth": owner, **smooth_query.model_dump()})
        return cached(request, key, settings, build_smooth)

    target = discretization(owner)
    query = parse_query(target.query, {**dict(entry.statement.defaults), **values})

    def build() -> Response:
        curve = compute(target, query, settings)
        return respond(curve.checks, curve.parameters, curve.arithmetic)

    key = canonical_key(request.url.path, {"discretization": owner, **query.model_dump()})
    return cached(request, key, settings, build)
