"""Timing helpers: medians of repeated runs, and ratios measured side by side in one run."""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable


def median_time(function: Callable[[], object], repeat: int = 5, min_time: float = 0.05) -> float:
    """Median wall time of ``function()`` in seconds (each sample loops until ``min_time``)."""
    samples = []
    for _ in range(repeat):
        loops, start = 0, time.perf_counter()
        while True:
            function()
            loops += 1
            elapsed = time.perf_counter() - start
            if elapsed >= min_time:
                break
        samples.append(elapsed / loops)
    return statistics.median(samples)


def row(label: str, seconds: float, reference: float, reference_label: str) -> str:
    """One printed line: the time and its ratio to the reference measured in the same run."""
    return f"  {label:<44} {seconds * 1e3:10.3f} ms   {seconds / reference:8.2f}× {reference_label}"
