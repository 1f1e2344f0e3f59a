"""On demand: a selected statement computes only what it needs, each shared quantity at most once.

Each discretization's checks read their shared quantities (fits, closed forms, Gauss images,
ring curvatures, refinements) from a per-computation context; the spies below count the calls of
the functions that compute them.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from types import ModuleType
from typing import Any

import pytest

from app.geometry import conditions
from app.geometry.curve import EVERYTHING, Curve, Selection
from app.geometry.d1 import closed_forms as d1_closed_forms, discretization as d1
from app.geometry.d2a import closed_forms as d2a_closed_forms, hex as d2a_hex, quad
from app.geometry.d2b import (
    closed_forms as d2b_closed_forms,
    construction as d2b_construction,
    discretization as d2b,
)
from app.geometry.d3 import closed_forms as d3_closed_forms, discretization as d3
from app.geometry.d4a import (
    closed_forms as d4a_closed_forms,
    construction as d4a_construction,
    discretization as d4a,
)
from app.geometry.precision import Float64, MultiPrecision

Compute = Callable[..., Curve]

#: The six discretizations whose checks this file covers (D4b has its own tests).
SIX: dict[str, Compute] = {
    "d1": d1.compute,
    "d2a-quad": quad.compute,
    "d2a-hex": d2a_hex.compute,
    "d2b": d2b.compute,
    "d3": d3.compute,
    "d4a": d4a.compute,
}
STATEMENTS = {
    "d1": d1.STATEMENTS,
    "d2a-quad": quad.STATEMENTS,
    "d2a-hex": d2a_hex.STATEMENTS,
    "d2b": d2b.STATEMENTS,
    "d3": d3.STATEMENTS,
    "d4a": d4a.STATEMENTS,
}
FITS = ("d1", "d3", "equation_2", "equilibrium", "equation_7")


def _spy(
    monkeypatch: pytest.MonkeyPatch, calls: Counter[str], module: ModuleType, *names: str
) -> None:
    """Count the calls of ``module.<name>`` (under ``module.__name__:name``)."""
    for name in names:
        original = getattr(module, name)
        key = f"{module.__name__.rsplit('.', 2)[-2]}.{name}"

        def counted(*args: Any, _original: Any = original, _key: str = key, **kwargs: Any) -> Any:
            calls[_key] += 1
            return _original(*args, **kwargs)

        monkeypatch.setattr(module, name, counted)


@pytest.fixture
def calls(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    """Calls of every function below that computes a shared quantity, counted."""
    counter: Counter[str] = Counter()
    _spy(monkeypatch, counter, conditions, *FITS)
    _spy(monkeypatch, counter, d1_closed_forms, "hyperbolic_cosine", "parameters")
    _spy(monkeypatch, counter, d3_closed_forms, "hyperbolic_cosine")
    _spy(monkeypatch, counter, d4a_closed_forms, "tractrix")
    _spy(monkeypatch, counter, d4a_construction, "darboux")
    _spy(monkeypatch, counter, d2a_closed_forms, "theorem_1_constant", "theorem_2_constants")
    _spy(monkeypatch, counter, d2a_closed_forms, "theorem_3_x", "quad_gauss_edge")
    _spy(monkeypatch, counter, d2b_closed_forms, "lemma_10", "radii")
    _spy(monkeypatch, counter, d2b_construction, "named_sequence")
    monkeypatch.setattr(d2b, "ring_curvatures", _counting(counter, "d2b.ring_curvatures", d2b))
    return counter


def _counting(counter: Counter[str], key: str, module: ModuleType) -> Any:
    original = module.ring_curvatures

    def counted(*args: Any, **kwargs: Any) -> Any:
        counter[key] += 1
        return original(*args, **kwargs)

    return counted


def _only(*ids: str) -> Selection:
    known = {s.id for statements in STATEMENTS.values() for s in statements}
    assert set(ids) <= known
    return Selection(frozenset(ids), frozenset())


def _fits(calls: Counter[str]) -> dict[str, int]:
    return {name: calls[f"geometry.{name}"] for name in FITS if calls[f"geometry.{name}"]}


def test_d1_a_single_check_computes_what_it_needs(calls: Counter[str]) -> None:
    curve = d1.compute(Float64(), selection=_only("d1-closed-form"))
    assert [c.holds for c in curve.checks] == [True] and curve.constants == {}
    assert _fits(calls) == {}
    assert calls["d1.hyperbolic_cosine"] == 1  # the closed form the construction is compared to
    calls.clear()
    curve = d1.compute(Float64(), selection=_only("d3", "equation-2"))
    assert _fits(calls) == {"d3": 1, "equation_2": 1} and list(curve.constants) == ["d3", "eq2"]
    # the offset C both notes name, computed once; no closed form
    assert calls["d1.hyperbolic_cosine"] == 0 and calls["d1.parameters"] == 1


def test_d1_closed_form_method_with_nothing_selected_computes_the_polygon_alone(
    calls: Counter[str],
) -> None:
    curve = d1.compute(Float64(), i_min=-1000, i_max=1000, method="closed-form", selection=_only())
    assert len(curve.polygon.vertices) == 2001 and curve.checks == [] and curve.constants == {}
    assert calls["d1.hyperbolic_cosine"] == 1 and _fits(calls) == {}


def test_d3_a_single_check_computes_what_it_needs(calls: Counter[str]) -> None:
    curve = d3.compute(Float64(), selection=_only("d1"))
    assert [c.id for c in curve.checks] == ["d1"] and list(curve.constants) == ["d1"]
    assert _fits(calls) == {"d1": 1} and calls["d3.hyperbolic_cosine"] == 0
    calls.clear()
    d3.compute(Float64(), selection=_only("d3-closed-form"))
    assert _fits(calls) == {} and calls["d3.hyperbolic_cosine"] == 1


def test_d4a_a_single_check_computes_what_it_needs(calls: Counter[str]) -> None:
    curve = d4a.compute(Float64(), selection=_only("d4a-arc-length"))
    assert [c.holds for c in curve.checks] == [True] and curve.constants == {}
    assert dict(calls) == {}  # no fit, no explicit form, no Darboux transform
    d4a.compute(Float64(), selection=Selection(frozenset({"darboux-d4a"}), frozenset()))
    assert dict(calls) == {"d4a.darboux": 1}
    calls.clear()
    d4a.compute(Float64(), selection=Selection(frozenset(), frozenset({"darboux"})))
    assert dict(calls) == {"d4a.darboux": 1}  # the companion alone
    calls.clear()
    d4a.compute(Float64(), selection=_only("d4a-closed-form"))
    assert dict(calls) == {"d4a.tractrix": 1}


def test_d2a_quad_a_single_check_computes_what_it_needs(calls: Counter[str]) -> None:
    curve = quad.compute(Float64(), selection=_only("theorem-1-gauss-edge"))
    assert [c.holds for c in curve.checks] == [True] and curve.constants == {}
    assert dict(calls) == {"d2a.quad_gauss_edge": 1}
    calls.clear()
    curve = quad.compute(Float64(), selection=_only("theorem-1"))
    assert _fits(calls) == {"equation_2": 1} and calls["d2a.theorem_1_constant"] == 1
    assert set(curve.constants) == {"eq2", "c_theorem_1", "r_theorem_1"}


def test_d2a_hex_a_single_check_computes_what_it_needs(calls: Counter[str]) -> None:
    curve = d2a_hex.compute(Float64(), selection=_only("theorem-3-odd"))
    assert [c.holds for c in curve.checks] == [True]
    assert _fits(calls) == {} and calls["d2a.theorem_2_constants"] == 0
    assert set(curve.constants) == {"x_step_even", "x_step_odd"}
    calls.clear()
    d2a_hex.compute(Float64(), selection=_only("equation-10"))
    assert _fits(calls) == {} and calls["d2a.theorem_2_constants"] == 1


def test_d2b_a_single_check_computes_what_it_needs(calls: Counter[str]) -> None:
    curve = d2b.compute(Float64(), selection=_only("d2b-parallel"))
    assert [c.holds for c in curve.checks] == [True]
    assert calls["d2b.named_sequence"] == 2  # the range validated, then the sequence (no 2j)
    assert calls["d2b.ring_curvatures"] == calls["d2b.lemma_10"] == calls["d2b.radii"] == 0
    calls.clear()
    d2b.compute(Float64(), selection=_only("theorem-11"))
    assert calls["d2b.named_sequence"] == 3 and calls["d2b.ring_curvatures"] == 0


@pytest.mark.parametrize(
    ("compute", "once"),
    [
        (d1.compute, {"geometry.d1", "geometry.d3", "geometry.equation_2", "d1.hyperbolic_cosine"}),
        (d3.compute, {"geometry.d1", "geometry.d3", "geometry.equation_2", "d3.hyperbolic_cosine"}),
        (d4a.compute, {"geometry.d1", "geometry.equation_2", "d4a.tractrix", "d4a.darboux"}),
        (quad.compute, {"geometry.equation_2", "d2a.theorem_1_constant"}),
        (d2a_hex.compute, {"geometry.equation_2", "geometry.equation_7"}),
        (d2b.compute, {"d2b.ring_curvatures", "d2b.lemma_10"}),
    ],
)
def test_every_check_reads_each_shared_quantity_computed_once(
    calls: Counter[str], compute: Compute, once: set[str]
) -> None:
    compute(Float64())
    assert {key: calls[key] for key in once} == dict.fromkeys(once, 1)


@pytest.mark.parametrize("identifier", sorted(SIX))
def test_each_check_alone_is_the_check_of_the_full_answer(identifier: str) -> None:
    for ar in (Float64(), MultiPrecision(30)):
        full = SIX[identifier](ar, detail=True)
        assert [c.id for c in full.checks] == [s.id for s in STATEMENTS[identifier]]
        for check in full.checks:
            alone = SIX[identifier](ar, detail=True, selection=_only(check.id))
            assert len(alone.checks) == 1
            assert _same(alone.checks[0], check), check.id
            assert alone.constants.items() <= full.constants.items()
        none = SIX[identifier](ar, selection=_only())
        assert none.checks == [] and none.constants == {}
        assert none.polygon.vertices.tolist() == full.polygon.vertices.tolist()


def test_every_constant_comes_with_some_check() -> None:
    for identifier, compute in SIX.items():
        full = compute(Float64(), selection=EVERYTHING)
        union: set[str] = set()
        for statement in STATEMENTS[identifier]:
            union |= set(compute(Float64(), selection=_only(statement.id)).constants)
        assert union == set(full.constants), identifier


def _same(a: Any, b: Any) -> bool:
    """Checks equal field by field (per-index residuals compared as lists)."""
    if a.per_index is not None or b.per_index is not None:
        if a.per_index.indices.tolist() != b.per_index.indices.tolist():
            return False
        if a.per_index.residuals.tolist() != b.per_index.residuals.tolist():
            return False
    return bool(
        (a.id, a.residual, a.tolerance, a.holds, a.erratum, a.note)
        == (b.id, b.residual, b.tolerance, b.holds, b.erratum, b.note)
    )
