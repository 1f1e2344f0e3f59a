"""`make bench`: every benchmark script, one after the other."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench import d4b, stick_chain

if __name__ == "__main__":
    d4b.main()
    stick_chain.main()
