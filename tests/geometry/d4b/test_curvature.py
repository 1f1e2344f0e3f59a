"""Section 5 on (D4b): Gauss images against an independent mp reference, (18)–(20), Thms 7, 8."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from app.geometry.d4b import closed_forms as kcf, discretization as d4b
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from tests.reference import curvature as reference, d4b as reference_d4b

SECTION_5 = {
    "equation-17",
    "equation-18",
    "equation-18-slope",
    "equation-19",
    "equation-19-rotation",
    "equation-20-inversion",
    "equation-20",
    "theorem-7",
    "theorem-8",
}


def _reference(h: str, d: str, beta0: str | None, i_min: int, i_max: int):
    """n, ñ, m on i_min .. i_max from the reference construction (dicts i -> (x, y))."""
    ctx = reference.context()
    lo, hi = min(0, i_min - 1), max(0, i_max + 2)
    p, tractrix, axis = reference_d4b.construct(h, d, beta0, lo, hi)
    stick = (tractrix[0][0] - axis[0][0], tractrix[0][1] - axis[0][1])
    length = ctx.sqrt(stick[0] ** 2 + stick[1] ** 2)
    n = reference.inscribed(ctx, tractrix, 0, (stick[1] / length, -stick[0] / length))
    contacts = reference.contact_points(ctx, p)
    m = reference.circumscribed(ctx, contacts)
    return n, contacts, m, p, tractrix


def _compare(ar: Arithmetic, got: np.ndarray, expected: dict, i_min: int, tolerance: float) -> None:
    for k, point in enumerate(got):
        want = expected[i_min + k]
        scale = max(abs(want[0]) + abs(want[1]), 1e-300)
        error = (
            abs(ar.to_float(point[0] - want[0])) + abs(ar.to_float(point[1] - want[1]))
        ) / scale
        assert error < tolerance, (i_min + k, error)


@pytest.mark.parametrize(("ar", "tolerance"), [(Float64(), 1e-12), (MultiPrecision(40), 1e-35)])
@pytest.mark.parametrize(("h", "d", "beta0"), [("1", "0.3", None), ("2", "0.15", "0.8")])
def test_gauss_images_agree_with_the_reference(
    ar: Arithmetic, tolerance: float, h: str, d: str, beta0: str | None
) -> None:
    i_min, i_max = -6, 7
    curve = d4b.compute(
        ar, float(h), float(d), None if beta0 is None else float(beta0), i_min, i_max
    )
    n, contacts, m, _, _ = _reference(h, d, beta0, i_min, i_max)
    _compare(ar, curve.companions["tractrix_gauss_image"].vertices, n, i_min, tolerance)
    _compare(ar, curve.companions["contact_points"].vertices, contacts, i_min, tolerance)
    _compare(ar, curve.companions["gauss_image"].vertices, m, i_min, tolerance)


def test_theorem_7_k_is_minus_one_over_h_squared_in_the_reference() -> None:
    # the reference's own Newell/polarization areas on the reference polygons
    ctx = reference.context()
    n, _, m, p, tractrix = _reference("1.5", "0.4", None, -3, 3)
    angle = ctx.pi / 7
    for i in range(-3, 3):
        K, _ = reference.curvatures(
            ctx,
            reference.face(ctx, tractrix[i], tractrix[i + 1], angle),
            reference.face(ctx, n[i], n[i + 1], angle),
        )
        assert abs(K + 1 / ctx.mpf("2.25")) < ctx.mpf("1e-50")
        _, H = reference.curvatures(
            ctx,
            reference.face(ctx, p[i], p[i + 1], angle),
            reference.face(ctx, m[i], m[i + 1], angle),
        )
        assert abs(H) < ctx.mpf("1e-50")


@pytest.mark.parametrize("beta0", [None, 0.4, 2.5])
@pytest.mark.parametrize(("h", "d"), [(1.0, 0.1), (3.0, 2.0), (0.2, 0.01)])
def test_section_5_checks_hold(float64: Float64, h: float, d: float, beta0: float | None) -> None:
    curve = d4b.compute(float64, h, d, beta0, -12, 12)
    results = {c.id: c for c in curve.checks if c.id in SECTION_5}
    assert set(results) == SECTION_5
    for check in results.values():
        assert check.holds is True, (check.id, check.residual)


def test_section_5_checks_at_40_digits(mp40: MultiPrecision) -> None:
    curve = d4b.compute(mp40, 1.0, 0.3, None, -8, 8)
    for check in curve.checks:
        if check.id in SECTION_5:
            assert check.holds is True and check.residual is not None
            assert check.residual < 1e-45, check.id


def test_the_zero_over_zero_face_of_the_catenoid_is_noted(float64: Float64) -> None:
    # p_0 = (−d, h) and p_1 = (d, h): the face 0 is a cylinder band
    curve = d4b.compute(float64, 1.0, 0.3, None, -3, 3)
    check = next(c for c in curve.checks if c.id == "equation-17")
    assert check.note is not None and "0/0 on 1 face" in check.note
    tilted = d4b.compute(float64, 1.0, 0.3, 1.2, -3, 3)
    assert next(c for c in tilted.checks if c.id == "equation-17").note is None


@pytest.mark.parametrize("field", ["tractrix_gauss", "contact", "gauss"])
def test_checks_fail_when_a_gauss_image_is_perturbed(float64: Float64, field: str) -> None:
    data = d4b.polygons(float64, 1.0, 0.3, None, -6, 6)
    images = data.gauss
    points = getattr(images, field).copy()
    points[5] = points[5] * (1 + 1e-7)
    bad = data.replaced(gauss=images.replaced(**{field: points}))
    results = {c.id: c.holds for c in d4b.evaluate(float64, 1.0, 0.3, bad)[1]}
    failing = {k for k, v in results.items() if v is False}
    expected = {
        # a radial perturbation keeps n_i on the line of slope k_{i+1}: equation-18-slope
        # (a statement about directions) still holds; see the rotation test below
        "tractrix_gauss": {
            "equation-18",
            "equation-19-rotation",
            "theorem-7",
            "equation-17",
        },
        "contact": {"equation-19", "equation-19-rotation", "equation-20-inversion"},
        "gauss": {"equation-20", "equation-20-inversion", "theorem-8", "equation-17"},
    }[field]
    assert failing == expected


def test_printed_forms_are_wrong_and_their_residuals_are_reported(float64: Float64) -> None:
    curve = d4b.compute(float64, 1.0, 0.3, None, -10, 10)
    errata = {c.id: c.erratum for c in curve.checks if c.erratum is not None}
    for check_id, entry in (
        ("equation-18", "E60"),
        ("equation-18-slope", "E61"),
        ("equation-19", "E62"),
        ("equation-20", "E63"),
    ):
        erratum = errata[check_id]
        assert erratum is not None and erratum.id == entry
        assert erratum.printed_residual is not None and erratum.printed_residual > 0.5


def test_stable_closed_forms_equal_the_power_forms_at_60_digits() -> None:
    ar = MultiPrecision(60)
    h, d = ar.scalar("1.7"), ar.scalar("0.45")
    zero = ar.scalar(0)
    for i in range(-4, 5):
        a2, b2 = (h - d) ** (2 * i), (h + d) ** (2 * i)
        A, B = b2 - a2, a2 + b2
        root = 2 * (h - d) ** i * (h + d) ** i
        index = ar.array([i])
        checks = {
            "18": (kcf.tractrix_gauss_image(ar, h, d, index, zero), (root / B, A / B)),
            "18 printed": (
                kcf.tractrix_gauss_image_printed(ar, h, d, index, zero),
                (root / B, -A / B),
            ),
            "19": (kcf.contact_points(ar, h, d, index, zero), (-A / B, root / B)),
            "19 printed": (kcf.contact_points_printed(ar, h, d, index, zero), (A / B, root / B)),
            "20": (
                kcf.circumscribed_gauss_image(ar, h, d, index, zero),
                ((d * B - h * A) / (h * B - d * A), 2 * h * (h * h - d * d) ** i / (h * B - d * A)),
            ),
            "20 printed": (
                kcf.circumscribed_gauss_image_printed(ar, h, d, index, zero),
                ((h * A - d * B) / (d * A + h * B), 2 * h * (h * h - d * d) ** i / (d * A + h * B)),
            ),
        }
        for name, (got, (x, y)) in checks.items():
            assert abs(got[0, 0] - x) < 1e-55 and abs(got[0, 1] - y) < 1e-55, (name, i)


def test_m_is_h_over_p_and_the_printed_20_is_shifted_by_one_index() -> None:
    ar = MultiPrecision(40)
    curve = d4b.compute(ar, 1.0, 0.3, None, -4, 4)
    p = curve.polygon.vertices
    m = curve.companions["gauss_image"].vertices
    for k in range(len(p)):
        assert abs(m[k, 1] * p[k, 1] - 1) < 1e-45
    printed = kcf.circumscribed_gauss_image_printed(
        ar, ar.scalar(1), ar.scalar("0.3"), ar.indices(-4, 3), ar.scalar(0)
    )
    # its second component is m_{i+1}^y
    for k in range(len(printed)):
        assert abs(printed[k, 1] - m[k + 1, 1]) < 1e-45


def test_slope_check_fails_when_n_is_turned(float64: Float64) -> None:
    data = d4b.polygons(float64, 1.0, 0.3, None, -6, 6)
    n = data.gauss.tractrix_gauss.copy()
    c, s = np.cos(1e-7), np.sin(1e-7)
    n[5] = [c * n[5, 0] - s * n[5, 1], s * n[5, 0] + c * n[5, 1]]
    bad = data.replaced(gauss=data.gauss.replaced(tractrix_gauss=n))
    results = {c.id: c.holds for c in d4b.evaluate(float64, 1.0, 0.3, bad)[1]}
    assert results["equation-18-slope"] is False


@pytest.mark.parametrize(
    ("h", "d", "beta0", "i_min", "i_max"),
    [(1.0, 0.1, None, -10, 10), (1.0, 1e-4, 1.0, -3000, 5000), (2.0, 0.5, 2.5, -1300, 1300)],
)
@pytest.mark.parametrize("method", ["construction", "closed-form"])
def test_closed_n_read_off_the_closed_contact_points_has_the_bits_of_its_own_form(
    h: float, d: float, beta0: float | None, i_min: int, i_max: int, method: str
) -> None:
    """Float64: (18)'s closed form n_i = (sech t, tanh t) is read off ñ_i = (−tanh t, sech t)
    at the same t; the same numbers as evaluating (18) itself (the last case reaches |t| near 700,
    the edge of the shortcut)."""
    ar = Float64()
    data = d4b.polygons(ar, h, d, beta0, i_min, i_max, method)  # type: ignore[arg-type]
    expected = kcf.tractrix_gauss_image(
        ar, data.h, data.d, ar.indices(i_min, i_max + 1), data.shift
    )
    got = data.gauss.closed_tractrix_gauss
    assert got.view(np.int64).tolist() == expected.view(np.int64).tolist()


@pytest.mark.parametrize("detail", [False, True])
@pytest.mark.parametrize(
    "checks", [None, frozenset({"equation-17"}), frozenset({"theorem-7", "theorem-8"})]
)
def test_both_rings_on_two_threads_give_the_one_thread_checks(
    monkeypatch: pytest.MonkeyPatch, detail: bool, checks: frozenset[str] | None
) -> None:
    """Theorems 7, 8 and (17) with the two rings on two threads (from
    ``RINGS_THREADED_FROM`` faces) are the checks of the rings computed one after the other."""
    from app.geometry.curve import Selection
    from app.geometry.d4b import curvature

    def section_5(threaded_from: int) -> list[object]:
        monkeypatch.setattr(curvature, "RINGS_THREADED_FROM", threaded_from)
        result = d4b.compute(
            Float64(), 1.0, 0.3, 0.8, -40, 60, detail=detail, selection=Selection(checks=checks)
        )
        return [
            (c.id, c.residual, c.tolerance, c.holds, c.erratum, c.note, _bits(c.per_index))
            for c in result.checks
            if c.id in SECTION_5
        ]

    threaded, alone = section_5(1), section_5(10**9)
    assert threaded == alone and len(threaded) == (9 if checks is None else len(checks))


def _bits(per_index: object) -> bytes | None:
    """A check's per-index residuals (and indices) as bytes: equal bits compare equal."""
    if per_index is None:
        return None
    return np.asarray(per_index.indices).tobytes() + np.asarray(per_index.residuals).tobytes()  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("d", "beta0", "i_min", "i_max"),
    [(0.1, None, -10, 10), (0.5, None, -200, 300), (1e-3, 0.7, -9000, 11000), (0.3, 2.9, -3, 40)],
)
@pytest.mark.parametrize(
    "checks",
    [None, frozenset({"equation-18"}), frozenset({"equation-19"}), frozenset({"equation-20"})],
)
def test_blocked_image_comparisons_give_the_stored_closed_forms_checks(
    monkeypatch: pytest.MonkeyPatch,
    d: float,
    beta0: float | None,
    i_min: int,
    i_max: int,
    checks: frozenset[str] | None,
) -> None:
    """(18)-(20) without detail: each closed point made and compared a block at a time
    (``fused_checks.closed_image_comparisons``) gives the checks, errata included, of the
    stored closed forms: the same tolerances, verdicts, errata and notes; the residuals within a
    thousandth of their tolerance and the printed residuals within 1e-12 relative (since session
    22 the blocks make the closed forms from one exponential a row and take one square root a
    block, which moves them at their last bits)."""
    from app.geometry.curve import Selection
    from app.geometry.d4b import fused_checks

    def section_5() -> list[object]:
        result = d4b.compute(Float64(), 1.0, d, beta0, i_min, i_max, selection=Selection(checks))
        return [
            (c.id, c.residual, c.tolerance, c.holds, c.erratum, c.note)
            for c in result.checks
            if c.id in SECTION_5
        ]

    blocked = section_5()
    monkeypatch.setattr(fused_checks, "closed_image_comparisons", lambda *_: None)
    stored = section_5()
    assert len(blocked) == len(stored)
    for found, expected in zip(blocked, stored, strict=True):
        id_, residual, tolerance, holds, erratum, note = found
        assert (id_, tolerance, holds, note) == (expected[0], *expected[2:4], expected[5])
        assert abs(residual - expected[1]) <= 1e-3 * tolerance, (found, expected)
        printed = None if erratum is None else erratum.printed_residual
        expected_printed = None if expected[4] is None else expected[4].printed_residual
        assert (printed is None) == (expected_printed is None), (found, expected)
        if printed is not None:
            assert printed == pytest.approx(expected_printed, rel=1e-12), (found, expected)
            assert replace(erratum, printed_residual=0.0) == replace(
                expected[4], printed_residual=0.0
            )


@pytest.mark.parametrize("method", ["construction", "closed-form"])
@pytest.mark.parametrize("detail", [False, True])
def test_every_path_of_section_5_gives_the_same_checks(method: str, detail: bool) -> None:
    """Each statement of Section 5 alone, the Gauss images' statements together, and every
    check: the same residuals, verdicts and errata (the statements share passes differently:
    (19) as a rotation and (20) by inversion in one pass without the resolutions' arrays when
    nothing else reads them; (18) by slopes with its erratum in one pass)."""
    from app.geometry.curve import EVERYTHING, Selection
    from app.geometry.d4b import curvature as section5

    ar = Float64()

    def answer(selection: Selection) -> dict[str, object]:
        curve = d4b.compute(ar, 1.0, 0.3, 1.2, -40, 60, method, detail, selection)  # type: ignore[arg-type]
        return {
            c.id: (c.residual, c.tolerance, c.holds, c.erratum, c.note, repr(c.per_index))
            for c in curve.checks
        }

    every = answer(EVERYTHING)
    ids = [s.id for s in section5.STATEMENTS]
    groups = [[i] for i in ids] + [ids[3:7], ["equation-19-rotation", "equation-20-inversion"]]
    for group in groups:
        found = answer(Selection(checks=frozenset(group)))
        for i in group:
            assert found[i] == every[i], i
