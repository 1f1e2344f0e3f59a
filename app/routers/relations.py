"""GET /relations: every registered discretization against the properties of Section 4."""

from __future__ import annotations

from collections.abc import Callable
from decimal import Decimal
from typing import Annotated, Any, Literal
from urllib.parse import urlencode

from fastapi import APIRouter, Depends, Query, Request, Response
from pydantic import Field, create_model

from app import compute_pool
from app.geometry import balls, relations
from app.geometry.curve import Curve
from app.geometry.errors import DomainError
from app.limits import LimitExceededError, enforce_digits, enforce_relation_row
from app.registry import DISCRETIZATIONS, Discretization
from app.rendering.tables import Table, TableCell, table_html, table_svg
from app.responses import bound, canonical_key, encode_json, number
from app.routers.caching import JSONBytesResponse, cached
from app.routers.common import (
    SVG_HEADERS,
    admit_curve,
    computed,
    in_child,
    parse_query,
    reject_repeated_parameters,
    settings_of,
)
from app.schemas.common import PROBLEM_RESPONSES, CurveQuery, StrictModel
from app.schemas.relations import RELATIONS_DESCRIPTION, RelationsResponse
from app.settings import Settings

router = APIRouter(prefix="/relations", tags=["relations"])

HTML_MEDIA_TYPE = "text/html; charset=utf-8"
COMMON_FIELDS = frozenset(CurveQuery.model_fields)


class RelationsBase(StrictModel):
    """Parameters of the whole matrix; the rows' parameters are added per discretization."""

    precision: Literal["float64", "mp"] = Field(
        "float64", description="`float64` or `mp` (every row in the same arithmetic)."
    )
    digits: int = Field(30, ge=1, le=100_000, description="Significant digits for precision=mp.")
    format: Literal["json", "html", "svg"] = Field(
        "json", description="`json` (default), `html` or `svg` (the matrix as a table)."
    )


def _row_fields() -> dict[str, tuple[Discretization, str, str]]:
    """Python field name -> (discretization, its public parameter name, query name)."""
    fields = {}
    for entry in DISCRETIZATIONS.values():
        for name, info in entry.query.model_fields.items():
            if name in COMMON_FIELDS:
                continue
            public = info.alias or name
            key = f"{entry.info.id.replace('-', '_')}__{name}"
            fields[key] = (entry, public, f"{entry.info.id}.{public}")
    return fields


ROW_FIELDS = _row_fields()


def _model() -> type[RelationsBase]:
    definitions: dict[str, Any] = {}
    for key, (entry, _public, query_name) in ROW_FIELDS.items():
        name = next(n for n, i in entry.query.model_fields.items() if (i.alias or n) == _public)
        info = entry.query.model_fields[name]
        extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else None
        annotation: Any = info.annotation
        if info.metadata:
            annotation = Annotated[(annotation, *info.metadata)]
        definitions[key] = (
            annotation,
            Field(
                info.default,
                alias=query_name,
                description=f"{entry.info.id}: {info.description or ''}",
                json_schema_extra=extra,
            ),
        )
    return create_model("RelationsQuery", __base__=RelationsBase, **definitions)


RelationsQuery = _model()


def _prefixed(error: DomainError | LimitExceededError, prefix: str) -> Exception:
    """The same error with the parameter named as in this endpoint (``d4b.d``)."""
    parameter = f"{prefix}{error.parameter}"
    if isinstance(error, LimitExceededError):
        return LimitExceededError(parameter, error.constraint, error.value)
    return type(error)(parameter, error.constraint, error.value, error.detail)


def _prepare(
    query: RelationsBase, settings: Settings
) -> Callable[[], list[tuple[Discretization, Curve]]]:
    """Validate every row's parameters, check its limits and charge its cost now, before any
    row is computed; return the computation."""
    if query.precision == "mp":
        enforce_digits(settings, query.digits)
    given = query.model_fields_set
    queries = []
    for entry in DISCRETIZATIONS.values():
        prefix = f"{entry.info.id}."
        values: dict[str, Any] = {"precision": query.precision, "digits": query.digits}
        for key, (owner, public, _name) in ROW_FIELDS.items():
            if owner is entry and key in given:
                values[public] = getattr(query, key)
        row_query = parse_query(entry.query, values, prefix)
        arguments = row_query.core_arguments()
        try:
            enforce_relation_row(settings, "i_max", arguments["i_min"], arguments["i_max"])
        except LimitExceededError as error:
            raise _prefixed(error, prefix) from None
        queries.append((entry, row_query, prefix))
    prepared = []
    for entry, row_query, prefix in queries:
        try:
            prepared.append((entry, row_query, prefix, *admit_curve(entry, row_query, settings)))
        except (DomainError, LimitExceededError) as error:
            raise _prefixed(error, prefix) from None

    def run() -> list[tuple[Discretization, Curve]]:
        curves = []
        for entry, row_query, prefix, chosen, arguments in prepared:
            try:
                curves.append((entry, computed(entry, row_query, settings, chosen, arguments)))
            except (DomainError, LimitExceededError) as error:
                raise _prefixed(error, prefix) from None
        return curves

    return run


def relations_document(curves: list[tuple[Discretization, Curve]]) -> dict[str, Any]:
    """The JSON document of ``RelationsResponse``."""
    ar = curves[0][1].arithmetic
    certified = ar.certified  # mp rows are computed on balls: bounds as decimal strings
    rows = []
    for entry, curve in curves:
        shown = {k: v for k, v in curve.parameters.items() if v is not None}
        with balls.session(curve.arithmetic):  # mp rows are balls: their working precision
            cells = relations.row(curve)
        rows.append(
            {
                "id": entry.info.id,
                "title": entry.info.title,
                "reference": entry.info.reference,
                "parameters": curve.parameters,
                "url": f"/discretizations/{entry.info.id}?{urlencode(shown)}",
                "cells": [
                    {
                        "property": cell.property,
                        "residual": bound(cell.residual, certified),
                        "tolerance": bound(cell.tolerance, certified),
                        "holds": cell.holds,
                        "constants": {k: number(ar, v) for k, v in cell.constants.items()},
                        "note": cell.note,
                    }
                    for cell in cells
                ],
            }
        )
    return {
        "precision": ar.describe(),
        "columns": [
            {"id": p.id, "title": p.title, "reference": p.reference, "claim": p.claim}
            for p in relations.PROPERTIES
        ],
        "rows": rows,
    }


def relations_table(document: dict[str, Any]) -> Table:
    """The matrix as a table: verdict, residual and constants in each cell."""
    precision = document["precision"]
    table = Table(
        title="Section 4: which discrete hyperbolic cosine satisfies which property",
        subtitle=f"precision {precision['mode']} ({precision['digits']} digits); residuals are "
        "the largest relative misfit of the least-squares fit (docs/checks.md)",
        footnote="GET /relations (JSON: format=json). H = 0: the surface of revolution of p "
        "with the row's Gauss image (own, else circumscribed); K constant: the pseudosphere of "
        "the row's tractrix; mixed-area curvatures of [3]. Grey: not applicable (see the note).",
        columns=[(c["title"], f"{c['reference']}: {c['claim']}") for c in document["columns"]],
        corner="discretization",
    )
    for row in document["rows"]:
        heading = (row["id"], *_parameter_lines(row["parameters"]))
        cells = []
        for cell in row["cells"]:
            state = "none" if cell["holds"] is None else "holds" if cell["holds"] else "fails"
            lines = []
            if cell["residual"] is not None:
                lines.append(f"residual {_residual_text(cell['residual'])}")
            lines.extend(f"{k} = {_short(v)}" for k, v in cell["constants"].items())
            if cell["holds"] is None and cell["residual"] is None:
                lines.append("not applicable")
            cells.append(TableCell(state, tuple(lines), cell["note"] or ""))  # type: ignore[arg-type]
        table.rows.append((heading, cells))
    return table


def _residual_text(value: float | str) -> str:
    """A cell's residual in the tables: mp residuals are decimal strings (beyond floats)."""
    return f"{Decimal(value):.2e}" if isinstance(value, str) else f"{value:.2e}"


def _short(value: Any) -> str:
    return f"{float(value):.6g}"


def _parameter_lines(parameters: dict[str, Any]) -> list[str]:
    items = [
        f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}"
        for k, v in parameters.items()
        if v is not None
    ]
    return [", ".join(items[k : k + 2]) for k in range(0, len(items), 2)]


@router.get(
    "",
    summary="Section 4: the discretizations against (D1), (D3), (2), (7), H = 0, K constant",
    description=RELATIONS_DESCRIPTION,
    response_model=RelationsResponse,
    responses={
        200: {
            "content": {"text/html": {"schema": {"type": "string"}}, "image/svg+xml": {}},
            "description": "The matrix as JSON (default), an HTML table (`format=html`) or an "
            "SVG table (`format=svg`). Carries an ETag and Cache-Control; If-None-Match gets "
            "304.",
        },
        304: {"description": "Not modified (the If-None-Match ETag matches)."},
        **PROBLEM_RESPONSES,
    },
    dependencies=[Depends(reject_repeated_parameters)],
)
def get_relations(
    request: Request,
    query: Annotated[RelationsQuery, Query()],  # type: ignore[valid-type]
) -> Response:
    parsed: RelationsBase = query
    settings = settings_of(request)
    run = _prepare(parsed, settings)

    def build() -> Response:
        # heavy or on balls (mp): computed and rendered in a child process
        pool = compute_pool.offload(balls=parsed.precision == "mp")
        if pool is not None:
            values = dict(parsed)
            return in_child(pool, render_relations, values, parsed.model_fields_set, settings)
        return relations_answer(run(), parsed.format)

    key = canonical_key(request.url.path, parsed.model_dump(by_alias=True))
    return cached(request, key, settings, build)


def relations_answer(curves: list[tuple[Discretization, Curve]], response_format: str) -> Response:
    """The matrix of the computed rows in the request's format."""
    document = relations_document(curves)
    if response_format == "html":
        return Response(
            table_html(relations_table(document)),
            media_type=HTML_MEDIA_TYPE,
            headers=SVG_HEADERS,
        )
    if response_format == "svg":
        return Response(
            table_svg(relations_table(document)),
            media_type="image/svg+xml",
            headers=SVG_HEADERS,
        )
    return JSONBytesResponse(encode_json(document))


def render_relations(values: dict[str, Any], fields_set: set[str], settings: Settings) -> Response:
    """What a pool child runs for ``get_relations`` (its charges are no-ops there)."""
    parsed: RelationsBase = RelationsQuery.model_construct(fields_set, **values)
    return relations_answer(_prepare(parsed, settings)(), parsed.format)
