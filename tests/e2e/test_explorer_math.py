"""Typeset mathematics: KaTeX (vendored from npm) renders the TeX that GET /theorems and GET
/discretizations serve, every claim and both sides of every erratum, without an error; the
explorer shows them in the checks table and the parameter help."""

from __future__ import annotations

import pytest
from playwright.sync_api import Page, expect

from app.geometry.statement_tex import CLAIM_TEX, CONSTANT_TEX, ERRATUM_TEX, PARAMETER_TEX
from tests.e2e.conftest import SCREENSHOTS, Server, screenshot
from tests.e2e.test_explorer import TIMEOUT, api, open_explorer

pytestmark = pytest.mark.e2e

RENDER_ALL = """async (sources) => {
  const katex = window.katex;  // loaded by the page
  const failures = [];
  for (const [key, tex] of sources) {
    try {
      const html = katex.renderToString(tex, { throwOnError: true, strict: 'error' });
      if (!html.includes('katex-mathml')) failures.push([key, 'no MathML']);
    } catch (error) {
      failures.push([key, String(error.message)]);
    }
  }
  return failures;
}"""


def test_katex_renders_every_claim_erratum_and_domain_without_error(
    page: Page, server: Server
) -> None:
    open_explorer(page, server)
    served = api(page, server, "/theorems")
    sources = [(f"claim {s['id']}", s["claim_tex"]) for s in served]
    assert len(sources) == len(CLAIM_TEX)
    for identifier, (printed, corrected) in ERRATUM_TEX.items():
        sources += [(f"{identifier} printed", printed), (f"{identifier} corrected", corrected)]
    sources += [(f"domain {d}", tex) for d, tex in PARAMETER_TEX.items()]
    sources += [(f"constant {c}", tex) for c, tex in CONSTANT_TEX.items()]
    assert page.evaluate(RENDER_ALL, sources) == []


def test_the_checks_and_the_help_are_typeset(page: Page, server: Server) -> None:
    open_explorer(page, server)
    expect(page.locator("body")).to_have_attribute("data-tex", "ready", timeout=TIMEOUT)
    body = api(page, server, "/discretizations/d4b")
    expect(page.locator("#checks-table .claim-tex .katex")).to_have_count(len(body["checks"]))
    expect(page.locator("[data-tex-error]")).to_have_count(0)
    # E3 printed and corrected side by side, each typeset from the served TeX
    row = page.locator("#checks-table tr[data-check='recursion-13-two-step']")
    expect(row.locator(".erratum-sides .printed .katex")).to_have_count(1)
    expect(row.locator(".erratum-sides .corrected .katex")).to_have_count(1)
    printed, corrected = ERRATUM_TEX["E3"]
    assert row.locator(".printed .math").get_attribute("data-tex") == printed
    assert row.locator(".corrected .math").get_attribute("data-tex") == corrected
    # the MathML a screen reader reads carries the formula, not only glyph boxes
    mathml = row.locator(".corrected annotation[encoding='application/x-tex']").text_content() or ""
    assert mathml.strip() == corrected
    # each constant with its defining relation
    expect(page.locator("#constants dt .katex")).to_have_count(len(body["constants"]))
    # the parameter help: 0 < d < h typeset
    expect(page.locator("#help-d .katex")).to_have_count(1)
    assert page.locator("#help-d .math").get_attribute("data-tex") == PARAMETER_TEX["0 < d < h"]
    screenshot(page, "explorer-typeset")
    page.locator("#checks").screenshot(path=str(SCREENSHOTS / "explorer-typeset-checks.png"))
