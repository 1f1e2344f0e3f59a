"""The fast lane (app/fast_lane.py) answers exactly as the full middleware chain does.

Two apps with the same settings, one with the lane and one without (``fast_lane_seconds=0``),
get the same requests, each twice (computed, then from the response cache); status, every
header in order and the body must be the same bytes. The lane must also really have answered
the requests it is meant for (``FastLane.served``).
"""

from __future__ import annotations

from typing import Any
from urllib.parse import parse_qsl

import anyio
import pytest
from fastapi import FastAPI
from fastapi._compat.shared import field_annotation_is_sequence
from fastapi.testclient import TestClient

from app.fast_lane import FastLane, is_sequence, split_query
from app.main import create_app
from app.registry import DISCRETIZATIONS
from app.settings import Settings

D4B = "/discretizations/d4b"
SMALL = "i_min=-5&i_max=5"

#: (method, path, query, headers, how many of the two requests the lane answers: 2 computed
#: and kept, 1 only the repeat from the response cache, 0 none)
CASES: list[tuple[str, str, str, dict[str, str], int]] = [
    ("GET", D4B, SMALL, {}, 2),
    ("GET", D4B, "", {}, 2),
    ("GET", D4B, f"{SMALL}&checks=none", {}, 2),
    ("GET", D4B, f"{SMALL}&checks=none&companions=none", {}, 2),
    ("GET", D4B, f"{SMALL}&checks=theorem-5,theorem-6&companions=tractrix", {}, 2),
    ("GET", D4B, f"{SMALL}&detail=true", {}, 2),
    ("GET", D4B, f"{SMALL}&method=closed-form", {}, 2),
    ("GET", D4B, f"{SMALL}&d=0.25&h=2&beta0=1", {}, 2),
    ("GET", D4B, f"{SMALL}&format=csv", {}, 2),
    ("GET", D4B, f"{SMALL}&format=npy", {}, 2),
    ("GET", D4B, f"{SMALL}&format=npz", {}, 2),
    ("GET", D4B, f"{SMALL}&format=svg", {}, 2),
    ("GET", D4B, f"{SMALL}&format=checks-csv", {}, 2),
    ("GET", D4B, f"{SMALL}&format=csv", {"Accept": "text/html"}, 2),
    ("GET", D4B, SMALL, {"Accept-Encoding": "gzip, deflate"}, 2),
    ("GET", D4B, f"{SMALL}&format=csv", {"Accept-Encoding": "gzip"}, 2),
    ("GET", D4B, SMALL, {"Accept-Encoding": "gzip;q=0"}, 2),
    ("GET", D4B, SMALL, {"Accept": "*/*"}, 2),
    ("GET", D4B, SMALL, {"Accept": "application/json, text/plain;q=0.5"}, 2),
    ("GET", "/discretizations/d1", "i_min=-4&i_max=4", {}, 2),
    ("GET", "/discretizations/d2a-quad", "i_min=0&i_max=6", {}, 2),
    ("GET", "/discretizations/d2a-hex", "i_min=0&i_max=6&lambda=0.4", {}, 2),
    ("GET", "/discretizations/d2b", "sequence=custom&s=0,0.2,0.5", {}, 2),
    ("GET", "/discretizations/d2b", "j=2", {}, 2),
    ("GET", "/discretizations/d3", "i_min=-4&i_max=4&branch=down", {}, 2),
    ("GET", "/discretizations/d4a", "i_min=-4&i_max=4", {}, 2),
    # computed by the chain, repeated from the cache by the lane: big or mp requests
    ("GET", D4B, "i_min=-800&i_max=800", {}, 1),
    ("GET", D4B, f"{SMALL}&precision=mp&digits=20", {}, 1),
    # the full chain's: other representations, conditions, CORS, HEAD
    ("GET", D4B, SMALL, {"Accept": "text/csv"}, 0),
    ("GET", D4B, SMALL, {"Accept": "text/html"}, 0),
    ("GET", D4B, SMALL, {"Accept": "image/png"}, 0),
    ("GET", D4B, SMALL, {"If-None-Match": '"nothing"'}, 0),
    ("GET", D4B, SMALL, {"If-None-Match": "*"}, 0),
    ("GET", D4B, SMALL, {"Origin": "https://example.org"}, 0),
    ("HEAD", D4B, SMALL, {}, 0),
    ("GET", D4B + "/", SMALL, {}, 0),
    # errors: every one answered by the chain's handlers
    ("GET", D4B, f"{SMALL}&d=2", {}, 0),
    ("GET", D4B, f"{SMALL}&d=abc", {}, 0),
    ("GET", D4B, f"{SMALL}&d=nan", {}, 0),
    ("GET", D4B, f"{SMALL}&d=", {}, 0),
    ("GET", D4B, "i_min=5&i_max=-5", {}, 0),
    ("GET", D4B, "i_min=-5000&i_max=5000", {}, 0),
    ("GET", D4B, f"{SMALL}&nonsense=1", {}, 0),
    ("GET", D4B, f"{SMALL}&d=0.3&d=0.4", {}, 0),
    ("GET", D4B, f"{SMALL}&digits=100000", {}, 0),
    ("GET", D4B, f"{SMALL}&digits=1e400", {}, 0),
    ("GET", D4B, f"{SMALL}&checks=no-such-statement", {}, 0),
    ("GET", D4B, f"{SMALL}&format=pdf", {}, 0),
    ("GET", D4B, "i_min=0&i_max=10000000", {}, 0),
    ("GET", "/discretizations/d2a-hex", "i_min=0&i_max=6&lambda_=0.4", {}, 0),
    ("GET", "/discretizations/d2b", "sequence=custom&s=0,0.2,0.1", {}, 0),
    ("GET", "/discretizations/nope", SMALL, {}, 0),
    # a statement checked on a discretization's curve (GET /theorems/{id})
    ("GET", "/theorems/theorem-5", "", {}, 2),
    ("GET", "/theorems/theorem-5", f"{SMALL}&d=0.2", {}, 2),
    ("GET", "/theorems/theorem-5", f"{SMALL}&detail=true", {}, 2),
    ("GET", "/theorems/theorem-5", f"{SMALL}&detail=false&digits=30", {}, 2),
    ("GET", "/theorems/theorem-5", SMALL, {"Accept-Encoding": "gzip"}, 2),
    ("GET", "/theorems/d1", "discretization=d3&i_min=-4&i_max=4", {}, 2),
    ("GET", "/theorems/d1", "i_min=-4&i_max=4", {}, 2),
    ("GET", "/theorems/theorem-1", "i_min=0&i_max=6", {}, 2),
    ("GET", "/theorems/remark-13", "", {}, 2),
    ("GET", "/theorems/lemma-10", "discretization=d2b", {}, 2),
    ("GET", "/theorems/theorem-5", f"{SMALL}&precision=mp&digits=20", {}, 1),
    ("GET", "/theorems/theorem-5", "i_min=-800&i_max=800", {}, 1),
    ("GET", "/theorems/theorem-5", SMALL, {"Accept": "text/csv"}, 2),
    ("GET", "/theorems/theorem-5", SMALL, {"Origin": "https://example.org"}, 0),
    ("GET", "/theorems/theorem-5", SMALL, {"If-None-Match": "*"}, 0),
    ("HEAD", "/theorems/theorem-5", SMALL, {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&detail=yes", {}, 1),
    ("GET", "/theorems/theorem-5", f"{SMALL}&detail=maybe", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&digits=0", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&digits=abc", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&d=2", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&checks=none", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&checks=theorem-6", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&checks=theorem-5,theorem-6", {}, 2),
    ("GET", "/theorems/theorem-5", f"{SMALL}&d=0.2&d=0.3", {}, 0),
    ("GET", "/theorems/theorem-5", f"{SMALL}&nonsense=1", {}, 0),
    ("GET", "/theorems/theorem-5", "discretization=d1", {}, 0),
    ("GET", "/theorems/theorem-5", "discretization=nope", {}, 0),
    ("GET", "/theorems/theorem-5", "study=theorem-11", {}, 0),
    ("GET", "/theorems/lemma-10", "study=theorem-11", {}, 1),
    ("GET", "/theorems/theorem-11", "", {}, 0),  # checked on its study: not a lane path
    ("GET", "/theorems/no-such-statement", "", {}, 0),
    ("GET", "/theorems/theorem-5", "format=csv", {}, 2),
]


def lane_of(app: FastAPI) -> FastLane | None:
    """The app's FastLane instance (built with the middleware stack on the first request)."""
    layer: Any = app.middleware_stack
    while layer is not None:
        if isinstance(layer, FastLane):
            return layer
        layer = getattr(layer, "app", None)
    return None


@pytest.fixture(scope="module")
def clients() -> tuple[TestClient, TestClient]:
    lane = TestClient(create_app(Settings()))
    chain = TestClient(create_app(Settings(fast_lane_seconds=0)))
    return lane, chain


def raw(client: TestClient, method: str, url: str, headers: dict[str, str]) -> Any:
    response = client.request(method, url, headers=headers, follow_redirects=False)
    return response.status_code, response.headers.raw, response.content


@pytest.mark.parametrize(("method", "path", "query", "headers", "in_lane"), CASES)
def test_the_lane_answers_as_the_chain(
    clients: tuple[TestClient, TestClient],
    method: str,
    path: str,
    query: str,
    headers: dict[str, str],
    in_lane: int,
) -> None:
    lane, chain = clients
    url = f"{path}?{query}" if query else path
    for repeat in range(2):  # computed, then kept
        lane.get("/health")  # builds the middleware stack
        fast = lane_of(lane.app)  # type: ignore[arg-type]
        assert fast is not None
        before = fast.served
        expected = raw(chain, method, url, headers)
        got = raw(lane, method, url, headers)
        assert got[0] == expected[0]
        assert got[1] == expected[1]
        assert got[2] == expected[2]
        assert fast.served - before == (1 if in_lane + repeat >= 2 else 0)
    assert lane_of(chain.app) is None  # type: ignore[arg-type]


def test_a_computed_answer_is_kept_for_the_chain(clients: tuple[TestClient, TestClient]) -> None:
    """What the lane kept answers the chain's conditional request (same key, same ETag)."""
    lane, _ = clients
    url = f"{D4B}?i_min=-3&i_max=3&d=0.123"
    first = lane.get(url)
    assert first.status_code == 200
    again = lane.get(url, headers={"If-None-Match": first.headers["etag"]})
    assert again.status_code == 304
    assert again.headers["etag"] == first.headers["etag"]
    assert lane.app.state.response_cache.fast_hits >= 0  # type: ignore[attr-defined]


def test_the_lane_charges_admission_and_gives_it_back(
    clients: tuple[TestClient, TestClient],
) -> None:
    lane, _ = clients
    admission = lane.app.state.admission  # type: ignore[attr-defined]
    response = lane.get(f"{D4B}?i_min=-3&i_max=3&d=0.321")
    assert response.status_code == 200
    assert admission.admitted == 0
    # an error after the charge (d >= h is found by the core): given back before the chain
    # answers it, and the chain's own charge at the end of the response
    response = lane.get(f"{D4B}?i_min=-3&i_max=3&d=1.5")
    assert response.status_code == 422
    assert admission.admitted == 0
    assert admission.seconds == pytest.approx(0.0, abs=1e-12)
    assert admission.bytes == 0


@pytest.mark.parametrize(
    "settings",
    [{"response_cache_bytes": 0}, {"gzip_level": 0}, {"cors_origins": ["https://example.org"]}],
)
def test_the_lane_answers_as_the_chain_in_other_settings(settings: dict[str, Any]) -> None:
    lane = TestClient(create_app(Settings(**settings)))
    chain = TestClient(create_app(Settings(**settings, fast_lane_seconds=0)))
    for url in (f"{D4B}?{SMALL}", f"{D4B}?{SMALL}&format=csv", f"{D4B}?{SMALL}&d=2"):
        for _ in range(2):
            headers = {"Accept-Encoding": "gzip"}
            assert raw(lane, "GET", url, headers) == raw(chain, "GET", url, headers)
    fast = lane_of(lane.app)  # type: ignore[arg-type]
    assert fast is not None and fast.served == 4


def test_sequence_fields_are_those_fastapi_reads_as_lists() -> None:
    seen = set()
    for entry in DISCRETIZATIONS.values():
        for name, field in entry.query.model_fields.items():
            expected = field_annotation_is_sequence(field.annotation)
            assert is_sequence(field.annotation) == expected, (entry.info.id, name)
            seen.add(expected)
    assert seen == {True, False}


@pytest.mark.parametrize("checks", ["none", "theorem-6", "failed"])
def test_a_theorem_whose_check_is_left_out_is_a_422_naming_checks(
    clients: tuple[TestClient, TestClient], checks: str
) -> None:
    """``checks`` that leaves the statement's own check out (``failed``: theorem 5 holds) was a
    500 (a missing check); now the chain's 422, the same with and without the lane."""
    for client in clients:
        response = client.get(f"/theorems/theorem-5?{SMALL}&checks={checks}")
        assert response.status_code == 422
        assert response.headers["content-type"] == "application/problem+json"
        [error] = response.json()["errors"]
        assert error["parameter"] == "checks"
        assert error["value"] == checks
        assert "theorem-5" in error["constraint"]


def test_replies_without_accept_encoding_refill_their_template_as_the_chain_answers() -> None:
    """Without Accept-Encoding the lane refills the headers of the last reply of the same kind
    (``_Template``): every kind, computed and repeated, still answers as the chain."""
    lane = TestClient(create_app(Settings()))
    chain = TestClient(create_app(Settings(fast_lane_seconds=0)))
    for client in (lane, chain):
        client.headers.pop("accept-encoding", None)
    queries = [f"{SMALL}&d={d}" for d in (0.1, 0.11, 0.12)]
    urls = [
        *(f"{D4B}?{q}" for q in queries),
        *(f"{D4B}?{q}&checks=none" for q in queries),
        *(f"{D4B}?{q}&format={f}" for q in queries[:2] for f in ("csv", "npy", "svg")),
        *(f"/theorems/theorem-5?{q}" for q in queries[:2]),
        "/discretizations/d1?i_min=-4&i_max=4",
        "/discretizations/d1?i_min=-4&i_max=5",
    ]
    for url in [*urls, *urls]:  # computed, then kept
        expected = raw(chain, "GET", url, {})
        got = raw(lane, "GET", url, {})
        assert all(name != b"content-encoding" for name, _ in got[1])
        assert got == expected, url
    fast = lane_of(lane.app)  # type: ignore[arg-type]
    assert fast is not None
    assert fast.served == 2 * len(urls)
    assert fast.templates


@pytest.mark.parametrize(
    "query",
    [
        "",
        "a=1",
        "a=1&b=2",
        "a=&b",
        "&&a=1&&",
        "=1&a==2",
        "a=1;b=2",
        "a=%20b&c=d",
        "a=b+c",
        "checks=theorem-5,theorem-6&d=0.25",
        "x=\u00e9",
    ],
)
def test_split_query_reads_a_query_as_parse_qsl(query: str) -> None:
    assert split_query(query) == parse_qsl(query, keep_blank_values=True)


def test_a_computed_answer_is_kept_once_it_is_sent() -> None:
    """The lane sends a computed answer first and keeps it after (``FastLane._keep``): while
    the body goes out nothing is kept yet; afterwards the cache holds the same bytes (copied
    out of the encoder's buffer), the raw request answers from it, and the answers agree."""
    app = create_app(Settings())
    cache = app.state.response_cache
    url = f"{D4B}?{SMALL}&checks=none&d=0.2345"
    path, _, query = url.partition("?")
    seen: list[tuple[int, int]] = []

    async def call() -> bytes:
        scope = {
            "type": "http",
            "asgi": {"version": "3.0"},
            "http_version": "1.1",
            "method": "GET",
            "scheme": "http",
            "path": path,
            "raw_path": path.encode(),
            "query_string": query.encode(),
            "root_path": "",
            "headers": [(b"host", b"test")],
            "client": ("127.0.0.1", 1),
            "server": ("127.0.0.1", 80),
        }
        body = b""

        async def receive() -> dict[str, Any]:
            return {"type": "http.request", "body": b"", "more_body": False}

        async def send(message: dict[str, Any]) -> None:
            nonlocal body
            if message["type"] == "http.response.body":
                body = message["body"]
                seen.append((len(cache), cache.fast_hits))

        await app(scope, receive, send)
        return body

    TestClient(app).get("/health")  # builds the middleware stack
    first = anyio.run(call)
    assert seen == [(0, 0)]  # nothing kept while the answer was sent
    [kept] = cache._entries.values()
    assert kept.body == first and kept.body is not first
    again = anyio.run(call)
    assert again == first and seen[1] == (1, 1)  # the raw request, from the cache
    fast = lane_of(app)
    assert fast is not None and fast.served == 2
