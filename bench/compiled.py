"""The compiled float64 kernels (issue 13), before → after, side by side in one run.

1. ns/vertex of each recursive construction at 10^5 vertices: *before* is the same
   ``construct`` taking its Python loop (the mp path's loop, run here over Python floats: the
   float64 code of before, step for step), *after* the compiled kernel; ratio of paired samples.
2. Every check of a 10^6-vertex D4b against the copy floor (copying a filled (n, 2) float64
   array into a fresh one), with method=closed-form (the checks alone) and construction.
3. The first request after the server starts against later computed requests of the same
   size (a new d each time, so no cache answers): what a kernel compiled or loaded on a request
   would cost. The issue's target: at most 1 s more.

Run: .venv/bin/python bench/compiled.py   (about 60 s; ``make bench`` runs it with the others)

``--base DIR`` compares with another version of the code instead (e.g. a commit exported with
``git archive <commit> app bench | tar -x -C DIR``): parts 1 and 2 run in DIR and here, each in
its own process, alternating for ``--rounds`` rounds (CPU time; the kernels of DIR compile into
its own cache on its first run).
"""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from app.geometry.d1 import construction as d1
from app.geometry.d3 import construction as d3
from app.geometry.d4a import construction as d4a
from app.geometry.d4b import (
    construction as d4b,
    discretization as d4b_full,
)
from app.geometry.precision import Float64
from bench.common import compare, ratio_row, record_target

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


def checks(n: int = 10**6) -> None:
    ar = Float64()
    lo, hi = -(n // 2), n - n // 2 - 1
    out = np.ones((n, 2))
    print(f" D4b at {n:,} vertices, every check, against copying the (n, 2) output")
    for method in ("closed-form", "construction"):
        paired = compare(
            lambda: out.copy(),
            lambda m=method: d4b_full.compute(ar, 1.0, 1e-4, None, lo, hi, m),  # type: ignore[misc]
            3,
        )
        label = f"compute, method={method}"
        verdict = record_target(
            f"D4b {n:,} vertices every check, {method}, × copy", paired.ratio, CHECKS_TARGET, "≤"
        )
        print(f"{ratio_row(label, paired, 'copy')}   {verdict}")


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
sys.path.insert(0, sys.argv[1])
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
lo, hi = -(10**6 // 2), 10**6 - 10**6 // 2 - 1
for method in ("closed-form", "construction"):
    seconds = cpu(lambda: full.compute(ar, 1.0, 1e-4, None, lo, hi, method), 3)
    print(f"D4b 10^6 every check, {method}|{seconds * 1e3:.0f} ms")
"""


def against(base: str, rounds: int) -> None:
    """Parts 1 and 2 in ``base`` and here, each in its own process, alternating."""
    import subprocess

    figures: dict[str, dict[str, list[str]]] = {}
    for _ in range(rounds):
        for name, root in (("base", base), ("here", str(ROOT))):
            out = subprocess.run(
                [sys.executable, "-c", CHILD, root],
                capture_output=True,
                text=True,
                check=True,
                cwd=root,
            ).stdout
            for line in out.splitlines():
                label, value = line.split("|")
                figures.setdefault(label, {}).setdefault(name, []).append(value)
    print(f" {base} → this tree, {rounds} rounds, each in its own process (CPU time)")
    for label, by_tree in figures.items():
        before, after = ", ".join(by_tree["base"]), ", ".join(by_tree["here"])
        print(f"  {label:<42} {before}  →  {after}")


def main() -> None:
    if "--base" in sys.argv:
        rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 2
        against(sys.argv[sys.argv.index("--base") + 1], rounds)
        return
    print("Compiled float64 kernels (median of paired ratios; CPU time unless said)")
    constructions()
    checks()
    first_request()


if __name__ == "__main__":
    main()
