"""The Dockerfile's install path and CMD, run here (there is no Docker engine on CI machines).

The image installs requirements/runtime.txt and runs the app from its source tree; its CMD
(python -m app.server) starts uvicorn on app.main:app with $HOST, $PORT, $WORKERS and the limits
of `make run`. This test runs that same command line in this venv
and asks /health, so a broken entry point or CMD fails here, not in production.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path
from typing import IO

ROOT = Path(__file__).resolve().parents[1]
DOCKERFILE = (ROOT / "Dockerfile").read_text(encoding="utf-8")


def test_dockerfile_installs_the_pinned_runtime_set_as_non_root() -> None:
    assert re.search(r"^ARG PYTHON_IMAGE=python:3\.11-slim", DOCKERFILE, re.M)
    assert re.search(r"^FROM \$\{PYTHON_IMAGE\}$", DOCKERFILE, re.M)
    assert "pip install -r requirements/runtime.txt" in DOCKERFILE
    user = re.search(r"^USER (\S+)", DOCKERFILE, re.M)
    assert user is not None and user.group(1) not in {"root", "0"}
    assert "HEALTHCHECK" in DOCKERFILE
    assert "WORKERS=2" in DOCKERFILE  # read by app.server


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_the_image_command_serves_health() -> None:
    cmd = json.loads(re.search(r"^CMD (\[.*\])$", DOCKERFILE, re.M).group(1))  # type: ignore[union-attr]
    assert cmd == ["python", "-m", "app.server"]
    port = free_port()
    env = {
        **os.environ,
        "HOST": "127.0.0.1",
        "PORT": str(port),
        "WORKERS": "2",
        "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}",
    }
    # the CMD exactly as the image runs it (app.server starts the workers); in a session of
    # its own with no stdin (an xdist worker's stdin is its channel to the controller), so that
    # the whole process group can be ended, whatever the server does
    with tempfile.TemporaryFile() as log:
        process = subprocess.Popen(
            cmd,
            cwd=ROOT,
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=log,
            start_new_session=True,
        )
        try:
            deadline = time.monotonic() + 30
            while True:
                try:
                    with urllib.request.urlopen(f"http://127.0.0.1:{port}/health", timeout=2) as r:
                        assert json.load(r)["status"] == "ok"
                        break
                except OSError:
                    assert process.poll() is None, server_log(log)
                    assert time.monotonic() < deadline, "no answer in 30 s: " + server_log(log)
                    time.sleep(0.2)
            with urllib.request.urlopen(
                f"http://127.0.0.1:{port}/discretizations/d4b?i_min=0&i_max=1", timeout=5
            ) as r:
                assert json.load(r)["vertices"] == [[-0.1, 1.0], [0.1, 1.0]]
        finally:
            end_process_group(process)


def server_log(log: IO[bytes]) -> str:
    log.seek(0)
    return log.read().decode(errors="replace")


def end_process_group(process: subprocess.Popen[bytes]) -> None:
    """SIGTERM to the server and its workers; SIGKILL to whatever is left after 10 s."""
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signal.SIGTERM)
    with contextlib.suppress(subprocess.TimeoutExpired):
        process.wait(timeout=10)
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signal.SIGKILL)
    process.wait(timeout=10)
