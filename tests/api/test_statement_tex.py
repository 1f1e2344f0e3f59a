"""The TeX of every statement, erratum and parameter domain exists, is served by the catalogs
and is well-formed enough to typeset (the browser test renders each with KaTeX)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.geometry.statement_tex import CLAIM_TEX, CONSTANT_TEX, ERRATUM_TEX, PARAMETER_TEX
from app.registry import STATEMENTS

ERRATA = Path(__file__).resolve().parents[2] / "docs" / "errata.md"

# domains that are words or choices, not formulas
WORDS = {"any real number", "example-12 | remark-13 | custom", "up or down"}


def erratum_ids() -> set[str]:
    return set(re.findall(r"^### (E\d+)\s*$", ERRATA.read_text(encoding="utf-8"), re.MULTILINE))


def balanced(tex: str) -> bool:
    depth = 0
    for k, c in enumerate(tex):
        if c in "{}" and k and tex[k - 1] == "\\":
            continue
        depth += {"{": 1, "}": -1}.get(c, 0)
        if depth < 0:
            return False
    return depth == 0


def test_every_statement_and_erratum_has_its_tex() -> None:
    assert set(CLAIM_TEX) == set(STATEMENTS)
    assert len(erratum_ids()) >= 20
    assert set(ERRATUM_TEX) == erratum_ids()


@pytest.mark.parametrize(
    "tex",
    [
        *CLAIM_TEX.values(),
        *(t for pair in ERRATUM_TEX.values() for t in pair),
        *CONSTANT_TEX.values(),
        *PARAMETER_TEX.values(),
    ],
)
def test_the_tex_is_balanced_and_not_plain_unicode(tex: str) -> None:
    assert tex.strip() and balanced(tex), tex
    # the paper's symbols as TeX commands, not pasted characters (KaTeX's fonts have both,
    # but a TeX source with Unicode Greek does not compile everywhere)
    assert not re.search(r"[α-ωΔΣλβφ−²³√∫]", tex), tex


def test_printed_and_corrected_differ() -> None:
    for identifier, (printed, corrected) in ERRATUM_TEX.items():
        assert printed != corrected, identifier


def test_the_catalogs_serve_the_tex(client: TestClient) -> None:
    statements = client.get("/theorems").json()
    assert {s["id"] for s in statements} == set(CLAIM_TEX)
    for statement in statements:
        assert statement["claim_tex"] == CLAIM_TEX[statement["id"]]
        assert [e["id"] for e in statement["errata_tex"]] == statement["errata"]
        for erratum in statement["errata_tex"]:
            printed, corrected = ERRATUM_TEX[erratum["id"]]
            assert (erratum["printed_tex"], erratum["corrected_tex"]) == (printed, corrected)
    assert any(s["errata_tex"] for s in statements)
    for entry in client.get("/discretizations").json():
        assert entry["constants_tex"] == {k: CONSTANT_TEX[k] for k in entry["constants"]}
        for parameter in entry["parameters"]:
            domain = parameter["domain"]
            if domain is None or domain in WORDS:
                assert parameter["domain_tex"] is None
            else:
                assert parameter["domain_tex"] == PARAMETER_TEX[domain], domain
