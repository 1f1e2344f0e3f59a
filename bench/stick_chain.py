"""D1, D3, D4a: the sequential constructions against their vectorized closed forms.

Each construction is a scalar loop (each step needs the previous vertex: a quadratic root for
D1 and D3, the previous stick for D4a); the closed forms are numpy expressions (and one cumsum
for D4a). Every figure is a ratio to copying the (n, 2) float64 output, measured in the same run.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry import area_length, hanging_chain, sauer_tractrix
from app.geometry import area_length_closed_forms as d3_closed
from app.geometry import hanging_chain_closed_forms as d1_closed
from app.geometry import sauer_closed_forms as d4a_closed
from app.geometry.precision import Float64
from bench.common import median_time, row


def cases(ar: Float64, lo: int, hi: int) -> list[tuple[str, Callable[[], object]]]:
    """What is timed for the index range lo .. hi."""
    i = ar.indices(lo, hi)
    return [
        ("D1 construction (loop)", lambda: hanging_chain.construct(ar, 1e-4, 0.2, 1, 1, lo, hi)),
        ("D1 closed form", lambda: d1_closed.hyperbolic_cosine(ar, 1e-4, 0.2, 1.0, 1.0, i)),
        ("D3 construction (loop)", lambda: area_length.construct(ar, 1, 1e-4, 1, "up", lo, hi)),
        ("D3 closed form", lambda: d3_closed.hyperbolic_cosine(ar, 1.0, 1e-4, 1.0, True, i)),
        (
            "D4a construction (loop)",
            lambda: sauer_tractrix.construct_sticks(ar, 1, 1e-3, None, lo, hi),
        ),
        ("D4a explicit form", lambda: d4a_closed.tractrix(ar, 1.0, 1e-3, None, lo, hi)),
    ]


def main(sizes: tuple[int, ...] = (10**3, 10**4, 10**5)) -> None:
    ar = Float64()
    print("D1 (c = 1e-4, delta = 0.2), D3 (c = 1, delta = 1e-4), D4a (h = 1, s = 1e-3), float64")
    for n in sizes:
        lo, hi = -(n // 2), n - n // 2 - 1
        out = np.empty((n, 2))
        copy = median_time(lambda out=out: out.copy())
        repeat = 3 if n >= 10**5 else 5
        print(f" n = {n:>9,} vertices (copy {copy * 1e3:.3f} ms)")
        for label, function in cases(ar, lo, hi):
            seconds = median_time(function, repeat, 0.0)
            print(row(label, seconds, copy, "copy") + f"   {seconds / n * 1e6:.2f} µs/vertex")


if __name__ == "__main__":
    main()
