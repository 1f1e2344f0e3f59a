"""Theorem 15: the curve through the vertices of (16) and the (D4b) tractrix approach the
tractrix x ↦ (x − h tanh(x/h), h/cosh(x/h)) as d → 0; (22) is the bound its proof uses."""

from __future__ import annotations

import numpy as np

from app.geometry.catalog.section6 import (
    INEQUALITY_22,
    INTERPOLATION_15,
    PROOF_15_X,
    PROOF_15_Y,
    THEOREM_15,
)
from app.geometry.checks import (
    Check,
    point_distance,
    relative_difference,
    relative_point_difference,
)
from app.geometry.d4b.construction import construct
from app.geometry.precision import Arithmetic
from app.geometry.smooth.distance import distance_to_tractrix
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

ERRATUM_PROOF_Y = (
    "E80",
    "f(d) = (1 − d/h)/(1 + d/h) and g(d) = 1/f(d)",
    "f(d) = ((1 − d/h)/(1 + d/h))^{(x+d)/(2d)} and g(d) = 1/f(d)",
)
ERRATUM_PROOF_X = (
    "E81",
    "f(d) = 1 − d/h and g(d) = 1 + d/h",
    "f(d) = (1 − d/h)^{(x+d)/d} and g(d) = (1 + d/h)^{(x+d)/d}",
)


TRACTRIX_MEASURES = (
    Measure(
        "parametric",
        "sup over the sample points x of |c(x) − T(x)|: Theorem 15's curve against the tractrix "
        "T(x) = (x − h tanh(x/h), h / cosh(x/h)) at the same parameter x (absolute)",
        1,
    ),
    Measure(
        "distance",
        "sup over the sample points x of the distance from c(x) to the tractrix (nearest point; "
        "absolute)",
        2,
    ),
    Measure(
        "vertices",
        "max over the constructed (D4b) tractrix points d_i with |(2i − 1)d| <= x_max of "
        "|d_i − T((2i − 1)d)|, the theorem's parametrization (absolute)",
        1,
    ),
    Measure(
        "vertices-distance",
        "max over the same d_i of their distance to the tractrix (absolute)",
        2,
    ),
    Measure(
        "natural",
        "max over the same d_i of |d_i − T(2di)|: T(2di) is the tractrix point whose tangent "
        "meets the x-axis at the foot x_i = (2di, 0) of stick i (absolute)",
        2,
    ),
    Measure(
        "inequality-22-y",
        "sup over the sample points x of |1/(f(d) + g(d)) − 1/(e^{−x/h} + e^{x/h})| with the "
        "proof's f(d) = ((1 − d/h)/(1 + d/h))^{(x+d)/(2d)}, g(d) = 1/f(d)",
        1,
    ),
    Measure(
        "inequality-22-x",
        "sup over the sample points x of |(f(d) − g(d))/(f(d) + g(d)) + tanh(x/h)| with the "
        "proof's f(d) = (1 − d/h)^{(x+d)/d}, g(d) = (1 + d/h)^{(x+d)/d}",
        1,
    ),
)


THEOREM_15_INFO = StudyInfo(
    id="theorem-15",
    title="Theorem 15: the discrete tractrix (16) converges to the tractrix",
    reference="Section 6, Theorem 15, (22); (D4b), eq. (16)",
    summary=(
        "The (D4b) discrete tractrix with vertical first stick and its interpolating curve c(x) "
        "of Theorem 15, against the tractrix T(x) = (x − h tanh(x/h), h / cosh(x/h)), for "
        "d = d0/2^k. The same-parameter error has order 1, the distance to the curve order 2: "
        "c(x) ≈ T(x + d)."
    ),
    refinement="d_k = d0/2^k, k = 0 .. levels − 1; compact set |x| <= x_max",
    step_name="d",
    measures=TRACTRIX_MEASURES,
    statements=(THEOREM_15, INTERPOLATION_15, PROOF_15_Y, PROOF_15_X, INEQUALITY_22),
)


def theorem_15(
    ar: Arithmetic,
    h: float = 1.0,
    d0: float = 0.2,
    levels: int = 8,
    x_max: float = 2.0,
    samples: int = 401,
    build: Builder = construct,
) -> Study:
    """Refinement study of Theorem 15 and (22) on the (D4b) construction (see module doc).

    Levels are sequential (a Python loop over at most ``levels`` refinements, each vectorized).
    """
    validate(h, d0, levels, x_max, samples)
    hh = ar.scalar(h)
    x = sample_points(ar, x_max, samples)
    result: list[Level] = []
    interpolation, proof_y, proof_x = Identity(), Identity(), Identity()
    for d in steps(d0, levels):
        dd = ar.scalar(d)
        i_min, i_max = index_range(d, x_max)
        built = build(ar, h, d, None, i_min, i_max)
        tip, parameter = built.tractrix, built.centres[:, 0]  # (2i − 1)d
        size = max(abs(i_min), abs(i_max)) + 1
        powers = power_steps(ar, hh, dd, x_max)
        c = lc.theorem_15_curve(ar, hh, dd, x)
        f_y, g_y = lc.substitution_15_y(ar, hh, dd, x)
        f_x, g_x = lc.substitution_15_x(ar, hh, dd, x)
        f, g = lc.limits_15(ar, hh, x)
        scale = ar.to_float(hh) + x_max
        local = ar.tolerance(LOCAL_STEPS) * scale
        noise = ar.tolerance(LOCAL_STEPS + size) * scale
        result.append(
            Level(
                step=d,
                vertices=len(tip),
                samples=samples,
                errors={
                    "parametric": largest(ar, point_distance(ar, c, lc.tractrix(ar, hh, x))),
                    "distance": largest(ar, distance_to_tractrix(ar, hh, c)),
                    "vertices": largest(
                        ar, point_distance(ar, tip, lc.tractrix(ar, hh, parameter))
                    ),
                    "vertices-distance": largest(ar, distance_to_tractrix(ar, hh, tip)),
                    "natural": largest(
                        ar, point_distance(ar, tip, lc.tractrix(ar, hh, built.axis_points[:, 0]))
                    ),
                    "inequality-22-y": largest(ar, abs(1 / (f_y + g_y) - 1 / (f + g))),
                    "inequality-22-x": largest(
                        ar, abs((f_x - g_x) / (f_x + g_x) - (f - g) / (f + g))
                    ),
                },
                resolution={
                    "parametric": local,
                    "distance": local,
                    "vertices": noise,
                    "vertices-distance": noise,
                    "natural": noise,
                    "inequality-22-y": ar.tolerance(unit_power_steps(ar, hh, dd, x_max)),
                    "inequality-22-x": ar.tolerance(unit_power_steps(ar, hh, dd, x_max)),
                },
            )
        )
        with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
            printed = lc.theorem_15_curve_printed(ar, hh, dd, parameter)
            interpolation.add(
                ar,
                np.maximum(
                    relative_point_difference(ar, printed, tip),
                    relative_point_difference(ar, lc.theorem_15_curve(ar, hh, dd, parameter), tip),
                ),
                2 * size + powers,
                keep=printable(ar, hh, dd, parameter, 1.0),
            )
            curve = lc.theorem_15_curve_printed(ar, hh, dd, x)
            keep = printable(ar, hh, dd, x, 1.0)
            pf, pg = lc.substitution_15_y(ar, hh, dd, x, printed=True)
            proof_y.add(
                ar,
                relative_difference(ar, 2 * hh / (f_y + g_y), curve[:, 1]),
                powers,
                relative_difference(ar, 2 * hh / (pf + pg), curve[:, 1]),
                keep,
            )
            fraction = (x + dd - curve[:, 0]) / hh
            qf, qg = lc.substitution_15_x(ar, hh, dd, x, printed=True)
            proof_x.add(
                ar,
                abs((g_x - f_x) / (g_x + f_x) - fraction),
                powers,
                abs((qg - qf) / (qg + qf) - fraction),
                keep,
            )
    parameters = {"h": h, "d0": d0, "levels": levels, "x_max": x_max, "samples": samples}

    def checks(fits: dict[str, OrderFit]) -> list[Check]:
        return [
            converges(THEOREM_15, result, ("parametric",), fits),
            interpolation.check(ar, INTERPOLATION_15),
            proof_y.check(ar, PROOF_15_Y, ERRATUM_PROOF_Y),
            proof_x.check(ar, PROOF_15_X, ERRATUM_PROOF_X),
            converges(INEQUALITY_22, result, ("inequality-22-y", "inequality-22-x"), fits),
        ]

    return finish(THEOREM_15_INFO, ar, parameters, result, checks)
