"""Browser-test fixtures: the app under uvicorn on a free port, and Debian's Chromium driven by
Playwright (system executable, fresh profile; Playwright never downloads a browser here)."""

from __future__ import annotations

import os
import socket
import tempfile
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
import uvicorn
from fastapi import FastAPI
from playwright.sync_api import BrowserContext, Page, Playwright, sync_playwright

from app.main import create_app
from app.settings import Settings
from tests.e2e.standin_surfaces import install_standin

ROOT = Path(__file__).resolve().parents[2]
SCREENSHOTS = ROOT / "test-output" / "screenshots"
CHROMIUM = os.environ.get("DCOSH_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-dev-shm-usage",  # a small /dev/shm (containers) must not crash the renderer
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Server:
    """uvicorn serving ``app`` on 127.0.0.1 in a background thread."""

    def __init__(self, app: FastAPI) -> None:
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        config = uvicorn.Config(app, host="127.0.0.1", port=self.port, log_level="warning")
        self.server = uvicorn.Server(config)
        self.thread = threading.Thread(target=self.server.run, daemon=True)

    def __enter__(self) -> Server:
        self.thread.start()
        deadline = time.monotonic() + 30
        while not self.server.started:
            assert self.thread.is_alive(), "uvicorn stopped while starting"
            assert time.monotonic() < deadline, "uvicorn did not start in 30 s"
            time.sleep(0.05)
        return self

    def __exit__(self, *exc: object) -> None:
        self.server.should_exit = True
        self.thread.join(timeout=10)


def has_surfaces(app: FastAPI) -> bool:
    return any(path.startswith("/surfaces/") for path in app.openapi()["paths"])


@pytest.fixture(scope="session")
def server() -> Iterator[Server]:
    """The service exactly as `make run` builds it."""
    with Server(create_app(Settings())) as running:
        yield running


@pytest.fixture(scope="session")
def surfaces_server() -> Iterator[Server]:
    """The service with GET /surfaces/{id}: the real one once it exists, else the stand-in."""
    app = create_app(Settings())
    if not has_surfaces(app):
        install_standin(app)
        app.openapi_schema = None
    with Server(app) as running:
        yield running


@pytest.fixture(scope="session")
def playwright() -> Iterator[Playwright]:
    assert Path(CHROMIUM).exists(), f"{CHROMIUM} is missing: `make test` installs Debian's chromium"
    with sync_playwright() as driver:
        yield driver


@pytest.fixture(scope="session")
def context(playwright: Playwright) -> Iterator[BrowserContext]:
    """One Chromium with a fresh, empty profile (Playwright passes it as --user-data-dir)."""
    with tempfile.TemporaryDirectory(prefix="dcosh-chromium-") as profile:
        context = playwright.chromium.launch_persistent_context(
            profile,
            executable_path=CHROMIUM,
            headless=True,
            args=CHROMIUM_FLAGS,
            viewport={"width": 1280, "height": 900},
            accept_downloads=True,
        )
        yield context
        context.close()


@pytest.fixture
def page(context: BrowserContext) -> Iterator[Page]:
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.on(
        "console",
        lambda message: errors.append(message.text) if message.type == "error" else None,
    )
    yield page
    # a 422 shown on purpose logs "Failed to load resource"; anything else is a bug of the page
    unexpected = [e for e in errors if "status of 422" not in e]
    assert not unexpected, unexpected


# The tallest explorer page is ~13,000 px on a phone; ReDoc lays out every operation on one page
# (~137,000 px, a 20 MB PNG whose capture took > 30 s on a loaded CI host), so a page taller than
# this is captured as its first viewport only.
SCREENSHOT_MAX_HEIGHT = 16_000


def screenshot(page: Page, name: str) -> Path:
    """Save a PNG for a human to look at: the whole page, or its first viewport if very tall."""
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    path = SCREENSHOTS / f"{name}.png"
    height = page.evaluate("document.documentElement.scrollHeight")
    page.screenshot(path=str(path), full_page=height <= SCREENSHOT_MAX_HEIGHT)
    return path
