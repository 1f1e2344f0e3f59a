"""GET / and /static: the explorer page, its CSP, its scripts and the built three.js files."""

from __future__ import annotations

import base64
import hashlib
import re

from fastapi.testclient import TestClient

from app.routers.explorer import VENDOR


def test_the_page_is_served_with_a_csp_that_allows_exactly_its_import_map(
    client: TestClient,
) -> None:
    response = client.get("/")
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/html")
    csp = response.headers["content-security-policy"]
    importmap = re.search(r'<script type="importmap">(.*?)</script>', response.text, re.S)
    assert importmap is not None
    digest = base64.b64encode(hashlib.sha256(importmap.group(1).encode()).digest()).decode()
    assert f"script-src 'self' 'sha256-{digest}'" in csp
    assert "unsafe-inline" not in csp and "unsafe-eval" not in csp
    assert "connect-src 'self'" in csp and "frame-ancestors 'none'" in csp
    # no other inline script, no inline style attribute (both would be blocked)
    scripts = re.findall(r"<script([^>]*)>", response.text)
    assert all('src="/static/' in s or 'type="importmap"' in s for s in scripts)
    assert "style=" not in response.text
    assert client.head("/").status_code == 200


def test_the_page_scripts_are_served_as_javascript(client: TestClient) -> None:
    for name in ("explorer.js", "plot.js", "view3d.js", "explorer.css"):
        response = client.get(f"/static/explorer/{name}")
        assert response.status_code == 200, name
    assert "javascript" in client.get("/static/explorer/explorer.js").headers["content-type"]


def test_the_page_uses_public_endpoints_only(client: TestClient) -> None:
    """Every path the scripts fetch is in the OpenAPI document, and the page never loads the
    document itself: the catalogs say what it needs."""
    spec = client.get("/openapi.json").json()
    source = "".join(
        client.get(f"/static/explorer/{name}").text
        for name in ("explorer.js", "view3d.js", "animation.js", "plot.js")
    )
    fetched = set(re.findall(r"(?:getJSON|fetch)\(\s*[`'\"](/[a-z.]+)", source))
    assert {"/discretizations", "/figures", "/surfaces", "/theorems", "/smooth"} <= fetched
    assert "openapi" not in source
    for path in fetched:
        assert any(p == path or p.startswith(path + "/") for p in spec["paths"]), path


def test_three_js_is_built_into_static_vendor(client: TestClient) -> None:
    version = (VENDOR / "three" / "VERSION").read_text().strip()
    assert version == "0.187.0"
    for path in (
        "build/three.module.js",
        "build/three.core.js",
        "examples/jsm/loaders/GLTFLoader.js",
        "examples/jsm/controls/OrbitControls.js",
    ):
        response = client.get(f"/static/vendor/three/{path}")
        assert response.status_code == 200, path
        assert "javascript" in response.headers["content-type"]


def test_the_image_builds_the_same_assets() -> None:
    """The Dockerfile runs the pinned npm install and the asset build before the Python install."""
    root = VENDOR.parents[2]
    dockerfile = (root / "Dockerfile").read_text(encoding="utf-8")
    assert "npm ci" in dockerfile and "npm run build" in dockerfile
    assert "COPY --from=assets /build/app/static/vendor ./app/static/vendor" in dockerfile
    assert dockerfile.index("COPY --from=assets") < dockerfile.index("python -m compileall")
    lock = (root / "package-lock.json").read_text(encoding="utf-8")
    assert '"node_modules/three": {\n      "version": "0.187.0"' in lock
