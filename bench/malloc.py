"""glibc's mmap threshold for the server (SERVER_ENV in the Makefile), chosen by measurement.

A buffer above ``MALLOC_MMAP_THRESHOLD_`` is a fresh mmap, returned to the system on free, and
its pages fault in again on the next request; below it, it comes from the heap, which keeps
what ``MALLOC_TRIM_THRESHOLD_`` allows. For each candidate threshold a fresh process (the
server's other settings: ``MALLOC_ARENA_MAX=2``, ``MALLOC_TRIM_THRESHOLD_=8388608``) times
D4b as served (construction and every check) at 10^4, 10^5 and 10^6 vertices and D2a-quad at
10^5, and reports its resident memory after the 10^6-vertex computation is freed. The
candidates run in alternation, round after round; figures are medians over rounds, each as a
ratio to glibc's default (no threshold set: dynamic, 128 KiB rising to 32 MiB) in the same
round.

Run: .venv/bin/python bench/malloc.py [rounds]   (about 2 minutes with 3 rounds)
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CANDIDATES: dict[str, str | None] = {
    "glibc default": None,
    "128 KiB": "131072",
    "1 MiB": "1048576",
    "4 MiB": "4194304",
    "32 MiB": "33554432",
}

CHILD = r"""
import json, sys, time
sys.path.insert(0, sys.argv[1])
from app.geometry.d4b import discretization as d4b
from app.geometry.d2a import quad
from app.geometry.precision import Float64
ar = Float64()

def rss():
    for line in open("/proc/self/status"):
        if line.startswith("VmRSS:"):
            return int(line.split()[1])

def best(f, repeat):
    times = []
    for _ in range(repeat):
        t = time.process_time(); f(); times.append(time.process_time() - t)
    return sorted(times)[len(times) // 2]

out = {}
for n, repeat in ((10**4, 9), (10**5, 5), (10**6, 3)):
    lo, hi = -(n // 2), n - n // 2 - 1
    d4b.compute(ar, 1.0, 1e-4, None, lo, hi)
    out[f"d4b {n}"] = best(lambda: d4b.compute(ar, 1.0, 1e-4, None, lo, hi), repeat)
    if n == 10**6:
        out["rss after 10^6 (MiB)"] = rss() / 1024
n = 10**5
quad.compute(ar, 1.0, 1.001, None, -(n // 2), n // 2 - 1)
out["d2a-quad 100000"] = best(lambda: quad.compute(ar, 1.0, 1.001, None, -(n // 2), n // 2 - 1), 5)
print(json.dumps(out))
"""


def run(threshold: str | None) -> dict[str, float]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("MALLOC_")}
    env.update({"MALLOC_ARENA_MAX": "2", "MALLOC_TRIM_THRESHOLD_": "8388608"})
    if threshold is not None:
        env["MALLOC_MMAP_THRESHOLD_"] = threshold
    result = subprocess.run(
        [sys.executable, "-c", CHILD, str(ROOT)], env=env, capture_output=True, text=True
    )
    if result.returncode:
        raise RuntimeError(result.stderr[-2000:])
    figures: dict[str, float] = json.loads(result.stdout.strip().splitlines()[-1])
    return figures


def main(rounds: int = 3) -> None:
    print(
        f"MALLOC_MMAP_THRESHOLD_ (ARENA_MAX=2, TRIM_THRESHOLD_=8 MiB), {rounds} rounds; "
        "time × glibc's default in the same round (median), resident memory after 10^6"
    )
    samples: dict[str, list[dict[str, float]]] = {name: [] for name in CANDIDATES}
    start = time.perf_counter()
    for _ in range(rounds):
        for name, threshold in CANDIDATES.items():
            samples[name].append(run(threshold))
    keys = [k for k in samples["glibc default"][0] if not k.startswith("rss")]
    print(f"  {'threshold':<14}" + "".join(f"{k:>17}" for k in keys) + f"{'RSS (MiB)':>12}")
    for name in CANDIDATES:
        cells = []
        for key in keys:
            pairs = zip(samples[name], samples["glibc default"], strict=True)
            ratio = statistics.median(s[key] / d[key] for s, d in pairs)
            seconds = statistics.median(s[key] for s in samples[name])
            cells.append(f"{seconds * 1e3:8.1f} ms {ratio:4.2f}×")
        rss = statistics.median(s["rss after 10^6 (MiB)"] for s in samples[name])
        print(f"  {name:<14}" + "".join(f"{c:>17}" for c in cells) + f"{rss:12.0f}")
    print(f"  ({time.perf_counter() - start:.0f} s)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
