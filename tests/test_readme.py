"""The README documents what the service has: every setting, discretization and resource."""

from __future__ import annotations

from pathlib import Path

from app.main import create_app
from app.registry import DISCRETIZATIONS
from app.settings import Settings

README = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")


def test_every_setting_is_documented_with_its_default() -> None:
    for name, field in Settings.model_fields.items():
        variable = f"`DCOSH_{name.upper()}`"
        assert variable in README, variable
        default = field.default if field.default_factory is None else None
        if isinstance(default, int | float) and not isinstance(default, bool):
            row = next(line for line in README.splitlines() if line.startswith(f"| {variable}"))
            assert float(row.split("|")[2]) == default, row


def test_every_discretization_is_in_the_table() -> None:
    for identifier in DISCRETIZATIONS:
        assert f"| `{identifier}` |" in README, identifier


def test_every_resource_is_mentioned() -> None:
    paths = create_app(Settings()).openapi()["paths"]
    for top in {"/" + p.strip("/").split("/")[0] for p in paths}:
        assert f"`GET {top}" in README or f"{top}/" in README, top
    assert "make test" in README.split("\n\n")[0] + README.split("\n\n")[1]
