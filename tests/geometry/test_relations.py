"""The relations matrix on computed curves: verdicts, signs, perturbations, missing columns."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from app.geometry import relations
from app.geometry.curve import Curve, Polyline
from app.geometry.discretizations import d2a_hex, d2a_quad, d4b
from app.geometry.precision import Arithmetic, Float64, MultiPrecision

EXPECTED = {  # Section 4: which discretization satisfies which property
    "d4b": {"d1": True, "d3": True, "equation-2": True, "equation-7": True},
    "d2a-quad": {"d1": False, "d3": False, "equation-2": True, "equation-7": True},
    "d2a-hex": {"d1": False, "d3": False, "equation-2": False, "equation-7": True},
}
MODULES = {"d4b": d4b, "d2a-quad": d2a_quad, "d2a-hex": d2a_hex}


def cells(curve: Curve) -> dict[str, relations.Cell]:
    return {cell.property: cell for cell in relations.row(curve)}


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(40)], ids=["float64", "mp40"])
@pytest.mark.parametrize("identifier", sorted(EXPECTED))
def test_verdicts_at_the_defaults(ar: Arithmetic, identifier: str) -> None:
    found = cells(MODULES[identifier].compute(ar))
    assert [c.property for c in found.values()] == [p.id for p in relations.PROPERTIES]
    assert {k: found[k].holds for k in EXPECTED[identifier]} == EXPECTED[identifier]
    for key in ("mean-curvature-zero", "gaussian-curvature-constant"):
        assert found[key].holds is None and found[key].residual is None
        assert "curvature" in (found[key].note or "")


def test_d4b_constants_are_d_over_h_h_and_d_over_h_squared(mp40: MultiPrecision) -> None:
    found = cells(d4b.compute(mp40, 2.0, 0.5, 0.7, -6, 9))
    assert float(found["d1"].constants["c"]) == pytest.approx(0.25, rel=1e-35)
    assert float(found["d3"].constants["c"]) == pytest.approx(2.0, rel=1e-35)
    assert float(found["equation-2"].constants["c"]) == pytest.approx(0.125, rel=1e-35)
    c1, c2 = found["equation-7"].constants["c1"], found["equation-7"].constants["c2"]
    assert float(c1) == pytest.approx(0.125, rel=1e-35) and float(c2) == pytest.approx(0.125)


def _moved(curve: Curve, points: np.ndarray) -> Curve:
    return replace(curve, polygon=Polyline(curve.polygon.indices, points))


def test_every_condition_fails_on_a_perturbed_polygon(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, -8, 8)
    points = curve.polygon.vertices.copy()
    points[5, 1] *= 1 + 1e-6
    found = cells(_moved(curve, points))
    for key in ("d1", "d3", "equation-2", "equation-7"):
        assert found[key].holds is False, key
        assert found[key].residual is not None and found[key].residual > 1e-8, key


def test_a_negative_constant_is_not_a_discrete_hyperbolic_cosine(float64: Float64) -> None:
    """The (D4b) polygon reflected in the x-axis fits (D1) and (D3) with c < 0 only."""
    curve = d4b.compute(float64)
    points = curve.polygon.vertices * np.array([1.0, -1.0])
    found = cells(_moved(curve, points))
    for key in ("d1", "d3"):
        assert found[key].holds is False and found[key].note == "the fitted c is not > 0", key
        assert found[key].residual is not None and found[key].residual < 1e-15
    assert found["equation-2"].holds is True  # Δ² and A both change sign
    assert found["equation-7"].holds is True


def test_too_short_polygons_are_not_applicable(float64: Float64) -> None:
    found = cells(d4b.compute(float64, 1.0, 0.1, None, 0, 1))
    assert found["d3"].holds is True  # one equation: fits exactly
    for key in ("d1", "equation-2", "equation-7"):
        assert found[key].holds is None and "vertices" in (found[key].note or ""), key


def test_d2a_rows_use_the_conditioned_tolerance(float64: Float64) -> None:
    curve = d2a_quad.compute(float64, 1.0, 1.05)  # gap 0.048: conditioning 1/gap = 21
    assert curve.local_tolerance == pytest.approx(float64.tolerance(16) * 21, rel=1e-12)
    assert relations.tolerance_of(curve) == curve.local_tolerance
    assert relations.tolerance_of(d4b.compute(float64)) == float64.tolerance(16)
    assert cells(curve)["equation-2"].holds is True
