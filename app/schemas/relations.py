"""Response of GET /relations: Section 4 as a matrix of discretizations against properties."""

from __future__ import annotations

from pydantic import BaseModel, Field

from app.schemas.curve import Coordinate, ParameterValue, PrecisionInfo

RELATIONS_DESCRIPTION = """\
Section 4 as a matrix. Rows: every discretization the service computes, at its default
parameters or at those given as `<id>.<parameter>` (e.g. `d4b.d=0.3`, `d2a-quad.f1=2`,
`d2a-hex.lambda=0.3`; the same names, domains and defaults as GET /discretizations/{id}).
Columns: (D1) Δ²p_i^y = c(l_i + l_{i+1}); (D3) A_i = c l_i; eq. (2) Δ²p_i^y = c(A_i + A_{i+1});
eq. (7) Δ²p_i^y = c_1 A_i + c_2 A_{i+1} (i even), c_2 A_i + c_1 A_{i+1} (i odd); H = 0 and
K constant of a surface of revolution (Section 5; Theorems 7, 8; (D2b)).

Each cell fits the constant(s) by least squares on the row's polygon and reports the largest
residual, relative to the magnitude of the numbers it is computed from (docs/checks.md), the
tolerance of that polygon's local checks and the verdict. (D1), (D3) and (2) hold when the
residual is within tolerance and c > 0, as the paper requires; (7) only asks for two constants.

The curvature columns use the mixed-area curvatures of Bobenko–Pottmann–Wallner [3] on
three-dimensional faces of the surface of revolution (15), not the formula (17):
- H = 0: p with the row's Gauss image, its own `gauss_image` companion where it has one (d2a: φ,
  the sphere of its Christoffel dual; d2b: the inscribed n; d4b: the circumscribed m of Theorem
  8), else the circumscribed Gauss image built from p (edges tangent to the unit circle and
  parallel to p's), on the interior vertices. Constant `a`: the least-squares p_i^y n_i^y, which
  H = 0 makes constant (the discrete neck radius).
- K constant: the row's tractrix with the Gauss image of Theorem 7 (`tractrix_gauss_image`);
  constant `K` fitted by least squares (−1/h² for d4b). Rows without a tractrix (catenoids)
  or without a Gauss image for it (d4a) are not applicable (`holds: null`, with the reason).
The tolerance of a curvature cell is the one the discretization gives its Gauss image (larger
where the image is built by a long recursion, such as d4b's inscribed n).

`format=html` and `format=svg` return the same matrix as a table (symbol, residual, constants).
"""


class CellModel(BaseModel):
    property: str = Field(description="Column id.")
    residual: float | str | None = Field(
        description="Largest residual; null when not evaluated. precision=mp (rigorous balls): "
        "a decimal string >= its rigorous upper bound (10 significant digits; from 324 digits "
        "on it leaves the float range)."
    )
    tolerance: float | str = Field(
        description="Largest residual that counts as holding; precision=mp: a decimal string "
        "(10 significant digits)."
    )
    holds: bool | None = Field(description="The verdict; null when not evaluated.")
    constants: dict[str, Coordinate] = Field(
        description="Fitted constant(s): c; c1 and c2 (eq. (7)); a (H = 0: p_i^y n_i^y); K (K "
        "constant)."
    )
    note: str | None = Field(
        None,
        description="Why a cell fails or is not applicable; for the curvature columns, which "
        "surface and Gauss image were used.",
    )


class ColumnModel(BaseModel):
    id: str
    title: str = Field(description="The property as the paper names it.")
    reference: str
    claim: str = Field(description="The property, and how its residual is measured.")


class RowModel(BaseModel):
    id: str = Field(description="Discretization id.")
    title: str
    reference: str
    parameters: dict[str, ParameterValue] = Field(
        description="Effective parameters of the polygon."
    )
    url: str = Field(description="The curve request with these parameters.")
    cells: list[CellModel] = Field(description="One per column, in column order.")


class RelationsResponse(BaseModel):
    """Every discretization against every property of Sections 3-5."""

    precision: PrecisionInfo
    columns: list[ColumnModel]
    rows: list[RowModel]
