"""The fits' summary by reciprocals (``fused_checks._ratio_scales``): where it applies, its
constants and largest residuals within rounding of ``_fits``'s; where it does not (a NaN, an
infinite, zero or extreme column), ``_fits``'s bits."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry.d4b import discretization
from app.geometry.d4b.fused_checks import FIT_BLOCK, Fits, fits_arrays, fits_summary
from app.geometry.precision import Float64
from tests.geometry.fit_rounding import summary_close


def _bits(a: np.ndarray) -> np.ndarray:
    return np.asarray(a, dtype=np.float64).view(np.int64)


@pytest.mark.parametrize(
    ("d", "beta0", "i_min", "i_max"),
    [
        (0.5, None, -200, 300),
        (1e-3, None, -700, 900),
        (1e-4, None, -5000, 5000),
        (0.1, 1.2, -300, 2000),
        (0.99, None, -20, 60),
    ],
)
def test_d4b_summary_by_reciprocals_is_within_rounding(
    d: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    """D4b polygons: the summary's constants and largest residuals within their rounding
    bounds of ``_fits``'s, the same existence, and far below any tolerance (1e-12)."""
    data = discretization.polygons(Float64(), 1.0, d, beta0, i_min, i_max)
    p = data.p[: data.vertices - 1]
    found, expected = fits_summary(p), fits_arrays(p)[0]
    assert summary_close(found, expected, p)
    assert np.array_equal(found[3:6], expected[3:6])
    assert np.all(abs(found[:3] - expected[:3]) <= 1e-12 * abs(expected[:3]))
    assert np.all(abs(found[6:] - expected[6:]) <= 1e-15)


def _quotient_polygons() -> list[np.ndarray]:
    """Polygons whose ratios leave the reciprocals' range or are NaN: a NaN or ±inf
    coordinate at and beside block edges, coordinates near the top of the range, subnormal
    ones, a line (Δ²y = 0: no (D1) constant), too few vertices."""
    rng = np.random.default_rng(13)
    m = 2 * FIT_BLOCK + 5
    out: list[np.ndarray] = [np.zeros((0, 2)), np.zeros((1, 2)), np.zeros((2, 2))]
    for at in (0, FIT_BLOCK - 1, FIT_BLOCK, FIT_BLOCK + 1, m - 1):
        for value in (np.nan, np.inf, -np.inf):
            p = rng.standard_normal((m, 2))
            p[at, at % 2] = value
            out.append(p)
    out.append(1e307 * rng.standard_normal((m, 2)))
    out.append(2.0**-1074 * rng.integers(-50, 50, (m, 2)).astype(float))
    x = np.arange(m, dtype=float)
    out.append(np.stack([x, 3.0 * x + 1.0], axis=1))
    return out


@pytest.mark.parametrize("p", _quotient_polygons())
def test_the_summary_keeps_the_quotients_where_reciprocals_do_not_apply(p: np.ndarray) -> None:
    with np.errstate(all="ignore"):
        assert np.array_equal(_bits(fits_summary(p)), _bits(fits_arrays(p)[0]))


@pytest.mark.parametrize(
    "count", [3, 4, FIT_BLOCK - 1, FIT_BLOCK, FIT_BLOCK + 1, FIT_BLOCK + 2, 3 * FIT_BLOCK + 1]
)
def test_the_summary_by_reciprocals_at_block_edges(count: int) -> None:
    """Random polygons of a block's size ± 1 (the last block of one, two, three edges): within
    rounding; a strided copy gives the same bits."""
    rng = np.random.default_rng(count)
    p = np.cumsum(rng.uniform(0.1, 1.0, (count, 2)), axis=0)
    found = fits_summary(p)
    assert summary_close(found, fits_arrays(p)[0], p)
    wide = np.zeros((count, 3))
    wide[:, :2] = p
    assert np.array_equal(_bits(fits_summary(wide[:, :2])), _bits(found))


def test_detail_fits_keep_the_constants_of_their_residuals() -> None:
    """``Fits.fits`` pairs each residual array with the constant it was computed with
    (``_fits``'s), with or without the summary's constants beside it."""
    data = discretization.polygons(Float64(), 1.0, 1e-3, None, -300, 400)
    p = data.p[: data.vertices - 1]
    arrays = fits_arrays(p)
    for fits in (Fits(p), Fits(p, arrays)):
        for k, key in enumerate(("d1", "d3", "eq2")):
            assert fits.fits[key].constant == arrays[0][k]
