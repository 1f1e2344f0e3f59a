"""Theorem 6 near a first stick along the axis: holds on the construction, fails when moved."""

from __future__ import annotations

import math

import pytest

from app.geometry.d4b import discretization as d4b
from app.geometry.precision import Float64, MultiPrecision


def _theorem_6(ar, beta0: float, d: float, shift: float = 0.0) -> d4b.Check:  # type: ignore[no-untyped-def]
    data = d4b.polygons(ar, 1.0, d, beta0, -30, 30)
    if shift:
        moved = data.tractrix.copy()
        moved[10, 0] = moved[10, 0] + ar.scalar(shift)
        data = data.replaced(tractrix=moved)
    _, checks = d4b.evaluate(ar, 1.0, d, data, beta0=beta0)
    return next(check for check in checks if check.id == "theorem-6")


@pytest.mark.parametrize("beta0", [3.16e-9, 1e-6, 1e-4, math.pi - 1e-7, math.pi - 1e-4])
@pytest.mark.parametrize("d", [0.05, 0.1, 0.5])
def test_theorem_6_holds_near_the_axis(beta0: float, d: float) -> None:
    assert _theorem_6(Float64(), beta0, d).holds is True


@pytest.mark.parametrize("beta0", [3.16e-9, math.pi - 1e-7])
def test_theorem_6_fails_on_a_moved_point(beta0: float) -> None:
    assert _theorem_6(Float64(), beta0, 0.1, shift=1e-9).holds is False
    mp = MultiPrecision(30)
    assert _theorem_6(mp, beta0, 0.1).holds is True
    assert _theorem_6(mp, beta0, 0.1, shift=1e-25).holds is False


def test_the_inscribed_gauss_image_does_not_drift() -> None:
    """n_i over 12001 vertices at d = 5e-4 (the accumulated form drifted to 1e-11)."""
    ar = Float64()
    data = d4b.polygons(ar, 1.0, 5e-4, None, -6000, 6000)
    drift = abs(data.gauss.tractrix_gauss - data.gauss.closed_tractrix_gauss)
    assert float(drift.max()) < 1e-13
    _, checks = d4b.evaluate(ar, 1.0, 5e-4, data)
    verdicts = {check.id: check.holds for check in checks}
    assert verdicts["equation-18"] is True
    assert verdicts["theorem-7"] is True
