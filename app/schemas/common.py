"""Shared request models and the problem+json error document."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator
from pydantic_core import PydanticCustomError

#: Nonzero real parameters are at least this large in magnitude: the checks square coordinates,
#: and squares of smaller numbers underflow float64 (subnormal inputs are refused, not garbled).
SMALLEST_MAGNITUDE = 1e-100


class StrictModel(BaseModel):
    """Base of every request model: rejects unknown fields, NaN/Infinity and tiny magnitudes."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    @field_validator("*", mode="after")
    @classmethod
    def _representable(cls, value: Any, info: ValidationInfo) -> Any:
        """Refuse 0 < |x| < 1e-100 for every real parameter (a 422 naming it)."""
        if isinstance(value, float) and value != 0 and abs(value) < SMALLEST_MAGNITUDE:
            raise PydanticCustomError(
                "magnitude",
                "{name} is 0 or at least 1e-100 in magnitude",
                {"name": info.field_name},
            )
        return value


class CurveQuery(StrictModel):
    """Parameters every curve endpoint accepts; subclasses add the paper's parameters."""

    precision: Literal["float64", "mp"] = Field(
        "float64",
        description="`float64`: IEEE doubles with numpy, coordinates as JSON numbers. `mp`: "
        "mpmath with `digits` significant digits, coordinates as decimal strings.",
    )
    digits: int = Field(
        30,
        ge=1,
        le=100_000,
        description="Significant digits for precision=mp (at most DCOSH_MAX_DIGITS, default "
        "1000; (digits + 200) × steps is bounded by DCOSH_MAX_MP_WORK). Ignored in float64.",
    )
    format: Literal["json", "csv", "svg", "npy"] = Field(
        "json",
        description="`json` (default), `csv` (columns curve,index,x,y: the polygon `p` "
        "followed by each companion), `svg` (a self-contained picture of `p` and its "
        "companions with axes and a legend, equal scales; at most DCOSH_MAX_SVG_VERTICES "
        "vertices per polygon) or `npy` (binary, for large curves: the vertices of `p` as one "
        "(n, 2) little-endian float64 array in NumPy's .npy format, row k holding index "
        "`X-First-Index` + k; precision=float64 only; no companions or checks).",
    )
    detail: bool = Field(
        False, description="Fill each check's `per_index` with the residual at every index."
    )

    @field_validator("format", mode="after")
    @classmethod
    def _binary_is_float64(cls, value: str, info: ValidationInfo) -> str:
        """format=npy holds float64 numbers; mp coordinates are decimal strings."""
        if value == "npy" and info.data.get("precision") == "mp":
            raise PydanticCustomError(
                "format_precision",
                "format=npy needs precision=float64 (mp coordinates are decimal strings; "
                "use format=json or csv)",
            )
        return value

    def core_arguments(self) -> dict[str, Any]:
        """The keyword arguments of the core's ``compute`` (the paper's parameters)."""
        return self.model_dump(exclude={"precision", "digits", "format"})


def strict_body(model: type[CurveQuery]) -> type[CurveQuery]:
    """The JSON-body variant of a request model: the same fields, validated strictly.

    Query strings are text and must be parsed leniently ("0.3" is a number); a JSON body has real
    types, so `false` is not an integer and `"1"` is not a number there.
    """
    name = model.__name__.removesuffix("Query") + "Body"
    config = ConfigDict(**{**model.model_config, "strict": True})
    namespace = {"model_config": config, "__doc__": model.__doc__, "__module__": model.__module__}
    return type(name, (model,), namespace)


class ProblemParameterError(BaseModel):
    """One offending parameter of a problem+json response."""

    parameter: str = Field(description="Public name of the parameter, e.g. `d` or `i_max`.")
    constraint: str = Field(description="The condition it must satisfy, e.g. `0 < d < h`.")
    value: Any = Field(None, description="The value received (as sent, or null if absent).")


class Problem(BaseModel):
    """RFC 9457 problem details, with the offending parameters in `errors`."""

    type: str = Field(description="URI reference identifying the problem type.")
    title: str = Field(description="Short summary of the problem type.")
    status: int = Field(description="HTTP status code.")
    detail: str = Field(description="What went wrong with this request, in words.")
    errors: list[ProblemParameterError] = Field(
        default_factory=list, description="The parameters at fault, each with its constraint."
    )
    valid: list[str] | None = Field(None, description="For unknown ids: the ids that exist.")


PROBLEM_RESPONSES: dict[int | str, dict[str, Any]] = {
    422: {
        "model": Problem,
        "content": {"application/problem+json": {}},
        "description": "Invalid, out-of-domain or oversize input (names the parameter), or a "
        "computation stopped at the time limit (type `…/problems/time-limit`).",
    },
    503: {
        "model": Problem,
        "content": {"application/problem+json": {}},
        "description": "Overloaded (type `…/problems/overloaded`): this worker does not admit the "
        "request now (its admitted work is at its budget, its queue is full, the request could "
        "not finish within the time limit of its arrival, or it is shutting down). Retry after "
        "`Retry-After` seconds.",
        "headers": {
            "Retry-After": {
                "description": "Seconds after which a retry is likely admitted.",
                "schema": {"type": "integer"},
            }
        },
    },
}
NOT_FOUND_RESPONSE: dict[int | str, dict[str, Any]] = {
    404: {
        "model": Problem,
        "content": {"application/problem+json": {}},
        "description": "Unknown id; `valid` lists the ids that exist.",
    },
}
