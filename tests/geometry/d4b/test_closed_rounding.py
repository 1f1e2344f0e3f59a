"""The closed comparisons' rounding since session 22 (``fused_checks``): sech, tanh and cosh from
one exponential w = e^(−|t|) (the fraction form the paper gives (18) in) within a few ulp of
numpy's, the exponents made as the arguments are, and the blocks' way back to the old path (an
argument past ``DECAY_LIMIT``, a NaN) giving the old loops' bits."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.geometry.d4b import discretization, fused_checks
from app.geometry.d4b.fused_checks import (
    DECAY_LIMIT,
    _image_arguments,
    _image_decays,
    _kinematic_arguments,
    _kinematic_decays,
    _sech_tanh,
    closed_image_comparisons,
    closed_kinematic_comparisons,
)
from app.geometry.precision import BLOCK_SIZE, Float64
from tests.geometry.bits import same_bits
from tests.geometry.d4b.test_closed_comparisons import (
    _WANTED,
    _images,
    _old_images,
    _old_kinematic,
)

_EPS = 2.0**-52


def _arguments() -> np.ndarray:
    """t across the range the blocks take: 0, ±tiny, around ½ (where 1 − w is exact), steps of
    the long polygons, and up to ±``DECAY_LIMIT``."""
    rng = np.random.default_rng(22)
    special = [0.0, -0.0, 5e-324, 1e-300, 1e-17, 1e-8, 0.3, 0.6931, 1.0, 20.0, 354.0, 699.9]
    t = np.concatenate([special, rng.uniform(-1, 1, 4000), rng.uniform(-DECAY_LIMIT, 700, 4000)])
    return np.concatenate([t, -t, [DECAY_LIMIT, -DECAY_LIMIT]])


def test_sech_and_tanh_from_one_exponential_are_within_ulps_of_numpys() -> None:
    """tanh within 2 ulp of 1 (its scale in the unit vectors n_i, ñ_i: near 0 its error is w's,
    absolute), with t's sign and 0 at 0; sech within 4 ulp of itself (relative, down to
    e^−700)."""
    for t in _arguments():
        sech, th = _sech_tanh(t, math.exp(-abs(t)))
        expected_sech, expected_tanh = 1.0 / np.cosh(t), np.tanh(t)
        assert abs(th - expected_tanh) <= 2 * _EPS, (t, th, expected_tanh)
        assert abs(sech - expected_sech) <= 4 * _EPS * expected_sech, (t, sech, expected_sech)
        assert abs(th) <= 1.0 and 0.0 < sech <= 1.0
        assert th == 0.0 if t == 0.0 else math.copysign(1.0, th) == math.copysign(1.0, t)


@pytest.mark.parametrize(
    ("first", "count", "L", "shift"),
    [
        (-500000, BLOCK_SIZE, 2e-4, 0.0),
        (-3, 44, 1.0986, 0.37),
        (630, 16, 1.0986122886681098, 0.0),  # crosses DECAY_LIMIT inside the block
        (1, 1, 0.5, 0.25),
        (0, 5, math.nan, 0.0),
        (0, 5, math.inf, 0.5),
        (-2, 5, 1e-300, -0.5),
    ],
)
def test_decays_are_minus_the_magnitudes_of_the_arguments(
    first: int, count: int, L: float, shift: float
) -> None:
    """−|t| of exactly the arguments the old path computes, and the limit's verdict of all of
    them (the ends of a run are its largest: t is monotone in the index)."""
    arguments, decays = np.empty(2 * count), np.empty(2 * count)
    _kinematic_arguments(first, count, L, shift, arguments)
    inside = _kinematic_decays(first, count, L, shift, decays)
    assert same_bits(decays, -np.abs(arguments))
    with np.errstate(invalid="ignore"):
        assert inside == bool(np.all(np.abs(arguments) <= DECAY_LIMIT))
    arguments, decays = np.empty(2 * count + 1), np.empty(2 * count + 1)
    _image_arguments(first, count, L, shift, arguments)
    inside = _image_decays(first, count, L, shift, decays)
    assert same_bits(decays, -np.abs(arguments))
    with np.errstate(invalid="ignore"):
        assert inside == bool(np.all(np.abs(arguments) <= DECAY_LIMIT))


def test_blocks_past_the_limit_take_the_old_path_and_give_its_bits() -> None:
    """d = 0.5h: |t| passes 700 from i ≈ 637 and cosh overflows from i ≈ 647. A block with any
    |t| > 700 goes the old way (numpy's cosh, its None on overflow): its numbers are the old
    loops', bit for bit; below, the fast path's (within ulps, test_closed_comparisons)."""
    for i_min, i_max in [(600, 640), (630, 645), (-645, -600), (600, 660)]:
        data = discretization.polygons(Float64(), 1.0, 0.5, None, i_min, i_max)
        n = data.vertices - 1
        for theorem_5, theorem_6 in [(True, True), (True, False), (False, True)]:
            expected = _old_kinematic(data, n, theorem_5, theorem_6)
            found = closed_kinematic_comparisons(data, n, theorem_5, theorem_6)
            assert same_bits(found, expected), (i_min, found, expected)
        rng = np.random.default_rng(n)
        arrays = (*rng.uniform(-1, 1, (3, n + 1, 2)), *rng.uniform(0, 9, (2, n + 1)))
        for wanted in _WANTED:
            expected = _old_images(data, n, wanted, *arrays)
            found = closed_image_comparisons(
                data.ar, data.h, data.d, data.shift, data.i_min, n, wanted, *arrays
            )
            assert same_bits(found, expected), (i_min, wanted, found, expected)


def test_real_polygons_never_leave_the_fast_path(monkeypatch: pytest.MonkeyPatch) -> None:
    """The old blocks are not called on real polygons (every block on the fast path), and the
    perturbed polygon's residuals still show the perturbation."""

    def refused(*_: object) -> None:
        raise AssertionError("the old path was taken")

    monkeypatch.setattr(fused_checks, "_closed_kinematic_block", refused)
    monkeypatch.setattr(fused_checks, "_closed_image_block", refused)
    n = 2 * BLOCK_SIZE + 7
    data = discretization.polygons(Float64(), 1.0, 1e-3, 0.4, -(n // 2), n - n // 2 - 1)
    found = closed_kinematic_comparisons(data, n)
    assert found is not None and max(found) < 1e-9
    moved = closed_kinematic_comparisons(data.replaced(p=data.p * (1 + 1e-6)), n)
    assert moved is not None and moved[0] > 5e-7
    arrays = _images(data, n)
    found_images = closed_image_comparisons(
        data.ar, data.h, data.d, data.shift, data.i_min, n, (True,) * 6, *arrays
    )
    assert found_images is not None and max(found_images[:3]) < 1e-6
    assert min(found_images[3:]) > 0.1  # the printed forms' errata
