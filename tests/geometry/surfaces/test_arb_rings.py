"""The compiled ring pass on balls (scales at ``RESIDUAL_BITS``): balls holding the exact residuals
the numpy code's balls hold, their upper bounds within 2^-26 relative of the numpy code's."""

from __future__ import annotations

import random
from typing import Any

import flint
import numpy as np
import pytest

from app.geometry import balls
from app.geometry.ball_arithmetic import Ball
from app.geometry.d4b import discretization as d4b
from app.geometry.surfaces import arb_rings, ring_curvature
from app.geometry.surfaces.revolution_formulas import equation_17_residuals

pytestmark = pytest.mark.skipif(not arb_rings.AVAILABLE, reason="no bundled libflint")


def _same(a: Any, b: Any) -> bool:
    """The same ball: equal midpoints and radii, bit for bit."""
    return bool(a.mid().man_exp() == b.mid().man_exp() and a.rad().man_exp() == b.rad().man_exp())


def _numpy(ar: Ball, meridian: Any, gauss: Any, curvature: Any) -> tuple[Any, Any, int]:
    """The residuals as the numpy code computes them (``d4b.curvature.evaluate`` before)."""
    theta = ar.pi / ring_curvature.RING_M
    faces = ring_curvature._ring_curvatures_in_the_meridian_plane(
        ar, meridian, gauss, ar.cos(theta), ar.sin(theta)
    )
    assert faces is not None
    if curvature is None:
        theorem = ar.maximum(ring_curvature.minimal_residuals(faces), faces.parallel)
    else:
        theorem = ar.maximum(
            ring_curvature.constant_curvature_residuals(faces, curvature), faces.parallel
        )
    k_res, h_res, defined = equation_17_residuals(ar, meridian[:, 1], gauss[:, 1], faces)
    both = np.where(defined, ar.maximum(k_res, h_res), ar.scalar(0))
    return theorem, both, int(np.count_nonzero(~defined))


def _close(got: Any, want: Any) -> bool:
    """Two balls of one exact residual (they overlap), their upper bounds within 2^-26
    relative: 2^-64 where the midpoint dominates; a residual at rounding level is mostly
    radius, which arb keeps to 30 bits and rounds at each step, so there the served pass's
    other order of roundings moves the bound by up to about 2^-29 (either way)."""
    if not got.overlaps(want):
        return False
    upper, expected = float(got.mid() + got.rad()), float(want.mid() + want.rad())
    return abs(upper - expected) <= 2.0**-26 * abs(expected) + 1e-300


def _compare(ar: Ball, meridian: Any, gauss: Any, curvature: Any) -> int:
    served = ring_curvature.ring_checks(ar, meridian, gauss, curvature)
    assert served is not None
    expected = _numpy(ar, meridian, gauss, curvature)
    assert served[2] == expected[2]
    for got, want in zip(served[:2], expected[:2], strict=True):
        assert len(got) == len(want) == len(meridian) - 1
        assert all(_close(a, b) for a, b in zip(got, want, strict=True))
    return served[2]


@pytest.mark.parametrize("digits", [50, 500])
def test_the_d4b_rings_agree_with_the_numpy_balls(digits: int) -> None:
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        h = ar.scalar(1)
        images = data.gauss
        skipped = _compare(ar, data.tractrix, images.tractrix_gauss, -1 / (h * h))
        skipped += _compare(ar, data.p, images.gauss, None)
        assert skipped == 1  # the face at the symmetric edge: (17) is 0/0 there


def _wide(values: list[float], rng: random.Random) -> np.ndarray:
    """Balls of radii from 0 to 1e-2, their midpoints carrying more bits than the working
    precision (so that python-flint's rounding of ``abs`` shows)."""
    out = np.empty(len(values), dtype=object)
    saved = flint.ctx.prec
    flint.ctx.prec = 3 * saved
    try:
        out[:] = [
            flint.arb(v) / 3 + flint.arb(0, 10.0 ** rng.randint(-40, -2) if k % 3 else 0)
            for k, v in enumerate(values)
        ]
    finally:
        flint.ctx.prec = saved
    return out


def test_wide_balls_and_the_fallback() -> None:
    rng = random.Random(7)
    ar = Ball(30)
    with balls.working_precision(ar.bits):
        count = 300
        meridian = np.empty((count, 2), dtype=object)
        gauss = np.empty((count, 2), dtype=object)
        meridian[:, 0] = _wide([rng.uniform(-5, 5) for _ in range(count)], rng)
        meridian[:, 1] = _wide([rng.uniform(0.1, 5) for _ in range(count)], rng)
        gauss[:, 0] = _wide([rng.uniform(-1, 1) for _ in range(count)], rng)
        gauss[:, 1] = _wide([rng.uniform(-1, 1) for _ in range(count)], rng)
        meridian[10, 1] = meridian[11, 1] = flint.arb(2)  # (17) 0/0 on face 10
        assert _compare(ar, meridian, gauss, ar.scalar(-0.25)) >= 1
        _compare(ar, meridian, gauss, None)
        meridian[20, 1] = -meridian[21, 1]  # a face whose area is not certainly positive
        assert ring_curvature.ring_checks(ar, meridian, gauss, None) is None
        gauss[5, 0] = 3  # not a ball: the numpy code runs
        assert arb_rings.ring_checks(meridian, gauss, flint.arb(1), flint.arb(0), None) is None


def test_the_compiled_maximum_is_the_balls_maximum() -> None:
    """(17)'s larger residual of the two rings per face: ``Ball.maximum``'s balls, and reduced
    the bounds of that column; a column with an entry not a ball is left to numpy."""
    ar = Ball(30)
    rng = random.Random(3)
    with balls.working_precision(ar.bits):
        a = _wide([rng.uniform(0, 2) for _ in range(300)], rng)
        b = _wide([rng.uniform(0, 2) for _ in range(300)], rng)
        want = ar.maximum(a, b)
        got = arb_rings.maximum(a, b, False)
        assert got is not None and all(_same(x, y) for x, y in zip(got, want, strict=True))
        reduced = arb_rings.maximum(a, b, True)
        assert reduced is not None and len(reduced) == 2
        for bound in (ar.largest_upper, ar.largest_lower):
            assert _same(bound(reduced), bound(want))
        mixed = a.copy()
        mixed[5] = 0.5
        assert arb_rings.maximum(mixed, b, True) is None


def _midpoints(balls_: Any) -> Any:
    out = np.empty(balls_.shape, dtype=object)
    out.flat[:] = [flint.arb(b.mid()) for b in balls_.flat]
    return out


@pytest.mark.parametrize("digits", [15, 50, 500])
def test_the_served_rings_hold_the_exact_residuals(digits: int) -> None:
    """On exact vertices (the midpoints of a D4b ring) the numpy code at four times the
    precision pins each residual to a narrow ball; the served pass's ball (scales at 64 bits)
    holds it, so its upper bound is one of the exact residual."""
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        h = ar.scalar(1)
        rings = [(data.tractrix, data.gauss.tractrix_gauss, -1 / (h * h))]
        rings.append((data.p, data.gauss.gauss, None))
        exact = []
        for meridian, gauss, curvature in rings:
            points = [_midpoints(a) for a in (meridian, gauss)]
            served = ring_curvature.ring_checks(ar, *points, curvature)
            assert served is not None
            exact.append((points, curvature, served))
    high = Ball(4 * digits)
    with balls.working_precision(high.bits):
        for (meridian, gauss), curvature, served in exact:
            k = None if curvature is None else flint.arb(curvature.mid())
            want = _numpy(high, meridian, gauss, k)
            assert served[2] == want[2]
            for got, narrow in zip(served[:2], want[:2], strict=True):
                assert all(a.contains(b) for a, b in zip(got, narrow, strict=True))
