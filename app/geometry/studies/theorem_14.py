"""Theorem 14: the curve through the vertices of (14) and the (D4b) centres approach the
catenary x ↦ (x, h cosh(x/h)) as d → 0; eq. (21) is the limit its proof takes."""

from __future__ import annotations

import numpy as np

from app.geometry.catalog.section6 import (
    EQUATION_21,
    INTERPOLATION_14,
    REARRANGEMENT_14,
    SUBSTITUTION_21,
    THEOREM_14,
)
from app.geometry.checks import (
    Check,
    point_distance,
    relative_difference,
    relative_point_difference,
)
from app.geometry.d4b.construction import construct
from app.geometry.precision import Arithmetic
from app.geometry.smooth.distance import distance_to_catenary
from app.geometry.studies import limit_curves as lc
from app.geometry.studies.common import (
    Level,
    Measure,
    OrderFit,
    Study,
    StudyInfo,
    converges,
)
from app.geometry.studies.tractrix import (
    Builder,
    Identity,
    finish,
    index_range,
    largest,
    power_steps,
    printable,
    sample_points,
    steps,
    unit_power_steps,
    validate,
)
from app.geometry.tolerances import LOCAL_STEPS

CATENARY_MEASURES = (
    Measure(
        "parametric",
        "sup over the sample points x of |c(x) − (x, h cosh(x/h))|: Theorem 14's curve against "
        "the catenary at the same x (absolute; both first coordinates are x, so this is the "
        "vertical gap)",
        2,
    ),
    Measure(
        "distance",
        "sup over the sample points x of the distance from c(x) to the catenary (nearest "
        "point; absolute)",
        2,
    ),
    Measure(
        "vertices",
        "max over the constructed (D4b) centres p_i with |p_i^x| <= x_max of |p_i − (p_i^x, "
        "h cosh(p_i^x/h))| (absolute)",
        2,
    ),
    Measure(
        "vertices-distance",
        "max over the same p_i of their distance to the catenary (absolute)",
        2,
    ),
    Measure(
        "equation-21",
        "sup over the sample points x of |(1 − d/h)^{(x+d)/(2d)} − e^{−x/(2h)}|, the limit (21)",
        1,
    ),
)


THEOREM_14_INFO = StudyInfo(
    id="theorem-14",
    title="Theorem 14: the discrete hyperbolic cosine (14) converges to the catenary",
    reference="Section 6, Theorem 14, eq. (21); (D4b), eq. (14)",
    summary=(
        "The (D4b) discrete hyperbolic cosine with vertical first stick and its interpolating "
        "curve c(x) of Theorem 14, against the catenary x ↦ (x, h cosh(x/h)), for d = d0/2^k. "
        "Every measure has order 2."
    ),
    refinement="d_k = d0/2^k, k = 0 .. levels − 1; compact set |x| <= x_max",
    step_name="d",
    measures=CATENARY_MEASURES,
    statements=(THEOREM_14, INTERPOLATION_14, REARRANGEMENT_14, SUBSTITUTION_21, EQUATION_21),
)


def theorem_14(
    ar: Arithmetic,
    h: float = 1.0,
    d0: float = 0.2,
    levels: int = 8,
    x_max: float = 2.0,
    samples: int = 401,
    build: Builder = construct,
) -> Study:
    """Refinement study of Theorem 14 and (21) on the (D4b) construction (see module doc).

    Levels are sequential (a Python loop over at most ``levels`` refinements, each vectorized).
    """
    validate(h, d0, levels, x_max, samples)
    hh = ar.scalar(h)
    x = sample_points(ar, x_max, samples)
    nonzero = np.asarray(x != 0, dtype=bool)
    result: list[Level] = []
    interpolation, rearrangement, substitution = Identity(), Identity(), Identity()
    for d in steps(d0, levels):
        dd = ar.scalar(d)
        i_min, i_max = index_range(d, x_max)
        built = build(ar, h, d, None, i_min, i_max)
        p = built.centres
        size = max(abs(i_min), abs(i_max)) + 1
        powers = power_steps(ar, hh, dd, x_max)
        c = lc.theorem_14_curve(ar, hh, dd, x)
        smooth = lc.catenary(ar, hh, x)
        at_vertices = lc.catenary(ar, hh, p[:, 0])
        power = lc.power_21(ar, hh, dd, x)
        scale = ar.to_float(hh * ar.cosh(ar.scalar(x_max) / hh))
        noise = ar.tolerance(LOCAL_STEPS + size) * scale
        result.append(
            Level(
                step=d,
                vertices=len(p),
                samples=samples,
                errors={
                    "parametric": largest(ar, point_distance(ar, c, smooth)),
                    "distance": largest(ar, distance_to_catenary(ar, hh, c)),
                    "vertices": largest(ar, point_distance(ar, p, at_vertices)),
                    "vertices-distance": largest(ar, distance_to_catenary(ar, hh, p)),
                    "equation-21": largest(ar, abs(power - lc.limit_21(ar, hh, x))),
                },
                resolution={
                    "parametric": ar.tolerance(LOCAL_STEPS) * scale,
                    "distance": ar.tolerance(LOCAL_STEPS) * scale,
                    "vertices": noise,
                    "vertices-distance": noise,
                    "equation-21": ar.tolerance(unit_power_steps(ar, hh, dd, x_max)),
                },
            )
        )
        with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
            printed = lc.theorem_14_curve_printed(ar, hh, dd, p[:, 0])
            interpolation.add(
                ar,
                np.maximum(
                    relative_point_difference(ar, printed, p),
                    relative_point_difference(ar, lc.theorem_14_curve(ar, hh, dd, p[:, 0]), p),
                ),
                2 * size + powers,
                keep=printable(ar, hh, dd, p[:, 0], 0.5),
            )
            rearrangement.add(
                ar,
                relative_difference(
                    ar,
                    lc.theorem_14_curve_rearranged(ar, hh, dd, x)[:, 1],
                    lc.theorem_14_curve_printed(ar, hh, dd, x)[:, 1],
                ),
                powers,
                keep=printable(ar, hh, dd, x, 0.5),
            )
            xs = x[nonzero]
            substitution.add(
                ar,
                relative_difference(
                    ar, lc.power_21_substituted(ar, hh, dd, xs), lc.power_21(ar, hh, dd, xs)
                ),
                unit_power_steps(ar, hh, dd, x_max),
            )
    parameters = {"h": h, "d0": d0, "levels": levels, "x_max": x_max, "samples": samples}

    def checks(fits: dict[str, OrderFit]) -> list[Check]:
        return [
            converges(THEOREM_14, result, ("parametric",), fits),
            interpolation.check(ar, INTERPOLATION_14),
            rearrangement.check(ar, REARRANGEMENT_14),
            substitution.check(ar, SUBSTITUTION_21),
            converges(EQUATION_21, result, ("equation-21",), fits),
        ]

    return finish(THEOREM_14_INFO, ar, parameters, result, checks)
