"""docs/paper-map.md is generated from the catalog and the source, and kept up to date."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

from app.geometry.catalog import CATALOG

ROOT = Path(__file__).resolve().parents[1]


def _generator() -> ModuleType:
    spec = importlib.util.spec_from_file_location("paper_map", ROOT / "scripts" / "paper_map.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_stored_paper_map_is_the_generated_one() -> None:
    stored = (ROOT / "docs" / "paper-map.md").read_text(encoding="utf-8")
    assert stored == _generator().generate(), "regenerate it: make paper-map"


def test_every_statement_has_its_code_endpoints_and_tests_in_one_hop() -> None:
    text = (ROOT / "docs" / "paper-map.md").read_text(encoding="utf-8")
    rows = [line for line in text.splitlines() if line.startswith("| **")]
    assert len(rows) == len(CATALOG)
    for row in rows:
        cells = row.split(" | ")
        assert "`app/" in cells[2] and "::" in cells[2], row[:80]  # path::function
        assert "`/" in cells[3], row[:80]  # an endpoint
        assert "`tests/" in cells[4], row[:80]  # a test
