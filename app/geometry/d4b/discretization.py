"""(D4b) Wunderlich's discrete hyperbolic cosine, with Theorems 4–8 checked on it.

The polygon comes from the construction (``construction``) by default, or from the closed forms
(``closed_forms``) with ``method="closed-form"``; the checks (``checks``) compare the two and test
the properties that Section 4.2 proves. The Gauss images of Section 5 and Theorems 7, 8 are built
and checked in ``curvature``. Every polygon is computed on demand (``D4bPolygons``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cached_property
from typing import Any, Literal

import numpy as np

from app.geometry import companion_kernels, darboux
from app.geometry.catalog.section3 import (
    D4B_DARBOUX as DARBOUX,
    D4B_DARBOUX_DISTANCE as DARBOUX_DISTANCE,
    D4B_NIKOLAIDES as NIKOLAIDES,
)
from app.geometry.catalog.section4 import (
    D4B_HYPOTHESIS as HYPOTHESIS,
    D4B_RECURSION_13 as RECURSION_13,
    D4B_ROTATION_ANGLE as ROTATION_ANGLE,
    D4B_THEOREM_4_I as THEOREM_4_I,
    D4B_THEOREM_4_II as THEOREM_4_II,
    D4B_THEOREM_4_III as THEOREM_4_III,
    D4B_THEOREM_5 as THEOREM_5,
    D4B_THEOREM_6 as THEOREM_6,
    D4B_TWO_STEP as TWO_STEP,
)
from app.geometry.checks import Check, Statement
from app.geometry.curve import EVERYTHING, Curve, DiscretizationInfo, Selection, require_range
from app.geometry.d4b import (
    closed_forms as kinematic_closed_forms,
    curvature as d4b_curvature,
)
from app.geometry.d4b.checks import conditioning, evaluate, tolerances
from app.geometry.d4b.construction import (
    KinematicTractrix,
    centre_rows,
    construct,
    from_sticks,
    initial_direction,
    stick_range,
    validate,
)
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points
from app.geometry.tolerances import (
    FLOAT64_COORDINATE_LIMIT,
    RESOLUTION_MARGIN,
    below_root_working_unit,
    exact,
    root_working_unit_text,
)

Method = Literal["construction", "closed-form"]


S = Statement

STATEMENTS: tuple[Statement, ...] = (
    HYPOTHESIS,
    THEOREM_4_I,
    THEOREM_4_II,
    THEOREM_4_III,
    ROTATION_ANGLE,
    RECURSION_13,
    TWO_STEP,
    THEOREM_5,
    THEOREM_6,
    DARBOUX,
    DARBOUX_DISTANCE,
    NIKOLAIDES,
    *d4b_curvature.STATEMENTS,
)

INFO = DiscretizationInfo(
    id="d4b",
    title="Wunderlich's kinematic discrete hyperbolic cosine (D4b)",
    reference="Section 3 (D4b); Section 4.2, Theorems 4-6; Section 5, Theorems 7, 8",
    summary=(
        "A stick of length h slides with one end along the x-axis in steps of 2d; each step is a "
        "rotation, and the rotation centres p_i form the discrete hyperbolic cosine. The other end "
        "of the stick traces the discrete tractrix d_i."
    ),
    default_range=(-10, 10),
    methods=("construction", "closed-form"),
    companions={
        "tractrix": "d_i, the free end of stick i (the discrete tractrix), same indices as p",
        "axis_points": "x_i = (2di, 0), the end of stick i on the x-axis",
        "darboux": "e_i = 2d_i − x_i, the reflection of x_i in d_i (a Darboux transform of x)",
        **d4b_curvature.COMPANIONS,
    },
    constants={
        "d1": "c of (D1), Δ²p_i^y = c(l_i + l_{i+1}); equals d/h",
        "d3": "c of (D3), A_i = c l_i; equals h",
        "eq2": "c of eq. (2), Δ²p_i^y = c(A_i + A_{i+1}); equals d/h²",
    },
    statements=STATEMENTS,
)


class D4bPolygons:
    """The polygons of one (D4b) computation, ``(n + 1, 2)`` each, on i_min .. i_max + 1.

    The extra last index only feeds checks (d_i needs p_{i+1}); responses show i_min .. i_max.
    ``p`` and ``tractrix`` come from the construction or, for ``method="closed-form"``, are the
    closed forms themselves (then ``constructed`` is false and Theorems 5, 6 are not compared).

    Every polygon is computed when it is first used, at most once: a request that asks for p
    alone runs the construction (or the closed form) and nothing else. ``replaced`` gives a copy
    with some polygons swapped (the tests perturb them to see the checks fail).
    """

    def __init__(
        self,
        ar: Arithmetic,
        h: float,
        d: float,
        beta0: float | None,
        i_min: int,
        i_max: int,
        method: Method = "construction",
    ) -> None:
        self.ar, self.beta0, self.i_min, self.i_max = ar, beta0, i_min, i_max
        self.parameters = (h, d)
        self.h, self.d = ar.scalar(h), ar.scalar(d)
        self.constructed: bool = method == "construction"

    def replaced(self, **polygons: Any) -> D4bPolygons:
        """A copy with the given polygons (``p=…``, ``gauss=…``) in place of the computed ones."""
        copy = object.__new__(D4bPolygons)
        copy.__dict__.update(self.__dict__)
        copy.__dict__.update(polygons)
        return copy

    @cached_property
    def shift(self) -> Scalar:
        """τ = ln(tan(β0/2))/L, the index shift of a tilted first stick (0 for a vertical one)."""
        return kinematic_closed_forms.tilt_shift(self.ar, self.h, self.d, self.beta0)

    @cached_property
    def _i(self) -> Array:
        return self.ar.indices(self.i_min, self.i_max + 1)

    @cached_property
    def _hull(self) -> tuple[int, KinematicTractrix]:
        """The construction on the hull of 0 and i_min − 1 .. i_max + 2 (it starts at stick 0
        anyway): the Gauss image n starts at index 0, and m_i needs p_{i−1} .. p_{i+1}."""
        lo, hi = min(0, self.i_min - 1), max(0, self.i_max + 2)
        with self.ar.recursion():  # on balls: with the digits its growing radii need
            return lo, construct(self.ar, *self.parameters, self.beta0, lo, hi)

    def _window(self, points: Array) -> Array:
        lo = self._hull[0]
        return points[self.i_min - lo : self.i_max + 2 - lo]

    @cached_property
    def _closed_balls(self) -> tuple[Array, Array] | None:
        """Theorems 5 and 6 together on balls, for the checks of a constructed polygon
        (``kinematic_balls``: one exponential per index); None otherwise."""
        if not self.constructed:
            return None  # served as the polygon: the two functions' balls
        return kinematic_closed_forms.kinematic_balls(self.ar, self.h, self.d, self._i, self.shift)

    @cached_property
    def closed_p(self) -> Array:
        """Theorem 5, eq. (14), at i_min .. i_max + 1."""
        if self._closed_balls is not None:
            return self._closed_balls[0]
        ar = self.ar
        return kinematic_closed_forms.hyperbolic_cosine(ar, self.h, self.d, self._i, self.shift)

    @cached_property
    def closed_tractrix(self) -> Array:
        """Theorem 6, eq. (16), at i_min .. i_max + 1."""
        if self._closed_balls is not None:
            return self._closed_balls[1]
        return kinematic_closed_forms.tractrix(self.ar, self.h, self.d, self._i, self.shift)

    @cached_property
    def p(self) -> Array:
        """The rotation centres p_i (the discrete hyperbolic cosine)."""
        return self._window(self._hull[1].centres) if self.constructed else self.closed_p

    @cached_property
    def tractrix(self) -> Array:
        """The stick ends d_i (the discrete tractrix)."""
        return self._window(self._hull[1].tractrix) if self.constructed else self.closed_tractrix

    @cached_property
    def axis(self) -> Array:
        """The axis points x_i = (2di, 0)."""
        if self.constructed:
            return self._window(self._hull[1].axis_points)
        return stack_points(2 * self.d * self._i, self.ar.zeros(len(self._i)))

    @cached_property
    def darboux(self) -> Array:
        """e_i = 2d_i − x_i, the Darboux transform of x."""
        return darboux.reflect_in_points(self.axis, self.tractrix)

    @cached_property
    def gauss(self) -> d4b_curvature.GaussImages:
        """Section 5: n_i, ñ_i, m_i (see ``d4b_curvature.GaussImages`` for their alignment)."""
        ar, h, d = self.ar, self.h, self.d
        if not self.constructed:
            return d4b_curvature.build(ar, h, d, self.shift, self.i_min, self.i_max)
        lo, built = self._hull

        def hull() -> tuple[Array, Array]:  # read only by an image not kept already
            return built.centres[self.i_min - 1 - lo : self.i_max + 3 - lo], built.directions

        images = d4b_curvature.build(
            ar, h, d, self.shift, self.i_min, self.i_max, lo, hull, self._centres_before(lo, built)
        )
        for name, points in self.__dict__.get("_images", {}).items():
            images.__dict__.setdefault(name, points)  # kept by ``compile_companions``
        return images

    def _centres_before(self, lo: int, built: KinematicTractrix) -> Array:
        """p_{i_min−1} and p_{i_min} ((2, 2)): in float64 two rows made from the recursion
        (``construction.centre_rows``: each row by the operations of the whole array, so the
        same bits) unless the hull's centres are there already."""
        if built.recursion is not None and "centres" not in vars(built):
            return centre_rows(built.recursion, self.i_min - 1, self.i_min)
        return built.centres[self.i_min - 1 - lo : self.i_min + 1 - lo]

    def compile_companions(self) -> None:
        """Float64 construction: the six companions (tractrix, axis points, Darboux transform,
        the three Gauss images) in one compiled pass over the recursion
        (``companion_kernels.d4b_companions``), kept as if each had been built on its own (the
        same bits); those built already stay. Nothing is kept when an edge of p has no length:
        the separate constructions then raise their domain error.

        Before the construction has run, it runs here too, with p, in the same compiled call
        (``companion_kernels.d4b_construction``): one dispatch for everything a default small
        request returns. The Gauss images are kept aside (``image``) until the checks read
        ``gauss``: a request without checks never builds its closed forms' table."""
        if not self.constructed or self.ar.mode != "float64":
            return
        if "_hull" in self.__dict__:
            recursion = self._hull[1].recursion
            if recursion is None:
                return
            h, d, cos_u, sin_u, centre_y, first = recursion
            axis, tractrix, darboux_, inscribed, contact, poles, positive = (
                companion_kernels.d4b_companions(
                    h, d, cos_u, sin_u, centre_y, first, self.i_min, self.i_max
                )
            )
            p = None
        else:
            h, d = float(self.parameters[0]), float(self.parameters[1])
            validate(h, d, self.beta0)
            hull_lo, hull_hi = min(0, self.i_min - 1), max(0, self.i_max + 2)
            lo, hi = stick_range(hull_lo, hull_hi)
            c0, s0 = initial_direction(self.ar, self.beta0)
            made = companion_kernels.d4b_construction(
                h, d, float(c0), float(s0), lo, hi, self.i_min, self.i_max
            )
            self.ar.check_time()  # as ``construct``: once, after the recursion
            sticks, points, centres, contact, poles, positive = made
            axis, tractrix, darboux_, inscribed = points
            p = centres[1:-1]
            built = from_sticks(h, d, hull_lo, hull_hi, lo, sticks)
            self.__dict__["_hull"] = (hull_lo, built)
        if not positive:
            return
        kept = self.__dict__
        if p is not None:
            kept.setdefault("p", p)
        for name, points in (("axis", axis), ("tractrix", tractrix), ("darboux", darboux_)):
            kept.setdefault(name, points)
        images = {"tractrix_gauss": inscribed, "contact": contact}
        images["gauss"] = poles
        if "gauss" in kept:  # built already: those it has stay
            for name, points in images.items():
                kept["gauss"].__dict__.setdefault(name, points)
        else:
            kept.setdefault("_images", images)

    def image(self, name: str) -> Array:
        """The Gauss image ``name`` (``tractrix_gauss``, ``contact``, ``gauss``): the one
        ``compile_companions`` kept aside while ``gauss`` is not built, else read off it."""
        if "gauss" not in self.__dict__:
            kept = self.__dict__.get("_images")
            if kept is not None:
                return kept[name]
        return getattr(self.gauss, name)

    @cached_property
    def exponent(self) -> float:
        """Largest |(i + τ)L| of the closed forms over i_min .. i_max + 1.

        Each closed-form vertex carries a relative error of about eps·exponent from rounding that
        argument; the comparisons with the construction allow for it, and so do the local checks
        when the polygons *are* the closed forms. |(i + τ)L| is largest at an end of the range.
        """
        ar = self.ar
        log_ratio = kinematic_closed_forms.log_ratio(ar, self.h, self.d)
        if ar.mode == "float64":  # the same two products and their larger, without arrays
            shift, L = float(self.shift), float(log_ratio)
            first = abs((self.i_min + shift) * L)
            last = abs((self.i_max + 1 + shift) * L)
            return first if (first >= last or first != first) else last  # NaN wins (np.max)
        ends = ar.array([self.i_min, self.i_max + 1])
        return ar.to_float(np.max(abs((ends + self.shift) * log_ratio)))

    @property
    def vertices(self) -> int:
        """n + 1: the rows of every polygon (i_min .. i_max + 1)."""
        return self.i_max - self.i_min + 2


def polygons(
    ar: Arithmetic,
    h: float,
    d: float,
    beta0: float | None,
    i_min: int,
    i_max: int,
    method: Method = "construction",
) -> D4bPolygons:
    """Construction (Section 3) and closed forms (14), (16) on i_min .. i_max + 1, on demand."""
    return D4bPolygons(ar, h, d, beta0, i_min, i_max, method)


def compute(
    ar: Arithmetic,
    h: float = 1.0,
    d: float = 0.1,
    beta0: float | None = None,
    i_min: int = -10,
    i_max: int = 10,
    method: Method = "construction",
    detail: bool = False,
    selection: Selection = EVERYTHING,
) -> Curve:
    """(D4b) on i_min .. i_max with its companions, constants and checks."""
    validate(h, d, beta0)
    require_range(i_min, i_max)
    _require_resolvable(ar, h, d)
    if ar.mode == "float64":
        _require_float64_representable(h, d, beta0, i_min, i_max)
    data = polygons(ar, h, d, beta0, i_min, i_max, method)
    wanted = [name for name in COMPANIONS if selection.wants_companion(name)]
    if ar.mode == "float64" and len(wanted) == len(COMPANIONS):
        data.compile_companions()  # all six in one compiled pass (the checks read them too)
    constants: dict[str, Scalar] = {}
    checks: list[Check] = []
    if not selection.no_checks:  # no check selected: no constant either (``evaluate``)
        constants, checks = evaluate(ar, h, d, data, detail, beta0, selection)
    local, construction, _ = tolerances(ar, h, d, data)
    parameters: dict[str, Any] = {
        "h": h,
        "d": d,
        "beta0": math.pi / 2 if beta0 is None else beta0,
        "i_min": i_min,
        "i_max": i_max,
        "method": method,
    }
    companions = {name: COMPANIONS[name](data) for name in wanted}
    gauss_tolerances = {}
    if any(name in companions for name in d4b_curvature.COMPANIONS):
        # what the tolerances read of the images is their class's (``conditioning``): the
        # images are not built for it when the companions were kept aside (``image``)
        images = vars(data).get("gauss", _NO_IMAGES)
        gauss_tolerances = d4b_curvature.companion_tolerances(ar, images, construction)
    return INFO.curve(
        ar,
        parameters,
        data.p,
        companions,
        constants=constants,
        checks=checks,
        local_tolerance=local,
        companion_tolerances=gauss_tolerances,
        selection=selection,
    )


#: Gauss images with no polygon: ``companion_tolerances`` reads only their ``conditioning``.
_NO_IMAGES = d4b_curvature.GaussImages(True, {})

#: How each companion of ``INFO`` is read off the polygons (computed only when selected).
COMPANIONS: dict[str, Callable[[D4bPolygons], Array]] = {
    "tractrix": lambda data: data.tractrix,
    "axis_points": lambda data: data.axis,
    "darboux": lambda data: data.darboux,
    "tractrix_gauss_image": lambda data: data.image("tractrix_gauss"),
    "contact_points": lambda data: data.image("contact")[1:],
    "gauss_image": lambda data: data.image("gauss"),
}


def _require_resolvable(ar: Arithmetic, h: float, d: float) -> None:
    """Refuse steps so small that Δ²p^y vanishes in the working precision."""
    if ar.mode == "float64":
        smallest = RESOLUTION_MARGIN * math.sqrt(ar.working_eps)
        unresolved, shown = d / h < smallest, f"{smallest:.2g}"
    else:  # exact: a float √(10^−(digits+guard)) is 0 from 314 digits on
        ratio = exact(d) / exact(h)
        unresolved = below_root_working_unit(ar, ratio, RESOLUTION_MARGIN)
        shown = root_working_unit_text(ar, RESOLUTION_MARGIN)
    if unresolved:
        more = "use precision=mp" if ar.mode == "float64" else "use more digits"
        raise NotRepresentableError(
            "d",
            f"d/h >= {shown} in {ar.mode} with {ar.digits} digits",
            d,
            f"d/h = {d / h:.3g}: the second differences of p^y are below the working "
            f"precision; {more}",
        )


def _require_float64_representable(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    """Refuse, before computing, ranges whose coordinates leave the float64 limits."""
    L = math.log1p(2 * d / (h - d))
    tan_half = 1.0 if beta0 is None else math.tan(beta0 / 2)
    if not 0 < tan_half < math.inf:  # β0 within a subnormal of 0
        raise NotRepresentableError(
            "beta0", "a first stick steep enough for float64", beta0, "use precision=mp"
        )
    tau = math.log(tan_half) / L
    budget = math.log(FLOAT64_COORDINATE_LIMIT) - max(0.0, math.log(h))
    largest = math.floor(budget / L - abs(tau) - 1.5)  # |i + 1 − ½ + τ|·L within the budget
    if largest < 0:
        raise NotRepresentableError(
            "beta0",
            "a first stick steep enough for float64",
            beta0,
            f"p_0^y would exceed {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
        )
    for name, value in (("i_max", i_max), ("i_min", i_min)):
        if abs(value) > largest:
            raise NotRepresentableError(
                name,
                f"|{name}| <= {largest} in float64",
                value,
                f"beyond it p_i^y exceeds {FLOAT64_COORDINATE_LIMIT:g}; use precision=mp",
            )


__all__ = [
    "INFO",
    "STATEMENTS",
    "D4bPolygons",
    "compute",
    "conditioning",
    "evaluate",
    "polygons",
    "tolerances",
]
