"""precision=mp: 10^3 D4b vertices at 50 and 500 digits, against a researcher's plain script.

The reference is what a researcher writes by hand: recursion (13) in plain mpmath at the same
digits, 1000 heights p_i^y, nothing else. Against it, side by side (median of paired ratios,
bench/common.py):

- the service's precision=mp as served today (mpmath numbers in numpy object arrays; the
  construction and every check, no encoding);
- the ball prototype of issue 15 (``app.geometry.d4b.certified``: python-flint ``arb`` balls,
  the construction, the closed forms (14), (16), and rigorous bounds for 9 of the 21 checks of
  (D4b) — the local ones and Theorems 4–6, not the fits (D1)/(D3)/(2) nor the Gauss images of
  Section 5 — and the erratum E3).

Target (issue 15): every check on balls within 5× of the script at 50 digits.
"""

from __future__ import annotations

import sys
from pathlib import Path

import mpmath

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry.d4b import certified, discretization as d4b
from app.geometry.precision import MultiPrecision
from bench.common import compare, ratio_row

H, D = 1.0, 0.1
LO, HI = -500, 499
TARGET = 5.0


def plain_script(digits: int) -> list[object]:
    """Recursion (13) as a researcher writes it: plain mpmath, 1000 heights."""
    ctx = mpmath.MPContext()
    ctx.dps = digits
    h, d = ctx.mpf(1), ctx.mpf("0.1")
    d2 = d * d
    heights = [h, h]  # p_0^y = p_1^y = h for the vertical first stick
    for _ in range(HI - LO - 1):
        a, b = heights[-2], heights[-1]
        heights.append((b**3 + 2 * d2 * b + d2 * a) / (b * a - d2))
    return heights


def main(digits: tuple[int, ...] = (50, 500)) -> None:
    print(
        f"precision=mp, D4b h = {H:g}, d = {D:g}, {HI - LO + 1} vertices, against a plain mpmath "
        "script of recursion (13) (median of paired ratios)"
    )
    for n_digits in digits:
        mp = MultiPrecision(n_digits)
        served = compare(
            lambda n=n_digits: plain_script(n),
            lambda mp=mp: d4b.compute(mp, H, D, None, LO, HI),
            1,
            warm=False,
        )
        balls = compare(
            lambda n=n_digits: plain_script(n),
            lambda n=n_digits: certified.certify(n, H, D, None, LO, HI),
            5,
        )
        print(ratio_row(f"digits={n_digits}: mpmath, every check", served, "script", TARGET))
        print(
            ratio_row(f"digits={n_digits}: arb balls, 9 certified checks", balls, "script", TARGET)
        )


if __name__ == "__main__":
    main()
