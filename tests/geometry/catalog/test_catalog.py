"""The catalog holds every statement once; everything that checks a statement uses its entry."""

from __future__ import annotations

import importlib
import pkgutil

import pytest

import app.geometry
from app.geometry.catalog import CATALOG, SECTION_OF
from app.geometry.checks import Statement
from app.geometry.precision import Float64
from app.registry import DISCRETIZATIONS, SMOOTH, STATEMENTS, STUDIES


def _every_statement_object() -> list[tuple[str, Statement]]:
    """(module, statement) for every Statement bound at module level anywhere in the core."""
    found = []
    for info in pkgutil.walk_packages(app.geometry.__path__, "app.geometry."):
        module = importlib.import_module(info.name)
        for value in vars(module).values():
            if isinstance(value, Statement):
                found.append((info.name, value))
            elif isinstance(value, tuple | dict):
                items = value.values() if isinstance(value, dict) else value
                found += [(info.name, v) for v in items if isinstance(v, Statement)]
    return found


def test_no_statement_is_defined_outside_the_catalog() -> None:
    objects = _every_statement_object()
    assert len(objects) > len(CATALOG)
    for module, statement in objects:
        assert statement.id in CATALOG, f"{module} defines {statement.id!r} outside the catalog"
        assert statement is CATALOG[statement.id], f"{module} redefines {statement.id!r}"


def test_ids_are_unique_and_every_section_holds_some() -> None:
    assert len(CATALOG) == 75
    assert set(SECTION_OF.values()) == {f"Section {n}" for n in range(2, 7)}


def test_every_statement_is_checked_somewhere() -> None:
    for key, entry in STATEMENTS.items():
        sources = entry.discretizations + entry.studies + entry.smooth + entry.surfaces
        assert sources, f"nothing checks {key}"
    assert list(STATEMENTS) == list(CATALOG)


@pytest.mark.parametrize("identifier", sorted(DISCRETIZATIONS))
def test_every_check_of_a_curve_is_a_catalog_statement(identifier: str) -> None:
    entry = DISCRETIZATIONS[identifier]
    curve = entry.compute(Float64(), **entry.query.model_validate({}).core_arguments())
    assert [c.id for c in curve.checks] == [s.id for s in entry.info.statements]
    for check in curve.checks:
        statement = CATALOG[check.id]
        assert (check.reference, check.claim) == (statement.reference, statement.claim)


@pytest.mark.parametrize("identifier", sorted(STUDIES))
def test_every_check_of_a_study_is_a_catalog_statement(identifier: str) -> None:
    source = STUDIES[identifier]
    study = source.run(Float64(), **source.query.model_validate({}).core_arguments())
    assert {c.id for c in study.checks} <= set(CATALOG)
    assert {c.id for c in study.checks} == {s.id for s in source.info.statements}


def test_every_check_of_a_smooth_reference_is_a_catalog_statement() -> None:
    for source in SMOOTH.values():
        curve = source.compute(Float64(), **source.query.model_validate({}).core_arguments())
        assert {c.id for c in curve.checks} == {s.id for s in source.info.statements}


def test_the_catalog_names_the_errata_its_checks_carry_at_the_defaults() -> None:
    carried: dict[str, set[str]] = {}
    results = [
        e.compute(Float64(), **e.query.model_validate({}).core_arguments()).checks
        for e in DISCRETIZATIONS.values()
    ]
    results += [
        s.run(Float64(), **s.query.model_validate({}).core_arguments()).checks
        for s in STUDIES.values()
    ]
    for checks in results:
        for check in checks:
            if check.erratum is not None:
                carried.setdefault(check.id, set()).add(check.erratum.id)
    expected = {key: s.errata for key, s in CATALOG.items() if s.errata}
    assert {key: tuple(sorted(v, key=lambda e: int(e[1:]))) for key, v in carried.items()} == (
        expected
    )
