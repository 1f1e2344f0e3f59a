"""Estimated against measured cost (app/limits.py): for a request of every computational
endpoint in both precisions, the estimate charged before any work is within an order of magnitude
of the CPU time and the peak traced memory it then takes. Sizes are small (the whole test takes
seconds); the model is linear in them, and bench/costs.py runs the heaviest admitted requests."""

from __future__ import annotations

import time
import tracemalloc
from collections.abc import Iterator

import pytest
from fastapi.testclient import TestClient

from app import admission
from app.main import create_app
from app.settings import Settings

REQUESTS = [
    "/discretizations/d4b?d=0.0001&i_min=-100000&i_max=-50000&format=npy",
    "/discretizations/d4b?d=0.0001&method=closed-form&i_min=-50000&i_max=50000",
    "/discretizations/d1?c=0.0001&delta=0.001&i_min=-30000&i_max=30000&format=csv",
    "/discretizations/d2b?i_min=0&i_max=100000",
    "/discretizations/d4b?precision=mp&digits=30&i_max=100",
    "/discretizations/d2a-quad?precision=mp&digits=300&i_max=60",
    "/discretizations/d2b?precision=mp&digits=10&i_min=0&i_max=80",
    # balls at many digits (the estimate recalibrated in stop 16: bench/ball_costs.py)
    "/discretizations/d4b?precision=mp&digits=1000&i_min=-60&i_max=60",
    "/discretizations/d3?precision=mp&digits=1000&i_min=-60&i_max=60",
    "/discretizations/d2a-hex?precision=mp&digits=500&i_min=-60&i_max=60",
    "/discretizations/d4a?precision=mp&digits=500&i_min=-60&i_max=60",
    "/surfaces/catenoid?discretization=d4b&d=0.01&i_min=-200&i_max=200&m=100&format=glb",
    "/surfaces/pseudosphere?discretization=d4b&i_min=0&i_max=100&m=60",
    "/surfaces/catenoid?discretization=d4b&precision=mp&digits=5&i_min=-4&i_max=4&m=8",
    "/smooth/tractrix?count=200000",
    "/smooth/tractrix?precision=mp&digits=50&count=400",
    "/figures/figure-3.svg?i_min=-960&i_max=960",
    "/figures/figure-2.svg?count=20001",
    "/relations",
    "/relations?precision=mp&digits=20",
    "/convergence/theorem-14?levels=12",
    "/convergence/theorem-11?precision=mp&digits=20&levels=3",
]


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    # a generous time limit: this test compares costs, whatever the load of the machine
    settings = Settings(response_cache_bytes=0, time_limit=300, admission_seconds=120)
    with TestClient(create_app(settings)) as client:
        client.get("/discretizations/d4b?i_max=3")
        client.get("/surfaces/catenoid?i_max=3&m=4")
        yield client


@pytest.fixture
def charges(monkeypatch: pytest.MonkeyPatch) -> list[tuple[float, int]]:
    seen: list[tuple[float, int]] = []
    original = admission.Admission.charge

    def spy(self: admission.Admission, ticket: admission.Ticket, s: float, b: int) -> None:
        seen.append((s, b))
        original(self, ticket, s, b)

    monkeypatch.setattr(admission.Admission, "charge", spy)
    return seen


#: Further runs of a request whose first one took more than 3× its estimate.
RETRIES = 2


def _cpu_seconds(client: TestClient, url: str) -> float:
    start = time.process_time()
    assert client.get(url).status_code == 200
    return time.process_time() - start


@pytest.mark.parametrize("url", REQUESTS)
def test_the_estimate_is_within_an_order_of_magnitude_of_the_cost(
    client: TestClient, charges: list[tuple[float, int]], url: str
) -> None:
    cpu = _cpu_seconds(client, url)
    seconds = sum(s for s, _ in charges)
    if cpu > 3 * seconds:
        # The process's CPU clock also counts whatever else runs in it (a thread a test before
        # left behind, a first call's cold caches), and a loaded host only adds to it: the
        # request's own cost is the least of a few runs (CI once measured 1.52 s for a request
        # that takes 0.07-0.25 s here).
        cpu = min([cpu] + [_cpu_seconds(client, url) for _ in range(RETRIES)])
    charges.clear()
    tracemalloc.start()
    try:
        assert client.get(url).status_code == 200
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    nbytes = sum(b for _, b in charges)
    # never an underestimate by more than 3×, never an overestimate by more than 30×
    assert cpu <= 3 * seconds, (cpu, seconds)
    assert seconds <= 30 * max(cpu, 0.01), (cpu, seconds)
    assert peak <= 3 * nbytes, (peak, nbytes)
    assert nbytes <= 30 * max(peak, 2**20), (peak, nbytes)
