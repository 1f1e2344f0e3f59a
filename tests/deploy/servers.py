"""Real servers on loopback for the deployment tests: uvicorn as `make run` starts it."""

from __future__ import annotations

import http.client
import os
import signal
import socket
import subprocess
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from app.server import command

ROOT = Path(__file__).resolve().parents[2]

#: The production malloc settings of the Makefile's SERVER_ENV.
SERVER_ENV = {
    "MALLOC_ARENA_MAX": "2",
    "MALLOC_MMAP_THRESHOLD_": "131072",
    "MALLOC_TRIM_THRESHOLD_": "8388608",
}


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port: int = s.getsockname()[1]
        return port


def wait_until_serving(port: int, path: str = "/health", timeout: float = 60.0) -> None:
    """Poll ``path`` until it answers (a server starting on a busy machine takes seconds)."""
    end = time.monotonic() + timeout
    while True:
        try:
            connection = http.client.HTTPConnection("127.0.0.1", port, timeout=5)
            connection.request("GET", path)
            connection.getresponse().read()
            connection.close()
            return
        except OSError:
            if time.monotonic() > end:
                raise
            time.sleep(0.1)


@contextmanager
def uvicorn_server(
    env: dict[str, str] | None = None, workers: int = 1, port: int | None = None
) -> Iterator[tuple[int, subprocess.Popen[bytes]]]:
    """A uvicorn server with the service's limits on a free loopback port: (port, process)."""
    port = port or free_port()
    process = subprocess.Popen(
        command("127.0.0.1", port, workers, ["--log-level", "warning"]),
        cwd=ROOT,
        env={**os.environ, **SERVER_ENV, **(env or {})},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        wait_until_serving(port)
        yield port, process
    finally:
        if process.poll() is None:
            process.send_signal(signal.SIGTERM)
            try:
                process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
