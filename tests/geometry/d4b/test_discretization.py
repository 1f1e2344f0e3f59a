"""(D4b) as served: every check holds on the true polygons and fails on perturbed ones."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.geometry.d4b import discretization as d4b
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision

ALL = {s.id for s in d4b.STATEMENTS}


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


@pytest.mark.parametrize("beta0", [None, 0.5, 2.4])
@pytest.mark.parametrize("method", ["construction", "closed-form"])
def test_every_check_holds_in_float64(float64: Float64, beta0: float | None, method: str) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, beta0, -15, 15, method)  # type: ignore[arg-type]
    results = verdicts(curve.checks)
    assert set(results) == ALL
    closed = {"theorem-5", "theorem-6", "equation-18", "equation-19", "equation-20"}
    skipped = closed if method == "closed-form" else set()
    assert {k for k, v in results.items() if v is not True} == skipped
    assert all(results[k] is None for k in skipped)


def test_every_check_holds_at_40_digits_with_residuals_near_1e_40(mp40: MultiPrecision) -> None:
    curve = d4b.compute(mp40, 1.5, 0.4, 0.9, -10, 10)
    for check in curve.checks:
        assert check.holds is True, check.id
        assert check.residual is not None and check.residual < 1e-38, check.id


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(30)], ids=["float64", "mp30"])
@pytest.mark.parametrize(("h", "d", "beta0"), [(1.0, 0.1, None), (2.0, 0.5, 0.7), (0.5, 0.45, 2.0)])
def test_constants_are_d_over_h_h_and_d_over_h_squared(
    ar: Arithmetic, h: float, d: float, beta0: float | None
) -> None:
    curve = d4b.compute(ar, h, d, beta0, -8, 8)
    got = {k: float(v) for k, v in curve.constants.items()}
    assert got == pytest.approx({"d1": d / h, "d3": h, "eq2": d / h**2}, rel=1e-12)


def test_errata_carry_printed_residuals_far_above_tolerance(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, -10, 10)
    errata = {c.id: c.erratum for c in curve.checks if c.erratum is not None}
    assert set(errata) == {
        "theorem-4-i",
        "theorem-4-rotation-angle",
        "recursion-13-two-step",
        "equation-18",
        "equation-18-slope",
        "equation-19",
        "equation-20",
    }
    for check_id, erratum in errata.items():
        assert erratum.printed_residual is not None and erratum.printed_residual > 1e-3, check_id
    assert {e.id for e in errata.values()} == {"E1", "E2", "E3", "E60", "E61", "E62", "E63"}


def _perturbed(data: d4b.D4bPolygons, field: str, index: int, factor: float) -> d4b.D4bPolygons:
    points = getattr(data, field).copy()
    points[index] = points[index] * factor
    return data.replaced(**{field: points})


PERTURBED_P = {
    "theorem-4-i",
    "theorem-4-ii",
    "theorem-4-iii",
    "recursion-13",
    "recursion-13-two-step",
    "theorem-5",
    "nikolaides-d4b",
    # the Gauss images m, ñ were built from the unperturbed p
    "theorem-8",
    "equation-17",
    "equation-18-slope",
}
PERTURBED_TRACTRIX = {
    "theorem-6",
    "nikolaides-d4b",
    "darboux-d4b",
    "darboux-d4b-distance",
    # the Gauss image n was built from the unperturbed tractrix
    "theorem-7",
    "equation-17",
}


@pytest.mark.parametrize(
    ("field", "failing"), [("p", PERTURBED_P), ("tractrix", PERTURBED_TRACTRIX)]
)
def test_checks_fail_on_a_perturbed_polygon(
    float64: Float64, field: str, failing: set[str]
) -> None:
    data = d4b.polygons(float64, 1.0, 0.3, None, -10, 10)
    assert all(verdicts(d4b.evaluate(float64, 1.0, 0.3, data)[1]).values())
    bad = _perturbed(data, field, 12, 1 + 1e-7)
    if field == "tractrix":  # the Darboux transform is derived from the tractrix
        bad = bad.replaced(darboux=2 * bad.tractrix - bad.axis)
    results = verdicts(d4b.evaluate(float64, 1.0, 0.3, bad)[1])
    assert {k for k, v in results.items() if v is False} == failing


def test_rotation_angle_check_fails_when_a_centre_leaves_the_bisector(float64: Float64) -> None:
    # the angle 2 arctan(d/p^y) is the same for every point of the bisector, so only a
    # horizontal displacement (second order in its size) can break the formula
    data = d4b.polygons(float64, 1.0, 0.3, None, -5, 5)
    p = data.p.copy()
    p[6, 0] += 1e-3
    results = verdicts(d4b.evaluate(float64, 1.0, 0.3, data.replaced(p=p))[1])
    assert results["theorem-4-rotation-angle"] is False


def test_hypothesis_check_fails_when_heights_drop_below_d(float64: Float64) -> None:
    data = d4b.polygons(float64, 1.0, 0.3, None, -5, 5)
    p = data.p.copy()
    p[4:6, 1] = 0.2  # p_{i-1}^y p_i^y = 0.04 < d² = 0.09
    check = next(
        c
        for c in d4b.evaluate(float64, 1.0, 0.3, data.replaced(p=p))[1]
        if c.id == "theorem-4-hypothesis"
    )
    assert check.holds is False
    assert check.residual == pytest.approx((0.09 - 0.04) / 0.09)


def test_hypothesis_margin_is_at_least_h_squared(float64: Float64) -> None:
    for beta0 in (None, 0.2, 1.0, 2.9):
        curve = d4b.compute(float64, 1.0, 0.95, beta0, -5, 5)
        y = curve.polygon.vertices[:, 1]
        assert np.min(y[:-1] * y[1:]) >= 1.0 - 1e-12


def test_short_ranges_make_the_long_checks_not_applicable(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, 0, 0)
    results = verdicts(curve.checks)
    assert results["theorem-4-i"] is None
    assert results["theorem-5"] is True


def test_range_order_and_float64_limits_are_domain_errors(float64: Float64) -> None:
    with pytest.raises(DomainError, match="i_max must satisfy i_min <= i_max"):
        d4b.compute(float64, 1.0, 0.1, None, 3, 2)
    with pytest.raises(NotRepresentableError, match=r"\|i_max\| <= 312 in float64"):
        d4b.compute(float64, 1.0, 0.5, None, 0, 313)
    with pytest.raises(NotRepresentableError, match=r"d/h >= 1\.5e-06 in float64"):
        d4b.compute(float64, 1.0, 1e-7, None, 0, 3)


def test_mp_has_no_float64_range_limit() -> None:
    curve = d4b.compute(MultiPrecision(20), 1.0, 0.5, None, 400, 402, "closed-form")
    y = curve.polygon.vertices[0, 1]
    assert y > 10**190
    expected = math.exp(2 * math.atanh(0.5) * 399.5 + math.log(math.sqrt(0.75) / 2))
    assert float(y / 10**190) == pytest.approx(expected / 1e190, rel=1e-12)


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max", "method"),
    [
        (3.0, 2.97, None, 0, 4, "closed-form"),  # d/h = 0.99: rounding grows like h²/(h² − d²)
        (0.0337, 0.0329, 1.36, -30, 30, "construction"),
        (848.0, 0.848, 0.25, 0, 4, "closed-form"),  # d/h = 1e-3 on five vertices
    ],
)
def test_every_check_holds_near_the_ends_of_the_domain(
    float64: Float64, h: float, d: float, beta0: float | None, i_min: int, i_max: int, method: str
) -> None:
    """Cases found by the property test: the tolerances follow the conditioning h²/(h² − d²), and
    c = c_(D1)/c_(D3) is tested through the equation (2), not by comparing constants."""
    curve = d4b.compute(float64, h, d, beta0, i_min, i_max, method)  # type: ignore[arg-type]
    assert [c.id for c in curve.checks if c.holds is False] == []
    assert d4b.conditioning(h, d) == pytest.approx(h * h / ((h - d) * (h + d)))


def test_fitted_constants_come_with_the_checks_that_fit_them(float64: Float64) -> None:
    """A selection without Theorem 4 (i)–(iii) computes no fit and reports no constant."""
    from app.geometry.curve import Selection

    alone = d4b.compute(float64, selection=Selection(checks=frozenset({"theorem-4-hypothesis"})))
    assert alone.constants == {}
    fitted = d4b.compute(float64, selection=Selection(checks=frozenset({"theorem-4-ii"})))
    assert set(fitted.constants) == {"d1", "d3", "eq2"}


@pytest.mark.parametrize("method", ["construction", "closed-form"])
def test_each_section_5_check_alone_equals_its_value_among_all(
    float64: Float64, method: str
) -> None:
    """The Section 5 checks run one by one (each computing what it uses) as in the full set."""
    from app.geometry.curve import Selection

    full = {c.id: c for c in d4b.compute(float64, 1.0, 0.3, 1.1, -20, 25, method).checks}  # type: ignore[arg-type]
    for statement in d4b.d4b_curvature.STATEMENTS:
        alone = d4b.compute(
            float64,
            1.0,
            0.3,
            1.1,
            -20,
            25,
            method,  # type: ignore[arg-type]
            selection=Selection(checks=frozenset({statement.id})),
        ).checks
        assert [c.id for c in alone] == [statement.id]
        assert alone[0] == full[statement.id]


_FITTED = ("theorem-4-i", "theorem-4-ii", "theorem-4-iii")


@pytest.mark.parametrize("detail", [False, True])
@pytest.mark.parametrize(
    "checks",
    [None, frozenset({"theorem-4-iii"}), frozenset({"theorem-4-ii", "recursion-13"}), frozenset()],
)
def test_fits_on_a_second_thread_give_the_one_thread_checks(
    monkeypatch: pytest.MonkeyPatch, detail: bool, checks: frozenset[str] | None
) -> None:
    """Theorem 4 (i)-(iii) with the fits on a second thread (from ``FITS_THREADED_FROM``
    indices, their checks evaluated after the others) are the checks and constants of the fits
    computed where they are read, in the same place of the response."""
    from app.geometry.curve import Selection
    from app.geometry.d4b import checks as d4b_checks

    def fitted(threaded_from: int) -> tuple[object, list[object], list[str]]:
        monkeypatch.setattr(d4b_checks, "FITS_THREADED_FROM", threaded_from)
        result = d4b.compute(
            Float64(), 1.0, 0.3, 0.8, -40, 60, detail=detail, selection=Selection(checks=checks)
        )
        found = [
            (c.id, c.residual, c.tolerance, c.holds, c.erratum, c.note, _bits(c.per_index))
            for c in result.checks
            if c.id in _FITTED
        ]
        constants = {k: float(v).hex() for k, v in result.constants.items()}
        return constants, found, [c.id for c in result.checks]  # in the response's order

    threaded, alone = fitted(1), fitted(10**9)
    assert threaded == alone
    wanted = [s for s in _FITTED if checks is None or s in checks]
    assert [c[0] for c in threaded[1]] == wanted
    assert all(c[1] is not None for c in threaded[1])


def _bits(per_index: object) -> bytes | None:
    """A check's per-index residuals (and indices) as bytes: equal bits compare equal."""
    if per_index is None:
        return None
    return np.asarray(per_index.indices).tobytes() + np.asarray(per_index.residuals).tobytes()  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("beta0", "i_min", "i_max", "method"),
    [(None, -50, 49, "construction"), (1.0, -5, 7, "construction"), (None, 3, 40, "closed-form")],
)
def test_no_check_is_every_check_without_them(
    float64: Float64, beta0: float | None, i_min: int, i_max: int, method: str
) -> None:
    """``checks=none`` (the companions and the construction in one compiled call, no checks'
    context): the polygon, every companion and the tolerances of the default answer, no check
    and no constant."""
    from app.geometry.curve import Selection

    none = Selection(checks=frozenset())
    arguments = (1.0, 0.1, beta0, i_min, i_max, method)
    alone = d4b.compute(float64, *arguments, selection=none)
    every = d4b.compute(float64, *arguments)
    assert alone.checks == [] and alone.constants == {}
    assert alone.polygon.vertices.tobytes() == every.polygon.vertices.tobytes()
    assert list(alone.companions) == list(every.companions)
    for name, polyline in every.companions.items():
        assert alone.companions[name].vertices.tobytes() == polyline.vertices.tobytes(), name
        assert alone.companions[name].indices.tolist() == polyline.indices.tolist()
    assert alone.local_tolerance == every.local_tolerance
    assert alone.companion_tolerances == every.companion_tolerances


def test_no_check_builds_no_gauss_images(float64: Float64, monkeypatch: pytest.MonkeyPatch) -> None:
    """The Gauss image companions come from the compiled call; their closed forms' table (the
    checks') is not built."""
    from app.geometry.curve import Selection
    from app.geometry.d4b import curvature

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("built")

    monkeypatch.setattr(curvature, "build", refuse)
    curve = d4b.compute(float64, selection=Selection(checks=frozenset()))
    assert set(curve.companions) == set(d4b.INFO.companions)


@pytest.mark.parametrize(
    ("i_min", "i_max", "beta0"), [(-40, 25, None), (3, 60, 0.7), (-90, -4, 2.2)]
)
def test_the_gauss_images_of_kept_companions_make_no_hull_arrays(
    float64: Float64, i_min: int, i_max: int, beta0: float | None
) -> None:
    # the images compile_companions kept are read as they are: none of the hull's (n, 2)
    # arrays is made for them, and p_{i_min-1}, p_{i_min} are the hull's rows, bit for bit
    data = d4b.polygons(float64, 1.0, 0.3, beta0, i_min, i_max)
    data.compile_companions()
    images = data.gauss
    lo, built = data._hull
    assert not {"tractrix", "centres", "directions"} & vars(built).keys()
    assert images.contact_edges_before is not None
    rows = built.centres[i_min - 1 - lo : i_min + 1 - lo]
    np.testing.assert_array_equal(images.contact_edges_before, rows)
    # the builders still read the hull when an image is asked for anew (the tests perturb them)
    fresh = d4b.polygons(float64, 1.0, 0.3, beta0, i_min, i_max).gauss
    for name in ("tractrix_gauss", "contact", "gauss"):
        np.testing.assert_array_equal(getattr(fresh, name), getattr(images, name))
    np.testing.assert_array_equal(fresh.contact_edges_before, rows)
