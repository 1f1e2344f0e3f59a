"""Heavy requests computed in a worker's child processes (app/compute_pool.py): the same answers
as in the worker, the same problems, and children that overrun or die are replaced."""

from __future__ import annotations

import os
import signal
import socket
import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app import admission
from app.compute_pool import ComputePool, PoolBusyError, _Job
from app.geometry import balls
from app.main import create_app
from app.routers import common
from app.settings import Settings

CURVE = "/discretizations/d4b"
#: Estimated well above DCOSH_POOL_MIN_SECONDS (0.05 s): computed in a child by default.
HEAVY = {"d": 1e-3, "i_min": -15_000, "i_max": 15_000}


#: The time limit of the pooled apps whose tests compare answers, not clocks. The children run
#: under SCHED_IDLE (app/compute_pool.py), so on a busy host (a CI runner, other suites beside
#: this one) any runnable process preempts them: a 3 s heavy request took 22 s there and came
#: back as the time-limit problem under the default 20 s.
ROOMY_TIME_LIMIT = 600.0


def pooled(settings: Settings) -> tuple[TestClient, ComputePool]:
    """A client of an app whose worker has a pool, as app/server.py starts it (with
    ``ROOMY_TIME_LIMIT`` unless ``settings`` sets a time limit of its own)."""
    if "time_limit" not in settings.model_fields_set:
        settings = settings.model_copy(update={"time_limit": ROOMY_TIME_LIMIT})
    app = create_app(settings)
    pool = ComputePool(settings)
    pool.start()
    app.state.admission.pool = pool
    return TestClient(app), pool


def children(pool: ComputePool) -> list[int]:
    """The pool's children once it has all of them again (replacements fork in the
    background)."""
    for _ in range(200):
        pids = pool.pids()
        if len(pids) == pool.size:
            return pids
        time.sleep(0.05)
    raise AssertionError(f"{pool.size} children expected, {len(pool.pids())} found")


def kill(pid: int) -> None:
    """SIGKILL ``pid`` and wait until it has died (a zombie until the pool reaps it)."""
    os.kill(pid, signal.SIGKILL)
    for _ in range(200):
        try:
            with open(f"/proc/{pid}/stat") as stat:
                if stat.read().rsplit(")", 1)[1].split()[0] in ("Z", "X"):
                    return
        except FileNotFoundError:
            return
        time.sleep(0.05)
    raise AssertionError(f"{pid} still runs")


def reaped(pid: int) -> None:
    """Wait until the pool has reaped ``pid`` (its reaper is a thread, slow on a busy host)."""
    for _ in range(400):
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return
        time.sleep(0.05)
    raise AssertionError(f"{pid} was not reaped")


@pytest.fixture
def pool_client() -> Iterator[tuple[TestClient, ComputePool]]:
    client, pool = pooled(Settings(compute_processes=1))
    yield client, pool
    pool.close()


@pytest.mark.parametrize("response_format", ["json", "npy", "csv"])
def test_a_heavy_request_from_a_child_is_the_workers_answer_byte_for_byte(
    pool_client: tuple[TestClient, ComputePool], response_format: str
) -> None:
    client, pool = pool_client
    params = {**HEAVY, "format": response_format}
    here = TestClient(create_app(Settings(compute_processes=0))).get(CURVE, params=params)
    there = client.get(CURVE, params=params)
    assert here.status_code == there.status_code == 200
    assert there.content == here.content
    for header in ("content-type", "etag", "x-first-index", "content-length"):
        assert there.headers.get(header) == here.headers.get(header), header
    assert pool.jobs == 1  # a child computed and rendered it


def test_precision_mp_from_a_child_is_the_workers_answer(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    client, pool = pool_client
    body = {"precision": "mp", "digits": 30, "d": 0.12345678901234567890123, "i_max": 200}
    here = TestClient(create_app(Settings(compute_processes=0))).post(CURVE, json=body)
    there = client.post(CURVE, json=body)
    assert here.status_code == there.status_code == 200
    assert there.content == here.content
    assert pool.jobs == 1


def test_a_domain_error_in_a_child_is_the_same_422(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    client, _ = pool_client
    params = {**HEAVY, "d": 2}  # the core refuses d >= h, in the child
    here = TestClient(create_app(Settings(compute_processes=0))).get(CURVE, params=params)
    there = client.get(CURVE, params=params)
    assert here.status_code == there.status_code == 422
    assert there.headers["content-type"] == "application/problem+json"
    assert there.json() == here.json()
    assert there.json()["errors"][0]["parameter"] == "d"


def _hang(*args: Any) -> Any:
    time.sleep(600)


def _die(*args: Any) -> Any:
    os.kill(os.getpid(), signal.SIGKILL)


def _out_of_memory(*args: Any) -> Any:
    raise MemoryError


def test_an_overrunning_child_is_killed_and_replaced_with_the_time_limit_problem(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    settings = Settings(compute_processes=1, time_limit=2.0, hard_stop_grace=0.2)
    app = create_app(settings)
    client = TestClient(app)
    client.get(CURVE, params={"i_max": 3})  # the first request pays the app's lazy set-up
    # the children are forked with a renderer that never returns (nothing checks the clock)
    monkeypatch.setattr(common, "curve_response", _hang)
    pool = app.state.admission.pool = ComputePool(settings)
    pool.start()
    try:
        (before,) = children(pool)
        response = client.get(CURVE, params=HEAVY)
        assert response.status_code == 422, response.text
        body = response.json()
        assert body["type"] == "/problems/time-limit"
        assert "stopped past its deadline" in body["detail"]
        assert body["errors"][0]["parameter"] == "i_max"
        assert pool.kills == 1
        (after,) = children(pool)
        assert after != before
        reaped(before)
    finally:
        pool.close()


@pytest.mark.parametrize("failure", [_die, _out_of_memory], ids=["killed", "out-of-memory"])
def test_a_child_that_dies_computing_is_a_503_and_is_replaced(
    monkeypatch: pytest.MonkeyPatch, failure: Any
) -> None:
    monkeypatch.setattr(common, "curve_response", failure)
    client, pool = pooled(Settings(compute_processes=1))
    try:
        (before,) = children(pool)
        response = client.get(CURVE, params=HEAVY)
        assert response.status_code == 503
        assert response.json()["type"] == "/problems/overloaded"
        assert int(response.headers["retry-after"]) >= 1
        assert pool.crashes == 1
        (after,) = children(pool)
        assert after != before
    finally:
        pool.close()


def test_a_child_killed_while_idle_is_replaced_and_the_request_is_answered(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    client, pool = pool_client
    (before,) = children(pool)
    kill(before)
    connection = socket.socketpair()  # open in the worker while the successor forks
    try:
        response = client.get(CURVE, params=HEAVY)
        assert response.status_code == 200
        assert len(response.json()["vertices"]) == 30_001
        (after,) = children(pool)
        assert after != before and pool.crashes == 1
        # the successor holds no socket of the worker's but its own pipe
        sockets = [
            fd
            for fd in os.listdir(f"/proc/{after}/fd")
            if os.readlink(f"/proc/{after}/fd/{fd}").startswith("socket:")
        ]
        assert len(sockets) == 1, sockets
    finally:
        for end in connection:
            end.close()


def scheduler(pid: int) -> int:
    """The scheduling policy of ``pid`` once it has left the one its parent forked it with
    (the child sets its own first thing), or that one after 10 s."""
    for _ in range(200):
        policy = os.sched_getscheduler(pid)
        if policy != os.SCHED_OTHER:
            return policy
        time.sleep(0.05)
    return os.sched_getscheduler(pid)


def test_children_and_their_replacements_run_in_the_idle_scheduling_class(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    # the worker's threads keep the normal class: a request's thread that wakes takes the CPU
    # from a computing child at once
    client, pool = pool_client
    (first,) = children(pool)
    assert scheduler(first) == os.SCHED_IDLE
    kill(first)
    assert client.get(CURVE, params=HEAVY).status_code == 200 and pool.jobs == 1
    (second,) = children(pool)
    assert second != first and scheduler(second) == os.SCHED_IDLE
    assert os.sched_getscheduler(0) == os.SCHED_OTHER


def test_a_cheap_request_stays_in_the_worker(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    client, pool = pool_client
    os.kill(pool.pids()[0], signal.SIGSTOP)  # a child that would never answer
    try:
        assert client.get(CURVE, params={"i_max": 5}).status_code == 200
        assert pool.jobs == 0
    finally:
        os.kill(pool.pids()[0], signal.SIGCONT)


def test_a_cheap_mp_curve_is_computed_in_a_child_never_under_the_watchdog(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    """Balls hold their precision lock throughout: the worker's asynchronous stop could land
    inside it, so precision=mp curves, however cheap, are computed in a child."""
    client, pool = pool_client
    params = {"precision": "mp", "digits": 20, "i_max": 3}
    expected = TestClient(create_app(Settings(compute_processes=0))).get(CURVE, params=params)
    for path in (CURVE, "/theorems/theorem-5"):
        jobs = pool.jobs
        answer = client.get(path, params=params)
        assert answer.status_code == 200, answer.text
        assert pool.jobs == jobs + 1
    assert client.get(CURVE, params=params).content == expected.content  # now from the cache


def test_a_refinement_study_from_a_child_is_the_workers_answer() -> None:
    client, pool = pooled(Settings(compute_processes=1, pool_min_seconds=0))
    try:
        here = TestClient(create_app(Settings(compute_processes=0)))
        for response_format in ("json", "csv"):
            params = {"levels": 4, "format": response_format}
            expected = here.get("/convergence/theorem-14", params=params)
            answer = client.get("/convergence/theorem-14", params=params)
            assert expected.status_code == answer.status_code == 200
            assert answer.content == expected.content
        assert pool.jobs == 2
    finally:
        pool.close()


def test_a_child_forked_while_a_worker_thread_holds_the_balls_lock_computes_mp(
    pool_client: tuple[TestClient, ComputePool],
) -> None:
    """A replacement forks while an in-worker mp request holds the core's precision lock."""
    client, pool = pool_client
    held, release = threading.Event(), threading.Event()

    def hold() -> None:
        with balls.LOCK:
            held.set()
            release.wait(60)

    thread = threading.Thread(target=hold)
    thread.start()
    try:
        held.wait(10)
        kill(children(pool)[0])
        body = {"precision": "mp", "digits": 30, "i_max": 200}
        response = client.post(CURVE, json=body)
        assert response.status_code == 200
        assert pool.jobs == 1 and pool.crashes == 1
    finally:
        release.set()
        thread.join()


#: (path, parameters) of every other endpoint that computes in a child when heavy enough
#: (``pool_min_seconds=0`` sends every one there); small, so that both sides stay quick.
ROUTED = [
    ("/surfaces/catenoid", {"m": 8, "i_min": -5, "i_max": 5}),
    ("/surfaces/catenoid", {"m": 8, "i_min": -5, "i_max": 5, "format": "glb"}),
    ("/surfaces/pseudosphere/d4b", {"m": 6, "i_max": 6, "format": "obj"}),
    ("/surfaces/catenoid-gauss-image", {"m": 6, "precision": "mp", "digits": 20, "i_max": 4}),
    ("/relations", {}),
    ("/relations", {"format": "html", "d4b.d": 0.25}),
    ("/theorems/theorem-5", {"d": 0.2}),
    ("/theorems/theorem-5", {"precision": "mp", "digits": 25, "i_max": 30}),
    ("/theorems/theorem-14", {"levels": 4}),
    ("/figures/figure-7.svg", {"i_min": -6, "i_max": 6}),
    ("/figures/figure-8.svg", {"j": "2,3"}),
    ("/smooth/tractrix", {"count": 21}),
    ("/smooth/catenary", {"count": 5, "precision": "mp", "digits": 20, "format": "csv"}),
]


@pytest.fixture(scope="module")
def both() -> Iterator[tuple[TestClient, TestClient, ComputePool]]:
    """A client whose worker computes everything in one child, and one without a pool."""
    # the fast lane computes tiny float64 GETs (theorem-5 here) on the event loop, never in a
    # child: off in the pooled app, so that every routed request reaches the pool
    client, pool = pooled(Settings(compute_processes=1, pool_min_seconds=0, fast_lane_seconds=0))
    yield client, TestClient(create_app(Settings(compute_processes=0))), pool
    pool.close()


@pytest.mark.parametrize(("path", "params"), ROUTED, ids=[f"{p} {q}" for p, q in ROUTED])
def test_every_routed_endpoint_from_a_child_is_the_workers_answer_byte_for_byte(
    both: tuple[TestClient, TestClient, ComputePool], path: str, params: dict[str, Any]
) -> None:
    client, plain, pool = both
    jobs = pool.jobs
    here = plain.get(path, params=params)
    there = client.get(path, params=params)
    assert here.status_code == there.status_code == 200, there.text
    assert there.content == here.content
    for header in ("content-type", "etag", "content-disposition", "content-length"):
        assert there.headers.get(header) == here.headers.get(header), header
    assert pool.jobs == jobs + 1  # a child computed and rendered it


def test_a_surface_theorem_from_a_child_is_the_workers_answer(
    both: tuple[TestClient, TestClient, ComputePool],
) -> None:
    client, plain, pool = both
    jobs = pool.jobs
    catalog = plain.get("/theorems").json()
    path = next(s["url"] for s in catalog if s["surfaces"] and not s["discretizations"])
    params = {"m": 6, "i_max": 4}
    expected = plain.get(path, params=params)
    answer = client.get(path, params=params)
    assert expected.status_code == answer.status_code == 200, answer.text
    assert answer.content == expected.content
    assert pool.jobs == jobs + 1


def test_a_domain_error_of_a_surface_in_a_child_is_the_same_422(
    both: tuple[TestClient, TestClient, ComputePool],
) -> None:
    client, plain, pool = both
    jobs = pool.jobs
    params = {"m": 6, "d": 2}  # the core refuses d >= h, in the child
    expected = plain.get("/surfaces/catenoid", params=params)
    answer = client.get("/surfaces/catenoid", params=params)
    assert expected.status_code == answer.status_code == 422
    assert answer.json() == expected.json()
    assert pool.jobs == jobs + 1


@pytest.mark.parametrize(
    ("module", "name", "path", "params", "parameter"),
    [
        ("app.routers.surfaces", "_file", "/surfaces/catenoid", {"m": 8}, "i_max"),
        # the whole child function: the rows it computes before rendering take over the 2 s
        # on a busy host, and the core's own clock check would answer before any kill
        ("app.routers.relations", "render_relations", "/relations", {}, "i_max"),
        ("app.routers.theorems", "respond", "/theorems/theorem-5", {"d": 0.2}, "i_max"),
        ("app.routers.figures", "render", "/figures/figure-7.svg", {}, "i_max"),
        ("app.routers.smooth", "curve_response", "/smooth/tractrix", {}, "count"),
    ],
)
def test_an_overrunning_child_of_every_routed_endpoint_is_the_time_limit_problem(
    monkeypatch: pytest.MonkeyPatch, module: str, name: str, path: str, params: Any, parameter: str
) -> None:
    settings = Settings(
        compute_processes=1,
        time_limit=2.0,
        hard_stop_grace=0.2,
        pool_min_seconds=0,
        fast_lane_seconds=0,  # theorem-5 would take the lane, on the event loop (see ``both``)
    )
    app = create_app(settings)
    client = TestClient(app)
    client.get(CURVE, params={"i_max": 3})  # the first request pays the app's lazy set-up
    monkeypatch.setattr(f"{module}.{name}", _hang)  # the child renders forever
    pool = app.state.admission.pool = ComputePool(settings)
    pool.start()
    try:
        (before,) = children(pool)
        response = client.get(path, params=params)
        assert response.status_code == 422, response.text
        body = response.json()
        assert body["type"] == "/problems/time-limit"
        assert body["errors"][0]["parameter"] == parameter
        assert pool.kills == 1
        (after,) = children(pool)
        assert after != before
    finally:
        pool.close()


def test_a_request_waiting_for_a_busy_pool_is_refused_before_its_deadline(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """No child frees up in time: a 503 with Retry-After before the deadline, no work done."""
    settings = Settings(compute_processes=1, time_limit=2.0, hard_stop_grace=0.2)
    app = create_app(settings)
    client = TestClient(app)
    client.get(CURVE, params={"i_max": 3})  # the first request pays the app's lazy set-up
    monkeypatch.setattr(common, "curve_response", _hang)  # the one child never answers
    pool = app.state.admission.pool = ComputePool(settings)
    pool.start()
    try:
        first = threading.Thread(target=client.get, args=(CURVE,), kwargs={"params": HEAVY})
        first.start()
        for _ in range(200):
            if pool.jobs:
                break
            time.sleep(0.01)
        response = client.get(CURVE, params={**HEAVY, "d": 2e-3})
        assert response.status_code == 503, response.text
        assert response.json()["type"] == "/problems/overloaded"
        assert "no compute process became free" in response.json()["detail"]
        assert int(response.headers["retry-after"]) >= 1
        assert pool.jobs == 1  # never handed to a child
        first.join()
        assert pool.kills == 1
    finally:
        pool.close()


def test_a_request_behind_more_queued_work_than_its_deadline_allows_is_refused_at_once() -> None:
    """The children's estimated backlog exceeds what the request can wait: a 503 at once (not
    after waiting until its deadline), and nothing handed to a child."""
    settings = Settings(compute_processes=1, time_limit=2.0)
    pool = ComputePool(settings)  # not started: no child is idle
    now = time.monotonic()
    pool._jobs.append(_Job(seconds=5.0, started=now))  # a child busy for about 5 s more
    token = admission.CURRENT.set(admission.Ticket(arrival=now, deadline=now + 2.0, seconds=0.1))
    try:
        with pytest.raises(PoolBusyError, match="more work queued") as refused:
            pool.run(print)
    finally:
        admission.CURRENT.reset(token)
    assert refused.value.retry_after == 1
    assert pool.jobs == 0
    assert len(pool._jobs) == 1  # the refused request left the queue
    # with the backlog almost done, the estimate lets it wait for the child instead
    pool._jobs[0].started = now - 4.95
    assert pool._expected_wait(time.monotonic()) < 0.1


def test_a_child_slower_than_its_estimate_makes_the_worker_stricter() -> None:
    """A job that took 10x its estimate in a child raises the worker's slowdown (the host is
    loaded): admission and the queue's expected wait scale every estimate by it."""
    state = admission.Admission(Settings())
    job = _Job(seconds=0.1, estimated=0.1, started=time.monotonic() - 1.0)
    ComputePool._observe(job, state)
    assert 1.0 < state.slowdown <= admission.MAX_SLOWDOWN
