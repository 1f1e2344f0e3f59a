"""The fused float64 passes of (D4b)'s checks give the numbers of the separate ones, bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry import conditions
from app.geometry.checks import relative_to
from app.geometry.d4b import discretization, residual_kernels
from app.geometry.d4b.fused_checks import (
    FIT_BLOCK,
    Fits,
    _buffers,
    closed_comparisons,
    closed_kinematic_comparisons,
    fill_closed_forms,
    fits_arrays,
    fits_summary,
)
from app.geometry.precision import Float64
from tests.geometry.d4b.test_closed_comparisons import close_residuals
from tests.geometry.fit_rounding import summary_close


def _same(a: object, b: object) -> bool:
    """Equal bits (NaN equal to NaN, +0 apart from −0)."""
    return np.array_equal(
        np.asarray(a, dtype=np.float64).view(np.int64),
        np.asarray(b, dtype=np.float64).view(np.int64),
    )


def _separate(p: np.ndarray) -> tuple[dict[str, conditions.ConditionFit], np.ndarray]:
    """The fits as ``d4b.checks`` took them: ``conditions.Columns``, then eq. (2)'s misfit."""
    columns = conditions.Columns(p)
    fits = {
        "d1": columns.fit(conditions.D1),
        "d3": columns.fit(conditions.D3),
        "eq2": columns.fit(conditions.EQUATION_2),
    }
    c1, c2 = fits["d1"].constant, fits["d3"].constant
    both = fits["eq2"].residuals
    if c1 is not None and c2 is not None and c2 != 0 and len(both):
        both = np.maximum(both, columns.misfit(conditions.EQUATION_2, c1 / c2))
    return fits, both


def _polygons() -> list[np.ndarray]:
    ar = Float64()
    out = []
    for h, d, i_min, i_max in [
        (1.0, 0.1, -50, 49),
        (1.0, 0.1, -10, 10),
        (2.5, 0.7, -3, 40),
        (1.0, 0.99, -20, 5),
        (1.0, 1e-3, 0, 300),
        (1.0, 0.1, 0, 0),
        (1.0, 0.1, 0, 1),
        (1.0, 0.1, 0, 2),
    ]:
        data = discretization.polygons(ar, h, d, None, i_min, i_max)
        out.append(data.p[: data.vertices - 1])
    rng = np.random.default_rng(7)
    out += [rng.standard_normal((m, 2)) for m in (1, 2, 3, 9, 17, 130)]
    out.append(np.zeros((12, 2)))
    line = np.stack([np.arange(10.0), np.full(10, 2.0)], axis=1)  # Δ²y = 0: no (D1) constant
    out.append(line)
    broken = rng.standard_normal((20, 2))
    broken[5, 1] = np.nan
    out.append(broken)
    broken = rng.standard_normal((20, 2))
    broken[3, 0] = np.inf
    out.append(broken)
    # beyond one block of the summary passes, and a last block of one, two and three edges
    for m in (FIT_BLOCK + 1, FIT_BLOCK + 2, FIT_BLOCK + 3, 2 * FIT_BLOCK + 2, 5000):
        out.append(rng.standard_normal((m, 2)))
    # hypot's scaled ranges (edges longer than 2^511, shorter than 2^-459, very flat ones)
    out.append(rng.standard_normal((300, 2)) * np.exp(rng.uniform(-700, 700, (300, 1))))
    flat = np.stack([np.arange(400.0), 1e-20 * rng.standard_normal(400)], axis=1)
    out.append(flat)
    out.append(np.ascontiguousarray(flat[:, ::-1]))  # steep: hypot's a + b, the other way
    x = np.linspace(-50.0, 50.0, 3001)  # a long cosh's ends: |Δy| > 2^54 |Δx| (a + b again)
    out.append(np.stack([x, np.cosh(x)], axis=1))
    broken = rng.standard_normal((3000, 2))
    broken[2500, 1] = np.nan  # a NaN in the third block only
    out.append(broken)
    broken = rng.standard_normal((3000, 2))
    broken[1500, 0] = -np.inf
    out.append(broken)
    return out


@pytest.mark.parametrize("p", _polygons())
def test_fits_have_the_separate_numbers(p: np.ndarray) -> None:
    fused = Fits(p)
    separate, both = _separate(p)
    for key in ("d1", "d3", "eq2"):
        a, b = fused.fits[key], separate[key]
        assert (a.constant is None) == (b.constant is None)
        if b.constant is not None:
            assert type(a.constant) is type(b.constant)
            assert _same(a.constant, b.constant)
        assert _same(a.residuals, b.residuals)
    assert _same(fused.equation_2, both)
    assert all(type(value) is float for value in fused.largest.values())
    # the largest from the summary: within rounding (tests/geometry/fit_rounding.py)
    assert summary_close(fits_summary(p), fits_arrays(p)[0], p)
    for key, residuals in (("d1", separate["d1"].residuals), ("d3", separate["d3"].residuals)):
        if len(residuals):
            assert _near(fused.largest[key], np.abs(residuals).max())
    if len(both):
        assert _near(fused.largest["eq2"], np.abs(both).max())


def _near(a: float, b: float) -> bool:
    """A largest residual of the summary beside the separate one: equal, or both finite and
    within 1e-12 (the residuals of these polygons are below 1; a constant's move of a few ulp
    moves them by about as much, relative to their scale)."""
    return _same(a, b) or (bool(np.isfinite(a) and np.isfinite(b)) and abs(a - b) <= 1e-12)


@pytest.mark.parametrize("p", _polygons())
def test_fits_summary_has_the_bits_of_the_fits_with_their_residuals(p: np.ndarray) -> None:
    """The summary passes (no array of the polygon's size) give the constants and largest
    residuals of the kernel that stores the columns and residuals, within rounding
    (``summary_close``: the summary multiplies by reciprocals); a strided p gives the same
    bits as a contiguous one."""
    arrays = fits_arrays(p)
    assert summary_close(fits_summary(p), arrays[0], p)
    wide = np.zeros((len(p), 3))
    wide[:, :2] = p
    assert _same(fits_summary(wide[:, :2]), fits_summary(p))
    alone, given = Fits(p), Fits(p, arrays)
    assert alone.constants.keys() == given.constants.keys()
    for key in alone.constants:
        a, b = alone.constants[key], given.constants[key]
        assert (a is None) == (b is None)
        assert a is None or b is None or _same(a, b) or abs(a - b) <= 1e-12 * abs(b)
        assert _near(alone.largest[key], given.largest[key])
        assert _same(alone.fits[key].constant, given.fits[key].constant)
        assert alone.counts[key] == len(given.fits[key].residuals)
    assert _same(alone.equation_2, given.equation_2)


def _adversarial() -> list[np.ndarray]:
    """Polygons for the summary passes' stored lengths and pass 4's test without divisions
    (``_may_raise``): NaN and ±inf at and beside block edges, zero-length edges, ±0, subnormal
    and huge coordinates (hypot's scaled ranges, residuals that overflow or underflow),
    residuals growing along the polygon (the largest raised in every block) or all equal."""
    rng = np.random.default_rng(21)
    out: list[np.ndarray] = [np.zeros((0, 2)), np.zeros((1, 2)), np.zeros((2, 2))]
    m = 2 * FIT_BLOCK + 5
    for at in (0, 1, FIT_BLOCK - 1, FIT_BLOCK, FIT_BLOCK + 1, FIT_BLOCK + 2, m - 1):
        for value in (np.nan, np.inf, -np.inf):
            for column in (0, 1):
                p = rng.standard_normal((m, 2))
                p[at, column] = value
                out.append(p)
    p = rng.standard_normal((m, 2))
    p[100:300] = p[100]  # zero-length edges, Δ²y = 0
    p[FIT_BLOCK - 3 : FIT_BLOCK + 4] = 0.0
    p[FIT_BLOCK + 10 :: 7] *= -0.0
    out.append(p)
    tiny = 2.0**-1074 * rng.integers(-50, 50, (m, 2)).astype(float)  # subnormal, zeros
    out.append(tiny)
    out.append(tiny + 1e-300 * rng.standard_normal((m, 2)))
    out.append(1e307 * rng.standard_normal((m, 2)))  # lengths and sums that overflow
    scaled = rng.standard_normal((m, 2)) * np.exp(rng.uniform(-745, 709, (m, 1)))
    out.append(scaled)
    grow = rng.standard_normal((m, 2)) * np.linspace(1e-3, 1e3, m)[:, None] ** 3
    out.append(np.cumsum(np.abs(grow), axis=0))
    out.append(np.cumsum(np.abs(grow[::-1]), axis=0))
    x = np.arange(m, dtype=float)
    out.append(np.stack([x, 3.0 * x + 1.0], axis=1))  # a line: residuals 0 or equal
    out.append(np.stack([x, x * x], axis=1))  # Δ²y constant
    for count in (FIT_BLOCK - 1, FIT_BLOCK, FIT_BLOCK + 1, 3 * FIT_BLOCK + 1):
        out.append(rng.standard_normal((count, 2)))
    return out


@pytest.mark.parametrize("p", _adversarial())
def test_fits_summary_on_adversarial_polygons_has_the_bits_of_the_fits(p: np.ndarray) -> None:
    """The summary (lengths computed once, pass 4's largest residuals found without dividing
    where they cannot count, the terms by reciprocals where the polygon allows) against
    ``_fits``, which stores every column and residual: within rounding, NaN, infinities and
    existence the same (``summary_close``)."""
    with np.errstate(all="ignore"):
        expected = fits_arrays(p)[0]
        found = fits_summary(p)
        assert summary_close(found, expected, p)
        strided = np.zeros((len(p), 3))
        strided[:, :2] = p
        assert _same(fits_summary(strided[:, :2]), found)


def test_fits_summary_on_random_polygons_has_the_bits_of_the_fits() -> None:
    """Random polygons of random sizes and scales, and cosh-like ones (their residuals at
    rounding level, many of them equal)."""
    rng = np.random.default_rng(2021)
    for _ in range(40):
        m = int(rng.integers(0, 4 * FIT_BLOCK))
        p = rng.standard_normal((m, 2)) * 10.0 ** rng.uniform(-200, 200)
        assert summary_close(fits_summary(p), fits_arrays(p)[0], p)
        x = np.linspace(-rng.uniform(0.1, 40), rng.uniform(0.1, 40), m)
        p = np.stack([x, np.cosh(x)], axis=1)
        assert summary_close(fits_summary(p), fits_arrays(p)[0], p)


def test_fits_summary_of_a_long_d4b_has_the_bits_of_the_stored_columns() -> None:
    """200 001 vertices of (D4b) (about 1600 leaves of numpy's pairwise sums, 196 blocks)."""
    data = discretization.polygons(Float64(), 1.0, 1e-4, None, -100_000, 100_000, "closed-form")
    p = data.p[: data.vertices - 1]
    assert summary_close(fits_summary(p), fits_arrays(p)[0], p)


#: glibc's mmap threshold as ``make run`` and the Dockerfile set it (MALLOC_MMAP_THRESHOLD_).
MMAP_THRESHOLD = 128 * 1024


@pytest.mark.parametrize("edges", [0, 1, 99, FIT_BLOCK - 1, FIT_BLOCK, FIT_BLOCK + 1, 10**6])
def test_the_fits_buffers_are_as_wide_as_the_largest_block(edges: int) -> None:
    """A short polygon's fits allocate a few KiB, below the server's mmap threshold (the
    served worker mapped, faulted in and unmapped 128 KiB for most 100-vertex requests); a long
    one's blocks keep their FIT_BLOCK + 2 columns."""
    buffers = _buffers(edges)
    assert buffers.shape == (16, min(edges, FIT_BLOCK) + 2)
    if edges < 1000:
        assert buffers.nbytes < MMAP_THRESHOLD


_CLOSED = ("closed_p", "closed_tractrix")
_CLOSED_IMAGES = ("closed_tractrix_gauss", "closed_contact", "closed_gauss")


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max", "method"),
    [
        (1.0, 0.1, None, -50, 49, "construction"),
        (1.0, 0.1, None, -10, 10, "closed-form"),
        (1.0, 0.3, 0.5, -15, 15, "construction"),
        (1.0, 0.3, 2.4, -15, 15, "closed-form"),
        (2.5, 0.7, 1e-3, -3, 40, "construction"),
        (1.0, 0.99, None, -20, 5, "construction"),
        (100.0, 1.0, 1.2, -300, 300, "construction"),
        (1.0, 1e-3, None, 0, 3000, "construction"),
        (1.0, 0.1, None, 0, 0, "construction"),
        # beyond one block (8192 rows): three blocks, the last a short one
        (1.0, 1e-3, 0.7, -9000, 11000, "construction"),
        (1.0, 1e-4, None, -8191, 0, "closed-form"),
    ],
)
def test_closed_forms_have_the_separate_bits(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int, method: str
) -> None:
    ar = Float64()
    fused = discretization.polygons(ar, h, d, beta0, i_min, i_max, method)  # type: ignore[arg-type]
    fill_closed_forms(fused)
    assert all(name in vars(fused) for name in _CLOSED)
    assert all(name in vars(fused.gauss) for name in _CLOSED_IMAGES)
    separate = discretization.polygons(ar, h, d, beta0, i_min, i_max, method)  # type: ignore[arg-type]
    for name in _CLOSED:
        a, b = getattr(fused, name), getattr(separate, name)
        assert a.shape == b.shape and a.flags.c_contiguous and _same(a, b), name
    for name in _CLOSED_IMAGES:
        a, b = getattr(fused.gauss, name), getattr(separate.gauss, name)
        assert a.shape == b.shape and a.flags.c_contiguous and _same(a, b), name


@pytest.mark.parametrize(("images", "kinematic"), [(True, False), (False, True)])
def test_closed_forms_make_only_those_asked_for(images: bool, kinematic: bool) -> None:
    ar = Float64()
    fused = discretization.polygons(ar, 1.0, 1e-3, 0.4, -5000, 9000)
    fill_closed_forms(fused, images, kinematic)
    separate = discretization.polygons(ar, 1.0, 1e-3, 0.4, -5000, 9000)
    assert all((name in vars(fused)) == kinematic for name in _CLOSED)
    assert all((name in vars(fused.gauss)) == images for name in _CLOSED_IMAGES)
    for name in _CLOSED if kinematic else ():
        assert _same(getattr(fused, name), getattr(separate, name)), name
    for name in _CLOSED_IMAGES if images else ():
        assert _same(getattr(fused.gauss, name), getattr(separate.gauss, name)), name


def test_closed_forms_keep_what_is_there_and_leave_overflows_to_closed_forms() -> None:
    ar = Float64()
    data = discretization.polygons(ar, 1.0, 0.1, None, -10, 10)
    given = np.zeros((22, 2))
    data = data.replaced(closed_p=given)
    fill_closed_forms(data)
    assert data.closed_p is given
    far = discretization.polygons(ar, 1.0, 0.5, None, 0, 700)  # cosh((i − ½)L) overflows
    fill_closed_forms(far)
    assert not any(name in vars(far) for name in _CLOSED)


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max"),
    [(1.0, 0.1, None, -50, 49), (1.0, 0.3, 1e-9, -15, 15), (2.5, 0.7, 3.1, -3, 40)],
)
def test_closed_comparisons_are_the_largest_of_the_arrays(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    data = discretization.polygons(Float64(), h, d, beta0, i_min, i_max)
    n = data.vertices - 1
    theorem_5, theorem_6 = closed_comparisons(data, n)
    ar = Float64()
    expected_5 = residual_kernels.relative_point_difference(ar, data.p[:n], data.closed_p[:n])
    distance = residual_kernels.point_distance(ar, data.tractrix[:n], data.closed_tractrix[:n])
    expected_6 = relative_to(ar, distance, (abs(data.axis[:, 0]) + h)[:n])
    assert _same(theorem_5, np.abs(expected_5).max())
    assert _same(theorem_6, np.abs(expected_6).max())
    moved = data.replaced(p=data.p * (1 + 1e-6))
    assert closed_comparisons(moved, n)[0] > 5e-7
    # one theorem alone: its own largest, the other's closed form not made
    alone = discretization.polygons(Float64(), h, d, beta0, i_min, i_max)
    assert _same(closed_comparisons(alone, n, theorem_5=False)[1], theorem_6)
    assert "closed_p" not in vars(alone)
    assert _same(closed_comparisons(alone, n, theorem_6=False)[0], theorem_5)
    # the closed points made and compared a block at a time (from one exponential a row, one
    # square root a block: the same largest within ULPS ulp, session 22), nothing stored
    fresh = discretization.polygons(Float64(), h, d, beta0, i_min, i_max)
    found = closed_kinematic_comparisons(fresh, n)
    assert close_residuals(found, (theorem_5, theorem_6), (1.0, 1.0)), (found, theorem_5, theorem_6)
    assert not {"closed_p", "closed_tractrix"} & vars(fresh).keys()
    alone_6 = closed_kinematic_comparisons(fresh, n, theorem_5=False)
    assert alone_6 is not None and alone_6[0] == 0.0 and _same(alone_6[1], found[1])
    assert closed_kinematic_comparisons(moved, n)[0] > 5e-7  # type: ignore[index]


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max"),
    [(1.0, 1e-3, 0.7, -9000, 11000), (1.0, 1e-4, None, -8191, 8191), (1.0, 0.5, None, 0, 700)],
)
def test_closed_kinematic_comparisons_beyond_one_block(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    data = discretization.polygons(Float64(), h, d, beta0, i_min, i_max)
    n = data.vertices - 1
    found = closed_kinematic_comparisons(data, n)
    if i_max == 700:  # cosh((i − ½)L) overflows: left to the separate closed forms
        assert found is None
        return
    assert found is not None
    expected = closed_comparisons(data, n)
    assert close_residuals(found, expected, (1.0, 1.0)), (found, expected)
