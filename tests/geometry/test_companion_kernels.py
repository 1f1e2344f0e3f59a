"""The compiled Gauss image companions (app/geometry/companion_kernels.py) give the bits of the
numpy formulas of ``gauss_image`` on many polygons: every scale, both orientations, nearly
straight and sharply turning meridians, and the construction's own (D4b) polygons."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry import gauss_image
from app.geometry.d4b.discretization import COMPANIONS, polygons
from app.geometry.errors import DomainError
from app.geometry.precision import Float64


class NumpyFloat64(Float64):
    """Float64 under another name: ``gauss_image`` then takes its numpy formulas."""

    mode = "numpy"  # type: ignore[assignment]


FLOAT64, NUMPY = Float64(), NumpyFloat64()


def _polygons() -> list[np.ndarray]:
    rng = np.random.default_rng(20261202)
    found = []
    for size in (2, 3, 5, 17, 100, 1001):
        for scale in (1e-150, 1e-8, 1.0, 1e5, 1e150):
            steps = rng.normal(size=(size - 1, 2)) * scale
            start = rng.normal(size=(1, 2)) * scale
            found.append(np.concatenate([start, start + np.cumsum(steps, axis=0)]))
    # nearly straight: tiny turning angles, where the pole is almost the contact point
    t = np.linspace(-3.0, 3.0, 400)
    found.append(np.stack([t, np.cosh(t)], axis=1))
    found.append(np.stack([t[::-1], np.cosh(t[::-1])], axis=1))  # runs towards −x
    found.append(np.stack([t, 1 + 1e-12 * t**2], axis=1))
    for d in (0.1, 0.3, 0.01):
        data = polygons(FLOAT64, 1.0, d, None, -60, 59)
        found.append(np.asarray(data.p))
        found.append(np.asarray(data.tractrix))
    return found


@pytest.mark.parametrize("polygon", _polygons(), ids=lambda p: f"{len(p)}x{abs(p).max():.0e}")
def test_the_kernels_give_the_numpy_bits(polygon: np.ndarray) -> None:
    for build in (gauss_image.contact_points, gauss_image.circumscribed):
        compiled, reference = build(FLOAT64, polygon), build(NUMPY, polygon)
        assert compiled.shape == reference.shape
        assert compiled.dtype == np.float64
        assert compiled.tobytes() == reference.tobytes(), build.__name__


def test_a_non_contiguous_polygon_gives_the_same_bits() -> None:
    polygon = _polygons()[-2]
    strided = np.asfortranarray(polygon)
    for build in (gauss_image.contact_points, gauss_image.circumscribed):
        assert build(FLOAT64, strided).tobytes() == build(NUMPY, polygon).tobytes()


@pytest.mark.parametrize("build", [gauss_image.contact_points, gauss_image.circumscribed])
def test_a_zero_length_edge_is_the_same_domain_error(build: object) -> None:
    polygon = np.array([[0.0, 1.0], [1.0, 2.0], [1.0, 2.0], [2.0, 4.0]])
    for ar in (FLOAT64, NUMPY):
        with pytest.raises(DomainError) as caught:
            build(ar, polygon)  # type: ignore[operator]
        assert caught.value.parameter == "meridian"


@pytest.mark.parametrize(
    "arguments",
    [
        (1.0, 0.1, None, -50, 49),
        (1.0, 0.3, 1.0, -5, 7),
        (2.0, 0.01, 2.5, 3, 40),
        (1.0, 0.2, None, -30, -4),
        (1.0, 0.1, None, 0, 0),
        (1e-3, 1e-4, 0.1, -200, 3),
    ],
)
def test_the_d4b_companions_in_one_pass_give_the_separate_bits(arguments: tuple) -> None:
    fused, separate = polygons(FLOAT64, *arguments), polygons(FLOAT64, *arguments)
    fused.compile_companions()
    assert {"axis", "tractrix", "darboux"} <= set(vars(fused))
    assert {"tractrix_gauss", "contact", "gauss"} <= set(vars(fused.gauss))
    for name, build in COMPANIONS.items():
        one, other = build(fused), build(separate)
        assert one.shape == other.shape, name
        assert one.tobytes() == other.tobytes(), name


@pytest.mark.parametrize(
    "arguments",
    [
        (1.0, 0.1, None, -50, 49),
        (1.0, 0.3, 1.0, -5, 7),
        (2.0, 0.01, 2.5, 3, 40),
        (1.0, 0.2, None, -30, -4),
        (1.0, 0.1, None, 0, 0),
        (1e-3, 1e-4, 0.1, -200, 3),
    ],
)
def test_the_construction_and_companions_in_one_call_give_the_separate_bits(
    arguments: tuple,
) -> None:
    """``compile_companions`` before the construction ran: the recursion, p, every companion
    and the Gauss images built later (for the checks) are the separate constructions' bits,
    and the images are not built for the companions alone."""
    fused, separate = polygons(FLOAT64, *arguments), polygons(FLOAT64, *arguments)
    fused.compile_companions()
    assert "gauss" not in vars(fused) and "p" in vars(fused)
    for name, build in COMPANIONS.items():
        one, other = build(fused), build(separate)
        assert one.shape == other.shape, name
        assert one.tobytes() == other.tobytes(), name
    assert "gauss" not in vars(fused)
    assert fused.p.tobytes() == separate.p.tobytes()
    (lo, built), (other_lo, other_built) = fused._hull, separate._hull
    assert lo == other_lo
    for one, other in zip(built.recursion or (), other_built.recursion or (), strict=True):
        assert np.asarray(one).tobytes() == np.asarray(other).tobytes()
    for name in ("axis_points", "tractrix", "centres", "directions"):
        assert getattr(built, name).tobytes() == getattr(other_built, name).tobytes(), name
    for name in ("tractrix_gauss", "contact", "gauss", "closed_contact", "closed_gauss"):
        one, other = getattr(fused.gauss, name), getattr(separate.gauss, name)
        assert one.tobytes() == other.tobytes(), name


def test_a_replaced_gauss_image_is_the_companion() -> None:
    data = polygons(FLOAT64, 1.0, 0.1, None, -10, 10)
    data.compile_companions()
    moved = data.image("gauss") + 1.0
    changed = data.replaced(gauss=data.gauss.replaced(gauss=moved))
    assert COMPANIONS["gauss_image"](changed) is moved
    assert COMPANIONS["gauss_image"](data) is not moved


def test_companions_built_already_are_kept() -> None:
    data = polygons(FLOAT64, 1.0, 0.1, None, -10, 10)
    tractrix, contact = data.tractrix, data.gauss.contact
    data.compile_companions()
    assert data.tractrix is tractrix
    assert data.gauss.contact is contact
