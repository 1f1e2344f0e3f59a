"""Which discretizations the service offers: core module, request model and description.

Adding a discretization means adding one entry to ``_ENTRIES`` (a refinement study: one entry
to ``_STUDIES``); the routers, the catalogs, the statement catalog and the relations matrix read
everything else from here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from functools import cached_property

from app.geometry.checks import Statement
from app.geometry.curve import Curve, DiscretizationInfo
from app.geometry.d1 import discretization as d1
from app.geometry.d2a import hex as d2a_hex
from app.geometry.d2a import quad as d2a_quad
from app.geometry.d2b import discretization as d2b
from app.geometry.d3 import discretization as d3
from app.geometry.d4a import discretization as d4a
from app.geometry.d4b import discretization as d4b
from app.geometry.smooth import references as smooth_curves
from app.geometry.studies import theorem_11 as catenoid_refinement
from app.geometry.studies import tractrix as convergence
from app.geometry.studies.tractrix import Study, StudyInfo
from app.schemas.common import CurveQuery, strict_body
from app.schemas.convergence import (
    THEOREM_11_DESCRIPTION,
    THEOREM_14_DESCRIPTION,
    THEOREM_15_DESCRIPTION,
    CatenoidStudyQuery,
    StudyQuery,
    TractrixStudyQuery,
)
from app.schemas.d1 import D1_DESCRIPTION, D1Query
from app.schemas.d2a import D2A_HEX_DESCRIPTION, D2A_QUAD_DESCRIPTION, D2aHexQuery, D2aQuadQuery
from app.schemas.d2b import D2B_DESCRIPTION, D2bQuery
from app.schemas.d3 import D3_DESCRIPTION, D3Query
from app.schemas.d4a import D4A_DESCRIPTION, D4aQuery
from app.schemas.d4b import D4B_DESCRIPTION, D4bQuery
from app.schemas.smooth import CATENARY_DESCRIPTION, TRACTRIX_DESCRIPTION, SmoothQuery


@dataclass(frozen=True, eq=False)
class Discretization:
    """One discretization as the API serves it."""

    info: DiscretizationInfo
    query: type[CurveQuery]
    compute: Callable[..., Curve]
    description: str

    @cached_property
    def body(self) -> type[CurveQuery]:
        """The strict JSON-body model of ``query`` (POST)."""
        return strict_body(self.query)


_ENTRIES = (  # in the paper's order
    Discretization(d1.INFO, D1Query, d1.compute, D1_DESCRIPTION),
    Discretization(d2a_quad.INFO, D2aQuadQuery, d2a_quad.compute, D2A_QUAD_DESCRIPTION),
    Discretization(d2a_hex.INFO, D2aHexQuery, d2a_hex.compute, D2A_HEX_DESCRIPTION),
    Discretization(d2b.INFO, D2bQuery, d2b.compute, D2B_DESCRIPTION),
    Discretization(d3.INFO, D3Query, d3.compute, D3_DESCRIPTION),
    Discretization(d4a.INFO, D4aQuery, d4a.compute, D4A_DESCRIPTION),
    Discretization(d4b.INFO, D4bQuery, d4b.compute, D4B_DESCRIPTION),
)

DISCRETIZATIONS: dict[str, Discretization] = {entry.info.id: entry for entry in _ENTRIES}


@dataclass(frozen=True, eq=False)
class ConvergenceStudy:
    """One refinement study as the API serves it (GET /convergence/{id})."""

    info: StudyInfo
    query: type[StudyQuery]
    run: Callable[..., Study]
    """The core's study: ``run(ar, **query.core_arguments())``."""
    work: Callable[..., int]
    """Its cost in construction steps for the mp budget, from the same arguments (validates)."""
    size: Callable[..., tuple[int, int]]
    """(construction steps, sample points) over all levels, from the same arguments."""
    description: str


_STUDIES = (  # in the paper's order
    ConvergenceStudy(
        catenoid_refinement.THEOREM_11_INFO,
        CatenoidStudyQuery,
        catenoid_refinement.theorem_11,
        catenoid_refinement.mp_work,
        catenoid_refinement.work,
        THEOREM_11_DESCRIPTION,
    ),
    ConvergenceStudy(
        convergence.THEOREM_14_INFO,
        TractrixStudyQuery,
        convergence.theorem_14,
        convergence.mp_work,
        convergence.work,
        THEOREM_14_DESCRIPTION,
    ),
    ConvergenceStudy(
        convergence.THEOREM_15_INFO,
        TractrixStudyQuery,
        convergence.theorem_15,
        convergence.mp_work,
        convergence.work,
        THEOREM_15_DESCRIPTION,
    ),
)

STUDIES: dict[str, ConvergenceStudy] = {entry.info.id: entry for entry in _STUDIES}


@dataclass(frozen=True, eq=False)
class SmoothReference:
    """One smooth reference curve of Section 2 as the API serves it (GET /smooth/{id})."""

    info: smooth_curves.SmoothInfo
    query: type[SmoothQuery]
    compute: Callable[..., Curve]
    description: str


_SMOOTH = (
    SmoothReference(
        smooth_curves.CATENARY, SmoothQuery, smooth_curves.compute_catenary, CATENARY_DESCRIPTION
    ),
    SmoothReference(
        smooth_curves.TRACTRIX, SmoothQuery, smooth_curves.compute_tractrix, TRACTRIX_DESCRIPTION
    ),
)

SMOOTH: dict[str, SmoothReference] = {entry.info.id: entry for entry in _SMOOTH}


@dataclass(frozen=True)
class StatementEntry:
    """A statement and the discretizations (curve responses), studies or smooth references that
    check it."""

    statement: Statement
    discretizations: tuple[str, ...]
    studies: tuple[str, ...] = ()
    smooth: tuple[str, ...] = ()


def _statements() -> dict[str, StatementEntry]:
    found: dict[str, StatementEntry] = {}
    sources = [(e.info.id, e.info.statements, "discretizations") for e in _ENTRIES]
    sources += [(s.info.id, s.info.statements, "studies") for s in _STUDIES]
    sources += [(s.info.id, s.info.statements, "smooth") for s in _SMOOTH]
    for owner, statements, kind in sources:
        for statement in statements:
            known = found.get(statement.id) or StatementEntry(statement, ())
            if kind == "discretizations":
                known = replace(known, discretizations=(*known.discretizations, owner))
            elif kind == "studies":
                known = replace(known, studies=(*known.studies, owner))
            else:
                known = replace(known, smooth=(*known.smooth, owner))
            found[statement.id] = known
    # a property named after a discretization (d1, d3, ...) is checked on it by default
    return {
        key: replace(
            entry, discretizations=tuple(sorted(entry.discretizations, key=lambda o: o != key))
        )
        for key, entry in found.items()
    }


STATEMENTS: dict[str, StatementEntry] = _statements()
