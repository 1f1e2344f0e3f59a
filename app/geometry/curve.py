"""What a discretization returns: its polygon, companion polygons, fitted constants and checks."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any, Protocol

import numpy as np

from app.geometry.checks import Check, Statement
from app.geometry.errors import DomainError
from app.geometry.on_demand import C, Constants, Evaluators
from app.geometry.precision import Arithmetic, Array, Scalar


@dataclass(frozen=True)
class Polyline:
    """Vertices ``(n, 2)`` with their paper indices ``(n,)``."""

    indices: np.ndarray[Any, np.dtype[np.int64]]
    vertices: Array
    description: str = ""

    def __init__(
        self, indices: np.ndarray[Any, np.dtype[np.int64]], vertices: Array, description: str = ""
    ) -> None:
        # written out as ``Check.__init__`` is: the generated one of a frozen dataclass sets
        # each field through object.__setattr__, and a D4b answer makes seven polylines
        fields = self.__dict__
        fields["indices"], fields["vertices"], fields["description"] = (
            indices,
            vertices,
            description,
        )


@dataclass(frozen=True)
class Curve:
    """One discrete hyperbolic cosine (``polygon``) with everything computed alongside it."""

    id: str
    title: str
    reference: str
    parameters: dict[str, Any]
    """The effective parameters (defaults filled in), as plain numbers."""
    arithmetic: Arithmetic
    polygon: Polyline
    companions: dict[str, Polyline] = field(default_factory=dict)
    constants: dict[str, Scalar] = field(default_factory=dict)
    checks: list[Check] = field(default_factory=list)
    local_tolerance: float | None = None
    """Tolerance of a condition on a few neighbouring vertices of this polygon, such as (D1) or
    eq. (2); ``None`` means ``arithmetic.tolerance(16)``. Discretizations whose vertices carry
    more rounding (D2a: conditioning 1/gap) set it; ``relations`` uses it."""
    companion_tolerances: dict[str, float] = field(default_factory=dict)
    """Gauss image companion name -> tolerance of a face-wise curvature statement (H = 0, K
    constant) on the surface it pairs with, where that is larger than ``local_tolerance``: a
    Gauss image built by a long recursion (D4b's inscribed n) or paired with a long
    construction carries that rounding. ``relations`` uses it."""

    def selected(self, selection: Selection) -> Curve:
        """This curve with only the companions and checks of ``selection``."""
        return replace(
            self,
            companions={k: v for k, v in self.companions.items() if selection.wants_companion(k)},
            checks=selection.keep(self.checks),
        )


@dataclass(frozen=True)
class Selection:
    """What a request asks for: which checks (statement ids) and which companions.

    ``None`` means all of them. A discretization computes a companion or a check only when it is
    selected (or when a selected one needs it: ``app.geometry.on_demand``), and reports the
    constants that come with the selected checks (a fitted constant with the statement it fits,
    a closed form's constant with the statements that use it; none for ``checks=none``);
    ``failed_only`` keeps, of the checks computed, those whose verdict is ``holds: false``.
    """

    checks: frozenset[str] | None = None
    companions: frozenset[str] | None = None
    failed_only: bool = False

    def wants_check(self, statement_id: str) -> bool:
        """Whether the check of ``statement_id`` is asked for."""
        return self.checks is None or statement_id in self.checks

    def wants_companion(self, name: str) -> bool:
        """Whether the companion ``name`` is asked for."""
        return self.companions is None or name in self.companions

    @property
    def no_checks(self) -> bool:
        """Whether no check at all is asked for."""
        return self.checks is not None and not self.checks

    def keep(self, checks: list[Check]) -> list[Check]:
        """The selected checks of ``checks``, in their order."""
        kept = [c for c in checks if self.wants_check(c.id)]
        return [c for c in kept if c.holds is False] if self.failed_only else kept

    def evaluate(self, context: C, evaluators: Evaluators[C]) -> list[Check]:
        """The checks of the selected statements, each evaluator run on ``context``.

        ``evaluators`` pairs each statement with the function that checks it, in the order of the
        response; an evaluator reads the shared quantities it needs from the context
        (``OnDemand``), so what no selected statement reads is never computed.
        """
        return [
            evaluate(context)
            for statement, evaluate in evaluators
            if self.wants_check(statement.id)
        ]

    def constants(self, context: C, constants: Constants[C]) -> dict[str, Scalar]:
        """The constants that come with the selected statements, each read from ``context``.

        ``constants`` names each constant, the statements it comes with and how it is read (the
        same shared quantity a check of those statements reads); an undetermined one (``None``)
        is left out.
        """
        found: dict[str, Scalar] = {}
        for name, statements, read in constants:
            if any(self.wants_check(statement.id) for statement in statements):
                value = read(context)
                if value is not None:
                    found[name] = value
        return found


EVERYTHING = Selection()
"""Every check and every companion (the default of every endpoint)."""

NOTHING = Selection(frozenset(), frozenset())
"""The polygon alone (``format=npy``, ``checks=none&companions=none``)."""


@dataclass(frozen=True)
class DiscretizationInfo:
    """Catalog facts of one discretization that the core knows (the API adds parameters)."""

    id: str
    title: str
    reference: str
    summary: str
    default_range: tuple[int, int]
    methods: tuple[str, ...]
    companions: dict[str, str]
    """Companion name -> what it is."""
    constants: dict[str, str]
    """Constant name -> what it is."""
    statements: tuple[Statement, ...]

    def curve(
        self,
        ar: Arithmetic,
        parameters: dict[str, Any],
        polygon: Array,
        companions: Mapping[str, Array | Callable[[], Array]] | None = None,
        selection: Selection = EVERYTHING,
        **fields: Any,
    ) -> Curve:
        """This discretization's ``Curve`` on ``parameters["i_min"] .. parameters["i_max"]``.

        ``polygon`` and each companion are ``(m, 2)`` arrays starting at i_min (m may exceed the
        range: extra rows that fed the checks are cut), a companion possibly as a function that
        computes it; ``fields`` are further ``Curve`` fields. Companions and checks outside
        ``selection`` are left out (a companion given as a function is then not computed).
        """
        if "checks" in fields:
            fields["checks"] = selection.keep(fields["checks"])
        indices = np.arange(parameters["i_min"], parameters["i_max"] + 1, dtype=np.int64)
        n = len(indices)
        return Curve(
            id=self.id,
            title=self.title,
            reference=self.reference,
            parameters=parameters,
            arithmetic=ar,
            polygon=Polyline(indices, polygon[:n]),
            companions={
                name: Polyline(
                    indices, (points() if callable(points) else points)[:n], self.companions[name]
                )
                for name, points in (companions or {}).items()
                if selection.wants_companion(name)
            },
            **fields,
        )


def require_range(i_min: int, i_max: int) -> None:
    """Raise ``DomainError`` unless i_min <= i_max."""
    if i_max < i_min:
        raise DomainError("i_max", "i_min <= i_max", i_max, f"i_min = {i_min}")


class ComputeCurve(Protocol):
    """What a discretization's ``compute`` is: ``compute(ar, <the paper's parameters>, i_min,
    i_max, …, detail=False, selection=EVERYTHING) -> Curve``.

    The paper's parameters differ from one discretization to the next (the request model of
    each, ``app/schemas/<id>.py``, has a field for each of them; tests/api/test_catalog.py
    checks that the two agree), so only the arithmetic and the result are typed here.
    """

    def __call__(self, ar: Arithmetic, /, *args: Any, **parameters: Any) -> Curve: ...


class DiscretizationModule(Protocol):
    """What each discretization's ``discretization`` module provides (``app.geometry.<id>``)."""

    INFO: DiscretizationInfo
    """Catalog facts: id, title, reference, companions, constants, statements."""

    @property
    def compute(self) -> ComputeCurve:
        """The curve on a range from the definition, its companions and checks."""
        ...
