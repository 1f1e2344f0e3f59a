"""Heavy computations in child processes of the serving worker, stopped from outside.

A computation holds the GIL for most of its time (mpmath's arithmetic, orjson encoding tens of
megabytes, numba kernels), and the serving process's event loop needs the GIL to answer
/health, refusals and cached answers. So each worker keeps a small pool of child processes
(``DCOSH_COMPUTE_PROCESSES``) and sends them every request whose estimated cost
(app/limits.py) is at least ``DCOSH_POOL_MIN_SECONDS``; cheaper requests compute in the worker,
where the round trip would cost more than it saves.

- The children are forked when the worker starts (``start``: after the app is imported, so they
  share its modules and loaded kernels page for page, before any other thread exists), run
  under Linux's idle scheduling class (``lower_priority``: a serving thread that wakes takes the
  CPU from a child at once, so refusals and /health do not wait behind heavy work) and under an
  address-space limit: what the child maps when it starts plus ``DCOSH_ADMISSION_BYTES`` (no
  admitted request may estimate more) plus ``HEADROOM``.
- A child computes *and renders*: it returns the response's status, media type, headers and
  body bytes; the worker keeps caching, ETags, coalescing, admission and compression. The
  waiting request thread blocks on the child's pipe, without the GIL.
- An exception raised in the child (a domain error, the time-limit error of the core's clock
  checks) is raised again in the worker as the same class with the same attributes, so the same
  problem response follows; one that cannot be sent becomes a ``RuntimeError`` (a 500).
- A child still computing ``DCOSH_HARD_STOP_GRACE`` seconds past its request's deadline is
  killed (SIGKILL) and replaced, and the request gets the time-limit problem
  (``HardStopError``). A child that dies (out of memory, killed) is replaced and its request
  gets a 503 with Retry-After, as does a request that waits for a free child until it could
  no longer finish by its deadline.
- A request that finds every child busy is refused at once (a 503 with Retry-After) when the
  work queued ahead of it (the rest of the running jobs' estimates and the waiting ones', over
  the children) would not let it finish by its deadline: it does not wait for that 503.
  Estimates are CPU seconds on a free core: each job's wall time in its child teaches the
  worker's slowdown (``Admission.observe``), which scales them on a loaded host.

Every computation on rigorous balls (precision=mp of a curve, app/geometry/balls.py) goes to a
child, however cheap: it holds the balls' precision lock for its whole run, and the worker's
watchdog (app/admission.py) stops a thread with an asynchronous exception, which may land
between the lock's acquisition and the code that releases it (a lock left held, or released
later by another thread). A child has no watchdog: it is stopped by being killed, lock and all.
(With ``DCOSH_COMPUTE_PROCESSES=0`` they compute in the worker, whose watchdog waits until the
thread has left that lock: ``admission.holds_precision_lock``.)

Replacement children are forked from a worker that runs threads by then; a lock another
thread held at that moment stays locked in the child. The core's one module lock (the balls'
precision, app/geometry/balls.py) is made anew in every child; a child stuck on another one
never answers: it is killed at its first request's deadline like any overrunning child, and
replaced again.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import pickle
import queue
import resource
import signal
import stat
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess
from typing import Any

from app import admission
from app.server import end_with_parent
from app.settings import Settings

#: Niceness of the children where the idle scheduling class is not available (the serving
#: processes keep 0).
NICENESS = 19


def lower_priority() -> str:
    """Put this process (a child, single-threaded) under ``SCHED_IDLE``, else at ``NICENESS``;
    returns which one it got.

    Under ``SCHED_IDLE`` a thread of normal priority that wakes preempts the child at once
    (the kernel's wake-up path checks the class first), whereas a child at niceness 5 kept its
    slice: the worker's event loop, woken by each request of a burst, waited behind the
    children for a few milliseconds per wake-up, and the last refusals of a burst came after
    100 ms (docs/reliability.md). The children still get every cycle the serving processes do
    not use; on a host whose other processes are busy they share what the service's group of
    processes gets (autogroups, containers' cgroups), so admitted work slows only when the
    service's own workers are busy, which the admission's slowdown learns."""
    try:
        os.sched_setscheduler(0, os.SCHED_IDLE, os.sched_param(0))
        return "idle"
    except (AttributeError, OSError):
        with contextlib.suppress(OSError):
            os.nice(NICENESS)
        return f"nice {NICENESS}"


#: Address space a child may map beyond its size at start and DCOSH_ADMISSION_BYTES (numpy's
#: temporaries beyond the estimate, mpmath caches, a kernel numba has to compile).
HEADROOM = 768 * 2**20

#: Seconds to wait for a killed child to be reaped.
JOIN_TIMEOUT = 5.0

_FORK = multiprocessing.get_context("fork")


@dataclass(frozen=True)
class Rendered:
    """A response rendered in a child: what the worker's Response is built from."""

    status: int
    media_type: str | None
    headers: dict[str, str]
    body: bytes


@dataclass(eq=False)
class _Job:
    """A request in a child or waiting for one: its estimated wall seconds, for the queue's
    expected wait."""

    seconds: float
    """Estimated wall seconds (CPU seconds scaled by the worker's slowdown)."""
    estimated: float = 0.0
    """Estimated CPU seconds on a free core (what admission charged)."""
    started: float | None = None


class PoolCrashError(admission.OverloadedError):
    """The child computing a request died (out of memory, killed): a 503 with Retry-After."""


class PoolBusyError(admission.OverloadedError):
    """No child became free in time for the request to finish by its deadline: a 503."""


def _mapped_bytes() -> int:
    """Bytes of address space this process maps now."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[0]) * resource.getpagesize()


def _portable(exc: BaseException) -> bytes:
    """``exc`` pickled as (class, args, attributes): exceptions whose ``__init__`` takes other
    arguments than ``args`` (``DomainError``) do not survive plain pickling."""
    try:
        return pickle.dumps((type(exc), exc.args, dict(vars(exc))))
    except Exception:  # a class or an attribute that cannot be pickled
        return pickle.dumps((RuntimeError, (f"{type(exc).__name__}: {exc}",), {}))


def _rebuilt(data: bytes) -> BaseException:
    cls, args, state = pickle.loads(data)
    exc: BaseException = cls.__new__(cls, *args)
    exc.args = args
    exc.__dict__.update(state)
    return exc


def _close_sockets(keep: int) -> None:
    """Close every socket this child inherited but ``keep``: the worker's listening socket,
    its clients' connections (a replacement child is forked while they are open: its copy
    would keep a connection the worker closed open, and reset it when the child is killed)
    and the other children's pipes."""
    for name in os.listdir("/proc/self/fd"):
        fd = int(name)
        if fd == keep:
            continue
        with contextlib.suppress(OSError):
            if stat.S_ISSOCK(os.fstat(fd).st_mode):
                os.close(fd)


def _fresh_locks() -> None:
    """New module locks that a thread of the worker may have held when a replacement forked
    (only the forking thread exists in the child, so nobody would release them)."""
    from app.geometry import balls

    balls.LOCK = threading.RLock()


def _child(conn: Connection, memory_limit: int) -> None:
    """A child's loop: receive a job, compute and render it, send the answer back."""
    end_with_parent(signal.SIGKILL)  # when the worker that forked it dies
    _fresh_locks()
    _close_sockets(keep=conn.fileno())
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the worker, which ends us
    lower_priority()
    limit = _mapped_bytes() + memory_limit + HEADROOM
    with contextlib.suppress(ValueError, OSError):
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    while True:
        try:
            function, args, arrival, deadline = conn.recv()
        except (EOFError, OSError):
            os._exit(0)
        # the request's deadline, for the core's clock checks (nothing is charged here)
        admission.CURRENT.set(admission.Ticket(arrival=arrival, deadline=deadline))
        try:
            response = function(*args)
            body = bytes(response.body)
            headers = [
                (k, v)
                for k, v in response.headers.items()
                if k not in ("content-length", "content-type")
            ]
            conn.send(("ok", response.status_code, response.media_type, headers))
            conn.send_bytes(body)
        except MemoryError:
            # past the address-space limit: this heap is not worth keeping
            with contextlib.suppress(OSError):
                conn.send(("crash", "it ran out of memory"))
            os._exit(1)
        except BaseException as exc:
            conn.send(("error", _portable(exc)))
        finally:
            response = body = None  # type: ignore[assignment]


class _Child:
    def __init__(self, memory_limit: int) -> None:
        self.conn, child_end = _FORK.Pipe(duplex=True)
        self.process: BaseProcess = _FORK.Process(
            target=_child,
            args=(child_end, memory_limit),
            daemon=True,
            name="dcosh-compute",
        )
        self.process.start()
        child_end.close()

    def kill(self) -> None:
        with contextlib.suppress(OSError, ValueError, AttributeError):
            self.process.kill()
        self.process.join(JOIN_TIMEOUT)
        with contextlib.suppress(OSError):
            self.conn.close()


class ComputePool:
    """``size`` child processes of one worker that compute and render heavy requests."""

    def __init__(self, settings: Settings) -> None:
        self.settings = settings
        self.size = settings.compute_processes
        self._idle: queue.LifoQueue[_Child] = queue.LifoQueue()
        self._children: list[_Child] = []
        self._wanted: queue.SimpleQueue[_Child | None] = queue.SimpleQueue()
        """A killed child to reap and replace (None: stop)."""
        self._lock = threading.Lock()
        self._jobs: list[_Job] = []
        """Requests in a child or waiting for one."""
        self._jobs_lock = threading.Lock()
        self.jobs = 0
        """Requests sent to a child."""
        self.kills = 0
        """Children killed past a deadline."""
        self.crashes = 0
        """Children that died on their own."""
        self.closed = False

    def start(self) -> None:
        for _ in range(self.size):
            self._idle.put(self._spawn())
        # replacements are forked by one thread that lives as long as the worker: Linux sends
        # a child its PR_SET_PDEATHSIG when the *thread* that forked it ends, and the request
        # threads that find a child dead end when idle
        threading.Thread(target=self._respawn, name="compute-pool", daemon=True).start()

    def _respawn(self) -> None:
        while (dead := self._wanted.get()) is not None:
            dead.kill()  # reaped here: a large child takes a while to exit on a busy host
            if not self.closed:
                self._idle.put(self._spawn())

    def _spawn(self) -> _Child:
        # one fork at a time: a child forked while another's pipe end is still open here
        # would hold it, and the worker would not see that other child die
        with self._lock:
            child = _Child(self.settings.admission_bytes)
            self._children.append(child)
        return child

    def _replace(self, child: _Child) -> None:
        """Kill ``child`` now; the pool's thread reaps it and forks its successor, so that
        the request answers at once (not after a large child's exit)."""
        with contextlib.suppress(OSError, ValueError, AttributeError):
            child.process.kill()
        with self._lock:
            if child in self._children:
                self._children.remove(child)
        if self.closed:
            child.kill()
        else:
            self._wanted.put(child)

    def pids(self) -> list[int]:
        with self._lock:
            return [c.process.pid for c in self._children if c.process.pid is not None]

    def close(self) -> None:
        self.closed = True
        self._wanted.put(None)
        with self._lock:
            children, self._children = self._children, []
        for child in children:
            child.kill()

    def run(self, function: Callable[..., Any], *args: Any) -> Rendered:
        """``function(*args)`` in a child, for the current request and within its deadline:
        ``function`` is module-level, its arguments picklable, and it returns a response with
        a ``body`` (Starlette's); its status, media type, headers and body come back."""
        ticket = admission.current()
        now = time.monotonic()
        arrival, deadline = (
            (now, now + self.settings.time_limit)
            if ticket is None
            else (ticket.arrival, ticket.deadline)
        )
        if ticket is not None:
            ticket.thread = None  # this thread only waits: the pool stops the child instead
        stop_at = deadline + self.settings.hard_stop_grace
        # waiting for a free child ends when the request could no longer finish in time: then
        # it is refused (503 with Retry-After), before any work, not stopped at its deadline
        state = admission.current_admission()
        slowdown = 1.0 if state is None else state.slowdown
        need = 0.0 if ticket is None else ticket.seconds * slowdown
        job = _Job(need, 0.0 if ticket is None else ticket.seconds)
        with self._jobs_lock:
            wait = self._expected_wait(now)
            self._jobs.append(job)
        try:
            return self._run(job, function, args, (arrival, deadline, stop_at), wait, state)
        finally:
            with self._jobs_lock:
                self._jobs.remove(job)

    @staticmethod
    def _observe(job: _Job, state: admission.Admission | None) -> None:
        """Teach the worker's slowdown (``Admission.observe``) how long a child took over the
        job's estimate: children compete for the host's cores like everything else, and a
        loaded host must make admission and this queue's expected wait stricter, or the
        requests queued here wait until their deadline for a 503."""
        if state is not None and job.started is not None and job.estimated > 0:
            state.observe(job.estimated, time.monotonic() - job.started)

    def _expected_wait(self, now: float) -> float:
        """Seconds a job queued now waits for a child, as estimated: the work still ahead of
        it (the rest of the running jobs' estimates and the waiting jobs') over the
        children; 0 while a child is idle."""
        if self._idle.qsize() > 0:
            return 0.0
        ahead = sum(
            job.seconds if job.started is None else max(0.0, job.seconds - (now - job.started))
            for job in self._jobs
        )
        return ahead / max(1, self.size)

    def _run(
        self,
        job: _Job,
        function: Callable[..., Any],
        args: tuple[Any, ...],
        times: tuple[float, float, float],
        wait: float,
        state: admission.Admission | None,
    ) -> Rendered:
        arrival, deadline, stop_at = times
        need = job.seconds
        if need > 0 and time.monotonic() + wait + need > deadline:
            # the queue ahead will not clear in time: refused now, not at the end of the wait
            raise PoolBusyError(
                "the compute processes have more work queued than it could wait for and still "
                f"finish within {self.settings.time_limit:g} s of its arrival",
                1 if state is None else state.retry_after(),
            )
        while True:
            try:
                child = self._idle.get(timeout=max(0.0, deadline - need - time.monotonic()))
            except queue.Empty:
                raise PoolBusyError(
                    "no compute process became free early enough for it to finish within "
                    f"{self.settings.time_limit:g} s of its arrival",
                    1 if state is None else state.retry_after(),
                ) from None
            if child.process.is_alive():
                break
            # it died while idle (killed from outside): nothing of this request was lost
            self.crashes += 1
            self._replace(child)
        self.jobs += 1
        job.started = time.monotonic()
        try:
            child.conn.send((function, args, arrival, deadline))
            if not child.conn.poll(max(0.0, stop_at - time.monotonic())):
                self.kills += 1
                self._replace(child)
                self._observe(job, state)
                raise admission.HardStopError
            message = child.conn.recv()
            body = child.conn.recv_bytes() if message[0] == "ok" else b""
        except (EOFError, OSError):
            self.crashes += 1
            self._replace(child)
            raise PoolCrashError("the process computing it ended unexpectedly", 1) from None
        if message[0] == "crash":
            self.crashes += 1
            self._replace(child)
            raise PoolCrashError(f"the process computing it failed: {message[1]}", 1)
        self._idle.put(child)
        if message[0] == "error":
            raise _rebuilt(message[1])
        self._observe(job, state)
        _, status, media_type, headers = message
        return Rendered(status, media_type, dict(headers), body)


def offload(balls: bool = False) -> ComputePool | None:
    """The current worker's pool if the current request is heavy enough to compute there, or
    computes on rigorous balls (``balls``: precision=mp of a curve, however cheap)."""
    state = admission.current_admission()
    ticket = admission.current()
    if state is None or ticket is None:
        return None
    pool: ComputePool | None = state.pool
    if pool is None or pool.closed:
        return None
    if not balls and ticket.seconds < state.settings.pool_min_seconds:
        return None
    return pool
