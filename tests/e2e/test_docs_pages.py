"""/docs and /redoc render in Chromium with self-hosted scripts under their CSP (no CDN)."""

from __future__ import annotations

from playwright.sync_api import BrowserContext, Page

from tests.e2e.conftest import Server, screenshot


def test_swagger_ui_lists_the_operations(server: Server, page: Page) -> None:
    requests: list[str] = []
    page.on("request", lambda request: requests.append(request.url))
    page.goto(f"{server.url}/docs")
    page.wait_for_selector(".opblock-summary-path", timeout=30_000)
    paths = page.locator(".opblock-summary-path").all_inner_texts()
    assert any("/discretizations/d4b" in p for p in paths)
    assert all(url.startswith(server.url) for url in requests), requests
    screenshot(page, "docs-swagger-ui")


def test_redoc_renders_the_description(server: Server, context: BrowserContext) -> None:
    # not the `page` fixture: ReDoc's side menu shows the Redocly logo from cdn.redoc.ly, which
    # the page's CSP blocks (nothing is loaded from outside); that is the one error allowed here
    page = context.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(f"{server.url}/redoc")
    page.wait_for_selector("h1:has-text('Discrete hyperbolic cosine service')", timeout=30_000)
    assert "List the discretizations" in page.content()
    screenshot(page, "docs-redoc")
    page.close()
    assert [e for e in errors if "cdn.redoc.ly/redoc/logo" not in e] == [], errors
