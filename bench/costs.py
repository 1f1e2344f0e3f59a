"""Estimated against measured cost of the heaviest admitted request of every endpoint.

Each request runs alone in a fresh process (in-process client, default settings): wall time,
CPU time and peak resident memory above the warmed-up process, beside the estimate that
admission control charged for it (app/limits.py). Run: .venv/bin/python bench/costs.py [url…]
"""

from __future__ import annotations

import json
import subprocess
import sys

#: The heaviest requests the default limits admit, one or two per endpoint and precision.
HEAVIEST = [
    "/discretizations/d4b?d=0.0001&i_min=-1726000&i_max=-726000&format=npy",
    "/discretizations/d4b?d=0.0001&method=closed-form&i_min=-500000&i_max=500000",
    "/discretizations/d1?c=0.0001&delta=0.001&i_min=-500000&i_max=500000&format=npy",
    "/discretizations/d2b?i_min=0&i_max=1000000&format=npy",
    "/discretizations/d4b?precision=mp&digits=1&i_min=-2000&i_max=2000",
    "/discretizations/d2b?precision=mp&digits=1&i_min=0&i_max=4000",
    "/discretizations/d4b?precision=mp&digits=1000&i_min=-400&i_max=400",
    "/discretizations/d2a-quad?precision=mp&digits=50&i_min=-1999&i_max=2000",
    "/surfaces/catenoid?discretization=d4b&d=0.001&i_min=-2500&i_max=-2000&m=500&format=glb",
    "/surfaces/catenoid?discretization=d4b&precision=mp&digits=1&i_min=-20&i_max=20&m=40",
    "/surfaces/catenoid?discretization=d4b&precision=mp&digits=1&i_min=-2486&i_max=2486&m=100",
    "/relations?d4b.i_max=50000&d1.i_max=50000&d4b.i_min=-50000&d1.i_min=-50000",
    "/relations?precision=mp&digits=1000",
    "/convergence/theorem-14?levels=15",
    "/convergence/theorem-11?precision=mp&digits=50",
    "/figures/figure-2.svg",
]

PROBE = r"""
import json, resource, sys, time
from fastapi.testclient import TestClient
from app.main import create_app
from app.settings import Settings
from app import admission

charged = []
original = admission.Admission.charge
def spy(self, ticket, seconds, nbytes):
    charged.append((seconds, nbytes))
    return original(self, ticket, seconds, nbytes)
admission.Admission.charge = spy

def rss():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize()

client = TestClient(create_app(Settings(response_cache_bytes=0)))
client.get("/discretizations/d4b?i_max=10"); client.get("/surfaces/catenoid?i_max=3&m=4")
charged.clear()
base = rss()
t0, c0 = time.perf_counter(), time.process_time()
r = client.get(sys.argv[1])
wall, cpu = time.perf_counter() - t0, time.process_time() - c0
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
print(json.dumps({"status": r.status_code, "wall": wall, "cpu": cpu,
                  "peak": max(0, peak - base), "bytes": len(r.content),
                  "est_s": sum(c[0] for c in charged), "est_b": sum(c[1] for c in charged),
                  "detail": r.json().get("detail") if r.status_code != 200 else None}))
"""


def measure(url: str) -> dict[str, object]:
    out = subprocess.run(
        [sys.executable, "-c", PROBE, url], capture_output=True, text=True, check=True
    )
    result: dict[str, object] = json.loads(out.stdout.strip().splitlines()[-1])
    return result


def main() -> None:
    urls = sys.argv[1:] or HEAVIEST
    print(
        f"{'request':70} {'st':>3} {'wall s':>7} {'cpu s':>7} {'est s':>7} "
        f"{'peak MB':>8} {'est MB':>7}"
    )
    for url in urls:
        m = measure(url)
        print(
            f"{url[:70]:70} {m['status']:>3} {m['wall']:7.2f} {m['cpu']:7.2f} {m['est_s']:7.2f} "
            f"{int(m['peak']) / 2**20:8.0f} {int(m['est_b']) / 2**20:7.0f}"  # type: ignore[call-overload]
            + (f"  {m['detail']}" if m["detail"] else "")
        )


if __name__ == "__main__":
    main()
