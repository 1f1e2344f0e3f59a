"""HTTP on 127.0.0.1: small GETs against the bare endpoint, and a 10^6-vertex response end to end.

Starts uvicorn (uvloop, httptools, 1 worker, the malloc settings of ``make run``, access log
off) on a free port of 127.0.0.1 and measures, with wall-clock time:

1. requests/s and p50/p99 latency (wrk, bounded runs of ``WRK_SECONDS``) at concurrency 1 and
   32 of a 100-vertex D4b GET, against GET /health on the same server in the same round
   (alternating, median of ``ROUNDS`` paired ratios):
   - *cached*: the same URL again and again (the response cache's fast path);
   - *computed*: a different d on every request (no cache can help: the full computation with
     every check, what a slider in a front end asks for);
   and the computed one with 2 workers against 1;
2. a 10^6-vertex response (the catenary sampled 10^6 times: its JSON is the vertex array plus
   the indices) fetched whole over a socket, first request (a new x_max each time, so computed)
   and cached, as JSON and as format=npy, against ``orjson.dumps`` of the same (n, 2) array in
   this process (measured next to each fetch).

``python bench/serving.py computed`` measures only the computed GETs of issue 13 on the served
configuration (``python -m app.server``), with and without the fast lane (app/fast_lane.py):
two servers, rounds interleaved, requests/s and the server's CPU per request side by side
(``BENCH_SERVERS=<n>``: over n sets of fresh servers; ``BENCH_BEFORE``: with another tree's).
``python bench/serving.py compute`` times the same 100-vertex D4b computation in process
(wall clock, fresh processes alternating with ``BENCH_BEFORE``'s tree if given).

Needs wrk (``make bench`` installs Debian's package when it is missing).
Run: .venv/bin/python bench/serving.py   (about 100 s)
"""

from __future__ import annotations

import functools
import gzip
import os
import re
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import zlib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import orjson

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from app.geometry.precision import Float64
from app.geometry.smooth import curves as smooth
from bench.common import record_target, sample
from bench.load import SERVER_ENV, free_port

clock = time.perf_counter

ROUNDS = int(os.environ.get("BENCH_ROUNDS", "3"))
WRK_SECONDS = int(os.environ.get("BENCH_WRK_SECONDS", "2"))
SMALL = "/discretizations/d4b?i_min=-50&i_max=49"
BIG_COUNT = 10**6
#: Targets of the issue: small GET >= 80 % of the bare endpoint's requests/s; the 10^6-vertex
#: JSON response <= 1.3× the encoder alone.
RPS_TARGET = 0.8
JSON_TARGET = 1.3
#: Issue 13: a computed (uncached) small GET against /health on the served configuration
#: (``python -m app.server``: h11, the service's limits), with every check and with none.
COMPUTED_TARGETS = {"every check": 0.3, "checks=none": 0.6}

#: wrk script: a new d on every request; the run's first d comes from its argument, so that no
#: two runs (nor rounds, nor concurrencies) ask for the same curve.
UNIQUE_SCRIPT = """
local n = 0
init = function(args)
  n = tonumber(args[1])
end
request = function()
  n = n + 1
  return wrk.format(nil, string.format("%s&d=%%.12f", 0.1 + n * 1e-9))
end
"""


@dataclass(frozen=True)
class Load:
    """One wrk run: requests/s and latency percentiles in seconds."""

    rps: float
    p50: float
    p99: float
    requests: int = 0
    cpu: float = 0.0
    """Server CPU seconds per request (``wrk(..., server=…)``), else 0."""


_UNITS = {"us": 1e-6, "ms": 1e-3, "s": 1.0, "m": 60.0}


def _seconds(text: str) -> float:
    match = re.fullmatch(r"([\d.]+)(us|ms|s|m)", text)
    if match is None:
        raise ValueError(f"unexpected wrk latency {text!r}")
    return float(match.group(1)) * _UNITS[match.group(2)]


_runs = iter(range(1, 10**6))
#: How far apart the first requests of two runs of UNIQUE_SCRIPT are: a run makes fewer than
#: 10^5 requests, and 300 runs keep d within 0.1 .. 0.13 (with 10^7, d grew by 0.01 a run and
#: reached h = 1 at the 90th run, whose requests were all refused).
RUN_SPACING = 10**5


def cpu_seconds(pid: int) -> float:
    """User plus system CPU seconds of process ``pid`` so far (Linux /proc)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def wrk(
    base: str,
    path: str,
    connections: int,
    script: str | None = None,
    server: subprocess.Popen[bytes] | None = None,
) -> Load:
    """A bounded wrk run (one thread) against ``base + path``; with ``server``, also the
    server's CPU seconds per request (which the other tenants of a busy host disturb far less
    than requests/s)."""
    command = ["wrk", "-t1", f"-c{connections}", f"-d{WRK_SECONDS}s", "--latency"]
    if script is not None:
        command += ["-s", script]
    command.append(base + path)
    if script is not None:
        command += ["--", str(next(_runs) * RUN_SPACING)]
    before = 0.0 if server is None else cpu_seconds(server.pid)
    out = subprocess.run(command, capture_output=True, text=True, check=True, timeout=60).stdout
    cpu = 0.0 if server is None else cpu_seconds(server.pid) - before
    rps = float(re.search(r"Requests/sec:\s+([\d.]+)", out).group(1))  # type: ignore[union-attr]
    p50 = _seconds(re.search(r"^\s+50%\s+(\S+)", out, re.M).group(1))  # type: ignore[union-attr]
    p99 = _seconds(re.search(r"^\s+99%\s+(\S+)", out, re.M).group(1))  # type: ignore[union-attr]
    if "Non-2xx" in out or "Socket errors" in out:
        raise RuntimeError(f"wrk saw errors:\n{out}")
    requests = int(re.search(r"(\d+) requests in", out).group(1))  # type: ignore[union-attr]
    return Load(rps, p50, p99, requests, cpu / max(requests, 1))


_buffer = bytearray(64 << 20)


def fetch(port: int, path: str, headers: str = "") -> tuple[float, bytes]:
    """Wall time to send one GET and read the whole response (into a reused buffer, no copies
    while timed); and the response's body."""
    global _buffer
    total = 0
    start = time.perf_counter()
    with socket.create_connection(("127.0.0.1", port)) as sock:
        request = f"GET {path} HTTP/1.1\r\nHost: bench\r\n{headers}Connection: close\r\n\r\n"
        sock.sendall(request.encode())
        while True:
            if total == len(_buffer):
                _buffer += bytearray(len(_buffer))
            got = sock.recv_into(memoryview(_buffer)[total:])
            if not got:
                break
            total += got
    elapsed = time.perf_counter() - start
    head, _, body = bytes(_buffer[:total]).partition(b"\r\n\r\n")
    if not head.startswith(b"HTTP/1.1 200"):
        raise RuntimeError(f"GET {path}: {head[:200]!r}")
    return elapsed, body


def start_server(port: int, workers: int = 1) -> subprocess.Popen[bytes]:
    command = [
        sys.executable,
        "-m",
        "uvicorn",
        "app.main:app",
        "--host",
        "127.0.0.1",
        "--port",
        str(port),
        "--workers",
        str(workers),
        "--loop",
        "uvloop",
        "--http",
        "httptools",
        "--log-level",
        "warning",
    ]
    return _serving(subprocess.Popen(command, cwd=ROOT, env={**os.environ, **SERVER_ENV}), port)


def _serving(server: subprocess.Popen[bytes], port: int) -> subprocess.Popen[bytes]:
    """``server`` once it answers /health on ``port`` (stopped if it never does)."""
    for _ in range(200):
        try:
            fetch(port, "/health")
            return server
        except OSError:
            time.sleep(0.1)
    server.terminate()
    raise RuntimeError("the server did not start")


def _ms(seconds: float) -> str:
    return f"{seconds * 1e3:8.2f} ms"


def _verdict(ratio: float, target: float, at_least: bool, label: str | None = None) -> str:
    if label is not None:
        record_target(label, ratio, target, "≥" if at_least else "≤")
    met = ratio >= target if at_least else ratio <= target
    return f"   target {'≥' if at_least else '≤'} {target:g}×: {'met' if met else 'NOT met'}"


LABELS = {"bare": "GET /health (bare)", "cached": "D4b, cached", "computed": "D4b, computed"}


def small_gets(base: str, script: str) -> None:
    print(
        f" 100-vertex D4b GET ({SMALL}) against GET /health, wrk {WRK_SECONDS} s per run, "
        f"median of {ROUNDS} alternating rounds"
    )
    for connections in (1, 32):
        runs: dict[str, list[Load]] = {"bare": [], "cached": [], "computed": []}
        for _ in range(ROUNDS):
            runs["bare"].append(wrk(base, "/health", connections))
            runs["cached"].append(wrk(base, SMALL, connections))
            runs["computed"].append(wrk(base, SMALL, connections, script))
        for name, loads in runs.items():
            ratio = statistics.median(
                s.rps / b.rps for s, b in zip(loads, runs["bare"], strict=True)
            )
            verdict = ""
            if name == "cached":
                label = f"cached 100-vertex D4b GET, c={connections}, × /health"
                verdict = _verdict(ratio, RPS_TARGET, True, label)
            rps = statistics.median(s.rps for s in loads)
            p50 = statistics.median(s.p50 for s in loads)
            p99 = statistics.median(s.p99 for s in loads)
            print(
                f"  c={connections:<3}{LABELS[name]:<20}{rps:9.0f} req/s  p50 {_ms(p50)}  "
                f"p99 {_ms(p99)}  {ratio:6.3f}× bare{verdict}"
            )


def _paired(
    port: int,
    reference: Callable[[], float],
    path: Callable[[], str],
    repeat: int,
    headers: str = "",
    client: Callable[[bytes], object] | None = None,
) -> tuple[float, float, int, float]:
    """Median fetch time, median ratio to the reference timed just before, bytes, reference."""
    pairs = []
    size = 0
    for _ in range(repeat):
        ref = reference()
        seconds, body = fetch(port, path(), headers)
        if client is not None:  # what the client does with the body (gunzip), timed too
            start = time.perf_counter()
            client(body)
            seconds += time.perf_counter() - start
        size = len(body)
        pairs.append((seconds, ref))
    return (
        statistics.median(s for s, _ in pairs),
        statistics.median(s / r for s, r in pairs),
        size,
        statistics.median(r for _, r in pairs),
    )


def big_response(port: int, count: int, gzip_too: bool) -> None:
    ar = Float64()
    vertices = smooth.catenary(ar, 1.0, smooth.sample(ar, -3.0, 3.0, count))

    def encoder() -> float:
        return statistics.median(
            sample(lambda: orjson.dumps(vertices, option=orjson.OPT_SERIALIZE_NUMPY), 0.0, clock)
            for _ in range(3)
        )

    encoded = len(orjson.dumps(vertices, option=orjson.OPT_SERIALIZE_NUMPY))
    base = f"/smooth/catenary?count={count}"
    counter = iter(range(1, 10**6))

    def fresh(suffix: str) -> Callable[[], str]:
        return lambda: f"{base}&x_max={3 + next(counter) * 1e-9!r}{suffix}"

    def same(suffix: str) -> Callable[[], str]:
        return lambda: base + suffix

    gz = "Accept-Encoding: gzip\r\n"
    cases: list[tuple[str, Callable[[], str], str, bool]] = [
        ("JSON, first request (computed)", fresh(""), "", True),
        ("JSON, cached", same(""), "", True),
        ("npy, first request (computed)", fresh("&format=npy"), "", False),
        ("npy, cached", same("&format=npy"), "", False),
    ]
    if gzip_too:
        cases += [
            ("JSON gzip + gunzip, first request", fresh(""), gz, False),
            ("JSON gzip + gunzip, cached", same(""), gz, False),
        ]
    for label, path, headers, _ in cases:
        if "first" not in label:
            fetch(port, path(), headers)  # now kept in the cache
    print(
        f" {count:,}-vertex catenary over HTTP (whole response read from a socket) against "
        f"orjson.dumps of its (n, 2) vertex array ({encoded / 1e6:.1f} MB), paired, median"
    )
    references = []
    for label, path, headers, targeted in cases:
        repeat = 3 if "first" in label else 5
        inflate = (lambda body: zlib.decompress(body, wbits=31)) if headers else None
        seconds, ratio, size, ref = _paired(port, encoder, path, repeat, headers, inflate)
        references.append(ref)
        targeted = targeted and count == BIG_COUNT  # the target is for 10^6 vertices
        verdict = ""
        if targeted:
            verdict = _verdict(
                ratio, JSON_TARGET, False, f"10^6 vertices, {label.strip()}, × orjson"
            )
        print(f"  {label:<36}{_ms(seconds)}  {size / 1e6:7.2f} MB  {ratio:6.2f}× orjson{verdict}")
    print(f"  (orjson of the array alone: {_ms(statistics.median(references))})")


def gzip_levels(count: int) -> None:
    """gzip's cost and gain per level on a curve's JSON, in this process."""
    from app.geometry.smooth import references as smooth_curves
    from app.responses import curve_document, encode_json

    body = encode_json(curve_document(smooth_curves.compute_catenary(Float64(), count=count)))
    print(f" gzip of a {count:,}-vertex catenary's JSON ({len(body) / 1e6:.1f} MB), in process")
    for level in (1, 6, 9):
        packed = gzip.compress(body, compresslevel=level, mtime=0)
        seconds = statistics.median(
            sample(functools.partial(gzip.compress, body, compresslevel=level), 0.0)
            for _ in range(3)
        )
        unpack = statistics.median(
            sample(functools.partial(gzip.decompress, packed), 0.0) for _ in range(3)
        )
        print(
            f"  level {level}: {len(body) / len(packed):5.2f}× smaller, compress {_ms(seconds)} "
            f"({len(body) / seconds / 1e6:4.0f} MB/s), decompress {_ms(unpack)}"
        )


def start_service(
    port: int, env: dict[str, str] | None = None, tree: Path = ROOT
) -> subprocess.Popen[bytes]:
    """The server as ``make run`` starts it (``python -m app.server``), access log off;
    ``tree``: the checkout whose ``app`` it serves (this one by default)."""
    from app.server import command

    argv = command("127.0.0.1", port, 1, ["--log-level", "warning", "--no-access-log"])
    environment = {**os.environ, **SERVER_ENV, **(env or {})}
    if (
        tree != ROOT
    ):  # its own compiled kernels (warm them there first: python -m app.geometry.warm)
        environment["NUMBA_CACHE_DIR"] = str(tree / ".numba-cache")
    return _serving(subprocess.Popen(argv, cwd=tree, env=environment), port)


#: The served configuration, and the same without the fast lane (app/fast_lane.py): every
#: request through the whole middleware chain, routing and the thread pool.
CONFIGURATIONS: dict[str, dict[str, str]] = {
    "lane": {},
    "chain": {"DCOSH_FAST_LANE_SECONDS": "0"},
}

#: ``BENCH_BEFORE=<directory>``: also a third server, the served configuration of another
#: checkout (an export of an earlier commit, its kernels warmed there), in the same rounds:
#: before and after side by side.
BEFORE = os.environ.get("BENCH_BEFORE")
TITLES = {
    "lane": "fast lane (served)",
    "chain": "full chain (DCOSH_FAST_LANE_SECONDS=0)",
    "before": f"before ({BEFORE})",
}


def _computed_rounds(
    trees: dict[str, tuple[dict[str, str], Path]],
    scripts: dict[str, str],
    runs: dict[str, dict[str, list[Load]]],
    rounds: int,
) -> None:
    """One set of fresh servers (one per tree), ``rounds`` interleaved rounds of /health and
    each script's GETs on each, appended to ``runs``."""
    servers = {}
    try:
        for name, (env, tree) in trees.items():
            port = free_port()
            servers[name] = (f"http://127.0.0.1:{port}", start_service(port, env, tree))
            fetch(port, SMALL)
        for _ in range(rounds):
            for name, (base, server) in servers.items():
                runs[name]["bare"].append(wrk(base, "/health", 1, server=server))
                for label, script in scripts.items():
                    runs[name][label].append(wrk(base, SMALL, 1, script, server))
    finally:
        for _, server in servers.values():
            server.terminate()
            server.wait(timeout=20)


#: ``BENCH_SERVERS=<n>``: ``computed`` starts its servers afresh n times, ``BENCH_ROUNDS``
#: rounds each, and takes the medians over all of them. One server process of the same code can
#: be 10–30 % faster or slower than the next (where its memory landed, what shares its core):
#: with one set of servers, a comparison mostly tells which process was luckier.
SERVER_SETS = int(os.environ.get("BENCH_SERVERS", "1"))


def _title(variant: str) -> str:
    """How ``computed_gets`` prints a variant (``bare``: the /health runs)."""
    return "GET /health" if variant == "bare" else variant


def computed_gets(rounds: int = ROUNDS, server_sets: int = SERVER_SETS) -> dict[str, float]:
    """Computed 100-vertex D4b GETs (a new d each request) against /health, on the served
    configuration with and without the fast lane (a server each, and one of ``BENCH_BEFORE``'s
    tree if given; rounds interleaved), c=1:
    median of paired ratios per variant over ``server_sets`` fresh sets of servers; returns the
    lane's ratios."""
    trees = {name: (env, ROOT) for name, env in CONFIGURATIONS.items()}
    if BEFORE:
        trees["before"] = ({}, Path(BEFORE).resolve())
    scripts: dict[str, str] = {}
    for label, query in (("every check", ""), ("checks=none", "&checks=none")):
        descriptor, scripts[label] = tempfile.mkstemp(suffix=".lua")
        with os.fdopen(descriptor, "w") as handle:
            handle.write(UNIQUE_SCRIPT % (SMALL + query))
    runs: dict[str, dict[str, list[Load]]] = {
        name: {"bare": [], **{label: [] for label in scripts}} for name in trees
    }
    try:
        for _ in range(server_sets):
            _computed_rounds(trees, scripts, runs, rounds)
    finally:
        for script in scripts.values():
            os.unlink(script)
    sets = f"{server_sets} sets of servers × " if server_sets > 1 else ""
    print(
        f" computed 100-vertex D4b GET (a new d each request) against GET /health, "
        f"python -m app.server (h11), c=1, wrk {WRK_SECONDS} s, median of {sets}{rounds} "
        f"interleaved rounds; load average {os.getloadavg()[0]:.1f}"
    )
    print(
        "  per variant: requests/s, p50, ratio to /health (requests/s), server CPU ms per "
        "request, and ratio to /health in server CPU"
    )
    print(f"  {'':<14}" + "   ".join(f"{TITLES[name]:>52}" for name in trees))
    ratios = {}
    for variant in runs["lane"]:
        cells = []
        for name in trees:
            loads, bare = runs[name][variant], runs[name]["bare"]
            ratio = statistics.median(s.rps / b.rps for s, b in zip(loads, bare, strict=True))
            rps = statistics.median(s.rps for s in loads)
            p50 = statistics.median(s.p50 for s in loads)
            cpu = statistics.median(s.cpu for s in loads)
            share = statistics.median(b.cpu / s.cpu for s, b in zip(loads, bare, strict=True))
            cells.append(
                f"{rps:6.0f} req/s {_ms(p50)} {ratio:5.3f}× {cpu * 1e3:6.3f} ms {share:5.3f}×"
            )
            if name == "lane":
                ratios[variant] = ratio
                target = COMPUTED_TARGETS.get(variant)
                if target:  # the same ratio in server CPU, steadier on a busy host
                    label = f"computed 100-vertex D4b GET, {variant}, × /health (server CPU)"
                    record_target(label, share, target, "≥")
        target = COMPUTED_TARGETS.get(variant)
        verdict = ""
        if target:
            label = f"computed 100-vertex D4b GET, {variant}, × /health"
            verdict = "   " + record_target(label, ratios[variant], target, "≥")
        title = _title(variant)
        print(f"  {title:<14}" + "   ".join(f"{cell:>52}" for cell in cells) + verdict)
    if "before" in runs:  # the same rounds of the two trees, run by run
        paired = {
            variant: statistics.median(
                a.cpu / b.cpu
                for a, b in zip(runs["lane"][variant], runs["before"][variant], strict=True)
            )
            for variant in runs["lane"]
        }
        print(
            "  server CPU a request, this tree / before, median of paired runs: "
            + ", ".join(f"{_title(v)} {ratio:5.3f}" for v, ratio in paired.items())
        )
    return ratios


def two_workers(base: str, script: str) -> None:
    """The computed small GET at concurrency 32: 2 workers against 1 (wrk shares the cores)."""
    port = free_port()
    server = start_server(port, workers=2)
    try:
        fetch(port, SMALL)
        pairs = []
        for _ in range(ROUNDS):
            one = wrk(base, SMALL, 32, script)
            two = wrk(f"http://127.0.0.1:{port}", SMALL, 32, script)
            pairs.append((two, one))
    finally:
        server.terminate()
        server.wait(timeout=20)
    ratio = statistics.median(t.rps / o.rps for t, o in pairs)
    rps = statistics.median(t.rps for t, _ in pairs)
    print(
        f" workers: D4b computed, c=32, 2 workers {rps:7.0f} req/s   {ratio:5.2f}× 1 worker "
        f"(p99 {_ms(statistics.median(t.p99 for t, _ in pairs))})"
    )


def main() -> None:
    port = free_port()
    base = f"http://127.0.0.1:{port}"
    server = start_server(port)
    descriptor, script = tempfile.mkstemp(suffix=".lua")
    try:
        with os.fdopen(descriptor, "w") as handle:
            handle.write(UNIQUE_SCRIPT % SMALL)
        cores = os.cpu_count()
        print(f"HTTP on 127.0.0.1: uvicorn (uvloop, httptools), 1 worker; {cores} cores, with wrk")
        fetch(port, SMALL)
        small_gets(base, script)
        two_workers(base, script)
        big_response(port, BIG_COUNT, gzip_too=False)
        big_response(port, BIG_COUNT // 10, gzip_too=True)
        gzip_levels(BIG_COUNT // 10)
    finally:
        os.unlink(script)
        server.terminate()
        server.wait(timeout=20)


#: ``python bench/serving.py compute``: the computation alone, in a fresh process of each tree
#: (``-c`` with the tree first on the path), per request: median and least wall-clock time of
#: 600 computations after 300 to warm up, with every check and with none, and with every check
#: after the data caches were flushed (an 8 MB array written between requests, as a server's
#: own code leaves them). Wall clock: this host's per-process CPU clock moves in steps of tens
#: of microseconds under load; the least of 600 is what a quiet core takes.
IN_PROCESS = """
import os, statistics, sys, time
sys.path.insert(0, os.getcwd())
import numpy as np
from app.geometry.curve import EVERYTHING, Selection
from app.geometry.d4b import discretization
from app.geometry.precision import arithmetic
junk = np.zeros(2**20)
def run(d, selection):
    ar = arithmetic("float64", None)
    discretization.compute(ar, 1.0, d, None, -50, 49, "construction", False, selection)
none = Selection(frozenset(), None)
for k in range(300):
    run(0.1 + k * 1e-9, EVERYTHING)
for label, selection, flush in (("every", EVERYTHING, False), ("none", none, False),
                                ("every, caches flushed", EVERYTHING, True)):
    times = []
    for k in range(600):
        if flush:
            junk += 1.0
        start = time.perf_counter_ns()
        run(0.2 + k * 1e-9, selection)
        times.append(time.perf_counter_ns() - start)
    print(label, statistics.median(times) / 1e3, min(times) / 1e3)
"""


def compute_alone(rounds: int = ROUNDS) -> None:
    """The 100-vertex D4b computation in process, this tree against ``BENCH_BEFORE`` (fresh
    processes, alternating): wall-clock µs per computation."""
    trees = {"after": ROOT}
    if BEFORE:
        trees = {"before": Path(BEFORE).resolve(), **trees}
    found: dict[str, dict[str, list[float]]] = {name: {} for name in trees}
    for _ in range(rounds):
        for name, tree in trees.items():
            environment = {**os.environ, "NUMBA_CACHE_DIR": str(tree / ".numba-cache")}
            output = subprocess.run(
                [sys.executable, "-c", IN_PROCESS],
                cwd=tree,
                env=environment,
                capture_output=True,
                text=True,
                check=True,
            ).stdout
            for line in output.splitlines():
                label, median, least = line.rsplit(" ", 2)
                found[name].setdefault(label, []).append(float(median))
                found[name].setdefault(f"{label} (least)", []).append(float(least))
    print(
        f" 100-vertex D4b computed in process (discretization.compute), wall-clock µs per "
        f"computation (each process's median, or least, of 600), median of {rounds} "
        f"alternating fresh processes; load average "
        f"{os.getloadavg()[0]:.1f}"
    )
    for label in found["after"]:
        cells = [f"{name} {statistics.median(found[name][label]):7.1f}" for name in trees]
        ratio = ""
        if "before" in found:
            after = statistics.median(found["after"][label])
            ratio = f"   after/before {after / statistics.median(found['before'][label]):.3f}"
        print(f"  {label:<30}" + "   ".join(cells) + ratio)


#: ``python bench/serving.py stages``: the served path split in stages. A worker as
#: ``python -m app.server`` configures it (h11, the service's limits, forked compute processes),
#: with ``perf_counter_ns`` around the fast lane's stages and around the whole app call (to the
#: send of the body: what the client waits for; and to the app's return); a raw-socket client
#: (keep-alive, c=1, another process) sends ``STAGE_REQUESTS`` GETs of each kind. Per kind:
#: the client's median wall time per request and each stage's median, in µs (medians do not
#: add up; "app: to body sent" minus the stages inside is the middlewares, the sends and h11's
#: writes).
STAGES = """
import collections, functools, os, statistics, subprocess, sys, threading, time
sys.path.insert(0, os.getcwd())
from time import perf_counter_ns as ns
ACC = collections.defaultdict(list)
def timed(owner, name, label):
    function = getattr(owner, name)
    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        start = ns()
        try:
            return function(*args, **kwargs)
        finally:
            ACC[label].append(ns() - start)
    setattr(owner, name, wrapper)
import app.server as server
config = server.uvicorn_config([*server.UVICORN_FLAGS, "--log-level", "warning", "--no-access-log"])
config.load()
server.warm_app(); server.tune_gc(); server.keep_request_threads(); server.start_pool()
import app.fast_lane as lane
from app.registry import DISCRETIZATIONS
d4b = DISCRETIZATIONS["d4b"]
for owner, name, label in [
    (lane.FastLane, "_answer", "lane: answer (to the reply)"),
    (lane.FastLane, "_compute", "lane: parse, price, compute, encode"),
    (lane, "compute", "compute: admission, selection, core"),
    (d4b.module, "compute", "core: D4b compute"),
    (d4b.query, "model_validate", "parse: model_validate"),
    (lane, "curve_document", "shape: curve_document"),
    (lane, "encode_json", "encode: orjson"),
    (lane, "canonical_key", "key: canonical_key"),
    (lane._Template, "fill", "headers: template fill"),
    (lane.FastLane, "_keep", "keep (after the send)"),
]:
    if hasattr(owner, name):
        timed(owner, name, label)
class Timed:
    def __init__(self, app):
        self.app = app
    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        start = ns()
        async def timed_send(message):
            begin = ns()
            await send(message)
            ACC["h11: send (each)"].append(ns() - begin)
            if message["type"] == "http.response.body":
                ACC["app: to body sent"].append(ns() - start)
        await self.app(scope, receive, timed_send)
        ACC["app: to return"].append(ns() - start)
config.loaded_app = Timed(config.loaded_app)
sock = server.listening_socket("127.0.0.1", 0)
port = sock.getsockname()[1]
uvicorn = server.uvicorn_server(config)
def client():
    time.sleep(1)
    out = {}
    for kind in ("/health", "checks=none", "every check"):
        ACC.clear()
        wall = subprocess.run([sys.executable, "-c", CLIENT, str(port), kind, N], check=True,
                              capture_output=True, text=True).stdout
        out[kind] = (float(wall), {k: statistics.median(v) / 1e3 for k, v in ACC.items()})
    for kind, (wall, stages) in out.items():
        print(f"  {kind}: client wall {wall:.1f} µs per request")
        for label, value in stages.items():
            print(f"    {label:<40}{value:8.1f} µs")
    uvicorn.should_exit = True
threading.Thread(target=client, daemon=True).start()
uvicorn.run(sockets=[sock])
"""

#: The raw-socket client of ``STAGES``: N keep-alive GETs (a new d each), median wall µs.
STAGE_CLIENT = """
import socket, statistics, sys, time
port, kind, n = int(sys.argv[1]), sys.argv[2], int(sys.argv[3])
sock = socket.create_connection(("127.0.0.1", port))
sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
buffer = bytearray(1 << 20)
times = []
for k in range(n):
    path = "/health"
    if kind != "/health":
        checks = "&checks=none" if kind == "checks=none" else ""
        path = "%s%s&d=%.12f" % (SMALL, checks, 0.1 + k * 1e-9)
    start = time.perf_counter_ns()
    sock.sendall(("GET %s HTTP/1.1\\r\\nHost: bench\\r\\n\\r\\n" % path).encode())
    total = 0
    while True:
        total += sock.recv_into(memoryview(buffer)[total:])
        end = buffer.find(b"\\r\\n\\r\\n", 0, total)
        if end >= 0:
            head = bytes(buffer[:end]).lower()
            at = head.index(b"content-length:") + 15
            length = int(head[at:].split(b"\\r\\n", 1)[0])
            if total >= end + 4 + length:
                break
    if not buffer.startswith(b"HTTP/1.1 200"):
        raise SystemExit(bytes(buffer[:200]))
    times.append(time.perf_counter_ns() - start)
print(statistics.median(times) / 1e3)
"""


def served_stages(requests: int = 2000) -> None:
    """The served path split in stages for /health, checks=none and every check (``STAGES``)."""
    print(
        f" the served path in stages (python -m app.server's worker, raw-socket client, c=1, "
        f"{requests} requests a kind), medians in µs; load average {os.getloadavg()[0]:.1f}"
    )
    prelude = f"CLIENT = {STAGE_CLIENT.replace('SMALL', repr(SMALL))!r}\nN = {str(requests)!r}\n"
    subprocess.run(
        [sys.executable, "-c", prelude + STAGES],
        cwd=ROOT,
        env={**os.environ, **SERVER_ENV},
        check=True,
    )


if __name__ == "__main__":
    if sys.argv[1:] == ["computed"]:
        computed_gets()
    elif sys.argv[1:] == ["compute"]:
        compute_alone()
    elif sys.argv[1:] == ["stages"]:
        served_stages(int(os.environ.get("STAGE_REQUESTS", "2000")))
    else:
        main()
