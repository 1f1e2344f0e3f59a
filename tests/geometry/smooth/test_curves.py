"""Smooth references: samples, the evolute from derivatives against an independent reference,
and the (S4) checks holding on true samples and failing on perturbed ones."""

from __future__ import annotations

import math
from dataclasses import replace

import mpmath
import numpy as np
import pytest

from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Float64, MultiPrecision
from app.geometry.smooth import curves as smooth, references as smooth_curves
from tests.reference import smooth as reference
from tests.reference.compare import worst_relative

XS = ["-3", "-0.7", "0.25", "1", "4.5"]


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(40)], ids=["float64", "mp40"])
def test_evolute_from_derivatives_agrees_with_numerical_differentiation(ar) -> None:
    points, centres = reference.tractrix_evolute("1.5", XS)
    x = ar.array([float(v) for v in XS])
    h = ar.scalar(1.5)
    d = smooth.tractrix(ar, h, x)
    first, second = smooth.tractrix_derivatives(ar, h, x)
    evolute = smooth.centres_of_curvature(ar, d, first, second)
    bound = 1e-12 if ar.mode == "float64" else 1e-35
    assert worst_relative(d, dict(enumerate(points)), range(5)) < bound
    assert worst_relative(evolute.centres, dict(enumerate(centres)), range(5)) < bound
    # (S4): the evolute is the catenary (x, h cosh(x/h)); here from an independent computation
    catenary = {k: (float(v), 1.5 * math.cosh(float(v) / 1.5)) for k, v in enumerate(XS)}
    assert worst_relative(evolute.centres, catenary, range(5)) < 1e-12


def test_samples_include_both_ends_and_the_cusp_is_not_evaluated(float64: Float64) -> None:
    curve = smooth_curves.compute_tractrix(float64, 1.0, -3.0, 3.0, 7)
    x = curve.companions["axis_points"].vertices[:, 0]
    np.testing.assert_allclose(x, [-3, -2, -1, 0, 1, 2, 3], atol=1e-15)
    np.testing.assert_allclose(curve.polygon.vertices[3], [0.0, 1.0], atol=1e-16)
    checks = {c.id: c for c in curve.checks}
    assert all(c.holds for c in checks.values())
    assert "cusp" in (checks["evolute-s4"].note or "")
    detailed = smooth_curves.compute_tractrix(float64, 1.0, -3.0, 3.0, 7, detail=True)
    evolute = next(c for c in detailed.checks if c.id == "evolute-s4")
    assert evolute.per_index is not None and 3 not in evolute.per_index.indices.tolist()


def test_catenary_samples(float64: Float64) -> None:
    curve = smooth_curves.compute_catenary(float64, 2.0, -1.0, 3.0, 5)
    np.testing.assert_allclose(
        curve.polygon.vertices[:, 1], 2 * np.cosh(np.array([-1.0, 0, 1, 2, 3]) / 2), rtol=1e-15
    )
    assert curve.checks == [] and curve.companions == {}


def test_checks_hold_at_40_digits(mp40: MultiPrecision) -> None:
    curve = smooth_curves.compute_tractrix(mp40, 0.8, -5.0, 2.0, 30)
    for check in curve.checks:
        assert check.holds is True and check.residual is not None and check.residual < 1e-38


@pytest.mark.parametrize(
    ("field", "failing"),
    [
        ("tractrix", {"tractrix-s4", "nikolaides-s4"}),
        ("evolute", {"evolute-s4", "nikolaides-s4"}),
        ("first", {"tractrix-s4"}),
    ],
)
def test_checks_fail_on_perturbed_samples(float64: Float64, field: str, failing: set) -> None:
    data = smooth_curves.tractrix_samples(float64, 1.0, -3.0, 2.0, 11)
    assert all(c.holds for c in smooth_curves.evaluate(float64, 1.0, data))
    points = getattr(data, field).copy()
    points[4] = points[4] * (1 + 1e-7) + 1e-7
    results = smooth_curves.evaluate(float64, 1.0, replace(data, **{field: points}))
    assert {c.id for c in results if c.holds is False} == failing


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((0.0, -1.0, 1.0, 5), "h must satisfy h > 0"),
        ((1.0, 1.0, 1.0, 5), "x_max must satisfy x_min < x_max"),
        ((1.0, 2.0, 1.0, 5), "x_max must satisfy x_min < x_max"),
        ((1.0, math.nan, 1.0, 5), "x_min must satisfy x_min is a finite number"),
        ((1.0, -1.0, 1.0, 1), "count must satisfy count >= 2"),
    ],
)
def test_domain_errors(float64: Float64, args: tuple, match: str) -> None:
    for compute in (smooth_curves.compute_catenary, smooth_curves.compute_tractrix):
        with pytest.raises(DomainError, match=match):
            compute(float64, *args)


def test_float64_range_limit(float64: Float64) -> None:
    with pytest.raises(NotRepresentableError, match=r"x_max must satisfy \|x_max\|/h <= 346"):
        smooth_curves.compute_catenary(float64, 1.0, 0.0, 400.0, 3)
    far = smooth_curves.compute_catenary(MultiPrecision(20), 1.0, 0.0, 400.0, 3)
    assert float(far.polygon.vertices[-1, 1]) == pytest.approx(math.exp(400) / 2, rel=1e-12)


def test_mp_refuses_arguments_it_cannot_resolve() -> None:
    with pytest.raises(NotRepresentableError, match=r"x_min must satisfy \|x_min\|/h <= 1e\+10"):
        smooth_curves.compute_tractrix(MultiPrecision(5), 0.1, -1e100, -1.0, 2)


@pytest.mark.parametrize(("digits", "bound"), [(None, 1e-14), (40, 1e-35)])
def test_catenary_offsets_are_at_normal_distance_eps(digits: int | None, bound: float) -> None:
    ar = Float64() if digits is None else MultiPrecision(digits)
    mpmath.mp.dps = 50
    h, eps = ar.scalar(1.5), ar.scalar(0.4)
    x = ar.array(["-2.5", "-1", "0", "0.3", "2"])
    above, below = smooth.catenary_offsets(ar, h, x, eps)
    for points, sign in ((above, 1), (below, -1)):
        for (qx, qy), t in zip(points.tolist(), x.tolist(), strict=True):
            t, hh = mpmath.mpf(t), mpmath.mpf(1.5)
            cx, cy = t, hh * mpmath.cosh(t / hh)
            dx, dy = mpmath.mpf(qx) - cx, mpmath.mpf(qy) - cy
            assert abs(mpmath.sqrt(dx**2 + dy**2) - mpmath.mpf("0.4")) < bound
            assert abs(dx + dy * mpmath.sinh(t / hh)) < bound * 10  # along the normal
            assert sign * dy > 0  # above or below


def test_catenary_offsets_refuse_eps_beyond_the_radius_of_curvature(float64: Float64) -> None:
    with pytest.raises(DomainError, match="eps"):
        smooth.catenary_offsets(float64, 1.0, np.array([0.0]), 1.0)
