"""Smooth references of Section 2: the catenary (S1)–(S3) and the tractrix with its evolute (S4).

Sampled at ``count`` equally spaced x in [x_min, x_max] (both included):

- catenary (S1): x ↦ (x, h cosh(x/h)), the solution of y'' = (1/h)√(1 + y'²) through (0, h);
- tractrix (S4) with stick h: x ↦ d(x) = (x − h tanh(x/h), h / cosh(x/h)); the leader is the
  axis point (x, 0), and |d(x) − (x, 0)| = h.

The evolute of the tractrix is computed from the tractrix's own derivatives, not from cosh:
with τ = tanh(x/h), σ = 1/cosh(x/h),

    d'(x) = (τ², −στ),    d''(x) = (2τσ²/h, σ(τ² − σ²)/h),

and the centre of curvature is q = d + (|d'|² / (d' × d'')) J d', J the rotation by +90°.
(S4) says q(x) = (x, h cosh(x/h)), and the construction of Nikolaides says that the triangle
(x, 0), q(x), d(x) has a right angle at d(x). At the cusp x = 0 the derivative vanishes and the
centre of curvature is a limit (0, h); there it is not evaluated.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.d4b.closed_forms import amplitude_cosh, amplitude_sech, tanh_and_sech
from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array, Scalar, stack_points


@dataclass(frozen=True)
class Evolute:
    """Centres of curvature ``(n, 2)`` and where they are defined (``(n,)`` bool)."""

    centres: Array
    defined: np.ndarray[Any, np.dtype[np.bool_]]


def validate(h: float, x_min: float, x_max: float, count: int) -> None:
    """Raise ``DomainError`` unless h > 0, x_min < x_max (finite) and count >= 2."""
    if not np.isfinite(h) or h <= 0:
        raise DomainError("h", "h > 0", h)
    if not np.isfinite(x_min):
        raise DomainError("x_min", "x_min is a finite number", x_min)
    if not np.isfinite(x_max) or not x_max > x_min:
        raise DomainError("x_max", "x_min < x_max", x_max, f"x_min = {x_min!r}")
    if count < 2:
        raise DomainError("count", "count >= 2", count)


def sample(ar: Arithmetic, x_min: float, x_max: float, count: int) -> Array:
    """x_k = x_min + (x_max − x_min)·k/(count − 1), k = 0 .. count − 1 (both ends exact)."""
    lo, hi = ar.scalar(x_min), ar.scalar(x_max)
    width, last = hi - lo, count - 1
    x = ar.values(lambda k: lo + width * k / last, ar.indices(0, last))
    x[-1] = hi
    return x


def catenary(ar: Arithmetic, h: Scalar, x: Array) -> Array:
    """(S1): (x, h cosh(x/h)); ``(n,) -> (n, 2)``, elementwise in x."""
    return ar.points(lambda x: (x, amplitude_cosh(ar, h, x / h)), x)


def catenary_offsets(ar: Arithmetic, h: Scalar, x: Array, distance: Scalar) -> tuple[Array, Array]:
    """The parallel curves of the catenary at normal distance ``distance`` (above, below).

    The unit normal of (x, h cosh(x/h)) is (−tanh(x/h), 1/cosh(x/h)). For distance < h (the
    least radius of curvature, at the vertex) the two curves bound the ε-neighbourhood of the
    catenary drawn in Figure 8 (right); ``(n,) -> (n, 2), (n, 2)``.
    """
    if not distance < h:
        raise DomainError("eps", "0 < eps < h (the least radius of curvature)", distance)
    points = catenary(ar, h, x)
    normal = stack_points(-ar.tanh(x / h), amplitude_sech(ar, h, x / h) / h)
    return points + distance * normal, points - distance * normal


def tractrix(ar: Arithmetic, h: Scalar, x: Array) -> Array:
    """(S4): d(x) = (x − h tanh(x/h), h / cosh(x/h)); ``(n,) -> (n, 2)``, elementwise in x."""

    def kernel(x: Array) -> tuple[Array, Array]:
        tanh, sech = tanh_and_sech(ar, x / h)
        return x - h * tanh, h * sech

    return ar.points(kernel, x)


def tractrix_derivatives(ar: Arithmetic, h: Scalar, x: Array) -> tuple[Array, Array]:
    """d'(x) and d''(x) of the tractrix, differentiated by hand; two ``(n, 2)`` arrays."""
    tau = ar.tanh(x / h)
    sigma = amplitude_sech(ar, ar.scalar(1), x / h)
    first = stack_points(tau * tau, -sigma * tau)
    second = stack_points(2 * tau * sigma * sigma / h, sigma * (tau * tau - sigma * sigma) / h)
    return first, second


def centres_of_curvature(ar: Arithmetic, points: Array, first: Array, second: Array) -> Evolute:
    """q = d + (|d'|²/(d' × d'')) J d' for a curve d with derivatives d', d''; ``(n, 2)``."""
    cross = first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0]
    speed2 = first[:, 0] * first[:, 0] + first[:, 1] * first[:, 1]
    defined = np.asarray(cross != 0, dtype=bool)
    ratio = speed2 / np.where(defined, cross, 1)
    ratio = np.where(defined, ratio, 0)
    centres = stack_points(points[:, 0] - ratio * first[:, 1], points[:, 1] + ratio * first[:, 0])
    return Evolute(centres, defined)
