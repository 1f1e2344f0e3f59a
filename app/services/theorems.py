"""GET /theorems: where each statement of the catalog is checked, and its check as a document.

A statement is checked on a discretization's curve, a refinement study, a smooth reference or a
surface (``app.registry.STATEMENTS`` says which); this module picks the source a request asks
for (or the default one), builds the catalog's entries and shapes one check's document.
"""

from __future__ import annotations

from typing import Any
from urllib.parse import urlencode

from app.errors import UnknownIdError
from app.geometry.checks import Check
from app.geometry.errors import DomainError
from app.registry import DISCRETIZATIONS, SMOOTH, STUDIES, StatementEntry
from app.responses import check_document
from app.schemas.catalog import ParameterInfo
from app.schemas.common import StrictModel
from app.schemas.surfaces import SurfaceQuery


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
    if entry.smooth:
        return "smooth", entry.smooth[0]
    return "surface", entry.surfaces[0]


def source_model(
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
    if kind == "surface":
        return {}, SurfaceQuery, ()
    fixed = {"study": owner} if entry.discretizations else {}
    return fixed, STUDIES[owner].query, ()


def resolve_source(
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
    if kind == "surface" and study_id is None:
        return kind, owner  # `discretization` is the surface's own parameter (its meridian)
    elsewhere = (
        f"discretization={entry.discretizations[0]}"
        if entry.discretizations
        else f"GET /convergence/{entry.studies[0]}"
        if entry.studies
        else f"GET /smooth/{entry.smooth[0]}"
        if entry.smooth
        else f"GET /surfaces/{entry.surfaces[0]}"
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


def document(
    statement: StatementEntry,
    kind: str,
    owner: str,
    checks: list[Check],
    parameters: dict[str, Any],
    precision: dict[str, Any],
    certified: bool = False,
) -> dict[str, Any]:
    """The ``TheoremResponse`` document of one statement checked on one source (``certified``:
    computed on rigorous balls, see ``responses.check_document``)."""
    key = statement.statement.id
    check = next(c for c in checks if c.id == key)
    return {
        "id": key,
        "reference": check.reference,
        "claim": check.claim,
        "discretization": owner if kind == "discretization" else None,
        "study": owner if kind == "study" else None,
        "smooth": owner if kind == "smooth" else None,
        "surface": owner if kind == "surface" else None,
        "parameters": parameters,
        "precision": precision,
        "conditions": list(statement.statement.conditions),
        "check": check_document(check, certified),
    }
