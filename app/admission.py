"""Admission control, deadlines from arrival, and bounded I/O for each worker.

Every HTTP request gets a ``Ticket`` when it arrives (``app.bounded_io.BoundedIO``):
its deadline is arrival + ``DCOSH_TIME_LIMIT``, so time spent waiting counts. Computing code
charges the ticket with its estimated cost (``charge``, called by the budget checks of
app/limits.py before any work); a charge is refused with a 503 and ``Retry-After`` when

- the worker is draining (SIGTERM received) or
- the estimated seconds cannot finish before the ticket's deadline, or
- the estimated seconds or bytes already admitted on this worker plus this charge exceed the
  worker's budget (``DCOSH_ADMISSION_SECONDS``, ``DCOSH_ADMISSION_BYTES``); a worker with
  nothing admitted always admits one request that fits the limits. Only a request's first
  charge is measured against the budget: a request that charges again as it goes (GET
  /relations, one charge per row) is not refused half-way, after its first rows were computed
  (a slow 503 for wasted work); it may take the worker past its budget by its own cost, which
  its limits bound.

In front of the thread pool, ``AdmissionGate`` bounds the queue: at most
``DCOSH_COMPUTE_THREADS + DCOSH_ADMISSION_QUEUE`` computational requests (paths that may
compute) are in flight per worker; the next one is a 503 at once. Catalogs, /health, /ready and
answers of the response cache never pass the gate (the cache's fast path sits in front of it).

Tickets are handed out by ``app.bounded_io.BoundedIO``, the outermost middleware, which also
bounds request bodies and sends.

Estimates are CPU seconds on a free core; ``Admission.slowdown`` learns how much longer the
host takes now (wall over estimated seconds of computations that ran alone on the worker, at
least 1) and scales every estimate by it, so a loaded host refuses sooner instead of missing
deadlines.

A computation that overruns its deadline is stopped: the core checks the clock in its loops and
mp functions (``Arithmetic.check_time``), and a watchdog thread raises ``HardStopError`` inside a
computing thread that is still running ``DCOSH_HARD_STOP_GRACE`` seconds past its deadline
(Python delivers it at the next bytecode, which covers the mp arithmetic on object arrays whose
``+ - * /`` run as Python methods of mpmath numbers). Never while that thread holds the rigorous
balls' precision lock (``holds_precision_lock``: with ``DCOSH_COMPUTE_PROCESSES=0`` mp curves
compute in the worker): the watchdog tries again every ``REPEAT`` seconds, and the balls' own
clock checks end such a computation with an ordinary exception that releases the lock.
"""

from __future__ import annotations

import contextvars
import ctypes
import heapq
import math
import re
import signal
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import orjson
from starlette.types import ASGIApp, Receive, Scope, Send

from app.settings import Settings

PROBLEM_MEDIA_TYPE = "application/problem+json"

#: Path prefixes whose requests may compute (everything else is a catalog, a page or a probe).
COMPUTING_PREFIXES = (
    "/discretizations/",
    "/surfaces/",
    "/relations",
    "/convergence/",
    "/theorems/",
    "/figures/",
    "/smooth/",
)

#: The slowdown (``Admission.slowdown``) learns from computations estimated at this many seconds
#: or more, with this weight each, and never exceeds MAX_SLOWDOWN.
MIN_OBSERVED = 0.05
SLOWDOWN_WEIGHT = 0.2
MAX_SLOWDOWN = 8.0

#: Seconds a thread holds the GIL before another may take it (Python's default is 0.005): the
#: event loop answers /health and refusals between the computations' slices.
SWITCH_INTERVAL = 0.001

#: Threads kept for requests that do not compute (catalogs, pages) beyond DCOSH_COMPUTE_THREADS.
SPARE_THREADS = 4


class OverloadedError(Exception):
    """The worker does not admit this request now: a 503 with ``Retry-After``."""

    def __init__(self, reason: str, retry_after: int) -> None:
        self.reason = reason
        self.retry_after = max(1, retry_after)
        super().__init__(reason)


class HardStopError(Exception):
    """Raised inside a computing thread by the watchdog once its deadline has long passed."""


@dataclass(eq=False)
class Ticket:
    """One request's deadline and the cost it has been admitted with."""

    arrival: float
    deadline: float
    seconds: float = 0.0
    bytes: int = 0
    thread: int | None = None
    """The thread computing for this request now (``computing``), for the watchdog."""
    stopped: bool = False
    parameter: str = "request"
    """The parameter that drives the cost charged last (named when the watchdog stops it)."""


CURRENT: contextvars.ContextVar[Ticket | None] = contextvars.ContextVar("ticket", default=None)


@dataclass(eq=False)
class Admission:
    """The admitted cost of one worker (thread-safe: requests charge from pool threads)."""

    settings: Settings
    seconds: float = 0.0
    bytes: int = 0
    admitted: int = 0
    in_flight: int = 0
    """Computational requests past the gate and not yet answered."""
    draining: bool = False
    refused: int = 0
    generation: int = 0
    """Requests admitted so far (to tell whether a computation ran alone)."""
    slowdown: float = 1.0
    """Wall seconds per estimated second of recent computations (≥ 1): the host's load, which
    the estimates (CPU seconds on a free core) do not know."""
    pool: Any = None
    """The worker's ``app.compute_pool.ComputePool`` (None: every request computes here)."""
    _lock: threading.Lock = field(default_factory=threading.Lock)

    def retry_after(self) -> int:
        """Seconds after which the admitted work will likely have finished."""
        return min(math.ceil(self.seconds) + 1, math.ceil(self.settings.time_limit))

    def charge(self, ticket: Ticket, seconds: float, nbytes: int, dry: bool = False) -> None:
        """Admit ``seconds`` and ``nbytes`` more for ``ticket``, or raise ``OverloadedError``
        (``dry``: only raise, admit nothing)."""
        settings = self.settings
        with self._lock:
            if self.draining:
                self.refused += 1
                raise OverloadedError("the worker is shutting down", 1)
            if time.monotonic() + seconds * self.slowdown > ticket.deadline:
                self.refused += 1
                raise OverloadedError(
                    f"the request cannot finish within {settings.time_limit:g} s of its arrival "
                    f"(it needs about {seconds * self.slowdown:.3g} s now and has waited "
                    f"{time.monotonic() - ticket.arrival:.3g} s)",
                    self.retry_after(),
                )
            first = ticket.seconds == 0 and ticket.bytes == 0
            others = self.admitted - (0 if first else 1)
            over_time = (self.seconds + seconds) * self.slowdown > settings.admission_seconds
            over_memory = self.bytes + nbytes > settings.admission_bytes
            if first and others > 0 and (over_time or over_memory):
                self.refused += 1
                what = "time" if over_time else "memory"
                raise OverloadedError(
                    f"the worker is busy (the work it has admitted is at its {what} budget)",
                    self.retry_after(),
                )
            if dry:
                return
            if first:
                self.admitted += 1
                self.generation += 1
            seconds = max(seconds, 1e-6)
            ticket.seconds += seconds
            ticket.bytes += nbytes
            self.seconds += seconds
            self.bytes += nbytes

    def observe(self, estimated: float, wall: float) -> None:
        """Learn the slowdown from one finished computation (estimated CPU s, wall s)."""
        if estimated < MIN_OBSERVED:
            return
        ratio = min(max(wall / estimated, 1.0), MAX_SLOWDOWN)
        with self._lock:
            self.slowdown += SLOWDOWN_WEIGHT * (ratio - self.slowdown)

    def release(self, ticket: Ticket) -> None:
        """Give back what ``ticket`` was admitted with (at the end of its response)."""
        with self._lock:
            if ticket.seconds or ticket.bytes:
                self.admitted -= 1
                self.seconds -= ticket.seconds
                self.bytes -= ticket.bytes
                ticket.seconds, ticket.bytes = 0.0, 0

    def ready(self) -> bool:
        """Whether this worker admits new work now (not draining, budget not exhausted)."""
        return not self.draining and (
            self.seconds < self.settings.admission_seconds
            and self.bytes < self.settings.admission_bytes
            and self.in_flight < self.settings.compute_threads + self.settings.admission_queue
        )

    def status(self) -> dict[str, Any]:
        return {
            "ready": self.ready(),
            "draining": self.draining,
            "admitted": self.admitted,
            "in_flight": self.in_flight,
            "seconds": round(self.seconds, 3),
            "slowdown": round(self.slowdown, 2),
            "bytes": self.bytes,
            "refused": self.refused,
        }


_ADMISSION: contextvars.ContextVar[Admission | None] = contextvars.ContextVar(
    "admission", default=None
)


_DRY_RUN: contextvars.ContextVar[bool] = contextvars.ContextVar("dry_run", default=False)


@contextmanager
def dry_run() -> Iterator[None]:
    """Within: ``charge`` refuses as ever (``OverloadedError``, counted) but admits nothing, so
    that the fast lane (app/fast_lane.py) can answer a refusal on the event loop and leave an
    admitted request to the chain, which charges it."""
    token = _DRY_RUN.set(True)
    try:
        yield
    finally:
        _DRY_RUN.reset(token)


def charge(seconds: float, nbytes: int, parameter: str = "request") -> None:
    """Charge the current request (if any: direct calls outside a request are not admitted);
    ``parameter`` drives the cost (named if the computation is stopped)."""
    ticket = CURRENT.get()
    admission = _ADMISSION.get()
    if ticket is None or admission is None:
        return
    if _DRY_RUN.get():
        admission.charge(ticket, seconds, nbytes, dry=True)
        return
    admission.charge(ticket, seconds, nbytes)
    ticket.parameter = parameter


def current_admission() -> Admission | None:
    """The admission state of the worker serving the current request."""
    return _ADMISSION.get()


def current() -> Ticket | None:
    """The current request's ticket."""
    return CURRENT.get()


def deadline() -> float | None:
    """The current request's deadline (``time.monotonic()``), or None outside a request."""
    ticket = CURRENT.get()
    return None if ticket is None else ticket.deadline


# --- the watchdog ---------------------------------------------------------------------------

_set_async_exc = ctypes.pythonapi.PyThreadState_SetAsyncExc
_set_async_exc.argtypes = (ctypes.c_ulong, ctypes.py_object)


#: Seconds between two attempts of the watchdog to stop the same computation.
REPEAT = 0.25


class Watchdog:
    """One daemon thread that stops computations still running well past their deadline."""

    def __init__(self) -> None:
        self._heap: list[tuple[float, int, Ticket]] = []
        self._lock = threading.Lock()
        self._wake = threading.Event()
        self._count = 0
        self._thread: threading.Thread | None = None
        self.stops = 0

    def watch(self, ticket: Ticket, at: float) -> None:
        with self._lock:
            self._count += 1
            heapq.heappush(self._heap, (at, self._count, ticket))
            # the thread sleeps until the earliest time in the heap: only a new earliest one
            # needs to wake it (deadlines mostly come in order, so a computation rarely costs
            # the thread a wake-up and a turn with the GIL)
            earliest = self._heap[0][1] == self._count
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name="watchdog", daemon=True)
                self._thread.start()
        if earliest:
            self._wake.set()

    def _run(self) -> None:
        while True:
            with self._lock:
                now = time.monotonic()
                while self._heap and self._heap[0][0] <= now:
                    _, _, ticket = heapq.heappop(self._heap)
                    thread = ticket.thread
                    if thread is not None and holds_precision_lock(thread):
                        # never inside the balls' precision lock: try again in REPEAT seconds
                        # (meanwhile the balls' own clock checks stop it cleanly)
                        self._count += 1
                        heapq.heappush(self._heap, (now + REPEAT, self._count, ticket))
                    elif thread is not None:
                        # again every REPEAT seconds while it runs: an exception raised inside
                        # a garbage-collector callback or a __del__ is lost
                        ticket.stopped = True
                        self.stops += 1
                        _set_async_exc(thread, HardStopError)
                        self._count += 1
                        heapq.heappush(self._heap, (now + REPEAT, self._count, ticket))
                wait = self._heap[0][0] - now if self._heap else 60.0
            self._wake.wait(wait)
            self._wake.clear()


WATCHDOG = Watchdog()

_OWNER = re.compile(r"owner=(\d+)")


def holds_precision_lock(thread: int) -> bool:
    """Whether ``thread`` holds the rigorous balls' precision lock (app/geometry/balls.py) now.

    An asynchronous exception raised there could land between the lock's acquisition and the
    code that releases it and leave it held (``DCOSH_COMPUTE_PROCESSES=0``: mp curves compute in
    the worker). An ``RLock`` tells its owner only in its repr."""
    from app.geometry import balls

    found = _OWNER.search(repr(balls.LOCK))
    return found is not None and int(found.group(1)) == thread


def stopped_inside(exc: BaseException) -> bool:
    """Whether the watchdog's ``HardStopError`` is in ``exc``'s chain: raised asynchronously, it
    can land inside a C extension calling back into Python (numba loading or running a kernel),
    which then reports it as a ``SystemError`` caused by it."""
    seen: set[int] = set()
    link: BaseException | None = exc
    while link is not None and id(link) not in seen:
        if isinstance(link, HardStopError):
            return True
        seen.add(id(link))
        link = link.__cause__ or link.__context__
    return False


@contextmanager
def computing(grace: float | None = None) -> Iterator[None]:
    """Mark the current thread as computing for the current request: the watchdog may stop it
    once ``grace`` seconds (``DCOSH_HARD_STOP_GRACE``) have passed after the deadline."""
    ticket = CURRENT.get()
    admission = _ADMISSION.get()
    if ticket is None or admission is None:
        yield
        return
    if grace is None:
        grace = admission.settings.hard_stop_grace
    ticket.thread = threading.get_ident()
    WATCHDOG.watch(ticket, ticket.deadline + grace)
    start = time.monotonic()
    charged = bool(ticket.seconds or ticket.bytes)
    others = admission.admitted - charged
    generation = admission.generation
    try:
        yield
    except SystemError as exc:
        if stopped_inside(exc):  # the stop landed inside a kernel: answer it as a stop
            raise HardStopError from exc
        raise
    finally:
        ticket.thread = None
        # only a computation that ran alone on this worker measures the host, not the GIL
        new = admission.generation - generation - (not charged and bool(ticket.seconds))
        if others == 0 and new == 0:
            admission.observe(ticket.seconds, time.monotonic() - start)


# --- the middlewares ------------------------------------------------------------------------


def problem_bytes(status: int, kind: str, title: str, detail: str) -> bytes:
    return orjson.dumps(
        {
            "type": f"/problems/{kind}",  # a page of app.errors.PROBLEM_TYPES
            "title": title,
            "status": status,
            "detail": detail,
            "errors": [],
        }
    )


async def send_problem(
    send: Send,
    status: int,
    kind: str,
    title: str,
    detail: str,
    headers: list[tuple[bytes, bytes]] | None = None,
) -> None:
    body = problem_bytes(status, kind, title, detail)
    await send(
        {
            "type": "http.response.start",
            "status": status,
            "headers": [
                (b"content-type", PROBLEM_MEDIA_TYPE.encode()),
                (b"content-length", str(len(body)).encode()),
                *(headers or []),
            ],
        }
    )
    await send({"type": "http.response.body", "body": body})


def overloaded_headers(retry_after: int) -> list[tuple[bytes, bytes]]:
    return [(b"retry-after", str(retry_after).encode()), (b"cache-control", b"no-store")]


def is_computing(path: str) -> bool:
    """Whether a request to ``path`` may compute (catalogs and pages do not)."""
    return path.startswith(COMPUTING_PREFIXES)


class AdmissionGate:
    """ASGI middleware (behind the cache's fast path): a bounded number of computational
    requests in flight per worker; beyond it an immediate 503 with Retry-After."""

    def __init__(self, app: ASGIApp, admission: Admission) -> None:
        self.app = app
        self.admission = admission

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or not is_computing(scope["path"]):
            await self.app(scope, receive, send)
            return
        admission = self.admission
        settings = admission.settings
        if admission.draining or admission.in_flight >= (
            settings.compute_threads + settings.admission_queue
        ):
            admission.refused += 1
            reason = (
                "the worker is shutting down"
                if admission.draining
                else "the worker's queue of computations is full"
            )
            await send_problem(
                send,
                503,
                "overloaded",
                "Overloaded",
                f"Not admitted now: {reason}; retry later (another replica may answer).",
                overloaded_headers(admission.retry_after()),
            )
            return
        admission.in_flight += 1
        try:
            await self.app(scope, receive, send)
        finally:
            admission.in_flight -= 1


def drain_on_sigterm(admission: Admission) -> None:
    """Turn ``/ready`` to 503 and refuse new work once SIGTERM arrives (then the server's own
    handler runs: uvicorn stops accepting and drains within --timeout-graceful-shutdown)."""
    if threading.current_thread() is not threading.main_thread():
        return
    previous = signal.getsignal(signal.SIGTERM)

    def handler(signum: int, frame: Any) -> None:
        admission.draining = True
        if callable(previous):
            previous(signum, frame)
        elif previous == signal.SIG_DFL:
            raise SystemExit(128 + signum)

    signal.signal(signal.SIGTERM, handler)
