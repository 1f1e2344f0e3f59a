"""The smooth references as served: sampled catenary and tractrix, with (S4) checked on them.

The tractrix response carries its evolute computed from the tractrix's derivatives and checks
(S4) — the centres of curvature lie on the catenary h cosh(x/h) — together with the pursuit
property and the right angle of Nikolaides, on the sampled points (so the checks fail on
perturbed samples).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry import nikolaides
from app.geometry.catalog.section2 import (
    S4_EVOLUTE as EVOLUTE,
    S4_NIKOLAIDES as NIKOLAIDES,
    S4_PURSUIT as PURSUIT,
)
from app.geometry.checks import Check, Statement, check_residuals, point_distance
from app.geometry.curve import Curve, Polyline
from app.geometry.errors import NotRepresentableError
from app.geometry.polygon import magnitude
from app.geometry.precision import GUARD_DIGITS, Arithmetic, Array, stack_points
from app.geometry.smooth import curves as smooth
from app.geometry.tolerances import FLOAT64_COORDINATE_LIMIT, LOCAL_STEPS

#: In mp, cosh(x/h) is resolved to about |x/h| units of the working precision, which carries
#: GUARD_DIGITS more digits than requested: |x|/h up to 10^GUARD_DIGITS keeps the requested ones.
MP_ARGUMENT_LIMIT = 10.0**GUARD_DIGITS


STATEMENTS: tuple[Statement, ...] = (PURSUIT, EVOLUTE, NIKOLAIDES)


@dataclass(frozen=True)
class SmoothInfo:
    """Catalog facts of one smooth reference."""

    id: str
    title: str
    reference: str
    companions: dict[str, str]
    statements: tuple[Statement, ...]


CATENARY = SmoothInfo(
    id="catenary",
    title="Smooth catenary h·cosh(x/h)",
    reference="Section 2, (S1)-(S3)",
    companions={},
    statements=(),
)
TRACTRIX = SmoothInfo(
    id="tractrix",
    title="Smooth tractrix with stick h, and its evolute",
    reference="Section 2, (S4)",
    companions={
        "evolute": "q(x), the centre of curvature of the tractrix, from its derivatives",
        "catenary": "(x, h cosh(x/h)), what (S4) says the evolute is",
        "axis_points": "(x, 0), the leader on the x-axis",
    },
    statements=STATEMENTS,
)


@dataclass(frozen=True)
class TractrixSamples:
    """Tractrix samples with what the checks need, ``(n, 2)`` each."""

    x: Array
    tractrix: Array
    first: Array
    second: Array
    evolute: Array
    defined: np.ndarray[Any, np.dtype[np.bool_]]
    catenary: Array
    axis: Array


def tractrix_samples(
    ar: Arithmetic, h: float, x_min: float, x_max: float, count: int
) -> TractrixSamples:
    """The tractrix, its derivatives and evolute, and the catenary at the sample points."""
    smooth.validate(h, x_min, x_max, count)
    hh = ar.scalar(h)
    x = smooth.sample(ar, x_min, x_max, count)
    d = smooth.tractrix(ar, hh, x)
    first, second = smooth.tractrix_derivatives(ar, hh, x)
    evolute = smooth.centres_of_curvature(ar, d, first, second)
    return TractrixSamples(
        x=x,
        tractrix=d,
        first=first,
        second=second,
        evolute=evolute.centres,
        defined=evolute.defined,
        catenary=smooth.catenary(ar, hh, x),
        axis=stack_points(x, ar.zeros(len(x))),
    )


def evaluate(ar: Arithmetic, h: float, data: TractrixSamples, detail: bool = False) -> list[Check]:
    """The (S4) checks on the given samples."""
    tolerance = ar.tolerance(LOCAL_STEPS)
    indices = np.arange(len(data.x), dtype=np.int64)
    d, q, axis, first = data.tractrix, data.evolute, data.axis, data.first
    stick = axis - d
    distance = abs(point_distance(ar, d, axis) - ar.scalar(h)) / magnitude(d, axis)
    tangent_size = (abs(first[:, 0]) + abs(first[:, 1])) * magnitude(d, axis)
    tiny = ar.scalar(np.finfo(np.float64).tiny)
    along = abs(first[:, 0] * stick[:, 1] - first[:, 1] * stick[:, 0]) / np.where(
        tangent_size > tiny, tangent_size, tiny
    )
    defined = data.defined
    on = indices[defined]
    evolute = point_distance(ar, q[defined], data.catenary[defined]) / magnitude(
        q[defined], data.catenary[defined]
    )
    right = nikolaides.right_angle_residuals(d[defined], axis[defined], q[defined])
    skipped = None if bool(np.all(defined)) else "the cusp x = 0 is skipped (d'(0) = 0)"
    return [
        check_residuals(PURSUIT, ar, indices, np.maximum(distance, along), tolerance, detail),
        check_residuals(EVOLUTE, ar, on, evolute, tolerance, detail, note=skipped),
        check_residuals(NIKOLAIDES, ar, on, right, tolerance, detail, note=skipped),
    ]


def compute_catenary(
    ar: Arithmetic,
    h: float = 1.0,
    x_min: float = -3.0,
    x_max: float = 3.0,
    count: int = 121,
    detail: bool = False,
) -> Curve:
    """(S1): the catenary h cosh(x/h) sampled at ``count`` points of [x_min, x_max]."""
    smooth.validate(h, x_min, x_max, count)
    _require_representable(ar, h, x_min, x_max)
    x = smooth.sample(ar, x_min, x_max, count)
    return _curve(
        CATENARY, ar, h, x_min, x_max, count, smooth.catenary(ar, ar.scalar(h), x), {}, []
    )


def compute_tractrix(
    ar: Arithmetic,
    h: float = 1.0,
    x_min: float = -3.0,
    x_max: float = 3.0,
    count: int = 121,
    detail: bool = False,
) -> Curve:
    """(S4): the tractrix with stick h, its evolute and the catenary, with the (S4) checks."""
    smooth.validate(h, x_min, x_max, count)
    _require_representable(ar, h, x_min, x_max)
    data = tractrix_samples(ar, h, x_min, x_max, count)
    companions = {
        "evolute": data.evolute,
        "catenary": data.catenary,
        "axis_points": data.axis,
    }
    checks = evaluate(ar, h, data, detail)
    return _curve(TRACTRIX, ar, h, x_min, x_max, count, data.tractrix, companions, checks)


def _curve(
    info: SmoothInfo,
    ar: Arithmetic,
    h: float,
    x_min: float,
    x_max: float,
    count: int,
    points: Array,
    companions: dict[str, Array],
    checks: list[Check],
) -> Curve:
    indices = np.arange(count, dtype=np.int64)
    return Curve(
        id=info.id,
        title=info.title,
        reference=info.reference,
        parameters={"h": h, "x_min": x_min, "x_max": x_max, "count": count},
        arithmetic=ar,
        polygon=Polyline(indices, points),
        companions={
            name: Polyline(indices, value, info.companions[name])
            for name, value in companions.items()
        },
        checks=checks,
    )


def _require_representable(ar: Arithmetic, h: float, x_min: float, x_max: float) -> None:
    """Refuse sample ranges the precision cannot represent (float64) or resolve (mp)."""
    if ar.mode == "float64":
        budget = math.log(FLOAT64_COORDINATE_LIMIT) - math.log(h / 2)
        reason = f"beyond it h·cosh(x/h) exceeds {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp"
        mode = "in float64"
    else:
        budget = MP_ARGUMENT_LIMIT
        reason = "beyond it cosh(x/h) is not resolved to the requested digits"
        mode = "in precision=mp"
    for name, value in (("x_max", x_max), ("x_min", x_min)):
        if abs(value) / h > budget:
            raise NotRepresentableError(name, f"|{name}|/h <= {budget:.6g} {mode}", value, reason)
