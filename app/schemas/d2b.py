"""Parameters of (D2b), the meridian of a discrete catenoid with vanishing mean curvature."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, Field

from app.geometry.d2b.discretization import DEFAULT_J, resolve_range
from app.schemas.common import CurveQuery

#: Longest custom sequence accepted (the body stays a few MB).
MAX_SEQUENCE_LENGTH = 100_000

D2B_DESCRIPTION = f"""\
The meridian p_i of a discrete catenoid with vanishing mean curvature (D2b), Section 6. A
sequence s_i gives the Gauss image meridian n_i = (s_i, √(1 − s_i²)) on the unit circle; p_i
has p_0 = (0, 1), edges parallel to those of n, and H = 0 on every face of the rotational mesh
in the mixed-area sense of Bobenko–Pottmann–Wallner. Companion: `gauss_image` (n_i).

Sequences: `example-12`, s_i = 4i²/(j² + 4i²) (Example 12; defined here for i ≥ 0, where it is
strictly increasing: it is even in i); `remark-13`, s_i = i/(i + j) (Remark 13; i > −j/2, where
|s_i| < 1); `custom`: `s` is the list s_{{i_min}}, s_{{i_min+1}}, … (strictly increasing, every
|s_i| < 1, the entry of index 0 equal to 0, at most {MAX_SEQUENCE_LENGTH} numbers), in a POST
body or, in a GET, comma-separated. No expression is ever evaluated: sequences are named or
given as numbers.

Defaults: j = {DEFAULT_J}; i_min..i_max covers t = i/j from max(start of the domain, −¼) to 2;
for `custom`, i_min = 0 and i_max = i_min + len(s) − 1. Lemma 10's sums use the usual
convention Σ_{{k=0}}^{{i−1}} = −Σ_{{k=i}}^{{−1}} for i < 0 (erratum E64). The `theorem-11` check
rebuilds the family at 2j on 2i_min..2i_max and compares the distances to the catenary.
"""


def _numbers(value: Any) -> Any:
    """Accept ``s`` as a list, or as one comma-separated string (a GET query)."""
    if isinstance(value, str):
        return [part for part in value.split(",") if part.strip()]
    if isinstance(value, list) and len(value) == 1 and isinstance(value[0], str):
        return [part for part in value[0].split(",") if part.strip()]
    return value


SequenceName = Annotated[
    Literal["example-12", "remark-13", "custom"],
    Field(
        description="`example-12`, `remark-13` (named sequences with refinement `j`) or `custom` "
        "(the numbers `s`).",
        json_schema_extra={"x-domain": "example-12 | remark-13 | custom"},
    ),
]
Refinement = Annotated[int, Field(ge=1, le=100_000)]
"""A refinement j of a named sequence (Example 12, Remark 13)."""


class D2bQuery(CurveQuery):
    """(D2b) parameters: the sequence, its refinement j or the numbers s, and the range."""

    sequence: SequenceName = "example-12"
    j: Refinement | None = Field(
        None,
        description=f"Refinement j of a named sequence (default {DEFAULT_J}); not with custom.",
        json_schema_extra={"x-domain": "j >= 1"},
    )
    s: Annotated[list[float] | None, BeforeValidator(_numbers)] = Field(
        None,
        max_length=MAX_SEQUENCE_LENGTH,
        description="sequence=custom only: s_{i_min}, s_{i_min+1}, …; strictly increasing, "
        "|s_i| < 1, s_0 = 0. Comma-separated in a GET query.",
        json_schema_extra={"x-domain": "strictly increasing, |s_i| < 1, s_0 = 0"},
    )
    i_min: int | None = Field(
        None,
        ge=-10_000_000,
        le=10_000_000,
        description="First index i (default: see the description; custom: index of s[0], 0). "
        "example-12: i_min >= 0; remark-13: i_min > −j/2.",
        json_schema_extra={"x-domain": "i_min >= 0 (example-12), i_min > −j/2 (remark-13)"},
    )
    i_max: int | None = Field(
        None,
        ge=-10_000_000,
        le=10_000_000,
        description="Last index i, >= i_min (custom: i_min + len(s) − 1).",
        json_schema_extra={"x-domain": "i_min <= i_max"},
    )

    def core_arguments(self) -> dict[str, Any]:
        arguments = super().core_arguments()
        first, last = resolve_range(self.sequence, self.j, self.s, self.i_min, self.i_max)
        arguments["i_min"], arguments["i_max"] = first, last
        return arguments
