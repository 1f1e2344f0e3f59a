"""Catalog responses: the discretizations and the paper's checkable statements."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from app.schemas.common import JSONValue
from app.schemas.curve import CheckModel, CheckModelMP, ParameterValue, PrecisionInfo


class ParameterInfo(BaseModel):
    name: str = Field(description="Query parameter / JSON field name.")
    description: str = Field(description="What it is, in the paper's notation.")
    kind: str = Field(description="`paper` (the paper's symbols and index range) or `common`.")
    domain: str | None = Field(None, description="The admissible values, e.g. `0 < d < h`.")
    default: JSONValue = Field(None, description="Default value.")
    json_schema: dict[str, JSONValue] = Field(
        description="JSON Schema of the value (type, bounds)."
    )
    domain_tex: str | None = Field(None, description="`domain` as TeX, where it has a formula.")


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
    constants_tex: dict[str, str] = Field(
        default_factory=dict, description="Each constant's defining relation as TeX."
    )
    statements: list[str] = Field(description="Ids of the statements checked (GET /theorems).")


class FigureEntry(BaseModel):
    id: str = Field(description="Id used in /figures/{id}.svg, e.g. `figure-4`.")
    title: str
    reference: str = Field(description="Where the paper shows it.")
    description: str = Field(description="What is drawn, and where its data come from.")
    url: str = Field(description="Path of the picture (default parameters).")
    parameters: list[ParameterInfo] = Field(description="Adjustable parameters (query).")
    discretizations: list[str] = Field(
        default_factory=list,
        description="Ids of the discretizations whose data it draws (the explorer shows it with "
        "them, passing on the parameters they share).",
    )


class ErratumTeX(BaseModel):
    id: str = Field(description="Erratum id (docs/errata.md), e.g. `E3`.")
    printed_tex: str = Field(description="The formula as printed, as TeX.")
    corrected_tex: str = Field(description="The formula as corrected, as TeX.")


class StatementInfo(BaseModel):
    id: str
    reference: str = Field(description="Where the paper states it.")
    claim: str = Field(description="The claim in words, and how its residual is measured.")
    claim_tex: str = Field("", description="The claim's formula as TeX (KaTeX renders it).")
    discretizations: list[str] = Field(description="Discretizations whose responses check it.")
    studies: list[str] = Field(
        default_factory=list,
        description="Refinement studies whose responses check it (GET /convergence/{id}).",
    )
    smooth: list[str] = Field(
        default_factory=list,
        description="Smooth references of Section 2 whose responses check it (GET /smooth/{id}).",
    )
    surfaces: list[str] = Field(
        default_factory=list,
        description="Surfaces whose mesh responses check it (GET /surfaces/{id}).",
    )
    url: str = Field(description="Path that checks it with default parameters.")
    example_url: str = Field(
        description="A ready-to-use request with every parameter of the paper at its default "
        "(change any of them)."
    )
    parameters: list[ParameterInfo] = Field(
        description="The parameters GET /theorems/{id} accepts: those of its (first) "
        "discretization or study, with domains and defaults."
    )
    conditions: list[str] = Field(
        default_factory=list,
        description="Hypotheses the text leaves implicit or states needlessly (see "
        "docs/errata.md).",
    )
    errata: list[str] = Field(
        default_factory=list,
        description="Errata (docs/errata.md) the check carries at the default parameters: the "
        "printed formula is wrong and the check tests the corrected one.",
    )
    errata_tex: list[ErratumTeX] = Field(
        default_factory=list, description="Each of `errata`: printed and corrected, as TeX."
    )


class TheoremResponse(BaseModel):
    """One statement checked on one computed polygon or refinement study."""

    id: str
    reference: str
    claim: str
    discretization: str | None = Field(
        description="The discretization it was checked on (null for a refinement study)."
    )
    study: str | None = Field(
        None, description="The refinement study it was checked on (GET /convergence/{id})."
    )
    smooth: str | None = Field(
        None, description="The smooth reference it was checked on (GET /smooth/{id})."
    )
    surface: str | None = Field(
        None, description="The surface whose meshes it was checked on (GET /surfaces/{id})."
    )
    parameters: dict[str, ParameterValue] = Field(
        description="Effective parameters of that computation."
    )
    precision: PrecisionInfo
    conditions: list[str] = Field(
        default_factory=list, description="Hypotheses the text leaves implicit (see /theorems)."
    )
    check: CheckModel | CheckModelMP = Field(
        description="The check; on rigorous balls (precision=mp of a discretization) its bounds "
        "are decimal strings (`CheckModelMP`)."
    )


class Readiness(BaseModel):
    status: Literal["ready"] = Field(description="`ready` while this worker admits new work.")


class Health(BaseModel):
    status: str = Field(description="`ok` when the service answers.")
    version: str = Field(description="Service version.")
