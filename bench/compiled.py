"""The compiled float64 kernels (issue 13), before → after, side by side in one run.

1. ns/vertex of each recursive construction at 10^5 vertices: *before* is the same
   ``construct`` taking its Python loop (the mp path's loop, run here over Python floats: the
   float64 code of before, step for step), *after* the compiled kernel; ratio of paired samples.
2. A 10^6-vertex D4b against the copy floor (copying a filled (n, 2) float64 array that is in
   no cache into another, median of 101: ``copy_floor``, which says why this floor and prints
   the warm copy and ``np.copy`` beside it), with method=closed-form and construction: *every
   check* (the whole computation) and *checks alone* (every check − ``checks=none``, paired in
   one process), on which the issue's target (≤ 100×) is judged: the construction and the
   companions are not checks.
3. The first request after the server starts against later computed requests of the same
   size (a new d each time, so no cache answers): what a kernel compiled or loaded on a request
   would cost. The issue's target: at most 1 s more.

Run: .venv/bin/python bench/compiled.py   (about 60 s; ``make bench`` runs it with the others)

``--base DIR`` compares with another version of the code instead (e.g. a commit exported with
``git archive <commit> app bench | tar -x -C DIR``): parts 1 and 2 run in DIR and here, each in
its own process, alternating for ``--rounds`` rounds (CPU time; each tree's kernels load from, or
on its first run compile into, its own ``.numba-cache``); part 2 runs once with glibc's default
malloc and once with the server's environment (the Makefile's ``SERVER_ENV``). ``--checks-only``
skips part 1.

``--statements`` (with or without ``--base DIR``): the checks of a 10^6 D4b one statement at a
time (``BREAKDOWN``, method=closed-form unless ``--method construction``), each tree in its own
process, glibc and server env; ``--group NAME`` (a name of ``GROUPS``, e.g. "Gauss images") times
that group's statements and the group alone.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numba
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from app.geometry.compiled import hypot, running_largest
from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d1 import construction as d1
from app.geometry.d3 import construction as d3
from app.geometry.d4a import construction as d4a
from app.geometry.d4b import (
    construction as d4b,
    discretization as d4b_full,
)
from app.geometry.elementary import exp_into
from app.geometry.precision import Float64
from bench.common import compare, record_target

TARGET_NS = 50
CHECKS_TARGET = 100
FIRST_REQUEST_TARGET = 1.0


class PythonLoop(Float64):
    """Float64 numbers taking the constructions' Python loop (their code before the kernels)."""

    mode = "float64-python-loop"  # type: ignore[assignment]


def constructions(n: int = 10**5) -> None:
    lo, hi = -(n // 2), n - n // 2 - 1
    cases: list[tuple[str, Callable[[Float64], object]]] = [
        ("D4b (h=1, d=1e-4)", lambda ar: d4b.construct(ar, 1.0, 1e-4, None, lo, hi)),
        ("D1 (c=1e-4, delta=0.2)", lambda ar: d1.construct(ar, 1e-4, 0.2, 1.0, 1.0, lo, hi)),
        ("D3 (c=1, delta=1e-4)", lambda ar: d3.construct(ar, 1.0, 1e-4, 1.0, "up", lo, hi)),
        ("D4a (h=1, s=1e-3)", lambda ar: d4a.construct_sticks(ar, 1.0, 1e-3, None, lo, hi)),
    ]
    fast, loop = Float64(), PythonLoop()
    print(f" constructions at {n:,} vertices, float64: Python loop → compiled kernel")
    for label, build in cases:
        paired = compare(lambda b=build: b(loop), lambda b=build: b(fast), 5)  # type: ignore[misc]
        after = paired.seconds / n * 1e9
        before = paired.reference / n * 1e9
        verdict = record_target(f"{label}, ns/vertex", after, TARGET_NS, "≤")
        print(
            f"  {label:<26} {before:7.0f} → {after:5.1f} ns/vertex   {1 / paired.ratio:6.1f}× "
            f"faster   {verdict}"
        )


#: The selection of ``checks=none``: the polygon and its six companions, no check.
NO_CHECKS = Selection(checks=frozenset())


#: Bytes the cold copies rotate over (``copy_floor``): more than any processor's last-level
#: cache, so each copy reads and writes arrays that have left it.
COLD_BYTES = 256 * 2**20


def copy_floor(n: int = 10**6, copies: int = 101, kind: str = "cold") -> float:
    """CPU seconds of copying a filled (n, 2) float64 array (median of ``copies``), by ``kind``:

    - ``"cold"``, the floor the target is judged on: source and destination written once before
      timing (no page faults), and each copy taken from a different pair of a rotation that
      spans ``COLD_BYTES``, so neither is in a cache when it is copied. This is what copying
      the output costs from memory, on any host and with any malloc settings;
    - ``"warm"``: the same pair every time, the floor this bench judged on from session 14 to
      30. Both 16 MB arrays then sit in the cache of a host whose L3 holds them (32 MiB on the
      AMD EPYC of sessions 29–31: 0.59–0.98 ms there, against 1.3–1.5 ms on the Intel host
      before it), so it measures the cache rather than memory;
    - ``"fresh"``: ``np.copy`` into a new array, the floor the issue measured its ≈ 1,200×
      against (≈ 3.3 ms then). Whether its pages fault in depends on malloc's settings: under
      the server's 128 KiB mmap threshold every copy maps fresh pages.
    """
    if kind == "fresh":
        source = np.ones((n, 2))
        return _median_cpu(lambda _: source.copy(), copies)
    pairs = max(2, COLD_BYTES // (2 * 16 * n)) if kind == "cold" else 1
    sources = [np.ones((n, 2)) for _ in range(pairs)]
    destinations = [np.zeros((n, 2)) for _ in range(pairs)]
    for source, destination in zip(sources, destinations, strict=True):
        np.copyto(destination, source)
    return _median_cpu(lambda k: np.copyto(destinations[k % pairs], sources[k % pairs]), copies)


def _median_cpu(run: Callable[[int], object], count: int) -> float:
    """Median CPU seconds of ``run(k)`` for k = 0 .. count − 1."""
    samples = []
    for k in range(count):
        start = time.process_time()
        run(k)
        samples.append(time.process_time() - start)
    return statistics.median(samples)


def checks(n: int = 10**6, rounds: int = 5) -> None:
    """Part 2: a 10^6-vertex D4b, every check and ``checks=none``, paired, against the copy.

    Each round times ``compute`` with every check and with none, one right after the other (the
    order alternating), in this process; *checks alone* is the median of the differences. The
    issue's target ("all checks of a 10^6-vertex D4b ≤ 100× the copy floor") is judged on that
    row: the construction and the six companions are not checks. The *every check* row is the
    whole computation (construction, companions and checks), kept for comparison with earlier
    figures.
    """
    ar = Float64()
    lo, hi = -(n // 2), n - n // 2 - 1
    floor, warm, fresh = (copy_floor(n, kind=kind) for kind in ("cold", "warm", "fresh"))
    print(
        f" D4b at {n:,} vertices against the copy floor (an (n, 2) float64 copy out of the "
        f"caches, median of 101: ``copy_floor``): {floor * 1e3:.3f} ms; beside it the warm copy "
        f"(judged on until session 30) {warm * 1e3:.3f} ms and the issue's own floor (np.copy "
        f"into a new array) {fresh * 1e3:.3f} ms"
    )
    for method in ("closed-form", "construction"):

        def run(selection: Selection, m: str = method) -> float:
            start = time.process_time()
            d4b_full.compute(ar, 1.0, 1e-4, None, lo, hi, m, selection=selection)  # type: ignore[arg-type]
            return time.process_time() - start

        run(EVERYTHING), run(NO_CHECKS)  # warm up
        every, none = [], []
        for k in range(rounds):
            if k % 2:
                none.append(run(NO_CHECKS))
                every.append(run(EVERYTHING))
            else:
                every.append(run(EVERYTHING))
                none.append(run(NO_CHECKS))
        whole = statistics.median(every)
        alone = statistics.median(e - o for e, o in zip(every, none, strict=True))
        for label, seconds, target in (
            (f"{method}: every check (polygon, companions, checks)", whole, None),
            (f"{method}: checks alone (every − none), TARGET", alone, CHECKS_TARGET),
        ):
            ratio = seconds / floor
            verdict = ""
            if target is not None:
                verdict = "   " + record_target(
                    f"D4b {n:,} checks alone, {method}, × cold copy", ratio, target, "≤"
                )
            print(
                f"  {label:<58} {seconds * 1e3:8.1f} ms {ratio:7.1f}× copy"
                f" ({seconds / warm:.0f}× warm copy, {seconds / fresh:.0f}× np.copy){verdict}"
            )
        print(f"  {method + ': checks=none':<58} {statistics.median(none) * 1e3:8.1f} ms")


# --- part 0: the arithmetic every check needs, and what it costs here at the least ---

#: Per vertex of a 10^6 D4b with every check (method=construction, no ``detail``), the calls each
#: check's float64 pass makes on an ordinary polygon, counted from the kernels' source (session
#: 22): (check, divisions, square roots, libm-exact hypots, numpy cosh/sinh/tanh, numpy exp, numpy
#: atan2). Per-vertex work only (not a block's one root of its largest square); divisions by a
#: power of two are products and are not counted; a ``length``, ``length3`` or ``fast_length`` is
#: one square root; the fits keep libm's hypot for the edges (their constants are shown). Session
#: 22 retook the counts: the rotation angle is a quotient im/re a row for the corrected and the
#: printed angle (atan2 only in blocks off that path, e.g. a perturbed polygon); Darboux's edges
#: are squares (one division, no root; the distances keep their root); Theorems 5, 6 and
#: (18)-(20) make their closed forms from w = e^(-|t|), numpy's exp of each argument (no cosh,
#: sinh, tanh), and compare squares (no root a row); the fits drop pass 2, take pass 3 by
#: reciprocals (a division a row) and run pass 4's divisions only in blocks that may raise a
#: largest residual (``_may_raise``; at 10^6 about a fifth of the blocks for (D3), 1 % for the
#: others: under 0.25 a vertex, not counted); E2's spread is read at the extreme ratios (no
#: division a row); the row of (18) by slopes now counts the along residual's division with
#: E61's four (one pass for both; session 18's row left it out).
ARITHMETIC: tuple[tuple[str, int, int, int, int, int, int], ...] = (
    ("Theorem 4's hypothesis", 2, 0, 0, 0, 0, 0),
    ("Theorem 4 (i)-(iii): three fits + (2)'s misfit", 4, 0, 1, 0, 0, 0),
    ("erratum E2 (the proof's ratio)", 1, 1, 0, 0, 0, 0),
    ("Theorem 4's rotation angle (a quotient im/re each)", 2, 0, 0, 0, 0, 0),
    ("(13) and its two-step form", 8, 0, 0, 0, 0, 0),
    ("two-step as printed (E3)", 2, 0, 0, 0, 0, 0),
    ("Theorems 5, 6 (closed forms (14), (16) + comparison)", 4, 0, 0, 0, 2, 0),
    ("Darboux: edges (squares) and distance", 2, 1, 0, 0, 0, 0),
    ("Nikolaides' right angles", 2, 0, 0, 0, 0, 0),
    ("(18)-(20) closed forms (19), (20)", 2, 0, 0, 0, 2, 0),
    ("(18), (19), (20) corrected and printed comparisons", 3, 0, 0, 0, 0, 0),
    ("(18) by slopes and as printed (E61)", 5, 2, 0, 0, 0, 0),
    ("(19) as a rotation, (20) by inversion, resolutions", 4, 4, 0, 0, 0, 0),
    ("Theorems 7, 8 and (17): two rings", 12, 4, 0, 0, 0, 0),
)

#: The columns of ``ARITHMETIC``'s counts as ``arithmetic`` prints them: (heading, width).
COUNT_COLUMNS = (("div", 3), ("sqrt", 4), ("hyp", 3), ("hyp.fn", 6), ("exp", 3), ("atan2", 5))


#: Entries of the cache-resident block the primitives loop over (``arithmetic``): 3 × 32 KB.
BLOCK = 4096


@numba.njit(error_model="numpy")
def _divisions(x: Any, y: Any, out: Any, rounds: int) -> None:
    for _ in range(rounds):
        for k in range(x.shape[0]):
            out[k] = x[k] / y[k]


@numba.njit(error_model="numpy")
def _roots(x: Any, y: Any, out: Any, rounds: int) -> None:
    for _ in range(rounds):
        for k in range(x.shape[0]):
            out[k] = math.sqrt(x[k] * x[k] + y[k] * y[k])


@numba.njit(error_model="numpy")
def _hypots(x: Any, y: Any, out: Any, rounds: int) -> None:
    for _ in range(rounds):
        for k in range(x.shape[0]):
            out[k] = hypot(x[k], y[k])


@numba.njit(error_model="numpy")
def _sums(x: Any, y: Any, out: Any, rounds: int) -> None:
    for _ in range(rounds):
        for k in range(x.shape[0]):
            out[k] = x[k] + y[k]


@numba.njit(error_model="numpy")
def _divisions_scalar(x: Any, y: Any, out: Any, rounds: int) -> None:
    largest = 0.0
    for _ in range(rounds):
        for k in range(x.shape[0]):
            largest = running_largest(x[k] / y[k], largest)
    out[0] = largest


@numba.njit(error_model="numpy")
def _roots_scalar(x: Any, y: Any, out: Any, rounds: int) -> None:
    largest = 0.0
    for _ in range(rounds):
        for k in range(x.shape[0]):
            largest = running_largest(math.sqrt(x[k] * x[k] + y[k] * y[k]), largest)
    out[0] = largest


@numba.njit(error_model="numpy")
def _hypots_scalar(x: Any, y: Any, out: Any, rounds: int) -> None:
    largest = 0.0
    for _ in range(rounds):
        for k in range(x.shape[0]):
            largest = running_largest(hypot(x[k], y[k]), largest)
    out[0] = largest


@numba.njit(error_model="numpy")
def _sums_scalar(x: Any, y: Any, out: Any, rounds: int) -> None:
    largest = 0.0
    for _ in range(rounds):
        for k in range(x.shape[0]):
            largest = running_largest(x[k] + y[k], largest)
    out[0] = largest


@numba.njit(error_model="numpy")
def _libm_cosh(x: Any, y: Any, out: Any, rounds: int) -> None:
    for _ in range(rounds):
        for k in range(x.shape[0]):
            out[k] = math.cosh(x[k])


@numba.njit(error_model="numpy")
def _libm_atan2(x: Any, y: Any, out: Any, rounds: int) -> None:
    for _ in range(rounds):
        for k in range(x.shape[0]):
            out[k] = math.atan2(x[k], y[k])


def _exp_into_rounds(x: Any, y: Any, out: Any, rounds: int) -> None:
    """``elementary.exp_into`` over the block, ``rounds`` times (as the closed comparisons)."""
    for _ in range(rounds):
        exp_into(x, out)


def _numpy_rounds(function: Any) -> Callable[[Any, Any, Any, int], None]:
    """A numpy ufunc over the block, ``rounds`` times (its arguments as the kernels')."""

    def run(x: Any, y: Any, out: Any, rounds: int) -> None:
        for _ in range(rounds):
            if function is np.arctan2:
                function(x, y, out=out)
            else:
                function(x, out=out)

    return run


def arithmetic(n: int = 10**6, repeat: int = 9) -> float:
    """Part 0: ns per entry of each primitive, n entries in all over a cache-resident block
    (``BLOCK``, so memory is not what is timed; median of ``repeat``, CPU time), in a loop the
    compiler vectorizes (``out[k] = …``) and in one it cannot (a running largest, as the checks'
    passes keep), less the same loop adding two numbers; then the counts of ``ARITHMETIC`` times
    those costs: the least time the checks' arithmetic takes on one core, however the passes
    are fused. Returns the floor (vectorized) in seconds."""
    rng = np.random.default_rng(18)
    x = rng.uniform(0.5, 2.0, BLOCK)  # moderate magnitudes: hypot's unscaled branch
    y = rng.uniform(0.5, 2.0, BLOCK)
    t = rng.uniform(-30.0, 30.0, BLOCK)  # the closed forms' arguments at 10^6 (|t| <= 100)
    decays = -np.abs(t)  # exp's arguments: w = e^(-|t|) of the closed forms since session 22
    out = np.empty(BLOCK)
    rounds = max(n // BLOCK, 1)

    def cpu(run: Callable[[Any, Any, Any, int], None], first: Any = x) -> float:
        run(first, y, out, 1)
        samples = []
        for _ in range(repeat):
            start = time.process_time()
            run(first, y, out, rounds)
            samples.append(time.process_time() - start)
        return statistics.median(samples) / (rounds * BLOCK) * 1e9

    base, base_scalar = cpu(_sums), cpu(_sums_scalar)
    rows = {
        "division": (cpu(_divisions), cpu(_divisions_scalar)),
        "√(x² + y²)": (cpu(_roots), cpu(_roots_scalar)),
        "hypot (libm's bits, inline)": (cpu(_hypots), cpu(_hypots_scalar)),
        "cosh (numpy | libm)": (cpu(_numpy_rounds(np.cosh), t), cpu(_libm_cosh, t)),
        "sinh (numpy)": (cpu(_numpy_rounds(np.sinh), t), math.nan),
        "tanh (numpy)": (cpu(_numpy_rounds(np.tanh), t), math.nan),
        "exp (numpy)": (cpu(_numpy_rounds(np.exp), decays), math.nan),
        "exp (exp_into: libm's bits)": (cpu(_exp_into_rounds, decays), math.nan),
        "atan2 (numpy | libm)": (cpu(_numpy_rounds(np.arctan2)), cpu(_libm_atan2)),
    }
    print(
        f" the checks' arithmetic, {n:,} entries over a {BLOCK}-entry block (ns an entry, CPU, "
        f"median of {repeat}; less an addition's loop: {base:.2f} / {base_scalar:.2f} ns)"
    )
    print(f"  {'primitive':<30} {'vectorized':>10} {'scalar loop':>12}")
    net: dict[str, tuple[float, float]] = {}
    for name, (fast, slow) in rows.items():
        libm = name.endswith("libm)")
        vector = max(fast - base, 0.0)
        scalar = max(slow - (base if libm else base_scalar), 0.0) if slow == slow else vector
        net[name] = (vector, scalar)
        print(f"  {name:<30} {vector:10.2f} {scalar:12.2f}")
    kinds = (
        ("division",),
        ("√(x² + y²)",),
        ("hypot (libm's bits, inline)",),
        ("cosh (numpy | libm)", "sinh (numpy)", "tanh (numpy)"),
        ("exp (exp_into: libm's bits)",),
        ("atan2 (numpy | libm)",),
    )  # in the order of ``COUNT_COLUMNS``
    # the kinds from the fourth on are whole-array calls (numpy's, or since session 28 libm's
    # through ``elementary``; exp by ``exp_into`` since session 29): their vectorized cost in
    # both columns
    per_kind = [statistics.mean(net[name][0] for name in kind) for kind in kinds]
    per_kind_scalar = [
        statistics.mean(net[name][0 if k >= 3 else 1] for name in kind)
        for k, kind in enumerate(kinds)
    ]

    def counted(values: list[int]) -> str:
        return " ".join(f"{v:{width}}" for v, (_, width) in zip(values, COUNT_COLUMNS, strict=True))

    headings = " ".join(f"{name:>{width}}" for name, width in COUNT_COLUMNS)
    print(f"  {'per vertex, every check':<54} {headings}   floor ns  scalar ns")
    total = total_scalar = 0.0
    counts = [0] * len(COUNT_COLUMNS)
    for label, *row in ARITHMETIC:
        ns = sum(c * cost for c, cost in zip(row, per_kind, strict=True))
        ns_scalar = sum(c * cost for c, cost in zip(row, per_kind_scalar, strict=True))
        total, total_scalar = total + ns, total_scalar + ns_scalar
        counts = [a + b for a, b in zip(counts, row, strict=True)]
        print(f"  {label:<54} {counted(row)} {ns:10.1f} {ns_scalar:10.1f}")
    print(f"  {'total':<54} {counted(counts)} {total:10.1f} {total_scalar:10.1f}")
    print(
        f"  arithmetic floor at 10^6 vertices: {total:.0f} ms vectorized, {total_scalar:.0f} ms "
        f"in scalar passes (ns/vertex × 10^6; the target: 100 copies of a 10^6-vertex output)"
    )
    return total * 1e-3


def first_request() -> None:
    from bench.load import free_port
    from bench.serving import fetch, start_server

    paths = {
        "D4b": "/discretizations/d4b?i_min=-500&i_max=500&d={}",
        "D1": "/discretizations/d1?i_min=-500&i_max=500&delta={}",
        "D3": "/discretizations/d3?i_min=-500&i_max=500&delta={}",
        "D4a": "/discretizations/d4a?i_min=-500&i_max=500&s={}",
    }
    print(" first computed request after the server starts, against later ones (wall time)")
    for name, path in paths.items():
        port = free_port()
        started = time.perf_counter()
        server = start_server(port)
        up = time.perf_counter() - started
        try:
            first, _ = fetch(port, path.format(0.1))
            later = statistics.median(
                fetch(port, path.format(0.1 + k * 1e-3))[0] for k in (1, 2, 3)
            )
        finally:
            server.terminate()
            server.wait(timeout=20)
        extra = first - later
        met = record_target(
            f"{name} first request − later ones, s", extra, FIRST_REQUEST_TARGET, "≤"
        )
        print(
            f"  {name:<4} start {up:5.2f} s   first {first * 1e3:7.1f} ms   "
            f"later {later * 1e3:6.1f} ms   first − later {extra * 1e3:7.1f} ms   {met}"
        )


#: Parts 1 and 2 in one process, on the tree given as its argument (its own code only).
CHILD = """
import sys, time, statistics
import numpy as np
sys.path.insert(0, sys.argv[1])
from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d1 import construction as d1
from app.geometry.d3 import construction as d3
from app.geometry.d4a import construction as d4a
from app.geometry.d4b import construction as d4b, discretization as full
from app.geometry.precision import Float64
ar = Float64()
def cpu(run, count):
    samples = []
    for _ in range(count):
        start = time.process_time()
        run()
        samples.append(time.process_time() - start)
    return statistics.median(samples)
if sys.argv[2] == "1":
    n = 10**5
    lo, hi = -(n // 2), n - n // 2 - 1
    cases = {
        "D4b (h=1, d=1e-4)": lambda: d4b.construct(ar, 1.0, 1e-4, None, lo, hi),
        "D1 (c=1e-4, delta=0.2)": lambda: d1.construct(ar, 1e-4, 0.2, 1.0, 1.0, lo, hi),
        "D3 (c=1, delta=1e-4)": lambda: d3.construct(ar, 1.0, 1e-4, 1.0, "up", lo, hi),
        "D4a (h=1, s=1e-3)": lambda: d4a.construct_sticks(ar, 1.0, 1e-3, None, lo, hi),
    }
    for label, build in cases.items():
        build()
        print(f"{label}, 10^5|{cpu(build, 7) / n * 1e9:.1f} ns/vertex")
n = 10**6
floor, warm, fresh = (copy_floor(n, kind=kind) for kind in ("cold", "warm", "fresh"))
print(f"copy floor, 10^6 (cold, median of 101)|{floor * 1e3:.2f} ms")
print(f"warm copy, 10^6 (median of 101)|{warm * 1e3:.2f} ms")
# the issue's own floor: a plain np.copy of the output, fresh pages each time (median of 101)
print(f"issue's floor: np.copy, fresh pages (median of 101)|{fresh * 1e3:.2f} ms")
lo, hi = -(n // 2), n - n // 2 - 1
none = Selection(checks=frozenset())
for method in ("closed-form", "construction"):
    def run(selection, m=method):
        start, wall = time.process_time(), time.perf_counter()
        full.compute(ar, 1.0, 1e-4, None, lo, hi, m, selection=selection)
        return time.process_time() - start, time.perf_counter() - wall
    run(EVERYTHING), run(none)
    pairs = [(run(EVERYTHING), run(none)) for _ in range(3)]
    every = statistics.median(e[0] for e, _ in pairs)
    alone = statistics.median(e[0] - o[0] for e, o in pairs)
    alone_wall = statistics.median(e[1] - o[1] for e, o in pairs)
    print(f"D4b 10^6 every check, {method}|{every * 1e3:.0f} ms {every / floor:.0f}x")
    print(
        f"D4b 10^6 checks alone, {method}|{alone * 1e3:.0f} ms {alone / floor:.0f}x"
        f" (warm {alone / warm:.0f}x, issue's floor {alone / fresh:.0f}x)"
    )
    print(f"D4b 10^6 checks alone, wall, {method}|{alone_wall * 1e3:.0f} ms")
    least = min(e[0] for e, _ in pairs) - min(o[0] for _, o in pairs)
    print(f"D4b 10^6 checks alone, least every - least none, {method}|{least * 1e3:.0f} ms")
"""


#: Part 2b, the checks one by one, in one process on the tree given as its argument: for each
#: statement the CPU of "checks=none + that statement" less checks=none (paired, interleaved,
#: median of ``sys.argv[3]`` pairs), then the groups whose members share a quantity (the first
#: member to need it pays for it alone), and the sum against "checks alone" (every − none).
BREAKDOWN = """
import sys, time, statistics, os
sys.path.insert(0, sys.argv[1])
from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d4b import checks as section4, curvature as section5, discretization as full
from app.geometry.precision import Float64
ar = Float64()
n, rounds, method = 10**6, int(sys.argv[2]), sys.argv[3]
lo, hi = -(n // 2), n - n // 2 - 1
ids = [s.id for s, _ in section4._EVALUATORS] + [s.id for s in section5.STATEMENTS]
if len(sys.argv) > 4:  # one group's statements alone (``--group``)
    GROUPS = [g for g in GROUPS if g[0] == sys.argv[4]]
    ids = [i for i in ids if i in GROUPS[0][1]]
def run(selection):
    start = time.process_time()
    full.compute(ar, 1.0, 1e-4, None, lo, hi, method, selection=selection)
    return time.process_time() - start
none = Selection(checks=frozenset())
nones = []
def alone(chosen):
    selection = EVERYTHING if chosen is None else Selection(checks=frozenset(chosen))
    run(selection)
    pairs = []
    for k in range(rounds):
        if k % 2:
            o = run(none); e = run(selection)
        else:
            e = run(selection); o = run(none)
        pairs.append((e, o))
        nones.append(o)
    # paired median, and the least of the selection's runs less the least checks=none so far
    # (on a loaded host noise only adds: the least runs are the least disturbed)
    return statistics.median(e - o for e, o in pairs), min(e for e, _ in pairs)
def least(value):
    return value - min(nones)
run(none)
total, total_least = alone(None)
rows = {i: alone([i]) for i in ids}
for i in ids:
    print(f"{i}|{rows[i][0] * 1e3:.1f} / {least(rows[i][1]) * 1e3:.1f}")
paired, fewest = sum(r[0] for r in rows.values()), sum(least(r[1]) for r in rows.values())
print(f"sum of the rows|{paired * 1e3:.1f} / {fewest * 1e3:.1f}")
print(f"checks alone (every - none)|{total * 1e3:.1f} / {least(total_least) * 1e3:.1f}")
print(f"checks=none (least)|{min(nones) * 1e3:.1f}")
for name, members in GROUPS:
    members = [m for m in members if m in rows]
    together = alone(members)
    shared = sum(least(rows[m][1]) for m in members) - least(together[1])
    print(
        f"group {name}: together (shared)|{together[0] * 1e3:.1f} / "
        f"{least(together[1]) * 1e3:.1f} ({shared * 1e3:.1f})"
    )
print(f"load average|{os.getloadavg()[0]:.2f}")
"""

#: Statements that share a quantity computed once for all of them (what the first to need it
#: pays): the three fits; (13) and its two-step form (one recursion pass); Theorems 5, 6 (one
#: pass over the closed forms); (18)-(20) and their two resolutions and comparisons (one blocked
#: pass); the two rings (Theorems 7, 8 and (17)).
GROUPS = (
    ("fits", ("theorem-4-i", "theorem-4-ii", "theorem-4-iii")),
    ("recursion", ("recursion-13", "two-step")),
    ("closed kinematics", ("theorem-5", "theorem-6")),
    (
        "Gauss images",
        (
            "equation-18",
            "equation-18-slope",
            "equation-19",
            "equation-19-rotation",
            "equation-20-inversion",
            "equation-20",
        ),
    ),
    ("rings", ("theorem-7", "theorem-8", "equation-17")),
    ("Darboux", ("darboux", "darboux-distance")),
)


def breakdown(
    trees: list[tuple[str, str]], rounds: int, method: str, group: str | None = None
) -> None:
    """Part 2b for each (name, root) of ``trees``, each in its own process, with glibc's
    default malloc and with the server's (``SERVER_ENV``); one column per tree and setting;
    ``group``: that group of ``GROUPS`` only."""
    import os
    import subprocess

    plain = {k: v for k, v in os.environ.items() if not k.startswith("MALLOC_")}
    settings = {"glibc": plain, "server env": {**plain, **server_env()}}
    script = f"GROUPS = {GROUPS!r}\n" + BREAKDOWN
    columns: list[str] = []
    figures: dict[str, dict[str, str]] = {}
    start_load = os.getloadavg()[0]
    for setting, env in settings.items():
        for name, root in trees:
            column = f"{name}, {setting}"
            columns.append(column)
            chosen = [] if group is None else [group]
            out = subprocess.run(
                [sys.executable, "-c", script, root, str(rounds), method, *chosen],
                capture_output=True,
                text=True,
                check=True,
                cwd=root,
                env={**env, "NUMBA_CACHE_DIR": f"{root}/.numba-cache"},
            ).stdout
            for line in out.splitlines():
                label, value = line.split("|")
                figures.setdefault(label, {})[column] = value
    print(
        f" the checks one by one at 10^6, {method}: CPU ms of checks=none + the statement less "
        f"checks=none, as 'paired median of {rounds} / least run less least checks=none' (the "
        f"second is the steadier under load); a quantity shared by a group is paid by "
        f"whichever member runs (each row alone pays for it), the group row shows the members "
        f"together and (in brackets, least) what they share; load average {start_load:.1f} at "
        f"the start"
    )
    print(f"  {'statement':<40}" + "".join(f"{c:>24}" for c in columns))
    for label, by_column in figures.items():
        cells = "".join(f"{by_column.get(c, ''):>24}" for c in columns)
        print(f"  {label:<40}{cells}")


def server_env() -> dict[str, str]:
    """The malloc settings the server runs with (the Makefile's ``SERVER_ENV``)."""
    for line in (ROOT / "Makefile").read_text().splitlines():
        if line.startswith("SERVER_ENV :="):
            return dict(item.split("=", 1) for item in line.split(":=", 1)[1].split())
    raise LookupError("SERVER_ENV not in the Makefile")


def _child() -> str:
    """``CHILD`` with this tree's ``copy_floor`` before it: both trees' checks are judged against
    the same floors, whichever bench the other tree has."""
    import inspect

    return (
        "from __future__ import annotations\n"
        "import statistics, time\nfrom collections.abc import Callable\nimport numpy as np\n"
        f"COLD_BYTES = {COLD_BYTES}\n"
        + inspect.getsource(_median_cpu)
        + inspect.getsource(copy_floor)
        + CHILD
    )


def against(base: str, rounds: int, parts: str) -> None:
    """Parts 1 and 2 in ``base`` and here, each in its own process, alternating; part 2 with
    glibc's default malloc and with the server's environment (``SERVER_ENV``)."""
    import os
    import subprocess

    plain = {k: v for k, v in os.environ.items() if not k.startswith("MALLOC_")}
    settings = {"glibc": plain, "server env": {**plain, **server_env()}}
    figures: dict[str, dict[str, list[str]]] = {}
    loads = [os.getloadavg()[0]]
    for _ in range(rounds):
        for setting, env in settings.items():
            for name, root in (("base", base), ("here", str(ROOT))):
                out = subprocess.run(
                    [sys.executable, "-c", _child(), root, parts if setting == "glibc" else "2"],
                    capture_output=True,
                    text=True,
                    check=True,
                    cwd=root,
                    env={**env, "NUMBA_CACHE_DIR": f"{root}/.numba-cache"},
                ).stdout
                for line in out.splitlines():
                    label, value = line.split("|")
                    if not label.endswith("10^5"):
                        label = f"{label} [{setting}]"
                    figures.setdefault(label, {}).setdefault(name, []).append(value)
    loads.append(os.getloadavg()[0])
    print(
        f" {base} → this tree, {rounds} rounds, each in its own process (CPU time unless "
        f"said; load average {loads[0]:.1f} at the start, {loads[1]:.1f} at the end)"
    )
    for label, by_tree in sorted(figures.items(), key=lambda item: item[0].endswith("]")):
        before, after = ", ".join(by_tree["base"]), ", ".join(by_tree["here"])
        print(f"  {label:<58} {before}  →  {after}")


def main() -> None:
    if "--arithmetic" in sys.argv:
        arithmetic()
        return
    if "--statements" in sys.argv:
        rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 3
        trees = [("here", str(ROOT))]
        if "--base" in sys.argv:
            trees.insert(0, ("base", sys.argv[sys.argv.index("--base") + 1]))
        method = sys.argv[sys.argv.index("--method") + 1] if "--method" in sys.argv else None
        group = sys.argv[sys.argv.index("--group") + 1] if "--group" in sys.argv else None
        breakdown(trees, rounds, method or "closed-form", group)
        return
    if "--base" in sys.argv:
        rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 2
        parts = "2" if "--checks-only" in sys.argv else "1"
        against(sys.argv[sys.argv.index("--base") + 1], rounds, parts)
        return
    print("Compiled float64 kernels (median of paired ratios; CPU time unless said)")
    arithmetic()
    constructions()
    checks()
    first_request()


if __name__ == "__main__":
    main()
