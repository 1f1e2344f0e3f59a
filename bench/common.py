"""Timing helpers: medians of repeated runs, and ratios measured side by side in one run.

The machine is shared and noisy, so no figure is an absolute time on its own: ``compare`` times
a reference and each subject alternately (reference, subject, reference, subject, …), takes the
ratio of every subject sample to the reference sample just before it, and reports the median of
those ratios. A slow drift of the machine (another process starting) then moves both sides of
each ratio alike. Compute is timed in CPU time of this process (``time.process_time``: numpy
runs on one thread here), so that time slices taken by other processes on the shared machine do
not count; on an idle machine it equals the wall time. HTTP figures are wall times
(bench/serving.py).
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass


def sample(
    function: Callable[[], object],
    min_time: float = 0.02,
    clock: Callable[[], float] = time.process_time,
) -> float:
    """Time of one call of ``function()`` in seconds (looping until ``min_time``)."""
    loops, start = 0, clock()
    while True:
        function()
        loops += 1
        elapsed = clock() - start
        if elapsed >= min_time:
            return elapsed / loops


def median_time(function: Callable[[], object], repeat: int = 5, min_time: float = 0.05) -> float:
    """Median time of ``function()`` in seconds (each sample loops until ``min_time``)."""
    return statistics.median(sample(function, min_time) for _ in range(repeat))


@dataclass(frozen=True)
class Paired:
    """A subject timed against a reference in alternation."""

    seconds: float
    """Median time of the subject."""
    reference: float
    """Median time of the reference samples taken next to the subject's."""
    ratio: float
    """Median of subject / reference over the pairs."""


def compare(
    reference: Callable[[], object],
    subject: Callable[[], object],
    repeat: int = 7,
    min_time: float = 0.0,
    reference_min_time: float = 0.02,
    warm: bool = True,
) -> Paired:
    """Median ratio subject / reference, the two sampled alternately (see the module doc)."""
    if warm:
        subject()  # warm up: imports, caches, first-touch allocations
    pairs = []
    for _ in range(repeat):
        ref = sample(reference, reference_min_time)
        pairs.append((sample(subject, min_time), ref))
    return Paired(
        seconds=statistics.median(s for s, _ in pairs),
        reference=statistics.median(r for _, r in pairs),
        ratio=statistics.median(s / r for s, r in pairs),
    )


def row(label: str, seconds: float, reference: float, reference_label: str) -> str:
    """One printed line: the time and its ratio to the reference measured in the same run."""
    return f"  {label:<44} {seconds * 1e3:10.3f} ms   {seconds / reference:8.2f}× {reference_label}"


def ratio_row(label: str, paired: Paired, reference_label: str, target: float | None = None) -> str:
    """One printed line from ``compare``: median time, median ratio and the target if any."""
    verdict = ""
    if target is not None:
        TARGETS[f"{label.strip()}, × {reference_label}"] = (paired.ratio, target, "≤")
        verdict = f"   target ≤ {target:g}×: {'met' if paired.ratio <= target else 'NOT met'}"
    return (
        f"  {label:<44} {paired.seconds * 1e3:10.3f} ms   {paired.ratio:8.2f}× "
        f"{reference_label}{verdict}"
    )


#: Every issue target measured in this process: label -> (measured, target, "≤" or "≥"), for
#: the side-by-side summary that ``make bench`` prints last (bench/run.py).
TARGETS: dict[str, tuple[float, float, str]] = {}


def record_target(label: str, measured: float, target: float, sense: str) -> str:
    """Keep a measured figure with its target; the verdict as printed next to it."""
    TARGETS[label] = (measured, target, sense)
    met = measured <= target if sense == "≤" else measured >= target
    return f"target {sense} {target:g}: {'met' if met else 'NOT met'}"


def target_summary() -> str:
    """Every recorded target, one line each: measured, target, verdict."""
    lines = [" every target of this run, side by side"]
    for label, (measured, target, sense) in TARGETS.items():
        met = measured <= target if sense == "≤" else measured >= target
        lines.append(
            f"  {label:<52} {measured:9.3f}   target {sense} {target:<6g} "
            f"{'met' if met else 'NOT met'}"
        )
    return "\n".join(lines)
