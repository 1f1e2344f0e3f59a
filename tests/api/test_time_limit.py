"""The time limit runs from arrival: a request that cannot finish in time is refused before it
starts (503); one that overruns is stopped by the core's clock checks or, failing those, from
outside by the watchdog, and answered with the time-limit problem type."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from app import limits
from app.admission import HardStopError
from app.geometry.d4b import discretization as d4b
from app.geometry.errors import TimeLimitError
from app.geometry.precision import Arithmetic, Float64, MultiPrecision
from app.main import create_app
from app.settings import Settings

TIME_LIMIT_TYPE = "/problems/time-limit"


@pytest.fixture
def free_estimates(monkeypatch: pytest.MonkeyPatch) -> None:
    """Estimates of zero cost, so that admission lets an overrunning request start."""
    for name in (
        "BASE_SECONDS",
        "F64_STEP_SECONDS",
        "F64_VERTEX_SECONDS",
        "MP_STEP_SECONDS",
        "BALL_STEP_SECONDS",
    ):
        monkeypatch.setattr(limits, name, 0.0)
    monkeypatch.setattr(limits, "MP_MESH_VERTEX_SECONDS", 0.0)


def warm(client: TestClient) -> TestClient:
    """The first request of an app pays for lazy set-up; later ones only for themselves."""
    client.get("/discretizations/d4b", params={"i_max": 3})  # the fast lane's set-up
    # the OpenAPI document, read by the format negotiation of the chain's GETs (the server
    # builds it before its first request, server.warm_app; built here on a loaded host it took
    # a 0.5 s limit's whole time, and the mp request below was refused with a 503)
    client.app.openapi()  # type: ignore[attr-defined]
    return client


def test_a_request_that_could_never_finish_in_time_is_a_422_naming_its_parameter() -> None:
    """Estimated alone on a free core above the time limit: waiting cannot help, so no 503."""
    client = TestClient(create_app(Settings(time_limit=0.001)))
    response = client.get("/discretizations/d4b", params={"d": 1e-4, "i_max": 200000})
    assert response.status_code == 422
    (error,) = response.json()["errors"]
    assert error["parameter"] == "i_max"
    assert error["constraint"].startswith("estimated time <= 0.001 s (DCOSH_TIME_LIMIT;")
    assert "retry-after" not in response.headers


def test_a_request_that_cannot_finish_in_time_now_is_refused_before_it_starts() -> None:
    """It would fit the limit on a free core, but the host is slow now: a 503 to retry later."""
    client = TestClient(create_app(Settings(time_limit=1.0)))
    client.app.state.admission.slowdown = 1000.0  # type: ignore[attr-defined]
    response = client.get("/discretizations/d4b", params={"d": 1e-4, "i_max": 200000})
    assert response.status_code == 503
    assert response.json()["type"] == "/problems/overloaded"
    assert "cannot finish within 1 s" in response.json()["detail"]
    assert int(response.headers["retry-after"]) >= 1


@pytest.mark.usefixtures("free_estimates")
def test_a_long_construction_stops_with_the_time_limit_problem_naming_the_range() -> None:
    client = warm(TestClient(create_app(Settings(time_limit=0.2))))
    # 10^6 vertices: the construction and its checks take ~0.35 s of wall on a quiet host and
    # shaping the answer reads no clock, so a limit near that could be passed only while
    # shaping (and answer 200); at 0.2 s the overrun comes in the checks
    response = client.get("/discretizations/d4b", params={"d": 1e-4, "i_min": 0, "i_max": 999_999})
    assert response.status_code == 422
    body = response.json()
    assert body["type"] == TIME_LIMIT_TYPE and body["title"] == "Over the time limit"
    (error,) = body["errors"]
    assert error["parameter"] == "i_max"
    assert "within 0.2 s (DCOSH_TIME_LIMIT)" in error["constraint"]


@pytest.mark.usefixtures("free_estimates")
def test_an_mp_computation_stops_with_the_time_limit_problem_naming_digits() -> None:
    client = warm(TestClient(create_app(Settings(time_limit=0.2))))
    response = client.get(  # the heaviest work the budget admits at 1000 digits: ~0.7 s on balls
        # (the checks read the clock between statements; shaping the answer reads none, so the
        # overrun must come before it: with a 0.5 s limit the checks of this request now end
        # at ~0.5 s on a quiet host, and one run in three overran only while shaping, answering
        # 200; with 0.2 s it stops in the checks, at ~0.22 s)
        "/discretizations/d4b",
        params={"precision": "mp", "digits": 1000, "i_max": 820},
    )
    assert response.status_code == 422
    assert response.json()["type"] == TIME_LIMIT_TYPE
    assert response.json()["errors"][0]["parameter"] == "digits"


@pytest.mark.usefixtures("free_estimates")
def test_a_computation_without_clock_checks_is_stopped_from_outside(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # mp arithmetic on object arrays (a * b) never reaches check_time; here no check does
    monkeypatch.setattr(Arithmetic, "check_time", lambda self: None)
    client = warm(TestClient(create_app(Settings(time_limit=1.0, hard_stop_grace=0.2))))
    response = client.get(  # minutes of work unstopped
        "/surfaces/catenoid",
        params={"discretization": "d4b", "precision": "mp", "digits": 20, "i_max": 100, "m": 200},
    )
    assert response.status_code == 422
    assert response.json()["type"] == TIME_LIMIT_TYPE
    assert "stopped past its deadline" in response.json()["detail"]
    # the worker thread survives and serves the next request
    assert client.get("/discretizations/d4b", params={"i_max": 10}).status_code == 200


def test_within_the_limit_nothing_changes() -> None:
    client = TestClient(create_app(Settings(time_limit=60)))
    assert client.get("/discretizations/d4b", params={"i_max": 5000, "d": 0.001}).status_code == 200


@pytest.mark.parametrize("ar", [Float64(), MultiPrecision(20)], ids=["float64", "mp"])
def test_the_core_checks_the_clock_in_its_loops(ar: Float64 | MultiPrecision) -> None:
    ar.start_clock(-1.0, "i_max")  # already past
    with pytest.raises(TimeLimitError, match="i_max must satisfy the computation finishes"):
        d4b.compute(ar, 1.0, 0.001, None, 0, 5000)


def test_a_hard_stop_that_lands_inside_an_extension_is_the_time_limit_not_a_500() -> None:
    """The watchdog's asynchronous HardStopError can surface as a SystemError caused by it (numba
    loading a kernel when the exception arrives): still the time-limit problem, never a 500."""
    app = create_app(Settings())

    @app.get("/__stopped_inside")
    def stopped_inside() -> None:
        try:
            raise HardStopError
        except HardStopError as stop:
            raise SystemError(
                "<built-in function x> returned a result with an exception set"
            ) from stop

    with TestClient(app, raise_server_exceptions=False) as client:
        response = client.get("/__stopped_inside")
    assert response.status_code == 422
    assert response.headers["content-type"] == "application/problem+json"
    body = response.json()
    assert body["title"] == "Over the time limit"
    assert body["type"].endswith("/problems/time-limit")
