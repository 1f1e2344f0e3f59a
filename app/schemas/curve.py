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
    link: str = Field(
        description="The erratum's page on this service (GET /errata/{id}): the printed and "
        "corrected forms with the evidence."
    )


class PerIndexModel(BaseModel):
    indices: list[int] = Field(description="Index i of each residual.")
    residuals: list[float] = Field(description="Residual at each index.")


class CheckModel(BaseModel):
    id: str = Field(description="Statement id, see GET /theorems.")
    reference: str = Field(description="Where the paper states it.")
    claim: str = Field(description="The claim, and how its residual is measured.")
    residual: float | None = Field(description="Largest residual; null when not applicable.")
    tolerance: float = Field(description="Largest residual that counts as holding.")
    holds: bool | None = Field(description="residual <= tolerance; null when not applicable.")
    per_index: PerIndexModel | None = Field(description="Residual per index (detail=true).")
    erratum: ErratumModel | None = Field(description="Set when the printed formula is wrong.")
    note: str | None = Field(None, description="Context for the verdict.")


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


class CurveResponseMP(CurveResponse):
    """One discretization in mp (`precision.mode` = `mp`): as `CurveResponse`, with coordinates
    and constants as decimal strings of `precision.digits` significant digits."""

    vertices: list[tuple[str, str]] = Field(description="p_i = (x, y), decimal strings.")  # type: ignore[assignment]
    companions: dict[str, PolylineModelMP] = Field(  # type: ignore[assignment]
        description="Polygons built alongside p."
    )
    constants: dict[str, str] = Field(  # type: ignore[assignment]
        description="Fitted constants (c of D1, D3, (2)), decimal strings."
    )
