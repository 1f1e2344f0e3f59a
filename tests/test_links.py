"""Every link the service emits resolves on the service: the explorer page, /docs, /redoc, the
errata and problem pages, and the links inside sample JSON responses (erratum links, catalog
urls, problem types). Fragments must name an id on the target page. The documentation pages
load nothing from another host."""

from __future__ import annotations

import re
from html.parser import HTMLParser
from typing import Any
from urllib.parse import urldefrag, urlsplit

from fastapi.testclient import TestClient

HTML_PAGES = ["/", "/docs", "/redoc", "/errata?format=html", "/problems?format=html"]
JSON_SAMPLES = [
    "/discretizations",
    "/discretizations/d4b",
    "/discretizations/d4a",
    "/discretizations/d2a-quad",
    "/convergence/theorem-11?levels=3",
    "/theorems",
    "/figures",
    "/surfaces",
    "/errata",
    "/problems",
    "/discretizations/d4b?d=5",  # a problem: its `type`
]
#: JSON members whose string values are links
LINK_KEYS = {"link", "url", "type", "example"}


class Links(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.links: list[str] = []
        self.ids: set[str] = set()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        for name, value in attrs:
            if name in ("href", "src") and value:
                self.links.append(value)
            if name == "id" and value:
                self.ids.add(value)


def parse(html: str) -> Links:
    parser = Links()
    parser.feed(html)
    return parser


def json_links(value: Any, key: str = "") -> list[str]:
    if isinstance(value, dict):
        return [link for k, v in value.items() for link in json_links(v, k)]
    if isinstance(value, list):
        return [link for v in value for link in json_links(v, key)]
    if key in LINK_KEYS and isinstance(value, str) and re.match(r"^/[^\s]*$", value):
        return [value]
    return []


#: What a browser sends when it follows a link: HTML preferred, anything else accepted (a data
#: endpoint answers with its default format, not 406).
BROWSER_ACCEPT = "text/html,application/xhtml+xml,application/xml;q=0.9,*/*;q=0.8"


def script_sources(html: str) -> list[str]:
    return re.findall(r"""(?:src|href)=["']([^"']+)["']""", html)


def test_no_dead_link(client: TestClient) -> None:
    pending: list[tuple[str, str]] = [(page, "start") for page in HTML_PAGES]
    for sample in JSON_SAMPLES:
        body = client.get(sample).json()
        pending += [(link, sample) for link in json_links(body)]
    seen: set[str] = set()
    html_ids: dict[str, set[str]] = {}
    dead: list[str] = []
    fragments: list[tuple[str, str, str]] = []
    while pending:
        link, source = pending.pop()
        if link.startswith(("data:", "mailto:")):
            continue
        parts = urlsplit(link)
        if parts.scheme or parts.netloc:
            continue  # other hosts: not followed (the docs pages have none, see below)
        target, fragment = urldefrag(link)
        target = target or source
        if fragment:
            fragments.append((target, fragment, source))
        if target in seen:
            continue
        seen.add(target)
        response = client.get(target, headers={"accept": BROWSER_ACCEPT})
        if response.status_code != 200:
            dead.append(f"{link} (from {source}): {response.status_code}")
            continue
        if response.headers["content-type"].startswith("text/html"):
            page = parse(response.text)
            html_ids[target] = page.ids
            # links of the errata and problem pages, and of the explorer and docs shells
            if urlsplit(target).path in ("/", "/docs", "/redoc") or target.startswith(
                ("/errata", "/problems")
            ):
                pending += [(href, target) for href in page.links]
    for target, fragment, source in fragments:
        if target in html_ids and fragment not in html_ids[target]:
            dead.append(f"{target}#{fragment} (from {source}): no such id")
    assert not dead, dead
    assert any(link.startswith("/errata/E") for link in seen), "erratum links were followed"
    assert any(link.startswith("/problems/") for link in seen), "problem types were followed"


def test_documentation_pages_load_nothing_from_another_host(client: TestClient) -> None:
    for page in ("/docs", "/redoc", "/", "/errata?format=html"):
        html = client.get(page).text
        for source in script_sources(html):
            parts = urlsplit(source)
            assert not parts.netloc, (page, source)


def test_redoc_bundle_does_not_reach_for_its_cdn_logo(client: TestClient) -> None:
    redoc = parse(client.get("/redoc").text)
    bundle = next(src for src in redoc.links if "redoc.standalone" in src)
    assert "cdn.redoc.ly" not in client.get(bundle).text
