"""precision=mp on balls: where the time of 10^3 D4b vertices with every check goes, and its floor.

For the served computation of ``bench/mp.py`` (50 digits, h = 1, d = 0.1, i = −500 … 499), each
statement of (D4b) is evaluated in the response's order on one shared context, so a statement
pays for the shared quantities it is the first to need (the fits (D1), (D3), (2) with Theorem 4
(i); the closed forms with Theorems 5, 6; the Gauss images, their closed forms and the ring
curvatures with Section 5, which is evaluated as one block). For each: its CPU time and the
elementwise operations on ``arb`` object arrays per vertex, counted by a numpy subclass that sees
every ufunc call (``+ − × ÷``, ``abs``, comparisons, reductions, and ``Ball``'s functions; a
hypot counts as its ×, +, part ≥ 0 and √), plus the float conversions of residuals; apart, the
libflint calls made in compiled loops (``arb_loops``, and Section 5's straight-line programs of
``arb_program``), counted as ``compiled``: no Python call each.

The floor: the operations counted times the cost of the cheapest one (a negation or a
comparison at the checks' working precision, measured here: a Python call on an ``arb``, since
python-flint 0.9 has no elementwise vector type), plus the square roots and transcendental
functions at their own cost, plus the time the compiled loops took (their libflint calls, no
Python call each). No rewrite of the arithmetic below these definitions of the checks gets
under it; only fewer operations do.

Then the served computation itself (``balls.serve`` as ``bench/mp.py`` runs it, uncounted): how
many times it computed (precision raises), the construction with every check, the rest of
``compute``, the certificate's radii and ``serve``'s own share, their sum against the total of
the parts; and apart, the decimal strings a response makes of every returned coordinate
(``responses.coordinates``), which ``bench/mp.py``'s served figure does not include.
"""

from __future__ import annotations

import collections
import math
import os
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import flint
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app import responses
from app.geometry import arb_loops, arb_program, balls
from app.geometry.ball_arithmetic import Ball
from app.geometry.curve import EVERYTHING
from app.geometry.d4b import (
    arb_gauss,
    certified,
    checks as d4b_checks,
    construction,
    curvature as d4b_curvature,
    discretization as d4b,
)
from app.geometry.d4b.closed_forms import tilt_shift
from app.geometry.surfaces import arb_rings
from bench.mp import HI, LO, D, H, on_balls, plain_script

DIGITS = int(os.environ.get("MP_PROFILE_DIGITS", "50"))  # 500: the same at 500 digits
COUNTS: collections.Counter[str] = collections.Counter()
TRANSCENDENTAL = (
    "exp",
    "expm1",
    "log",
    "log1p",
    "cos",
    "sin",
    "cosh",
    "sinh",
    "tanh",
    "atan2",
    "power",  # x ** y of balls: exp(y log x)
)


class Counted(np.ndarray):
    """An object array that counts the entries of every ufunc applied to it."""

    def __array_ufunc__(self, ufunc: Any, method: str, *inputs: Any, **kwargs: Any) -> Any:
        plain = [np.asarray(x) if isinstance(x, Counted) else x for x in inputs]
        if "out" in kwargs:
            kwargs["out"] = tuple(np.asarray(x) for x in kwargs["out"])
        result = getattr(ufunc, method)(*plain, **kwargs)
        if any(isinstance(x, np.ndarray) and x.dtype == object for x in plain):
            size = max(np.size(x) for x in plain if isinstance(x, np.ndarray))
            name = ufunc.__name__.replace(" (vectorized)", "")
            COUNTS[name if method == "__call__" else f"{name}.{method}"] += size
        return _counted(result)


def _counted(value: Any) -> Any:
    if isinstance(value, np.ndarray) and value.dtype == object:
        return value.view(Counted)
    if isinstance(value, tuple):
        return tuple(_counted(v) for v in value)
    return value


#: CPU seconds spent inside the compiled loops (the counted run).
COMPILED_SECONDS: list[float] = []

#: Section 5's straight-line programs in the counted run, by name: runs, rows, libflint calls
#: (counted as ``compiled``) and CPU seconds (``_instrument_section_5``).
PROGRAMS: dict[str, list[float]] = {}
_IN_SECTION_5 = [False]

#: libflint calls per entry of each compiled loop of ``arb_loops`` (counted as "compiled").
COMPILED = {
    "relative_point_difference": 15,  # two differences, two hypot (5 each), a test, a quotient
    "hypot": 5,
    "argmax_abs": 2,  # the bound and a comparison
    "largest_radii": 10,
}


def _instrument() -> None:
    """Every object array ``Ball`` makes, and every polygon of the construction, counted; the
    entries of ``arb_loops``' compiled loops counted apart (``compiled``, libflint calls)."""
    for name, calls in COMPILED.items():
        loop = getattr(arb_loops, name)

        def counted_loop(*arguments: Any, _loop: Any = loop, _calls: int = calls) -> Any:
            COUNTS["compiled"] += _calls * len(np.asarray(arguments[0]))
            start = time.process_time()
            try:
                return _loop(*arguments)
            finally:
                COMPILED_SECONDS.append(time.process_time() - start)

        setattr(arb_loops, name, counted_loop)
    _instrument_section_5()
    for name in ("array", "indices", "zeros", "empty"):
        method = getattr(Ball, name)
        setattr(Ball, name, lambda self, *a, _m=method: _counted(_m(self, *a)))
    for name in ("to_floats", "lower_floats"):
        method = getattr(Ball, name)

        def convert(self: Ball, values: Any, _m: Any = method, _name: str = name) -> Any:
            if isinstance(values, np.ndarray) and values.dtype == object:
                COUNTS[_name] += values.size
            return _m(self, np.asarray(values))

        setattr(Ball, name, convert)
    for name in ("empty", "stack", "concatenate", "where", "full_like", "empty_like", "array"):
        make = getattr(np, name)
        setattr(np, name, lambda *a, _m=make, **k: _counted(_m(*a, **k)))
    construct = construction.construct

    def counted_construct(*arguments: Any) -> Any:
        built = construct(*arguments)
        for name in ("axis_points", "centres", "tractrix", "directions"):
            built.__dict__[name] = _counted(getattr(built, name))
        return built

    d4b.construct = counted_construct  # type: ignore[attr-defined,assignment]


def _instrument_section_5() -> None:
    """Section 5's compiled straight-line programs (``arb_program.run``: the ring pass of
    ``arb_rings`` and the Gauss images' formulas) counted as ``compiled`` too, each operation a
    libflint call (an ``abs`` two, its rounding included; a ``SWAP`` none; an operation on the
    first row only once; a reduced output two bounds, two comparisons and the kept balls'
    copies counted as two calls)."""
    run = arb_program.run
    names = {
        id(value): f"{module.__name__.rsplit('.', 1)[-1]}.{name}"
        for module in (arb_gauss, arb_rings)
        for name, value in vars(module).items()
        if isinstance(value, arb_program.Program)
    }

    def counted_run(program: Any, inputs: Any, *arguments: Any, **keywords: Any) -> Any:
        rows = len(next(iter(inputs.values()))) if inputs else keywords.get("rows", 0)
        before = COUNTS["compiled"]
        for code, _, _, _, flags in program.steps:
            calls = 0 if code == arb_program.SWAP else 2 if code == arb_program.ABS else 1
            COUNTS["compiled"] += calls * (1 if flags & arb_program.FIRST else rows)
        reduced = keywords.get("reduce", arguments[2] if len(arguments) > 2 else ())
        COUNTS["compiled"] += 2 * len(reduced) * rows
        start = time.process_time()
        try:
            return run(program, inputs, *arguments, **keywords)
        finally:
            COMPILED_SECONDS.append(time.process_time() - start)
            if _IN_SECTION_5[0]:
                entry = PROGRAMS.setdefault(names.get(id(program), "other"), [0, 0, 0, 0.0])
                entry[0] += 1
                entry[1] += rows
                entry[2] += COUNTS["compiled"] - before
                entry[3] += COMPILED_SECONDS[-1]

    arb_program.run = counted_run


def _timed(function: Callable[[], object]) -> tuple[float, dict[str, int]]:
    COUNTS.clear()
    start = time.process_time()
    function()
    return time.process_time() - start, dict(COUNTS)


_SQRT: Any = np.frompyfunc(flint.arb.sqrt, 1, 1)
_COSH: Any = np.frompyfunc(flint.arb.cosh, 1, 1)


def _unit_costs(bits: int) -> list[dict[str, float]]:
    """Seconds per entry of arb operations on 1000 entries at ``bits``, each set of them
    measured right after a run of the script (``"script"``, seconds): 15 pairs, so that a
    floor is a ratio to the script taken under the same load."""
    with balls.working_precision(bits):
        x = [flint.arb(k) / 7 + flint.arb(1) / 3 for k in range(1000)]
        y = [flint.arb(k) / 3 + flint.arb(2) for k in range(1000)]
        xs, ys = np.empty(1000, dtype=object), np.empty(1000, dtype=object)
        xs[:], ys[:] = x, y
        operations: dict[str, Callable[[], object]] = {
            # on object arrays through numpy's loops, as the checks run them
            "product": lambda: xs * ys,
            "negation": lambda: np.negative(xs),
            "comparison": lambda: np.less(xs, ys),
            "sqrt": lambda: _SQRT(xs),
            "transcendental": lambda: _COSH(xs / 1000),
        }
        pairs = []
        for _ in range(15):
            costs = {"script": _timed(lambda: plain_script(DIGITS))[0]}
            for name, run in operations.items():
                start = time.process_time()
                run()
                costs[name] = (time.process_time() - start) / 1000
            costs["transcendental"] -= costs["product"]  # the division by 1000 inside
            costs["cheapest"] = min(costs["negation"], costs["comparison"])
            pairs.append(costs)
    return pairs


def _parts(ar: Ball) -> list[tuple[str, float, dict[str, int]]]:
    """Each part of the served computation in order: (label, seconds, counts)."""
    rows: list[tuple[str, float, dict[str, int]]] = []
    with balls.working_precision(ar.bits):
        data = d4b.polygons(ar, H, D, None, LO, HI)
        rows.append(("construction (recursion bits)", *_timed(lambda: data.p)))
        ctx = d4b_checks._Context(ar, ar.scalar(H), ar.scalar(D), data, False)
        for statement, evaluator in d4b_checks._EVALUATORS:
            rows.append((statement.id, *_timed(lambda e=evaluator: e(ctx))))  # type: ignore[misc]

        def section_5() -> object:
            shift = tilt_shift(ar, ctx.h, ctx.d, None)
            printed = d4b_curvature.printed_forms(ar, ctx.h, ctx.d, shift, LO, LO + ctx.n - 1)
            return d4b_curvature.evaluate(
                ar,
                ctx.h,
                data.p,
                data.tractrix,
                data.gauss,
                printed,
                ctx.indices,
                ctx.n,
                ctx.tolerance,
                ctx.construction_tolerance,
                False,
            )

        _IN_SECTION_5[0] = True
        try:
            rows.append(("Section 5 (9 statements, Gauss images)", *_timed(section_5)))
        finally:
            _IN_SECTION_5[0] = False
        mark = len(COMPILED_SECONDS)
        curve = d4b.compute(ar, H, D, None, LO, HI, selection=EVERYTHING)
        del COMPILED_SECONDS[mark:]  # the checks again, only for the curve: not counted twice
        rows.append(("certificate radii", *_timed(lambda: balls._radii(curve, DIGITS))))
    return rows


def _served() -> list[tuple[str, float]]:
    """The served computation of ``bench/mp.py`` (``balls.serve``) stage by stage, median of 3
    (CPU ms): everything from the parameters to the returned ``Curve``, and apart the decimal
    strings a response makes of its coordinates (``responses.coordinates``: not in
    ``bench/mp.py``, whose served figure ends at the ``Curve``)."""
    spent: collections.defaultdict[str, float] = collections.defaultdict(float)
    wrapped = {
        "evaluate": (d4b, d4b.evaluate),  # construction (first read of p) and every check
        "compute": (d4b, d4b.compute),
        "radii": (balls, balls._radii),
    }

    def timer(name: str, function: Any) -> Any:
        def timed(*arguments: Any, **keywords: Any) -> Any:
            spent[name + " calls"] += 1
            start = time.process_time()
            try:
                return function(*arguments, **keywords)
            finally:
                spent[name] += time.process_time() - start

        return timed

    for name, (module, function) in wrapped.items():
        setattr(module, function.__name__, timer(name, function))
    runs: list[dict[str, float]] = []
    try:
        for _ in range(3):
            spent.clear()
            start = time.process_time()
            curve = on_balls(DIGITS)
            spent["served"] = time.process_time() - start
            start = time.process_time()
            for polyline in (curve.polygon, *curve.companions.values()):
                responses.coordinates(curve.arithmetic, polyline.vertices)
            spent["strings"] = time.process_time() - start
            runs.append(dict(spent))
    finally:
        for module, function in wrapped.values():
            setattr(module, function.__name__, function)
    at = {key: statistics.median(run[key] for run in runs) for key in runs[0]}
    values = 2 * sum(len(p.vertices) for p in (curve.polygon, *curve.companions.values()))
    return [
        ("served: balls.serve (bench/mp.py)", at["served"]),
        (f"  computations (1 + raises): {at['compute calls']:.0f}", math.nan),
        ("  construction, every check (evaluate)", at["evaluate"]),
        ("  compute's rest (tolerances, Curve)", at["compute"] - at["evaluate"]),
        ("  certificate radii (_radii)", at["radii"]),
        ("  serve's own (precision, certificate)", at["served"] - at["compute"] - at["radii"]),
        (f"response's decimal strings ({values})", at["strings"]),
    ]


def main() -> None:
    arguments = {"h": H, "d": D, "beta0": None, "i_min": LO, "i_max": HI}
    extra = certified.extra_digits(arguments)
    n = HI - LO + 1
    script = statistics.median(_timed(lambda: plain_script(DIGITS))[0] for _ in range(7))
    # times without the counting (median of 3), then the counts
    runs = [_parts(Ball(DIGITS, extra, recursions_only=True)) for _ in range(3)]
    seconds_of = [statistics.median(run[k][1] for run in runs) for k in range(len(runs[0]))]
    served = _served()  # before the counting instruments anything
    _instrument()
    ar = Ball(DIGITS, extra, recursions_only=True)
    rows = [
        (label, seconds, counts)
        for (label, _, counts), seconds in zip(_parts(ar), seconds_of, strict=True)
    ]
    print(
        f"precision=mp on balls, D4b {n} vertices at {DIGITS} digits (checks at {ar.bits} bits, "
        f"construction at {ar.recursion_bits}); the script {script * 1e3:.1f} ms; load average "
        f"{os.getloadavg()[0]:.2f}"
    )
    print(
        f"  {'part':<42} {'ms':>7} {'ops/vertex':>11} {'√':>5} {'transc.':>8} {'→ float':>8} "
        f"{'compiled':>9}"
    )
    total_ops = total_sqrt = total_transcendental = total_compiled = 0.0
    total_time = 0.0
    for label, seconds, counts in rows:
        sqrt = counts.get("sqrt", 0) / n
        transcendental = sum(counts.get(name, 0) for name in TRANSCENDENTAL) / n
        conversions = (counts.get("to_floats", 0) + counts.get("lower_floats", 0)) / n
        compiled = counts.get("compiled", 0) / n
        ops = sum(counts.values()) / n - conversions - compiled
        print(
            f"  {label:<42} {seconds * 1e3:7.1f} {ops:11.0f} {sqrt:5.0f} {transcendental:8.0f} "
            f"{conversions:8.0f} {compiled:9.0f}"
        )
        total_time += seconds
        if label != "construction (recursion bits)":
            total_ops += ops
            total_compiled += counts.get("compiled", 0) / n
            total_sqrt += sqrt
            total_transcendental += transcendental
    pairs = _unit_costs(ar.bits)

    def floor(costs: dict[str, float]) -> float:
        return n * (
            (total_ops - total_sqrt - total_transcendental) * costs["cheapest"]
            + total_sqrt * costs["sqrt"]
            + total_transcendental * costs["transcendental"]
        )

    # the compiled loops at the time they took (no Python call per entry to take away)
    compiled = sum(COMPILED_SECONDS) / script
    ratio = statistics.median(floor(costs) / costs["script"] for costs in pairs) + compiled
    typical = {k: statistics.median(c[k] for c in pairs) for k in pairs[0]}
    print(
        f"  {'total':<42} {total_time * 1e3:7.1f} {total_ops:11.0f}   ({total_time / script:.1f}× "
        "the script)"
    )
    header = f"{'runs':>5} {'rows':>6} {'calls/row':>9} {'ms':>6}"
    print(f"  Section 5's programs (the counted run): {header}")
    for name, (runs_of, rows_of, calls, seconds) in PROGRAMS.items():
        print(
            f"    {name:<38} {runs_of:5d} {rows_of:6d} {calls / max(rows_of, 1):9.1f} "
            f"{seconds * 1e3:6.2f}"
        )
    for label, seconds in served:
        shown = "" if math.isnan(seconds) else f"{seconds * 1e3:7.1f}"
        print(f"  {label:<42} {shown}")
    print(
        f"  {'served − total of the parts':<42} {(served[0][1] - total_time) * 1e3:7.1f}   (the "
        "decimal strings in neither: bench/mp.py's served figure ends at the Curve)"
    )
    print(
        f"  floor of the checks and the certificate: {total_ops:.0f} operations a vertex, each at "
        f"least {typical['cheapest'] * 1e9:.0f} ns (a negation or a comparison; a product "
        f"{typical['product'] * 1e9:.0f} ns), √ at {typical['sqrt'] * 1e9:.0f} ns, "
        f"transcendental functions at {typical['transcendental'] * 1e9:.0f} ns (medians), and "
        f"{total_compiled:.0f} libflint calls a vertex in compiled loops at the time they took "
        f"({sum(COMPILED_SECONDS) * 1e3:.1f} ms, {compiled:.1f}× the script): "
        f"{ratio:.1f}× the script (median of 15 pairs, each floor over the script run next to "
        "it; target 5×)"
    )


if __name__ == "__main__":
    main()
