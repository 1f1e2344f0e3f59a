"""The SVG plot writer: ticks, equal scales, escaping, self-containment, markers."""

from __future__ import annotations

import re

import numpy as np
import pytest

from app.rendering.svg import MAX_MARKERS, Panels, Plot, Series, segments
from app.rendering.svg_scale import nice_step, parse_tick_label, tick_label, ticks
from app.rendering.text_width import text_width, wrap
from tests.svg_reading import (
    circle_pixels,
    inverse_transform,
    panel,
    panel_names,
    parse,
    polygon_pixels,
    polyline_pixels,
    segment_pixels,
    series,
    series_names,
)


@pytest.mark.parametrize(
    ("span", "target", "step"),
    [(10.0, 5, 2.0), (1.0, 4, 0.5), (0.03, 3, 0.01), (7300.0, 8, 1000.0), (1.0, 10, 0.1)],
)
def test_nice_steps_are_one_two_or_five_times_a_power_of_ten(
    span: float, target: int, step: float
) -> None:
    assert nice_step(span, target) == pytest.approx(step)


def test_ticks_cover_the_range_at_the_step_and_labels_round_trip() -> None:
    values = ticks(-0.73, 2.41, 7)  # raw step 0.45 -> 0.5
    assert values[0] >= -0.73 and values[-1] <= 2.41
    assert np.allclose(np.diff(values), 0.5)
    labels = [tick_label(v, 0.5) for v in values]
    assert labels == ["\u22120.5", "0.0", "0.5", "1.0", "1.5", "2.0"]
    assert [parse_tick_label(t) for t in labels] == pytest.approx(values)


def circle(n: int) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n)
    return np.stack([3 + 2 * np.cos(t), -1 + 2 * np.sin(t)], axis=1)


def test_drawn_points_map_back_to_the_data_through_the_ticks() -> None:
    plot = Plot(title="circle")
    data = circle(50)
    plot.add(Series("c", "circle", data))
    root = parse(plot.render())
    inverse = inverse_transform(root)
    assert inverse.bx == pytest.approx(inverse.by, rel=1e-5)  # equal aspect
    drawn = inverse(polyline_pixels(series(root, "c")))
    np.testing.assert_allclose(drawn, data, atol=inverse.resolution)
    np.testing.assert_allclose(
        inverse(circle_pixels(series(root, "c"))), data, atol=inverse.resolution
    )
    # the comparison is sharp enough to see a shift of a hundredth
    assert not np.allclose(drawn, data + np.array([0.01, 0]), atol=inverse.resolution)


def test_unequal_aspect_fills_the_plot_on_both_axes() -> None:
    plot = Plot(title="wide", equal_aspect=False)
    plot.add(Series("w", "wide", np.array([[0.0, 0.0], [1000.0, 1.0]])))
    inverse = inverse_transform(parse(plot.render()))
    assert inverse.by / inverse.bx > 100


def test_segments_are_drawn_as_separate_pieces() -> None:
    starts = np.array([[0.0, 0.0], [1.0, 0.0]])
    ends = np.array([[0.0, 1.0], [2.0, 1.0]])
    plot = Plot(title="sticks")
    plot.add(Series("s", "sticks", segments(starts, ends), kind="segments"))
    root = parse(plot.render())
    inverse = inverse_transform(root)
    pairs = segment_pixels(series(root, "s"))
    assert pairs.shape == (2, 2, 2)
    np.testing.assert_allclose(inverse(pairs[:, 0]), starts, atol=inverse.resolution)
    np.testing.assert_allclose(inverse(pairs[:, 1]), ends, atol=inverse.resolution)


def test_the_document_is_self_contained_scalable_and_escaped() -> None:
    plot = Plot(title='a < b & "c"', subtitle="<script>alert(1)</script>", footnote="x & y")
    plot.add(Series("p<1>", "label & <tag>", circle(5), description="d'escription"))
    text = plot.render()
    root = parse(text)  # well-formed despite the markup characters
    assert re.fullmatch(r"0 0 \d+ \d+", root.get("viewBox") or "")
    assert root.findtext("{http://www.w3.org/2000/svg}title") == 'a < b & "c"'
    assert "<script" not in text and "http://" not in text.replace("http://www.w3.org/2000/svg", "")
    assert "href" not in text and "@import" not in text and "@font-face" not in text
    assert re.findall(r"url\(([^)]*)\)", text) == ["#plot-area"]
    assert series_names(root) == ["p<1>"]


def test_long_series_are_drawn_without_markers() -> None:
    plot = Plot(title="long")
    plot.add(Series("long", "long", circle(MAX_MARKERS + 1)))
    plot.add(Series("short", "short", circle(MAX_MARKERS)))
    root = parse(plot.render())
    assert len(circle_pixels(series(root, "long"))) == 0
    assert len(circle_pixels(series(root, "short"))) == MAX_MARKERS
    assert len(polyline_pixels(series(root, "long"))) == MAX_MARKERS + 1


def test_non_finite_points_are_refused() -> None:
    plot = Plot(title="bad")
    with pytest.raises(ValueError, match="non-finite"):
        plot.add(Series("bad", "bad", np.array([[0.0, np.inf]])))


def test_a_single_point_still_gets_axes() -> None:
    plot = Plot(title="one")
    plot.add(Series("one", "one", np.array([[2.0, 2.0]])))
    root = parse(plot.render())
    inverse = inverse_transform(root)
    np.testing.assert_allclose(
        inverse(circle_pixels(series(root, "one"))), [[2.0, 2.0]], atol=inverse.resolution
    )


def test_panels_keep_their_own_axes_and_distinct_ids() -> None:
    small, large = circle(30), 100 * circle(30) + 7
    figure = Panels(title="two <parts>", subtitle="s & t", footnote="data")
    for name, data in (("left", small), ("right", large)):
        plot = Plot(title=name, width=400, height=300)
        plot.add(Series("c", "circle", data))
        plot.add(Series("band", "band", data[:-1], kind="area"))
        figure.add(name, plot)
    text = figure.render()
    root = parse(text)
    assert panel_names(root) == ["left", "right"]
    assert root.get("viewBox") == f"0 0 800 {root.get('height')}"
    assert sorted(re.findall(r'id="([^"]+)"', text)) == sorted(
        ["plot-title", "plot-desc", "left-plot-area", "right-plot-area"]
    )
    for name, data in (("left", small), ("right", large)):
        part = panel(root, name)
        inverse = inverse_transform(part)
        np.testing.assert_allclose(
            inverse(polyline_pixels(series(part, "c"))), data, atol=inverse.resolution
        )
        np.testing.assert_allclose(
            inverse(polygon_pixels(series(part, "band"))), data[:-1], atol=inverse.resolution
        )
    # the panels have different scales: reading one with the other's ticks is wrong
    wrong = inverse_transform(panel(root, "left"))
    assert not np.allclose(wrong(polyline_pixels(series(panel(root, "right"), "c"))), large, atol=1)


def test_long_text_is_wrapped_inside_the_picture_and_the_picture_grows() -> None:
    long = "GET /discretizations/d4b?" + "&".join(f"name{k}={k / 7:.12f}" for k in range(12))
    short = Plot(title="t", subtitle="s", footnote="f")
    short.add(Series("p", "p", circle(8), description="short"))
    plot = Plot(title="A title " * 12, subtitle=long, footnote=long)
    plot.add(Series("p", "p", circle(8), description="a legend entry " * 12))
    root = parse(plot.render())
    width = float(root.get("width") or 0)
    assert int(root.get("height") or 0) > int(parse(short.render()).get("height") or 0)
    svg = "{http://www.w3.org/2000/svg}"
    for text in root.iter(f"{svg}text"):
        lines = [text.text or ""] + [span.text or "" for span in text.iter(f"{svg}tspan")]
        bold = text.get("font-weight") == "bold"
        size = float(text.get("font-size") or 12)
        x = float(text.get("x") or 0)
        for line in lines:
            w = text_width(line, size, bold)
            anchor = text.get("text-anchor")
            left = x - w / 2 if anchor == "middle" else x - w if anchor == "end" else x
            assert left >= 0 and left + w <= width, (line, left, w)
    # nothing is lost by wrapping
    subtitle = next(t for t in root.iter(f"{svg}text") if t.get("class") == "subtitle")
    assert "".join(subtitle.itertext()).replace(" ", "") == long.replace(" ", "")


def test_wrap_keeps_every_word_and_fits_the_width() -> None:
    text = "the discrete hyperbolic cosine p_i and its companions " * 5
    lines = wrap(text, 150, 12)
    assert len(lines) > 3
    assert " ".join(lines).split() == text.split()
    assert all(text_width(line, 12) <= 150 for line in lines)
    assert wrap("", 100, 12) == [""]
