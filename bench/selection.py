"""What `checks` and `companions` save (the on-demand catalog), measured over HTTP side by side.

Starts the server as bench/serving.py does (uvicorn, 1 worker, the malloc settings of ``make
run``) and prints, each as a median of paired samples:

1. a 10^6-vertex D4b with ``method=closed-form&checks=none&companions=none`` fetched whole
   (computed: a new d each time) against ``orjson.dumps`` of its (10^6, 2) vertex array in this
   process, timed just before it (target ≤ 1.5×);
2. the same as ``format=npy`` against the closed-form kernel (14) alone in this process
   (target ≤ 10×);
3. requests/s of a computed 100-vertex D4b GET with ``checks=none`` against the same with every
   check (the default, what every request paid before), alternating wrk runs (target ≥ 2×);
4. the peak memory of a 10^6-vertex D4b with ``checks=none&companions=none`` (construction and
   closed form, JSON and npy): the growth of the server's peak RSS during the request (VmHWM,
   reset just before) over its RSS before, against the response's size (target ≤ 4×).

Run: .venv/bin/python bench/selection.py   (about a minute)
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import orjson

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from app.geometry.curve import NOTHING
from app.geometry.d4b import closed_forms, discretization as d4b
from app.geometry.precision import Float64
from bench.load import free_port
from bench.serving import ROUNDS, UNIQUE_SCRIPT, _verdict, fetch, start_server, wrk

BIG = "/discretizations/d4b?h=1&i_min=-500000&i_max=499999"
SMALL = "/discretizations/d4b?i_min=-50&i_max=49"
REPEAT = 5

_counter = iter(range(1, 10**6))


def _fresh(path: str) -> Callable[[], str]:
    """A new d on every call (1e-4 + k·1e-12): computed, never served from a cache."""
    return lambda: f"{path}&d={1e-4 + next(_counter) * 1e-12!r}"


def _paired(reference: Callable[[], float], port: int, path: Callable[[], str]) -> float:
    ratios = []
    for _ in range(REPEAT):
        ref = reference()
        seconds, _ = fetch(port, path())
        ratios.append(seconds / ref)
    return statistics.median(ratios)


def _timed(function: Callable[[], object]) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def big_answers(port: int) -> None:
    ar = Float64()
    curve = d4b.compute(ar, 1.0, 1e-4, None, -500_000, 499_999, "closed-form", selection=NOTHING)
    vertices = np.ascontiguousarray(curve.polygon.vertices)
    i = ar.indices(-500_000, 500_000)
    shift = closed_forms.tilt_shift(ar, 1.0, 1e-4, None)

    def encoder() -> float:
        return _timed(lambda: orjson.dumps(vertices, option=orjson.OPT_SERIALIZE_NUMPY))

    def kernel() -> float:
        return _timed(lambda: closed_forms.hyperbolic_cosine(ar, 1.0, 1e-4, i, shift))

    bare = "&method=closed-form&checks=none&companions=none"
    json_ratio = _paired(encoder, port, _fresh(BIG + bare))
    npy_ratio = _paired(kernel, port, _fresh(BIG + "&method=closed-form&format=npy"))
    print(" 10^6-vertex D4b over HTTP (computed, whole response read), paired medians")
    print(
        f"  closed form, checks=none&companions=none  {json_ratio:6.2f}× orjson of its vertices"
        + _verdict(json_ratio, 1.5, at_least=False)
    )
    print(
        f"  closed form, format=npy                   {npy_ratio:6.2f}× the kernel (14) alone"
        + _verdict(npy_ratio, 10, at_least=False)
    )


def _script(path: str) -> str:
    descriptor, script = tempfile.mkstemp(suffix=".lua")
    with os.fdopen(descriptor, "w") as handle:
        handle.write(UNIQUE_SCRIPT % path)
    return script


def small_gets(base: str) -> None:
    every_script, none_script = _script(SMALL), _script(SMALL + "&checks=none")
    ratios: list[float] = []
    rates: dict[str, list[float]] = {"all": [], "none": []}
    try:
        for _ in range(ROUNDS):
            every = wrk(base, "", 1, every_script)
            none = wrk(base, "", 1, none_script)
            rates["all"].append(every.rps)
            rates["none"].append(none.rps)
            ratios.append(none.rps / every.rps)
    finally:
        os.unlink(every_script)
        os.unlink(none_script)
    ratio = statistics.median(ratios)
    print(
        f" 100-vertex D4b GET, computed, c=1: every check "
        f"{statistics.median(rates['all']):7.0f} req/s, checks=none "
        f"{statistics.median(rates['none']):7.0f} req/s  {ratio:5.2f}×"
        + _verdict(ratio, 2, at_least=True)
    )


def _status(pid: int, key: str) -> int:
    with open(f"/proc/{pid}/status") as handle:
        return next(int(line.split()[1]) * 1024 for line in handle if line.startswith(key))


def peak_memory(port: int, pid: int) -> None:
    """Peak RSS growth of the server process during one request, against the response's size.

    Writing 5 to /proc/<pid>/clear_refs resets the process's peak (VmHWM) to its current RSS, so
    that VmHWM after the request is the request's own peak.
    """
    print(" peak memory of one 10^6-vertex D4b in the server (peak RSS growth / response size)")
    for label, query in (
        ("construction, JSON", "&checks=none&companions=none"),
        ("closed form, JSON", "&method=closed-form&checks=none&companions=none"),
        ("construction, npy", "&format=npy"),
        ("closed form, npy", "&method=closed-form&format=npy"),
        ("construction, every check (before)", ""),
    ):
        with open(f"/proc/{pid}/clear_refs", "w") as handle:
            handle.write("5")
        before = _status(pid, "VmRSS:")
        _, body = fetch(port, _fresh(BIG + query)())
        grown = _status(pid, "VmHWM:") - before
        size = len(body)
        verdict = "" if "before" in label else _verdict(grown / size, 4, at_least=False)
        print(
            f"  {label:<36} peak +{grown / 2**20:7.1f} MiB, response {size / 2**20:6.1f} MiB  "
            f"{grown / size:5.2f}×{verdict}"
        )


def main() -> None:
    port = free_port()
    base = f"http://127.0.0.1:{port}"
    server = start_server(port)
    try:
        print("On-demand checks and companions (issue 12): HTTP on 127.0.0.1, 1 worker")
        fetch(port, SMALL)
        big_answers(port)
        small_gets(base)
        peak_memory(port, server.pid)
    finally:
        server.terminate()
        server.wait(timeout=20)


if __name__ == "__main__":
    main()
