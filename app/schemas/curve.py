"""The curve response: a discrete hyperbolic cosine with companions, constants and checks.

These models document the JSON in OpenAPI and let tests validate real responses; the service
encodes responses directly with orjson (numpy arrays never pass through pydantic).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

Coordinate = float | str
"""A JSON number in float64 mode, a decimal string with `digits` digits in mp mode."""

ParameterValue = bool | int | float | str | list[int] | list[float] | list[str] | None
"""An effective parameter as the response repeats it (numbers, ids, sequences)."""


class PrecisionInfo(BaseModel):
    mode: Literal["float64", "mp"] = Field(description="The arithmetic used.")
    digits: int = Field(description="Significant decimal digits (16 for float64).")


class PolylineModel(BaseModel):
    """A companion polygon in float64: coordinates are JSON numbers."""

    description: str = Field("", description="What this companion is.")
    indices: list[int] = Field(description="Paper indices i, aligned with `vertices`.")
    vertices: list[tuple[float, float]] = Field(description="Points (x, y).")


class PolylineModelMP(PolylineModel):
    """A companion polygon in mp: coordinates are decimal strings."""

    vertices: list[tuple[str, str]] = Field(description="Points (x, y), decimal strings.")  # type: ignore[assignment]


class ErratumModel(BaseModel):
    id: str = Field(description="Entry in docs/errata.md, e.g. `E3`.")
    printed: str = Field(description="The formula as printed in the paper's transcription.")
    corrected: str = Field(description="The formula that holds; the check tests this one.")
    printed_residual: float | None = Field(
        description="The same residual for the printed formula (large: the print is wrong)."
    )
    certified: Literal["false", "undecided"] | None = Field(
        None,
        description="precision=mp on rigorous balls (the response's `certified` is set): "
        "`printed_residual` is then a rigorous lower bound, and `false` certifies that the "
        "printed formula is false on this polygon (the bound is > 0); `undecided` when the "
        "ball still holds 0. null in float64 and where mp is not computed on balls (surfaces, "
        "GET /theorems/{id} on smooth references).",
    )
    link: str = Field(
        description="The erratum's page on this service (GET /errata/{id}): the printed and "
        "corrected forms with the evidence."
    )


class ErratumModelMP(ErratumModel):
    """An erratum of a precision=mp answer computed on rigorous balls."""

    printed_residual: str | None = Field(  # type: ignore[assignment]
        description="A rigorous lower bound of the printed formula's residual, a decimal string "
        "rounded down (10 significant digits; a string: from 324 digits on it leaves the float "
        "range). Greater than 0: the printed formula is false on this polygon (`certified`)."
    )


class PerIndexModel(BaseModel):
    indices: list[int] = Field(description="Index i of each residual.")
    residuals: list[float] = Field(description="Residual at each index.")


class PerIndexModelMP(PerIndexModel):
    """Per-index residuals of a precision=mp answer computed on rigorous balls."""

    residuals: list[str | None] = Field(  # type: ignore[assignment]
        description="A rigorous upper bound of the residual at each index, a decimal string "
        "rounded up (10 significant digits; a string: from 324 digits on they leave the float "
        "range); none exceeds the check's `residual`. null where a residual could not be "
        "computed (not finite)."
    )


class CheckModel(BaseModel):
    id: str = Field(description="Statement id, see GET /theorems.")
    reference: str = Field(description="Where the paper states it.")
    claim: str = Field(description="The claim, and how its residual is measured.")
    residual: float | None = Field(description="Largest residual; null when not applicable.")
    tolerance: float = Field(description="Largest residual that counts as holding.")
    holds: bool | None = Field(
        description="residual <= tolerance; null when not applicable. On rigorous balls "
        "(`certified` set) `residual` is an upper bound, so true is a proof; false needs a "
        "lower bound above the tolerance, and null with the note `undecided` is the case in "
        "between."
    )
    per_index: PerIndexModel | None = Field(description="Residual per index (detail=true).")
    erratum: ErratumModel | None = Field(description="Set when the printed formula is wrong.")
    note: str | None = Field(None, description="Context for the verdict.")


class CheckModelMP(CheckModel):
    """A check of a precision=mp answer computed on rigorous balls (the curve's `certified` is
    set): `residual`, `tolerance` and the `per_index` residuals are decimal strings, since from
    324 digits on they leave the float range (10^−digits is 0 as a float)."""

    residual: str | None = Field(  # type: ignore[assignment]
        description="A rigorous upper bound of the largest residual, a decimal string rounded up "
        "(10 significant digits); null when not applicable."
    )
    tolerance: str = Field(  # type: ignore[assignment]
        description="Largest residual that counts as holding, a decimal string (10 significant "
        "digits). `holds` is true when `residual` <= `tolerance` as these decimals."
    )
    per_index: PerIndexModelMP | None = Field(
        description="Residual bound per index (detail=true), decimal strings."
    )
    erratum: ErratumModelMP | None = Field(description="Set when the printed formula is wrong.")


class CertificateModel(BaseModel):
    """What the rigorous balls of a precision=mp answer guarantee (python-flint `arb`)."""

    radius: str = Field(
        description="Largest radius of any returned coordinate (vertices and companions), a "
        "decimal rounded up (a string: radii of long ranges leave the float range): each exact "
        "coordinate is within `radius` of the computed midpoint, which is shown rounded to "
        "`precision.digits` significant digits."
    )
    relative_radius: str = Field(
        description="Largest radius of a point's coordinates divided by the point's size "
        "max(|x|, |y|), a decimal rounded up: below 10^−(digits+1) when `resolved`."
    )
    working_digits: int = Field(
        description="Decimal digits the balls were computed with (digits, guard digits and the "
        "digits a recursion's radii grow by)."
    )
    resolved: bool = Field(
        description="Whether every returned coordinate's radius is below 10^−(digits+1) of its "
        "point's size (the precision is raised until it is, within a bound)."
    )


class CurveResponse(BaseModel):
    """One discretization in float64 (`precision.mode` = `float64`): `vertices` is always the
    discrete hyperbolic cosine p_i, coordinates and constants are JSON numbers."""

    id: str
    title: str
    reference: str
    parameters: dict[str, ParameterValue] = Field(
        description="Effective parameters, defaults filled in."
    )
    precision: PrecisionInfo
    indices: list[int] = Field(description="Paper indices i of `vertices`.")
    vertices: list[tuple[float, float]] = Field(description="p_i = (x, y).")
    companions: dict[str, PolylineModel] = Field(description="Polygons built alongside p.")
    constants: dict[str, float] = Field(description="Fitted constants (c of D1, D3, (2)).")
    checks: list[CheckModel] = Field(description="Every statement checked on this polygon.")
    certified: CertificateModel | None = Field(
        None,
        description="Set when precision=mp is computed on rigorous balls (every discretization "
        "of /discretizations): residuals are rigorous bounds and `radius` bounds every "
        "coordinate; null in float64.",
    )


class CurveResponseMP(CurveResponse):
    """One discretization in mp (`precision.mode` = `mp`): as `CurveResponse`, with coordinates
    and constants as decimal strings of `precision.digits` significant digits, and each check's
    `residual`, `tolerance`, `printed_residual` and per-index residuals as decimal strings
    (rigorous bounds)."""

    vertices: list[tuple[str, str]] = Field(description="p_i = (x, y), decimal strings.")  # type: ignore[assignment]
    companions: dict[str, PolylineModelMP] = Field(  # type: ignore[assignment]
        description="Polygons built alongside p."
    )
    constants: dict[str, str] = Field(  # type: ignore[assignment]
        description="Fitted constants (c of D1, D3, (2)), decimal strings."
    )
    checks: list[CheckModelMP] = Field(  # type: ignore[assignment]
        description="Every statement checked on this polygon; bounds as decimal strings."
    )
