"""`make load`: a bounded load run against a real server on 127.0.0.1, printing the figures of
issue 17's "Done when".

Starts the service as `make run` does (app/server.py, 2 workers, the production malloc settings)
on a free port, then:

1. bursts: 32 concurrent maximum-size requests of each computational endpoint, both precisions
   (each with a fresh parameter, so that all compute; sent from a plain-socket client in a
   process of its own, ``BURST``; LOAD_BURSTS=name,... runs only those): every answer must be
   a 200 within the time limit or a 503 with Retry-After within 100 ms, none later than the
   limit + 1 s; /health is polled meanwhile (p99 <= 50 ms), and each worker's peak resident
   memory and the most connections it held (the spread of the burst over the workers) are
   sampled;
2. hostile clients: a 2 GiB chunked upload, a 10 MB header and a 1-byte/s body, each cut off
   early with a 4xx, and the workers' memory before and after;
3. mixed load: the mix below over 64 connections for LOAD_MIXED_SECONDS (300): a line per fifth
   of the run (requests, 503s, /health p50 and p99, worker memory, load average), then errors
   other than 503 with Retry-After, latency percentiles per kind, and whether worker memory
   stayed flat after the first fifth: resident memory minus what the worker's response cache
   holds (read from /ready) grows by under 10 % or 20 MiB, and no cache passes its bound
   (``memory_flat``).

Every phase prints the host's load average, and the end lists each target as met or MISSED;
exit status 1 when one is missed. Measurements on a shared machine are the machine's: rerun on
a quiet host for the figures of the issue.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
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
sys.path.insert(0, str(ROOT))

from app.server import command
from app.settings import Settings

TIME_LIMIT = Settings().time_limit

#: The heaviest requests the default limits admit, per endpoint and precision; {h} is a fresh
#: h in [1, 1.2) for every request, so that none is answered from a cache.
BURSTS: list[tuple[str, str]] = [
    (
        "d4b construction",
        "/discretizations/d4b?h={h}&d=0.0001&i_min=-1726000&i_max=-726000&format=npy",
    ),
    (
        "d4b closed form",
        "/discretizations/d4b?h={h}&d=0.0001&method=closed-form&i_min=-500000&i_max=500000",
    ),
    ("d1", "/discretizations/d1?c=0.0001&delta=0.001&y0={h}&i_min=-500000&i_max=500000&format=npy"),
    ("d4b mp 50", "/discretizations/d4b?h={h}&precision=mp&digits=50&i_min=-1249&i_max=1249"),
    ("d4b mp 1000", "/discretizations/d4b?h={h}&precision=mp&digits=1000&i_min=-399&i_max=399"),
    (
        "d2a-quad mp",
        "/discretizations/d2a-quad?f1=1.{k}&precision=mp&digits=50&i_min=-1999&i_max=1999",
    ),
    (
        "surface glb",
        "/surfaces/catenoid?discretization=d4b&h={h}&d=0.001&i_min=-1000&i_max=999&m=150&format=glb",
    ),
    (
        "surface mp",
        "/surfaces/catenoid?discretization=d4b&h={h}&precision=mp&digits=1&i_min=-20&i_max=20&m=40",
    ),
    ("relations", "/relations?d4b.h={h}&d4b.i_min=-50000&d4b.i_max=50000&d4b.d=0.0001"),
    ("relations mp", "/relations?d4b.h={h}&precision=mp&digits=1000"),
    ("convergence", "/convergence/theorem-14?levels=15&h={h}"),
    ("convergence mp", "/convergence/theorem-11?precision=mp&digits=20&levels=3&j0={k}"),
]

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


def worker_rss_mib(pid: int) -> dict[int, float]:
    """Resident memory of each uvicorn worker (the children of the server process), MiB."""
    out: dict[int, float] = {}
    children = Path(f"/proc/{pid}/task/{pid}/children")
    pids = [int(p) for p in children.read_text().split()] if children.exists() else [pid]
    for p in pids:
        try:
            for line in Path(f"/proc/{p}/status").read_text().splitlines():
                if line.startswith("VmRSS:"):
                    out[p] = int(line.split()[1]) / 1024
        except FileNotFoundError:
            pass
    return out


def pool_rss_mib(pid: int) -> float:
    """Resident memory of the workers' compute processes (app/compute_pool.py) together, MiB
    (pages they still share with their worker are counted in both)."""
    total = 0.0
    for worker in worker_pids(pid):
        pids = []  # children of any of its threads (replacements fork from a thread of the pool)
        for children in Path(f"/proc/{worker}/task").glob("*/children"):
            try:
                pids += [int(p) for p in children.read_text().split()]
            except FileNotFoundError:
                continue
        for p in pids:
            try:
                for line in Path(f"/proc/{p}/status").read_text().splitlines():
                    if line.startswith("VmRSS:"):
                        total += int(line.split()[1]) / 1024
            except FileNotFoundError:
                pass
    return total


def worker_pids(pid: int) -> list[int]:
    """The worker processes of the server (app/server.py's children, or the server itself)."""
    children = Path(f"/proc/{pid}/task/{pid}/children")
    pids = [int(p) for p in children.read_text().split()] if children.exists() else []
    return pids or [pid]


def connections_per_worker(pid: int, port: int) -> dict[int, int]:
    """Established connections to ``port`` held by each worker (from /proc: socket inodes)."""
    established = set()
    for line in Path("/proc/net/tcp").read_text().splitlines()[1:]:
        fields = line.split()
        if int(fields[1].split(":")[1], 16) == port and fields[3] == "01":
            established.add(int(fields[9]))
    held: dict[int, int] = {}
    for worker in worker_pids(pid):
        count = 0
        try:
            for fd in Path(f"/proc/{worker}/fd").iterdir():
                try:
                    target = os.readlink(fd)
                except OSError:
                    continue
                if target.startswith("socket:[") and int(target[8:-1]) in established:
                    count += 1
        except FileNotFoundError:
            pass
        held[worker] = count
    return held


def cache_mib(pid: int, port: int, attempts: int = 64) -> dict[int, float]:
    """What each worker's response cache holds, MiB (``X-Response-Cache-Bytes`` of /ready): a
    new connection per attempt, the kernel picks its worker, /proc tells which one accepted
    it; until every worker has answered once."""
    workers = worker_pids(pid)
    found: dict[int, float] = {}
    for _ in range(attempts):
        if len(found) == len(workers):
            break
        with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
            sock.sendall(b"GET /ready HTTP/1.1\r\nHost: load\r\n\r\n")
            data = b""
            while b"\r\n\r\n" not in data:
                chunk = sock.recv(65536)
                if not chunk:
                    break
                data += chunk
            held = next(
                (
                    int(line.split(b":", 1)[1])
                    for line in data.split(b"\r\n")
                    if line.lower().startswith(b"x-response-cache-bytes:")
                ),
                None,
            )
            worker = worker_of(workers, port, sock.getsockname()[1])
        if held is not None and worker is not None:
            found[worker] = held / 2**20
    return found


def worker_of(workers: list[int], port: int, client_port: int) -> int | None:
    """The worker holding the server end of the connection from ``client_port``."""
    inode = None
    for line in Path("/proc/net/tcp").read_text().splitlines()[1:]:
        fields = line.split()
        local, remote = fields[1].split(":")[1], fields[2].split(":")[1]
        if int(local, 16) == port and int(remote, 16) == client_port:
            inode = int(fields[9])
    if inode is None:
        return None
    for worker in workers:
        with contextlib.suppress(FileNotFoundError):
            for fd in Path(f"/proc/{worker}/fd").iterdir():
                with contextlib.suppress(OSError):
                    if os.readlink(fd) == f"socket:[{inode}]":
                        return worker
    return None


def load_average() -> str:
    one, five, _ = os.getloadavg()
    return f"load average {one:.1f} (5 min {five:.1f})"


#: A /health prober in a process of its own (``HealthProbe``): one keep-alive connection, a GET
#: every 50 ms, (time, latency) pairs printed as JSON when its stdin closes. The load
#: generator's own event loop (64 connections, answers of tens of MB parsed) was the slowest
#: party on a loaded host (1.9 GB and 40 % of a core in the mixed phase), and a /health
#: request sent from it waited for that loop, not only for the server.
PROBE = r"""
import json, select, socket, sys, time
port = int(sys.argv[1])
out = []
def connect():
    return socket.create_connection(("127.0.0.1", port), timeout=10)
sock = connect()
while not select.select([sys.stdin], [], [], 0)[0]:
    start = time.perf_counter()
    try:
        sock.sendall(b"GET /health HTTP/1.1\r\nHost: probe\r\n\r\n")
        data = b""
        while b"\r\n\r\n" not in data:
            chunk = sock.recv(65536)
            if not chunk:
                raise OSError("closed")
            data += chunk
        head, _, body = data.partition(b"\r\n\r\n")
        length = next(
            int(line.split(b":", 1)[1])
            for line in head.split(b"\r\n")
            if line.lower().startswith(b"content-length:")
        )
        while len(body) < length:
            chunk = sock.recv(65536)
            if not chunk:
                raise OSError("closed")
            body += chunk
        out.append((start, time.perf_counter() - start))
    except OSError:
        out.append((start, 10.0))
        sock.close()
        sock = connect()
    if len(out) == 1:
        print("ready", flush=True)  # started: the burst may be sent
    time.sleep(0.05)
print(json.dumps(out))
"""


class HealthProbe:
    """``PROBE`` running against ``port`` until ``stop()``, which returns its samples."""

    def __init__(self, port: int) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-c", PROBE, str(port)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )
        # its interpreter's start (≈ 35 ms of CPU) is over before the burst is sent: it
        # overlapped the burst's first refusals, on the same two cores, before
        assert self.process.stdout is not None
        self.process.stdout.readline()

    def stop(self) -> list[tuple[float, float]]:
        out, _ = self.process.communicate("", timeout=60)
        return [(t, latency) for t, latency in json.loads(out.splitlines()[-1])]


#: What httpx's client sends, so that the bursts' answers are compressed as before.
ACCEPT_ENCODING = "gzip, deflate"


def percentile(values: list[float], q: float) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))] if values else float("nan")


#: One burst's requests, sent from a process of its own (``burst``): each request on a
#: connection of its own (connect, write), all at once; the time from the connect to the
#: response's end, its status and whether it carried Retry-After, as JSON on stdout. Plain
#: sockets and one selector: the client's own work is ≈ 0.3 ms of CPU a request (32 /health:
#: 6-12 ms beyond the interpreter's start). httpx's AsyncClient, used before, took 100-180 ms
#: of CPU for the same 32 (3-5 ms a request and its set-up), all of it inside the measured
#: times, on the same two cores as the burst's computations: on one server at load 5 its
#: D1 and D4b construction refusals measured p50 223-454 ms against 77-184 ms from this
#: client, interleaved (docs/reliability.md).
BURST = r"""
import json, selectors, socket, sys, time
port, timeout = int(sys.argv[1]), float(sys.argv[2])
requests = json.loads(sys.stdin.read())
selector = selectors.DefaultSelector()
state = {}
for url, encoding in requests:
    start = time.perf_counter()
    try:
        sock = socket.create_connection(("127.0.0.1", port), timeout=10)
        sock.sendall(
            f"GET {url} HTTP/1.1\r\nHost: load\r\nAccept: */*\r\n"
            f"Accept-Encoding: {encoding}\r\nConnection: close\r\n\r\n".encode()
        )
    except OSError:
        state[object()] = [start, time.perf_counter(), b"", True]
        continue
    sock.setblocking(False)
    selector.register(sock, selectors.EVENT_READ)
    state[sock] = [start, None, b"", False]
deadline = time.perf_counter() + timeout
while selector.get_map() and time.perf_counter() < deadline:
    for key, _ in selector.select(1.0):
        sock = key.fileobj
        entry = state[sock]
        try:
            data = sock.recv(1 << 20)
        except OSError:
            data, entry[3] = b"", True
        if len(entry[2]) < 4096:
            entry[2] += data[:4096]  # the head (a 503's problem fits too)
        if not data:
            entry[1] = time.perf_counter()
            selector.unregister(sock)
            sock.close()
out = []
for entry in state.values():
    head = entry[2].split(b"\r\n\r\n", 1)[0].lower()
    status = int(head.split(b" ", 2)[1]) if head.startswith(b"http/1.1 ") else 0
    ended = entry[1] if entry[1] is not None else time.perf_counter()
    out.append((0 if entry[3] else status, ended - entry[0], b"\r\nretry-after:" in head))
print(json.dumps(out))
"""


async def burst(
    base: str, pid: int, port: int, name: str, path: str, rng: random.Random
) -> dict[str, bool]:
    """32 concurrent copies of one request (sent by ``BURST`` in a process of its own);
    /health polled; peak worker memory and the most connections each worker held sampled.
    Returns which targets were met."""
    health: list[float] = []
    peaks: dict[int, float] = defaultdict(float)
    pool_peak = 0.0
    spread: dict[int, int] = defaultdict(int)
    done = asyncio.Event()
    urls = []
    for _ in range(32):
        url = path.replace("{h}", f"{rng.uniform(1, 1.2):.9f}")
        urls.append((url.replace("{k}", str(rng.randint(10, 99))), ACCEPT_ENCODING))

    async def probe() -> None:
        nonlocal pool_peak
        async with httpx.AsyncClient(base_url=base, timeout=10) as prober:
            while not done.is_set():
                start = time.perf_counter()
                try:
                    await prober.get("/health")
                    health.append(time.perf_counter() - start)
                except httpx.HTTPError:
                    health.append(10.0)
                for worker, rss in worker_rss_mib(pid).items():
                    peaks[worker] = max(peaks[worker], rss)
                pool_peak = max(pool_peak, pool_rss_mib(pid))
                for worker, held in connections_per_worker(pid, port).items():
                    spread[worker] = max(spread[worker], held)
                await asyncio.sleep(0.05)

    separate = HealthProbe(port)
    client = await asyncio.create_subprocess_exec(
        sys.executable,
        "-c",
        BURST,
        str(port),
        str(TIME_LIMIT + 30),
        stdin=asyncio.subprocess.PIPE,
        stdout=asyncio.subprocess.PIPE,
    )
    prober = asyncio.create_task(probe())
    out, _ = await client.communicate(json.dumps(urls).encode())
    done.set()
    await prober
    probed = [latency for _, latency in separate.stop()]
    results: list[tuple[int, float, bool]] = [(s, t, r) for s, t, r in json.loads(out)]
    ok = [t for s, t, _ in results if s == 200]
    refused = [t for s, t, r in results if s == 503]
    other = [s for s, _, _ in results if s not in (200, 503)]
    late = sum(t > TIME_LIMIT + 1 for _, t, _ in results)
    slow_refusals = sum(t > 0.1 for t in refused)
    no_retry = sum(1 for s, _, r in results if s == 503 and not r)
    h99 = percentile(probed, 0.99) * 1e3
    print(
        f"{name:<16} 200: {len(ok):>2} (max {max(ok, default=0):5.1f} s)  503: {len(refused):>2} "
        f"(p50 {percentile(refused, 0.5) * 1e3 if refused else 0:6.1f} ms, "
        f"p99 {percentile(refused, 0.99) * 1e3 if refused else 0:6.1f} ms, "
        f"max {max(refused, default=0) * 1e3:6.1f} ms, "
        f"> 100 ms: {slow_refusals})  other: {sorted(set(other))}  late: {late}  "
        f"/health p99 {h99:5.1f} ms (from the load's client {percentile(health, 0.99) * 1e3:5.1f})"
        f"  peak RSS {', '.join(f'{v:.0f}' for v in peaks.values())} MiB"
        f" (compute processes {pool_peak:.0f} MiB)"
        f"  connections per worker {'/'.join(str(v) for v in spread.values())}"
        f"  load {os.getloadavg()[0]:.1f}"
    )
    return {
        "answers: 200 in time or 503 with Retry-After": late == 0 and not other and not no_retry,
        "503 within 100 ms": slow_refusals == 0,
        "/health p99 <= 50 ms": h99 <= 50,
    }


def hostile(port: int, pid: int) -> bool:
    """A 2 GiB chunked upload, a 10 MB header, a 1-byte/s body: each cut off with a 4xx."""

    def status_of(sock: socket.socket) -> int:
        data = b""
        while b"\r\n" not in data:
            chunk = sock.recv(4096)
            if not chunk:
                return 0
            data += chunk
        return int(data.split(b" ", 2)[1])

    before = worker_rss_mib(pid)
    ok = True
    head = "POST /discretizations/d2b HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
    cases = {
        "2 GiB chunked upload": (head + "Transfer-Encoding: chunked\r\n\r\n").encode(),
        "10 MB header": b"GET /health HTTP/1.1\r\nHost: x\r\nX-Big: "
        + b"a" * 10_000_000
        + b"\r\n\r\n",
        "1-byte/s body": (head + "Content-Length: 1000\r\n\r\n").encode(),
    }
    for name, start in cases.items():
        begin = time.perf_counter()
        sent = 0
        with socket.create_connection(("127.0.0.1", port), timeout=60) as sock:
            try:
                sock.sendall(start)
                if name.startswith("2 GiB"):
                    chunk = b"x" * (1 << 20)
                    while sent < 2 << 30:
                        sock.sendall(b"%x\r\n%s\r\n" % (len(chunk), chunk))
                        sent += len(chunk)
                elif name.startswith("1-byte"):
                    sock.settimeout(1.0)
                    for _ in range(60):
                        sock.sendall(b" ")
                        sent += 1
                        try:
                            if sock.recv(1, socket.MSG_PEEK):
                                break
                        except TimeoutError:
                            continue
            except OSError:
                pass
            sock.settimeout(60)
            try:
                status = status_of(sock)
            except OSError:
                status = 0
        elapsed = time.perf_counter() - begin
        ok &= 400 <= status < 500
        print(f"{name:<22} {status} after {elapsed:5.1f} s, {sent / 2**20:8.1f} MiB sent")
    time.sleep(2)
    after = worker_rss_mib(pid)
    print(
        "worker memory before "
        + ", ".join(f"{v:.0f}" for v in before.values())
        + " MiB, after "
        + ", ".join(f"{v:.0f}" for v in after.values())
        + " MiB"
    )
    return ok


async def mixed(
    base: str,
    pid: int,
    port: int,
    seconds: float,
    concurrency: int,
    windows: int = 5,
    seed: int = 1,
) -> tuple[
    dict[str, tuple[list[float], dict[int, int]]],
    int,
    list[dict[int, float]],
    list[dict[int, float]],
]:
    """The mix over ``concurrency`` connections for ``seconds``; a line of figures per window
    (requests, errors, /health p99, worker memory, load average). Returns the latencies and
    statuses per kind, the errors and each window's worker memory."""
    rng = random.Random(seed)
    kinds = [k for k, _, w in MIX for _ in range(w)]
    paths = {k: p for k, p, _ in MIX}
    latencies: dict[str, list[float]] = defaultdict(list)
    statuses: dict[str, dict[int, int]] = defaultdict(lambda: defaultdict(int))
    errors = 0
    failures: dict[str, int] = defaultdict(int)
    etags: dict[str, str] = {}
    window: list[tuple[str, float, int]] = []  # (kind, latency, status) of the current window
    memory: list[dict[int, float]] = []
    caches: list[dict[int, float]] = []  # each window's response cache per worker, MiB
    begin = time.perf_counter()
    end = begin + seconds
    # keep-alive below the server's 5 s: a connection uvicorn closes while idle is never reused
    limits = httpx.Limits(
        max_connections=concurrency, max_keepalive_connections=concurrency, keepalive_expiry=2.0
    )
    async with httpx.AsyncClient(base_url=base, timeout=60, limits=limits) as client:

        async def worker() -> None:
            nonlocal errors
            while time.perf_counter() < end:
                kind = rng.choice(kinds)
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
                    window.append((kind, time.perf_counter() - start, 0))
                    continue
                elapsed = time.perf_counter() - start
                latencies[kind].append(elapsed)
                statuses[kind][response.status_code] += 1
                window.append((kind, elapsed, response.status_code))
                documented = response.status_code == 503 and "retry-after" in response.headers
                if response.status_code >= 500 and not documented:
                    errors += 1
                    failures[f"{kind}: HTTP {response.status_code}"] += 1
                if "etag" in response.headers:
                    etags[kind] = response.headers["etag"]

        async def reporter() -> None:
            step = seconds / windows
            for number in range(1, windows + 1):
                await asyncio.sleep(max(0.0, begin + number * step - time.perf_counter()))
                done = window[:]
                window.clear()
                health = [t for k, t, _ in done if k == "health"]
                refused = sum(1 for _, _, code in done if code == 503)
                rss = worker_rss_mib(pid)
                cached = await asyncio.to_thread(cache_mib, pid, port)
                memory.append(rss)
                caches.append(cached)
                print(
                    f"  {number * step:5.0f} s: {len(done):5d} requests "
                    f"({len(done) / step:4.0f}/s), 503: {refused:4d}, "
                    f"/health p50 {percentile(health, 0.5) * 1e3:6.1f} ms "
                    f"p99 {percentile(health, 0.99) * 1e3:7.1f} ms, worker memory "
                    + ", ".join(f"{v:.0f}" for v in rss.values())
                    + " MiB (response cache "
                    + ", ".join(f"{cached.get(w, float('nan')):.0f}" for w in rss)
                    + f" MiB), {load_average()}",
                    flush=True,
                )

        separate = HealthProbe(port)
        await asyncio.gather(reporter(), *(worker() for _ in range(concurrency)))
        probed = separate.stop()
    step = seconds / windows
    for number in range(windows):
        low = begin + number * step
        inside = [latency for t, latency in probed if low <= t < low + step]
        print(
            f"  /health from a separate process, {(number + 1) * step:5.0f} s: p50 "
            f"{percentile(inside, 0.5) * 1e3:6.1f} ms p99 {percentile(inside, 0.99) * 1e3:7.1f} ms"
        )
    report = {k: (latencies[k], dict(statuses[k])) for k in latencies}
    for what, count in sorted(failures.items()):
        print(f"  failed: {what} × {count}")
    return report, errors, memory, caches


def memory_flat(
    memory: list[dict[int, float]], caches: list[dict[int, float]], cache_bound: int
) -> tuple[bool, str]:
    """Whether worker memory stayed flat after the first window, and a line saying so.

    The response cache (DCOSH_RESPONSE_CACHE_BYTES per worker) fills with the load's distinct
    answers for longer than a run lasts, so resident memory grows with it until it reaches
    its bound: that is the bound working, not a leak. Flat therefore means: each worker's
    resident memory *minus what its cache holds* grows by at most 10 % (or 20 MiB) after the
    first window, and no cache holds more than its bound. A worker whose cache could not be
    read is judged on its resident memory alone."""
    first, last = memory[0], memory[-1]
    first_cache, last_cache = caches[0], caches[-1]
    bound = cache_bound / 2**20
    flat = True
    parts = []
    for worker, rss in first.items():
        cached = worker in first_cache and worker in last_cache
        before = rss - first_cache.get(worker, 0.0) if cached else rss
        after = last.get(worker, 0.0) - (last_cache.get(worker, 0.0) if cached else 0.0)
        within = after - before <= max(20.0, 0.1 * before)
        kept = all(c.get(worker, 0.0) <= bound for c in caches)
        flat = flat and within and kept
        parts.append(
            f"{rss:.0f} -> {last.get(worker, 0.0):.0f} MiB resident, response cache "
            f"{first_cache.get(worker, float('nan')):.0f} -> "
            f"{last_cache.get(worker, float('nan')):.0f} MiB (bound {bound:.0f}), "
            f"without it {before:.0f} -> {after:.0f} MiB"
        )
    return flat, "worker memory after the first window to the end: " + "; ".join(parts)


def main() -> int:
    seconds = float(os.environ.get("LOAD_MIXED_SECONDS", "300"))
    concurrency = int(os.environ.get("LOAD_CONCURRENCY", "64"))
    only = os.environ.get("LOAD_PHASES", "bursts,hostile,mixed").split(",")
    port = free_port()
    server = subprocess.Popen(
        command("127.0.0.1", port, 2, ["--log-level", "warning"]),
        cwd=ROOT,
        env={**os.environ, **SERVER_ENV},
    )
    base = f"http://127.0.0.1:{port}"
    targets: dict[str, bool] = {}

    def record(met: dict[str, bool]) -> None:
        for what, ok in met.items():
            targets[what] = targets.get(what, True) and ok

    try:
        for _ in range(300):
            try:
                httpx.get(f"{base}/health", timeout=1)
                break
            except httpx.HTTPError:
                time.sleep(0.1)
        for _ in range(4):
            httpx.get(f"{base}/discretizations/d4b")  # warm both workers' code paths once
        idle = worker_rss_mib(server.pid)
        print(f"idle workers: {', '.join(f'{v:.0f}' for v in idle.values())} MiB; {load_average()}")
        if "bursts" in only:
            print(
                f"\n1. bursts: 32 concurrent requests each, 2 workers, time limit {TIME_LIMIT:g} s;"
                f" {load_average()}"
            )
            rng = random.Random(1)
            chosen = os.environ.get("LOAD_BURSTS", "")  # names of BURSTS, comma-separated
            for name, path in BURSTS:
                if chosen and name not in chosen.split(","):
                    continue
                record(asyncio.run(burst(base, server.pid, port, name, path, rng)))
        if "hostile" in only:
            print(f"\n2. hostile clients; {load_average()}")
            record({"hostile clients cut off with a 4xx": hostile(port, server.pid)})
        if "mixed" in only:
            print(f"\n3. mixed load: {concurrency} connections for {seconds:g} s; {load_average()}")
            run = mixed(base, server.pid, port, seconds, concurrency)
            report, errors, memory, caches = asyncio.run(run)
            total = sum(len(v[0]) for v in report.values())
            print(f"{total} requests ({total / seconds:.0f}/s); {load_average()}")
            print(f"{'kind':<14}{'count':>7}{'p50 ms':>10}{'p99 ms':>10}  statuses")
            for kind, (lat, codes) in sorted(report.items()):
                p50 = statistics.median(lat) * 1e3
                p99 = percentile(lat, 0.99) * 1e3
                print(f"{kind:<14}{len(lat):>7}{p50:>10.1f}{p99:>10.1f}  {codes}")
            print(f"errors other than 503 with Retry-After: {errors}")
            flat, summary = memory_flat(memory, caches, Settings().response_cache_bytes)
            print(summary)
            record(
                {
                    "mixed: no errors other than 503 with Retry-After": errors == 0,
                    "mixed: worker memory flat": flat,
                }
            )
    finally:
        server.send_signal(signal.SIGTERM)
        server.wait(timeout=40)
    print(f"\ntargets ({load_average()}; figures on a loaded host are the host's):")
    for what, ok in targets.items():
        print(f"  {'met   ' if ok else 'MISSED'} {what}")
    return 0 if all(targets.values()) else 1


if __name__ == "__main__":
    raise SystemExit(main())
