"""Time the (D2a) constructions (vectorized cumulative sums) against a plain Python loop.

Run: .venv/bin/python bench/d2a.py [vertices]. Prints seconds and the ratio loop / numpy for the
same edges; short by default (10^5 vertices) so it stays cheap on a shared machine.
"""

from __future__ import annotations

import sys
import time

from app.geometry.d2a import construction as christoffel
from app.geometry.precision import Float64


def main(vertices: int = 100_000) -> None:
    ar = Float64()
    half = vertices // 2
    start = time.perf_counter()
    built = christoffel.quad(ar, 1.0, 1.0005, 0.0, -half, half)
    vectorized = time.perf_counter() - start
    edges = christoffel.dual_edges(ar, built.gauss_edges, 1)
    start = time.perf_counter()
    x = y = 0.0
    for ex, ey in edges.tolist():  # the same sums, one vertex at a time
        x, y = x + ex, y + ey
    loop = time.perf_counter() - start
    print(f"d2a-quad, {vertices} vertices: numpy {vectorized:.4f} s (whole construction);")
    print(f"python loop over the cumulative sum alone {loop:.4f} s, ratio {loop / vectorized:.1f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100_000)
