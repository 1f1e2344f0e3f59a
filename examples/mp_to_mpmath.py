"""An answer in precision=mp read into mpmath, keeping every digit."""

from __future__ import annotations

import sys
from typing import Any

import mpmath
from _http import DEFAULT_URL, get_json

DIGITS = 50


def main(base: str = DEFAULT_URL) -> dict[str, Any]:
    curve = get_json(f"{base}/discretizations/d4b?precision=mp&digits={DIGITS}&i_min=0&i_max=4")
    mpmath.mp.dps = DIGITS
    # coordinates are decimal strings in mp mode: mpmath parses them exactly to its precision
    points = [(mpmath.mpf(x), mpmath.mpf(y)) for x, y in curve["vertices"]]
    # Theorem 5: p_i^x = (2i - 1) d, with the d the service used (its default)
    d = mpmath.mpf(str(curve["parameters"]["d"]))
    worst = max(
        abs(x - (2 * i - 1) * d) for i, (x, _) in zip(curve["indices"], points, strict=True)
    )
    print(f"{len(points)} points at {curve['precision']['digits']} digits; p_1^y = {points[1][1]}")
    print(f"largest |p_i^x - (2i - 1) d| = {mpmath.nstr(worst, 5)}")
    return {"points": points, "worst": worst, "d": d, "digits": curve["precision"]["digits"]}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_URL)
