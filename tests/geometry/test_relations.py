"""The relations matrix on computed curves: verdicts, signs, perturbations, missing columns."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from app.geometry import relations
from app.geometry.curve import Curve, Polyline
from app.geometry.d1 import discretization as d1
from app.geometry.d2a import hex as d2a_hex, quad as d2a_quad
from app.geometry.d2b import discretization as d2b
from app.geometry.d3 import discretization as d3
from app.geometry.d4a import discretization as d4a
from app.geometry.d4b import discretization as d4b
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
    minimal, constant = found["mean-curvature-zero"], found["gaussian-curvature-constant"]
    assert minimal.holds is (identifier != "d2a-hex"), minimal
    assert "own Gauss image" in (minimal.note or "")
    if identifier == "d4b":
        assert constant.holds is True and float(constant.constants["K"]) == pytest.approx(-1)
    else:
        assert constant.holds is None and constant.residual is None
        assert (constant.note or "").startswith(
            "not applicable: this discretization has no tractrix"
        )


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
    assert relations.tolerance_of(d4b.compute(float64)) == pytest.approx(
        float64.tolerance(16) * d4b.conditioning(1.0, 0.1), rel=1e-15
    )
    assert cells(curve)["equation-2"].holds is True


# --- the curvature columns ----------------------------------------------------------------------


def test_minimal_rows_and_their_neck_radius(mp40: MultiPrecision) -> None:
    """H = 0 with the constant a = p_i^y n_i^y: h for (D4b), c for (D3), h − s/2 for (D4a)."""
    expected = [
        (d4b.compute(mp40, 2.0, 0.5, 0.7, -6, 9), 2.0),
        (d3.compute(mp40, 1.5, 0.4, 2.0, "up", -5, 5), 1.5),
        (d4a.compute(mp40, 1.0, 0.1, None, -8, 8), 0.95),
        (d4a.compute(mp40, 2.0, 0.5, 2.8, -8, 8), 1.75),  # through the cusp (c = −3)
        (d1.compute(mp40, 0.1, 0.2, 1.0, 1.0, -6, 6), 1.0),  # offset C = 0: y0 = δ/(2c)
        (d2b.compute(mp40, "remark-13", 6, None, -2, 12), 1.0),
    ]
    for curve, a in expected:
        cell = cells(curve)["mean-curvature-zero"]
        assert cell.holds is True, curve.id
        assert cell.residual is not None and cell.residual < 1e-45, curve.id
        assert float(cell.constants["a"]) == pytest.approx(a, rel=1e-35), curve.id


def test_which_gauss_image_each_row_uses(float64: Float64) -> None:
    own = [d4b.compute(float64), d2b.compute(float64), d2a_quad.compute(float64)]
    for curve in own:
        assert "own Gauss image" in (cells(curve)["mean-curvature-zero"].note or ""), curve.id
    for curve in (d1.compute(float64), d3.compute(float64), d4a.compute(float64)):
        note = cells(curve)["mean-curvature-zero"].note or ""
        assert "circumscribed Gauss image built from p" in note, curve.id
    # (D4b)'s own m is the circumscribed image of Theorem 8: the same cell either way
    curve = d4b.compute(float64, 1.0, 0.3, None, -6, 6)
    built = relations.surface_pair(replace(curve, companions={}), "minimal")
    assert not isinstance(built, str)
    np.testing.assert_allclose(
        built.gauss, curve.companions["gauss_image"].vertices[1:-1], rtol=1e-14, atol=1e-15
    )


def test_mean_curvature_fails_where_the_paper_does_not_claim_it(mp40: MultiPrecision) -> None:
    cases = [
        (d1.compute(mp40, 0.2, 0.5, 1.0, 1.1, -6, 6), 1e-4),  # offset C = −0.225
        (d2a_quad.compute(mp40, 1.0, 1.5, 0.0), 1e-2),  # the Christoffel dual needs r = r*
        (d2a_hex.compute(mp40), 3e-3),  # the hexagonal meridian revolved as quads
    ]
    for curve, at_least in cases:
        cell = cells(curve)["mean-curvature-zero"]
        assert cell.holds is False and cell.residual is not None, curve.id
        assert cell.residual > at_least, (curve.id, cell.residual)


@pytest.mark.parametrize("identifier", ["d4b", "d3", "d2b"])
def test_mean_curvature_fails_on_a_perturbed_polygon(float64: Float64, identifier: str) -> None:
    curve = {"d4b": d4b.compute, "d3": d3.compute, "d2b": d2b.compute}[identifier](float64)
    assert cells(curve)["mean-curvature-zero"].holds is True
    points = curve.polygon.vertices.copy()
    points[4, 1] *= 1 + 1e-7
    cell = cells(_moved(curve, points))["mean-curvature-zero"]
    assert cell.holds is False and cell.residual is not None and cell.residual > 1e-10


def test_constant_curvature_fails_on_a_perturbed_tractrix(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, -6, 6)
    tractrix = curve.companions["tractrix"]
    points = tractrix.vertices.copy()
    points[3, 1] *= 1 + 1e-7
    moved = replace(
        curve, companions={**curve.companions, "tractrix": replace(tractrix, vertices=points)}
    )
    cell = cells(moved)["gaussian-curvature-constant"]
    assert cell.holds is False and cell.residual is not None and cell.residual > 1e-10


def test_curvature_cells_use_the_companion_tolerances(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.01, None, -300, 300)
    found = cells(curve)
    for key, companion in (
        ("mean-curvature-zero", "gauss_image"),
        ("gaussian-curvature-constant", "tractrix_gauss_image"),
    ):
        assert found[key].tolerance == curve.companion_tolerances[companion] > float64.tolerance(16)
        assert found[key].holds is True, (key, found[key].residual, found[key].tolerance)
    checks = {c.id: c for c in curve.checks}  # the discretization's own Theorems 7 and 8 agree
    assert checks["theorem-7"].tolerance == found["gaussian-curvature-constant"].tolerance
    assert checks["theorem-8"].tolerance == found["mean-curvature-zero"].tolerance


def test_d4a_has_a_tractrix_but_no_gauss_image_for_it(float64: Float64) -> None:
    cell = cells(d4a.compute(float64))["gaussian-curvature-constant"]
    assert cell.holds is None and "only for (D4b)" in (cell.note or "")


def test_no_inscribed_gauss_image_gives_the_d4a_pseudosphere_constant_curvature(
    float64: Float64,
) -> None:
    """Section 5 remark: the one-parameter family of inscribed parallel polygons (start n_1)
    contains none with constant K for Sauer's tractrix (after the cusp: i = 1 .. 12)."""
    from app.geometry import conditions, gauss_image
    from app.geometry.surfaces.ring_curvature import ring_curvatures

    tractrix = d4a.compute(float64, 1.0, 0.1, None, 1, 12).companions["tractrix"].vertices
    best = np.inf
    for angle in np.linspace(-np.pi / 2, np.pi / 2, 721)[1:-1]:
        n = gauss_image.inscribed_parallel(
            float64, tractrix, 0, np.array([np.cos(angle), np.sin(angle)])
        )
        faces = ring_curvatures(float64, tractrix, n)
        fit = conditions.fit(
            float64, faces.gauss_area, faces.area, faces.gauss_area_magnitude, faces.area_magnitude
        )
        best = min(best, float(np.max(fit.residuals)))
    assert best > 1e-5  # (D4b)'s pseudosphere: 1e-16


def test_curvature_cells_of_degenerate_polygons_are_not_evaluable(float64: Float64) -> None:
    curve = d3.compute(float64)
    points = curve.polygon.vertices.copy()
    points[5] = points[4]  # a zero-length edge: no circumscribed Gauss image
    cell = cells(_moved(curve, points))["mean-curvature-zero"]
    assert cell.holds is None and (cell.note or "").startswith("not evaluable")
    short = cells(d3.compute(float64, 1.0, 0.2, 1.0, "up", 0, 2))["mean-curvature-zero"]
    assert short.holds is None and "needs 4 vertices" in (short.note or "")
