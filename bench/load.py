"""`make load`: a bounded load run against a real server on 127.0.0.1.

Starts uvicorn (2 workers, as in production) on a free port, records the workers' resident
memory, sends a fixed number of requests over many concurrent connections — a mix of valid
small and heavy curves, mp requests, invalid and oversize input, unknown ids, 304
revalidations — then reports errors (any 5xx or transport error), latency percentiles per kind
and the memory after the run and after a pause. Exit status 1 on any server error.
"""

from __future__ import annotations

import asyncio
import os
import random
import signal
import socket
import statistics
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

import httpx

ROOT = Path(__file__).resolve().parents[1]

MIX: list[tuple[str, str, int]] = [  # (kind, path and query, weight)
    # {u} is replaced by a fresh number in (0.01, 0.9) and {k} by an integer in 1..20 on every
    # request, so that these compute instead of hitting the response cache (a slider's traffic)
    ("slider", "/discretizations/d4b?d={u}", 20),
    ("d1", "/discretizations/d1?c={u}", 4),
    ("d3", "/discretizations/d3?c={k}&y0=2{k}", 4),
    ("d4a", "/discretizations/d4a?s={u}", 4),
    ("d2a-quad", "/discretizations/d2a-quad?f1=1.{k}", 4),
    ("d2a-hex", "/discretizations/d2a-hex?lambda={u}", 4),
    ("d2b", "/discretizations/d2b?j={k}", 4),
    ("smooth", "/smooth/tractrix?h={u}", 3),
    ("surface-glb", "/surfaces/catenoid?format=glb&d={u}", 3),
    ("figure", "/figures/figure-7.svg?d={u}", 3),
    ("relations", "/relations?d4b.d={u}", 2),
    ("convergence", "/convergence/theorem-15?levels=5&d0={u}", 2),
    ("npy", "/discretizations/d4b?format=npy&i_min=-5000&i_max=5000&d=0.001{k}", 2),
    ("mp-heavy", "/discretizations/d4b?precision=mp&digits=200&i_min=-60&i_max=60&d={u}", 1),
    ("small", "/discretizations/d4b", 30),
    ("small-tilted", "/discretizations/d4b?beta0=0.7&d=0.3", 10),
    ("heavy", "/discretizations/d4b?method=closed-form&d=0.0001&i_min=-100000&i_max=100000", 3),
    ("construction", "/discretizations/d4b?d=0.001&i_min=-20000&i_max=20000", 3),
    ("mp", "/discretizations/d4b?precision=mp&digits=60&i_min=-20&i_max=20", 5),
    ("csv", "/discretizations/d4b?format=csv&i_min=-500&i_max=500", 5),
    ("theorem", "/theorems/theorem-5?d=0.2", 8),
    ("invalid", "/discretizations/d4b?d=2", 10),
    ("oversize", "/discretizations/d4b?i_min=-9000000&i_max=9000000", 5),
    ("nan", "/discretizations/d4b?h=nan", 5),
    ("unknown", "/discretizations/d99", 5),
    ("catalog", "/discretizations", 5),
    ("health", "/health", 5),
]


#: glibc malloc settings of the server processes (also in the Makefile and the Dockerfile);
#: overridable from the environment for comparison runs.
SERVER_ENV = {
    "MALLOC_ARENA_MAX": os.environ.get("MALLOC_ARENA_MAX", "2"),
    "MALLOC_MMAP_THRESHOLD_": os.environ.get("MALLOC_MMAP_THRESHOLD_", "131072"),
    "MALLOC_TRIM_THRESHOLD_": os.environ.get("MALLOC_TRIM_THRESHOLD_", "8388608"),
}


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def rss_kib(pid: int) -> int:
    """Resident memory of a process and its children (the uvicorn workers), KiB."""
    total = 0
    pids = [pid]
    children = Path(f"/proc/{pid}/task/{pid}/children")
    if children.exists():
        pids += [int(p) for p in children.read_text().split()]
    for p in pids:
        try:
            for line in Path(f"/proc/{p}/status").read_text().splitlines():
                if line.startswith("VmRSS:"):
                    total += int(line.split()[1])
        except FileNotFoundError:
            pass
    return total


async def run(base: str, requests: int, concurrency: int, seed: int = 1) -> tuple[dict, int]:
    rng = random.Random(seed)
    kinds = [k for k, _, w in MIX for _ in range(w)]
    paths = {k: p for k, p, _ in MIX}
    latencies: dict[str, list[float]] = defaultdict(list)
    statuses: dict[str, dict[int, int]] = defaultdict(lambda: defaultdict(int))
    errors = 0
    failures: dict[str, int] = defaultdict(int)
    queue: asyncio.Queue[str] = asyncio.Queue()
    for _ in range(requests):
        queue.put_nowait(rng.choice(kinds))
    etags: dict[str, str] = {}
    # keep-alive below the server's 5 s: a connection uvicorn closes while idle is never reused
    limits = httpx.Limits(
        max_connections=concurrency, max_keepalive_connections=concurrency, keepalive_expiry=2.0
    )
    async with httpx.AsyncClient(base_url=base, timeout=60, limits=limits) as client:

        async def worker() -> None:
            nonlocal errors
            while not queue.empty():
                kind = queue.get_nowait()
                path = paths[kind].replace("{u}", f"{rng.uniform(0.01, 0.9):.6f}")
                path = path.replace("{k}", str(rng.randint(1, 20)))
                headers = {}
                if kind == "small" and rng.random() < 0.3 and "small" in etags:
                    headers["If-None-Match"] = etags["small"]
                start = time.perf_counter()
                try:
                    response = await client.get(path, headers=headers)
                except httpx.HTTPError as error:
                    errors += 1
                    failures[f"{kind}: {type(error).__name__}"] += 1
                    continue
                latencies[kind].append(time.perf_counter() - start)
                statuses[kind][response.status_code] += 1
                if response.status_code >= 500:
                    errors += 1
                    failures[f"{kind}: HTTP {response.status_code}"] += 1
                if "etag" in response.headers:
                    etags[kind] = response.headers["etag"]

        await asyncio.gather(*(worker() for _ in range(concurrency)))
    report = {k: (latencies[k], dict(statuses[k])) for k in latencies}
    for what, count in sorted(failures.items()):
        print(f"  failed: {what} × {count}")
    return report, errors


def main() -> int:
    requests = int(os.environ.get("LOAD_REQUESTS", "3000"))
    concurrency = int(os.environ.get("LOAD_CONCURRENCY", "64"))
    port = free_port()
    env = {**os.environ, **SERVER_ENV}
    server = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "uvicorn",
            "app.main:app",
            "--host",
            "127.0.0.1",
            "--port",
            str(port),
            "--workers",
            "2",
            "--log-level",
            "warning",
        ],
        cwd=ROOT,
        env=env,
    )
    base = f"http://127.0.0.1:{port}"
    try:
        for _ in range(150):
            try:
                httpx.get(f"{base}/health", timeout=1)
                break
            except httpx.HTTPError:
                time.sleep(0.1)
        httpx.get(f"{base}/discretizations/d4b")  # warm both code paths once
        before = rss_kib(server.pid)
        started = time.perf_counter()
        report, errors = asyncio.run(run(base, requests, concurrency))
        elapsed = time.perf_counter() - started
        memory = [rss_kib(server.pid)]
        # the same load again, twice: memory that grows with traffic would keep growing;
        # caches and allocator pools that reached their size stay where they are
        for seed in (2, 3):
            again, errors_again = asyncio.run(run(base, requests, concurrency, seed=seed))
            errors += errors_again
            for kind, (lat, codes) in again.items():
                report.setdefault(kind, ([], {}))[0].extend(lat)
                for code, count in codes.items():
                    report[kind][1][code] = report[kind][1].get(code, 0) + count
            memory.append(rss_kib(server.pid))
    finally:
        server.send_signal(signal.SIGINT)
        server.wait(timeout=20)
    total = sum(len(v[0]) for v in report.values())
    print(
        f"load: 3 × {requests} requests, {concurrency} connections, 2 workers; first round "
        f"{elapsed:.1f} s ({total / 3 / elapsed:.0f} requests/s)"
    )
    print(f"{'kind':<14}{'count':>7}{'p50 ms':>10}{'p99 ms':>10}  statuses")
    for kind, (lat, codes) in sorted(report.items()):
        lat = sorted(lat)
        p50 = statistics.median(lat) * 1e3
        p99 = lat[min(len(lat) - 1, int(0.99 * len(lat)))] * 1e3
        print(f"{kind:<14}{len(lat):>7}{p50:>10.1f}{p99:>10.1f}  {codes}")
    print(f"server errors (5xx or transport): {errors}")
    rounds = ", ".join(f"{m / 1024:.1f}" for m in memory)
    print(
        f"memory of the server processes: {before / 1024:.1f} MiB before, after each round "
        f"{rounds} MiB (the response cache holds up to DCOSH_RESPONSE_CACHE_BYTES per worker)"
    )
    return 1 if errors else 0


if __name__ == "__main__":
    raise SystemExit(main())
