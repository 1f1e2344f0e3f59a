"""How far the fits' summary (``fused_checks.fits_summary``) may be from ``_fits``'s numbers.

The summary takes its terms by reciprocals (one division a row) where the polygon allows it,
``_fits`` by the quotients of ``conditions``: each u and v within a few ulp, so each sum within a
few ulp of the sum of its terms' magnitudes. A constant c = Σ u'v' / Σ v'² (u' = lhs / w,
v' = rhs / w, whatever the scales) then moves by at most 64 eps Σ |u'v'| / Σ v'², and a largest
residual |lhs − c·rhs| / (|lhs|~ + |c|·|rhs|~) by at most the constants' relative moves (eq. (2)'s
misfit at c_(D1)/c_(D3): two of them) and a few ulp of its own.
"""

from __future__ import annotations

import numpy as np

from app.geometry import conditions

EPS = float(np.finfo(np.float64).eps)


def _spreads(p: np.ndarray) -> list[float]:
    """Per fit ((D1), (D3), eq. (2)): Σ |u'v'| / Σ v'², the constant's scale of rounding."""
    columns = conditions._shared_columns(np.ascontiguousarray(p, dtype=np.float64))
    lengths, _, areas, area_sizes, second, second_sizes = (np.asarray(c) for c in columns)
    tiny = np.finfo(np.float64).tiny
    out = []
    with np.errstate(all="ignore"):
        for lhs, size, rhs in (
            (second, second_sizes, lengths[:-1] + lengths[1:]),
            (areas, area_sizes, lengths),
            (second, second_sizes, areas[:-1] + areas[1:]),
        ):
            w = np.maximum(size, tiny)
            u, v = lhs / w, rhs[: len(lhs)] / w
            if not len(u):
                out.append(0.0)
                continue
            big_u, big_v = np.max(abs(u)), np.max(abs(v))  # scaled as the fits scale them
            u, v = u / (big_u if big_u > 0 else 1.0), v / (big_v if big_v > 0 else 1.0)
            ratio = (big_u if big_u > 0 else 1.0) / (big_v if big_v > 0 else 1.0)
            out.append(float(np.sum(abs(u * v)) / np.sum(v * v) * ratio))
    return out


def summary_close(found: np.ndarray, expected: np.ndarray, p: np.ndarray) -> bool:
    """The summary ``found`` against ``_fits``'s ``expected``: the same bits, or the same
    existence, the same NaN and infinities, and each number within its bound of rounding."""
    found, expected = np.asarray(found, dtype=np.float64), np.asarray(expected, dtype=np.float64)
    if np.array_equal(found.view(np.int64), expected.view(np.int64)):
        return True
    if not np.array_equal(found[3:6], expected[3:6]):
        return False
    finite = np.isfinite(expected)
    if not np.array_equal(np.isfinite(found), finite):
        return False
    if not np.array_equal(found[~finite].view(np.int64), expected[~finite].view(np.int64)):
        return False
    spreads = _spreads(p)
    relative = []
    for k in range(3):
        a, b = float(found[k]), float(expected[k])
        bound = 64 * EPS * spreads[k]
        if not (np.isfinite(bound) and abs(a - b) <= bound):
            return a == b
        relative.append(bound / abs(b) if b != 0 else np.inf)
    moved = relative[0] + relative[1] + relative[2]
    for k in range(6, 9):
        a, b = float(found[k]), float(expected[k])
        if finite[k] and a != b and not abs(a - b) <= moved + 8 * EPS * abs(b):
            return False
    return True
