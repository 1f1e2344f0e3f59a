"""`make bench`: every benchmark, one after the other (about 4 minutes on 2 shared cores).

Every printed figure is a ratio to a reference measured in the same run (medians of paired
samples): the machine is shared and noisy, absolute times drift. Results and the exact commands
are in docs/performance.md. The last lines put every issue target measured in the run side by
side (``bench.common.TARGETS``).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench import compiled, d4b, kernels, mp, selection, serving, stick_chain
from bench.common import target_summary

if __name__ == "__main__":
    start = time.perf_counter()
    parts = (
        compiled.main,
        kernels.main,
        stick_chain.main,
        d4b.main,
        mp.main,
        serving.main,
        serving.computed_gets,
        selection.main,
    )
    for part in parts:
        part()
        print(flush=True)
    print(target_summary())
    print(f"make bench: {time.perf_counter() - start:.0f} s")
