"""The response cache (hits, bound, eviction, ETags, fast path), gzip and format=npy."""

from __future__ import annotations

import gzip
import io
import random
import threading

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.response_cache import (
    ALIAS_OVERHEAD,
    ENTRY_OVERHEAD,
    Entry,
    ResponseCache,
    accepts_gzip,
    etag_for,
)
from app.responses import canonical_key
from app.schemas.d4b import D4bQuery
from app.settings import Settings

IDENTITY = {"Accept-Encoding": "identity"}
GZIP = {"Accept-Encoding": "gzip"}


def make_client(**settings: int) -> TestClient:
    return TestClient(create_app(Settings(**settings)))


def cache_of(client: TestClient) -> ResponseCache:
    cache: ResponseCache = client.app.state.response_cache  # type: ignore[attr-defined]
    return cache


def d4b_key(**params: object) -> str:
    return canonical_key("/discretizations/d4b", D4bQuery.model_validate(params).model_dump())


def test_a_repeated_query_is_a_hit_with_the_same_body_and_etag(client: TestClient) -> None:
    cache = cache_of(client)
    first = client.get("/discretizations/d4b", params={"d": 0.2}, headers=IDENTITY)
    assert (cache.misses, cache.hits, len(cache)) == (1, 0, 1)
    # a different spelling of the same query: validated to the same canonical key
    spelled = client.get("/discretizations/d4b?d=0.20&h=1", headers=IDENTITY)
    again = client.get("/discretizations/d4b", params={"d": 0.2}, headers=IDENTITY)
    assert cache.hits == 2 and cache.fast_hits == 1 and len(cache) == 1
    for response in (spelled, again):
        assert response.status_code == 200
        assert response.content == first.content
        assert response.headers["etag"] == first.headers["etag"] == etag_for(d4b_key(d=0.2))
        assert response.headers["cache-control"] == first.headers["cache-control"]
        assert "Accept-Encoding" in response.headers["vary"]


def test_the_fast_path_answers_exactly_as_the_full_path(client: TestClient) -> None:
    url = "/discretizations/d4b?d=0.3&i_max=4&format=csv"
    headers = {**GZIP, "Origin": "https://example.org"}
    full = client.get(url, headers=headers)
    fast = client.get(url, headers=headers)
    assert cache_of(client).fast_hits == 1
    assert fast.content == full.content
    assert dict(fast.headers) == dict(full.headers)  # CORS and security headers included
    revalidated = client.get(url, headers={"If-None-Match": full.headers["etag"]})
    assert revalidated.status_code == 304
    assert revalidated.headers["etag"] == full.headers["etag"]


def test_get_and_post_share_one_entry(client: TestClient) -> None:
    params = {"h": 2.0, "d": 0.3, "i_min": -4, "i_max": 7}
    got = client.get("/discretizations/d4b", params=params, headers=IDENTITY)
    posted = client.post("/discretizations/d4b", json=params, headers=IDENTITY)
    assert cache_of(client).hits == 1 and len(cache_of(client)) == 1
    assert posted.content == got.content
    assert "etag" not in posted.headers


def test_errors_are_not_kept(client: TestClient) -> None:
    for _ in range(2):
        assert client.get("/discretizations/d4b", params={"d": 2}).status_code == 422
    assert len(cache_of(client)) == 0 and cache_of(client).hits == 0


def test_the_cache_stays_within_its_bound_and_evicts_the_least_recently_used() -> None:
    one = len(make_client().get("/discretizations/d4b?d=0.1", headers=IDENTITY).content)
    # three bodies, their keys (~300 bytes), entries and the fast path's raw requests
    room = 3 * (one + 300 + ENTRY_OVERHEAD + 300 + ALIAS_OVERHEAD) + 1000
    assert room < 4 * one
    client = make_client(response_cache_bytes=room, gzip_level=0)
    cache = cache_of(client)
    for d in (0.1, 0.2, 0.3):
        client.get("/discretizations/d4b", params={"d": d})
    assert len(cache) == 3
    client.get("/discretizations/d4b", params={"d": 0.1})  # 0.1 is now the most recent
    client.get("/discretizations/d4b", params={"d": 0.4})  # evicts 0.2, the least recent
    assert cache.evictions == 1 and cache.bytes <= cache.max_bytes and len(cache) == 3
    assert d4b_key(d=0.2) not in cache
    assert all(d4b_key(d=d) in cache for d in (0.1, 0.3, 0.4))
    # an evicted query is computed again, with the same ETag
    before = cache.misses
    again = client.get("/discretizations/d4b", params={"d": 0.2})
    assert cache.misses == before + 1 and again.headers["etag"] == etag_for(d4b_key(d=0.2))


def test_oversize_bodies_are_served_but_not_kept() -> None:
    client = make_client(response_cache_entry_bytes=10_000)
    response = client.get("/discretizations/d4b", params={"i_max": 200}, headers=IDENTITY)
    assert response.status_code == 200 and len(response.content) > 10_000
    assert len(cache_of(client)) == 0
    assert response.headers["etag"] == etag_for(d4b_key(i_max=200))


def test_a_disabled_cache_still_answers_with_etags() -> None:
    client = make_client(response_cache_bytes=0)
    first = client.get("/discretizations/d4b", headers=IDENTITY)
    assert len(cache_of(client)) == 0
    assert client.get("/discretizations/d4b").content == first.content
    assert first.headers["etag"] == etag_for(d4b_key())


def test_concurrent_use_keeps_the_accounting_exact() -> None:
    cache = ResponseCache(max_bytes=50_000, max_entry_bytes=20_000)

    def work(seed: int) -> None:
        rng = random.Random(seed)
        for _ in range(300):
            key = f"k{rng.randrange(40)}"
            if cache.get(key) is None:
                cache.put(key, Entry(200, (), b"x" * rng.randrange(100, 5000), "text/plain"))
            cache.alias(("/p", key.encode()), key)
            cache.lookup(("/p", key.encode()))

    threads = [threading.Thread(target=work, args=(seed,)) for seed in range(8)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    kept = list(cache._entries.values())
    assert cache.bytes == sum(entry.size for entry in kept) <= cache.max_bytes
    assert cache.evictions > 0


def test_gzip_when_accepted_with_its_own_etag(client: TestClient) -> None:
    plain = client.get("/discretizations/d4b", headers=IDENTITY)
    packed = client.get("/discretizations/d4b", headers=GZIP)
    assert "content-encoding" not in plain.headers
    assert packed.headers["content-encoding"] == "gzip"
    assert packed.content == plain.content  # httpx decompresses
    assert packed.headers["etag"] == plain.headers["etag"][:-1] + '-gzip"'
    assert "Accept-Encoding" in packed.headers["vary"]
    raw = client.get("/discretizations/d4b", headers=GZIP)  # from the cache: compressed once
    assert cache_of(client)._entries[d4b_key()].gzipped is not None
    assert gzip.decompress(cache_of(client)._entries[d4b_key()].gzipped or b"") == plain.content
    assert raw.headers["etag"] == packed.headers["etag"]
    for tag in (plain.headers["etag"], packed.headers["etag"]):
        revalidated = client.get("/discretizations/d4b", headers={**GZIP, "If-None-Match": tag})
        assert revalidated.status_code == 304 and revalidated.headers["etag"] == tag


def test_gzip_is_skipped_for_small_binary_refused_or_disabled() -> None:
    client = make_client()
    tiny = client.get("/health", headers=GZIP)
    assert "content-encoding" not in tiny.headers
    small = client.get("/discretizations/d4b?i_min=0&i_max=0&format=csv", headers=GZIP)
    assert len(small.content) < 1024 and "content-encoding" not in small.headers
    binary = client.get("/discretizations/d4b?i_max=500&format=npy", headers=GZIP)
    assert "content-encoding" not in binary.headers
    refused = client.get("/discretizations/d4b", headers={"Accept-Encoding": "gzip;q=0, br"})
    assert "content-encoding" not in refused.headers
    off = make_client(gzip_level=0).get("/discretizations/d4b", headers=GZIP)
    assert "content-encoding" not in off.headers
    big = make_client(gzip_max_bytes=10_000).get("/discretizations/d4b", headers=GZIP)
    assert len(big.content) > 10_000 and "content-encoding" not in big.headers


@pytest.mark.parametrize(
    ("header", "expected"),
    [
        ("gzip", True),
        ("deflate, gzip;q=0.5", True),
        ("GZIP", True),
        ("gzip;q=0", False),
        ("gzip;q=0.0, *", False),
        ("*", True),
        ("*;q=0", False),
        ("identity", False),
        ("br, zstd", False),
        ("gzip;q=oops", False),
        ("", False),
        (None, False),
    ],
)
def test_accept_encoding_parsing(header: str | None, expected: bool) -> None:
    assert accepts_gzip(header) is expected


def test_npy_round_trip_equals_the_json(client: TestClient) -> None:
    params = {"d": 0.3, "beta0": 1.2, "i_min": -7, "i_max": 12}
    body = client.get("/discretizations/d4b", params=params).json()
    response = client.get("/discretizations/d4b", params={**params, "format": "npy"})
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/x-npy"
    assert response.headers["x-first-index"] == "-7"
    array = np.load(io.BytesIO(response.content), allow_pickle=False)
    assert array.dtype == np.dtype("<f8") and array.shape == (20, 2)
    np.testing.assert_array_equal(array, np.array(body["vertices"]))  # bit for bit
    # as documented for clients without numpy: version 1.0, header length in bytes 8–9
    content = response.content
    assert content[:8] == b"\x93NUMPY\x01\x00"
    start = 10 + int.from_bytes(content[8:10], "little")
    raw = np.frombuffer(content[start:], dtype="<f8").reshape(-1, 2)
    np.testing.assert_array_equal(raw, array)
    assert body["indices"] == list(range(-7, 13))
    posted = client.post("/discretizations/d4b", json={**params, "format": "npy"})
    assert posted.content == response.content


@pytest.mark.parametrize(
    "url",
    [
        "/discretizations/d1?i_max=30",
        "/discretizations/d2a-hex",
        "/discretizations/d2b",
        "/discretizations/d4a?method=closed-form",
        "/smooth/tractrix?count=50",
    ],
)
def test_npy_of_every_kind_of_curve_equals_its_json(client: TestClient, url: str) -> None:
    body = client.get(url).json()
    response = client.get(url + "&format=npy" if "?" in url else url + "?format=npy")
    array = np.load(io.BytesIO(response.content), allow_pickle=False)
    np.testing.assert_array_equal(array, np.array(body["vertices"], dtype=float))
    assert int(response.headers["x-first-index"]) == body["indices"][0]


def test_npy_needs_float64(client: TestClient) -> None:
    response = client.get("/discretizations/d4b", params={"format": "npy", "precision": "mp"})
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    [error] = response.json()["errors"]
    assert error["parameter"] == "format" and "precision=float64" in error["constraint"]


def test_health_is_bare_bytes(client: TestClient) -> None:
    response = client.get("/health")
    assert response.headers["content-type"] == "application/json"
    assert response.content.startswith(b'{"status":"ok","version":')
