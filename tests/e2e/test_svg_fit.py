"""Every picture the service draws keeps its text inside its viewBox, measured by Chromium's own
text layout (getBBox): the figures, a curve per discretization and each refinement study."""

from __future__ import annotations

import pytest
from playwright.sync_api import Page

from tests.e2e.conftest import Server

pytestmark = pytest.mark.e2e

# Each text's box in the root's user space (the viewBox's), and those that leave the viewBox.
OUTSIDE = """() => {
  const svg = document.documentElement;
  const [vx, vy, vw, vh] = svg.getAttribute('viewBox').trim().split(/[\\s,]+/).map(Number);
  const texts = [...svg.querySelectorAll('text')];
  const outside = [];
  for (const text of texts) {
    const b = text.getBBox();
    const m = text.getCTM();
    const corners = [[b.x, b.y], [b.x + b.width, b.y], [b.x, b.y + b.height],
      [b.x + b.width, b.y + b.height]]
      .map(([x, y]) => [m.a * x + m.c * y + m.e, m.b * x + m.d * y + m.f]);
    const xs = corners.map((c) => c[0]), ys = corners.map((c) => c[1]);
    const box = [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
    const slack = 0.5;
    if (box[0] < vx - slack || box[1] < vy - slack
        || box[2] > vx + vw + slack || box[3] > vy + vh + slack) {
      outside.push({ text: text.textContent, box: box.map((v) => Math.round(v)) });
    }
  }
  return { count: texts.length, outside, width: svg.getBoundingClientRect().width, vw };
}"""


def pictures(page: Page, server: Server) -> list[str]:
    def get(path: str) -> list[dict]:  # type: ignore[type-arg]
        response = page.request.get(f"{server.url}{path}")
        assert response.ok, path
        return response.json()  # type: ignore[no-any-return]

    urls = [f["url"] for f in get("/figures")]
    urls += [f"/discretizations/{d['id']}?format=svg" for d in get("/discretizations")]
    # long subtitles: many digits, mp arithmetic, a figure with every parameter set
    urls += [
        "/discretizations/d4b?format=svg&precision=mp&digits=40&h=1.234567891234&d=0.123456789123"
        "&beta0=1.3&i_min=-3&i_max=4",
        "/discretizations/d2a-hex?format=svg&a=0.912345678&b=2.712345678&lambda=0.312345678",
        "/discretizations/d1?format=svg&c=0.000123456789&delta=12345.6789&y0=-98765.4321",
    ]
    studies = page.request.get(f"{server.url}/convergence")
    if studies.ok:
        urls += [f"/convergence/{s['id']}?format=svg" for s in studies.json()]
    return urls


def test_no_text_leaves_the_viewbox_of_any_picture(page: Page, server: Server) -> None:
    page.set_viewport_size({"width": 2400, "height": 1600})
    urls = pictures(page, server)
    assert sum(u.startswith("/figures/") for u in urls) >= 7
    clipped = {}
    for url in urls:
        response = page.goto(f"{server.url}{url}")
        assert response is not None and response.ok, url
        result = page.evaluate(OUTSIDE)
        assert result["count"] > 5, url  # a title, ticks and a legend at least
        assert result["width"] == pytest.approx(result["vw"]), url  # drawn 1:1
        if result["outside"]:
            clipped[url] = result["outside"]
    assert not clipped, clipped
