"""Which discretizations the service offers: core module, request model and description.

Adding a discretization means adding one entry to ``_ENTRIES`` (a refinement study: one entry
to ``_STUDIES``); the routers, the catalogs, the statement catalog and the relations matrix read
everything else from here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

from app.geometry.catalog import CATALOG, SECTION_OF
from app.geometry.checks import Statement
from app.geometry.curve import ComputeCurve, Curve, DiscretizationInfo, DiscretizationModule
from app.geometry.d1 import discretization as d1
from app.geometry.d2a import hex as d2a_hex, quad as d2a_quad
from app.geometry.d2b import discretization as d2b
from app.geometry.d3 import discretization as d3
from app.geometry.d4a import discretization as d4a
from app.geometry.d4b import discretization as d4b
from app.geometry.smooth import references as smooth_curves
from app.geometry.studies import theorem_11 as catenoid_refinement, theorem_14, theorem_15, tractrix
from app.geometry.studies.common import Study, StudyInfo
from app.geometry.surfaces import rotational
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
    """One discretization as the API serves it: its core module, request model, description."""

    module: DiscretizationModule
    query: type[CurveQuery]
    description: str

    @property
    def info(self) -> DiscretizationInfo:
        return self.module.INFO

    @property
    def compute(self) -> ComputeCurve:
        return self.module.compute

    @cached_property
    def body(self) -> type[CurveQuery]:
        """The strict JSON-body model of ``query`` (POST)."""
        return strict_body(self.query)


_ENTRIES = (  # in the paper's order
    Discretization(d1, D1Query, D1_DESCRIPTION),
    Discretization(d2a_quad, D2aQuadQuery, D2A_QUAD_DESCRIPTION),
    Discretization(d2a_hex, D2aHexQuery, D2A_HEX_DESCRIPTION),
    Discretization(d2b, D2bQuery, D2B_DESCRIPTION),
    Discretization(d3, D3Query, D3_DESCRIPTION),
    Discretization(d4a, D4aQuery, D4A_DESCRIPTION),
    Discretization(d4b, D4bQuery, D4B_DESCRIPTION),
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
        theorem_14.THEOREM_14_INFO,
        TractrixStudyQuery,
        theorem_14.theorem_14,
        tractrix.mp_work,
        tractrix.work,
        THEOREM_14_DESCRIPTION,
    ),
    ConvergenceStudy(
        theorem_15.THEOREM_15_INFO,
        TractrixStudyQuery,
        theorem_15.theorem_15,
        tractrix.mp_work,
        tractrix.work,
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
    """A statement of the catalog and what checks it: discretizations (curve responses), refinement
    studies, smooth references and surfaces (mesh responses)."""

    statement: Statement
    section: str
    discretizations: tuple[str, ...] = ()
    studies: tuple[str, ...] = ()
    smooth: tuple[str, ...] = ()
    surfaces: tuple[str, ...] = ()


#: The surfaces (GET /surfaces/{id}) and the statements their meshes are checked for.
SURFACE_STATEMENTS: dict[str, tuple[Statement, ...]] = {
    "catenoid": rotational.STATEMENTS["minimal"],
    "catenoid-gauss-image": rotational.STATEMENTS["minimal"],
    "pseudosphere": rotational.STATEMENTS["constant-curvature"],
    "pseudosphere-gauss-image": rotational.STATEMENTS["constant-curvature"],
}


def _statements() -> dict[str, StatementEntry]:
    """Every statement of the catalog, in its order, with the sources that check it."""
    sources: dict[str, dict[str, list[str]]] = {
        key: {"discretizations": [], "studies": [], "smooth": [], "surfaces": []} for key in CATALOG
    }
    owners: list[tuple[str, str, tuple[Statement, ...]]] = [
        ("discretizations", e.info.id, e.info.statements) for e in _ENTRIES
    ]
    owners += [("studies", s.info.id, s.info.statements) for s in _STUDIES]
    owners += [("smooth", s.info.id, s.info.statements) for s in _SMOOTH]
    owners += [("surfaces", key, statements) for key, statements in SURFACE_STATEMENTS.items()]
    for kind, owner, statements in owners:
        for statement in statements:
            if CATALOG.get(statement.id) is not statement:
                raise ValueError(f"{owner} checks {statement.id!r}, which is not the catalog's")
            sources[statement.id][kind].append(owner)
    entries = {}
    for key, statement in CATALOG.items():
        found = sources[key]
        # a property named after a discretization (d1, d3, ...) is checked on it by default
        curves = tuple(sorted(found["discretizations"], key=lambda o: o != key))
        entries[key] = StatementEntry(
            statement,
            SECTION_OF[key],
            curves,
            tuple(found["studies"]),
            tuple(found["smooth"]),
            tuple(found["surfaces"]),
        )
    return entries


STATEMENTS: dict[str, StatementEntry] = _statements()
"""The catalog (``app.geometry.catalog``) joined with what checks each statement."""
