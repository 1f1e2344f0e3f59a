"""Accessibility of the explorer: an axe-core audit (vendored from npm, loaded by this test only)
with no serious or critical violation in each state of the page, and every control reachable
and usable from the keyboard."""

from __future__ import annotations

import pytest
from playwright.sync_api import Page, expect

from tests.e2e.conftest import Server
from tests.e2e.test_explorer import TIMEOUT, computed, open_explorer, wait_for_new_result

pytestmark = pytest.mark.e2e

AUDIT = """async () => {
  const result = await axe.run(document, { resultTypes: ['violations'] });
  return result.violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => ({ id: v.id, impact: v.impact, help: v.help,
                   nodes: v.nodes.slice(0, 5).map((n) => n.target.join(' ')) }));
}"""


def audit(page: Page) -> list[dict]:  # type: ignore[type-arg]
    if not page.evaluate("typeof axe !== 'undefined'"):
        page.add_script_tag(url="/static/vendor/axe-core/axe.min.js")
    return page.evaluate(AUDIT)  # type: ignore[no-any-return]


@pytest.mark.parametrize("width", [1280, 390])
def test_axe_finds_no_serious_violation(page: Page, server: Server, width: int) -> None:
    page.set_viewport_size({"width": width, "height": 900})
    open_explorer(page, server)
    page.locator("#figures").scroll_into_view_if_needed()
    assert audit(page) == []
    # the refused state, with its messages
    page.fill("#param-d", "2")
    page.press("#param-d", "Enter")
    expect(page.locator("#error-d")).to_be_visible(timeout=TIMEOUT)
    assert audit(page) == []


def focusable(page: Page) -> list[str]:
    """The ids (or tag and text) of the elements Tab visits, in order, once around the page."""
    seen: list[str] = []
    page.evaluate("document.activeElement && document.activeElement.blur()")
    for _ in range(400):
        page.keyboard.press("Tab")
        here = page.evaluate(
            "(() => { const e = document.activeElement; if (e === document.body) return '';"
            " return e.id || e.tagName + ':' + e.textContent.trim(); })()"
        )
        if not here or (seen and here == seen[0]):
            break
        seen.append(here)
    return seen


def test_every_control_is_reached_by_tab(page: Page, server: Server) -> None:
    open_explorer(page, server)
    reached = set(focusable(page))
    controls = page.evaluate(
        "[...document.querySelectorAll('input, select, textarea, button, a[href], [tabindex]')]"
        ".filter((e) => e.checkVisibility() && !e.disabled && e.tabIndex >= 0)"
        ".map((e) => e.id || e.tagName + ':' + e.textContent.trim())"
    )
    missing = [c for c in controls if c not in reached]
    assert not missing, missing


def test_layers_and_defaults_work_from_the_keyboard(page: Page, server: Server) -> None:
    open_explorer(page, server, "?id=d4b&d=0.3")
    page.focus("#layer-tractrix")
    page.keyboard.press("Space")
    expect(page.locator("#plot svg g.series[data-name='tractrix']")).to_have_count(0)
    expect(page.locator("#layer-tractrix")).to_be_focused()
    page.keyboard.press("Space")
    expect(page.locator("#plot svg g.series[data-name='tractrix']")).to_have_count(1)
    before = computed(page)
    page.focus("#defaults")
    page.keyboard.press("Enter")
    wait_for_new_result(page, before)
    expect(page.locator("#param-d")).to_have_value("0.1")
    page.focus("#discretization")
    before = computed(page)
    page.keyboard.press("ArrowUp")  # d4b is the last entry
    wait_for_new_result(page, before)
    assert page.evaluate("document.querySelector('#discretization').value") != "d4b"
