"""openapi/openapi.json is what the app serves (regenerate with `make openapi`)."""

from __future__ import annotations

import json
from pathlib import Path

from app.openapi_export import document

STORED = Path(__file__).resolve().parents[2] / "openapi" / "openapi.json"


def test_stored_openapi_document_matches_the_app() -> None:
    assert STORED.exists(), "run `make openapi`"
    assert json.loads(STORED.read_text(encoding="utf-8")) == json.loads(document()), (
        "openapi/openapi.json is stale: run `make openapi` and commit it"
    )


def test_every_operation_is_documented() -> None:
    spec = json.loads(document())
    for path, operations in spec["paths"].items():
        for method, operation in operations.items():
            assert operation.get("summary"), (method, path)
            assert operation.get("description"), (method, path)
            assert operation.get("tags"), (method, path)
