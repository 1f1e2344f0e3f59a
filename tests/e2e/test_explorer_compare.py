"""Compare mode: (D1) and (D3) drawn over Wunderlich's (D4b) polygon with the constants the
polygon's own checks fit (Theorem 4 (i), (ii)), and they coincide with it."""

from __future__ import annotations

import numpy as np
import pytest
from playwright.sync_api import Page, expect

from tests.e2e.conftest import Server, screenshot
from tests.e2e.test_explorer import TIMEOUT, api, open_explorer, plotted, resolution

pytestmark = pytest.mark.e2e


def test_d1_and_d3_with_matched_constants_redraw_the_d4b_polygon(
    page: Page, server: Server
) -> None:
    open_explorer(page, server, "?id=d4b&d=0.2&i_min=-6&i_max=6")
    body = api(page, server, "/discretizations/d4b?d=0.2&i_min=-6&i_max=6")
    expect(page.locator("#compare input")).to_have_count(6)  # every other discretization
    page.check("#compare-d1")
    expect(page.locator("#compare-status")).to_contain_text("d1 (", timeout=TIMEOUT)
    page.check("#compare-d3")
    status = page.locator("#compare-status")
    expect(status).to_contain_text("d3 (", timeout=TIMEOUT)
    expect(status).to_contain_text("constants.d1")
    expect(status).to_contain_text("constants.d3")
    drawn = plotted(page)
    p = np.array(body["vertices"], dtype=float)
    # (D1) from p_0, p_1 and c = constants.d1 is the same polygon (Theorem 4 (i))
    d1 = api(
        page,
        server,
        f"/discretizations/d1?c={body['constants']['d1']}&delta={p[7, 0] - p[6, 0]}"
        f"&y0={p[6, 1]}&y1={p[7, 1]}&i_min=-6&i_max=6",
    )
    shifted = np.array(d1["vertices"], dtype=float) + np.array([p[6, 0], 0.0])
    np.testing.assert_allclose(shifted, p, atol=1e-9)
    np.testing.assert_allclose(drawn["compare-d1"], p, atol=resolution(page))
    np.testing.assert_allclose(drawn["compare-d3"], p, atol=resolution(page))
    assert status.inner_text().count("the same polygon") == 2
    screenshot(page, "explorer-compare")
    # a discretization without matched constants is drawn with its defaults, and said so
    page.uncheck("#compare-d1")
    page.check("#compare-d2a-quad")
    expect(status).to_contain_text("d2a-quad (its own defaults)", timeout=TIMEOUT)
    drawn = plotted(page)
    assert "compare-d1" not in drawn and "compare-d2a-quad" in drawn
