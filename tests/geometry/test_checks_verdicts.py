"""A residual that cannot be computed never passes a check (issue 15)."""

from __future__ import annotations

from decimal import Decimal

import flint
import numpy as np
import pytest

from app.geometry import balls
from app.geometry.ball_arithmetic import Ball
from app.geometry.checks import IndexRange, Statement, check_residuals
from app.geometry.curvature import planarity
from app.geometry.precision import Float64, MultiPrecision

STATEMENT = Statement("example", "nowhere", "a claim")
INDICES = np.arange(3)


def test_finite_residuals_decide() -> None:
    ar = Float64()
    assert check_residuals(STATEMENT, ar, INDICES, np.array([0.0, 1e-17, 0.0]), 1e-15, False).holds
    fails = check_residuals(STATEMENT, ar, INDICES, np.array([0.0, 1e-3, 0.0]), 1e-15, False)
    assert fails.holds is False


def test_an_uncomputable_residual_is_not_a_pass() -> None:
    ar = Float64()
    values = np.array([0.0, np.inf, np.nan])
    check = check_residuals(STATEMENT, ar, INDICES, values, 1e-15, False)
    assert check.holds is None
    assert check.residual is None
    assert "2 of 3 residuals could not be computed" in (check.note or "")


def test_an_uncomputable_residual_beside_a_counterexample_fails() -> None:
    values = np.array([1.0, np.inf, 0.0])
    check = check_residuals(STATEMENT, Float64(), INDICES, values, 1e-15, False)
    assert check.holds is False
    assert check.residual == 1.0


def _face(scale: float, lift: float) -> np.ndarray:
    square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, lift], [0, 1, 0]], dtype=np.float64)
    return (scale * square)[None]


def test_planarity_of_huge_faces_is_measured_not_overflowed() -> None:
    ar = Float64()
    for scale in (1.0, 1e120, 1e300):
        assert planarity(ar, _face(scale, 0.0))[0] == 0.0
        bent = planarity(ar, _face(scale, 0.5))[0]
        assert np.isfinite(bent)
        assert abs(bent - planarity(ar, _face(1.0, 0.5))[0]) < 1e-15
    mp = MultiPrecision(30)
    face = np.array(
        [[[mp.scalar(v) * mp.scalar("1e400") for v in row] for row in _face(1.0, 0.5)[0]]],
        dtype=object,
    )
    assert abs(float(planarity(mp, face)[0]) - planarity(ar, _face(1.0, 0.5))[0]) < 1e-15


def test_on_balls_an_uncomputable_residual_shows_none_per_index() -> None:
    """Per index on balls: the decimal upper bound of each finite residual, None elsewhere."""
    ar = Ball(30)
    with balls.working_precision(ar.bits):
        values = np.array([flint.arb(0), flint.arb("inf"), flint.arb("1e-40")], dtype=object)
        check = check_residuals(STATEMENT, ar, INDICES, values, 1e-25, True)
    assert check.holds is None and check.residual is None
    assert "1 of 3 residuals could not be computed" in (check.note or "")
    assert check.per_index is not None
    zero, missing, small = check.per_index.residuals
    assert zero == 0 and missing is None
    assert small is not None and Decimal("1e-40") <= small <= Decimal("1.000000001e-40")


def test_an_index_range_is_the_arange_it_stands_for() -> None:
    """``IndexRange`` (the indices a D4b check reads, made only when shown): its slices, its
    length and its array are those of ``np.arange``; a check's indices per index are the same."""
    indices, plain = IndexRange(-7, 12), np.arange(-7, 5, dtype=np.int64)
    for rows in (slice(None), slice(3), slice(2, 9), slice(-4, None), slice(20, 30), slice(5, 2)):
        assert np.array_equal(np.asarray(indices[rows]), plain[rows])
        assert len(indices[rows]) == len(plain[rows])
    assert np.asarray(indices).dtype == np.int64
    with pytest.raises(ValueError, match="step 1"):
        indices[::2]
    values = np.array([0.0, np.inf, 1e-17])
    for detail in (True, False):
        lazy = check_residuals(STATEMENT, Float64(), IndexRange(4, 3), values, 1e-15, detail)
        eager = check_residuals(STATEMENT, Float64(), np.arange(4, 7), values, 1e-15, detail)
        assert (lazy.holds, lazy.residual, lazy.note) == (eager.holds, eager.residual, eager.note)
        if detail:
            assert lazy.per_index is not None and eager.per_index is not None
            assert np.array_equal(lazy.per_index.indices, [4, 5, 6])
            assert np.array_equal(lazy.per_index.indices, eager.per_index.indices)
