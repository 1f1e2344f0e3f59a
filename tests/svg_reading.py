"""Reading the service's SVG back: parse it safely, recover the plot transform from the drawn
ticks (their positions and their visible labels), and map drawn points back to data."""

from __future__ import annotations

from dataclasses import dataclass
from xml.etree.ElementTree import Element

import numpy as np
from defusedxml import ElementTree

NS = {"svg": "http://www.w3.org/2000/svg"}
G = "{http://www.w3.org/2000/svg}g"


def parse(svg: bytes | str) -> Element:
    root = ElementTree.fromstring(svg)
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    return root


def _label(text: str) -> float:
    return float(text.replace("\u2212", "-"))


@dataclass(frozen=True)
class Inverse:
    """Picture -> data, fitted from the ticks: x = (X − ax)/bx, y = (ay − Y)/by."""

    ax: float
    bx: float
    ay: float
    by: float

    def __call__(self, pixels: np.ndarray) -> np.ndarray:
        out = np.empty_like(pixels)
        out[:, 0] = (pixels[:, 0] - self.ax) / self.bx
        out[:, 1] = (self.ay - pixels[:, 1]) / self.by
        return out

    @property
    def resolution(self) -> float:
        """Data size of the writer's rounding (1/1000 px) plus the ticks' own rounding."""
        return 3e-3 / min(self.bx, self.by)


def inverse_transform(root: Element) -> Inverse:
    fits = []
    for axis, coordinate in (("x", "x1"), ("y", "y1")):
        ticks = [g for g in root.iter(G) if g.get("class") == f"tick {axis}"]
        assert len(ticks) >= 2, f"fewer than two {axis} ticks"
        values = np.array([_label(g.find("svg:text", NS).text or "") for g in ticks])
        positions = np.array(
            [float(g.find("svg:line", NS).get(coordinate) or "nan") for g in ticks]
        )
        slope, intercept = np.polyfit(values, positions, 1)
        residual = np.max(np.abs(intercept + slope * values - positions))
        assert residual < 2e-3, f"{axis} ticks are not evenly placed ({residual})"
        fits.append((intercept, slope))
    (ax, bx), (ay, minus_by) = fits
    return Inverse(ax, bx, ay, -minus_by)


def series(root: Element, name: str) -> Element:
    found = [
        g for g in root.iter(G) if g.get("data-name") == name and "series" in (g.get("class") or "")
    ]
    assert len(found) == 1, f"series {name!r} drawn {len(found)} times"
    return found[0]


def series_names(root: Element) -> list[str]:
    return [
        g.get("data-name") or ""
        for g in root.iter(G)
        if (g.get("class") or "").startswith("series")
    ]


def polyline_pixels(group: Element) -> np.ndarray:
    line = group.find("svg:polyline", NS)
    assert line is not None
    pairs = [p.split(",") for p in (line.get("points") or "").split()]
    return np.array(pairs, dtype=np.float64).reshape(-1, 2)


def circle_pixels(group: Element) -> np.ndarray:
    circles = group.findall("svg:circle", NS)
    return np.array(
        [[float(c.get("cx") or "nan"), float(c.get("cy") or "nan")] for c in circles]
    ).reshape(-1, 2)


def segment_pixels(group: Element) -> np.ndarray:
    """``M X Y L X Y ...`` as ``(m, 2, 2)`` start/end pairs."""
    path = group.find("svg:path", NS)
    assert path is not None
    tokens = (path.get("d") or "").split()
    assert tokens[0::3] == ["M", "L"] * (len(tokens) // 6)
    numbers = np.array([t for k, t in enumerate(tokens) if k % 3], dtype=np.float64)
    return numbers.reshape(-1, 2, 2)


def panel(root: Element, name: str) -> Element:
    """One panel of a multi-panel figure (``<g class="panel" data-panel=name>``)."""
    found = [g for g in root.iter(G) if g.get("class") == "panel" and g.get("data-panel") == name]
    assert len(found) == 1, f"panel {name!r} drawn {len(found)} times"
    return found[0]


def panel_names(root: Element) -> list[str]:
    return [g.get("data-panel") or "" for g in root.iter(G) if g.get("class") == "panel"]


def polygon_pixels(group: Element) -> np.ndarray:
    """The outline of an ``area`` series."""
    shape = group.find("svg:polygon", NS)
    assert shape is not None
    pairs = [p.split(",") for p in (shape.get("points") or "").split()]
    return np.array(pairs, dtype=np.float64).reshape(-1, 2)
