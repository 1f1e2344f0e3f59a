"""The response cache's bound holds for the memory its entries really hold (tracemalloc), not
only for the bytes of their bodies: many small entries are where per-entry costs add up."""

from __future__ import annotations

import gc
import tracemalloc

import orjson
from fastapi.testclient import TestClient
from starlette.responses import Response

from app.main import create_app
from app.response_cache import Entry, ResponseCache, entry_of
from app.settings import Settings

BOUND = 1 << 20


def _small_requests(count: int) -> list[str]:
    urls = []
    for k in range(count):
        urls += [
            f"/discretizations/d4b?d=0.{k + 1000}&i_min=-3&i_max=3",
            f"/theorems/theorem-5?d=0.{k + 1000}",
            f"/discretizations/d1?c=0.{k + 1000}&format=csv",
        ]
    return urls


def test_the_bound_covers_what_the_kept_entries_hold() -> None:
    app = create_app(Settings(response_cache_bytes=BOUND))
    client = TestClient(app)
    cache: ResponseCache = app.state.response_cache
    tracemalloc.start()
    try:
        for url in _small_requests(200):  # more than fit: the cache evicts
            assert client.get(url).status_code == 200
        gc.collect()
        charged = cache.bytes + cache.alias_bytes
        kept = len(cache)
        held = tracemalloc.get_traced_memory()[0]
        cache.clear()
        gc.collect()
        freed = held - tracemalloc.get_traced_memory()[0]
    finally:
        tracemalloc.stop()
    assert cache.evictions > 0 and kept > 50
    assert charged <= BOUND
    # what clearing the cache gave back is what its entries held: within the charge, and the
    # charge is not far above it (before: 18.3 kB held per entry charged 7.9 kB)
    assert 0.7 * charged <= freed <= charged, (freed, charged, kept)


def test_a_kept_body_is_an_object_of_its_own_size() -> None:
    """orjson's bytes keep the encoder's whole buffer; the cache keeps a copy of the bytes."""
    document = {"values": list(range(3000))}
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        body = orjson.dumps(document)
        encoded = tracemalloc.get_traced_memory()[0] - before
        entry = entry_of(Response(body, media_type="application/json"))
        assert isinstance(entry, Entry) and entry.body == body
        del body
        gc.collect()
        kept = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert encoded > 1.5 * len(entry.body)  # the encoder's capacity (orjson 3.x)
    assert kept < len(entry.body) + 4096  # the body and the entry's small parts
