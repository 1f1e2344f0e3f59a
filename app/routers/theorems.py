"""GET /theorems (statement catalog) and GET /theorems/{id} (one statement checked)."""

from typing import Annotated, Any, Literal

from fastapi import APIRouter, Depends, Path, Query, Request, Response

from app.errors import UnknownIdError
from app.registry import STATEMENTS
from app.responses import JSONBytesResponse, cached, canonical_key, check_document, encode_json
from app.routers.common import (
    compute,
    discretization,
    parse_query,
    reject_repeated_parameters,
    settings_of,
)
from app.schemas.catalog import StatementInfo, TheoremResponse
from app.schemas.common import NOT_FOUND_RESPONSE, PROBLEM_RESPONSES

router = APIRouter(prefix="/theorems", tags=["theorems"])


@router.get(
    "",
    summary="List the checkable statements",
    description="Every statement of the paper the service checks (theorems, their parts and "
    "hypotheses, recursions, printed formulas of the proofs, named properties), with its "
    "reference, the claim in words and how its residual is measured.",
    response_model=list[StatementInfo],
)
def list_statements() -> list[StatementInfo]:
    return [
        StatementInfo(
            id=identifier,
            reference=entry.statement.reference,
            claim=entry.statement.claim,
            discretizations=list(entry.discretizations),
            url=f"/theorems/{identifier}",
        )
        for identifier, entry in STATEMENTS.items()
    ]


@router.get(
    "/{statement_id}",
    summary="Check one statement",
    description="Computes the polygon of the statement's discretization (`discretization`, "
    "default: the first that checks it) and returns this statement's check: residual, "
    "tolerance, verdict and, where the printed formula is wrong, the erratum. Besides the "
    "parameters below, every parameter of that discretization is accepted (see "
    "GET /discretizations); unknown parameters are rejected.",
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
    precision: Annotated[Literal["float64", "mp"], Query(description="Arithmetic.")] = "float64",
    digits: Annotated[int, Query(ge=1, le=100_000, description="Digits for mp.")] = 30,
    detail: Annotated[bool, Query(description="Residual per index.")] = False,
) -> Response:
    entry = STATEMENTS.get(statement_id)
    if entry is None:
        raise UnknownIdError("statement", statement_id, sorted(STATEMENTS))
    owner = discretization_id or entry.discretizations[0]
    if owner not in entry.discretizations:
        raise UnknownIdError(
            "discretization for this statement", owner, list(entry.discretizations)
        )
    target = discretization(owner)
    values: dict[str, Any] = dict(request.query_params)
    values.pop("discretization", None)
    query = parse_query(target.query, values)
    settings = settings_of(request)

    def build() -> Response:
        curve = compute(target, query, settings)
        check = next(c for c in curve.checks if c.id == statement_id)
        document = {
            "id": statement_id,
            "reference": check.reference,
            "claim": check.claim,
            "discretization": owner,
            "parameters": curve.parameters,
            "precision": curve.arithmetic.describe(),
            "check": check_document(check),
        }
        return JSONBytesResponse(encode_json(document))

    key = canonical_key(request.url.path, {"discretization": owner, **query.model_dump()})
    return cached(request, key, settings, build)
