"""Refinement study of Theorem 11: orders and errors against an independent study, the order-2
analysis, every check holding on true data and failing on perturbed data, errata, domain."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.geometry.d2b import closed_forms as cc, construction as vmc
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from app.geometry.studies import theorem_11 as cr
from tests.reference import catenoid_refinement as reference

SMALL = {"j0": 4, "levels": 4, "i_min": -1, "i_max": 8}


@pytest.fixture(scope="module")
def reference_study() -> list:
    return reference.study(**SMALL)


def verdicts(study) -> dict[str, bool | None]:
    return {c.id: c.holds for c in study.checks}


def test_observed_orders_and_errors_agree_with_an_independent_study(
    reference_study: list,
) -> None:
    study = cr.theorem_11(Float64(), **SMALL)
    assert [level.step for level in study.levels] == [0.25, 0.125, 0.0625, 0.03125]
    for measure in study.info.measures:
        expected = reference.order(reference_study, measure.id)
        assert study.fits[measure.id].order == pytest.approx(expected, abs=0.05), measure.id
        ours = [level.errors[measure.id] for level in study.levels]
        theirs = [float(errors[measure.id]) for _, errors in reference_study]
        # same vertices, same sup: agreement to rounding (distances: to the golden search's)
        rtol = 1e-6 if measure.id.endswith("distance") else 1e-10
        np.testing.assert_allclose(ours, theirs, rtol=rtol, err_msg=measure.id)


def test_default_orders_are_the_predicted_ones_and_every_check_holds() -> None:
    study = cr.theorem_11(Float64())
    for measure in study.info.measures:
        fit = study.fits[measure.id]
        assert fit.levels == tuple(range(7)), measure.id
        assert fit.order == pytest.approx(measure.expected_order, abs=0.06), measure.id
    assert all(v is True for v in verdicts(study).values()), verdicts(study)
    assert {c.id for c in study.checks} == {s.id for s in study.info.statements}


def test_the_error_is_the_cubed_integral_over_six_j_squared() -> None:
    """With u = artanh g the error is Σ (sinh Δu − Δu) ≈ (1/(6j²))|∫_0^t u'³|; its largest value
    on the compact set is at an end (Remark 13: t = −1/4; Example 12: t = 2)."""
    study = cr.theorem_11(Float64())
    finest = study.levels[-1]
    j = round(1 / finest.step)
    remark = float(reference.error_integral("remark-13", -0.25, 0))
    example = float(reference.error_integral("example-12", 0, 2))
    assert remark == pytest.approx(0.125, rel=1e-12)  # ∫_{−1/4}^0 (1 + 2t)^−3 dt = 3/4
    assert finest.errors["remark-13"] * j * j == pytest.approx(remark, rel=2e-3)
    assert finest.errors["example-12"] * j * j == pytest.approx(example, rel=2e-3)


def test_every_check_holds_at_30_digits() -> None:
    study = cr.theorem_11(MultiPrecision(30), j0=4, levels=3, i_min=-1, i_max=4)
    assert all(v is True for v in verdicts(study).values()), verdicts(study)
    lemma = next(c for c in study.checks if c.id == "lemma-10")
    assert lemma.residual is not None and lemma.residual < 1e-38


def _shifted(amount: float):
    """A (D2b) construction whose meridian is moved sideways by ``amount`` (not shrinking)."""

    def meridian(ar: Arithmetic, n, start: int):
        p = vmc.catenoid_meridian(ar, n, start)
        p[:, 0] = p[:, 0] + ar.scalar(amount)
        return p

    return meridian


def test_checks_fail_on_a_perturbed_meridian() -> None:
    study = cr.theorem_11(Float64(), **SMALL, meridian=_shifted(1e-3))
    found = {c.id: c for c in study.checks}
    for key in ("theorem-11", "lemma-10", "remark-13-uniform"):
        assert found[key].holds is False, key
    assert found["theorem-11"].residual is not None and found["theorem-11"].residual > 0.9
    # the hypotheses are about the Gauss image and Lemma 10's proof about g: unaffected
    assert found["example-12"].holds is True and found["lemma-10-proof"].holds is True


def test_hypothesis_checks_fail_on_a_perturbed_gauss_image(float64: Float64) -> None:
    from app.geometry.d2b import discretization as d2b

    seq = vmc.named_sequence(float64, "remark-13", 8, -3, 10)
    n = vmc.gauss_image(float64, seq)
    indices = np.arange(-3, 11)
    assert float(np.max(d2b.hypothesis_residuals(float64, "remark-13", 8, indices, n))) == 0
    n[5, 0] += 1e-9
    assert float(np.max(d2b.hypothesis_residuals(float64, "remark-13", 8, indices, n))) > 5e-10


def test_errata_carry_the_printed_forms_residuals() -> None:
    study = cr.theorem_11(Float64())
    found = {c.id: c for c in study.checks}
    lemma = found["lemma-10"].erratum
    assert lemma is not None and lemma.id == "E64"
    assert lemma.printed_residual is not None and lemma.printed_residual > 0.1
    uniform = found["remark-13-uniform"].erratum
    assert uniform is not None and uniform.id == "E66"
    assert uniform.printed_residual is not None and uniform.printed_residual > 0.99
    proof = found["lemma-10-proof"].erratum
    assert proof is not None and proof.id == "E65"
    assert proof.printed_residual is not None and proof.printed_residual > 0.9
    # the corrected claims hold with margin
    assert found["remark-13-uniform"].residual is not None
    assert found["remark-13-uniform"].residual < 0.3
    domain = [level.errors["remark-13-domain"] for level in study.levels]
    assert all(e is not None and 0.0069 < e < 0.0096 for e in domain), domain


def test_a_bounded_derivative_does_not_make_the_convergence_uniform(float64: Float64) -> None:
    """E66, the general counterexample: g = tanh has g' <= 1, but u = artanh g = t has u' = 1 and
    the error grows like t/(6j²) without bound."""
    j = 16
    count = 8 * j + 1
    values = [math.tanh(i / j) for i in range(count)]
    seq = vmc.custom_sequence(float64, values, 0)
    p = vmc.catenoid_meridian(float64, vmc.gauss_image(float64, seq), 0)
    t = float64.indices(0, count - 1) / j
    c = cc.limit_points(float64, t)  # artanh g(t) = t
    error = np.abs(p[:, 0] - c[:, 0])
    for i in (2 * j, 4 * j, 8 * j):
        assert error[i] == pytest.approx((i / j) / (6 * j * j), rel=1e-3), i
    assert error[8 * j] > 3.9 * error[2 * j]


@pytest.mark.parametrize(
    ("arguments", "parameter", "constraint"),
    [
        ({"j0": 0}, "j0", "j0 >= 1"),
        ({"levels": 1}, "levels", "levels >= 2"),
        ({"i_max": 0, "i_min": -1}, "i_max", "i_max >= 1"),
        ({"i_min": 8}, "i_min", "i_min < i_max"),
        ({"i_min": -2}, "i_min", "i_min > −j0/2"),
    ],
)
def test_domain_errors_name_the_parameter(arguments: dict, parameter: str, constraint: str) -> None:
    with pytest.raises(DomainError, match=constraint.replace("(", r"\(")) as error:
        cr.theorem_11(Float64(), **arguments)
    assert error.value.parameter == parameter
    with pytest.raises(DomainError):
        cr.work(**{**SMALL, **arguments})


def test_work_counts_the_constructed_and_measured_vertices() -> None:
    # level 0: j = 4, Example 12 on 0..8 (9), Remark 13 on −1..8 (10); level 1: j = 8,
    # Example 12 on 0..16 (17), Remark 13 built on −3..16 (20), measured on −2..16 (19)
    assert cr.work(4, 2, -1, 8) == (9 + 10 + 17 + 20, 9 + 10 + 17 + 19)
    study = cr.theorem_11(Float64(), 4, 2, -1, 8)
    assert [(level.vertices, level.samples) for level in study.levels] == [(19, 19), (37, 36)]
    assert cr.mp_work(4, 2, -1, 8) == 56 + 30 * 55
    assert cr.work(1, 64, 0, 1)[0] >= 10**15  # capped, never computed
