"""Section 5's compiled passes on balls give the very balls of the numpy formulas they replace, or,
where a pass runs the scales of its residuals at ``RESIDUAL_BITS`` (the edges' sizes and
resolutions, ``_along``'s quotient, the printed slope form, the rotation's distance), balls
holding the same exact values whose bounds agree to 2^-26 relative."""

from __future__ import annotations

from typing import Any

import flint
import numpy as np
import pytest

from app.geometry import arb_program as ap, balls, checks, gauss_image
from app.geometry.ball_arithmetic import Ball
from app.geometry.d4b import arb_gauss, closed_forms, curvature, discretization as d4b
from app.geometry.d4b.closed_forms import tilt_shift
from app.geometry.polygon import magnitude
from app.geometry.precision import stack_points

pytestmark = pytest.mark.skipif(not arb_gauss.AVAILABLE, reason="no bundled libflint")


def _same(got: Any, want: Any) -> None:
    got, want = np.asarray(got).reshape(-1), np.asarray(want).reshape(-1)
    assert len(got) == len(want) > 0
    for a, b in zip(got, want, strict=True):
        assert a.mid().man_exp() == b.mid().man_exp()
        assert a.rad().man_exp() == b.rad().man_exp()


def _close(got: Any, want: Any) -> None:
    """Balls of the same exact values (they overlap), their upper and lower bounds within
    2^-26 of the larger |upper bound| (scales at 64 bits; arb's 30-bit radii where a ball is
    mostly radius)."""
    got, want = np.asarray(got).reshape(-1), np.asarray(want).reshape(-1)
    assert len(got) == len(want) > 0
    for a, b in zip(got, want, strict=True):
        assert a.overlaps(b)
        ua, ub = float(a.mid() + a.rad()), float(b.mid() + b.rad())
        la, lb = float(a.mid() - a.rad()), float(b.mid() - b.rad())
        size = 2.0**-26 * max(abs(ua), abs(ub)) + 1e-300
        assert abs(ua - ub) <= size and abs(la - lb) <= size


def _points(columns: Any) -> Any:
    assert columns is not None
    return stack_points(columns[0], columns[1])


def _numpy_only(compute: Any) -> Any:
    """``compute`` with the compiled programs off (``arb_program.AVAILABLE``): the numpy code."""
    saved = ap.AVAILABLE
    ap.AVAILABLE = False
    try:
        return compute()
    finally:
        ap.AVAILABLE = saved


@pytest.mark.parametrize("digits", [50, 500])
def test_the_gauss_image_passes_are_the_numpy_balls(digits: int) -> None:
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        h, d = ar.scalar(1.0), ar.scalar(0.1)
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        p, images = data.p, data.gauss
        shift = tilt_shift(ar, h, d, None)
        # the hyperbolic table and the printed (20)
        table = curvature._BallHyperbolic(ar, h, d, shift, -41, 40)
        got = arb_gauss.hyperbolic(
            -41,
            40,
            shift,
            closed_forms.log_ratio(ar, h, d),
            ar.sqrt((h - d) / (h + d)),
        )
        assert got is not None
        _same(got[0], table.tanh_t)
        _same(got[1], table.sech_t)
        _same(got[2], table.tanh_u)
        _same(got[3], table.sech_u)
        _same(
            _points(arb_gauss.printed_20(h, d, table.tanh_t, table.sech_t)),
            table.printed("20", -41, 40),
        )
        # the contact points, the poles, the inversion
        extended = data.gauss.contact_edges_before
        assert extended is not None
        sign = gauss_image.orientation(p)
        contact = gauss_image.contact_points(ar, p)
        found = arb_gauss.contact_points(p, sign)
        assert found is not None and found[1] == -1
        _same(_points(found[0]), contact)
        _same(_points(arb_gauss.poles(contact)), curvature._poles(contact))
        _same(
            _points(arb_gauss.pole_by_inversion(contact[:-1], contact[1:])),
            closed_forms.pole_by_inversion(contact[:-1], contact[1:]),
        )
        # the edges, their sizes and resolutions; _along of n and of the printed slope form
        ex, ey, size, resolution = arb_gauss.edges(p)
        edges = p[1:] - p[:-1]
        _same(ex, edges[:, 0])
        _same(ey, edges[:, 1])
        _close(size, magnitude(p[:-1], p[1:]))
        _same(resolution, curvature._edge_resolution(ar, p))  # the same pass
        with_numpy = _numpy_only(lambda: curvature._edge_resolution(ar, p))
        _close(resolution, with_numpy)
        n = len(p) - 1
        normals = images.tractrix_gauss[:n]
        numpy_along = _numpy_only(lambda: curvature._along(ar, normals, p))
        _close(arb_gauss.along(normals, ex, ey, size), numpy_along)
        backwards = -normals  # v · e < 0: the residual 1
        numpy_along = _numpy_only(lambda: curvature._along(ar, backwards, p))
        _same(arb_gauss.along(backwards, ex, ey, size), numpy_along)
        slope = closed_forms.normal_from_slope_printed(ar, edges[:, 1] / edges[:, 0])
        numpy_along = _numpy_only(lambda: curvature._along(ar, slope, p))
        printed = arb_gauss.along_printed_slope(ex, ey, size)
        # read only as erratum E61's printed residual, the largest lower bound (its form at
        # 64 bits: where it is right, k > 0, the balls are ~2^-64 wide and the bound 0 there)
        assert all(a.overlaps(b) for a, b in zip(printed, numpy_along, strict=True))
        lower, expected = float(ar.largest_lower(printed)), float(ar.largest_lower(numpy_along))
        assert expected > 0.1 and abs(lower - expected) <= 2.0**-26 * expected
        # the rotation's scaled distances, minima and products
        c, normals = contact[1:n], normals[: n - 1]
        rotated = stack_points(-normals[:, 1], normals[:, 0])
        want = checks.point_distance(ar, c, rotated) * resolution[: n - 1]
        _close(arb_gauss.rotation(c, normals, resolution[: n - 1]), want)
        _same(arb_gauss.minimum(resolution, size), curvature._ball_minimum(resolution, size))
        # relative point differences, alone and scaled (closed forms, errata, the inversion)
        poles = curvature._poles(contact)[: n - 1]
        inverted = closed_forms.pole_by_inversion(contact[:-1], contact[1:])
        want = checks.relative_point_difference(ar, poles, inverted)
        _same(curvature._relative(ar, poles, inverted), want)
        _same(
            curvature._relative(ar, poles, inverted, resolution[: n - 1]),
            want * resolution[: n - 1],
        )
        wide = inverted + flint.arb(0, 1e-3)  # radii beyond the low precision's
        want = checks.relative_point_difference(ar, poles, wide)
        _same(curvature._relative(ar, poles, wide), want)
        _same(arb_gauss.product(resolution, size), resolution * size)


@pytest.mark.parametrize("digits", [50, 500])
def test_the_closed_and_printed_pairs_are_the_numpy_balls(digits: int) -> None:
    """(18) and (19) against their corrected and printed closed forms in one program: the
    balls of ``_relative`` on the closed forms' arrays (per row, as with ``detail``), and the
    reduced pairs' bounds those of the columns."""
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        h, d = ar.scalar(1.0), ar.scalar(0.1)
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        images = data.gauss
        shift = tilt_shift(ar, h, d, None)
        table = curvature._ball_hyperbolic(ar, h, d, shift, -41, 40)
        n = 80
        rows = table._rows(-40, -40 + n - 1)
        tanh, sech = table.tanh_t[rows], table.sech_t[rows]
        low = min(flint.ctx.prec, curvature.RESIDUAL_BITS)
        with ar.residual_precision():
            tiny = ar.scalar(np.finfo(np.float64).tiny)
        resolution = curvature._edge_resolution(ar, data.p)[:n]
        cases = (
            ("18", images.tractrix_gauss[:n], None),
            ("19", images.contact[1 : n + 1], resolution),
        )
        for key, built, factor in cases:
            corrected = (
                table.tractrix_gauss_image(-40, 40)
                if key == "18"
                else table.contact_points(-41, 40)[1:]
            )[:n]
            printed = table.printed(key, -40, 39)[:n]
            want_closed = curvature._relative(ar, built, corrected, factor)
            want_printed = curvature._relative(ar, built, printed)
            got = arb_gauss.closed_and_printed(key, built, tanh, sech, tiny, low, factor, True)
            assert got is not None
            _same(got[0], want_closed)
            assert len(got[1]) == 2  # reduced: the balls of the largest upper and lower bounds
            for bound in (ar.largest_upper, ar.largest_lower):
                _same(bound(got[1]), bound(want_printed))
            got = arb_gauss.closed_and_printed(key, built, tanh, sech, tiny, low, factor, False)
            assert got is not None and len(got[0]) == 2
            for bound in (ar.largest_upper, ar.largest_lower):
                _same(bound(got[0]), bound(want_closed))


@pytest.mark.parametrize("digits", [50, 500])
def test_the_image_20_program_is_the_numpy_balls(digits: int) -> None:
    """m against its poles by inversion, (20) corrected and (20) printed in one program: the
    balls of ``_relative`` on the arrays the separate passes make (per row, as with
    ``detail``; the printed ones reduced to the bounds of the column)."""
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        h, d = ar.scalar(1.0), ar.scalar(0.1)
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        images = data.gauss
        shift = tilt_shift(ar, h, d, None)
        table = curvature._ball_hyperbolic(ar, h, d, shift, -41, 40)
        n = 80
        rows = table._rows(-40, -40 + n - 1)
        m, contact = images.gauss[:n], images.contact
        scale = curvature._edge_resolution(ar, data.p)[:n]
        with ar.residual_precision():
            tiny = ar.scalar(np.finfo(np.float64).tiny)
        constants = {"h": h, "d": d, "amplitude": table.amplitude, "two": flint.arb(2)}
        constants |= {"tiny": tiny, "low": min(flint.ctx.prec, curvature.RESIDUAL_BITS)}
        columns = (table.tanh_t[rows], table.sech_t[rows], table.tanh_u[rows], table.sech_u[rows])
        before, after = contact[:n], contact[1 : n + 1]
        inverted = curvature._pole_by_inversion(ar, before, after)
        want = (
            curvature._relative(ar, m, inverted, scale),
            curvature._relative(ar, m, table.circumscribed_gauss_image(-40, 40)[:n], scale),
            curvature._relative(ar, m, table.printed("20", -40, 39)[:n]),
        )
        got = arb_gauss.image_20(m, before, after, columns, constants, scale, True)
        assert got is not None
        _same(got[0], want[0])
        _same(got[1], want[1])
        for bound in (ar.largest_upper, ar.largest_lower):
            _same(bound(got[2]), bound(want[2]))
        got = arb_gauss.image_20(m, before, after, columns, constants, scale, False)
        assert got is not None
        for k in range(3):
            assert len(got[k]) == 2
            for bound in (ar.largest_upper, ar.largest_lower):
                _same(bound(got[k]), bound(want[k]))


@pytest.mark.parametrize("digits", [50, 500])
def test_the_edge_checks_program_is_the_separate_passes(digits: int) -> None:
    """Every check on p's edges in one program: the balls of ``edges``, ``minimum``, ``along``,
    ``along_printed_slope`` and ``rotation`` (per row; the reduced ones' bounds)."""
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        p, images = data.p, data.gauss
        n = len(p) - 1
        normals, contact = images.tractrix_gauss[:n], images.contact[1 : n + 1]
        assert images.contact_edges_before is not None
        before = curvature._edge_resolution(ar, images.contact_edges_before)
        ex, ey, size, resolution = arb_gauss.edges(p)
        previous = np.concatenate([before, resolution[:-1]])
        want = (
            resolution,
            arb_gauss.minimum(previous, resolution),
            arb_gauss.along(normals, ex, ey, size),
            arb_gauss.along_printed_slope(ex, ey, size),
            arb_gauss.rotation(contact, normals, resolution),
        )
        got = arb_gauss.edge_checks(p, normals, contact, before[0], True)
        assert got is not None
        for k in (0, 1, 2, 4):
            _same(got[k], want[k])
        got = arb_gauss.edge_checks(p, normals, contact, before[0], False)
        assert got is not None
        _same(got[0], want[0])
        _same(got[1], want[1])
        for k in (2, 3, 4):
            assert len(got[k]) == 2
            for bound in (ar.largest_upper, ar.largest_lower):
                _same(bound(got[k]), bound(want[k]))


def test_a_zero_edge_and_other_entries() -> None:
    ar = Ball(30)
    with balls.working_precision(ar.bits):
        points = np.empty((3, 2), dtype=object)
        points[:, 0] = [flint.arb(0), flint.arb(1), flint.arb(1)]
        points[:, 1] = [flint.arb(1), flint.arb(2), flint.arb(2)]
        found = arb_gauss.contact_points(points, 1)
        assert found is not None and found[1] == 1  # the second edge has no length
        points[0, 0] = 0.5  # not a ball: the numpy code runs
        assert arb_gauss.contact_points(points, 1) is None
        assert arb_gauss.edges(points[:1]) is None  # no edge


@pytest.mark.parametrize("digits", [15, 50, 500])
def test_the_edge_checks_hold_the_exact_values(digits: int) -> None:
    """On exact vertices (the midpoints of D4b's p, n and ñ) the numpy code at four times the
    precision pins each resolution, ``_along`` residual and rotation residual to a narrow
    ball; the compiled program's balls (scales at 64 bits) hold them."""
    ar = Ball(digits, 4, recursions_only=True)
    with balls.working_precision(ar.bits):
        data = d4b.polygons(ar, 1.0, 0.1, None, -40, 39)
        n = len(data.p) - 1
        exact = [_midpoints(a) for a in (data.p, data.gauss.tractrix_gauss[:n])]
        exact.append(_midpoints(data.gauss.contact[1 : n + 1]))
        p, normals, contact = exact
        got = arb_gauss.edge_checks(p, normals, contact, flint.arb(1), True)
        assert got is not None
    with balls.working_precision(Ball(4 * digits).bits):
        high = Ball(4 * digits)

        def numpy() -> Any:
            resolution = curvature._edge_resolution(high, p)
            rotated = stack_points(-normals[:, 1], normals[:, 0])
            distance = checks.point_distance(high, contact, rotated)
            return resolution, curvature._along(high, normals, p), distance * resolution

        want = _numpy_only(numpy)
    for k, narrow in zip((0, 2, 4), want, strict=True):
        assert all(a.contains(b) for a, b in zip(got[k], narrow, strict=True))


def _midpoints(points: Any) -> Any:
    out = np.empty(points.shape, dtype=object)
    out.flat[:] = [flint.arb(b.mid()) for b in points.flat]
    return out
