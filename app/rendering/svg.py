"""A dependency-free SVG plot writer: axes with ticks and labels, a legend, polylines, points
and segments, optionally with equal aspect (for geometry).

The output is one self-contained document: no external fonts, stylesheets, images or scripts;
a ``viewBox`` so that it scales to any container; every text escaped. Data coordinates map to
the picture by ``X = a_x + b_x·x`` and ``Y = a_y − b_y·y`` (y grows upwards), and each tick
carries its value as visible text, so a reader can invert the transform from two ticks of each
axis.

Structure (what tests and scripts can rely on)::

    <svg class="dcosh-plot">
      <g class="axes"> <g class="tick x"><line/><text>0.5</text></g> ... </g>
      <g class="data" clip-path="...">
        <g class="series" data-name="p"> <polyline points="X,Y X,Y ..."/> <circle/>... </g>
        <g class="series" data-name="sticks"> <path d="M X Y L X Y M ..."/> </g>
      </g>
      <g class="legend"> ... </g>
    </svg>
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from app.rendering.svg_scale import (
    Transform,
    fmt,
    nice_step,
    points_attribute,
    tick_label,
    ticks,
)
from app.rendering.text_width import text_width, wrap

#: Colour-blind-safe palette (Okabe–Ito), in the order series are added without a colour.
PALETTE = (
    "#0072B2",
    "#D55E00",
    "#009E73",
    "#CC79A7",
    "#E69F00",
    "#56B4E9",
    "#000000",
    "#F0E442",
)

#: Series with more vertices than this are drawn without a marker per vertex.
MAX_MARKERS = 400


SeriesKind = Literal["line", "points", "segments", "area"]


@dataclass(frozen=True)
class Series:
    """One thing to draw: ``(n, 2)`` finite float points (for ``segments``: ``(2m, 2)``, pairs;
    for ``area``: a closed outline, filled translucently)."""

    name: str
    label: str
    points: np.ndarray
    kind: SeriesKind = "line"
    color: str | None = None
    markers: bool = True
    dashed: bool = False
    width: float = 1.5
    description: str = ""


@dataclass
class Plot:
    """A 2D plot; add series, then ``render()``."""

    title: str
    x_label: str = "x"
    y_label: str = "y"
    equal_aspect: bool = True
    width: int = 800
    height: int = 560
    """Size of the plot with its axes; the legend and footnote add rows below."""
    subtitle: str = ""
    footnote: str = ""
    series: list[Series] = field(default_factory=list)

    def add(self, series: Series) -> None:
        """Add one series (its points must be finite)."""
        points = np.asarray(series.points, dtype=np.float64).reshape(-1, 2)
        if not np.all(np.isfinite(points)):
            raise ValueError(f"series {series.name!r} has non-finite points")
        color = series.color or PALETTE[len(self.series) % len(PALETTE)]
        self.series.append(
            Series(
                series.name,
                series.label,
                points,
                series.kind,
                color,
                series.markers,
                series.dashed,
                series.width,
                series.description,
            )
        )

    def render(self) -> str:
        """The SVG document."""
        return _Renderer(self).render()


@dataclass
class Panels:
    """Several plots side by side under one title: a figure with left, centre and right parts.

    Each panel keeps its own axes, scales and legend inside ``<g class="panel"
    data-panel="name" transform="translate(…)">``, so a reader recovers each panel's transform
    from that panel's ticks.
    """

    title: str
    panels: list[tuple[str, Plot]] = field(default_factory=list)
    subtitle: str = ""
    footnote: str = ""

    HEADER = 52
    """Height of the figure's title and subtitle above the panels."""

    def add(self, name: str, plot: Plot) -> None:
        """Add one panel (``name`` is its ``data-panel``, e.g. ``left``)."""
        self.panels.append((name, plot))

    def render(self) -> str:
        """The SVG document."""
        renderers = [(name, _Renderer(plot, prefix=f"{name}-")) for name, plot in self.panels]
        width = sum(r.plot.width for _, r in renderers) or 400
        tallest = max((r.total_height for _, r in renderers), default=0)
        title_lines = wrap(self.title, width - 16, 16, bold=True)
        subtitle_lines = wrap(self.subtitle, width - 16, 12) if self.subtitle else []
        footnote_lines = wrap(self.footnote, width - 32, 10) if self.footnote else []
        header = self.HEADER + 20 * (len(title_lines) - 1) + 16 * max(0, len(subtitle_lines) - 1)
        footnote = 20 + 13 * (len(footnote_lines) - 1) if footnote_lines else 0
        height = header + tallest + footnote
        words = " ".join(f"{name}: {r.description()}" for name, r in renderers)
        parts = [
            '<svg xmlns="http://www.w3.org/2000/svg" class="dcosh-plot dcosh-figure" '
            f'viewBox="0 0 {width} {height}" width="{width}" height="{height}" role="img" '
            'aria-labelledby="plot-title plot-desc" '
            'font-family="DejaVu Sans, Helvetica, Arial, sans-serif" font-size="12">',
            f'<title id="plot-title">{escape(self.title)}</title>',
            f'<desc id="plot-desc">{escape(words)}</desc>',
            f'<rect class="background" x="0" y="0" width="{width}" height="{height}" '
            'fill="#ffffff"/>',
            _text(
                'class="title" text-anchor="middle" font-size="16" font-weight="bold"',
                title_lines,
                width / 2,
                22,
                20,
            ),
        ]
        if subtitle_lines:
            parts.append(
                _text(
                    'class="subtitle" text-anchor="middle" fill="#444444"',
                    subtitle_lines,
                    width / 2,
                    42 + 20 * (len(title_lines) - 1),
                    16,
                )
            )
        x = 0
        for name, renderer in renderers:
            parts.append(
                f'<g class="panel" data-panel={quoteattr(name)} '
                f'transform="translate({x} {header})">'
            )
            parts.append(renderer.body())
            parts.append("</g>")
            x += renderer.plot.width
        if footnote_lines:
            parts.append(
                _text(
                    'class="footnote" font-size="10" fill="#555555"',
                    footnote_lines,
                    16,
                    height - 8 - 13 * (len(footnote_lines) - 1),
                    13,
                )
            )
        parts.append("</svg>")
        return "\n".join(parts) + "\n"


def _text(attributes: str, lines: list[str], x: float, y: float, step: float) -> str:
    """One ``<text>`` element; further lines as ``<tspan>`` at the same ``x``, ``step`` lower."""
    first, rest = lines[0], lines[1:]
    spans = "".join(f'<tspan x="{x:g}" dy="{step:g}">{escape(line)}</tspan>' for line in rest)
    return f'<text {attributes} x="{x:g}" y="{y:g}">{escape(first)}{spans}</text>'


def _data_range(values: np.ndarray) -> tuple[float, float]:
    low, high = float(np.min(values)), float(np.max(values))
    if high - low < 1e-12 * max(1.0, abs(low), abs(high)):
        pad = max(0.5, abs(low) * 0.1)
        return low - pad, high + pad
    return low, high


class _Renderer:
    MARGIN_LEFT = 64
    MARGIN_RIGHT = 16
    MARGIN_TOP = 48
    MARGIN_BOTTOM = 48

    def __init__(self, plot: Plot, prefix: str = "") -> None:
        self.plot = plot
        self.prefix = prefix
        """Prefix of the element ids (several plots in one document need distinct ids)."""
        w = plot.width
        self.title_lines = wrap(plot.title, w - 16, 15, bold=True)
        self.subtitle_lines = wrap(plot.subtitle, w - 16, 12) if plot.subtitle else []
        # one line each: the title's baseline at 22, the subtitle's at 40, the plot from 48 or 64
        header = 22 + 18 * (len(self.title_lines) - 1)
        self.subtitle_y = header + 18
        if self.subtitle_lines:
            header = self.subtitle_y + 16 * (len(self.subtitle_lines) - 1)
        self.top = header + (24 if self.subtitle_lines else 26)
        grown = self.top - (self.MARGIN_TOP + (16 if plot.subtitle else 0))
        self.right = w - self.MARGIN_RIGHT
        self.bottom = plot.height + grown - self.MARGIN_BOTTOM
        self.left = self.MARGIN_LEFT
        self.x_range, self.y_range, self.transform = self._fit()
        # the widest y tick label and the rotated y label beside it must fit left of the frame
        needed = math.ceil(max(text_width(label, 12) for _, label in self._y_ticks()) + 30)
        if needed > self.left:
            self.left = needed
            self.x_range, self.y_range, self.transform = self._fit()
        text_room = w - (self.left + 32) - 8
        self.legend_lines = [
            wrap(s.label + (f" — {s.description}" if s.description else ""), text_room, 12)
            for s in plot.series
        ]
        rows = sum(18 + 15 * (len(lines) - 1) for lines in self.legend_lines)
        self.legend_height = rows + 12 if plot.series else 0
        self.footnote_lines = wrap(plot.footnote, w - self.left - 8, 10) if plot.footnote else []
        self.footnote_height = (
            18 + 13 * (len(self.footnote_lines) - 1) if self.footnote_lines else 0
        )
        self.total_height = plot.height + grown + self.legend_height + self.footnote_height

    def _x_ticks(self) -> list[tuple[float, str]]:
        target = max(3, (self.right - self.left) // 90)
        step = nice_step(self.x_range[1] - self.x_range[0], target)
        return [(v, tick_label(v, step)) for v in ticks(*self.x_range, target)]

    def _y_ticks(self) -> list[tuple[float, str]]:
        target = max(3, (self.bottom - self.top) // 60)
        step = nice_step(self.y_range[1] - self.y_range[0], target)
        return [(v, tick_label(v, step)) for v in ticks(*self.y_range, target)]

    def _fit(self) -> tuple[tuple[float, float], tuple[float, float], Transform]:
        series = self.plot.series
        if series:
            every = np.concatenate(
                [s.points for s in series if len(s.points)] or [np.zeros((1, 2))]
            )
        else:
            every = np.zeros((1, 2))
        x0, x1 = _data_range(every[:, 0])
        y0, y1 = _data_range(every[:, 1])
        padx, pady = 0.04 * (x1 - x0), 0.06 * (y1 - y0)
        x0, x1, y0, y1 = x0 - padx, x1 + padx, y0 - pady, y1 + pady
        width, height = self.right - self.left, self.bottom - self.top
        bx, by = width / (x1 - x0), height / (y1 - y0)
        if self.plot.equal_aspect:
            b = min(bx, by)
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            x0, x1 = cx - width / (2 * b), cx + width / (2 * b)
            y0, y1 = cy - height / (2 * b), cy + height / (2 * b)
            bx = by = b
        transform = Transform(self.left - bx * x0, bx, self.top + by * y1, by)
        return (x0, x1), (y0, y1), transform

    def render(self) -> str:
        plot = self.plot
        w, h = plot.width, self.total_height
        parts = [
            '<svg xmlns="http://www.w3.org/2000/svg" class="dcosh-plot" '
            f'viewBox="0 0 {w} {h}" width="{w}" height="{h}" role="img" '
            'aria-labelledby="plot-title plot-desc" '
            'font-family="DejaVu Sans, Helvetica, Arial, sans-serif" font-size="12">',
            f'<title id="plot-title">{escape(plot.title)}</title>',
            f'<desc id="plot-desc">{escape(self.description())}</desc>',
            f'<rect class="background" x="0" y="0" width="{w}" height="{h}" fill="#ffffff"/>',
            self.body(),
            "</svg>",
        ]
        return "\n".join(parts) + "\n"

    def body(self) -> str:
        """Everything inside the document: title, axes, data, legend, footnote."""
        plot = self.plot
        w, h = plot.width, self.total_height
        area = f"{self.prefix}plot-area"
        parts = [
            "<defs>",
            f'<clipPath id="{area}"><rect x="{self.left}" y="{self.top}" '
            f'width="{self.right - self.left}" height="{self.bottom - self.top}"/></clipPath>',
            "</defs>",
            _text(
                'class="title" text-anchor="middle" font-size="15" font-weight="bold"',
                self.title_lines,
                w / 2,
                22,
                18,
            ),
        ]
        if self.subtitle_lines:
            parts.append(
                _text(
                    'class="subtitle" text-anchor="middle" fill="#444444"',
                    self.subtitle_lines,
                    w / 2,
                    self.subtitle_y,
                    16,
                )
            )
        parts.append(self._axes())
        parts.append(f'<g class="data" clip-path="url(#{area})">')
        parts.extend(self._series(s) for s in plot.series)
        parts.append("</g>")
        parts.append(self._legend())
        if self.footnote_lines:
            parts.append(
                _text(
                    'class="footnote" font-size="10" fill="#555555"',
                    self.footnote_lines,
                    self.left,
                    h - 8 - 13 * (len(self.footnote_lines) - 1),
                    13,
                )
            )
        return "\n".join(parts)

    def description(self) -> str:
        """The plot in words (the document's ``desc``)."""
        names = ", ".join(s.label for s in self.plot.series)
        return f"{self.plot.title}. Axes {self.plot.x_label} and {self.plot.y_label}. {names}."

    def _axes(self) -> str:
        t = self.transform
        left, right, top, bottom = self.left, self.right, self.top, self.bottom
        out = [
            '<g class="axes" stroke="#333333" fill="#222222">',
            f'<rect class="frame" x="{left}" y="{top}" width="{right - left}" '
            f'height="{bottom - top}" fill="none" stroke="#999999"/>',
        ]
        for value, label in self._x_ticks():
            X = fmt(t.ax + t.bx * value)
            # a label at either end stays inside the picture (the tick line keeps its place)
            half = text_width(label, 12) / 2
            at = min(max(t.ax + t.bx * value, half + 2), self.plot.width - half - 2)
            out.append(
                f'<g class="tick x"><line x1="{X}" y1="{top}" x2="{X}" y2="{bottom}" '
                f'stroke="#eeeeee"/><line x1="{X}" y1="{bottom}" x2="{X}" y2="{bottom + 5}"/>'
                f'<text x="{fmt(at)}" y="{bottom + 18}" text-anchor="middle" stroke="none">'
                f"{label}</text></g>"
            )
        for value, label in self._y_ticks():
            Y = fmt(t.ay - t.by * value)
            out.append(
                f'<g class="tick y"><line x1="{left}" y1="{Y}" x2="{right}" y2="{Y}" '
                f'stroke="#eeeeee"/><line x1="{left - 5}" y1="{Y}" x2="{left}" y2="{Y}"/>'
                f'<text x="{left - 8}" y="{Y}" dy="0.35em" text-anchor="end" stroke="none">'
                f"{label}</text></g>"
            )
        # the coordinate axes themselves, where they cross the plot
        if self.y_range[0] <= 0 <= self.y_range[1]:
            Y = fmt(t.ay)
            out.append(
                f'<line class="axis x" x1="{left}" y1="{Y}" x2="{right}" y2="{Y}" '
                'stroke="#777777"/>'
            )
        if self.x_range[0] <= 0 <= self.x_range[1]:
            X = fmt(t.ax)
            out.append(
                f'<line class="axis y" x1="{X}" y1="{top}" x2="{X}" y2="{bottom}" '
                'stroke="#777777"/>'
            )
        out.append(
            f'<text class="label x" x="{(left + right) / 2:g}" y="{bottom + 36}" '
            f'text-anchor="middle" stroke="none">{escape(self.plot.x_label)}</text>'
        )
        out.append(
            f'<text class="label y" x="16" y="{(top + bottom) / 2:g}" text-anchor="middle" '
            f'stroke="none" transform="rotate(-90 16 {(top + bottom) / 2:g})">'
            f"{escape(self.plot.y_label)}</text>"
        )
        out.append("</g>")
        return "\n".join(out)

    def _series(self, s: Series) -> str:
        pixels = self.transform.apply(s.points)
        dash = ' stroke-dasharray="6 4"' if s.dashed else ""
        head = (
            f'<g class="series {s.kind}" data-name={quoteattr(s.name)} '
            f"data-label={quoteattr(s.label)}>"
        )
        if s.description:
            head += f"<title>{escape(s.label)}: {escape(s.description)}</title>"
        body: list[str] = [head]
        if s.kind == "area" and len(pixels) >= 3:
            body.append(
                f'<polygon points="{points_attribute(pixels)}" fill="{s.color}" '
                f'fill-opacity="0.18" stroke="{s.color}" stroke-opacity="0.5" '
                f'stroke-width="{s.width:g}"{dash}/>'
            )
        elif s.kind == "line" and len(pixels) >= 2:
            body.append(
                f'<polyline points="{points_attribute(pixels)}" fill="none" stroke="{s.color}" '
                f'stroke-width="{s.width:g}" stroke-linejoin="round"{dash}/>'
            )
        elif s.kind == "segments":
            pairs = pixels.reshape(-1, 2, 2)
            d = " ".join(
                f"M {fmt(a[0])} {fmt(a[1])} L {fmt(b[0])} {fmt(b[1])}" for a, b in pairs.tolist()
            )
            body.append(
                f'<path d="{d}" fill="none" stroke="{s.color}" stroke-width="{s.width:g}"{dash}/>'
            )
        draw_markers = s.kind == "points" or (s.kind == "line" and (s.markers or len(pixels) < 2))
        if draw_markers and len(pixels) <= MAX_MARKERS:
            r = 3.0 if s.kind == "points" else 2.2
            body.extend(
                f'<circle cx="{fmt(x)}" cy="{fmt(y)}" r="{r:g}" fill="{s.color}"/>'
                for x, y in pixels.tolist()
            )
        elif s.kind == "points":
            # too many to mark one by one: a polyline of zero-length dashes keeps them visible
            body.append(
                f'<polyline points="{points_attribute(pixels)}" fill="none" stroke="{s.color}" '
                'stroke-width="3" stroke-linecap="round" stroke-dasharray="0 1e9"/>'
            )
        body.append("</g>")
        return "".join(body)

    def _legend(self) -> str:
        if not self.plot.series:
            return ""
        row = self.bottom + self.MARGIN_BOTTOM + 14
        out = ['<g class="legend">']
        for s, lines in zip(self.plot.series, self.legend_lines, strict=True):
            x = self.left
            dash = ' stroke-dasharray="6 4"' if s.dashed else ""
            if s.kind == "points":
                swatch = f'<circle cx="{x + 12}" cy="{row - 4}" r="3" fill="{s.color}"/>'
            elif s.kind == "area":
                swatch = (
                    f'<rect x="{x}" y="{row - 10}" width="24" height="12" fill="{s.color}" '
                    'fill-opacity="0.18"/>'
                )
            else:
                swatch = (
                    f'<line x1="{x}" y1="{row - 4}" x2="{x + 24}" y2="{row - 4}" '
                    f'stroke="{s.color}" stroke-width="{max(s.width, 2):g}"{dash}/>'
                )
            label = _text('class="label"', lines, x + 32, row, 15)
            out.append(f'<g class="entry" data-name={quoteattr(s.name)}>{swatch}{label}</g>')
            row += 18 + 15 * (len(lines) - 1)
        out.append("</g>")
        return "\n".join(out)


def segments(starts: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """Interleave ``(m, 2)`` start and end points into the ``(2m, 2)`` layout of ``segments``."""
    out = np.empty((2 * len(starts), 2), dtype=np.float64)
    out[0::2], out[1::2] = starts, ends
    return out


def describe_parameters(parameters: dict[str, object], names: Sequence[str] | None = None) -> str:
    """``h = 1, d = 0.25, …`` for a subtitle (numbers to 6 significant digits)."""
    shown = []
    for key, value in parameters.items():
        if names is not None and key not in names:
            continue
        if isinstance(value, float):
            shown.append(f"{key} = {value:.6g}")
        elif value is not None:
            shown.append(f"{key} = {value}")
    return ", ".join(shown)
