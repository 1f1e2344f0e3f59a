"""HTTP as clients expect it: HEAD, Allow, 415, malformed JSON, unknown parameters, If-None-Match,
problem types that resolve on the service."""

from __future__ import annotations

import json

import pytest
from fastapi.testclient import TestClient

from app.errors import PROBLEM_TYPES
from app.openapi_export import document

SPEC = json.loads(document())
GET_PATHS = [
    path for path, operations in SPEC["paths"].items() if "get" in operations and "{" not in path
] + ["/discretizations/d4b", "/theorems/theorem-5", "/errata/E2", "/problems/not-found"]


@pytest.mark.parametrize("path", [*GET_PATHS, "/", "/docs", "/redoc", "/openapi.json"])
def test_head_answers_like_get_without_a_body(client: TestClient, path: str) -> None:
    get = client.get(path)
    head = client.head(path)
    assert get.status_code == 200, (path, get.text[:200])
    assert head.status_code == 200, path
    assert head.content == b""
    for name in ("content-type", "content-length", "etag", "cache-control"):
        assert head.headers.get(name) == get.headers.get(name), (path, name)


@pytest.mark.parametrize(
    ("method", "path", "allow"),
    [
        ("DELETE", "/discretizations/d4b", "GET, HEAD, POST"),
        ("PUT", "/discretizations", "GET, HEAD"),
        ("POST", "/theorems", "GET, HEAD"),
        ("PATCH", "/surfaces/catenoid", "GET, HEAD, POST"),
        ("POST", "/errata/E2", "GET, HEAD"),
    ],
)
def test_405_lists_the_allowed_methods(
    client: TestClient, method: str, path: str, allow: str
) -> None:
    response = client.request(method, path)
    assert response.status_code == 405
    assert response.headers["allow"] == allow
    assert response.json()["type"] == "/problems/method-not-allowed"


def test_a_body_that_is_not_json_is_415(client: TestClient) -> None:
    response = client.post(
        "/discretizations/d4b", content=b"d=0.3", headers={"content-type": "text/plain"}
    )
    assert response.status_code == 415
    assert response.headers["content-type"] == "application/problem+json"
    body = response.json()
    assert body["type"] == "/problems/unsupported-media-type"
    assert body["errors"][0]["parameter"] == "Content-Type"
    assert body["errors"][0]["value"] == "text/plain"
    ok = client.post(
        "/discretizations/d4b",
        content=b'{"d": 0.3}',
        headers={"content-type": "application/json; charset=utf-8"},
    )
    assert ok.status_code == 200


def test_malformed_json_names_the_body_and_the_position(client: TestClient) -> None:
    response = client.post(
        "/discretizations/d4b",
        content=b'{"d": 0.3,,}',
        headers={"content-type": "application/json"},
    )
    assert response.status_code == 422
    error = response.json()["errors"][0]
    assert error["parameter"] == "body"
    assert "character offset 10" in error["constraint"]


@pytest.mark.parametrize(
    "url",
    [
        "/theorems?format=csv",
        "/discretizations?x=1",
        "/health?verbose=1",
        "/errata?x=1",
        "/discretizations/d4b?x=1",
        "/figures?x=1",
    ],
)
def test_unknown_query_parameters_are_refused_everywhere(client: TestClient, url: str) -> None:
    response = client.get(url)
    assert response.status_code == 422, url
    body = response.json()
    assert body["type"] == "/problems/invalid-parameters"
    assert body["errors"][0]["constraint"] == "not a parameter of this endpoint"


def test_if_none_match_star_does_not_hide_an_invalid_request(client: TestClient) -> None:
    assert client.get("/discretizations/d4b?d=5", headers={"if-none-match": "*"}).status_code == 422
    assert (
        client.get("/discretizations/d4b?d=0.2", headers={"if-none-match": "*"}).status_code == 304
    )
    # a second time the answer comes from the cache's fast path: still 304
    assert (
        client.get("/discretizations/d4b?d=0.2", headers={"if-none-match": "*"}).status_code == 304
    )


def test_every_problem_type_resolves_with_one_title(client: TestClient) -> None:
    titles: dict[str, set[str]] = {}
    samples = [
        client.get("/discretizations/d4b?d=5"),
        client.get("/discretizations/d4b?h=abc"),
        client.get("/discretizations/d9"),
        client.get("/theorems/nothing"),
        client.get("/no/such/path"),
        client.delete("/discretizations/d4b"),
        client.get("/discretizations/d4b?i_min=-600000&i_max=600000"),
    ]
    for response in samples:
        body = response.json()
        titles.setdefault(body["type"], set()).add(body["title"])
        page = client.get(body["type"])
        assert page.status_code == 200, body["type"]
        assert page.json()["title"] == body["title"]
        assert page.json()["status"] == body["status"]
        html = client.get(body["type"], headers={"accept": "text/html"})
        assert html.headers["content-type"].startswith("text/html")
        assert body["title"] in html.text
    assert all(len(t) == 1 for t in titles.values()), titles
    listed = client.get("/problems").json()
    assert [p["type"] for p in listed] == [t.uri for t in PROBLEM_TYPES.values()]
    assert len({p["title"] for p in listed}) == len(listed)


def test_documentation_bundles_are_fingerprinted_immutable_and_gzipped(client: TestClient) -> None:
    import re

    for page in ("/docs", "/redoc"):
        sources = re.findall(r"""(?:src|href)=["'](/assets/[^"']+)["']""", client.get(page).text)
        assert sources, page
        for source in sources:
            plain = client.get(source, headers={"accept-encoding": "identity"})
            zipped = client.get(source, headers={"accept-encoding": "gzip"})
            assert plain.status_code == zipped.status_code == 200
            assert plain.headers["cache-control"] == "public, max-age=31536000, immutable"
            assert zipped.content == plain.content  # httpx decodes the gzip body
            if plain.headers["content-type"].startswith("text/"):
                assert zipped.headers["content-encoding"] == "gzip"
                assert int(zipped.headers["content-length"]) < len(plain.content) / 2
            again = client.get(source, headers={"if-none-match": plain.headers["etag"]})
            assert again.status_code == 304


def test_openapi_document_has_an_etag_and_is_gzipped(client: TestClient) -> None:
    plain = client.get("/openapi.json", headers={"accept-encoding": "identity"})
    zipped = client.get("/openapi.json", headers={"accept-encoding": "gzip"})
    assert plain.json() == zipped.json() == json.loads(document())
    assert zipped.headers["content-encoding"] == "gzip"
    assert int(zipped.headers["content-length"]) < len(plain.content) / 4
    for response in (plain, zipped):
        tag = response.headers["etag"]
        assert client.get("/openapi.json", headers={"if-none-match": tag}).status_code == 304


def test_catalogs_and_static_files_are_gzipped(client: TestClient) -> None:
    theorems = client.get("/theorems", headers={"accept-encoding": "gzip"})
    assert theorems.headers["content-encoding"] == "gzip"
    assert int(theorems.headers["content-length"]) < len(theorems.content) / 4
    script = client.get("/static/explorer/explorer.js", headers={"accept-encoding": "gzip"})
    assert script.headers["content-encoding"] == "gzip"
    assert script.headers["cache-control"] == "no-cache"
    assert script.headers["etag"].endswith('-gzip"')
    again = client.get(
        "/static/explorer/explorer.js",
        headers={"accept-encoding": "gzip", "if-none-match": script.headers["etag"]},
    )
    assert again.status_code == 304


def test_three_js_is_fingerprinted_immutable_and_gzipped(client: TestClient) -> None:
    import re

    from app.routers.explorer import THREE, directory_fingerprint

    importmap = json.loads(
        re.search(r'<script type="importmap">(.*?)</script>', client.get("/").text, re.S).group(1)  # type: ignore[union-attr]
    )["imports"]
    fingerprint = directory_fingerprint(THREE)
    assert importmap == {
        "three": f"/assets/three-{fingerprint}/build/three.module.js",
        "three/addons/": f"/assets/three-{fingerprint}/examples/jsm/",
    }
    for url in (
        importmap["three"],
        importmap["three"].replace("three.module.js", "three.core.js"),  # its relative import
        importmap["three/addons/"] + "loaders/GLTFLoader.js",
        importmap["three/addons/"] + "controls/OrbitControls.js",
    ):
        plain = client.get(url, headers={"accept-encoding": "identity"})
        zipped = client.get(url, headers={"accept-encoding": "gzip"})
        assert plain.status_code == zipped.status_code == 200, url
        assert plain.headers["cache-control"] == "public, max-age=31536000, immutable"
        assert zipped.headers["content-encoding"] == "gzip" and zipped.content == plain.content
        assert plain.content == (THREE / url.split(f"three-{fingerprint}/", 1)[1]).read_bytes()
        again = client.get(url, headers={"if-none-match": plain.headers["etag"]})
        assert again.status_code == 304
    missing = client.get(f"/assets/three-{fingerprint}/build/none.js")
    assert missing.status_code == 404 and "immutable" not in missing.headers.get(
        "cache-control", ""
    )
    # another fingerprint is not served: an address never changes content
    assert client.get("/assets/three-0000000000000000/build/three.module.js").status_code == 404
