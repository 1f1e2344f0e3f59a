"""What the explorer shows always belongs to the parameters it shows: a refused value leaves
no checks, constants, downloads or figures of the previous answer behind."""

from __future__ import annotations

import pytest
from playwright.sync_api import Page, expect

from tests.e2e.conftest import Server, screenshot
from tests.e2e.test_explorer import TIMEOUT, api, computed, open_explorer, wait_for_new_result

pytestmark = pytest.mark.e2e


def test_a_refused_value_leaves_nothing_of_the_previous_answer(page: Page, server: Server) -> None:
    open_explorer(page, server)
    body = api(page, server, "/discretizations/d4b")
    rows = page.locator("#checks-table tbody tr")
    expect(rows).to_have_count(len(body["checks"]))
    expect(page.locator("#constants dd")).to_have_count(len(body["constants"]))
    expect(page.locator("#downloads a")).to_have_count(3)
    expect(page.locator("#figure-list li")).to_have_count(2)
    # d = 2 > h = 1: (D4b) needs 0 < d < h
    page.fill("#param-d", "2")
    page.press("#param-d", "Enter")
    expect(page.locator("#error-d")).to_contain_text("0 < d < h", timeout=TIMEOUT)
    expect(page.locator("#status")).to_contain_text("Not computed")
    expect(page.locator("body")).to_have_attribute("data-result", "none")
    expect(page.locator("#plot")).to_have_class("plot stale")
    expect(rows).to_have_count(0)
    expect(page.locator("#checks-summary")).to_contain_text("No checks")
    expect(page.locator("#checks-summary")).not_to_contain_text("hold")
    expect(page.locator("#constants dd")).to_have_count(0)
    expect(page.locator("#downloads a")).to_have_count(0)
    expect(page.locator("#downloads")).to_contain_text("No downloads")
    expect(page.locator("#figure-list li")).to_have_count(0)
    expect(page.locator("#figures-note")).to_contain_text("No figures")
    for section in ("checks", "share", "figures"):
        expect(page.locator(f"#{section}")).not_to_have_attribute("aria-busy", "true")
    screenshot(page, "explorer-refused-d2")
    # a valid value brings everything back, for the new parameters
    before = computed(page)
    page.fill("#param-d", "0.3")
    page.press("#param-d", "Enter")
    wait_for_new_result(page, before)
    expect(page.locator("body")).to_have_attribute("data-result", "current")
    fresh = api(page, server, "/discretizations/d4b?d=0.3")
    expect(rows).to_have_count(len(fresh["checks"]))
    expect(page.locator("#plot")).to_have_class("plot")
    href = page.locator("#downloads a[data-format='json']").get_attribute("href") or ""
    assert "d=0.3" in href
    expect(page.locator("#figure-list li")).to_have_count(2)
    for figure in ("figure-4", "figure-7"):
        src = page.locator(f"#figure-list li[data-figure='{figure}'] img").get_attribute("src")
        assert src is not None and "d=0.3" in src, src


def test_the_page_loads_the_catalogs_it_shows_and_never_the_openapi_document(
    page: Page, server: Server
) -> None:
    requested: list[str] = []
    page.on("request", lambda request: requested.append(request.url))
    open_explorer(page, server)
    expect(page.locator("#surface option")).not_to_have_count(0)
    expect(page.locator("#overlay-status")).to_contain_text("Drawn with h =")
    paths = {url.removeprefix(server.url).split("?")[0] for url in requested}
    assert "/openapi.json" not in paths
    assert {"/discretizations", "/figures", "/surfaces", "/discretizations/d4b"} <= paths
    assert {"/smooth/catenary", "/smooth/tractrix"} <= paths


def test_on_a_phone_the_plot_comes_first_and_the_figures_are_drawn_unscrolled(
    page: Page, server: Server
) -> None:
    page.set_viewport_size({"width": 390, "height": 844})
    open_explorer(page, server)
    plot = page.locator("#plot svg").bounding_box()
    form = page.locator("#form").bounding_box()
    assert plot is not None and form is not None
    assert plot["y"] < form["y"]
    assert plot["y"] + plot["height"] <= 844, plot  # the whole plot on the first screen
    # every figure is loaded without scrolling to it (no lazy, blank frames)
    page.wait_for_function(
        "() => { const images = [...document.querySelectorAll('#figure-list img')];"
        " return images.length > 0 && images.every((i) => i.complete && i.naturalWidth > 0); }",
        timeout=TIMEOUT,
    )
    assert page.evaluate("window.scrollY") == 0
    screenshot(page, "explorer-phone-plot-first")
