"""app/server.py: workers on SO_REUSEPORT sockets of their own, spread by the kernel, restarted
when they die, drained on SIGTERM."""

from __future__ import annotations

import os
import signal
import socket
import time
from pathlib import Path

from tests.deploy.servers import uvicorn_server, wait_until_serving


def _workers(pid: int) -> list[int]:
    children = Path(f"/proc/{pid}/task/{pid}/children").read_text().split()
    return [int(child) for child in children]


def _socket_inodes(pid: int) -> set[int]:
    inodes = set()
    for fd in Path(f"/proc/{pid}/fd").iterdir():
        try:
            target = os.readlink(fd)
        except OSError:
            continue
        if target.startswith("socket:["):
            inodes.add(int(target[8:-1]))
    return inodes


def _connections(port: int) -> set[int]:
    """Inodes of the established TCP connections to ``port`` on 127.0.0.1."""
    inodes = set()
    for line in Path("/proc/net/tcp").read_text().splitlines()[1:]:
        fields = line.split()
        if int(fields[1].split(":")[1], 16) == port and fields[3] == "01":
            inodes.add(int(fields[9]))
    return inodes


def test_each_worker_accepts_its_share_of_a_burst() -> None:
    with uvicorn_server(workers=2) as (port, process):
        workers = _workers(process.pid)
        assert len(workers) == 2
        clients = [socket.create_connection(("127.0.0.1", port)) for _ in range(32)]
        try:
            for client in clients:
                client.sendall(b"GET /health HTTP/1.1\r\nHost: x\r\n\r\n")
            for client in clients:
                assert client.recv(12) == b"HTTP/1.1 200"
            held = {w: len(_socket_inodes(w) & _connections(port)) for w in workers}
        finally:
            for client in clients:
                client.close()
        # each worker has a queue of its own: the kernel hashes connections over both (all 32
        # on one worker has a probability of 2^-31 when the hash is fair)
        assert sum(held.values()) == 32
        assert min(held.values()) >= 1, held


def test_a_worker_that_dies_is_replaced_and_the_port_keeps_serving() -> None:
    with uvicorn_server(workers=2) as (port, process):
        first = _workers(process.pid)
        os.kill(first[0], signal.SIGKILL)
        end = time.monotonic() + 60
        while True:
            now = _workers(process.pid)
            if len(now) == 2 and first[0] not in now:
                break
            assert time.monotonic() < end, now
            time.sleep(0.2)
        assert first[1] in now
        for _ in range(20):
            wait_until_serving(port)


def test_sigterm_stops_every_worker() -> None:
    with uvicorn_server(workers=2) as (_, process):
        workers = _workers(process.pid)
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=40) == 0
        for worker in workers:
            assert not Path(f"/proc/{worker}").exists() or "Z" in _state(worker)


def _state(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/stat").read_text().split()[2]
    except FileNotFoundError:
        return "gone"


def test_a_worker_freezes_what_the_import_made_and_collects_young_objects_less_often() -> None:
    import gc

    from app.server import GC_THRESHOLDS, tune_gc

    thresholds = gc.get_threshold()
    try:
        tune_gc()
        assert gc.get_threshold() == GC_THRESHOLDS == (10_000, 10, 10)
        assert gc.get_freeze_count() > 10_000  # the modules, schemas and kernels imported
    finally:
        gc.unfreeze()
        gc.set_threshold(*thresholds)


def test_a_worker_builds_the_openapi_document_before_its_first_request() -> None:
    """The format negotiation of a GET reads it; built lazily, the first such request held the
    event loop 0.6-0.9 s and every refusal of a burst waited behind it."""
    from app.main import app
    from app.server import warm_app

    warm_app()
    assert app.openapi_schema is not None
    assert "/discretizations/d4b" in app.openapi_schema["paths"]
