"""The scale of an SVG plot: data to picture coordinates, tick values and their labels, and how
pixel coordinates are written (``app.rendering.svg``).

Ticks fall on steps of 1, 2 or 5 × 10^k and each carries its value as text (``tick_label``,
inverted by ``parse_tick_label``), so a reader can recover the transform from two ticks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Pixel coordinates are written with this many decimals (1/1000 px).
DECIMALS = 3


@dataclass(frozen=True)
class Transform:
    """Data -> picture coordinates: ``X = ax + bx·x``, ``Y = ay − by·y``."""

    ax: float
    bx: float
    ay: float
    by: float

    def apply(self, points: np.ndarray) -> np.ndarray:
        out = np.empty_like(points)
        out[:, 0] = self.ax + self.bx * points[:, 0]
        out[:, 1] = self.ay - self.by * points[:, 1]
        return out


def nice_step(span: float, target: int) -> float:
    """A tick step of the form 1, 2 or 5 × 10^k giving about ``target`` ticks over ``span``."""
    raw = span / max(target, 1)
    magnitude = 10 ** math.floor(math.log10(raw))
    for factor in (1, 2, 5, 10):
        if factor * magnitude >= raw:
            return float(factor * magnitude)
    return float(10 * magnitude)  # pragma: no cover (10 always qualifies)


def ticks(low: float, high: float, target: int) -> list[float]:
    """Tick values covering [low, high] at a nice step."""
    step = nice_step(high - low, target)
    first = math.ceil(low / step - 1e-9)
    last = math.floor(high / step + 1e-9)
    return [k * step for k in range(first, last + 1)]


def tick_label(value: float, step: float) -> str:
    """A tick value with as many decimals as the step needs; a real minus sign."""
    decimals = max(0, -math.floor(math.log10(step) + 1e-9))
    if abs(value) < step * 1e-6:
        value = 0.0
    text = f"{value:.{decimals}f}"
    if abs(value) >= 1e6 or (value != 0 and abs(value) < 1e-4):
        text = f"{value:.3g}"
    return text.replace("-", "\u2212")


def parse_tick_label(text: str) -> float:
    """The inverse of ``tick_label``."""
    return float(text.replace("\u2212", "-"))


def fmt(value: float) -> str:
    """A pixel coordinate with ``DECIMALS`` decimals, trailing zeros dropped."""
    text = f"{value:.{DECIMALS}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def points_attribute(points: np.ndarray) -> str:
    """``X,Y X,Y …`` of pixel points (an SVG ``points`` attribute)."""
    return " ".join(f"{fmt(x)},{fmt(y)}" for x, y in points.tolist())
