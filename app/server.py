"""Start the service's workers with its connection limits: one command for `make run`, the Docker
image, `make load` and the tests that need a real server (tests/deploy/).

Workers: each worker process has a listening socket of its own, all bound to the same address
with ``SO_REUSEPORT``, so the kernel spreads new connections over the workers (by a hash of the
connection's addresses and ports). uvicorn's ``--workers`` shares one socket between its
workers instead, and whichever worker is idle in ``accept`` takes the whole queue: a burst of 32
connections all landed on one worker while the other had nothing to do (measured:
docs/reliability.md). This process binds the sockets, starts the workers, restarts a worker
that dies (on the same socket: connections waiting in its queue are served by the new one),
and forwards SIGTERM to every worker. With one worker it serves in-process.

The limits (docs/reliability.md):

- h11 parses requests, so the header block is bounded (``--h11-max-incomplete-event-size``,
  64 KiB: 100 000 headers or one 10 MB header get a 400 before they are buffered);
- idle keep-alive connections close after 5 s;
- on SIGTERM the worker stops accepting, /ready turns 503, and in-flight requests get
  ``--timeout-graceful-shutdown`` seconds (by then every admitted request has met its deadline:
  DCOSH_TIME_LIMIT + DCOSH_HARD_STOP_GRACE) before the rest are cut;
- at most ``--limit-concurrency`` connections per worker (a last resort: admission control in
  app/admission.py answers overload with 503 problems long before).

Request bodies, body and send timeouts and the cost budget are the app's (app/admission.py).
Each worker forks its compute processes (app/compute_pool.py) once the app is imported, before
uvicorn starts.
Usage: python -m app.server [--host H] [--port P] [--workers N] [uvicorn options…]
"""

from __future__ import annotations

import argparse
import contextlib
import ctypes
import ctypes.util
import gc
import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

#: Connections waiting to be accepted, per worker socket.
BACKLOG = 1024

#: uvicorn's options for every deployment of the service.
UVICORN_FLAGS = (
    "--http",
    "h11",
    "--h11-max-incomplete-event-size",
    str(64 * 1024),
    "--timeout-keep-alive",
    "5",
    "--timeout-graceful-shutdown",
    "25",
    "--limit-concurrency",
    "1024",
    "--backlog",
    str(BACKLOG),
    "--no-server-header",
)

#: A worker that exits by itself within this many seconds of its start is not restarted (it
#: cannot start: a bad option, an import error, a port in use); the server stops instead. A
#: worker killed by a signal is always restarted.
MIN_LIFETIME = 10.0

#: Exit status when a worker cannot start (uvicorn's own code for a startup failure).
STARTUP_FAILURE = 3


def command(host: str, port: int, workers: int, extra: Sequence[str] = ()) -> list[str]:
    """The command line serving the app with the service's limits (this module)."""
    return [
        sys.executable,
        "-m",
        "app.server",
        "--host",
        host,
        "--port",
        str(port),
        "--workers",
        str(workers),
        *extra,
    ]


def listening_socket(host: str, port: int) -> socket.socket:
    """A TCP socket listening on ``(host, port)`` that other sockets may share (SO_REUSEPORT)."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    sock = socket.socket(family, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
    sock.bind((host, port))
    sock.listen(BACKLOG)
    sock.set_inheritable(True)
    return sock


def uvicorn_config(options: Sequence[str]) -> Any:
    """uvicorn's Config for the app from uvicorn's command-line options (parsed by uvicorn's own
    command, so every option of ``uvicorn --help`` works here)."""
    import uvicorn
    from uvicorn.config import LOGGING_CONFIG
    from uvicorn.main import main as uvicorn_main

    with uvicorn_main.make_context("uvicorn", ["app.main:app", *options]) as context:
        params = dict(context.params)
    if params.pop("app_dir", None):
        sys.path.insert(0, os.path.abspath(str(context.params["app_dir"])))
    if params.get("log_config") is None:
        params["log_config"] = LOGGING_CONFIG
    params["headers"] = [header.split(":", 1) for header in params.get("headers") or ()]
    for name in ("reload_dirs", "reload_includes", "reload_excludes"):
        params[name] = params.get(name) or None
    return uvicorn.Config(**params)


def serve(sock: socket.socket, options: Sequence[str]) -> None:
    """Run one worker on ``sock`` until SIGTERM (uvicorn's graceful shutdown)."""
    config = uvicorn_config(options)
    config.load()  # imports the app: everything it holds for good exists from here on
    warm_app()
    tune_gc()
    keep_request_threads()
    start_pool()
    uvicorn_server(config).run(sockets=[sock])


def warm_app() -> None:
    """Build what the app otherwise builds on its first request, on the event loop: the
    OpenAPI document (read by the format negotiation of every GET that has formats, 0.6-0.9 s
    of the GIL; a burst's refusals waited behind it)."""
    from app.main import app

    app.openapi()


def start_pool() -> None:
    """Fork the worker's compute processes (app/compute_pool.py) now: the app and its kernels
    are loaded, and no other thread runs yet."""
    from app.compute_pool import ComputePool
    from app.main import app

    admission = app.state.admission
    if admission.settings.compute_processes > 0:
        admission.pool = ComputePool(admission.settings)
        admission.pool.start()


#: Seconds an idle request thread waits for work before it ends (anyio's default: 10).
REQUEST_THREAD_IDLE_SECONDS = 3600


def keep_request_threads() -> None:
    """Keep the worker's request threads between bursts instead of starting them anew.

    FastAPI runs each synchronous endpoint, a refusal's pricing included, in one of anyio's
    threads (at most ``DCOSH_COMPUTE_THREADS`` + ``SPARE_THREADS``), and anyio ends the threads
    idle for 10 s. So a burst after a quiet spell started up to seven threads per worker, and
    ``Thread.start`` holds the event loop until the new thread has run: on a busy host, a wait
    for the scheduler per thread, before the burst's first refusals. A 2 ms stack sampler of
    both workers' loops, D1 and D4b construction bursts 11 s apart at load 8-9: 4-24 samples
    (median 7.5) in ``Thread.start`` per burst with anyio's default, 0-3 with this after the
    first burst (which starts them); the refusals' latency at that load moved less than its
    noise. The threads are bounded, so keeping them costs their stacks only.
    anyio's knob is a class attribute of its asyncio backend; tests/api/test_admission.py
    fails if it moves."""
    from anyio._backends._asyncio import WorkerThread

    WorkerThread.MAX_IDLE_TIME = REQUEST_THREAD_IDLE_SECONDS


#: The cyclic garbage collector's thresholds in a worker (Python's default: 700, 10, 10).
GC_THRESHOLDS = (10_000, 10, 10)


def tune_gc() -> None:
    """Keep the cyclic garbage collector from stopping the worker for long.

    A collection holds the GIL, so while it runs the event loop answers nothing, /health
    included. mp computations allocate millions of tracked objects (mpmath numbers), so the
    collector ran hundreds of times per request, and each full collection walked the ~180,000
    objects of the imported modules too: 1.2-1.8 s pauses. The objects that exist after the
    import are frozen (never walked again: they live as long as the worker), and a young
    collection waits for 10,000 allocations instead of 700 (docs/reliability.md, measured).
    """
    gc.collect()
    gc.freeze()
    gc.set_threshold(*GC_THRESHOLDS)


def uvicorn_server(config: Any) -> Any:
    import uvicorn

    return uvicorn.Server(config)


def end_with_parent(signum: int = signal.SIGTERM) -> None:
    """Ask Linux to send this process ``signum`` when the thread that started it dies: SIGTERM
    for a worker (never left serving alone after a ``kill -9`` of the server), SIGKILL for a
    compute process (app/compute_pool.py)."""
    name = ctypes.util.find_library("c")
    if name is None:
        return
    with contextlib.suppress(OSError, AttributeError):
        pr_set_pdeathsig = 1
        ctypes.CDLL(name, use_errno=True).prctl(pr_set_pdeathsig, signum)


@dataclass
class Worker:
    sock: socket.socket
    process: subprocess.Popen[bytes] | None = None
    started: float = 0.0


class Supervisor:
    """N workers, each on its own SO_REUSEPORT socket (see the module doc)."""

    def __init__(self, host: str, port: int, workers: int, options: Sequence[str]) -> None:
        self.options = list(options)
        self.workers = [Worker(listening_socket(host, port)) for _ in range(workers)]
        self.stopping = False

    def start(self, worker: Worker) -> None:
        fd = worker.sock.fileno()
        worker.process = subprocess.Popen(
            [sys.executable, "-m", "app.server", "--listen-fd", str(fd), *self.options],
            pass_fds=(fd,),
        )
        worker.started = time.monotonic()

    def stop(self, signum: int = signal.SIGTERM, frame: Any = None) -> None:
        """Forward SIGTERM to every worker; they drain and exit (uvicorn's graceful shutdown)."""
        self.stopping = True
        for worker in self.workers:
            if worker.process is not None and worker.process.poll() is None:
                with contextlib.suppress(ProcessLookupError):
                    worker.process.send_signal(signal.SIGTERM)
            # no new connection is queued on a socket whose worker is leaving
            worker.sock.close()

    def run(self) -> int:
        signal.signal(signal.SIGTERM, self.stop)
        signal.signal(signal.SIGINT, self.stop)
        for worker in self.workers:
            self.start(worker)
        status = 0
        while True:
            running = [w for w in self.workers if w.process is not None]
            if not running:
                return status
            try:
                pid, code = os.wait()
            except ChildProcessError:
                return status
            for worker in running:
                assert worker.process is not None
                if worker.process.pid != pid:
                    continue
                exit_code = os.waitstatus_to_exitcode(code)
                worker.process.returncode = exit_code
                worker.process = None
                if self.stopping:
                    continue
                # killed (OOM, kill -9) is restarted; an exit of its own right away is a failure
                if exit_code >= 0 and time.monotonic() - worker.started < MIN_LIFETIME:
                    print(f"app.server: worker {pid} exited at start; stopping", file=sys.stderr)
                    status = STARTUP_FAILURE
                    self.stop()
                else:
                    print(f"app.server: worker {pid} died; starting another", file=sys.stderr)
                    self.start(worker)


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--host", default=os.environ.get("HOST", "127.0.0.1"))
    parser.add_argument("--port", type=int, default=int(os.environ.get("PORT", "8000")))
    parser.add_argument("--workers", type=int, default=int(os.environ.get("WORKERS", "1")))
    parser.add_argument("--listen-fd", type=int, default=None, help=argparse.SUPPRESS)
    args, extra = parser.parse_known_args(argv)
    options = [*UVICORN_FLAGS, *extra]
    if args.listen_fd is not None:  # a worker started by the supervisor
        end_with_parent()
        serve(socket.socket(fileno=args.listen_fd), options)
        return
    print(
        f"app.server: serving on {args.host}:{args.port} with {args.workers} worker(s)",
        file=sys.stderr,
    )
    if args.workers <= 1:
        serve(listening_socket(args.host, args.port), options)
        return
    raise SystemExit(Supervisor(args.host, args.port, args.workers, options).run())


if __name__ == "__main__":
    main()
