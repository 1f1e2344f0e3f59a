"""D1, D3, D4a: the sequential constructions against their vectorized closed forms.

Each construction is a sequential recursion (each step needs the previous vertex: a quadratic
root for D1 and D3, the previous stick for D4a), so numpy cannot vectorize it; it runs as a
compiled kernel (app/geometry/compiled.py; bench/compiled.py compares it with the Python
loop); the closed forms (theorems, checked against the constructions) are numpy kernels
(bench/kernels.py). Every figure is a median of paired ratios to copying the (n, 2) float64
output, here at 10^5 vertices.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry.d1 import closed_forms as d1_closed, construction as hanging_chain
from app.geometry.d3 import closed_forms as d3_closed, construction as area_length
from app.geometry.d4a import closed_forms as d4a_closed, construction as sauer_tractrix
from app.geometry.precision import Float64
from bench.common import compare, ratio_row


def cases(ar: Float64, lo: int, hi: int) -> list[tuple[str, Callable[[], object]]]:
    """What is timed for the index range lo .. hi."""
    i = ar.indices(lo, hi)
    return [
        (
            "D1 construction (compiled)",
            lambda: hanging_chain.construct(ar, 1e-4, 0.2, 1, 1, lo, hi),
        ),
        ("D1 closed form", lambda: d1_closed.hyperbolic_cosine(ar, 1e-4, 0.2, 1.0, 1.0, i)),
        ("D3 construction", lambda: area_length.construct(ar, 1, 1e-4, 1, "up", lo, hi)),
        ("D3 closed form", lambda: d3_closed.hyperbolic_cosine(ar, 1.0, 1e-4, 1.0, True, i)),
        (
            "D4a construction (compiled)",
            lambda: sauer_tractrix.construct_sticks(ar, 1, 1e-3, None, lo, hi),
        ),
        ("D4a explicit form", lambda: d4a_closed.tractrix(ar, 1.0, 1e-3, None, lo, hi)),
    ]


def main(n: int = 10**5) -> None:
    ar = Float64()
    lo, hi = -(n // 2), n - n // 2 - 1
    out = np.ones((n, 2))
    print(
        f"D1 (c = 1e-4, delta = 0.2), D3 (c = 1, delta = 1e-4), D4a (h = 1, s = 1e-3), float64, "
        f"{n:,} vertices (median of paired ratios)"
    )
    for label, function in cases(ar, lo, hi):
        paired = compare(lambda: out.copy(), function, 5)
        print(f"{ratio_row(label, paired, 'copy')}   {paired.seconds / n * 1e9:7.0f} ns/vertex")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10**5)
