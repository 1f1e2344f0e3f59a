"""Identical requests in flight are computed once (app/response_cache.py, ``FastPath``)."""

from __future__ import annotations

import time

import anyio
import httpx
from starlette.types import Receive, Scope, Send

from app.admission import CURRENT, Ticket
from app.main import create_app
from app.response_cache import FastPath, ResponseCache
from app.settings import Settings

#: A curve that takes a while to compute (a 40 001-step construction), so the copies overlap.
CURVE = "/discretizations/d4b?d=0.001&i_min=-20000&i_max=20000&format=npy"


async def _together(app: object, urls: list[str]) -> list[httpx.Response]:
    transport = httpx.ASGITransport(app=app)  # type: ignore[arg-type]
    async with httpx.AsyncClient(transport=transport, base_url="http://test") as client:
        responses: list[httpx.Response] = [httpx.Response(0)] * len(urls)

        async def one(i: int) -> None:
            responses[i] = await client.get(urls[i])

        async with anyio.create_task_group() as group:
            for i in range(len(urls)):
                group.start_soon(one, i)
    return responses


def test_identical_requests_in_flight_are_computed_and_charged_once() -> None:
    app = create_app(Settings())
    cache: ResponseCache = app.state.response_cache
    charges: list[float] = []
    admission = app.state.admission
    charge = admission.charge

    def counting_charge(ticket: Ticket, seconds: float, nbytes: int) -> None:
        charges.append(seconds)
        charge(ticket, seconds, nbytes)

    admission.charge = counting_charge
    responses = anyio.run(_together, app, [CURVE] * 8)
    assert [r.status_code for r in responses] == [200] * 8
    assert len({r.content for r in responses}) == 1
    assert len(responses[0].content) == 128 + 40_001 * 2 * 8  # the npy header and the vertices
    assert cache.misses == 1  # one computation
    assert len(charges) >= 1 and admission.admitted == 0 and admission.seconds == 0
    assert cache.fast_hits == 7  # after waiting for the first (coalesced) or after it ended
    assert 0 <= cache.coalesced <= 7
    single = len(charges)  # what one request charges
    # the same query once more: answered from the cache, nothing charged
    again = anyio.run(_together, app, [CURVE])
    assert again[0].content == responses[0].content and len(charges) == single


def test_different_requests_are_not_coalesced() -> None:
    app = create_app(Settings())
    cache: ResponseCache = app.state.response_cache
    urls = [f"/discretizations/d4b?d=0.00{k}&i_min=-2000&i_max=2000" for k in range(1, 5)]
    responses = anyio.run(_together, app, urls)
    assert [r.status_code for r in responses] == [200] * 4
    assert len({r.content for r in responses}) == 4
    assert cache.misses == 4 and cache.coalesced == 0


def test_requests_waiting_for_a_failure_get_their_own_answer() -> None:
    app = create_app(Settings())
    cache: ResponseCache = app.state.response_cache
    responses = anyio.run(_together, app, ["/discretizations/d4b?d=2"] * 5)
    # nothing kept: each is answered on its own, with the problem naming the parameter
    assert [r.status_code for r in responses] == [422] * 5
    assert all(r.json()["errors"][0]["parameter"] == "d" for r in responses)
    assert cache.coalesced == 0 and len(cache) == 0


def test_a_waiting_request_goes_on_alone_at_its_deadline() -> None:
    """The first request never finishes; the second waits until its own deadline, then is
    served as if it had arrived alone (here by the inner app's second answer)."""
    release = anyio.Event()
    calls: list[str] = []

    async def inner(scope: Scope, receive: Receive, send: Send) -> None:
        calls.append("call")
        number = len(calls)
        if number == 1:
            await release.wait()
        body = f"answer {number}".encode()
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": body})

    settings = Settings()
    fast = FastPath(inner, ResponseCache(2**20, 2**20), settings)
    scope: Scope = {
        "type": "http",
        "method": "GET",
        "path": "/discretizations/d4b",
        "query_string": b"d=0.3",
        "headers": [],
    }
    sent: list[bytes] = []

    async def receive() -> dict[str, object]:
        return {"type": "http.request", "body": b"", "more_body": False}

    async def first(send: Send) -> None:
        await fast(scope, receive, send)

    async def collect(message: dict[str, object]) -> None:
        if message["type"] == "http.response.body":
            sent.append(message["body"])  # type: ignore[arg-type]

    async def second() -> None:
        now = time.monotonic()
        token = CURRENT.set(Ticket(arrival=now, deadline=now + 0.2))
        try:
            await fast(scope, receive, collect)  # type: ignore[arg-type]
        finally:
            CURRENT.reset(token)
        release.set()

    async def main() -> None:
        async with anyio.create_task_group() as group:
            group.start_soon(first, collect)
            await anyio.sleep(0)  # the first one is in flight
            group.start_soon(second)

    anyio.run(main)
    assert sent == [b"answer 2", b"answer 1"]
