"""The compiled ring pass on balls gives the very balls of the numpy code it replaces."""

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


def _compare(ar: Ball, meridian: Any, gauss: Any, curvature: Any) -> int:
    fused = ring_curvature.ring_checks(ar, meridian, gauss, curvature)
    assert fused is not None
    expected = _numpy(ar, meridian, gauss, curvature)
    assert fused[2] == expected[2]
    for got, want in zip(fused[:2], expected[:2], strict=True):
        assert len(got) == len(want) == len(meridian) - 1
        assert all(_same(a, b) for a, b in zip(got, want, strict=True))
    return fused[2]


@pytest.mark.parametrize("digits", [50, 500])
def test_the_d4b_rings_are_the_numpy_balls(digits: int) -> None:
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
