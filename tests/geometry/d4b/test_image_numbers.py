"""Section 5 from one call (``fused_checks.image_numbers``): each number has the bits of the
check's own pass, and the checks read from it are those computed without it."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d4b import (
    checks as d4b_checks,
    curvature as d4b_curvature,
    discretization as d4b,
    fused_checks,
    residual_kernels,
)
from app.geometry.precision import Float64
from app.geometry.surfaces import ring_kernel
from app.geometry.surfaces.ring_curvature import ring_rotation
from app.responses import check_document, encode_json
from tests.geometry.bits import same_bits

RING = ring_rotation(Float64())


def _arrays(data: d4b.D4bPolygons) -> tuple[Any, ...]:
    images = data.gauss
    return (
        data.p,
        data.tractrix,
        images.tractrix_gauss,
        images.contact,
        images.gauss,
        images.contact_edges_before,
    )


def _separately(arrays: tuple[Any, ...], n: int, curvature: float) -> list[Any]:
    """Every number as each check's own pass gives it."""
    p, tractrix, normals, contact, gauss, before = arrays
    resolution = residual_kernels.edge_resolution(p)
    poles = residual_kernels.pole_resolution(residual_kernels.edge_resolution(before), resolution)
    along, printed = residual_kernels.along_largest(normals[:n], p[: n + 1])
    found = [
        resolution,
        poles,
        along.value,
        printed,
        residual_kernels.contact_rotation_largest(contact, normals, resolution, n).value,
        residual_kernels.pole_inversion_largest(gauss, contact, poles, n).value,
    ]
    cos, sin = RING
    for meridian, image, k in ((tractrix, normals, curvature), (p, gauss, None)):
        found.append(ring_kernel.ring_largest(meridian, image, cos, sin, k))
    return found


def _fused(numbers: fused_checks.ImageNumbers, arrays: tuple[Any, ...], n: int) -> list[Any]:
    """The same numbers through the wrappers' ``found``."""
    p, _, normals, contact, gauss, _ = arrays
    along, printed = residual_kernels.along_largest(normals[:n], p[: n + 1], numbers.along)
    rotation, inversion = numbers.rotation, numbers.inversion
    found = [
        numbers.resolution,
        numbers.poles,
        along.value,
        printed,
        residual_kernels.contact_rotation_largest(contact, normals, [], n, rotation).value,
        residual_kernels.pole_inversion_largest(gauss, contact, [], n, inversion).value,
    ]
    for pseudosphere in (True, False):
        valid, largest, largest_17, skipped = numbers.ring(pseudosphere)
        found.append((largest, largest_17, skipped) if valid else None)
    return found


def _assert_same(found: list[Any], expected: list[Any]) -> None:
    for got, wanted in zip(found, expected, strict=True):
        if wanted is None or got is None:
            assert got is wanted
        else:
            assert same_bits(
                np.asarray(got, dtype=np.float64), np.asarray(wanted, dtype=np.float64)
            )


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max"),
    [
        (1.0, 0.1, None, -50, 49),
        (1.0, 0.99, 0.4, -3, 2),
        (2.5, 0.3, 2.9, 5, 300),
        (1.0, 1e-3, None, -200, 200),
        (1.0, 0.5, 1e-6, 0, 4),
    ],
)
def test_numbers_are_the_passes_bits_on_real_polygons(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int
) -> None:
    data = d4b.polygons(Float64(), h, d, beta0, i_min, i_max)
    arrays = _arrays(data)
    n = len(data.p) - 1
    numbers = fused_checks.image_numbers(*arrays, n, RING, -1 / (h * h))
    assert numbers is not None
    expected = _separately(arrays, n, -1 / (h * h))
    _assert_same(_fused(numbers, arrays, n), expected)


def test_numbers_are_the_passes_bits_on_adversarial_points() -> None:
    """NaN, infinities, zeros (faces without area: a ring not valid), huge and tiny values."""
    rng = np.random.default_rng(13)
    specials = [np.nan, np.inf, -np.inf, 0.0, -0.0, 5e-324, 1e300, 2.0**-500]
    invalid = 0
    for n in (4, 9, 40):
        for value in specials:
            for target in range(6):
                arrays = [rng.normal(size=(rows, 2)) for rows in (n + 1, n + 1, n, n + 1, n, 2)]
                arrays[target][int(rng.integers(len(arrays[target]))), int(rng.integers(2))] = value
                if target == 1 and value == 0.0:
                    arrays[1][:, 0] = 0.0  # the whole meridian on the axis
                numbers = fused_checks.image_numbers(*arrays, n, RING, -0.25)
                assert numbers is not None
                invalid += not numbers.ring(True)[0]
                _assert_same(
                    _fused(numbers, tuple(arrays), n), _separately(tuple(arrays), n, -0.25)
                )
    assert invalid  # a ring without area was among them


def test_none_where_the_checks_read_other_arrays() -> None:
    rng = np.random.default_rng(3)
    n = 10
    arrays = [rng.normal(size=(rows, 2)) for rows in (n + 1, n + 1, n, n + 1, n, 2)]
    assert fused_checks.image_numbers(*arrays, n, RING, -1.0) is not None
    for at in range(6):
        for bad in (np.asfortranarray(arrays[at]), arrays[at][:-1], arrays[at].astype(np.float32)):
            changed = list(arrays)
            changed[at] = bad
            assert fused_checks.image_numbers(*changed, n, RING, -1.0) is None


def _answer(data: d4b.D4bPolygons, selection: Selection) -> bytes:
    constants, checks = d4b_checks.evaluate(Float64(), 1.0, data.d, data, False, None, selection)
    documents = [check_document(check) for check in checks]
    return encode_json([{k: float(v) for k, v in constants.items()}, documents])


@pytest.mark.parametrize(("d", "i_min", "i_max"), [(0.1, -50, 49), (0.9, -6, 7), (0.5, 0, 4)])
def test_checks_read_from_one_call_are_the_checks(
    d: float, i_min: int, i_max: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every check with Section 5's numbers from one call equals the one computed pass by
    pass; a selection without all of them makes no such call, nor does one from
    ``SECTION_BELOW`` indices."""
    calls = []
    original = fused_checks.image_numbers

    def counted(*arguments: Any) -> Any:
        calls.append(1)
        return original(*arguments)

    def polygons() -> d4b.D4bPolygons:
        return d4b.polygons(Float64(), 1.0, d, None, i_min, i_max)

    monkeypatch.setattr(fused_checks, "image_numbers", counted)
    fused = _answer(polygons(), EVERYTHING)
    assert calls, "the one call was not made"
    calls.clear()
    some = Selection(frozenset(s.id for s in d4b_curvature.STATEMENTS[1:]), None)
    _answer(polygons(), some)
    assert not calls
    monkeypatch.setattr(fused_checks, "image_numbers", lambda *arguments: None)
    assert fused == _answer(polygons(), EVERYTHING)


def test_no_call_from_section_below(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(fused_checks, "image_numbers", None)  # a call would raise
    n = fused_checks.SECTION_BELOW
    data = d4b.polygons(Float64(), 1.0, 0.1, None, -n // 2, n - n // 2 - 1)
    _, checks = d4b_checks.evaluate(Float64(), 1.0, 0.1, data, False)
    assert len(checks) == 21 and all(check.holds for check in checks)
