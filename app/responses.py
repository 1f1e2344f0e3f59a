"""Shaping and encoding responses: curve documents, CSV, JSON bytes, ETag and caching.

Arrays go straight from numpy to orjson (OPT_SERIALIZE_NUMPY): no Python lists, no pydantic
validation on the way out (see the serving-path facts in design.md and bench/).
"""

from __future__ import annotations

import io
from decimal import Decimal
from typing import Any

import numpy as np
import orjson

from app.geometry import balls
from app.geometry.ball_arithmetic import Ball, decimal_text
from app.geometry.checks import Check
from app.geometry.curve import Curve, Polyline
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Arithmetic, Array, ExactReal, MultiPrecision
from app.geometry.studies.common import Study

JSON_OPTIONS = orjson.OPT_SERIALIZE_NUMPY
JSON_MEDIA_TYPE = "application/json"
CSV_MEDIA_TYPE = "text/csv; charset=utf-8"
NPY_MEDIA_TYPE = "application/x-npy"
NPZ_MEDIA_TYPE = "application/x-npz"


def exact_number(value: Any) -> orjson.Fragment:
    """orjson's fallback: a parameter of precision=mp as the JSON number the client wrote."""
    if isinstance(value, ExactReal):
        return orjson.Fragment(value.text)
    raise TypeError(f"{type(value).__name__} is not JSON serializable")


def encode_json(document: Any) -> bytes:
    """orjson bytes; numpy arrays and scalars are encoded natively, exact decimals as written."""
    return orjson.dumps(document, option=JSON_OPTIONS, default=exact_number)


def coordinates(ar: Arithmetic, points: Array) -> Any:
    """``(n, 2)`` points as float64 array (float64 mode) or ``[[str, str], ...]`` (mp mode)."""
    if isinstance(ar, MultiPrecision | Ball):
        xs, ys = ar.to_strings(points[:, 0]), ar.to_strings(points[:, 1])
        return [list(pair) for pair in zip(xs, ys, strict=True)]
    return np.ascontiguousarray(points, dtype=np.float64)


def number(ar: Arithmetic, value: Any) -> float | str:
    """A computed value: float in float64 mode, decimal string in mp mode."""
    if isinstance(ar, MultiPrecision):
        return str(ar.ctx.nstr(value, ar.digits))
    if isinstance(ar, Ball):
        return ar.to_strings(np.array([value], dtype=object))[0]
    return float(value)


def ensure_finite(curve: Curve) -> None:
    """Last line of defence: no NaN or Infinity ever reaches a response."""
    ar = curve.arithmetic
    polylines = [("p", curve.polygon), *curve.companions.items()]
    name = not_finite(ar, [(name, polyline.vertices) for name, polyline in polylines])
    if name is not None:
        raise NotRepresentableError(
            "precision",
            "values representable in the chosen precision",
            ar.mode,
            f"the polygon {name!r} leaves the float64 range on this index range; "
            "use precision=mp or a shorter range",
        )


def not_finite(ar: Arithmetic, named: list[tuple[str, Any]]) -> str | None:
    """The name of the first array with a NaN or an infinity, or None.

    Array by array, flattened (``reshape(-1)``: a view of a contiguous array), with
    ``ar.all_finite``: in float64 one compiled pass each (``compiled.all_finite_vector``),
    which touches less code than numpy's join, ``isfinite`` and reduction did for a small
    curve's arrays (docs/performance.md, issue 13, session 27)."""
    for name, values in named:
        if not ar.all_finite(values.reshape(-1)):
            return name
    return None


def polyline_document(ar: Arithmetic, polyline: Polyline) -> dict[str, Any]:
    return {
        "description": polyline.description,
        "indices": polyline.indices,
        "vertices": coordinates(ar, polyline.vertices),
    }


def bound(value: Any, certified: bool) -> Any:
    """A residual, tolerance or printed residual: a number, or on balls (``certified``) the
    decimal string of its bound (``checks``: they leave the float range from 324 digits on)."""
    if not certified or value is None:
        return value
    return decimal_text(value if isinstance(value, Decimal) else Decimal(repr(float(value))))


def check_document(check: Check, certified: bool = False) -> dict[str, Any]:
    """One check; ``certified``: computed on balls, so that a positive printed residual (a
    rigorous lower bound) certifies the printed formula false, and the bounds are decimal
    strings."""
    erratum = check.erratum
    return {
        "id": check.id,
        "reference": check.reference,
        "claim": check.claim,
        "residual": bound(check.residual, certified),
        "tolerance": bound(check.tolerance, certified),
        "holds": check.holds,
        "per_index": None
        if check.per_index is None
        else {
            "indices": check.per_index.indices,
            "residuals": [None if v is None else decimal_text(v) for v in check.per_index.residuals]
            if isinstance(check.per_index.residuals, list)
            else check.per_index.residuals,
        },
        "erratum": None
        if erratum is None
        else {
            "id": erratum.id,
            "printed": erratum.printed,
            "corrected": erratum.corrected,
            "printed_residual": bound(erratum.printed_residual, certified),
            "certified": _erratum_certified(erratum.printed_residual) if certified else None,
            "link": erratum.link,
        },
        "note": check.note,
    }


def _erratum_certified(printed_residual: float | Decimal | None) -> str:
    """``"false"`` when the printed residual's lower bound is > 0, else ``"undecided"``."""
    return "false" if printed_residual is not None and printed_residual > 0 else "undecided"


def curve_document(curve: Curve) -> dict[str, Any]:
    """The JSON document of ``CurveResponse`` (see app/schemas/curve.py)."""
    ensure_finite(curve)
    ar = curve.arithmetic
    certificate = balls.certificate(ar)
    return {
        "id": curve.id,
        "title": curve.title,
        "reference": curve.reference,
        "parameters": curve.parameters,
        "precision": ar.describe(),
        "indices": curve.polygon.indices,
        "vertices": coordinates(ar, curve.polygon.vertices),
        "companions": {
            name: polyline_document(ar, polyline) for name, polyline in curve.companions.items()
        },
        "constants": {name: number(ar, value) for name, value in curve.constants.items()},
        "checks": [check_document(check, certificate is not None) for check in curve.checks],
        "certified": None if certificate is None else certificate.document(),
    }


def curve_csv(curve: Curve) -> bytes:
    """``curve,index,x,y`` rows: the polygon ``p``, then every companion."""
    ensure_finite(curve)
    ar = curve.arithmetic
    lines = ["curve,index,x,y"]
    for name, polyline in [("p", curve.polygon), *curve.companions.items()]:
        points = coordinates(ar, polyline.vertices)
        if isinstance(points, np.ndarray):
            xs = [repr(v) for v in points[:, 0].tolist()]
            ys = [repr(v) for v in points[:, 1].tolist()]
        else:
            xs, ys = [x for x, _ in points], [y for _, y in points]
        lines.extend(
            f"{name},{i},{x},{y}" for i, x, y in zip(polyline.indices.tolist(), xs, ys, strict=True)
        )
    return ("\n".join(lines) + "\n").encode()


def curve_npy(curve: Curve) -> tuple[bytes, int]:
    """The vertices of ``p`` as a NumPy .npy file ((n, 2) ``<f8``), and the first index.

    Rows are consecutive indices from the first one. float64 only (the request models refuse
    format=npy with precision=mp).
    """
    ensure_finite(curve)
    points = coordinates(curve.arithmetic, curve.polygon.vertices)
    if not isinstance(points, np.ndarray):
        raise NotRepresentableError("format", "format=npy needs precision=float64", "npy")
    indices = curve.polygon.indices
    return npy_bytes(points), int(indices[0]) if len(indices) else 0


def npy_bytes(array: np.ndarray[Any, Any]) -> bytes:
    """``array`` as a NumPy .npy file (``<f8``, version 1.0 header), copied once.

    The header is written on its own, and ``bytes.join`` copies it and the array's buffer into
    the one bytes object that is returned (``np.save`` into a ``BytesIO`` copied the data twice
    and over-allocated while the buffer grew).
    """
    data = np.ascontiguousarray(array, dtype="<f8")
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, np.lib.format.header_data_from_array_1_0(data))
    return b"".join((header.getvalue(), data.reshape(-1).view(np.uint8).data))


def curve_npz(curve: Curve) -> bytes:
    """Every polyline of the curve (``p`` and each companion) with its indices, as one NumPy
    .npz: ``<name>_indices`` (n,) int64 and ``<name>_vertices`` (n, 2) float64. float64 only."""
    ensure_finite(curve)
    arrays: dict[str, np.ndarray[Any, Any]] = {}
    for name, polyline in [("p", curve.polygon), *curve.companions.items()]:
        points = coordinates(curve.arithmetic, polyline.vertices)
        if not isinstance(points, np.ndarray):
            raise NotRepresentableError("format", "format=npz needs precision=float64", "npz")
        arrays[f"{name}_indices"] = np.asarray(polyline.indices, dtype="<i8")
        arrays[f"{name}_vertices"] = points.astype("<f8", copy=False)
    buffer = io.BytesIO()
    np.savez(buffer, allow_pickle=False, **arrays)
    return buffer.getvalue()


def checks_csv(checks: list[Check]) -> bytes:
    """One row per check: id,reference,residual,tolerance,holds,erratum,printed_residual
    (empty cells for null; references quoted)."""

    def cell(value: Any) -> str:
        if value is None:
            return ""
        if isinstance(value, bool):
            return "true" if value else "false"
        if isinstance(value, float):
            return repr(value)
        if isinstance(value, Decimal):
            return decimal_text(value)
        text = str(value)
        return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n') else text

    lines = ["id,reference,residual,tolerance,holds,erratum,printed_residual"]
    for check in checks:
        erratum = check.erratum
        row = [
            check.id,
            check.reference,
            check.residual,
            check.tolerance,
            check.holds,
            None if erratum is None else erratum.id,
            None if erratum is None else erratum.printed_residual,
        ]
        lines.append(",".join(cell(v) for v in row))
    return ("\n".join(lines) + "\n").encode()


def canonical_key(path: str, query: Any) -> str:
    """Path plus the validated query with defaults, keys sorted: one key per distinct answer."""
    return (
        path + "?" + orjson.dumps(query, option=orjson.OPT_SORT_KEYS, default=exact_number).decode()
    )


def study_document(study: Study) -> dict[str, Any]:
    """The JSON document of ``ConvergenceResponse`` (see app/schemas/convergence.py)."""
    info = study.info
    return {
        "id": info.id,
        "title": info.title,
        "reference": info.reference,
        "summary": info.summary,
        "refinement": info.refinement,
        "step_name": info.step_name,
        "parameters": study.parameters,
        "precision": study.arithmetic.describe(),
        "levels": [
            {
                "level": k,
                "step": level.step,
                "vertices": level.vertices,
                "samples": level.samples,
                "errors": level.errors,
                "resolved": {m.id: level.resolved(m.id) for m in info.measures},
            }
            for k, level in enumerate(study.levels)
        ],
        "measures": [
            {
                "id": m.id,
                "description": m.description,
                "expected_order": m.expected_order,
                "observed_order": study.fits[m.id].order,
                "constant": study.fits[m.id].constant,
                "levels_used": list(study.fits[m.id].levels),
                "local_orders": list(study.fits[m.id].local_orders),
            }
            for m in info.measures
        ],
        "checks": [check_document(check) for check in study.checks],
    }


def study_csv(study: Study) -> bytes:
    """``level,<step>,measure,error,resolved`` rows, level by level."""
    lines = [f"level,{study.info.step_name},measure,error,resolved"]
    for k, level in enumerate(study.levels):
        for measure in study.info.measures:
            error = level.errors.get(measure.id)
            shown = "" if error is None else repr(error)
            resolved = "true" if level.resolved(measure.id) else "false"
            lines.append(f"{k},{level.step!r},{measure.id},{shown},{resolved}")
    return ("\n".join(lines) + "\n").encode()
