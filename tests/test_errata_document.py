"""docs/errata.md: every erratum the API links to has an entry, every entry is complete, names the
check that carries it and is listed in the contents; every link in the document resolves."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from app.geometry.checks import ERRATA_DOCUMENT, ERRATA_PAGE, Check
from app.geometry.precision import Float64
from app.registry import DISCRETIZATIONS, SMOOTH, STATEMENTS, STUDIES

ROOT = Path(__file__).resolve().parents[1]
DOCUMENT = (ROOT / ERRATA_DOCUMENT).read_text(encoding="utf-8")


def slug(heading: str) -> str:
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def headings() -> list[str]:
    return [m.group(2) for m in re.finditer(r"(?m)^(#{1,6}) (.+)$", DOCUMENT)]


def anchors() -> set[str]:
    return {slug(h) for h in headings()}


def entries() -> dict[str, str]:
    """Erratum id -> its text (up to the next heading)."""
    found = {}
    for match in re.finditer(r"(?ms)^### (E\d+)\n(.*?)(?=^#{2,3} |\Z)", DOCUMENT):
        found[match.group(1)] = match.group(2)
    return found


def carried() -> dict[str, set[str]]:
    """Erratum id -> ids of the checks that carry it, over every source at its defaults."""
    pairs: dict[str, set[str]] = {}

    def collect(checks: list[Check]) -> None:
        for check in checks:
            if check.erratum is not None:
                pairs.setdefault(check.erratum.id, set()).add(check.id)

    ar = Float64()
    for entry in DISCRETIZATIONS.values():
        collect(entry.compute(ar, **entry.query.model_validate({}).core_arguments()).checks)
    for study in STUDIES.values():
        collect(study.run(ar, **study.query.model_validate({}).core_arguments()).checks)
    for smooth in SMOOTH.values():
        collect(smooth.compute(ar, **smooth.query.model_validate({}).core_arguments()).checks)
    return pairs


@pytest.fixture(scope="module")
def carrying() -> dict[str, set[str]]:
    return carried()


def test_headings_are_unique() -> None:
    slugs = [slug(h) for h in headings()]
    assert len(slugs) == len(set(slugs)), [s for s in slugs if slugs.count(s) > 1]


def test_every_link_of_the_document_resolves() -> None:
    targets = re.findall(r"\]\(#([^)]+)\)", DOCUMENT)
    assert targets, "the contents link to the entries"
    missing = sorted(set(targets) - anchors())
    assert missing == []


def test_every_erratum_the_api_links_to_has_an_entry(carrying: dict[str, set[str]]) -> None:
    declared = set(re.findall(r'"(E\d+)",\n', _sources()))
    assert set(carrying) <= declared
    for erratum_id in declared:
        assert erratum_id.lower() in anchors(), erratum_id
    # and every entry is carried by a check (no entry without evidence in the API)
    assert set(entries()) == declared


def _sources() -> str:
    return "\n".join(p.read_text(encoding="utf-8") for p in (ROOT / "app").rglob("*.py"))


def test_every_entry_is_complete_and_names_its_checks(carrying: dict[str, set[str]]) -> None:
    for erratum_id, text in entries().items():
        for part in ("**Where:**", "**Printed:**", "**Corrected:**", "**Evidence"):
            assert part in text, (erratum_id, part)
        where = text.split("**Printed:**")[0]
        named = set(re.findall(r"`([a-z0-9-]+)`", where))
        assert named, erratum_id
        assert named <= set(STATEMENTS), (erratum_id, named - set(STATEMENTS))
        if erratum_id in carrying:  # the checks that carry it at the defaults are named
            assert carrying[erratum_id] <= named, (erratum_id, carrying[erratum_id], named)


def test_the_contents_list_every_entry_with_its_checks() -> None:
    table = DOCUMENT.split("## Contents")[1].split("\n## ")[0]
    rows = re.findall(r"(?m)^\| \[(E\d+)\]\(#(e\d+)\) \|.*\| (.+) \|$", table)
    assert sorted(r[0] for r in rows) == sorted(entries())
    for erratum_id, anchor, checks in rows:
        assert anchor == erratum_id.lower()
        where = entries()[erratum_id].split("**Printed:**")[0]
        for check_id in re.findall(r"`([a-z0-9-]+)`", checks):
            assert f"`{check_id}`" in where, (erratum_id, check_id)


def test_erratum_links_in_responses_resolve(client) -> None:  # type: ignore[no-untyped-def]
    body = client.get("/convergence/theorem-11", params={"levels": 3}).json()
    links = [c["erratum"]["link"] for c in body["checks"] if c["erratum"]]
    body = client.get("/discretizations/d4b").json()
    links += [c["erratum"]["link"] for c in body["checks"] if c["erratum"]]
    assert links
    for link in links:
        prefix, erratum_id = link.rsplit("/", 1)
        assert prefix == ERRATA_PAGE and erratum_id.lower() in anchors(), link
        page = client.get(link)
        assert page.status_code == 200 and page.json()["id"] == erratum_id, link
