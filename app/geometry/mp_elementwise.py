"""mpmath over numpy object arrays: its functions entry by entry, and ``scalar * array`` kept O(n).

``MultiPrecision`` (``app.geometry.precision``) builds its functions with these.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np


def array_aware_npconvert(convert: Callable[[Any], Any]) -> Callable[[Any], Any]:
    """mpmath's numpy conversion, refusing arrays at once.

    ``mpf * array`` asks mpmath to convert the array first; mpmath refuses with a TypeError whose
    message holds the repr of the whole array (formatting every entry) before numpy takes over
    elementwise. Refusing without the repr keeps ``scalar * array`` O(n) arithmetic only.
    """

    def npconvert(x: Any) -> Any:
        if isinstance(x, np.ndarray) and x.ndim > 0:
            raise TypeError("cannot create mpf from an array")
        return convert(x)

    return npconvert


def elementwise(
    function: Callable[..., Any], arity: int = 1, clock: Callable[[], None] | None = None
) -> Callable[..., Any]:
    """Apply an mpmath function to scalars or, entry by entry, to object arrays.

    ``clock`` (the arithmetic's ``check_time``) runs before every array operation.
    """
    ufunc = np.frompyfunc(function, arity, 1)

    def apply(*args: Any) -> Any:
        if any(isinstance(a, np.ndarray) for a in args):
            if clock is not None:
                clock()
            return ufunc(*args)
        return function(*args)

    return apply
