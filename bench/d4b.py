"""D4b: construction, closed forms, full computation and JSON encoding for 10^3..10^6 vertices.

Every figure is printed as a ratio to a reference measured in the same run:
- compute against copying the (n, 2) float64 output array (the memory-bandwidth floor);
- encoding the whole response against orjson serializing the bare vertex array.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import orjson

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry import kinematic_closed_forms as cf
from app.geometry.discretizations import d4b
from app.geometry.kinematic_tractrix import construct
from app.geometry.precision import Float64, MultiPrecision
from app.responses import curve_document, encode_json
from bench.common import median_time, row

H, D = 1.0, 1e-4


def main(sizes: tuple[int, ...] = (10**3, 10**4, 10**5, 10**6)) -> None:
    ar = Float64()
    print("D4b, h = 1, d = 0.0001, float64 (median of 5; ratios in the same run)")
    for n in sizes:
        i_min, i_max = -(n // 2), n - n // 2 - 1
        out = np.empty((n, 2))
        copy = median_time(lambda out=out: out.copy())
        dump = median_time(lambda out=out: orjson.dumps(out, option=orjson.OPT_SERIALIZE_NUMPY))
        i = ar.indices(i_min, i_max)
        repeat = 3 if n >= 10**6 else 5
        closed = median_time(
            lambda i=i: (cf.hyperbolic_cosine(ar, H, D, i, 0.0), cf.tractrix(ar, H, D, i, 0.0)),
            repeat,
        )
        built = median_time(
            lambda lo=i_min, hi=i_max: construct(ar, H, D, None, lo, hi), repeat, 0.0
        )
        full_cf = median_time(
            lambda lo=i_min, hi=i_max: d4b.compute(ar, H, D, None, lo, hi, "closed-form"),
            repeat,
            0.0,
        )
        curve = d4b.compute(ar, H, D, None, i_min, i_max, "closed-form")
        encode = median_time(lambda curve=curve: encode_json(curve_document(curve)), repeat)
        print(
            f" n = {n:>9,} vertices (copy {copy * 1e3:.3f} ms, orjson of the array "
            f"{dump * 1e3:.3f} ms)"
        )
        print(row("closed forms (14) + (16)", closed, copy, "copy"))
        print(row("construction (sequential loop)", built, copy, "copy"))
        print(row("per vertex, construction", built / n, copy / n, "copy"))
        print(row("compute, closed-form method, with checks", full_cf, copy, "copy"))
        print(row("encode the whole JSON response", encode, dump, "orjson(array)"))
    mp = MultiPrecision(50)
    t = median_time(lambda: d4b.compute(mp, H, 0.1, None, -500, 499), 3, 0.0)
    fl = median_time(lambda: d4b.compute(ar, H, 0.1, None, -500, 499), 3)
    print(" mp, 50 digits, 1000 vertices, construction with checks")
    print(row("precision=mp, digits=50", t, fl, "float64"))


if __name__ == "__main__":
    main()
