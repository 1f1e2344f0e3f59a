"""Section 5 on (D4b): the Gauss images (18)–(20) and Theorems 7 and 8, built and checked.

The Gauss images come from their geometric descriptions (``gauss_image``); the printed closed
forms (``kinematic_closed_forms``) are compared with them, and the printed versions that are wrong
carry an erratum (E60–E63 in docs/errata.md):

- n_i, the pseudosphere's Gauss image: inscribed in the unit circle, edges parallel to the
  tractrix edges d_i d_{i+1}, starting at the unit normal of stick 0 ((1, 0) for a vertical
  stick, the choice n_0 = (±1, 0) of the paper with the + sign);
- ñ_i, the contact points: unit normals of the edges p_i p_{i+1} on the side away from the axis;
- m_i, the catenoid's Gauss image: the pole of the chord ñ_{i−1} ñ_i.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from functools import cached_property
from typing import Any, ClassVar

import flint
import numpy as np

from app.geometry import gauss_image
from app.geometry.ball_arithmetic import RESIDUAL_BITS
from app.geometry.catalog.section5 import (
    D4B_EQUATION_18 as EQUATION_18,
    D4B_EQUATION_18_SLOPE as EQUATION_18_SLOPE,
    D4B_EQUATION_19 as EQUATION_19,
    D4B_EQUATION_19_ROTATION as EQUATION_19_ROTATION,
    D4B_EQUATION_20 as EQUATION_20,
    D4B_EQUATION_20_INVERSION as EQUATION_20_INVERSION,
    D4B_THEOREM_7 as THEOREM_7,
    D4B_THEOREM_8 as THEOREM_8,
    RING_EQUATION_17 as EQUATION_17,
)
from app.geometry.checks import (
    Check,
    Erratum,
    Indices,
    Largest,
    Statement,
    check_residuals,
    not_applicable,
    printed_residual,
)
from app.geometry.d4b import (
    arb_gauss,
    closed_forms as kinematic_closed_forms,
    fused_checks,
    residual_kernels,
)
from app.geometry.d4b.fused_checks import CLOSED_IMAGES, IMAGE_COMPARISONS
from app.geometry.d4b.residual_kernels import point_distance, relative_point_difference
from app.geometry.polygon import magnitude
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points
from app.geometry.surfaces.ring_curvature import (
    constant_curvature_residuals,
    equation_17_check,
    equation_17_result,
    minimal_residuals,
    ring_checks,
    ring_curvatures,
    ring_largest,
    ring_rotation,
)

S = Statement

STATEMENTS: tuple[Statement, ...] = (
    EQUATION_17,
    EQUATION_18,
    EQUATION_18_SLOPE,
    EQUATION_19,
    EQUATION_19_ROTATION,
    EQUATION_20_INVERSION,
    EQUATION_20,
    THEOREM_7,
    THEOREM_8,
)

COMPANIONS = {
    "tractrix_gauss_image": "n_i, the Gauss image meridian of the pseudosphere (Theorem 7, eq. "
    "(18)): inscribed in the unit circle, edges parallel to the tractrix, n_0 = (1, 0)",
    "contact_points": "ñ_i, where the edge m_i m_{i+1} touches the unit circle: the unit normal "
    "of the edge p_i p_{i+1} (eq. (19))",
    "gauss_image": "m_i, the Gauss image meridian of the catenoid (Theorem 8, eq. (20)): edges "
    "parallel to p and tangent to the unit circle, m_i the pole of the chord ñ_{i−1} ñ_i",
}

ERRATUM_18 = (
    "E60",
    "n_i = (2(h−d)^i(h+d)^i, (h−d)^{2i} − (h+d)^{2i}) / ((h−d)^{2i} + (h+d)^{2i})",
    "n_i = (2(h−d)^i(h+d)^i, (h+d)^{2i} − (h−d)^{2i}) / ((h−d)^{2i} + (h+d)^{2i}) = "
    "(sech iL, tanh iL)",
)
ERRATUM_18_SLOPE = (
    "E61",
    "n_i = (√(1/(1 + k_{i+1}²)), √(k_{i+1}²/(1 + k_{i+1}²)))",
    "n_i = (1, k_{i+1})/√(1 + k_{i+1}²): the second component has the sign of k_{i+1}",
)
ERRATUM_19 = (
    "E62",
    "ñ_i = ((h+d)^{2i} − (h−d)^{2i}, 2(h−d)^i(h+d)^i) / ((h−d)^{2i} + (h+d)^{2i})",
    "ñ_i = ((h−d)^{2i} − (h+d)^{2i}, 2(h−d)^i(h+d)^i) / ((h−d)^{2i} + (h+d)^{2i}) = "
    "(−tanh iL, sech iL)",
)
ERRATUM_20 = (
    "E63",
    "m_i = 1/(dA + hB) · ((hA − dB) / 2h(h²−d²)^i) (read as the vector (hA − dB, "
    "2h(h²−d²)^i)/(dA + hB))",
    "m_i = (dB − hA, 2h(h²−d²)^i)/(hB − dA) = (−tanh((i−½)L), h/p_i^y)",
)


class GaussImages:
    """The three polygons of Section 5 for one (D4b) computation, with their closed forms.

    ``tractrix_gauss`` and ``gauss`` are aligned with ``D4bPolygons.p`` (i_min .. i_max + 1);
    ``contact`` starts one index earlier (i_min − 1 .. i_max + 1), since m_i needs ñ_{i−1}.
    Each of the six polygons is computed when first read (``build`` says how), so that a
    companion or a check computes the images and closed forms it uses and no others.
    """

    ball_table: tuple[_BallHyperbolic, int] | None = None
    """Balls, constructed images: the hyperbolic table the closed forms are read from and the
    first index of n (i_min), for comparing n and ñ with their closed forms straight from it."""

    conditioning: float = 1.0
    """Step count of n's tolerance beyond the construction's: 1, since n is read from the stick
    directions (``build``) instead of accumulated from edge angles."""

    def __init__(
        self,
        constructed: bool,
        parts: dict[str, Callable[[GaussImages], Array]],
        contact_edges_before: Array | None = None,
    ) -> None:
        self.constructed = constructed
        self._parts = parts
        self.contact_edges_before = contact_edges_before
        """p_{i_min−1} and p_{i_min}: the edge before the range, which m_{i_min} also uses."""

    def replaced(self, **polygons: Array) -> GaussImages:
        """A copy with some of the six polygons given (the tests perturb them)."""
        unknown = set(polygons) - {*self._parts}
        if unknown:
            raise TypeError(f"no polygon named {sorted(unknown)}")
        copy = GaussImages(self.constructed, self._parts, self.contact_edges_before)
        copy.ball_table = self.ball_table
        copy.__dict__.update(polygons)
        return copy

    @cached_property
    def tractrix_gauss(self) -> Array:
        """n_i, inscribed (Theorem 7, (18))."""
        return self._parts["tractrix_gauss"](self)

    @cached_property
    def contact(self) -> Array:
        """ñ_i, the contact points ((19))."""
        return self._parts["contact"](self)

    @cached_property
    def gauss(self) -> Array:
        """m_i, circumscribed (Theorem 8, (20))."""
        return self._parts["gauss"](self)

    @cached_property
    def closed_tractrix_gauss(self) -> Array:
        """(18) corrected, closed form."""
        return self._parts["closed_tractrix_gauss"](self)

    @cached_property
    def closed_contact(self) -> Array:
        """(19) corrected, closed form."""
        return self._parts["closed_contact"](self)

    @cached_property
    def closed_gauss(self) -> Array:
        """(20) corrected, closed form."""
        return self._parts["closed_gauss"](self)


def build(
    ar: Arithmetic,
    h: Scalar,
    d: Scalar,
    shift: Scalar,
    i_min: int,
    i_max: int,
    hull_start: int = 0,
    hull: Callable[[], tuple[Array, Array]] | None = None,
    before: Array | None = None,
) -> GaussImages:
    """The Gauss images on i_min .. i_max + 1 (``contact`` from i_min − 1), each made when read.

    With a construction, ``hull()`` gives (p on i_min − 1 .. i_max + 2, the unit stick
    directions u on hull_start .., covering 0 and the range), called only when an image is
    built from them (not when ``compile_companions`` kept the images: no (n, 2) array of the
    hull is made then), and ``before`` is p_{i_min−1}, p_{i_min} ((2, 2)). Without
    (method=closed-form) the closed forms are used.
    """
    closed: dict[str, Callable[[GaussImages], Array]]
    if ar.certified:  # balls: from one exponential per index (``_BallHyperbolic``)
        table = _ball_hyperbolic(ar, h, d, shift, i_min - 1, i_max + 1)
        closed = {
            "closed_tractrix_gauss": lambda _: table.tractrix_gauss_image(i_min, i_max + 1),
            "closed_gauss": lambda _: table.circumscribed_gauss_image(i_min, i_max + 1),
            "closed_contact": lambda _: table.contact_points(i_min - 1, i_max + 1),
        }
    else:  # (on balls the indices' balls are not made: the table has its own)
        # the indices made when a closed form is (a float64 computation of 10^6 vertices that
        # compares in blocks, ``fused_checks``, never reads them: 8 MB not made)
        def shown() -> Array:
            return ar.indices(i_min, i_max + 1)

        closed = {
            "closed_tractrix_gauss": lambda _: kinematic_closed_forms.tractrix_gauss_image(
                ar, h, d, shown(), shift
            ),
            "closed_gauss": lambda _: kinematic_closed_forms.circumscribed_gauss_image(
                ar, h, d, shown(), shift
            ),
            "closed_contact": lambda _: kinematic_closed_forms.contact_points(
                ar, h, d, ar.indices(i_min - 1, i_max + 1), shift
            ),
        }
    if ar.mode == "float64" and _cosh_finite(ar, h, d, shift, i_min - 1, i_max + 1):
        # n_i = (sech t, tanh t) and ñ_i = (−tanh t, sech t) at the same t = (i + τ)L: n read
        # off ñ on i_min .. i_max + 1 (the same numbers: the same t, and cosh finite on both, so
        # ``amplitude_sech`` takes its direct form on both), one tanh and cosh pass fewer
        closed["closed_tractrix_gauss"] = lambda images: _turned(images.closed_contact[1:])
    if hull is None or before is None:
        before = kinematic_closed_forms.hyperbolic_cosine(
            ar, h, d, ar.indices(i_min - 1, i_min), shift
        )
        return GaussImages(
            False,
            {
                **closed,
                "tractrix_gauss": lambda images: images.closed_tractrix_gauss,
                "contact": lambda images: images.closed_contact,
                "gauss": lambda images: images.closed_gauss,
            },
            before,
        )
    # n is inscribed with edges parallel to the tractrix's and n_0 = J u_0, the unit normal of
    # stick 0 (J(x, y) = (y, −x)). Its exact form is n_i = J u_i for every i: the rotation R
    # about p_{i+1} takes u_i to u_{i+1} and d_i to d_{i+1}, and d_i − p_{i+1} = λ J u_i (p_{i+1}
    # is on the normal of stick i at d_i), so d_{i+1} − d_i = λ J (u_{i+1} − u_i) (R commutes
    # with J): the chords n_i n_{i+1} are parallel to the tractrix edges, as (18) asks. Read from
    # the construction's stick directions, n carries their rounding only, where accumulating the
    # edge angles (gauss_image.inscribed_parallel) drifted to 1e-11 over 12001 vertices.
    window = slice(i_min - hull_start, i_max + 1 - hull_start + 1)

    def normals(_: GaussImages) -> Array:
        directions = hull()[1]
        return stack_points(directions[window, 1], -directions[window, 0])

    constructed = GaussImages(
        True,
        {
            **closed,
            "tractrix_gauss": normals,
            "contact": lambda _: _contact_points(ar, hull()[0]),
            "gauss": (
                # balls: the tangents at ñ_{i−1}, ñ_i intersected algebraically (``_poles``)
                (lambda images: _poles(images.contact))
                if ar.certified
                else (lambda _: gauss_image.circumscribed(ar, hull()[0]))
            ),
        },
        before,
    )
    if ar.certified:
        constructed.ball_table = (table, i_min)
    return constructed


def _cosh_finite(ar: Arithmetic, h: Scalar, d: Scalar, shift: Scalar, lo: int, hi: int) -> bool:
    """Float64: whether cosh((i + τ)L) is far from overflowing for every i in lo .. hi (|t| is
    largest at an end; 700 < ln(max float) ≈ 709.8)."""
    L = float(kinematic_closed_forms.log_ratio(ar, h, d))
    return all(abs((i + float(shift)) * L) <= 700 for i in (lo, hi))


def _turned(contact: Array) -> Array:
    """(sech t, tanh t) from rows (−tanh t, sech t): each row turned back by a quarter."""
    return stack_points(contact[:, 1], -contact[:, 0])


def companion_tolerances(
    ar: Arithmetic, images: GaussImages, construction_tolerance: float
) -> dict[str, float]:
    """Tolerances of face-wise statements on the two Gauss images (Theorems 7 and 8).

    n accumulates the rounding of every tractrix edge direction it was built from (see
    ``GaussImages.conditioning``); m is built locally from p, whose vertices come from the whole
    construction.
    """
    return {
        "tractrix_gauss_image": max(
            construction_tolerance, ar.tolerance(math.ceil(images.conditioning))
        ),
        "gauss_image": construction_tolerance,
    }


class PrintedForms:
    """The printed (18), (19), (20) on i_min .. i_max (for the errata's printed residuals), by
    ``"18"``, ``"19"``, ``"20"``, each computed when asked for; in float64 ``largest`` reads
    them off the corrected closed forms instead (the same numbers, ``residual_kernels``)."""

    FORMS: ClassVar[dict[str, Callable[..., Array]]] = {
        "18": kinematic_closed_forms.tractrix_gauss_image_printed,
        "19": kinematic_closed_forms.contact_points_printed,
        "20": kinematic_closed_forms.circumscribed_gauss_image_printed,
    }

    def __init__(
        self, ar: Arithmetic, h: Scalar, d: Scalar, shift: Scalar, i_min: int, i_max: int
    ) -> None:
        self.ar, self.h, self.d, self.shift, self.i_min, self.i_max = ar, h, d, shift, i_min, i_max

    def __call__(self, key: str) -> Array:
        ar = self.ar
        if ar.certified:  # balls: from one exponential per index (``_BallHyperbolic``)
            table = _ball_hyperbolic(ar, self.h, self.d, self.shift, self.i_min, self.i_max)
            return table.printed(key, self.i_min, self.i_max)
        return self.FORMS[key](ar, self.h, self.d, ar.indices(self.i_min, self.i_max), self.shift)

    def largest(self, key: str, built: Array, images: GaussImages) -> float | None:
        """Float64: the printed residual of form ``key`` against ``built`` (rows from i_min),
        from the closed forms of ``images`` (n_i for (18), (20); ñ_i for (19)) in one pass."""
        closed = images.closed_contact[1:] if key == "19" else images.closed_tractrix_gauss
        count = len(built)
        return residual_kernels.largest_printed_gauss_difference(
            int(key), built, closed[:count], self.h, self.d
        )


#: From this many faces a float64 computation that needs both rings (Theorems 7 and 8, or
#: (17)) computes them on two threads (≈ 45 ms each at 10^6 faces here; a thread costs ≈ 0.1 ms).
RINGS_THREADED_FROM = 100_000


def _both_rings(wanted: Callable[[str], bool]) -> bool:
    """Whether the selected statements read both rings: Theorem 7 the pseudosphere's, Theorem 8
    the catenoid's, (17) both."""
    if wanted(EQUATION_17.id):
        return True
    return wanted(THEOREM_7.id) and wanted(THEOREM_8.id)


def printed_forms(
    ar: Arithmetic, h: Scalar, d: Scalar, shift: Scalar, i_min: int, i_max: int
) -> PrintedForms:
    """The printed (18), (19), (20) on i_min .. i_max (``PrintedForms``)."""
    return PrintedForms(ar, h, d, shift, i_min, i_max)


def evaluate(
    ar: Arithmetic,
    h: Scalar,
    p: Array,
    tractrix: Array,
    images: GaussImages,
    printed: Callable[[str], Array],
    indices: Indices,
    n: int,
    local_tolerance: float,
    construction_tolerance: float,
    detail: bool,
    wanted: Callable[[str], bool] = lambda statement_id: True,
) -> list[Check]:
    """The checks of ``STATEMENTS`` that are ``wanted`` (by id) on the given polygons (aligned
    as in ``GaussImages``), each computing only the images and shared quantities it uses.

    ``n`` is the number of indices shown (i_min .. i_max); the face-wise checks use the faces
    i_min .. i_max (edges to i + 1); ``printed`` gives the printed forms ``"18"``, ``"19"``,
    ``"20"`` (``printed_forms``).
    """

    def nt() -> Array:
        return images.tractrix_gauss

    def c() -> Array:
        return images.contact

    def m() -> Array:
        return images.gauss

    shown = indices[:n]
    n_tolerance = companion_tolerances(ar, images, construction_tolerance)["tractrix_gauss_image"]

    def check(
        statement: Statement,
        residuals: Array | Largest,
        tolerance: float,
        erratum: Erratum | None = None,
    ) -> Check:
        return check_residuals(
            statement, ar, shown[: len(residuals)], residuals, tolerance, detail, erratum
        )

    def closed(
        statement: Statement,
        built: Array,
        closed_form: Callable[[], Array],
        make_erratum: Callable[[], Erratum],
        tolerance: float = construction_tolerance,
        make_scale: Callable[[], Any] | None = None,
    ) -> Check:
        if not images.constructed:  # neither the erratum nor the scale is read
            return not_applicable(
                statement,
                tolerance,
                "method=closed-form: the Gauss image was not constructed to compare",
            )
        erratum = make_erratum()
        fused = image_comparisons()
        if fused is not None:  # made and compared a block at a time (``image_comparisons``)
            largest = fused[IMAGE_COMPARISONS.index(statement.id.removeprefix("equation-"))]

            def rows() -> Array:  # per index only when shown: the scales' array made then
                factor = None if make_scale is None else make_scale()[:n]
                return residual_kernels.largest_scaled_relative_point_difference(
                    built[:n], closed_form()[:n], factor
                ).residuals()

            return check(statement, Largest(largest, n, rows), tolerance, erratum)
        scale = None if make_scale is None else make_scale()
        pair = ball_pair(statement.id.removeprefix("equation-"))
        if pair is not None:  # balls: with the printed form, from the table (``ball_pair``)
            return check(statement, pair[0], tolerance, erratum)
        formula = closed_form()
        residuals: Array | Largest
        if ar.mode == "float64" and not detail:  # the largest alone, in one pass, no array
            residuals = residual_kernels.largest_scaled_relative_point_difference(
                built[:n], formula[:n], None if scale is None else scale[:n]
            )
        elif scale is not None and ar.mode == "float64":  # the same product, in one pass
            residuals = residual_kernels.scaled_relative_point_difference(
                built[:n], formula[:n], scale[:n]
            )
        else:
            factor = None if scale is None else scale[:n]
            residuals = _relative(ar, built[:n], formula[:n], factor, reduce=not detail)
        return check(statement, residuals, tolerance, erratum)

    def printed_erratum(entry: tuple[str, str, str], built: Array, key: str) -> Erratum:
        fused = image_comparisons()
        if fused is not None:  # made and compared a block at a time (``image_comparisons``)
            found = fused[IMAGE_COMPARISONS.index(f"{key} printed")]
            return Erratum(*entry, printed_residual=found if math.isfinite(found) else None)
        if ar.mode == "float64" and isinstance(printed, PrintedForms):  # one pass, no arrays
            return Erratum(*entry, printed_residual=printed.largest(key, built[:n], images))
        pair = ball_pair(key)
        if pair is not None:  # balls: with the corrected form, from the table (``ball_pair``)
            return Erratum(*entry, printed_residual=printed_residual(ar, pair[1]))
        formula = printed(key)
        if ar.mode == "float64":  # the largest alone, in one pass
            worst = residual_kernels.largest_relative_point_difference(built[:n], formula[:n])
            return Erratum(*entry, printed_residual=worst)
        residuals = _relative(ar, built[:n], formula[:n], reduce=True)  # the largest alone
        return Erratum(*entry, printed_residual=printed_residual(ar, residuals))

    memo: dict[str, Any] = {}

    def shared(name: str, make: Callable[[], Any]) -> Any:
        """A quantity several checks use, computed when the first of them runs."""
        if name not in memo:
            memo[name] = make()
        return memo[name]

    def numbers() -> fused_checks.ImageNumbers | None:
        """Float64 without ``detail``, constructed images, every statement selected and n
        below ``fused_checks.SECTION_BELOW``: the resolutions, (18) by slopes, (19) as a
        rotation, (20) by inversion and both rings from one compiled call (the same bits as
        each pass; ``fused_checks.image_numbers``), else None (each calls its own)."""

        def make() -> fused_checks.ImageNumbers | None:
            if ar.mode != "float64" or detail or not images.constructed:
                return None
            if not 4 <= n < fused_checks.SECTION_BELOW or images.contact_edges_before is None:
                return None
            if not all(wanted(statement.id) for statement in STATEMENTS):
                return None
            return fused_checks.image_numbers(
                p,
                tractrix,
                nt(),
                c(),
                m(),
                images.contact_edges_before,
                n,
                ring_rotation(ar),
                -1 / (h * h),
            )

        return shared("numbers", make)

    def rings(pseudosphere: bool) -> tuple[Any, Any, int] | None:
        """The ring's theorem and (17) residuals in one pass (``ring_checks``, float64 and
        balls); in float64 their largest values alone (``ring_largest``) when no residual is
        shown per index."""
        exact = not detail and len(tractrix) == len(p) == n + 1  # n faces each
        if ar.certified:  # the residual balls per face in one compiled pass (``arb_rings``)
            # without detail the theorem's reduced to what its check reads, no ball per face
            if pseudosphere:
                k = -1 / (h * h)
                return shared("pseudo", lambda: ring_checks(ar, tractrix, nt(), k, exact))
            return shared("catenoid", lambda: ring_checks(ar, p, m(), None, exact))
        fused: Callable[..., Any] = ring_largest if exact else ring_checks
        if exact and (found := numbers()) is not None:  # the pass's numbers from the one call
            fused = functools.partial(ring_largest, found=found.ring(pseudosphere))
        if pseudosphere:
            return shared("pseudo", lambda: fused(ar, tractrix, nt(), -1 / (h * h)))
        return shared("catenoid", lambda: fused(ar, p, m(), None))

    if ar.mode == "float64" and n >= RINGS_THREADED_FROM and _both_rings(wanted):
        # both rings at once: the pseudosphere's on a second thread (the compiled pass releases
        # the GIL), the catenoid's here; the images are made here first (not thread-safe)
        pseudo_gauss, catenoid_gauss = nt(), m()
        exact = not detail and len(tractrix) == len(p) == n + 1
        fused: Callable[..., Any] = ring_largest if exact else ring_checks
        with ThreadPoolExecutor(max_workers=1, thread_name_prefix="ring") as pool:
            pending = pool.submit(fused, ar, tractrix, pseudo_gauss, -1 / (h * h))
            memo["catenoid"] = fused(ar, p, catenoid_gauss, None)
            memo["pseudo"] = pending.result()

    def curvatures(pseudosphere: bool) -> Any:
        """The ring's curvatures, numpy (mp, or a face without area to name)."""
        if pseudosphere:
            return shared("pseudo curvatures", lambda: ring_curvatures(ar, tractrix, nt()))
        return shared("catenoid curvatures", lambda: ring_curvatures(ar, p, m()))

    def theorem_7() -> Check:
        fused = rings(True)
        if fused is not None:
            residuals = fused[0]  # n faces: tractrix and n on i_min .. i_max + 1
        else:
            pseudo = curvatures(True)
            residuals = ar.maximum(
                constant_curvature_residuals(pseudo, -1 / (h * h)), pseudo.parallel
            )
        return check(THEOREM_7, _first(residuals, n), n_tolerance)

    def theorem_8() -> Check:
        fused = rings(False)
        if fused is not None:
            residuals = fused[0]
        else:
            catenoid = curvatures(False)
            residuals = ar.maximum(minimal_residuals(catenoid), catenoid.parallel)
        return check(THEOREM_8, _first(residuals, n), construction_tolerance)

    def equation_17() -> Check:
        pseudo, catenoid = rings(True), rings(False)
        if pseudo is not None and catenoid is not None:
            return equation_17_result(
                ar,
                shown,
                [pseudo[1], catenoid[1]],
                pseudo[2] + catenoid[2],
                construction_tolerance,
                detail,
            )
        return equation_17_check(
            ar,
            shown,
            [(tractrix, nt()), (p, m())],
            construction_tolerance,
            detail,
            [curvatures(True), curvatures(False)],
        )

    # ñ and m come from the edges of p, which the stored vertices resolve only to eps times
    # |p_i| + |p_{i+1}| (coordinates summed): residuals of quantities built from edge directions
    # are scaled by the resolution |e_i| / (|p_i| + |p_{i+1}|) <= 1 (docs/checks.md)
    p_edges = _Edges(p)  # mp: p's edges and their sizes, made once when first used

    def resolution() -> Array:  # edges i_min .. i_max (p_i p_{i+1})
        if (fused := ball_edge_checks()) is not None:
            return fused[0]
        if (found := numbers()) is not None:
            return found.resolution
        return shared("resolution", lambda: _edge_resolution(ar, p, p_edges))

    def along_normals() -> Array:  # (18)'s slope check: n along the edges of p
        if (fused := ball_edge_checks()) is not None:
            return fused[2]
        return _along(ar, nt()[:n], p[: n + 1], p_edges, reduce=not detail)

    def ball_edge_checks() -> Any:
        """Balls, (18)'s slope form and ñ's rotation both wanted: every check on the edges of
        p in one compiled program (``arb_gauss.edge_checks``: the resolutions and their
        consecutive minima per edge, ``_along`` of n and of the printed slope form, the
        rotation's residuals; no array of the edges or sizes); None where that does not
        apply."""

        def make() -> Any:
            if not (ar.certified and wanted(EQUATION_18_SLOPE.id)):
                return None
            if not wanted(EQUATION_19_ROTATION.id) or n < 1 or len(p) != n + 1:
                return None
            if images.contact_edges_before is None or len(nt()) < n or len(c()) < n + 1:
                return None
            before = _edge_resolution(ar, images.contact_edges_before)
            return arb_gauss.edge_checks(p, nt()[:n], c()[1 : n + 1], before[0], detail)

        return shared("edge checks", make)

    def pole_resolution() -> Array:
        if (fused := ball_edge_checks()) is not None:
            return fused[1]
        if (found := numbers()) is not None:
            return found.poles

        def make() -> Array:
            assert images.contact_edges_before is not None
            before = _edge_resolution(ar, images.contact_edges_before)
            if ar.certified:  # balls: a ball holding each minimum (residuals stay balls)
                previous = np.concatenate([before, resolution()[:-1]])
                compiled = arb_gauss.minimum(previous, resolution())
                return compiled if compiled is not None else _ball_minimum(previous, resolution())
            # np.minimum of the shifted resolutions and the resolutions, in one compiled pass
            return residual_kernels.pole_resolution(
                ar.to_floats(before), ar.to_floats(resolution())
            )

        return shared("pole resolution", make)

    def ball_pair(key: str) -> Any:
        """Balls, constructed images: (18) (n) or (19) (ñ) against its corrected and printed
        closed forms in one compiled program straight from the hyperbolic table (the closed
        forms' arrays not made; ``arb_gauss.closed_and_printed``: the balls of ``closed`` and
        ``printed_erratum``, the printed residuals reduced, the corrected ones too without
        ``detail``); None where that does not apply (another key, the closed forms given or
        made already, another table)."""

        if key == "20":
            both = ball_image_20()
            return None if both is None else (both[1], both[2])

        def make() -> Any:
            found = images.ball_table
            if key not in ("18", "19") or found is None or n < 1:
                return None
            if ball_table() is None:
                return None
            table, first = found
            rows = table._rows(first, first + n - 1)
            low = min(flint.ctx.prec, RESIDUAL_BITS)
            with ar.residual_precision():
                tiny = ar.scalar(np.finfo(np.float64).tiny)
            built, factor = (nt()[:n], None) if key == "18" else (c()[1 : n + 1], resolution())
            return arb_gauss.closed_and_printed(
                key,
                built,
                table.tanh_t[rows],
                table.sech_t[rows],
                tiny,
                low,
                None if factor is None else factor[:n],
                detail,
            )

        return shared(f"pair {key}", make)

    def ball_table() -> Any:
        """The hyperbolic table ``ball_pair`` reads and the first row of n in it, or None."""
        found = images.ball_table
        if found is None or n < 1 or not isinstance(printed, PrintedForms):
            return None
        if CLOSED_IMAGES & vars(images).keys():  # closed forms given (the tests perturb them)
            return None
        table, first = found
        same = _ball_hyperbolic(
            ar, printed.h, printed.d, printed.shift, printed.i_min, printed.i_max
        )
        return (table, first) if printed.i_min == first and same is table else None

    def ball_image_20() -> Any:
        """Balls, constructed images, (20) and its inversion both wanted: m against the poles by
        inversion, (20) corrected and (20) printed in one compiled program from the hyperbolic
        table (``arb_gauss.image_20``: the balls of ``inversion``, ``closed`` and
        ``printed_erratum``, reduced as ``ball_pair``'s); None where that does not apply."""

        def make() -> Any:
            if not (wanted(EQUATION_20.id) and wanted(EQUATION_20_INVERSION.id)):
                return None
            found = ball_table()
            if found is None:
                return None
            table, first = found
            assert isinstance(printed, PrintedForms)  # (``ball_table``)
            rows = table._rows(first, first + n - 1)
            columns = (table.tanh_t[rows], table.sech_t[rows], table.tanh_u[rows])
            with ar.residual_precision():
                tiny = ar.scalar(np.finfo(np.float64).tiny)
            constants = {"h": printed.h, "d": printed.d, "amplitude": table.amplitude}
            constants |= {"two": flint.arb(2), "tiny": tiny}
            constants["low"] = min(flint.ctx.prec, RESIDUAL_BITS)
            contact = c()
            return arb_gauss.image_20(
                m()[:n],
                contact[:n],
                contact[1 : n + 1],
                (*columns, table.sech_u[rows]),
                constants,
                pole_resolution()[:n],
                detail,
            )

        return shared("image 20", make)

    def image_comparisons() -> list[float] | None:
        """Float64 without ``detail``, constructed images: the largest residuals of (18)–(20)
        against their corrected and printed closed forms, those selected, from one blocked pass
        that makes each closed point and compares it at once (``fused_checks``: the same
        numbers as the stored closed forms give); None where that pass does not apply."""

        def make() -> list[float] | None:
            if not (ar.mode == "float64" and not detail and images.constructed and n > 0):
                return None
            if not isinstance(printed, PrintedForms) or CLOSED_IMAGES & vars(images).keys():
                return None  # closed forms given (the tests perturb them) or made already
            if len(nt()) < n or len(c()) < n + 1 or len(m()) < n:
                return None
            chosen = [wanted(s.id) for s in (EQUATION_18, EQUATION_19, EQUATION_20)]
            # the scales of (19) and (20) made a block at a time from p, unless their arrays
            # are made already (8 MB each at 10^6 vertices, a fresh mapping each in the server)
            before = images.contact_edges_before
            arrays = "resolution" in memo or numbers() is not None  # made already, or at once
            scales: tuple[Array | None, Array | None, tuple[Array, float] | None]
            if not arrays and before is not None and len(before) == 2 and n < len(p):
                scales = None, None, (p, float(_edge_resolution(ar, before)[0]))
            else:
                scales = (
                    resolution() if chosen[1] else None,
                    pole_resolution() if chosen[2] else None,
                    None,
                )
            return fused_checks.closed_image_comparisons(
                ar,
                printed.h,
                printed.d,
                printed.shift,
                printed.i_min,
                n,
                (*chosen, *chosen),
                nt(),
                c(),
                m(),
                *scales,
            )

        return shared("image comparisons", make)

    def slope_erratum() -> Erratum:
        if ar.mode == "float64":  # the same numbers in one pass, the largest alone
            worst = residual_kernels.largest_along_printed_slope(min(n, len(p) - 1), p)
            return Erratum(*ERRATUM_18_SLOPE, printed_residual=worst)
        if (fused := ball_edge_checks()) is not None:  # balls: with the edges' other checks
            return Erratum(*ERRATUM_18_SLOPE, printed_residual=printed_residual(ar, fused[3]))
        compiled = p_edges.compiled if ar.certified else None
        if compiled is not None and n <= len(compiled[0]):  # balls: one compiled pass
            ex, ey, size = (column[:n] for column in compiled[:3])
            along = arb_gauss.along_printed_slope(ex, ey, size, reduce=True)
            if along is not None:
                return Erratum(*ERRATUM_18_SLOPE, printed_residual=printed_residual(ar, along))
        edges = p_edges.edges
        slope = edges[:, 1] / edges[:, 0]  # k_{i+1} of the edge p_i p_{i+1}, eq. (12)
        slope_printed = kinematic_closed_forms.normal_from_slope_printed(ar, slope)
        along = _along(ar, slope_printed[:n], p[: n + 1], p_edges)
        return Erratum(*ERRATUM_18_SLOPE, printed_residual=printed_residual(ar, along))

    def slope() -> Check:
        if ar.mode == "float64" and not detail and n > 0 and len(nt()) >= n and len(p) > n:
            # the check and its erratum from one pass, the largest of each alone
            found = numbers()
            pair = None if found is None else found.along
            largest, worst = residual_kernels.along_largest(nt()[:n], p[: n + 1], pair)
            erratum = Erratum(*ERRATUM_18_SLOPE, printed_residual=worst)
            return check(EQUATION_18_SLOPE, largest, n_tolerance, erratum)
        return check(EQUATION_18_SLOPE, along_normals(), n_tolerance, slope_erratum())

    def one_pass() -> tuple[float, float] | None:
        """Float64 without ``detail``: (19) as a rotation and (20) by inversion, the largest
        of each (those selected), from one pass that makes the resolutions as it goes; None
        where the resolutions' arrays are made already, the fused numbers hold both
        (``numbers``), or the lengths do not fit. The comparisons with the constructed images'
        closed forms make their scales a block at a time as well (``image_comparisons``), so
        no (n,) array of resolutions is made (issue 13, session 30)."""

        def make() -> tuple[float, float] | None:
            if ar.mode != "float64" or detail or n <= 0 or "resolution" in memo:
                return None
            if numbers() is not None:  # below SECTION_BELOW: with the other numbers already
                return None
            before = images.contact_edges_before
            if before is None or len(before) != 2 or len(p) <= n or len(c()) <= n:
                return None
            if len(nt()) < n or len(m()) < n:
                return None
            rotation, inversion = wanted(EQUATION_19_ROTATION.id), wanted(EQUATION_20_INVERSION.id)
            return residual_kernels.rotation_and_inversion_largest(
                p, before, c(), nt(), m(), n, rotation, inversion
            )

        return shared("rotation and inversion", make)

    def rotation() -> Check:
        fused = one_pass()
        if fused is not None:
            rows = lambda: residual_kernels.contact_rotation_largest(  # noqa: E731
                c(), nt(), resolution(), n
            ).residuals()
            return check(EQUATION_19_ROTATION, Largest(fused[0], n, rows), n_tolerance)
        count = min(n, len(c()) - 1, len(nt()), len(resolution()))
        if ar.mode == "float64" and not detail and count == n > 0:  # one pass, no arrays
            found = numbers()
            largest = None if found is None else found.rotation
            return check(
                EQUATION_19_ROTATION,
                residual_kernels.contact_rotation_largest(c(), nt(), resolution(), n, largest),
                n_tolerance,
            )
        if ar.certified and (fused := ball_edge_checks()) is not None:  # with the edges' checks
            return check(EQUATION_19_ROTATION, fused[4], n_tolerance)
        if ar.certified:  # balls: the distances and their scaling in one compiled pass
            compiled = arb_gauss.rotation(
                c()[1 : n + 1], nt()[:n], resolution()[:n], reduce=not detail
            )
            if compiled is not None:
                return check(EQUATION_19_ROTATION, compiled, n_tolerance)
        rotated = stack_points(-nt()[:, 1], nt()[:, 0])
        return check(
            EQUATION_19_ROTATION,
            _scaled(ar, point_distance(ar, c()[1 : n + 1], rotated[:n]), resolution()[:n]),
            n_tolerance,
        )

    def inversion() -> Check:
        fused = one_pass()
        if fused is not None:
            rows = lambda: residual_kernels.pole_inversion_largest(  # noqa: E731
                m(), c(), pole_resolution(), n
            ).residuals()
            return check(EQUATION_20_INVERSION, Largest(fused[1], n, rows), local_tolerance)
        count = min(n, len(m()), len(c()) - 1, len(pole_resolution()))
        if ar.mode == "float64" and not detail and count == n > 0:  # one pass, no arrays
            found = numbers()
            largest = None if found is None else found.inversion
            return check(
                EQUATION_20_INVERSION,
                residual_kernels.pole_inversion_largest(m(), c(), pole_resolution(), n, largest),
                local_tolerance,
            )
        if ar.certified and (fused := ball_image_20()) is not None:  # with (20), one program
            return check(EQUATION_20_INVERSION, fused[0], local_tolerance)
        inverted = _pole_by_inversion(ar, c()[:-1], c()[1:])  # i_min .. +1
        return check(
            EQUATION_20_INVERSION,
            _relative(ar, m()[:n], inverted[:n], pole_resolution()[:n], reduce=not detail),
            local_tolerance,
        )

    evaluators: tuple[tuple[Statement, Callable[[], Check]], ...] = (
        (EQUATION_17, equation_17),
        (
            EQUATION_18,
            lambda: closed(
                EQUATION_18,
                nt(),
                lambda: images.closed_tractrix_gauss,
                lambda: printed_erratum(ERRATUM_18, nt(), "18"),
                n_tolerance,
            ),
        ),
        (EQUATION_18_SLOPE, slope),
        (
            EQUATION_19,
            lambda: closed(
                EQUATION_19,
                c()[1:],
                lambda: images.closed_contact[1:],
                lambda: printed_erratum(ERRATUM_19, c()[1:], "19"),
                make_scale=resolution,
            ),
        ),
        (EQUATION_19_ROTATION, rotation),
        (EQUATION_20_INVERSION, inversion),
        (
            EQUATION_20,
            lambda: closed(
                EQUATION_20,
                m(),
                lambda: images.closed_gauss,
                lambda: printed_erratum(ERRATUM_20, m(), "20"),
                make_scale=pole_resolution,
            ),
        ),
        (THEOREM_7, theorem_7),
        (THEOREM_8, theorem_8),
    )
    checks = []
    for statement, evaluate in evaluators:
        if wanted(statement.id):
            ar.check_time()  # the compiled ball passes read no clock: one check per statement
            checks.append(evaluate())
    return checks


def _first(residuals: Any, n: int) -> Any:
    """The first n residuals (a ``checks.Largest`` holds exactly n, see ``rings``)."""
    return residuals if isinstance(residuals, Largest) else residuals[:n]


class _Edges:
    """mp: the edges p_{i+1} − p_i of a polygon and their sizes |p_i| + |p_{i+1}| (coordinates
    summed), each computed once for the checks that use them (``_along``, ``_edge_resolution``)."""

    def __init__(self, points: Array) -> None:
        self.points = points

    @cached_property
    def compiled(self) -> list[Array] | None:
        """Balls: the edges' coordinates, sizes and resolutions in one compiled pass
        (``arb_gauss.edges``: the sizes and resolutions at ``RESIDUAL_BITS``); None where it
        does not apply."""
        return arb_gauss.edges(self.points) if len(self.points) >= 2 else None

    @cached_property
    def edges(self) -> Array:
        compiled = self.compiled
        if compiled is not None:
            return stack_points(compiled[0], compiled[1])
        return self.points[1:] - self.points[:-1]

    @cached_property
    def size(self) -> Array:
        compiled = self.compiled
        if compiled is not None:
            return compiled[2]
        return magnitude(self.points[:-1], self.points[1:])


def _edge_resolution(ar: Arithmetic, points: Array, shared: _Edges | None = None) -> Array:
    """|p_{i+1} − p_i| / (|p_i| + |p_{i+1}|) per edge (coordinates summed): at most 1.

    ``shared``: the edges and sizes of ``points`` already made (mp)."""
    if ar.mode == "float64":  # one compiled pass (the length within 2 ulp of hypot)
        return residual_kernels.edge_resolution(points)
    made = shared if shared is not None else _Edges(points)
    if ar.certified and made.compiled is not None:
        return made.compiled[3]
    edges = made.edges
    return ar.hypot(edges[:, 0], edges[:, 1]) / made.size


def _along(
    ar: Arithmetic,
    vectors: Array,
    points: Array,
    shared: _Edges | None = None,
    reduce: bool = False,
) -> Array:
    """How far unit vectors v_i are from pointing along the edges p_i p_{i+1}.

    |v_i × e_i| / (|p_i| + |p_{i+1}|), or 1 where v_i points against the edge: 0 when v_i is
    the unit vector of the edge's direction (the line of slope k_{i+1} through the centre).
    ``shared``: the edges and sizes of a polygon whose first len(points) vertices are
    ``points`` (mp). ``reduce`` (balls): only what a check without per-index residuals reads
    (``arb_gauss.along``).
    """
    if ar.mode == "float64":  # the same operations in one compiled pass
        return residual_kernels.along(vectors, points)
    count = len(points) - 1
    made = shared if shared is not None else _Edges(points)
    if ar.certified and made.compiled is not None:  # balls: one compiled pass
        ex, ey, size = (column[:count] for column in made.compiled[:3])
        compiled = arb_gauss.along(vectors, ex, ey, size, reduce)
        if compiled is not None:
            return compiled
    edges = made.edges[:count]
    crossed = abs(vectors[:, 0] * edges[:, 1] - vectors[:, 1] * edges[:, 0])
    residual = crossed / made.size[:count]
    backwards = vectors[:, 0] * edges[:, 0] + vectors[:, 1] * edges[:, 1] < 0
    return np.where(backwards, ar.scalar(1), residual)


def _relative(
    ar: Arithmetic, computed: Array, expected: Array, scale: Any = None, reduce: bool = False
) -> Array:
    """``relative_point_difference`` of two ``(n, 2)`` arrays, times ``scale`` if given
    (``_scaled``); on balls in one compiled program (``arb_gauss.relative_difference``: the
    same balls, ``tiny`` and the low precision made as ``checks.relative_point_difference``
    makes them; ``reduce``: only the two balls a check without per-index residuals reads)."""
    if ar.certified and len(computed):
        low = min(flint.ctx.prec, RESIDUAL_BITS)
        with ar.residual_precision():
            tiny = ar.scalar(np.finfo(np.float64).tiny)
        found = arb_gauss.relative_difference(computed, expected, tiny, low, scale, reduce)
        if found is not None:
            return found
    residuals = relative_point_difference(ar, computed, expected)
    return residuals if scale is None else _scaled(ar, residuals, scale)


def _scaled(ar: Arithmetic, residuals: Array, scale: Array) -> Array:
    """Residuals times their resolution factors: floats (each a bound on balls would round the
    product down, and underflow from 324 digits on), except on balls, where the product of the
    balls is kept, so that its bounds stay rigorous (``checks.check_residuals``)."""
    if ar.certified:
        compiled = arb_gauss.product(residuals, scale)  # the same products, one pass
        return compiled if compiled is not None else residuals * scale
    return ar.to_floats(residuals) * ar.to_floats(scale)


_ball_minimum: Any = np.frompyfunc(lambda a, b: a.min(b), 2, 1)


def _contact_points(ar: Arithmetic, polygon: Array) -> Array:
    """``gauss_image.contact_points``; on balls in one compiled pass (``arb_gauss``: the same
    balls), which leaves a polygon with an edge not certainly of positive length to it (the
    refusal)."""
    if ar.certified:
        found = arb_gauss.contact_points(polygon, gauss_image.orientation(polygon))
        if found is not None and found[1] < 0:
            return stack_points(found[0][0], found[0][1])
    return gauss_image.contact_points(ar, polygon)


def _pole_by_inversion(ar: Arithmetic, before: Array, after: Array) -> Array:
    """``closed_forms.pole_by_inversion``; on balls in one compiled pass (the same balls)."""
    if ar.certified:
        compiled = arb_gauss.pole_by_inversion(before, after)
        if compiled is not None:
            return stack_points(compiled[0], compiled[1])
    return kinematic_closed_forms.pole_by_inversion(before, after)


def _poles(contact: Array) -> Array:
    """m_i on balls: the intersection of the tangents at ñ_{i−1} and ñ_i (rows of ``contact``),
    the solution x of x·ñ_{i−1} = 1, x·ñ_i = 1 for unit vectors a, b: (a + b)/(1 + a·b).

    The same point as ``gauss_image.circumscribed`` (on the bisector at distance 1/cos(δ/2):
    |a + b| = 2cos(δ/2), 1 + a·b = 2cos²(δ/2)), without its two atan2, two cos and a sin per
    vertex; parallel edges give ñ_i, and 1 + a·b ≥ 1 for turning angles up to π/2.
    """
    compiled = arb_gauss.poles(contact)  # the same balls in one compiled pass
    if compiled is not None:
        return stack_points(compiled[0], compiled[1])
    a, b = contact[:-1], contact[1:]
    total = a + b
    denominator = 1 + (a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1])
    return stack_points(total[:, 0] / denominator, total[:, 1] / denominator)


class _BallHyperbolic:
    """tanh and sech of t = (i + τ)L and of u = t − L/2 for i = lo .. hi, on balls, from one
    exponential per index: with E = e^t, tanh t = 1 − 2/(E² + 1), sech t = 2/(E + 1/E)
    (``_tanh_sech``), and e^u = E·√((h − d)/(h + d)) (e^{−L/2}, L = ln((h + d)/(h − d))). The
    closed forms (18)–(20) and their printed versions (``kinematic_closed_forms``: the same
    rewritings of the power forms) are read off these; each of them took a cosh and a tanh of
    its own."""

    def __init__(self, ar: Arithmetic, h: Scalar, d: Scalar, shift: Scalar, lo: int, hi: int):
        self.lo, self.hi, self.h, self.d = lo, hi, h, d
        self.amplitude = h / ar.sqrt((h - d) * (h + d))  # h/√(h² − d²): m_i^y = h / p_i^y
        log_ratio = kinematic_closed_forms.log_ratio(ar, h, d)
        ratio = ar.sqrt((h - d) / (h + d))
        compiled = arb_gauss.hyperbolic(lo, hi, shift, log_ratio, ratio)
        if compiled is not None:  # the same balls in one compiled pass
            self.tanh_t, self.sech_t, self.tanh_u, self.sech_u = compiled
            return
        t = (ar.indices(lo, hi) + shift) * log_ratio
        e = ar.exp(t)
        self.tanh_t, self.sech_t = self._tanh_sech(e)
        self.tanh_u, self.sech_u = self._tanh_sech(e * ratio)

    @staticmethod
    def _tanh_sech(e: Array) -> tuple[Array, Array]:
        """(tanh, sech) = (1 − 2/(E² + 1), 2/(E + 1/E)): written so that the balls' radii stay
        near those of a tanh and a 1/cosh (the quotient (E² − 1)/(E² + 1) would carry E²'s
        relative radius twice into a value near ±1)."""
        return 1 - 2 / (e * e + 1), 2 / (e + 1 / e)

    def _rows(self, a: int, b: int) -> slice:
        return slice(a - self.lo, b - self.lo + 1)

    def tractrix_gauss_image(self, a: int, b: int) -> Array:
        """(18) corrected: (sech t, tanh t)."""
        rows = self._rows(a, b)
        return stack_points(self.sech_t[rows], self.tanh_t[rows])

    def contact_points(self, a: int, b: int) -> Array:
        """(19) corrected: (−tanh t, sech t)."""
        rows = self._rows(a, b)
        return stack_points(-self.tanh_t[rows], self.sech_t[rows])

    def circumscribed_gauss_image(self, a: int, b: int) -> Array:
        """(20) corrected: (−tanh u, h sech u / √(h² − d²))."""
        rows = self._rows(a, b)
        return stack_points(-self.tanh_u[rows], self.amplitude * self.sech_u[rows])

    def printed(self, key: str, a: int, b: int) -> Array:
        """The printed (18), (19) or (20) (``PrintedForms.FORMS``) on a .. b."""
        rows = self._rows(a, b)
        tanh, sech = self.tanh_t[rows], self.sech_t[rows]
        if key == "18":
            return stack_points(sech, -tanh)
        if key == "19":
            return stack_points(tanh, sech)
        compiled = arb_gauss.printed_20(self.h, self.d, tanh, sech)
        if compiled is not None:  # the same balls in one compiled pass
            return stack_points(compiled[0], compiled[1])
        denominator = self.h + self.d * tanh
        return stack_points((self.h * tanh - self.d) / denominator, self.h * sech / denominator)


def _ball_hyperbolic(
    ar: Arithmetic, h: Scalar, d: Scalar, shift: Scalar, lo: int, hi: int
) -> _BallHyperbolic:
    """The table of ``_BallHyperbolic`` covering lo .. hi for these h, d, τ, made once per
    computation (kept on the arithmetic, keyed by the balls' exact midpoints and radii): the
    Gauss images' closed forms and the printed forms read the same one."""
    tables: dict[tuple[Any, ...], _BallHyperbolic] = ar.__dict__.setdefault("_d4b_hyperbolic", {})
    key = tuple(part for x in (h, d, shift) for part in (x.mid().man_exp(), x.rad().man_exp()))
    table = tables.get(key)
    if table is None or table.lo > lo or table.hi < hi:
        table = tables[key] = _BallHyperbolic(ar, h, d, shift, lo, hi)
    return table
