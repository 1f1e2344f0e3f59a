"""precision=mp: 10^3 D4b vertices at 50 and 500 digits, against a researcher's plain script.

The reference is what a researcher writes by hand: recursion (13) in plain mpmath at the same
digits, 1000 heights p_i^y, nothing else. Against it, side by side (median of paired ratios,
bench/common.py), the construction and all 21 checks of (D4b) with every companion, no encoding:

- on mpmath numbers in numpy object arrays (``MultiPrecision``: the mp path before issue 15,
  still what ``discretization.compute`` does when called with it directly);
- on rigorous balls (``balls.serve``: python-flint ``arb``, what the service serves for
  precision=mp of (D4b)), residuals as rigorous bounds, the precision raised as needed;
- on balls with ``checks=none`` (the polygon and companions alone).

Target (issue 15): every check on balls within 5× of the script at 50 digits.

What a ratio measures (``bench.common.compare``): CPU time of this process, the script and the
subject alternating (script, subject, script, subject, …), each subject sample one call from
the parameters to the returned ``Curve`` (no response encoding: the decimal strings of the
coordinates are not in it), each script sample as many runs as fill 20 ms (one or two), and
the figure the median over the pairs of subject / the script sample just before it. The
served row takes ``SERVED_PAIRS`` pairs (15; one run of the 5 pairs it took before moved by
±0.3× from run to run), the other rows fewer (they have no target). The rows on balls run
before the mpmath ones: after the mpmath path this process ran both sides about 45 % slower
(docs/performance.md, issue 15, session 20), while alternating itself costs neither side
measurable time.
"""

from __future__ import annotations

import functools
import os
import sys
from pathlib import Path
from typing import Any

import mpmath

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.geometry import balls
from app.geometry.curve import EVERYTHING, NOTHING, Selection
from app.geometry.d4b import discretization as d4b
from app.geometry.precision import MultiPrecision
from bench.common import compare, ratio_row

H, D = 1.0, 0.1
LO, HI = -500, 499
TARGET = 5.0
#: Pairs of the served row (the one with the target); the others take ``PAIRS``.
SERVED_PAIRS, PAIRS = 15, 5


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


def on_balls(digits: int, selection: Selection = EVERYTHING) -> Any:
    """(D4b) as the service computes precision=mp: on balls, every check."""
    arguments: dict[str, Any] = {"h": H, "d": D, "beta0": None, "i_min": LO, "i_max": HI}
    return balls.serve(
        "d4b",
        MultiPrecision(digits),
        lambda ar: d4b.compute(ar, **arguments, selection=selection),
        arguments,
    )


def main(digits: tuple[int, ...] = (50, 500)) -> None:
    print(
        f"precision=mp, D4b h = {H:g}, d = {D:g}, {HI - LO + 1} vertices, against a plain mpmath "
        f"script of recursion (13) (median of paired ratios; load average {os.getloadavg()[0]:.2f})"
    )
    # the balls first, at every digits: after the mpmath path (seconds of mpmath numbers) this
    # process runs both the script and the served computation about 45 % slower (heap and
    # caches; a gc.collect() does not undo it), which made the ratio jump from run to run
    for n_digits in digits:
        script = functools.partial(plain_script, n_digits)
        served = compare(script, functools.partial(on_balls, n_digits), SERVED_PAIRS)
        polygon = compare(script, functools.partial(on_balls, n_digits, NOTHING), PAIRS)
        print(
            ratio_row(f"digits={n_digits}: balls (served), every check", served, "script", TARGET)
        )
        print(ratio_row(f"digits={n_digits}: balls, checks=none", polygon, "script"))
    for n_digits in digits:
        mp = MultiPrecision(n_digits)
        mpmath_path = compare(
            functools.partial(plain_script, n_digits),
            functools.partial(d4b.compute, mp, H, D, None, LO, HI),
            1,
            warm=False,
        )
        print(ratio_row(f"digits={n_digits}: mpmath, every check", mpmath_path, "script"))


if __name__ == "__main__":
    main()
