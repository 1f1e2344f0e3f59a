"""Estimated against measured CPU time of mp curves on balls (``BALL_STEP_*``, app/limits.py).

For each discretization at 50, 500 and 1000 digits and two range sizes: the seconds admission
control charges (spied on ``Admission.charge``) beside the CPU seconds the request then takes
(in-process client, response cache off, every check and companion, JSON; median of ``RUNS``
runs, interleaved). Prints one row per request and the median of measured/predicted per digits.
Run: .venv/bin/python bench/ball_costs.py [runs]
"""

from __future__ import annotations

import os
import statistics
import sys
import time
from typing import Any

from fastapi.testclient import TestClient

from app import admission
from app.main import create_app
from app.settings import Settings

KINDS = ["d1", "d2a-quad", "d2a-hex", "d2b", "d3", "d4a", "d4b"]
DIGITS = [50, 500, 1000]
HALF_WIDTHS = [100, 400]

charged: list[float] = []
_original = admission.Admission.charge


def _spy(self: Any, ticket: Any, seconds: float, nbytes: int, dry: bool = False) -> None:
    if not dry:  # a dry charge only tests what a charge would refuse: nothing is admitted
        charged.append(seconds)
    _original(self, ticket, seconds, nbytes, dry)


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    admission.Admission.charge = _spy  # type: ignore[method-assign]
    settings = Settings(response_cache_bytes=0, time_limit=600, admission_seconds=600)
    client = TestClient(create_app(settings))
    client.get("/discretizations/d4b?precision=mp&digits=20&i_max=3")
    urls = [
        f"/discretizations/{kind}?precision=mp&digits={digits}&"
        + (f"i_min=0&i_max={2 * w}" if kind == "d2b" else f"i_min={-w}&i_max={w}")
        for digits in DIGITS
        for w in HALF_WIDTHS
        for kind in KINDS
    ]
    if kind_filter := os.environ.get("KINDS"):
        urls = [u for u in urls if any(f"/{k}?" in u for k in kind_filter.split(","))]
    cpu: dict[str, list[float]] = {u: [] for u in urls}
    predicted: dict[str, float] = {}
    for _ in range(runs):
        for url in urls:
            charged.clear()
            start = time.process_time()
            status = client.get(url).status_code
            cpu[url].append(time.process_time() - start)
            predicted[url] = sum(charged) if status == 200 else float("nan")
    ratios: dict[int, list[float]] = {d: [] for d in DIGITS}
    print(f"load {os.getloadavg()[0]:.1f}; median of {runs}")
    print(f"{'request':70} {'predicted s':>11} {'measured s':>10} {'meas/pred':>9}")
    for url in urls:
        measured = statistics.median(cpu[url])
        ratio = measured / predicted[url]
        digits = int(url.split("digits=")[1].split("&")[0])
        ratios[digits].append(ratio)
        print(f"{url:70} {predicted[url]:11.3f} {measured:10.3f} {ratio:9.2f}")
    for digits, values in ratios.items():
        if values:
            print(
                f"{digits} digits: measured/predicted median {statistics.median(values):.2f}, "
                f"range {min(values):.2f}-{max(values):.2f}"
            )


if __name__ == "__main__":
    main()
