"""precision=mp of every discretization on rigorous balls (issue 15): the same answers as the
mpmath path, certified, and branch choices decided by raising the precision, never guessed."""

from __future__ import annotations

from decimal import Decimal
from typing import Any

import flint
import mpmath
import pytest
from fastapi.testclient import TestClient

from app.geometry import balls
from app.geometry.ball_arithmetic import Ball
from app.geometry.curve import Curve
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import MultiPrecision, UndecidedError
from app.registry import DISCRETIZATIONS


def _served(identifier: str, digits: int, **query: Any) -> tuple[Curve, dict[str, Any]]:
    entry = DISCRETIZATIONS[identifier]
    parsed = entry.query.model_validate({"precision": "mp", "digits": digits, **query})
    arguments = parsed.core_arguments()
    curve = balls.serve(
        identifier, MultiPrecision(digits), lambda ar: entry.compute(ar, **arguments), arguments
    )
    return curve, arguments


@pytest.mark.parametrize("identifier", sorted(DISCRETIZATIONS))
def test_balls_agree_with_mpmath_and_are_certified(identifier: str) -> None:
    assert balls.serves(identifier)
    curve, arguments = _served(identifier, 30)
    ar = curve.arithmetic
    assert isinstance(ar, Ball)
    certificate = balls.certificate(ar)
    assert certificate is not None and certificate.resolved
    on_mpmath = DISCRETIZATIONS[identifier].compute(MultiPrecision(30), **arguments)
    mp = on_mpmath.arithmetic
    assert isinstance(mp, MultiPrecision)
    ctx = mpmath.MPContext()
    ctx.dps = 40
    for name, polyline in [("p", curve.polygon), *curve.companions.items()]:
        other = on_mpmath.polygon if name == "p" else on_mpmath.companions[name]
        for x, y in zip(
            ar.to_strings(polyline.vertices.reshape(-1)),
            mp.to_strings(other.vertices.reshape(-1)),
            strict=True,
        ):
            assert abs(ctx.mpf(x) - ctx.mpf(y)) <= 1e-28 * max(1, abs(ctx.mpf(y))), name
    assert {c.id: c.holds for c in curve.checks} == {c.id: c.holds for c in on_mpmath.checks}
    for check in curve.checks:
        if check.holds is True:
            assert check.residual is not None and check.residual <= check.tolerance


def test_a_comparison_the_balls_cannot_decide_raises() -> None:
    ar = Ball(30)
    with balls.working_precision(ar.bits):
        a, b = flint.arb(1, 1e-20), flint.arb(1)
        with pytest.raises(UndecidedError):
            ar.exceeds(a, b, "beta0", "which stick is the cusp stick")
        assert ar.exceeds(flint.arb(2), b, "beta0", "x") is True
        assert ar.exceeds(b, flint.arb(2), "beta0", "x") is False
        both = ar.at_least_or(a, b, flint.arb(3), flint.arb(5))
        assert both.contains(3) and both.contains(5)


def test_the_cusp_stick_near_a_tie_is_decided_by_raising_the_precision() -> None:
    ctx = mpmath.MPContext()
    ctx.dps = 120
    beta0 = mpmath.nstr(ctx.pi / 6, 105, strip_zeros=False)
    curve, _ = _served("d4a", 30, h=2, s=1, beta0=beta0, i_min=-3, i_max=3)
    certificate = balls.certificate(curve.arithmetic)
    assert certificate is not None and certificate.working_digits >= 105
    own = [check for check in curve.checks if check.id.startswith("d4a")]
    assert own and all(check.holds is True for check in own)


def test_a_cusp_tie_beyond_every_raise_is_refused_as_undecided(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(balls, "MAX_RAISES", 1)
    ctx = mpmath.MPContext()
    ctx.dps = 120
    beta0 = mpmath.nstr(ctx.pi / 6, 105, strip_zeros=False)
    with pytest.raises(NotRepresentableError) as raised:
        _served("d4a", 30, h=2, s=1, beta0=beta0, i_min=-3, i_max=3)
    assert raised.value.parameter == "beta0"
    assert "undecided" in str(raised.value)


def test_the_response_says_what_is_certified(client: TestClient) -> None:
    body = client.get("/discretizations/d4b?precision=mp&digits=30").json()
    certified = body["certified"]
    assert certified["resolved"] is True and certified["working_digits"] >= 40
    assert 0 < float(certified["radius"]) < 1e-30
    assert float(certified["relative_radius"]) < 1e-31
    errata = {c["erratum"]["id"]: c["erratum"] for c in body["checks"] if c["erratum"]}
    assert errata["E3"]["certified"] == "false" and float(errata["E3"]["printed_residual"]) > 1e-4
    assert all(c["holds"] is True for c in body["checks"])
    plain = client.get("/discretizations/d4b").json()
    assert plain["certified"] is None
    assert all(c["erratum"]["certified"] is None for c in plain["checks"] if c["erratum"])
    theorem = client.get("/theorems/recursion-13-two-step?precision=mp&digits=30").json()
    assert theorem["check"]["erratum"]["certified"] == "false"


@pytest.mark.parametrize("identifier", ["d4b", "d2a-hex", "d1"])
def test_verdicts_from_324_digits_on_are_decided(client: TestClient, identifier: str) -> None:
    # 10^-500 is 0.0 as a float: residuals and tolerances are decimal strings, compared as
    # decimals, so every verdict of the default polygon is the one of 30 digits (true by the
    # mathematics: proved; false: certified by a lower bound), never undecided
    deep = client.get(f"/discretizations/{identifier}?precision=mp&digits=500").json()
    shallow = client.get(f"/discretizations/{identifier}?precision=mp&digits=30").json()
    expected = {c["id"]: c["holds"] for c in shallow["checks"]}
    assert {c["id"]: c["holds"] for c in deep["checks"]} == expected
    for check in deep["checks"]:
        note = check["note"] or ""
        assert "undecided" not in note, (check["id"], note)
        tolerance = Decimal(check["tolerance"])
        assert Decimal("1e-499") < tolerance < Decimal("1e-490"), check["id"]
        if check["holds"] is True:
            assert Decimal(check["residual"]) <= tolerance
        erratum = check["erratum"]
        if erratum is not None and erratum["printed_residual"] is not None:
            assert erratum["certified"] == "false" and Decimal(erratum["printed_residual"]) > 0
    assert any(c["erratum"] for c in deep["checks"]) or identifier == "d1"
    if identifier == "d4b":
        assert all(c["holds"] is True for c in deep["checks"])
