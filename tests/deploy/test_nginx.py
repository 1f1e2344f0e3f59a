"""Two replicas behind nginx (deploy/nginx.conf, Debian's nginx) on loopback: a repeated GET is a
cache hit, If-None-Match revalidates through the proxy, killing one replica loses no GET, and
overload 503s reach the client with Retry-After. `make test` installs nginx when missing."""

from __future__ import annotations

import http.client
import os
import shutil
import signal
import subprocess
import tempfile
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import ExitStack
from pathlib import Path

import pytest

from tests.deploy.servers import ROOT, free_port, uvicorn_server, wait_until_serving

NGINX = shutil.which("nginx") or shutil.which("nginx", path="/usr/sbin:/sbin")
pytestmark = pytest.mark.skipif(NGINX is None, reason="nginx is not installed (make test does)")

CURVE = "/discretizations/d4b?d=0.3&i_max=40"


def render(config: str, ports: tuple[int, int], listen: int, root: Path) -> str:
    """deploy/nginx.conf on loopback: the replicas' ports, the proxy's port, private paths."""
    for directory in ("cache", "lib", "log"):
        (root / directory).mkdir()
        (root / directory).chmod(0o777)  # nginx's workers run as nobody when started as root
    return (
        config.replace("server app1:8000", f"server 127.0.0.1:{ports[0]}")
        .replace("server app2:8000", f"server 127.0.0.1:{ports[1]}")
        .replace("listen 8080;", f"listen 127.0.0.1:{listen};")
        .replace("/var/cache/nginx/dcosh", str(root / "cache"))
        .replace("/var/lib/nginx", str(root / "lib"))
        .replace("/var/log/nginx", str(root / "log"))
    )


@pytest.fixture(scope="module")
def proxy() -> Iterator[dict[str, object]]:
    # not under pytest's private temporary directory: nginx's workers (nobody) must reach it
    root = Path(tempfile.mkdtemp(prefix="dcosh-nginx-"))
    root.chmod(0o755)
    # a 1 s admission budget: a second request admitted beside one of 0.6 s is refused (503)
    env = {"DCOSH_TIME_LIMIT": "10", "DCOSH_ADMISSION_SECONDS": "1"}
    with ExitStack() as stack:
        replicas = [stack.enter_context(uvicorn_server(env)) for _ in range(2)]
        listen = free_port()
        config = root / "nginx.conf"
        template = (ROOT / "deploy" / "nginx.conf").read_text(encoding="utf-8")
        config.write_text(render(template, (replicas[0][0], replicas[1][0]), listen, root))
        assert NGINX is not None
        nginx = subprocess.Popen(
            [NGINX, "-p", str(root), "-c", str(config), "-g", f"daemon off; pid {root}/nginx.pid;"],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
        )
        try:
            wait_until_serving(listen, "/health", timeout=30)
            yield {"port": listen, "replicas": replicas}
        finally:
            nginx.send_signal(signal.SIGQUIT)
            try:
                nginx.wait(timeout=10)
            except subprocess.TimeoutExpired:
                nginx.kill()
                nginx.wait()
            shutil.rmtree(root, ignore_errors=True)


def get(port: int, path: str, headers: dict[str, str] | None = None) -> http.client.HTTPResponse:
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    connection.request("GET", path, headers=headers or {})
    response = connection.getresponse()
    response.read()
    connection.close()
    return response


def test_a_repeated_get_is_a_cache_hit(proxy: dict[str, object]) -> None:
    port = int(proxy["port"])  # type: ignore[call-overload]
    first = get(port, CURVE)
    assert first.status == 200
    assert first.getheader("X-Cache-Status") == "MISS"
    second = get(port, CURVE)
    assert second.status == 200
    assert second.getheader("X-Cache-Status") == "HIT"
    assert second.getheader("ETag") == first.getheader("ETag")


def test_if_none_match_revalidates_through_the_proxy(proxy: dict[str, object]) -> None:
    port = int(proxy["port"])  # type: ignore[call-overload]
    path = "/discretizations/d1?i_max=30"
    etag = get(port, path).getheader("ETag")
    assert etag
    again = get(port, path, {"If-None-Match": etag})
    assert again.status == 304
    assert again.getheader("ETag") == etag
    other = get(port, path, {"If-None-Match": '"something-else"'})
    assert other.status == 200


def test_killing_one_replica_loses_no_get(proxy: dict[str, object]) -> None:
    port = int(proxy["port"])  # type: ignore[call-overload]
    replicas = proxy["replicas"]
    assert isinstance(replicas, list)
    _, process = replicas[0]
    os.kill(process.pid, signal.SIGKILL)
    process.wait()
    statuses = [get(port, f"/discretizations/d4b?d=0.3&i_max={k}").status for k in range(10, 40)]
    assert statuses == [200] * 30


def test_overload_503s_reach_the_client_with_retry_after(proxy: dict[str, object]) -> None:
    port = int(proxy["port"])  # type: ignore[call-overload]
    # each estimated at about 0.6 s against the replicas' 1 s admission budget: one at a time per
    # replica is admitted, the others sent at the same moment are refused (distinct queries, so
    # neither nginx's cache lock nor the app's coalescing of identical requests merges them)
    paths = [
        f"/discretizations/d4b?d=0.0001{k}&method=closed-form&i_min=0&i_max=150000"
        for k in range(6)
    ]
    with ThreadPoolExecutor(len(paths)) as pool:
        responses = list(pool.map(lambda path: get(port, path), paths))
    refused = [r for r in responses if r.status == 503]
    assert refused, [r.status for r in responses]
    assert {r.status for r in responses} <= {200, 503}
    for response in refused:
        assert response.getheader("Content-Type") == "application/problem+json"
        assert int(response.getheader("Retry-After") or 0) >= 1
        assert response.getheader("X-Cache-Status") != "HIT"
    assert get(port, "/health").status == 200
