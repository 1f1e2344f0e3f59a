"""Every closed form and vectorized construction at 10^6 vertices, against the memory floor.

Each kernel is timed alternately with copying a filled (n, 2) float64 array (the output of a
curve: the memory-bandwidth floor) and the printed ratio is the median of the paired ratios
(bench/common.py). A second column divides by one ``np.exp`` pass over n doubles (measured the
same way against the copy): numpy has no fused kernels, so a formula with one exp and k other
elementwise operations costs at least about one exp pass plus k cheaper passes.

"arrays" is how many (n, 2) arrays the kernel writes (D4a returns four polygons, D2a the
sequence f, the Gauss image, its edges and p; Theorem 3 one coordinate): its own floor is that
many copies.

Run: .venv/bin/python bench/kernels.py [vertices]   (default 10^6; about 40 s)
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from functools import partial
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry import elementary
from app.geometry.d1 import closed_forms as d1_closed
from app.geometry.d2a import closed_forms as d2a_closed, construction as christoffel
from app.geometry.d2b import (
    closed_forms as catenoid_convergence,
    construction as vanishing_mean_curvature,
)
from app.geometry.d3 import closed_forms as d3_closed
from app.geometry.d4a import closed_forms as d4a_closed
from app.geometry.d4b import closed_forms as d4b_closed
from app.geometry.precision import Float64
from app.geometry.smooth import curves as smooth
from bench.common import compare, ratio_row

#: The target of the issue for closed forms and vectorized constructions (× the copy).
TARGET = 3.0


def kernels(ar: Float64, n: int) -> list[tuple[str, float, Callable[[], object]]]:
    """(label, (n, 2) arrays returned, function) for every kernel at n vertices."""
    lo, hi = -(n // 2), n - n // 2 - 1
    i = ar.indices(lo, hi)
    even, odd = i[i % 2 == 0], i[i % 2 == 1]  # (8) holds for even indices, (9) for odd ones
    x = np.linspace(-3.0, 3.0, n)
    half = n // 2
    a, b, lam = 1.0, 1.0 + 2.0 / n, 0.5
    sequence = vanishing_mean_curvature.named_sequence(ar, "remark-13", n, 0, n - 1)
    gauss = vanishing_mean_curvature.gauss_image(ar, sequence)
    return [
        ("D4b (14) p_i, Theorem 5", 1, lambda: d4b_closed.hyperbolic_cosine(ar, 1.0, 1e-4, i, 0.0)),
        ("D4b (16) d_i, Theorem 6", 1, lambda: d4b_closed.tractrix(ar, 1.0, 1e-4, i, 0.0)),
        ("D1 closed form", 1, lambda: d1_closed.hyperbolic_cosine(ar, 1e-4, 0.2, 1.0, 1.0, i)),
        ("D3 closed form", 1, lambda: d3_closed.hyperbolic_cosine(ar, 1.0, 1e-4, 1.0, True, i)),
        (
            "D4a explicit form (x, d, e, p)",
            4,
            lambda: d4a_closed.tractrix(ar, 1.0, 1e-3, None, lo, hi),
        ),
        (
            "D2a-hex Theorem 3 (8), (9) p^y",
            0.5,
            lambda: (
                d2a_closed.theorem_3_y_even(ar, a, b, lam, 0.0, even),
                d2a_closed.theorem_3_y_odd(ar, a, b, lam, 0.0, odd),
            ),
        ),
        ("S1 catenary samples", 1, lambda: smooth.catenary(ar, 1.0, x)),
        ("S4 tractrix samples", 1, lambda: smooth.tractrix(ar, 1.0, x)),
        (
            "D2b Lemma 10 (cumsum)",
            1,
            lambda: catenoid_convergence.lemma_10(ar, sequence.s, sequence.one_minus_s2, 0),
        ),
        (
            "D2a-quad construction (f, φ, Δφ, p)",
            3.5,
            lambda: christoffel.quad(ar, 1.0, 1.0 + 1.0 / n, 0.0, -half, half - 1),
        ),
        (
            "D2a-hex construction (f, φ, Δφ, p)",
            3.5,
            lambda: christoffel.hexagonal(ar, a, b, lam, 0.0, -half, half - 1),
        ),
        (
            "D2b construction (3D mixed areas)",
            1,
            lambda: vanishing_mean_curvature.catenoid_meridian(ar, gauss, 0),
        ),
    ]


def main(n: int = 10**6) -> None:
    ar = Float64()
    out = np.ones((n, 2))
    ones = np.linspace(-1.0, 1.0, n)

    def copy() -> object:
        return out.copy()

    exp = compare(copy, lambda: np.exp(ones), repeat=9, min_time=0.02)
    print(
        f"Kernels, {n:,} vertices, float64 (median of paired ratios; copy of the (n, 2) output "
        f"{exp.reference * 1e3:.3f} ms; one np.exp pass {exp.seconds * 1e3:.3f} ms = "
        f"{exp.ratio:.2f}× copy)"
    )
    for label, arrays, function in kernels(ar, n):
        paired = compare(copy, function, repeat=3 if "3D" in label else 5)
        target = TARGET if "construction (3D" not in label else None
        line = ratio_row(label, paired, "copy", target)
        print(f"{line}   {paired.ratio / exp.ratio:6.1f}× exp   ({arrays:g} arrays)")
    elementary_functions()


#: numpy's ufunc of each of ``elementary``'s functions (their arguments: in the domain).
NUMPY_TWINS = {
    "exp": np.exp,
    "log": np.log,
    "cos": np.cos,
    "sin": np.sin,
    "cosh": np.cosh,
    "sinh": np.sinh,
    "tanh": np.tanh,
    "atanh": np.arctanh,
    "atan2": np.arctan2,
    "power": np.power,
}


def elementary_functions(sizes: tuple[int, ...] = (100, 10**6)) -> None:
    """The C library's functions (``app.geometry.elementary``, what the float64 arithmetic
    calls) against numpy's ufuncs of the same name, side by side: on a processor with AVX-512
    numpy's are SVML's (faster, other bits), without it mostly the same C library calls."""
    print(
        "Elementary functions, float64: app.geometry.elementary (the C library) × numpy's ufunc "
        "(median of paired ratios)"
    )
    for n in sizes:
        x = np.linspace(0.1, 0.9, n)  # in every domain: log, atanh, power with a real result
        y = np.linspace(0.5, 1.5, n)
        cells = []
        for name, twin in NUMPY_TWINS.items():
            ours = getattr(elementary, name)
            args = (x, y) if twin.nin == 2 else (x,)
            paired = compare(partial(twin, *args), partial(ours, *args), repeat=5, min_time=0.02)
            cells.append(f"{name} {paired.ratio:4.2f}×")
        out = np.empty(n)  # exp_into: glibc's exp written out and vectorized, the same bits
        paired = compare(
            partial(np.exp, x, out=out),
            partial(elementary.exp_into, x, out),
            repeat=5,
            min_time=0.02,
        )
        cells.append(f"exp_into {paired.ratio:4.2f}×")
        print(f"  n = {n:>9,}: " + ", ".join(cells))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10**6)
