"""Accept chooses the format a GET does not name (app.negotiation): CSV, SVG, npy, npz, OBJ,
GLB, HTML where the endpoint has them; `format` wins; 406 lists what is available; the cache
key, the ETag and `Vary` follow the negotiated representation."""

from __future__ import annotations

import io
import json

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.negotiation import choose, endpoints, negotiable
from app.openapi_export import document
from app.settings import Settings

SPEC = json.loads(document())
CURVE = "/discretizations/d4b?i_min=-3&i_max=3"
BROWSER = "text/html,application/xhtml+xml,application/xml;q=0.9,image/avif,image/webp,*/*;q=0.8"
CURVE_FORMATS = {
    "json": "application/json",
    "csv": "text/csv",
    "svg": "image/svg+xml",
    "npy": "application/x-npy",
    "npz": "application/x-npz",
}


def _vary(response: object) -> set[str]:
    header = response.headers.get("vary", "")  # type: ignore[attr-defined]
    return {v.strip().lower() for v in header.split(",")}


@pytest.mark.parametrize(
    ("accept", "media_type", "format_"),
    [
        ("text/csv", "text/csv; charset=utf-8", "csv"),
        ("image/svg+xml", "image/svg+xml", "svg"),
        ("application/x-npy", "application/x-npy", "npy"),
        ("application/x-npz", "application/x-npz", "npz"),
        ("application/json", "application/json", "json"),
        ("text/*", "text/csv; charset=utf-8", "csv"),
        ("application/json;q=0, text/csv;q=0.5, */*;q=0.1", "text/csv; charset=utf-8", "csv"),
        (BROWSER, "application/json", "json"),  # a page opened in a browser stays JSON
        ("*/*", "application/json", "json"),
    ],
)
def test_accept_chooses_the_format_when_the_query_names_none(
    accept: str, media_type: str, format_: str
) -> None:
    client = TestClient(create_app(Settings()))  # a fresh cache: no answer from another test
    negotiated = client.get(CURVE, headers={"accept": accept, "accept-encoding": "identity"})
    named = client.get(f"{CURVE}&format={format_}", headers={"accept-encoding": "identity"})
    assert negotiated.status_code == named.status_code == 200, negotiated.text
    assert negotiated.headers["content-type"] == named.headers["content-type"] == media_type
    assert negotiated.content == named.content
    assert negotiated.headers["etag"] == named.headers["etag"]
    assert "accept" in _vary(negotiated) and "accept-encoding" in _vary(negotiated)


def test_the_negotiated_body_is_the_format(client: TestClient) -> None:
    csv = client.get(CURVE, headers={"accept": "text/csv"})
    assert csv.text.splitlines()[0] == "curve,index,x,y"
    npy = client.get(CURVE, headers={"accept": "application/x-npy"})
    points = np.load(io.BytesIO(npy.content))
    assert points.shape == (7, 2) and npy.headers["x-first-index"] == "-3"
    assert points.tolist() == client.get(CURVE).json()["vertices"]


def test_format_wins_over_accept(client: TestClient) -> None:
    response = client.get(f"{CURVE}&format=csv", headers={"accept": "application/json"})
    assert response.headers["content-type"] == "text/csv; charset=utf-8"
    response = client.get(f"{CURVE}&format=json", headers={"accept": "application/pdf"})
    assert response.status_code == 200 and response.headers["content-type"] == "application/json"


def test_an_accept_nothing_satisfies_is_406_listing_what_is_available(client: TestClient) -> None:
    for method in ("GET", "HEAD"):
        response = client.request(method, CURVE, headers={"accept": "application/pdf"})
        assert response.status_code == 406
        assert response.headers["content-type"] == "application/problem+json"
        assert "accept" in _vary(response)
    body = client.get(CURVE, headers={"accept": "application/pdf"}).json()
    assert body["type"] == "/problems/not-acceptable" and body["title"] == "Not acceptable"
    assert {a["format"]: a["media_type"] for a in body["available"]} == CURVE_FORMATS
    assert body["errors"][0]["parameter"] == "Accept"
    assert client.get(body["type"]).status_code == 200  # the problem type resolves
    # q=0 refuses a type: JSON refused and nothing else named
    refused = client.get(CURVE, headers={"accept": "application/json;q=0"})
    assert refused.status_code == 406


def test_the_cache_and_the_fast_path_keep_representations_apart(client: TestClient) -> None:
    url = "/discretizations/d2b?sequence=remark-13&j=3"
    first = client.get(url)  # JSON, kept and remembered by the fast path
    assert first.headers["content-type"] == "application/json"
    csv = client.get(url, headers={"accept": "text/csv"})
    assert csv.headers["content-type"] == "text/csv; charset=utf-8"
    assert csv.headers["etag"] != first.headers["etag"]
    again = client.get(url)  # the fast path: still JSON without Accept
    assert again.headers["content-type"] == "application/json"
    # a revalidation of the CSV's tag is a 304 only for the CSV
    tag = csv.headers["etag"]
    headers = {"accept": "text/csv", "if-none-match": tag}
    assert client.get(url, headers=headers).status_code == 304
    assert client.get(url, headers={"if-none-match": tag}).status_code == 200


@pytest.mark.parametrize(
    ("url", "accept", "media_type"),
    [
        ("/surfaces/catenoid?m=3&i_min=-2&i_max=2", "model/gltf-binary", "model/gltf-binary"),
        ("/surfaces/catenoid/d1?m=3&i_min=-2&i_max=2", "model/obj", "model/obj"),
        ("/convergence/theorem-11?levels=2", "text/csv", "text/csv; charset=utf-8"),
        ("/relations", "text/html", "text/html; charset=utf-8"),
        ("/smooth/catenary", "image/svg+xml", "image/svg+xml"),
    ],
)
def test_other_endpoints_negotiate_their_own_formats(
    client: TestClient, url: str, accept: str, media_type: str
) -> None:
    response = client.get(url, headers={"accept": accept})
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == media_type
    assert "accept" in _vary(response)


def test_formats_without_a_media_type_of_their_own_are_not_negotiated(client: TestClient) -> None:
    # PLY and VTU go out as application/octet-stream and application/xml: a browser's
    # application/xml;q=0.9 must not turn a surface link into a VTU download
    url = "/surfaces/catenoid?m=3&i_min=-2&i_max=2"
    assert client.get(url, headers={"accept": BROWSER}).headers["content-type"] == (
        "application/json"
    )
    assert client.get(url, headers={"accept": "text/csv"}).status_code == 406


def test_endpoints_without_formats_ignore_accept(client: TestClient) -> None:
    for url in ("/health", "/discretizations", "/theorems"):
        response = client.get(url, headers={"accept": "application/pdf"})
        assert response.status_code == 200, url


def test_the_document_says_where_accept_chooses_and_documents_406() -> None:
    table = endpoints(SPEC)
    negotiating = {
        path
        for path, operations in SPEC["paths"].items()
        if "get" in operations and len(negotiable(operations["get"])) > 1
    }
    assert len(table) == len(negotiating) >= 20
    for path in negotiating:
        operation = SPEC["paths"][path]["get"]
        assert "406" in operation["responses"], path
        format_ = next(p for p in operation["parameters"] if p["name"] == "format")
        assert "`Accept` header chooses" in format_["description"], path
    assert negotiable(SPEC["paths"]["/discretizations/d1"]["get"]) == CURVE_FORMATS
    assert "406" not in SPEC["paths"]["/theorems"]["get"]["responses"]


def test_choose() -> None:
    formats = CURVE_FORMATS
    assert choose("text/csv, image/svg+xml", formats) == "csv"  # equal q: first in the header
    assert choose("image/svg+xml, text/csv", formats) == "svg"
    assert choose("text/csv, application/json", formats) == "json"  # equal q: the default
    assert choose("text/csv;q=0.9, application/json;q=0.8", formats) == "csv"
    assert choose("image/*;q=0.5, text/csv;q=0.4", formats) == "svg"
    assert choose("*/*, application/json;q=0", formats) == "csv"  # the next one */* allows
    assert choose("application/pdf", formats) is None
    assert choose("", formats) == "json" and choose("garbage", formats) == "json"
    assert choose("text/csv;q=abc", formats) is None
