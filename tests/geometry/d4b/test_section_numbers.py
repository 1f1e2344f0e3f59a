"""Sections 3 and 4.2 from one call (``fused_checks.section_numbers``): each number has the bits
of the check's own pass, and the checks read from it are those computed without it."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from app.geometry import darboux
from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d4b import (
    checks as d4b_checks,
    discretization as d4b,
    fused_checks,
    residual_kernels,
)
from app.geometry.precision import Float64
from app.responses import check_document, encode_json
from tests.geometry.bits import same_bits
from tests.geometry.d4b.test_rotation_angle import adversarial


def _wrappers(p: Any, axis: Any, e: Any, tractrix: Any, n: int, d: float, h: float) -> list[Any]:
    """Every number as each check's own pass gives it."""
    hypothesis, smallest = residual_kernels.hypothesis_largest(p, n, d)
    one, two = residual_kernels.recursion_largest(d, p[:, 1])
    rotation, printed = residual_kernels.rotation_angle_largest(d, p, axis, n)
    return [
        hypothesis.value,
        smallest,
        residual_kernels.ratio_spread(p),
        rotation.value,
        printed,
        one.value,
        two.value,
        residual_kernels.largest_two_step_printed_residual(d, p[:, 1]),
        darboux.edge_length_largest(axis[:n], e[:n]).value,
        darboux.distance_largest(axis[:n], e[:n], 2 * h).value,
        residual_kernels.right_angle_largest(tractrix, axis, p, n).value,
        fused_checks.fits_summary(p[:n]),
    ]


def _fused(
    numbers: fused_checks.SectionNumbers,
    p: Any,
    axis: Any,
    e: Any,
    tractrix: Any,
    n: int,
    d: float,
    h: float,
) -> list[Any]:
    """The same numbers through the wrappers' ``found``."""
    hypothesis, smallest = residual_kernels.hypothesis_largest(p, n, d, numbers.hypothesis)
    one, two = residual_kernels.recursion_largest(d, p[:, 1], numbers.recursion)
    rotation, printed = residual_kernels.rotation_angle_largest(d, p, axis, n, numbers.rotation)
    return [
        hypothesis.value,
        smallest,
        residual_kernels.ratio_spread(p, numbers.ratio),
        rotation.value,
        printed,
        one.value,
        two.value,
        residual_kernels.largest_two_step_printed_residual(d, p[:, 1], numbers.two_step_printed),
        darboux.edge_length_largest(axis[:n], e[:n], numbers.darboux_edges).value,
        darboux.distance_largest(axis[:n], e[:n], 2 * h, numbers.darboux_distances).value,
        residual_kernels.right_angle_largest(tractrix, axis, p, n, numbers.right_angles).value,
        numbers.fits,
    ]


def _assert_same(found: list[Any], expected: list[Any]) -> None:
    for got, wanted in zip(found, expected, strict=True):
        if wanted is None or got is None:
            assert got is wanted
        else:
            assert same_bits(np.asarray(got), np.asarray(wanted))


def test_numbers_are_the_passes_bits_on_real_polygons() -> None:
    ar = Float64()
    for h, d, beta0 in ((1.0, 0.1, None), (1.0, 0.99, 0.4), (2.5, 0.3, 2.9), (1.0, 1e-3, None)):
        for i_min, i_max in ((-50, 49), (0, 4), (-3, 2), (5, 300), (-2000, 1500)):
            data = d4b.polygons(ar, h, d, beta0, i_min, i_max)
            p, axis, e, tractrix = data.p, data.axis, data.darboux, data.tractrix
            n = len(p) - 1
            numbers = fused_checks.section_numbers(p, axis, e, tractrix, n, d, h)
            assert numbers is not None
            # below 512 vertices every block of the rotation angle's pass is compiled
            assert (numbers.rotation is not None) == (n - 1 < residual_kernels.ROTATION_LIBM_BELOW)
            expected = _wrappers(p, axis, e, tractrix, n, d, h)
            _assert_same(_fused(numbers, p, axis, e, tractrix, n, d, h), expected)


def test_numbers_are_the_passes_bits_on_adversarial_points() -> None:
    """NaN, infinities, zeros, subnormal and huge coordinates (where the rotation angle's pass
    stops at 512 vertices and more, ``rotation`` None, the check's own pass goes on)."""
    rng = np.random.default_rng(25)
    stopped = 0
    for n in (4, 9, 70, 600):
        for p, axis in adversarial(rng, n):
            e, tractrix = rng.normal(size=(n + 1, 2)), rng.normal(size=(n + 1, 2))
            e[n // 2] = p[n // 3]  # a zero-length edge of the Darboux polygon
            d, h = float(rng.uniform(0.01, 2)), float(rng.uniform(2, 3))
            numbers = fused_checks.section_numbers(p, axis, e, tractrix, n, d, h)
            assert numbers is not None
            stopped += numbers.rotation is None
            expected = _wrappers(p, axis, e, tractrix, n, d, h)
            _assert_same(_fused(numbers, p, axis, e, tractrix, n, d, h), expected)
    assert stopped  # the fallback was exercised


def test_none_where_the_checks_read_other_arrays() -> None:
    rng = np.random.default_rng(3)
    n = 10
    p, axis = rng.normal(size=(n + 1, 2)), rng.normal(size=(n + 1, 2))
    e, tractrix = rng.normal(size=(n + 1, 2)), rng.normal(size=(n + 1, 2))
    assert fused_checks.section_numbers(p, axis, e, tractrix, n, 0.1, 1.0) is not None
    for bad in (np.asfortranarray(p), p[::-1], p.astype(np.float32), p[:, :1], p[:-1]):
        assert fused_checks.section_numbers(bad, axis, e, tractrix, n, 0.1, 1.0) is None
    small = p[:4]
    assert fused_checks.section_numbers(small, axis, e, tractrix, 3, 0.1, 1.0) is None


def _answer(data: d4b.D4bPolygons, h: float, d: float, selection: Selection) -> bytes:
    constants, checks = d4b_checks.evaluate(Float64(), h, d, data, False, None, selection)
    documents = [check_document(check) for check in checks]
    return encode_json([{k: float(v) for k, v in constants.items()}, documents])


def _perturbed(data: d4b.D4bPolygons) -> list[d4b.D4bPolygons]:
    p = data.p
    cases = []
    last = len(p) - 2
    for row, value in ((1, np.nan), (2, np.inf), (last // 2, 1e200), (last, p[last, 1] * 1.000001)):
        moved = p.copy()
        moved[row, 1] = value
        cases.append(data.replaced(p=moved))
    return cases


@pytest.mark.parametrize(
    ("h", "d", "i_min", "i_max"), [(1.0, 0.1, -50, 49), (1.0, 0.9, -6, 7), (2.0, 0.5, 0, 4)]
)
def test_checks_read_from_one_call_are_the_checks(
    h: float, d: float, i_min: int, i_max: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every check and fitted constant with the numbers from one call equals the one computed
    pass by pass, on the polygons and on polygons with a NaN, an infinity, a huge height (the
    printed two-step form's guard) or a moved vertex; a selection without all of them makes
    no such call."""
    calls = []
    original = fused_checks.section_numbers

    def counted(*arguments: Any) -> Any:
        calls.append(1)
        return original(*arguments)

    data = d4b.polygons(Float64(), h, d, None, i_min, i_max)
    section = Selection(frozenset(s.id for s in d4b_checks._SECTION), None)
    partial = Selection(frozenset(s.id for s in d4b_checks._SECTION[1:]), None)
    # the curvature checks refuse the perturbed polygons (a face without area): Sections 3, 4.2
    cases = [(data, EVERYTHING), *((case, section) for case in _perturbed(data))]
    for case, selection in cases:
        monkeypatch.setattr(fused_checks, "section_numbers", counted)
        fused = _answer(case.replaced(), h, d, selection)
        assert calls, "the one call was not made"
        calls.clear()
        _answer(case.replaced(), h, d, partial)
        assert not calls
        monkeypatch.setattr(fused_checks, "section_numbers", lambda *arguments: None)
        assert fused == _answer(case.replaced(), h, d, selection)


def test_no_call_from_section_below(monkeypatch: pytest.MonkeyPatch) -> None:
    """From ``SECTION_BELOW`` indices each check calls its own pass."""
    monkeypatch.setattr(fused_checks, "section_numbers", None)  # a call would raise
    n = fused_checks.SECTION_BELOW
    data = d4b.polygons(Float64(), 1.0, 0.1, None, -n // 2, n - n // 2 - 1)
    assert len(data.p) - 1 == n
    constants, checks = d4b_checks.evaluate(Float64(), 1.0, 0.1, data, False)
    assert len(checks) == 21 and all(check.holds for check in checks)
    assert len(constants) == 3  # the fitted constants of Theorem 4 (i)-(iii)
