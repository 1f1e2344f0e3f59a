"""Theorems 14 and 15 as formulas: the printed curves, their cosh/tanh forms, the proofs' steps.

Every value here is compared with something computed another way: the (D4b) construction, the
closed forms (14) and (16) of the kinematic module, plain mpmath, or the smooth limits.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from app.geometry.d4b import closed_forms as kcf
from app.geometry.d4b.construction import construct
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from app.geometry.studies import limit_curves as lc


def relative(ar: Arithmetic, a: np.ndarray, b: np.ndarray) -> float:
    """Largest |a_k − b_k| / |b_k| over points (rows) or numbers, computed in mpmath."""
    ctx = mpmath.MPContext()
    ctx.dps = 80
    a2, b2 = a.reshape(len(a), -1), b.reshape(len(b), -1)
    worst = 0.0
    for u, v in zip(a2, b2, strict=True):
        diff = ctx.sqrt(sum((ctx.mpf(p) - ctx.mpf(q)) ** 2 for p, q in zip(u, v, strict=True)))
        size = ctx.sqrt(sum(ctx.mpf(q) ** 2 for q in v))
        worst = max(worst, float(diff / size))
    return worst


@pytest.mark.parametrize(("ar", "tol"), [(Float64(), 1e-12), (MultiPrecision(40), 1e-35)])
@pytest.mark.parametrize(("h", "d"), [(1.0, 0.1), (2.5, 0.7), (0.3, 0.01)])
def test_printed_curves_pass_through_the_constructed_vertices(
    ar: Arithmetic, tol: float, h: float, d: float
) -> None:
    built = construct(ar, h, d, None, -12, 12)
    hh, dd = ar.scalar(h), ar.scalar(d)
    x = built.centres[:, 0]  # (2i − 1)d
    assert relative(ar, lc.theorem_14_curve_printed(ar, hh, dd, x), built.centres) < tol
    assert relative(ar, lc.theorem_14_curve(ar, hh, dd, x), built.centres) < tol
    assert relative(ar, lc.theorem_15_curve_printed(ar, hh, dd, x), built.tractrix) < tol
    assert relative(ar, lc.theorem_15_curve(ar, hh, dd, x), built.tractrix) < tol


def test_the_curves_agree_with_the_closed_forms_14_and_16_at_the_vertices(
    mp40: MultiPrecision,
) -> None:
    ar = mp40
    h, d = ar.scalar(1.5), ar.scalar(0.4)
    i = ar.indices(-8, 8)
    x = (2 * i - 1) * d
    p = kcf.hyperbolic_cosine_printed(ar, h, d, i)
    tip = kcf.tractrix_printed(ar, h, d, i)
    assert relative(ar, lc.theorem_14_curve_printed(ar, h, d, x), p) < 1e-38
    assert relative(ar, lc.theorem_15_curve_printed(ar, h, d, x), tip) < 1e-38


def test_cosh_forms_equal_the_printed_forms_between_the_vertices(mp40: MultiPrecision) -> None:
    ar = mp40
    h, d = ar.scalar(1.0), ar.scalar(0.15)
    x = ar.array(np.linspace(-3.1, 2.9, 37))
    assert (
        relative(ar, lc.theorem_14_curve(ar, h, d, x), lc.theorem_14_curve_printed(ar, h, d, x))
        < 1e-38
    )
    assert (
        relative(ar, lc.theorem_15_curve(ar, h, d, x), lc.theorem_15_curve_printed(ar, h, d, x))
        < 1e-38
    )


def test_rearrangement_of_the_proof_of_theorem_14_is_an_identity(mp40: MultiPrecision) -> None:
    ar = mp40
    h, d = ar.scalar(2.0), ar.scalar(0.3)
    x = ar.array(np.linspace(-4, 4, 17))
    assert (
        relative(
            ar,
            lc.theorem_14_curve_rearranged(ar, h, d, x),
            lc.theorem_14_curve_printed(ar, h, d, x),
        )
        < 1e-38
    )


def test_equation_21_substitution_and_limit(mp40: MultiPrecision) -> None:
    ar = mp40
    h = ar.scalar(1.3)
    x = ar.array([-2.0, -0.5, 0.25, 1.0, 3.0])
    for d in (0.1, 0.01):
        dd = ar.scalar(d)
        assert (
            relative(ar, lc.power_21_substituted(ar, h, dd, x), lc.power_21(ar, h, dd, x)) < 1e-38
        )
    # the limit, with plain mpmath for e^{−x/(2h)}
    ctx = mpmath.MPContext()
    ctx.dps = 50
    expected = [ctx.exp(-ctx.mpf(v) / (2 * ctx.mpf("1.3"))) for v in (-2, -0.5, 0.25, 1, 3)]
    errors = []
    for d in ("1e-2", "1e-3", "1e-4"):
        got = lc.power_21(ar, h, ar.scalar(d), x)
        errors.append(max(abs(float(g) - float(e)) for g, e in zip(got, expected, strict=True)))
    assert errors[0] > 9 * errors[1] > 81 * errors[2] > 0  # first order: ×10 per decade


def test_cosh_forms_tend_to_the_smooth_curves(float64: Float64) -> None:
    ar = float64
    h = 1.7
    x = np.linspace(-3, 3, 41)
    previous = None
    for d in (0.1, 0.05, 0.025):
        gap = np.max(np.abs(lc.theorem_14_curve(ar, h, d, x)[:, 1] - h * np.cosh(x / h)))
        if previous is not None:
            assert gap == pytest.approx(previous / 4, rel=0.02)  # order 2
        previous = gap
    # Theorem 15: the same parameter lags by d (order 1); the shifted parameter has order 2
    for d in (0.01, 0.005):
        c = lc.theorem_15_curve(ar, h, d, x)
        same = np.max(np.hypot(*(c - lc.tractrix(ar, h, x)).T))
        shifted = np.max(np.hypot(*(c - lc.tractrix(ar, h, x + d)).T))
        assert same == pytest.approx(d * np.tanh(3 / h), rel=0.02)
        assert shifted < 2 * d * d


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(30)], ids=["float64", "mp30"])
def test_printed_substitutions_of_the_proof_of_theorem_15_are_wrong(ar: Arithmetic) -> None:
    h, d = ar.scalar(1.0), ar.scalar(0.1)
    x = ar.array(np.linspace(-2, 2, 9))
    c = lc.theorem_15_curve_printed(ar, h, d, x)
    f, g = lc.substitution_15_y(ar, h, d, x)
    pf, pg = lc.substitution_15_y(ar, h, d, x, printed=True)
    assert relative(ar, 2 * h / (f + g), c[:, 1]) < 64 * ar.eps * 100
    assert relative(ar, 2 * h / (pf + pg), c[:, 1]) > 0.3  # E80
    fraction = (x + d - c[:, 0]) / h
    f, g = lc.substitution_15_x(ar, h, d, x)
    pf, pg = lc.substitution_15_x(ar, h, d, x, printed=True)
    assert float(np.max(ar.to_floats(abs((g - f) / (g + f) - fraction)))) < 64 * ar.eps * 100
    assert float(np.max(ar.to_floats(abs((pg - pf) / (pg + pf) - fraction)))) > 0.5  # E81
    # the printed f(d), g(d) tend to 1, not to e^{∓x/h}: 2h/(f + g) -> h, not h/cosh(x/h)
    small = ar.scalar(1e-6)
    pf, pg = lc.substitution_15_y(ar, h, small, x, printed=True)
    assert float(np.max(ar.to_floats(abs(2 * h / (pf + pg) - h)))) < 1e-11


def test_limits_of_the_corrected_substitutions(mp40: MultiPrecision) -> None:
    ar = mp40
    h = ar.scalar(0.8)
    x = ar.array([-1.5, 0.0, 0.7, 2.0])
    lim_f, lim_g = lc.limits_15(ar, h, x)
    for substitution in (lc.substitution_15_y, lc.substitution_15_x):
        f, g = substitution(ar, h, ar.scalar("1e-12"), x)
        assert relative(ar, f, lim_f) < 1e-9
        assert relative(ar, g, lim_g) < 1e-9
