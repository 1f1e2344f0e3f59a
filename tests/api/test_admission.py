"""Admission control: a bounded queue, a cost budget per worker, deadlines from arrival, /ready."""

from __future__ import annotations

import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.admission import Admission, OverloadedError, Ticket
from app.main import create_app
from app.settings import Settings

CURVE = "/discretizations/d4b"


def _ticket(seconds: float = 20.0) -> Ticket:
    now = time.monotonic()
    return Ticket(arrival=now, deadline=now + seconds)


def test_a_worker_with_nothing_admitted_admits_one_request() -> None:
    admission = Admission(Settings(admission_seconds=1.0))
    admission.charge(_ticket(), 0.9, 10)
    assert admission.admitted == 1 and admission.seconds == pytest.approx(0.9)


def test_work_beyond_the_budget_is_refused_with_a_retry_after() -> None:
    admission = Admission(Settings(admission_seconds=1.0))
    first = _ticket()
    admission.charge(first, 0.9, 10)
    with pytest.raises(OverloadedError, match="time budget") as refused:
        admission.charge(_ticket(), 0.2, 10)
    assert refused.value.retry_after >= 1
    admission.release(first)
    assert admission.admitted == 0 and admission.seconds == 0
    admission.charge(_ticket(), 0.2, 10)  # room again


def test_memory_beyond_the_budget_is_refused() -> None:
    admission = Admission(Settings(admission_bytes=2**20))
    admission.charge(_ticket(), 0.01, 2**19)
    with pytest.raises(OverloadedError, match="memory budget"):
        admission.charge(_ticket(), 0.01, 2**19 + 1)


def test_one_request_may_charge_several_times() -> None:
    admission = Admission(Settings(admission_seconds=1.0))
    ticket = _ticket()
    admission.charge(ticket, 0.6, 0)
    admission.charge(ticket, 0.6, 0)  # its own earlier charge does not count as another's
    assert admission.admitted == 1 and ticket.seconds == pytest.approx(1.2)


def test_an_admitted_request_is_not_refused_half_way_for_the_budget() -> None:
    admission = Admission(Settings(admission_seconds=1.0))
    first, second = _ticket(), _ticket()
    admission.charge(first, 0.5, 0)
    admission.charge(second, 0.4, 0)
    admission.charge(first, 0.5, 0)  # its next row: over the budget, but already admitted
    assert admission.admitted == 2 and admission.seconds == pytest.approx(1.4)
    with pytest.raises(OverloadedError, match="time budget"):
        admission.charge(_ticket(), 0.1, 0)  # a new request is refused


def test_a_request_that_cannot_finish_before_its_deadline_is_refused_before_it_starts() -> None:
    admission = Admission(Settings())
    with pytest.raises(OverloadedError, match="cannot finish within"):
        admission.charge(_ticket(seconds=0.5), 1.0, 0)


@pytest.fixture
def client() -> Iterator[TestClient]:
    with TestClient(create_app(Settings(response_cache_bytes=2**24))) as client:
        yield client


def test_ready_says_whether_the_worker_admits_work(client: TestClient) -> None:
    ok = client.get("/ready")
    assert ok.status_code == 200 and ok.json() == {"status": "ready"}
    admission: Admission = client.app.state.admission  # type: ignore[attr-defined]
    admission.draining = True
    refused = client.get("/ready")
    assert refused.status_code == 503
    assert refused.headers["content-type"] == "application/problem+json"
    assert int(refused.headers["retry-after"]) >= 1
    assert "shutting down" in refused.json()["detail"]
    assert client.get("/health").status_code == 200  # liveness is not readiness
    busy = client.get(CURVE, params={"i_max": 10})
    assert busy.status_code == 503 and busy.json()["type"].endswith("/overloaded")


def test_ready_reports_the_bytes_the_response_cache_holds(client: TestClient) -> None:
    """bench/load.py reads it to tell the cache filling up from a leak."""
    cache = client.app.state.response_cache  # type: ignore[attr-defined]
    empty = int(client.get("/ready").headers["x-response-cache-bytes"])
    assert empty == cache.bytes + cache.alias_bytes
    assert client.get(CURVE, params={"i_max": 12, "d": 0.25}).status_code == 200
    held = int(client.get("/ready").headers["x-response-cache-bytes"])
    assert held > empty
    assert held == cache.bytes + cache.alias_bytes <= cache.max_bytes


def test_a_full_queue_is_an_immediate_503_and_cheap_requests_still_pass(
    client: TestClient,
) -> None:
    assert client.get(CURVE, params={"i_max": 10}).status_code == 200
    admission: Admission = client.app.state.admission  # type: ignore[attr-defined]
    settings = admission.settings
    admission.in_flight = settings.compute_threads + settings.admission_queue
    refused = client.get(CURVE, params={"i_max": 11})
    assert refused.status_code == 503
    assert refused.headers["content-type"] == "application/problem+json"
    assert int(refused.headers["retry-after"]) >= 1
    assert refused.json()["status"] == 503
    assert "queue" in refused.json()["detail"]
    assert client.get("/health").status_code == 200
    assert client.get("/discretizations").status_code == 200
    assert client.get("/ready").status_code == 503
    cached = client.get(CURVE, params={"i_max": 10})  # answered by the response cache
    assert cached.status_code == 200
    admission.in_flight = 0


def test_work_over_the_budget_is_a_503_problem_before_any_computation(
    client: TestClient,
) -> None:
    admission: Admission = client.app.state.admission  # type: ignore[attr-defined]
    other = _ticket()
    admission.charge(other, admission.settings.admission_seconds, 0)  # another request's work
    refused = client.get(CURVE, params={"i_max": 5000, "d": 0.001})
    assert refused.status_code == 503
    body = refused.json()
    assert body["type"] == "/problems/overloaded"
    assert "budget" in body["detail"]
    assert refused.headers["cache-control"] == "no-store"
    assert "etag" not in refused.headers
    admission.release(other)
    assert client.get(CURVE, params={"i_max": 5000, "d": 0.001}).status_code == 200
    assert admission.admitted == 0 and admission.seconds == 0  # released after the answer


def test_a_slow_host_scales_the_estimates() -> None:
    admission = Admission(Settings())
    for _ in range(20):
        admission.observe(1.0, 4.0)  # computations alone took 4× their estimate
    assert admission.slowdown == pytest.approx(4.0, rel=0.05)
    admission.observe(0.001, 100.0)  # too small to tell anything
    assert admission.slowdown == pytest.approx(4.0, rel=0.05)
    with pytest.raises(OverloadedError, match="cannot finish within 20 s"):
        admission.charge(_ticket(), 6.0, 0)  # 6 s of CPU take about 24 s now
    admission.charge(_ticket(), 4.0, 0)


def test_a_computation_alone_teaches_the_slowdown(client: TestClient) -> None:
    admission: Admission = client.app.state.admission  # type: ignore[attr-defined]
    before = admission.generation
    assert client.get(CURVE, params={"i_max": 2000, "d": 0.01}).status_code == 200
    assert admission.generation == before + 1
    assert admission.slowdown >= 1.0


def test_the_watchdog_never_stops_a_thread_inside_the_balls_precision_lock() -> None:
    """With no compute processes, mp curves hold the balls' lock in the worker: the watchdog's
    asynchronous stop waits until the lock is released (it could leave the lock held)."""
    from app.admission import WATCHDOG, HardStopError, holds_precision_lock
    from app.geometry import balls

    now = time.monotonic()
    ticket = Ticket(arrival=now, deadline=now)
    seen: dict[str, Any] = {}
    started = threading.Event()

    def run() -> None:
        try:
            with balls.LOCK:
                seen["held"] = holds_precision_lock(threading.get_ident())
                ticket.thread = threading.get_ident()
                WATCHDOG.watch(ticket, time.monotonic())  # overdue at once
                started.set()
                end = time.monotonic() + 0.6
                while time.monotonic() < end:  # bytecodes where a stop could land
                    pass
            seen["released"] = time.monotonic()
            while time.monotonic() < end + 5:
                pass
        except HardStopError:
            seen["stopped"] = time.monotonic()
        finally:
            ticket.thread = None  # done (as ``computing`` does): the watchdog lets it be

    thread = threading.Thread(target=run)
    thread.start()
    started.wait(5)
    thread.join(10)
    assert seen["held"] is True
    assert not holds_precision_lock(threading.get_ident())
    assert seen["stopped"] >= seen["released"]  # stopped, but only once out of the lock
    assert balls.LOCK.acquire(blocking=False)  # and the lock is free
    balls.LOCK.release()


def test_the_workers_keep_their_request_threads_between_bursts(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A server worker keeps idle request threads for an hour (app.server.keep_request_threads)
    through anyio's knob, which anyio's thread pool still reads when it prunes idle threads."""
    import inspect

    from anyio._backends import _asyncio as backend

    from app import server

    monkeypatch.setattr(backend.WorkerThread, "MAX_IDLE_TIME", backend.WorkerThread.MAX_IDLE_TIME)
    server.keep_request_threads()
    assert backend.WorkerThread.MAX_IDLE_TIME == server.REQUEST_THREAD_IDLE_SECONDS == 3600
    pruning = inspect.getsource(backend.AsyncIOBackend.run_sync_in_worker_thread)
    assert "WorkerThread.MAX_IDLE_TIME" in pruning


#: Heavy GETs a worker at its budget refuses: float64 beyond the lane's estimate, and mp.
REFUSED_HEAVY = [
    "/discretizations/d4b?h=1.1&d=0.0001&method=closed-form&i_min=-500000&i_max=500000",
    "/discretizations/d1?c=0.0001&delta=0.001&i_min=-500000&i_max=500000&format=npy",
    "/discretizations/d4b?h=1.1&precision=mp&digits=50&i_min=-1249&i_max=1249",
]


@pytest.mark.parametrize("url", REFUSED_HEAVY)
def test_a_heavy_get_the_worker_refuses_is_the_chains_503_from_the_fast_lane(url: str) -> None:
    from tests.api.test_fast_lane import lane_of

    answers = []
    for lane_seconds in (0.002, 0.0):  # the lane, then the chain alone
        app = create_app(Settings(compute_processes=0, fast_lane_seconds=lane_seconds))
        state: Admission = app.state.admission
        state.bytes, state.seconds, state.admitted = 1600 * 2**20, 11.9, 1  # at its budget
        client = TestClient(app)
        response = client.get(url, headers={"Accept-Encoding": "gzip, deflate"})
        lane = lane_of(app)
        answers.append((response.status_code, response.headers.raw, response.content))
        assert (state.refused, state.admitted, state.seconds) == (1, 1, 11.9)
        assert (lane.served if lane is not None else 0) == (1 if lane_seconds else 0)
    assert answers[0] == answers[1]
    assert answers[0][0] == 503 and b"retry-after" in dict(answers[0][1])


def test_a_heavy_get_the_worker_admits_is_charged_once_and_computed_by_the_chain() -> None:
    from tests.api.test_fast_lane import lane_of

    app = create_app(Settings(compute_processes=0))
    state: Admission = app.state.admission
    client = TestClient(app)
    url = "/discretizations/d4b?d=0.001&i_min=-3000&i_max=3000"  # above the lane's estimate
    response = client.get(url)
    assert response.status_code == 200 and len(response.json()["vertices"]) == 6001
    lane = lane_of(app)
    assert lane is not None and lane.served == 0
    assert (state.admitted, state.seconds, state.bytes, state.refused) == (0, 0.0, 0, 0)
    # a cached answer is never refused, busy or not
    state.bytes, state.seconds, state.admitted = 1600 * 2**20, 11.9, 1
    again = client.get("/discretizations/d4b?i_max=3000&i_min=-3000&d=0.001")
    assert again.status_code == 200 and again.content == response.content
