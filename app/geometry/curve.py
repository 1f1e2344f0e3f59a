"""What a discretization returns: its polygon, companion polygons, fitted constants and checks."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from app.geometry.checks import Check, Statement
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array, Scalar


@dataclass(frozen=True)
class Polyline:
    """Vertices ``(n, 2)`` with their paper indices ``(n,)``."""

    indices: np.ndarray[Any, np.dtype[np.int64]]
    vertices: Array
    description: str = ""


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
        companions: dict[str, Array] | None = None,
        **fields: Any,
    ) -> Curve:
        """This discretization's ``Curve`` on ``parameters["i_min"] .. parameters["i_max"]``.

        ``polygon`` and each companion are ``(m, 2)`` arrays starting at i_min (m may exceed the
        range: extra rows that fed the checks are cut); ``fields`` are further ``Curve`` fields.
        """
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
                name: Polyline(indices, points[:n], self.companions[name])
                for name, points in (companions or {}).items()
            },
            **fields,
        )


def require_range(i_min: int, i_max: int) -> None:
    """Raise ``DomainError`` unless i_min <= i_max."""
    if i_max < i_min:
        raise DomainError("i_max", "i_min <= i_max", i_max, f"i_min = {i_min}")
