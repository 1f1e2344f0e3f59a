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

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry import gauss_image
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
    Statement,
    check_residuals,
    not_applicable,
    printed_residual,
)
from app.geometry.d4b import closed_forms as kinematic_closed_forms, residual_kernels
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


@dataclass(frozen=True)
class GaussImages:
    """The three polygons of Section 5 for one (D4b) computation, with their closed forms.

    ``tractrix_gauss`` and ``gauss`` are aligned with ``D4bPolygons.p`` (i_min .. i_max + 1);
    ``contact`` starts one index earlier (i_min − 1 .. i_max + 1), since m_i needs ñ_{i−1}.
    """

    tractrix_gauss: Array
    contact: Array
    gauss: Array
    closed_tractrix_gauss: Array
    closed_contact: Array
    closed_gauss: Array
    constructed: bool
    contact_edges_before: Array | None = None
    """p_{i_min−1} and p_{i_min}: the edge before the range, which m_{i_min} also uses."""
    conditioning: float = 1.0
    """Step count of n's tolerance beyond the construction's: 1, since n is read from the stick
    directions (``build``) instead of accumulated from edge angles."""


def build(
    ar: Arithmetic,
    h: Scalar,
    d: Scalar,
    shift: Scalar,
    i_min: int,
    i_max: int,
    hull_start: int,
    tractrix_hull: Array | None,
    first_direction: tuple[Scalar, Scalar] | None,
    p_extended: Array | None,
    directions_hull: Array | None = None,
) -> GaussImages:
    """The Gauss images on i_min .. i_max + 1 (``contact`` from i_min − 1).

    With a construction, ``tractrix_hull`` is the tractrix on hull_start .. (covering 0 and the
    range), ``first_direction`` the unit vector of stick 0, ``p_extended`` the hyperbolic cosine on
    i_min − 1 .. i_max + 2, ``directions_hull`` the unit stick directions u on the same indices as
    ``tractrix_hull``. Without (method=closed-form) the closed forms are used.
    """
    i = ar.indices(i_min, i_max + 1)
    closed_n = kinematic_closed_forms.tractrix_gauss_image(ar, h, d, i, shift)
    closed_m = kinematic_closed_forms.circumscribed_gauss_image(ar, h, d, i, shift)
    closed_c = kinematic_closed_forms.contact_points(
        ar, h, d, ar.indices(i_min - 1, i_max + 1), shift
    )
    if tractrix_hull is None or first_direction is None or p_extended is None:
        before = kinematic_closed_forms.hyperbolic_cosine(
            ar, h, d, ar.indices(i_min - 1, i_min), shift
        )
        return GaussImages(
            closed_n, closed_c, closed_m, closed_n, closed_c, closed_m, False, before
        )
    # n is inscribed with edges parallel to the tractrix's and n_0 = J u_0, the unit normal of
    # stick 0 (J(x, y) = (y, −x)). Its exact form is n_i = J u_i for every i: the rotation R
    # about p_{i+1} takes u_i to u_{i+1} and d_i to d_{i+1}, and d_i − p_{i+1} = λ J u_i (p_{i+1}
    # is on the normal of stick i at d_i), so d_{i+1} − d_i = λ J (u_{i+1} − u_i) (R commutes
    # with J): the chords n_i n_{i+1} are parallel to the tractrix edges, as (18) asks. Read from
    # the construction's stick directions, n carries their rounding only, where accumulating the
    # edge angles (gauss_image.inscribed_parallel) drifted to 1e-11 over 12001 vertices.
    del first_direction
    if directions_hull is None:
        raise ValueError("a construction needs its stick directions")
    n_hull = stack_points(directions_hull[:, 1], -directions_hull[:, 0])
    window = slice(i_min - hull_start, i_max + 1 - hull_start + 1)
    return GaussImages(
        tractrix_gauss=n_hull[window],
        contact=gauss_image.contact_points(ar, p_extended),
        gauss=gauss_image.circumscribed(ar, p_extended),
        closed_tractrix_gauss=closed_n,
        closed_contact=closed_c,
        closed_gauss=closed_m,
        constructed=True,
        contact_edges_before=p_extended[:2],
    )


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


def printed_forms(
    ar: Arithmetic, h: Scalar, d: Scalar, shift: Scalar, i_min: int, i_max: int
) -> dict[str, Array]:
    """The printed (18), (19), (20) on i_min .. i_max (for the errata's printed residuals)."""
    i = ar.indices(i_min, i_max)
    return {
        "18": kinematic_closed_forms.tractrix_gauss_image_printed(ar, h, d, i, shift),
        "19": kinematic_closed_forms.contact_points_printed(ar, h, d, i, shift),
        "20": kinematic_closed_forms.circumscribed_gauss_image_printed(ar, h, d, i, shift),
    }


def evaluate(
    ar: Arithmetic,
    h: Scalar,
    p: Array,
    tractrix: Array,
    images: GaussImages,
    printed: dict[str, Array],
    indices: np.ndarray[Any, np.dtype[np.int64]],
    n: int,
    local_tolerance: float,
    construction_tolerance: float,
    detail: bool,
) -> list[Check]:
    """Every check of ``STATEMENTS`` on the given polygons (aligned as in ``GaussImages``).

    ``n`` is the number of indices shown (i_min .. i_max); the face-wise checks use the faces
    i_min .. i_max (edges to i + 1).
    """
    nt, c, m = images.tractrix_gauss, images.contact, images.gauss
    shown = indices[:n]
    n_tolerance = companion_tolerances(ar, images, construction_tolerance)["tractrix_gauss_image"]

    def check(
        statement: Statement,
        residuals: Array,
        tolerance: float,
        erratum: Erratum | None = None,
    ) -> Check:
        return check_residuals(
            statement, ar, shown[: len(residuals)], residuals, tolerance, detail, erratum
        )

    def closed(
        statement: Statement,
        built: Array,
        formula: Array,
        erratum: Erratum,
        tolerance: float = construction_tolerance,
        scale: Any = None,
    ) -> Check:
        if not images.constructed:
            return not_applicable(
                statement,
                tolerance,
                "method=closed-form: the Gauss image was not constructed to compare",
            )
        if scale is not None and ar.mode == "float64":  # the same product, in one pass
            residuals = residual_kernels.scaled_relative_point_difference(
                built[:n], formula[:n], scale[:n]
            )
        else:
            residuals = relative_point_difference(ar, built[:n], formula[:n])
            if scale is not None:
                residuals = ar.to_floats(residuals) * ar.to_floats(scale[:n])
        return check(statement, residuals, tolerance, erratum)

    def printed_erratum(entry: tuple[str, str, str], built: Array, formula: Array) -> Erratum:
        if ar.mode == "float64":  # the largest alone, in one pass
            worst = residual_kernels.largest_relative_point_difference(built[:n], formula[:n])
            return Erratum(*entry, printed_residual=worst)
        residuals = relative_point_difference(ar, built[:n], formula[:n])
        return Erratum(*entry, printed_residual=printed_residual(ar, residuals))

    pseudo_rings = ring_checks(ar, tractrix, nt, -1 / (h * h))
    catenoid_rings = ring_checks(ar, p, m, None)
    if pseudo_rings is not None and catenoid_rings is not None:  # float64, one pass per ring
        theorem_7, theorem_8 = pseudo_rings[0], catenoid_rings[0]
        equation_17 = equation_17_result(
            ar,
            shown,
            [pseudo_rings[1], catenoid_rings[1]],
            pseudo_rings[2] + catenoid_rings[2],
            construction_tolerance,
            detail,
        )
    else:
        pseudo = ring_curvatures(ar, tractrix, nt)
        theorem_7 = np.maximum(
            ar.to_floats(constant_curvature_residuals(pseudo, -1 / (h * h))),
            ar.to_floats(pseudo.parallel),
        )
        catenoid = ring_curvatures(ar, p, m)
        theorem_8 = np.maximum(
            ar.to_floats(minimal_residuals(catenoid)), ar.to_floats(catenoid.parallel)
        )
        equation_17 = equation_17_check(
            ar,
            shown,
            [(tractrix, nt), (p, m)],
            construction_tolerance,
            detail,
            [pseudo, catenoid],
        )
    # ñ and m come from the edges of p, which the stored vertices resolve only to eps times
    # |p_i| + |p_{i+1}| (coordinates summed): residuals of quantities built from edge directions
    # are scaled by the resolution |e_i| / (|p_i| + |p_{i+1}|) <= 1 (docs/checks.md)
    resolution = _edge_resolution(ar, p)  # edges i_min .. i_max (p_i p_{i+1})
    assert images.contact_edges_before is not None
    before = _edge_resolution(ar, images.contact_edges_before)
    pole_resolution = np.minimum(
        ar.to_floats(np.concatenate([before, resolution[:-1]])), ar.to_floats(resolution)
    )
    edges = p[1:] - p[:-1]
    slope = edges[:, 1] / edges[:, 0]  # k_{i+1} of the edge p_i p_{i+1}, eq. (12)
    slope_printed = kinematic_closed_forms.normal_from_slope_printed(ar, slope)
    rotated = stack_points(-nt[:, 1], nt[:, 0])
    inverted = kinematic_closed_forms.pole_by_inversion(c[:-1], c[1:])  # i_min .. i_max + 1
    return [
        equation_17,
        closed(
            EQUATION_18,
            nt,
            images.closed_tractrix_gauss,
            printed_erratum(ERRATUM_18, nt, printed["18"]),
            n_tolerance,
        ),
        check(
            EQUATION_18_SLOPE,
            _along(ar, nt[:n], p[: n + 1]),
            n_tolerance,
            Erratum(
                *ERRATUM_18_SLOPE,
                printed_residual=printed_residual(ar, _along(ar, slope_printed[:n], p[: n + 1])),
            ),
        ),
        closed(
            EQUATION_19,
            c[1:],
            images.closed_contact[1:],
            printed_erratum(ERRATUM_19, c[1:], printed["19"]),
            scale=resolution,
        ),
        check(
            EQUATION_19_ROTATION,
            ar.to_floats(point_distance(ar, c[1 : n + 1], rotated[:n]))
            * ar.to_floats(resolution[:n]),
            n_tolerance,
        ),
        check(
            EQUATION_20_INVERSION,
            ar.to_floats(relative_point_difference(ar, m[:n], inverted[:n])) * pole_resolution[:n],
            local_tolerance,
        ),
        closed(
            EQUATION_20,
            m,
            images.closed_gauss,
            printed_erratum(ERRATUM_20, m, printed["20"]),
            scale=pole_resolution,
        ),
        check(THEOREM_7, theorem_7[:n], n_tolerance),
        check(THEOREM_8, theorem_8[:n], construction_tolerance),
    ]


def _edge_resolution(ar: Arithmetic, points: Array) -> Array:
    """|p_{i+1} − p_i| / (|p_i| + |p_{i+1}|) per edge (coordinates summed): at most 1."""
    if ar.mode == "float64":  # one compiled pass (the length within 2 ulp of hypot)
        return residual_kernels.edge_resolution(points)
    edges = points[1:] - points[:-1]
    return ar.hypot(edges[:, 0], edges[:, 1]) / magnitude(points[:-1], points[1:])


def _along(ar: Arithmetic, vectors: Array, points: Array) -> Array:
    """How far unit vectors v_i are from pointing along the edges p_i p_{i+1}.

    |v_i × e_i| / (|p_i| + |p_{i+1}|), or 1 where v_i points against the edge: 0 when v_i is
    the unit vector of the edge's direction (the line of slope k_{i+1} through the centre).
    """
    if ar.mode == "float64":  # the same operations in one compiled pass
        return residual_kernels.along(vectors, points)
    edges = points[1:] - points[:-1]
    crossed = abs(vectors[:, 0] * edges[:, 1] - vectors[:, 1] * edges[:, 0])
    residual = crossed / magnitude(points[:-1], points[1:])
    backwards = vectors[:, 0] * edges[:, 0] + vectors[:, 1] * edges[:, 1] < 0
    return np.where(backwards, ar.scalar(1), residual)
