"""The golden answers: every default response recorded once, compared by tests/test_golden.py.

A restructure keeps every default answer identical; this file records them. Run it only when a
change of an answer is intended, and list the change in the issue's note:

    .venv/bin/python -m tests.golden.capture
"""

from __future__ import annotations

import gzip
import json
import re
from pathlib import Path
from typing import Any

from fastapi.testclient import TestClient

from app.main import create_app
from app.settings import Settings

GOLDEN = Path(__file__).with_name("answers.json.gz")

#: Every discretization, smooth reference, study, surface and figure at its defaults, plus the
#: mp answer of each discretization (30 digits) and the relations matrix.
DISCRETIZATIONS = ("d1", "d2a-quad", "d2a-hex", "d2b", "d3", "d4a", "d4b")
PATHS: tuple[str, ...] = (
    *(f"/discretizations/{d}" for d in DISCRETIZATIONS),
    *(f"/discretizations/{d}?precision=mp&digits=30" for d in DISCRETIZATIONS),
    "/discretizations/d4b?detail=true",
    "/discretizations/d4b?method=closed-form",
    "/smooth/catenary",
    "/smooth/tractrix",
    "/relations",
    "/convergence/theorem-11",
    "/convergence/theorem-14",
    "/convergence/theorem-15",
    "/surfaces/catenoid",
    "/surfaces/pseudosphere",
    "/surfaces/catenoid-gauss-image",
    "/surfaces/pseudosphere-gauss-image",
    *(f"/figures/figure-{n}.svg" for n in range(2, 9)),
)

_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def svg_polylines(svg: str) -> list[list[float]]:
    """The coordinates of every polyline and path of an SVG, in document order."""
    shapes = re.findall(
        r'<(?:polyline|polygon)[^>]*\bpoints="([^"]*)"|<path[^>]*\bd="([^"]*)"', svg
    )
    return [[float(v) for v in _NUMBER.findall(a or b)] for a, b in shapes]


def answer(client: TestClient, path: str) -> Any:
    """The response at ``path`` in the form the golden file keeps."""
    response = client.get(path)
    assert response.status_code == 200, (path, response.text[:500])
    if path.startswith("/figures/"):
        return {"polylines": svg_polylines(response.text)}
    return response.json()


def main() -> None:
    client = TestClient(create_app(Settings()))
    answers = {path: answer(client, path) for path in PATHS}
    GOLDEN.write_bytes(gzip.compress(json.dumps(answers, sort_keys=True).encode(), mtime=0))
    print(f"{len(answers)} answers -> {GOLDEN} ({GOLDEN.stat().st_size} bytes)")


if __name__ == "__main__":
    main()
