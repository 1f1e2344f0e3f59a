"""precision=mp: 10^3 D4b vertices at 50 and 500 digits, against the same request in float64.

The whole computation (construction and every check, as served by default) and the encoding of
the response (coordinates as decimal strings), each a median of paired ratios to float64
(bench/common.py). mp numbers are Python objects (mpmath on gmpy2), so every elementwise
operation is a Python call per vertex: the ratio measures that, not numpy.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry.d4b import discretization as d4b
from app.geometry.precision import Float64, MultiPrecision
from app.responses import curve_document, encode_json
from bench.common import compare, ratio_row

H, D = 1.0, 0.1
LO, HI = -500, 499


def main(digits: tuple[int, ...] = (50, 500)) -> None:
    ar = Float64()
    print(
        f"precision=mp, D4b h = {H:g}, d = {D:g}, {HI - LO + 1} vertices (median of paired ratios)"
    )
    fl_curve = d4b.compute(ar, H, D, None, LO, HI)
    for n_digits in digits:
        mp = MultiPrecision(n_digits)
        curve = d4b.compute(mp, H, D, None, LO, HI)
        compute = compare(
            lambda: d4b.compute(ar, H, D, None, LO, HI),
            lambda mp=mp: d4b.compute(mp, H, D, None, LO, HI),
            3,
            warm=False,
        )
        encode = compare(
            lambda: encode_json(curve_document(fl_curve)),
            lambda curve=curve: encode_json(curve_document(curve)),
            3,
        )
        per_vertex = compute.seconds / (HI - LO + 1) * 1e3
        print(
            ratio_row(
                f"digits={n_digits}: compute, every check ({per_vertex:.2f} ms/vertex)",
                compute,
                "float64",
            )
        )
        print(ratio_row(f"digits={n_digits}: encode the response", encode, "float64"))


if __name__ == "__main__":
    main()
