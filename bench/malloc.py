"""glibc's malloc thresholds for the server (SERVER_ENV in the Makefile), chosen by measurement.

A buffer above ``MALLOC_MMAP_THRESHOLD_`` is a fresh mmap, returned to the system on free, and
its pages fault in again on the next request; a smaller one comes from the heap, whose free top
goes back to the system once it exceeds ``MALLOC_TRIM_THRESHOLD_`` (and faults in again on the
next request). For each candidate pair a fresh process (``MALLOC_ARENA_MAX=2`` as the server)
times the D4b construction at 10^4, 10^5, 10^6 vertices, D4b with every check at 10^5 and
D2a-quad at 10^5, and reports its resident memory once a 10^6-vertex D4b with every check has
been computed and freed. The candidates run in alternation, round after round; figures are
medians over rounds, with the ratio to glibc's default (no threshold set: dynamic, 128 KiB
rising to 32 MiB) in the same round.

Run: .venv/bin/python bench/malloc.py [rounds]   (about 3 minutes with 3 rounds)
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

#: (MALLOC_MMAP_THRESHOLD_, MALLOC_TRIM_THRESHOLD_); None: glibc's default (dynamic).
CANDIDATES: dict[str, tuple[str, str] | None] = {
    "glibc default": None,
    "128 KiB / 8 MiB": ("131072", "8388608"),
    "32 MiB / 8 MiB": ("33554432", "8388608"),
    "32 MiB / 32 MiB": ("33554432", "33554432"),
    "32 MiB / 64 MiB": ("33554432", "67108864"),
}

CHILD = r"""
import json, sys, time
sys.path.insert(0, sys.argv[1])
from app.geometry.d4b import discretization as d4b
from app.geometry.d4b.construction import construct
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
for n, repeat in ((10**4, 21), (10**5, 9), (10**6, 5)):
    lo, hi = -(n // 2), n - n // 2 - 1
    construct(ar, 1.0, 1e-4, None, lo, hi)
    out[f"D4b constr. {n:.0e}"] = best(lambda: construct(ar, 1.0, 1e-4, None, lo, hi), repeat)
n = 10**5
lo, hi = -(n // 2), n - n // 2 - 1
d4b.compute(ar, 1.0, 1e-4, None, lo, hi)
out["D4b all 1e+05"] = best(lambda: d4b.compute(ar, 1.0, 1e-4, None, lo, hi), 3)
n = 10**6
d4b.compute(ar, 1.0, 1e-4, None, -(n // 2), n // 2 - 1)
out["rss after 10^6 (MiB)"] = rss() / 1024
n = 10**5
quad.compute(ar, 1.0, 1.001, None, -(n // 2), n // 2 - 1)
out["D2a-quad 1e+05"] = best(lambda: quad.compute(ar, 1.0, 1.001, None, -(n // 2), n // 2 - 1), 3)
print(json.dumps(out))
"""


def run(thresholds: tuple[str, str] | None) -> dict[str, float]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("MALLOC_")}
    env["MALLOC_ARENA_MAX"] = "2"
    if thresholds is not None:
        env["MALLOC_MMAP_THRESHOLD_"], env["MALLOC_TRIM_THRESHOLD_"] = thresholds
    result = subprocess.run(
        [sys.executable, "-c", CHILD, str(ROOT)], env=env, capture_output=True, text=True
    )
    if result.returncode:
        raise RuntimeError(result.stderr[-2000:])
    figures: dict[str, float] = json.loads(result.stdout.strip().splitlines()[-1])
    return figures


def main(rounds: int = 3) -> None:
    print(
        f"MALLOC_MMAP_THRESHOLD_ / MALLOC_TRIM_THRESHOLD_ (ARENA_MAX=2), {rounds} rounds; "
        "CPU time and its ratio to glibc's default in the same round (medians); resident "
        "memory once a 10^6-vertex D4b with every check is freed"
    )
    samples: dict[str, list[dict[str, float]]] = {name: [] for name in CANDIDATES}
    start = time.perf_counter()
    for _ in range(rounds):
        for name, threshold in CANDIDATES.items():
            samples[name].append(run(threshold))
    keys = [k for k in samples["glibc default"][0] if not k.startswith("rss")]
    print(f"  {'mmap / trim':<16}" + "".join(f"{k:>19}" for k in keys) + f"{'RSS MiB':>9}")
    for name in CANDIDATES:
        cells = []
        for key in keys:
            pairs = zip(samples[name], samples["glibc default"], strict=True)
            ratio = statistics.median(s[key] / d[key] for s, d in pairs)
            seconds = statistics.median(s[key] for s in samples[name])
            cells.append(f"{seconds * 1e3:8.1f} ms {ratio:4.2f}×")
        rss = statistics.median(s["rss after 10^6 (MiB)"] for s in samples[name])
        print(f"  {name:<16}" + "".join(f"{c:>19}" for c in cells) + f"{rss:9.0f}")
    print(f"  ({time.perf_counter() - start:.0f} s)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
