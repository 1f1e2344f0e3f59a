"""Live parameters: a slider beside each number of the paper; the curve and the verdicts follow
it while it moves (from the keyboard and dragged with a pointer)."""

from __future__ import annotations

import numpy as np
import pytest
from playwright.sync_api import Page, expect

from tests.e2e.conftest import Server, screenshot
from tests.e2e.test_explorer import (
    TIMEOUT,
    api,
    computed,
    open_explorer,
    plotted,
    resolution,
    wait_for_new_result,
)

pytestmark = pytest.mark.e2e

# the answer on the page is for d = value, and the fields still say so
SETTLED = (
    "(value) => new URLSearchParams(document.body.dataset.query).get('d') === value"
    " && document.body.dataset.result === 'current'"
)


def assert_shows(page: Page, server: Server, query: str) -> None:
    """The plot and every verdict and residual on the page are those of GET ...?query."""
    body = api(page, server, f"/discretizations/d4b?{query}")
    np.testing.assert_allclose(plotted(page)["p"], body["vertices"], atol=resolution(page))
    rows = page.locator("#checks-table tbody tr")
    expect(rows).to_have_count(len(body["checks"]))
    for check in body["checks"]:
        cells = page.locator(f"#checks-table tr[data-check='{check['id']}'] td")
        word = {True: "holds", False: "fails", None: "n/a"}[check["holds"]]
        expect(cells.nth(3)).to_contain_text(word)
        if isinstance(check["residual"], float) and check["residual"] != 0:
            shown = float(cells.nth(1).inner_text())
            assert shown == pytest.approx(check["residual"], rel=1e-3), check["id"]


def test_a_slider_from_the_keyboard_updates_the_curve_and_the_verdicts(
    page: Page, server: Server
) -> None:
    open_explorer(page, server)
    slider = page.locator("#slider-d")
    expect(slider).to_have_value("0.1")
    slider.focus()
    for _ in range(4):
        page.keyboard.press("ArrowRight")
    expect(page.locator("#param-d")).to_have_value("0.12")
    page.wait_for_function(SETTLED, arg="0.12", timeout=TIMEOUT)
    assert_shows(page, server, "d=0.12")
    # the number field moves the slider too
    page.fill("#param-d", "0.3")
    expect(slider).to_have_value("0.3")


def test_dragging_a_slider_computes_while_it_moves(page: Page, server: Server) -> None:
    open_explorer(page, server)
    box = page.locator("#slider-d").bounding_box()
    assert box is not None
    y = box["y"] + box["height"] / 2
    start = box["x"] + box["width"] * 0.1  # about d = 0.1, where the thumb is
    page.mouse.move(start, y)
    page.mouse.down()
    for fraction in (0.25, 0.4):
        before = computed(page)
        page.mouse.move(box["x"] + box["width"] * fraction, y, steps=5)
        wait_for_new_result(page, before)  # a new curve while the button is still held
    page.mouse.up()
    value = page.locator("#param-d").input_value()
    assert 0.2 < float(value) < 0.5, value
    page.wait_for_function(SETTLED, arg=value, timeout=TIMEOUT)
    assert_shows(page, server, f"d={value}")
    screenshot(page, "explorer-slider")


def test_a_slider_into_a_refused_value_clears_the_result(page: Page, server: Server) -> None:
    open_explorer(page, server, "?id=d4b&h=0.5")
    slider = page.locator("#slider-d")
    slider.focus()
    page.keyboard.press("End")  # d = 1 > h = 0.5: refused
    expect(page.locator("#error-d")).to_contain_text("0 < d < h", timeout=TIMEOUT)
    expect(page.locator("body")).to_have_attribute("data-result", "none")
    expect(page.locator("#checks-table tbody tr")).to_have_count(0)
