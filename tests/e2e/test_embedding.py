"""Another site embeds the service: the README's snippet in Chromium, across origins (CORS)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from fastapi import FastAPI
from fastapi.responses import HTMLResponse
from fastapi.testclient import TestClient
from playwright.sync_api import Page, expect

from app.main import create_app
from app.settings import Settings
from tests.e2e.conftest import Server, screenshot

pytestmark = pytest.mark.e2e

SNIPPET = (Path(__file__).parent / "embed.html").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def other_site(server: Server) -> Iterator[Server]:
    """A page on another origin (another port) holding the snippet, pointed at the service."""
    site = FastAPI()
    page = SNIPPET.replace("http://127.0.0.1:8000", server.url)

    @site.get("/")
    def index() -> HTMLResponse:
        return HTMLResponse(page)

    with Server(site) as running:
        yield running


def test_the_readme_snippet_draws_the_curve_from_another_origin(
    page: Page, server: Server, other_site: Server
) -> None:
    assert other_site.url != server.url
    page.goto(other_site.url)
    line = page.locator("#curve polyline")
    expect(line).to_have_count(1, timeout=20_000)
    points = np.array(
        [p.split(",") for p in (line.get_attribute("points") or "").split()], dtype=float
    )
    body = page.request.get(f"{server.url}/discretizations/d4b").json()
    np.testing.assert_array_equal(points * [1, -1], body["vertices"])
    expect(page.locator("body")).to_contain_text(f"{len(body['checks'])} of {len(body['checks'])}")
    screenshot(page, "embedding-snippet")


def test_cors_origins_come_from_the_settings() -> None:
    client = TestClient(create_app(Settings(cors_origins=["https://teacher.example"])))
    allowed = client.get("/discretizations/d4b", headers={"Origin": "https://teacher.example"})
    assert allowed.headers["access-control-allow-origin"] == "https://teacher.example"
    assert "etag" in allowed.headers["access-control-expose-headers"].lower()
    other = client.get("/discretizations/d4b", headers={"Origin": "https://elsewhere.example"})
    assert "access-control-allow-origin" not in other.headers
    preflight = client.options(
        "/discretizations/d4b",
        headers={
            "Origin": "https://teacher.example",
            "Access-Control-Request-Method": "POST",
            "Access-Control-Request-Headers": "Content-Type",
        },
    )
    assert preflight.status_code == 200
    assert "POST" in preflight.headers["access-control-allow-methods"]
