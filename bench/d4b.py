"""D4b as served: the whole computation (polygons and every check) and the JSON of the response.

At 10^6 vertices, float64, h = 1, d = 10^-4:
- the construction (a compiled recursion: each stick needs the previous one) and the whole
  computation with every check, by both methods, against copying the (n, 2) output;
- encoding the whole response (p, six companions, checks) against orjson of the same arrays
  alone (the encoder's floor for this document).

Ratios are medians of paired samples (bench/common.py). Run: .venv/bin/python bench/d4b.py
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import orjson

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry.d4b import discretization as d4b
from app.geometry.d4b.construction import construct
from app.geometry.precision import Float64
from app.responses import curve_document, encode_json
from bench.common import compare, ratio_row

H, D = 1.0, 1e-4


def one_size(ar: Float64, n: int) -> None:
    """Every line for n vertices."""
    lo, hi = -(n // 2), n - n // 2 - 1
    out = np.ones((n, 2))

    def copy() -> object:
        return out.copy()

    repeat = 3 if n >= 10**6 else 5
    built = compare(copy, lambda: construct(ar, H, D, None, lo, hi), repeat)
    closed = compare(copy, lambda: d4b.compute(ar, H, D, None, lo, hi, "closed-form"), repeat)
    full = compare(copy, lambda: d4b.compute(ar, H, D, None, lo, hi), repeat)
    curve = d4b.compute(ar, H, D, None, lo, hi, "closed-form")
    arrays = [curve.polygon.vertices, curve.polygon.indices] + [
        part
        for polyline in curve.companions.values()
        for part in (polyline.vertices, polyline.indices)
    ]

    def alone() -> object:
        return [orjson.dumps(a, option=orjson.OPT_SERIALIZE_NUMPY) for a in arrays]

    def whole() -> bytes:
        return encode_json(curve_document(curve))

    size = len(whole())
    encode = compare(alone, whole, repeat, reference_min_time=0.0)
    print(f" n = {n:>9,} vertices (copy of the output {built.reference * 1e3:.3f} ms)")
    label = f"construction (compiled recursion, {built.seconds / n * 1e9:.0f} ns/vertex)"
    print(ratio_row(label, built, "copy"))
    print(ratio_row("compute, method=closed-form, every check", closed, "copy"))
    print(ratio_row("compute, method=construction, every check", full, "copy"))
    print(ratio_row(f"encode the response ({size / 1e6:.1f} MB JSON)", encode, "orjson(arrays)"))


def main(sizes: tuple[int, ...] = (10**6,)) -> None:
    ar = Float64()
    print(f"D4b as served, h = {H:g}, d = {D:g}, float64 (median of paired ratios)")
    for n in sizes:
        one_size(ar, n)


if __name__ == "__main__":
    main(tuple(int(a) for a in sys.argv[1:]) or (10**6,))
