"""Every response carries the security headers; pages carry their own CSP."""

from __future__ import annotations

from fastapi.testclient import TestClient

from app.security import API_POLICY, inline_script_hashes, page_policy


def test_api_responses_get_the_strict_default(client: TestClient) -> None:
    for url in ("/health", "/discretizations/d4b", "/discretizations/d4b?d=2", "/nowhere"):
        response = client.get(url)
        assert response.headers["content-security-policy"] == API_POLICY, url
        assert response.headers["x-content-type-options"] == "nosniff"
        assert response.headers["referrer-policy"] == "no-referrer"


def test_pages_allow_only_their_own_inline_scripts(client: TestClient) -> None:
    for url in ("/", "/docs", "/redoc"):
        response = client.get(url)
        policy = response.headers["content-security-policy"]
        assert "'unsafe-eval'" not in policy
        assert f"script-src 'self' {inline_script_hashes(response.text)}".strip() + ";" in policy
        assert "cdn" not in response.text.lower(), url
    assert "'sha256-" in client.get("/docs").headers["content-security-policy"]


def test_inline_script_hashes_skip_external_scripts() -> None:
    html = '<script src="/a.js"></script><script>alert(1)</script>'
    assert inline_script_hashes(html) == "'sha256-bhHHL3z2vDgxUt0W3dWQOrprscmda2Y5pLsLg4GF+pI='"
    assert "style-src 'self' 'unsafe-inline'" in page_policy(html, inline_styles=True)
