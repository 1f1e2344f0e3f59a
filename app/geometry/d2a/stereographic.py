"""Stereographic projection of the conformal plane's y-axis to the unit circle ((S2), Theorem 1).

The proof of Theorem 1 projects from the centre (1, 0, 0): the point f of the y-axis goes to
Φ(f) = (f² − 1, 2f, 0)/(f² + 1) on the unit sphere. All images lie in the plane of the first two
coordinates, on the unit circle; the first coordinate is the axis of the rotational symmetry
(the x-axis of the meridian polygon), the second the distance from that axis (its y-axis).

Accurate differences. Images of large or small f crowd towards the poles (±1, 0), where the
first coordinates of neighbours agree in many leading digits and a plain subtraction loses them.
So each image also keeps its *pole offset* t = 1 − |Φ_1| = 2/(F² + 1), F = max(f, 1/f), which is
computed without cancellation, and ``chords`` subtracts offsets of images in the same hemisphere.
This is the same definition evaluated carefully, not a formula of the proof.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.precision import Arithmetic, Array


@dataclass(frozen=True)
class CircleImages:
    """Φ(f_i) for an ``(n,)`` array of f_i > 0."""

    table: Array
    """``(n, 3)``: the columns Φ_1, Φ_2 and the pole offset t."""
    hemisphere: np.ndarray[Any, np.dtype[np.int64]]
    """+1 where f ≥ 1 (Φ_1 ≥ 0), −1 where f < 1."""

    @property
    def x(self) -> Array:
        """Φ_1 = (f² − 1)/(f² + 1), along the symmetry axis."""
        return self.table[:, 0]

    @property
    def y(self) -> Array:
        """Φ_2 = 2f/(f² + 1) = 2/(F + 1/F), the distance from the axis."""
        return self.table[:, 1]

    @property
    def pole_offset(self) -> Array:
        """t = 1 − |Φ_1| = 2/(F² + 1) with F = max(f, 1/f); Φ_1 = hemisphere·(1 − t)."""
        return self.table[:, 2]

    def points(self) -> Array:
        """The images as an ``(n, 2)`` array (Φ_1, Φ_2), a view of ``table``."""
        return self.table[:, :2]


def project(ar: Arithmetic, f: Array) -> CircleImages:
    """Φ(f) = (f² − 1, 2f)/(f² + 1), the projection from (1, 0, 0) of the proof of Theorem 1.

    Elementwise in f (``Arithmetic.columns``); x, y and the pole offset t are columns of one
    ``(n, 3)`` table, so ``points()`` is a view.
    """
    big = np.asarray(f >= 1, dtype=bool)

    def kernel(f: Array) -> tuple[Array, Array, Array]:
        up = f >= 1
        far = np.where(up, f, 1 / f)  # F = max(f, 1/f) >= 1
        s = far + 1 / far  # F + 1/F, no overflow for large F
        t = 2 / (far * s)  # 2/(F² + 1)
        return np.where(up, 1 - t, t - 1), 2 / s, t

    sign = np.where(big, 1, -1).astype(np.int64)
    return CircleImages(table=ar.columns(kernel, 3, f), hemisphere=sign)


def chords(ar: Arithmetic, images: CircleImages) -> Array:
    """Δφ_i = φ_{i+1} − φ_i for consecutive images; ``(n,) images -> (n-1, 2)``."""
    h, t, x = images.hemisphere, images.pole_offset, images.x

    def kernel(
        h0: Array, h1: Array, t0: Array, t1: Array, x0: Array, x1: Array, y0: Array, y1: Array
    ) -> tuple[Array, Array]:
        # same hemisphere: Φ_1 = h(1 − t), so the difference is h(t_i − t_{i+1}) without
        # cancellation; otherwise the first coordinates have opposite signs and subtract without
        # loss
        return np.where(h1 == h0, h1 * (t0 - t1), x1 - x0), y1 - y0

    y = images.y
    return ar.points(kernel, h[:-1], h[1:], t[:-1], t[1:], x[:-1], x[1:], y[:-1], y[1:])
