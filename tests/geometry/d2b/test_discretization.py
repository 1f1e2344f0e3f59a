"""(D2b): the construction against an independent reference, every check true and perturbed."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from app.geometry.d2b import (
    closed_forms as catenoid_convergence,
    construction as vanishing_mean_curvature,
    discretization as d2b,
)
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from tests.reference import curvature as reference

ALL = {s.id for s in d2b.STATEMENTS}


def verdicts(checks: list) -> dict[str, bool | None]:
    return {c.id: c.holds for c in checks}


def _reference_sequence(ctx, name: str, j: int, i_min: int, i_max: int) -> dict:
    out = {}
    for i in range(min(0, i_min), max(0, i_max) + 1):
        ii, jj = ctx.mpf(i), ctx.mpf(j)
        out[i] = 4 * ii * ii / (jj * jj + 4 * ii * ii) if name == "example-12" else ii / (ii + jj)
    return out


@pytest.mark.parametrize(("ar", "tolerance"), [(Float64(), 1e-12), (MultiPrecision(40), 1e-35)])
@pytest.mark.parametrize(
    ("name", "j", "i_min", "i_max"), [("example-12", 3, 0, 9), ("remark-13", 6, -2, 8)]
)
def test_meridian_agrees_with_the_reference(
    ar: Arithmetic, tolerance: float, name: str, j: int, i_min: int, i_max: int
) -> None:
    ctx = reference.context()
    expected, gauss = reference.d2b(ctx, _reference_sequence(ctx, name, j, i_min, i_max))
    curve = d2b.compute(ar, name, j, None, i_min, i_max)  # type: ignore[arg-type]
    for k, i in enumerate(range(i_min, i_max + 1)):
        for got, want in (
            (curve.polygon.vertices[k], expected[i]),
            (curve.companions["gauss_image"].vertices[k], gauss[i]),
        ):
            scale = abs(want[0]) + abs(want[1])
            error = abs(ar.to_float(got[0] - want[0])) + abs(ar.to_float(got[1] - want[1]))
            assert error / scale < tolerance, (i, error)


def test_custom_sequence_agrees_with_the_reference(mp40: MultiPrecision) -> None:
    values = [-0.7, -0.25, 0.0, 0.1, 0.55, 0.9, 0.999]
    ctx = reference.context()
    s = {i - 2: ctx.mpf(repr(v)) for i, v in enumerate(values)}
    expected, _ = reference.d2b(ctx, s)
    curve = d2b.compute(mp40, "custom", None, values, -2, 4)
    for k, i in enumerate(range(-2, 5)):
        got = curve.polygon.vertices[k]
        assert abs(got[0] - expected[i][0]) + abs(got[1] - expected[i][1]) < 1e-36 * abs(
            expected[i][1]
        )


@pytest.mark.parametrize(
    ("name", "j", "s", "i_min", "i_max"),
    [
        ("example-12", 5, None, None, None),
        ("example-12", 1, None, 0, 40),
        ("remark-13", 7, None, None, None),
        ("remark-13", 2, None, 0, 30),
        ("custom", None, [-0.6, -0.1, 0.0, 0.3, 0.31, 0.95], -2, None),
    ],
)
def test_every_check_holds_in_float64(
    float64: Float64, name: str, j: int | None, s: list[float] | None, i_min, i_max
) -> None:
    curve = d2b.compute(float64, name, j, s, i_min, i_max)  # type: ignore[arg-type]
    results = verdicts(curve.checks)
    assert set(results) == ALL
    expected_none = {"example-12", "remark-13"} - {name}
    if name == "custom":
        expected_none |= {"theorem-11", "example-12", "remark-13"}
    assert {k for k, v in results.items() if v is None} == expected_none
    assert all(v is True for k, v in results.items() if k not in expected_none)


def test_every_check_holds_at_40_digits(mp40: MultiPrecision) -> None:
    curve = d2b.compute(mp40, "remark-13", 8, None, -3, 12)
    for check in curve.checks:
        if check.id in {"theorem-11", "example-12"}:
            continue
        assert check.holds is True, check.id
        assert check.residual is not None and check.residual < 1e-45, check.id


def test_radii_are_one_over_the_gauss_image_and_p0_is_0_1(float64: Float64) -> None:
    curve = d2b.compute(float64, "example-12", 4, None, 0, 12)
    p, n = curve.polygon.vertices, curve.companions["gauss_image"].vertices
    assert p[0].tolist() == [0.0, 1.0] and n[0].tolist() == [0.0, 1.0]
    np.testing.assert_allclose(p[:, 1] * n[:, 1], 1.0, rtol=1e-14)
    # the meridian runs towards −x (every x-step (s_k − s_{k+1})/… is negative)
    assert np.all(np.diff(p[:, 0]) < 0)


def test_convergence_to_the_catenary_is_of_order_two(float64: Float64) -> None:
    distances = []
    for j in (4, 8, 16, 32):
        curve = d2b.compute(float64, "example-12", j, None, 0, 2 * j)
        distances.append(d2b.distance_to_limit(float64, "example-12", j, curve.polygon.vertices, 0))
    orders = np.log2(np.array(distances[:-1]) / np.array(distances[1:]))
    assert np.all(orders > 1.8) and np.all(orders < 2.1)
    # the limit points lie on C: c(t) = (−artanh g, cosh artanh g)
    t = np.linspace(0, 2, 5)
    c = catenoid_convergence.limit_points(
        float64, catenoid_convergence.artanh_example_12(float64, t)
    )
    np.testing.assert_allclose(c[:, 1], np.cosh(c[:, 0]), rtol=1e-15)
    np.testing.assert_allclose(np.tanh(-c[:, 0]), catenoid_convergence.example_12_g(t), rtol=1e-15)


def test_lemma_10_printed_convention_is_wrong_for_negative_indices(float64: Float64) -> None:
    curve = d2b.compute(float64, "remark-13", 10, None, -4, 6)
    check = next(c for c in curve.checks if c.id == "lemma-10")
    assert check.holds is True
    assert check.erratum is not None and check.erratum.id == "E64"
    assert check.erratum.printed_residual is not None and check.erratum.printed_residual > 0.1
    # without negative indices there is nothing to evaluate the printed convention on
    positive = d2b.compute(float64, "example-12", 5, None, 0, 6)
    lemma = next(c for c in positive.checks if c.id == "lemma-10")
    assert lemma.erratum is not None and lemma.erratum.printed_residual is None


def test_lemma_10_printed_sum_by_hand(mp40: MultiPrecision) -> None:
    ar = mp40
    s = ar.array(["-0.5", "-0.2", "0", "0.4"])
    rest = (1 - s) * (1 + s)
    t = catenoid_convergence.lemma_10_terms(ar, s, rest)
    where, printed = catenoid_convergence.lemma_10_printed(ar, s, rest, 2)
    assert where == slice(1, 4)
    # i = −1 (local 1): printed Σ_{k=−2}^{0} t_k; i = 0: Σ_{k=−1}^{0} t_k; i = 1: t_0
    assert abs(printed[0] - (t[0] + t[1] + t[2])) < 1e-45
    assert abs(printed[1] - (t[1] + t[2])) < 1e-45
    assert abs(printed[2] - t[2]) < 1e-45
    closed = catenoid_convergence.lemma_10(ar, s, rest, 2)
    assert abs(closed[1, 0] + t[1]) < 1e-45 and abs(closed[0, 0] + t[0] + t[1]) < 1e-45
    assert closed[2, 0] == 0


PERTURBABLE = {"d2b-mean-curvature", "d2b-parallel", "equation-17", "theorem-11-radii", "lemma-10"}


def test_checks_fail_on_a_perturbed_meridian(float64: Float64) -> None:
    data = d2b.polygons(float64, "remark-13", 6, None, -2, 10)
    assert all(v is not False for v in verdicts(d2b.evaluate(float64, data)).values())
    p = data.p.copy()
    p[5] = p[5] * (1 + 1e-7)
    results = verdicts(d2b.evaluate(float64, replace(data, p=p)))
    assert {k for k, v in results.items() if v is False} == PERTURBABLE | {"theorem-11-recursion"}


def test_example_check_fails_on_a_perturbed_gauss_image(float64: Float64) -> None:
    data = d2b.polygons(float64, "example-12", 4, None, 0, 8)
    n = data.n.copy()
    n[3, 0] += 1e-9
    results = verdicts(d2b.evaluate(float64, replace(data, n=n)))
    assert results["example-12"] is False


def test_convergence_check_fails_when_the_refinement_does_not_get_closer(float64: Float64) -> None:
    data = d2b.polygons(float64, "example-12", 4, None, 0, 8)
    assert verdicts(d2b.evaluate(float64, data))["theorem-11"] is True
    fine_sequence, fine_n, fine_p = data.refined  # type: ignore[misc]
    bad = data.replaced(refined=(fine_sequence, fine_n, fine_p + np.array([0.1, 0.0])))
    assert verdicts(d2b.evaluate(float64, bad))["theorem-11"] is False


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (("example-12", 5, None, -1, 4), "i_min >= 0 for sequence=example-12"),
        (("remark-13", 6, None, -3, 4), "i_min > −j/2"),
        (("example-12", 0, None, 0, 4), "j >= 1"),
        (("example-12", 5, None, 4, 3), "i_min <= i_max"),
        (("custom", None, [0.0, 0.5, 0.5], 0, None), "strictly increasing"),
        (("custom", None, [0.0, 0.5, 1.0], 0, None), r"\|s_i\| < 1"),
        (("custom", None, [0.0, float("nan")], 0, None), "finite"),
        (("custom", None, [0.1, 0.5], 0, None), "s_0 = 0"),
        (("custom", None, [0.0, 0.5], 1, None), "the list must contain s_0"),
        (("custom", None, [0.0, 0.5], 0, 5), "i_max = i_min \\+ len\\(s\\) − 1"),
        (("custom", None, [0.0], 0, None), "at least two values"),
        (("custom", 3, [0.0, 0.5], 0, None), "j is not used with sequence=custom"),
        (("example-12", 3, [0.0, 0.5], 0, None), "only used with sequence=custom"),
    ],
)
def test_domain_errors(float64: Float64, arguments: tuple, message: str) -> None:
    with pytest.raises(DomainError, match=message):
        d2b.compute(float64, *arguments)


def test_named_sequences_keep_one_minus_s_squared_accurate() -> None:
    ar = Float64()
    seq = vanishing_mean_curvature.named_sequence(ar, "example-12", 1, 0, 10_000)
    # 1 − s_i² = j²(j² + 8i²)/(j² + 4i²)²; at i = 10⁴ it is ≈ 5e-8, computed to full precision
    i = 10_000.0
    expected = (1 + 8 * i * i) / (1 + 4 * i * i) ** 2
    assert seq.one_minus_s2[-1] == pytest.approx(expected, rel=1e-15)
