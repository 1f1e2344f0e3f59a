"""The explorer in headless Chromium: load, change, refuse, download, share, 3D, phone."""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path
from urllib.parse import parse_qs, urlparse

import numpy as np
import pytest
from playwright.sync_api import Page, expect

from tests.e2e.conftest import Server, screenshot
from tests.svg_reading import (
    inverse_transform,
    parse,
    polyline_pixels,
    series,
    series_names,
)

pytestmark = pytest.mark.e2e

TIMEOUT = 20_000


def open_explorer(page: Page, server: Server, query: str = "") -> None:
    page.goto(f"{server.url}/{query}")
    expect(page.locator("body")).to_have_attribute("data-state", "ready", timeout=TIMEOUT)


def computed(page: Page) -> int:
    return int(page.locator("body").get_attribute("data-computed") or 0)


def wait_for_new_result(page: Page, before: int) -> None:
    page.wait_for_function(
        "(before) => Number(document.body.dataset.computed || 0) > before",
        arg=before,
        timeout=TIMEOUT,
    )


def plotted(page: Page) -> dict[str, np.ndarray]:
    """The explorer's SVG read back to data coordinates through its own tick labels."""
    text = page.evaluate(
        "new XMLSerializer().serializeToString(document.querySelector('#plot svg'))"
    )
    root = parse(text)
    inverse = inverse_transform(root)
    return {name: inverse(polyline_pixels(series(root, name))) for name in series_names(root)}


def resolution(page: Page) -> float:
    text = page.evaluate(
        "new XMLSerializer().serializeToString(document.querySelector('#plot svg'))"
    )
    # the page writes pixels with 2 decimals: ten times the server's rounding
    return 10 * inverse_transform(parse(text)).resolution


def api(page: Page, server: Server, path: str) -> dict:  # type: ignore[type-arg]
    response = page.request.get(f"{server.url}{path}")
    assert response.ok, path
    return response.json()  # type: ignore[no-any-return]


def test_the_page_loads_and_draws_the_default_curve_with_its_checks(
    page: Page, server: Server
) -> None:
    open_explorer(page, server)
    expect(page.locator("#discretization option[value='d4b']")).to_have_count(1)
    expect(page.locator("#param-d")).to_have_value("0.1")
    body = api(page, server, "/discretizations/d4b")
    drawn = plotted(page)
    # the smooth references are overlaid with the discretization's h (= 1 here)
    assert set(drawn) == {"p", *body["companions"], "smooth-catenary", "smooth-tractrix"}
    np.testing.assert_allclose(drawn["p"], body["vertices"], atol=resolution(page))
    x, y = drawn["smooth-catenary"].T
    np.testing.assert_allclose(y, np.cosh(x), atol=resolution(page))
    x, y = drawn["smooth-tractrix"].T  # the tractrix (t − tanh t, 1/cosh t) has y = 1/cosh t
    t = np.arccosh(np.clip(1 / np.maximum(y, 1e-12), 1, None)) * np.sign(x)
    np.testing.assert_allclose(x, t - np.tanh(t), atol=3 * resolution(page))
    rows = page.locator("#checks-table tbody tr")
    expect(rows).to_have_count(len(body["checks"]))
    expect(page.locator("#checks-table tbody .verdict-holds")).to_have_count(len(body["checks"]))
    expect(page.locator("#checks-summary")).to_contain_text(f"{len(body['checks'])} hold, 0 fail")
    erratum = page.locator("#checks-table tr[data-check='recursion-13-two-step'] td").nth(4)
    expect(erratum).to_contain_text("E3")
    # the figures of (D4b): 4 and 7, drawn
    expect(page.locator("#figure-list li")).to_have_count(2)
    page.locator("#figures").scroll_into_view_if_needed()
    for figure in ("figure-4", "figure-7"):
        expect(page.locator(f"#figure-list li[data-figure='{figure}']")).to_have_attribute(
            "data-state", "ready", timeout=TIMEOUT
        )
    screenshot(page, "explorer-default")


def test_changing_a_parameter_updates_the_plot_and_the_checks(page: Page, server: Server) -> None:
    open_explorer(page, server)
    before_residual = (
        page.locator("#checks-table tr[data-check='theorem-4-i'] td").nth(1).inner_text()
    )
    before = computed(page)
    page.fill("#param-d", "0.35")
    page.fill("#param-i_max", "4")
    page.press("#param-i_max", "Enter")
    wait_for_new_result(page, before)
    page.wait_for_function(
        "() => document.querySelector('#status').textContent.includes('15 vertices')",
        timeout=TIMEOUT,
    )
    body = api(page, server, "/discretizations/d4b?d=0.35&i_max=4")
    drawn = plotted(page)
    assert drawn["p"].shape == (15, 2)
    np.testing.assert_allclose(drawn["p"], body["vertices"], atol=resolution(page))
    np.testing.assert_allclose(
        drawn["tractrix"], body["companions"]["tractrix"]["vertices"], atol=resolution(page)
    )
    check = next(c for c in body["checks"] if c["id"] == "theorem-4-i")
    cell = page.locator("#checks-table tr[data-check='theorem-4-i'] td").nth(1)
    expect(cell).not_to_have_text(before_residual)
    assert float(cell.inner_text()) == pytest.approx(check["residual"], rel=1e-3)
    constant = page.locator("#constants dd").first
    expect(constant).to_contain_text("0.3")  # updated (it showed d/h = 0.1 before)
    # the same constant; its last bits may differ between two computations (numpy's summation
    # order depends on the alignment of the arrays), so compare numerically
    shown = float(constant.inner_text().split(" — ")[0])
    assert shown == pytest.approx(body["constants"]["d1"], rel=1e-12)
    screenshot(page, "explorer-changed")


def test_an_invalid_value_shows_the_api_error_next_to_its_field(page: Page, server: Server) -> None:
    open_explorer(page, server)
    page.fill("#param-d", "1.5")
    page.press("#param-d", "Enter")
    error = page.locator("#error-d")
    expect(error).to_be_visible(timeout=TIMEOUT)
    expect(error).to_contain_text("0 < d < h")
    expect(error).to_contain_text("1.5")
    expect(page.locator("#param-d")).to_have_attribute("aria-invalid", "true")
    expect(page.locator("#error-h")).to_be_hidden()
    expect(page.locator("#plot")).to_have_class("plot stale")
    expect(page.locator("#status")).to_contain_text("Not computed")
    screenshot(page, "explorer-error")
    # a value that is not a number: the validation error names h
    page.fill("#param-d", "0.1")
    page.fill("#param-h", "one")
    page.press("#param-h", "Enter")
    expect(page.locator("#error-h")).to_be_visible(timeout=TIMEOUT)
    expect(page.locator("#error-d")).to_be_hidden()
    # fixing it clears the error and draws again
    before = computed(page)
    page.fill("#param-h", "2")
    page.press("#param-h", "Enter")
    wait_for_new_result(page, before)
    expect(page.locator("#error-h")).to_be_hidden()
    expect(page.locator("#plot")).to_have_class("plot")


def test_downloads_hold_the_current_curve(page: Page, server: Server, tmp_path: Path) -> None:
    open_explorer(page, server, "?id=d4b&d=0.25&i_min=-3&i_max=3")
    body = api(page, server, "/discretizations/d4b?d=0.25&i_min=-3&i_max=3")
    files = {}
    for fmt in ("json", "csv", "svg"):
        with page.expect_download() as info:
            page.click(f"#downloads a[data-format='{fmt}']")
        download = info.value
        assert download.suggested_filename == f"d4b.{fmt}"
        target = tmp_path / download.suggested_filename
        download.save_as(target)
        files[fmt] = target.read_bytes()
    assert json.loads(files["json"])["vertices"] == body["vertices"]
    rows = list(csv.DictReader(io.StringIO(files["csv"].decode())))
    p_rows = [r for r in rows if r["curve"] == "p"]
    assert [[float(r["x"]), float(r["y"])] for r in p_rows] == body["vertices"]
    root = parse(files["svg"])
    inverse = inverse_transform(root)
    np.testing.assert_allclose(
        inverse(polyline_pixels(series(root, "p"))), body["vertices"], atol=inverse.resolution
    )


def test_the_address_shares_the_state(page: Page, server: Server, context) -> None:  # type: ignore[no-untyped-def]
    open_explorer(page, server)
    before = computed(page)
    page.fill("#param-h", "2")
    page.fill("#param-d", "0.5")
    page.select_option("#param-precision", "mp")
    page.fill("#param-digits", "40")
    page.press("#param-digits", "Enter")
    page.wait_for_function(
        "(before) => Number(document.body.dataset.computed || 0) > before && "
        "location.search.includes('digits=40')",
        arg=before,
        timeout=TIMEOUT,
    )
    shared = page.url
    query = parse_qs(urlparse(shared).query)
    assert query == {"id": ["d4b"], "h": ["2"], "d": ["0.5"], "precision": ["mp"], "digits": ["40"]}
    page.click("#copy-link")
    expect(page.locator("#copy-status")).not_to_be_empty()
    other = context.new_page()
    try:
        other.goto(shared)
        expect(other.locator("body")).to_have_attribute("data-state", "ready", timeout=TIMEOUT)
        expect(other.locator("#param-h")).to_have_value("2")
        expect(other.locator("#param-d")).to_have_value("0.5")
        expect(other.locator("#param-precision")).to_have_value("mp")
        expect(other.locator("#checks-summary")).to_contain_text("mp, 40 digits")
    finally:
        other.close()


def test_the_form_works_from_the_keyboard(page: Page, server: Server) -> None:
    open_explorer(page, server)
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.textContent") == "Skip to the parameters"
    for _ in range(12):
        if page.evaluate("document.activeElement.id") == "param-d":
            break
        page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.id") == "param-d"
    before = computed(page)
    page.keyboard.press("Control+A")
    page.keyboard.type("0.4")
    page.keyboard.press("Enter")
    wait_for_new_result(page, before)
    expect(page.locator("#param-d")).to_have_value("0.4")
    assert "d=0.4" in page.url


def test_the_page_fits_a_phone(page: Page, server: Server) -> None:
    page.set_viewport_size({"width": 390, "height": 844})
    open_explorer(page, server)
    width = page.evaluate("document.documentElement.scrollWidth")
    assert width <= 390, f"the page is {width}px wide on a 390px screen"
    box = page.locator("#plot svg").bounding_box()
    assert box is not None and 300 <= box["width"] <= 390
    font = page.evaluate(
        "parseFloat(getComputedStyle(document.querySelector('#param-d')).fontSize)"
    )
    assert font >= 14
    screenshot(page, "explorer-phone")


def test_the_3d_panel_follows_what_the_service_offers(page: Page, server: Server) -> None:
    open_explorer(page, server)
    spec = api(page, server, "/openapi.json")
    if any(path.startswith("/surfaces/") for path in spec["paths"]):
        expect(page.locator("#show-3d")).to_be_enabled()
        expect(page.locator("#surface option")).not_to_have_count(0)
    else:
        expect(page.locator("#surface-status")).to_contain_text("does not offer yet")
        expect(page.locator("#show-3d")).to_be_disabled()


BACKGROUND_SHARE = """() => {
  const source = document.querySelector('#view3d canvas');
  const canvas = document.createElement('canvas');
  canvas.width = source.width; canvas.height = source.height;
  const ctx = canvas.getContext('2d');
  ctx.drawImage(source, 0, 0);
  const data = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
  let other = 0;
  for (let k = 0; k < data.length; k += 4) {
    const r = data[k] - 0xf4, g = data[k + 1] - 0xf6, b = data[k + 2] - 0xf8;
    if (Math.abs(r) + Math.abs(g) + Math.abs(b) > 24) other++;
  }
  return [other / (data.length / 4), canvas.toDataURL()];
}"""


def test_the_3d_view_renders_the_surface_coloured_by_curvature(
    page: Page, surfaces_server: Server
) -> None:
    open_explorer(page, surfaces_server, "?id=d4b&d=0.2&i_min=-6&i_max=6")
    expect(page.locator("#show-3d")).to_be_enabled(timeout=TIMEOUT)
    expect(page.locator("#surface option[value='catenoid']")).to_have_count(1)
    page.select_option("#surface", "catenoid")
    page.click("#show-3d")
    view = page.locator("#view3d")
    expect(view).to_have_attribute("data-triangles", re.compile(r"^[1-9]"), timeout=TIMEOUT)
    assert int(view.get_attribute("data-triangles") or 0) > 0
    share, image = page.evaluate(BACKGROUND_SHARE)
    assert share > 0.05, f"only {share:.1%} of the canvas shows the surface"
    legend = page.locator("#colour-legend")
    expect(legend).to_contain_text("K from")
    screenshot(page, "view3d-catenoid-K")
    # rotate from the keyboard: the picture changes
    view.focus()
    _, image = page.evaluate(BACKGROUND_SHARE)
    frames = int(view.get_attribute("data-rendered") or 0)
    page.keyboard.press("ArrowLeft")
    page.wait_for_function(
        "(n) => Number(document.querySelector('#view3d').dataset.rendered) > n",
        arg=frames,
        timeout=TIMEOUT,
    )
    _, rotated = page.evaluate(BACKGROUND_SHARE)
    assert rotated != image
    # colour by H
    page.select_option("#colour-by", "_h")
    expect(legend).to_contain_text("H ", timeout=TIMEOUT)
    glb = page.locator("#surface-downloads a[data-format='glb']").get_attribute("href") or ""
    assert glb.startswith("/surfaces/catenoid?") and glb.endswith("format=glb")
    assert "d=0.2" in glb or "d=" not in glb  # the form's values go along where the API takes them
    screenshot(page, "view3d-catenoid-H")
