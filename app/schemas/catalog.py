"""Catalog responses: the discretizations and the paper's checkable statements."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, Field

from app.schemas.curve import CheckModel, PrecisionInfo


class ParameterInfo(BaseModel):
    name: str = Field(description="Query parameter / JSON field name.")
    description: str = Field(description="What it is, in the paper's notation.")
    kind: str = Field(description="`paper` (the paper's symbols and index range) or `common`.")
    domain: str | None = Field(None, description="The admissible values, e.g. `0 < d < h`.")
    default: Any = Field(None, description="Default value.")
    json_schema: dict[str, Any] = Field(description="JSON Schema of the value (type, bounds).")


class DiscretizationEntry(BaseModel):
    id: str = Field(description="Id used in /discretizations/{id}.")
    title: str
    reference: str = Field(description="Where the paper defines it.")
    summary: str
    url: str = Field(description="Path of the curve endpoint.")
    default_range: tuple[int, int] = Field(description="Default (i_min, i_max).")
    methods: list[str] = Field(description="Values of `method`.")
    parameters: list[ParameterInfo]
    companions: dict[str, str] = Field(description="Companion polygons in the response.")
    constants: dict[str, str] = Field(description="Fitted constants in the response.")
    statements: list[str] = Field(description="Ids of the statements checked (GET /theorems).")


class FigureEntry(BaseModel):
    id: str = Field(description="Id used in /figures/{id}.svg, e.g. `figure-4`.")
    title: str
    reference: str = Field(description="Where the paper shows it.")
    description: str = Field(description="What is drawn, and where its data come from.")
    url: str = Field(description="Path of the picture (default parameters).")
    parameters: list[ParameterInfo] = Field(description="Adjustable parameters (query).")


class StatementInfo(BaseModel):
    id: str
    reference: str
    claim: str
    discretizations: list[str] = Field(description="Discretizations whose responses check it.")
    url: str = Field(description="Path that checks it with default parameters.")


class TheoremResponse(BaseModel):
    """One statement checked on one computed polygon."""

    id: str
    reference: str
    claim: str
    discretization: str = Field(description="The discretization it was checked on.")
    parameters: dict[str, Any] = Field(description="Effective parameters of that polygon.")
    precision: PrecisionInfo
    check: CheckModel


class Health(BaseModel):
    status: str = Field(description="`ok` when the service answers.")
    version: str = Field(description="Service version.")
