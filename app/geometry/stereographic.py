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

from app.geometry.precision import Arithmetic, Array, stack_points


@dataclass(frozen=True)
class CircleImages:
    """Φ(f_i) for an ``(n,)`` array of f_i > 0."""

    x: Array
    """Φ_1 = (f² − 1)/(f² + 1), along the symmetry axis."""
    y: Array
    """Φ_2 = 2f/(f² + 1) = 2/(F + 1/F), the distance from the axis."""
    hemisphere: np.ndarray[Any, np.dtype[np.int64]]
    """+1 where f ≥ 1 (Φ_1 ≥ 0), −1 where f < 1."""
    pole_offset: Array
    """t = 1 − |Φ_1| = 2/(F² + 1) with F = max(f, 1/f); Φ_1 = hemisphere·(1 − t)."""

    def points(self) -> Array:
        """The images as an ``(n, 2)`` array (Φ_1, Φ_2)."""
        return stack_points(self.x, self.y)


def project(ar: Arithmetic, f: Array) -> CircleImages:
    """Φ(f) = (f² − 1, 2f)/(f² + 1), the projection from (1, 0, 0) of the proof of Theorem 1."""
    big = np.asarray(f >= 1, dtype=bool)
    far = np.where(big, f, 1 / f)  # F = max(f, 1/f) >= 1
    s = far + 1 / far  # F + 1/F, no overflow for large F
    t = 2 / (far * s)  # 2/(F² + 1)
    sign = np.where(big, 1, -1).astype(np.int64)
    return CircleImages(x=sign * (1 - t), y=2 / s, hemisphere=sign, pole_offset=t)


def chords(images: CircleImages) -> Array:
    """Δφ_i = φ_{i+1} − φ_i for consecutive images; ``(n,) images -> (n-1, 2)``."""
    h, t = images.hemisphere, images.pole_offset
    same = h[1:] == h[:-1]
    # same hemisphere: Φ_1 = h(1 − t), so the difference is h(t_i − t_{i+1}) without cancellation;
    # otherwise the two first coordinates have opposite signs and subtract without loss
    dx = np.where(same, h[1:] * (t[:-1] - t[1:]), images.x[1:] - images.x[:-1])
    dy = images.y[1:] - images.y[:-1]
    return stack_points(dx, dy)
