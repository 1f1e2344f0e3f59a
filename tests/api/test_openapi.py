"""openapi/openapi.json is what the app serves (regenerate with `make openapi`)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from app.openapi_export import document

STORED = Path(__file__).resolve().parents[2] / "openapi" / "openapi.json"


def normalized(value: Any) -> Any:
    """Floats to 9 digits, |x| < 1e-9 to 0: the examples hold computed residuals, rounding noise
    whose last bits moved with the CPU while numpy's SIMD functions computed them (the C
    library's now, app/geometry/elementary.py) and would move with any reordering of a check;
    everything else compares exactly."""
    if isinstance(value, float):
        return 0.0 if abs(value) < 1e-9 else float(f"{value:.9g}")
    if isinstance(value, list):
        return [normalized(v) for v in value]
    if isinstance(value, dict):
        return {k: normalized(v) for k, v in value.items()}
    return value


def test_stored_openapi_document_matches_the_app() -> None:
    assert STORED.exists(), "run `make openapi`"
    stored = json.loads(STORED.read_text(encoding="utf-8"))
    assert normalized(stored) == normalized(json.loads(document())), (
        "openapi/openapi.json is stale: run `make openapi` and commit it"
    )


def test_every_operation_is_documented() -> None:
    spec = json.loads(document())
    for path, operations in spec["paths"].items():
        for method, operation in operations.items():
            assert operation.get("summary"), (method, path)
            assert operation.get("description"), (method, path)
            assert operation.get("tags"), (method, path)
