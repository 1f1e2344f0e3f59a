"""The paper's checkable statements, each defined once, in the paper's order.

Every ``Statement`` (id, paper reference, claim with how its residual is measured, implicit
conditions) lives in the module of its section:

- ``section2``: the smooth curves (S1)–(S4);
- ``section3``: the definitions (D1)–(D4b) and what the text says of each;
- ``section4``: Theorems 1–6 and the formulas of their proofs;
- ``section5``: Gauss images, curvatures, Theorems 7 and 8;
- ``section6``: Lemma 10, Theorem 11, Example 12, Remark 13, Theorems 14 and 15.

The discretizations, studies and smooth references say which statements they evaluate (their
``statements``); the registry (``app.registry``) joins the two, and ``docs/paper-map.md`` is
generated from both. Implicit hypotheses, in words, are in ``conditions``.
"""

from __future__ import annotations

from types import ModuleType

from app.geometry.catalog import section2, section3, section4, section5, section6
from app.geometry.checks import Statement

SECTIONS: tuple[tuple[str, ModuleType], ...] = (
    ("Section 2", section2),
    ("Section 3", section3),
    ("Section 4", section4),
    ("Section 5", section5),
    ("Section 6", section6),
)


def _collect() -> dict[str, tuple[str, Statement]]:
    found: dict[str, tuple[str, Statement]] = {}
    for section, module in SECTIONS:
        for value in vars(module).values():
            if isinstance(value, Statement):
                if value.id in found and found[value.id][1] is not value:
                    raise ValueError(f"statement {value.id!r} is defined twice")
                found[value.id] = (section, value)
    return found


_FOUND = _collect()

CATALOG: dict[str, Statement] = {key: statement for key, (_, statement) in _FOUND.items()}
"""Statement id -> the statement, in the paper's order (section by section)."""

SECTION_OF: dict[str, str] = {key: section for key, (section, _) in _FOUND.items()}
"""Statement id -> the section of the paper it belongs to."""
