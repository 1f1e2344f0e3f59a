"""The Dockerfile's install path and CMD, run here (there is no Docker engine on CI machines).

The image installs requirements/runtime.txt and then the package; its CMD starts uvicorn on
app.main:app with $HOST, $PORT, $WORKERS. This test runs that same command line in this venv
and asks /health, so a broken entry point or CMD fails here, not in production.
"""

from __future__ import annotations

import json
import os
import re
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCKERFILE = (ROOT / "Dockerfile").read_text(encoding="utf-8")


def test_dockerfile_installs_the_pinned_runtime_set_as_non_root() -> None:
    assert re.search(r"^FROM python:3\.11-slim", DOCKERFILE, re.M)
    assert "pip install -r requirements/runtime.txt" in DOCKERFILE
    assert "pip install --no-deps ." in DOCKERFILE
    user = re.search(r"^USER (\S+)", DOCKERFILE, re.M)
    assert user is not None and user.group(1) not in {"root", "0"}
    assert "HEALTHCHECK" in DOCKERFILE
    assert "$WORKERS" in DOCKERFILE


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_the_image_command_serves_health() -> None:
    cmd = json.loads(re.search(r"^CMD (\[.*\])$", DOCKERFILE, re.M).group(1))  # type: ignore[union-attr]
    assert cmd[:2] == ["sh", "-c"]
    port = free_port()
    env = {
        **os.environ,
        "HOST": "127.0.0.1",
        "PORT": str(port),
        "WORKERS": "2",
        "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}",
    }
    # the CMD exactly as the image runs it: sh -c 'exec uvicorn ... "$PORT" ...'
    process = subprocess.Popen(
        cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE
    )
    try:
        deadline = time.monotonic() + 30
        while True:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/health", timeout=2) as r:
                    assert json.load(r)["status"] == "ok"
                    break
            except OSError:
                assert process.poll() is None, process.stderr.read().decode()  # type: ignore[union-attr]
                assert time.monotonic() < deadline, "the server did not answer in 30 s"
                time.sleep(0.2)
        with urllib.request.urlopen(
            f"http://127.0.0.1:{port}/discretizations/d4b?i_min=0&i_max=1", timeout=5
        ) as r:
            assert json.load(r)["vertices"] == [[-0.1, 1.0], [0.1, 1.0]]
    finally:
        process.terminate()
        process.wait(timeout=10)
