"""Shared request models and the problem+json error document."""

from __future__ import annotations

import functools
import re
from decimal import Decimal
from typing import Any, Literal, get_args

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    ValidationInfo,
    ValidatorFunctionWrapHandler,
    field_validator,
    model_validator,
)
from pydantic_core import PydanticCustomError
from typing_extensions import TypeAliasType

from app.geometry.precision import ExactReal

JSONValue = TypeAliasType(
    "JSONValue",
    "bool | int | float | str | list[JSONValue] | dict[str, JSONValue] | None",
)
"""Any JSON value (typed, so that generated clients see JSON rather than `unknown`)."""


#: Nonzero real parameters are at least this large in magnitude: the checks square coordinates,
#: and squares of smaller numbers underflow float64 (subnormal inputs are refused, not garbled).
SMALLEST_MAGNITUDE = 1e-100

#: A decimal as precision=mp takes it: optional sign, digits with an optional point, optional
#: exponent (no hex, no underscores, no nan/inf).
DECIMAL = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")

#: Longest decimal text accepted for a real parameter in precision=mp.
MAX_DECIMAL_CHARACTERS = 2000


def _is_real(annotation: Any) -> bool:
    """Whether a field holds a real parameter: ``float`` or ``float | None``."""
    return annotation is float or set(get_args(annotation)) == {float, type(None)}


@functools.cache
def real_fields(model: type[BaseModel]) -> frozenset[str]:
    """The names of ``model``'s real parameters (``_is_real``), found once per class: the
    validators below run for every field of every request, and reading ``model_fields`` and
    the annotations there took half of a query's validation."""
    return frozenset(
        name for name, field in model.model_fields.items() if _is_real(field.annotation)
    )


class StrictModel(BaseModel):
    """Base of every request model: rejects unknown fields, NaN/Infinity and tiny magnitudes."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    @field_validator("*", mode="wrap")
    @classmethod
    def _exact_decimal(
        cls, value: Any, handler: ValidatorFunctionWrapHandler, info: ValidationInfo
    ) -> Any:
        """In precision=mp a real parameter is the decimal the client wrote (an ``ExactReal``).

        GET gives the query text; POST a JSON string (accepted in mp only) or a JSON number,
        as written where the route reads bodies with ``ExactJSONRoute`` (else its shortest
        repr). In float64 nothing changes.
        """
        if (
            info.field_name not in real_fields(cls)
            or info.data.get("precision") != "mp"
            or isinstance(value, bool)
            or not isinstance(value, str | int | float)
        ):
            # a JSON number read as written (routers.common.ExactJSONRoute) is its double here
            return handler(float(value) if isinstance(value, ExactReal) else value)
        if isinstance(value, ExactReal):
            text = value.text
        else:
            text = value.strip() if isinstance(value, str) else repr(value)
        if isinstance(value, str):
            if len(text) > MAX_DECIMAL_CHARACTERS or DECIMAL.fullmatch(text) is None:
                raise PydanticCustomError(
                    "decimal",
                    "{name} is a decimal number such as 0.125, -3 or 1.5e-7 (at most "
                    "{limit} characters)",
                    {"name": info.field_name, "limit": MAX_DECIMAL_CHARACTERS},
                )
            value = float(text)
        result = handler(value)
        if not isinstance(result, float):
            return result
        return ExactReal(str(Decimal(text)))

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


CHECKS_DESCRIPTION = (
    "Which checks to compute and return: `all` (default), `none`, `failed` (those whose verdict "
    "is `holds: false`), or a comma-separated list of statement ids (GET /theorems; the "
    "discretization's own are listed in GET /discretizations). Only what is asked for is "
    "computed, so `checks=none` answers fastest. An unknown id is a 422 listing the valid ones."
)
COMPANIONS_DESCRIPTION = (
    "Which companion polygons to compute and return: `all` (default), `none`, or a "
    "comma-separated list of names (GET /discretizations lists each discretization's). "
    "An unknown name is a 422 listing the valid ones."
)
_SELECTION_WORDS = {"checks": ("all", "none", "failed"), "companions": ("all", "none")}


def normalized_selection(value: Any, name: str) -> str:
    """A selection as one canonical string: a keyword, or sorted unique ids joined by commas.

    Accepts a string (``"theorem-5, d1"``) or, in a JSON body, a list of strings.
    """
    if isinstance(value, list | tuple):
        if not all(isinstance(v, str) for v in value):
            raise PydanticCustomError("selection", "{name} is a list of ids", {"name": name})
        value = ",".join(value)
    if not isinstance(value, str):
        raise PydanticCustomError("selection", "{name} is a string of ids", {"name": name})
    ids = sorted({part.strip() for part in value.split(",") if part.strip()})
    words = _SELECTION_WORDS[name]
    if not ids:
        raise PydanticCustomError(
            "selection", "{name} is one of {words} or a list of ids", {"name": name, "words": words}
        )
    if len(ids) > 1 and set(ids) & set(words):
        raise PydanticCustomError(
            "selection",
            "{name}: {words} stand alone, not in a list of ids",
            {"name": name, "words": ", ".join(words)},
        )
    return ",".join(ids)


class CurveQuery(StrictModel):
    """Parameters every curve endpoint accepts; subclasses add the paper's parameters."""

    precision: Literal["float64", "mp"] = Field(
        "float64",
        description="`float64`: IEEE doubles with numpy, coordinates as JSON numbers; every "
        "real parameter is its nearest double. `mp`: `digits` significant digits, coordinates "
        "as decimal strings, and so are the checks' rigorous bounds (`residual`, `tolerance`, "
        "`printed_residual`: beyond the float range from 324 digits on); every real parameter "
        "is the decimal written (GET: the query text; "
        'POST: a JSON string such as "0.1234567890123456789", or a JSON number, which '
        "arrives as a double and is read as its shortest decimal), carried at the working "
        "precision and echoed exactly in `parameters`. A malformed decimal is a 422 naming "
        "the parameter.",
    )
    digits: int = Field(
        30,
        ge=1,
        le=100_000,
        description="Significant digits for precision=mp (at most DCOSH_MAX_DIGITS, default "
        "1000; (digits + 200) × steps is bounded by DCOSH_MAX_MP_WORK). Ignored in float64.",
    )
    format: Literal["json", "csv", "svg", "npy", "npz", "checks-csv"] = Field(
        "json",
        description="`json` (default), `csv` (columns curve,index,x,y: the polygon `p` "
        "followed by each companion), `svg` (a self-contained picture of `p` and its "
        "companions with axes and a legend, equal scales; at most DCOSH_MAX_SVG_VERTICES "
        "vertices per polygon) or `npy` (binary, for large curves: the vertices of `p` as one "
        "(n, 2) little-endian float64 array in NumPy's .npy format, row k holding index "
        "`X-First-Index` + k; precision=float64 only; no companions or checks), `npz` "
        "(NumPy's .npz: for p and every companion `<name>_indices` (int64) and "
        "`<name>_vertices` ((n, 2) float64); precision=float64 only) or `checks-csv` (one row "
        "per check: id,reference,residual,tolerance,holds,erratum,printed_residual).",
    )
    detail: bool = Field(
        False, description="Fill each check's `per_index` with the residual at every index."
    )
    checks: str = Field(
        "all", max_length=4096, description=CHECKS_DESCRIPTION, examples=["all", "theorem-5,d1"]
    )
    companions: str = Field(
        "all", max_length=1024, description=COMPANIONS_DESCRIPTION, examples=["all", "tractrix"]
    )

    @field_validator("checks", "companions", mode="before")
    @classmethod
    def _selection(cls, value: Any, info: ValidationInfo) -> str:
        """One canonical spelling per selection (it is part of the cache key and the ETag)."""
        return normalized_selection(value, str(info.field_name))

    @field_validator("format", mode="after")
    @classmethod
    def _binary_is_float64(cls, value: str, info: ValidationInfo) -> str:
        """format=npy holds float64 numbers; mp coordinates are decimal strings."""
        if value in ("npy", "npz") and info.data.get("precision") == "mp":
            raise PydanticCustomError(
                "format_precision",
                "format={format} needs precision=float64 (mp coordinates are decimal strings; "
                "use format=json or csv)",
                {"format": value},
            )
        return value

    def core_arguments(self) -> dict[str, Any]:
        """The keyword arguments of the core's ``compute`` (the paper's parameters)."""
        return self.model_dump(exclude={"precision", "digits", "format", "checks", "companions"})


def strict_body(model: type[CurveQuery]) -> type[CurveQuery]:
    """The JSON-body variant of a request model: the same fields, validated strictly.

    Query strings are text and must be parsed leniently ("0.3" is a number); a JSON body has real
    types, so `false` is not an integer and `"1"` is not a number there.
    """
    name = model.__name__.removesuffix("Query") + "Body"
    config = ConfigDict(**{**model.model_config, "strict": True})
    integers = frozenset(
        field
        for field, schema in model.model_json_schema()["properties"].items()
        if "integer" in {schema.get("type"), *(o.get("type") for o in schema.get("anyOf", []))}
    )

    def integral_floats(cls: type[BaseModel], data: Any) -> Any:
        """JSON has one number type: 1.0 is the integer 1 (JSON Schema's `integer` says so)."""
        if not isinstance(data, dict):
            return data
        return {
            key: int(value)
            if key in integers and isinstance(value, float) and value.is_integer()
            else value
            for key, value in data.items()
        }

    namespace = {
        "model_config": config,
        "__doc__": model.__doc__,
        "__module__": model.__module__,
        "_integral_floats": model_validator(mode="before")(classmethod(integral_floats)),  # type: ignore[arg-type]
    }
    return type(name, (model,), namespace)


class ProblemParameterError(BaseModel):
    """One offending parameter of a problem+json response."""

    parameter: str = Field(description="Public name of the parameter, e.g. `d` or `i_max`.")
    constraint: str = Field(description="The condition it must satisfy, e.g. `0 < d < h`.")
    value: JSONValue = Field(None, description="The value received (as sent, or null if absent).")


class ProblemFormat(BaseModel):
    """One representation an endpoint has (406 Not acceptable lists them)."""

    format: str = Field(description="The value of the query parameter `format` that asks for it.")
    media_type: str = Field(description="Its media type, as `Accept` names it.")


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
    available: list[ProblemFormat] | None = Field(
        None, description="For 406 Not acceptable: the representations the endpoint has."
    )


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
