"""Surfaces as the API serves them: which meridian and Gauss image, limits, documents, files.

The geometry is in ``app.geometry.surfaces.rotational``; this module picks the polygons from a
discretization's curve (through the registry, so any discretization with the right companions
works; the curve is computed with those companions only and no checks), enforces the mesh
budget before any work, and encodes JSON, OBJ, PLY or GLB as bytes.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from app.errors import UnknownIdError
from app.geometry import gauss_image
from app.geometry.curve import Selection
from app.geometry.errors import DomainError, NotRepresentableError
from app.geometry.precision import Arithmetic, MultiPrecision
from app.geometry.surfaces import rotational as rotational_surface
from app.geometry.tolerances import LOCAL_STEPS
from app.limits import enforce_mesh, enforce_range, timed_arithmetic
from app.mesh_formats import glb_bytes, obj_bytes, ply_bytes, vtu_bytes
from app.registry import DISCRETIZATIONS
from app.responses import check_document, encode_json, not_finite
from app.schemas.common import CurveQuery
from app.schemas.surfaces import SurfaceQuery
from app.services.selection import chosen
from app.settings import Settings


@dataclass(frozen=True)
class SurfaceKind:
    id: str
    title: str
    reference: str
    meridian: str
    """``p`` (the discrete hyperbolic cosine) or ``tractrix``."""
    mesh: str
    """``surface`` or ``gauss_image``: which of the two meshes the response holds."""


KINDS = {
    kind.id: kind
    for kind in (
        SurfaceKind(
            "catenoid",
            "Discrete catenoid",
            "eq. (15); Theorem 8; (D2b); Theorem 11",
            "p",
            "surface",
        ),
        SurfaceKind(
            "catenoid-gauss-image",
            "Gauss image of the discrete catenoid",
            "Theorem 8, eq. (20); (D2b)",
            "p",
            "gauss_image",
        ),
        SurfaceKind(
            "pseudosphere",
            "Discrete pseudosphere",
            "Section 5, Theorem 7",
            "tractrix",
            "surface",
        ),
        SurfaceKind(
            "pseudosphere-gauss-image",
            "Gauss image of the discrete pseudosphere",
            "Section 5, eq. (18), Theorem 7",
            "tractrix",
            "gauss_image",
        ),
    )
}

MEDIA_TYPES = {
    "json": "application/json",
    "obj": "model/obj",
    "ply": "application/octet-stream",
    "vtu": "application/xml",
    "glb": "model/gltf-binary",
}


@dataclass(frozen=True)
class SurfaceResult:
    kind: SurfaceKind
    discretization: str
    parameters: dict[str, Any]
    meridian_indices: np.ndarray[Any, np.dtype[np.int64]]
    surface: rotational_surface.RotationalSurface


def kind_of(identifier: str) -> SurfaceKind:
    try:
        return KINDS[identifier]
    except KeyError:
        raise UnknownIdError("surface", identifier, sorted(KINDS)) from None


#: The request parameters that place a discretization's meridian where a face of its surface
#: can degenerate (zero area: a meridian edge on or across the axis, or of zero length): (D1)'s
#: free start heights. Other meridians stay off the axis; there the range is named.
MERIDIAN_PARAMETERS = {"d1": "y0"}
DEGENERATE_MERIDIAN = {
    "d1": "y0, y1 give a meridian p with every face of positive area (no edge of p on or "
    "across the axis p^y = 0, none of zero length)",
}


def degenerate_meridian(
    discretization: str, parameters: dict[str, Any], i_min: int, steps: int, error: DomainError
) -> DomainError:
    """The geometry's refusal of a zero-area face (``meridian``, a face number) as the request
    parameter that causes it, with the meridian edge of that face."""
    face = int(error.value)
    start = i_min + face // max(steps, 1)
    where = f"face {face}, the meridian edge p_{start} p_{start + 1} revolved,"
    name = MERIDIAN_PARAMETERS.get(discretization, "i_min")
    constraint = DEGENERATE_MERIDIAN.get(
        discretization,
        "i_min .. i_max give a meridian with every face of positive area (no edge on or "
        "across the axis, none of zero length)",
    )
    return DomainError(name, constraint, parameters.get(name), f"{where} has no area")


@dataclass(frozen=True)
class SurfacePlan:
    """A surface request checked and charged (``admit``), not yet computed (``build``)."""

    kind: SurfaceKind
    surface: SurfaceQuery
    curve_query: CurveQuery
    arguments: dict[str, Any]
    """The meridian's arguments (one index wider on each side for a circumscribed image)."""
    circumscribed: bool
    wanted: frozenset[str] | None
    steps: int


def admit(
    kind: SurfaceKind, surface: SurfaceQuery, curve_query: CurveQuery, settings: Settings
) -> SurfacePlan:
    """Validate the mesh, check its budgets and charge its estimated cost; no geometry yet."""
    claim = "constant-curvature" if kind.meridian == "tractrix" else "minimal"
    wanted = chosen("checks", surface.checks, (s.id for s in rotational_surface.STATEMENTS[claim]))
    entry = DISCRETIZATIONS[surface.discretization]
    arguments = curve_query.core_arguments()
    i_min, i_max = arguments["i_min"], arguments["i_max"]
    m = surface.m
    steps = surface.steps if surface.steps is not None else 2 * m
    if steps > 2 * m:
        raise DomainError("steps", "1 <= steps <= 2m (2m steps close the surface)", steps)
    if i_max <= i_min:
        raise DomainError("i_max", "i_max >= i_min + 1 (a surface needs a meridian edge)", i_max)
    columns = steps if steps == 2 * m else steps + 1
    enforce_mesh(settings, i_max - i_min + 1, columns, curve_query.precision, curve_query.digits)
    circumscribed = kind.meridian == "p" and (
        surface.gauss_image == "circumscribed" or "gauss_image" not in entry.info.companions
    )
    if circumscribed:
        arguments = {**arguments, "i_min": i_min - 1, "i_max": i_max + 1}
    method = arguments.get("method", "construction")
    enforce_range(
        settings,
        arguments["i_min"],
        arguments["i_max"],
        method,
        curve_query.precision,
        curve_query.digits,
        kind=entry.info.id,
    )
    if kind.meridian == "tractrix" and not {"tractrix", "tractrix_gauss_image"} <= set(
        entry.info.companions
    ):
        with_tractrix = [
            k for k, e in DISCRETIZATIONS.items() if "tractrix_gauss_image" in e.info.companions
        ]
        raise DomainError(
            "discretization",
            "a discretization with a tractrix and its Gauss image: " + ", ".join(with_tractrix),
            surface.discretization,
        )
    return SurfacePlan(kind, surface, curve_query, arguments, circumscribed, wanted, steps)


def build(plan: SurfacePlan, settings: Settings) -> SurfaceResult:
    """Compute an admitted surface: the meridian curve, then the meshes and their checks."""
    kind, surface, curve_query = plan.kind, plan.surface, plan.curve_query
    entry = DISCRETIZATIONS[surface.discretization]
    arguments, circumscribed, m, steps = plan.arguments, plan.circumscribed, surface.m, plan.steps
    given = curve_query.core_arguments()
    i_min, i_max = given["i_min"], given["i_max"]
    ar = timed_arithmetic(settings, curve_query.precision, curve_query.digits)
    if kind.meridian == "tractrix":
        needed = frozenset({"tractrix", "tractrix_gauss_image"})
    else:
        needed = frozenset() if circumscribed else frozenset({"gauss_image"})
    try:
        curve = entry.compute(ar, **arguments, selection=Selection(frozenset(), needed))
    except DomainError as error:
        if not circumscribed:
            raise
        raise DomainError(
            "gauss_image",
            "the circumscribed Gauss image needs the meridian on i_min − 1 .. i_max + 1",
            surface.gauss_image,
            f"{surface.discretization} refuses that range: {error}",
        ) from None
    if kind.meridian == "tractrix":
        meridian = curve.companions["tractrix"].vertices
        gauss = curve.companions["tractrix_gauss_image"].vertices
        h = ar.scalar(curve.parameters["h"])
        claim, K, resolved = "constant-curvature", -1 / (h * h), "inscribed (18)"
    elif circumscribed:
        meridian = curve.polygon.vertices[1:-1]
        gauss = gauss_image.circumscribed(ar, curve.polygon.vertices)
        claim, K, resolved = "minimal", None, "circumscribed"
    else:
        meridian = curve.polygon.vertices
        gauss = curve.companions["gauss_image"].vertices
        claim, K, resolved = "minimal", None, "auto"
    recursion = max(abs(i_min), abs(i_max)) + 2
    try:
        built = rotational_surface.build(
            ar,
            meridian,
            gauss,
            m,
            steps,
            claim,  # type: ignore[arg-type]
            K,
            ar.tolerance(max(recursion, LOCAL_STEPS)),
        )
    except DomainError as error:
        if error.parameter != "meridian":
            raise
        raise degenerate_meridian(
            surface.discretization, curve.parameters, i_min, steps, error
        ) from None
    selected = Selection(plan.wanted, failed_only=surface.checks == "failed")
    built = replace(built, checks=selected.keep(built.checks))
    parameters = {**curve.parameters, "i_min": i_min, "i_max": i_max}
    parameters.update({"m": m, "steps": steps, "gauss_image": resolved})
    return SurfaceResult(
        kind,
        surface.discretization,
        parameters,
        np.arange(i_min, i_max + 1, dtype=np.int64),
        built,
    )


def compute(
    kind: SurfaceKind,
    surface: SurfaceQuery,
    curve_query: CurveQuery,
    settings: Settings,
) -> SurfaceResult:
    """Check the budgets, compute the meridian curve, then the meshes and their checks."""
    return build(admit(kind, surface, curve_query, settings), settings)


def _vertices(result: SurfaceResult) -> Any:
    built = result.surface
    return built.surface if result.kind.mesh == "surface" else built.gauss_image


def _planarity(result: SurfaceResult) -> Any:
    built = result.surface
    return built.surface_planarity if result.kind.mesh == "surface" else built.gauss_planarity


def _floats(ar: Arithmetic, values: Any) -> np.ndarray[Any, np.dtype[np.float64]]:
    return ar.to_floats(values.reshape(-1)).reshape(values.shape)


def _strings(ar: Arithmetic, values: Any) -> Any:
    assert isinstance(ar, MultiPrecision)
    return np.array(ar.to_strings(values.reshape(-1)), dtype=object).reshape(values.shape)


def _ensure_finite(ar: Arithmetic, *arrays: Any) -> None:
    if not_finite(ar, [("mesh", values) for values in arrays]) is not None:
        raise NotRepresentableError(
            "precision",
            "values representable in the chosen precision",
            ar.mode,
            "the mesh leaves the float64 range; use precision=mp or a shorter range",
        )


def document(result: SurfaceResult) -> dict[str, Any]:
    """The JSON document (``SurfaceResponse``)."""
    built = result.surface
    ar = built.arithmetic
    vertices = _vertices(result)
    values = {"K": built.curvature.K, "H": built.curvature.H, "planarity": _planarity(result)}
    _ensure_finite(ar, vertices, *values.values())
    if isinstance(ar, MultiPrecision):
        shown_vertices: Any = _strings(ar, vertices).tolist()
        shown_values: dict[str, Any] = {k: _strings(ar, v).tolist() for k, v in values.items()}
    else:
        shown_vertices = np.ascontiguousarray(vertices, dtype=np.float64)
        shown_values = {k: np.asarray(v, dtype=np.float64) for k, v in values.items()}
    layout = built.layout
    return {
        "id": result.kind.id,
        "title": result.kind.title,
        "reference": result.kind.reference,
        "mesh": result.kind.mesh,
        "discretization": result.discretization,
        "parameters": result.parameters,
        "precision": ar.describe(),
        "layout": {
            "rows": layout.rows,
            "columns": layout.columns,
            "closed": layout.closed,
            "m": layout.m,
            "steps": layout.steps,
            "meridian_indices": result.meridian_indices,
        },
        "vertices": shown_vertices,
        "faces": layout.faces,
        "face_values": shown_values,
        "checks": [check_document(check) for check in built.checks],
    }


def _comments(result: SurfaceResult) -> list[str]:
    parameters = ", ".join(f"{k}={v}" for k, v in result.parameters.items() if k != "s")
    return [
        f"{result.kind.title} ({result.kind.mesh}), {result.kind.reference}",
        f"discretization={result.discretization}, {parameters}",
        "faces: quads (k, j), (k, j+1), (k+1, j+1), (k+1, j); K, H per face w.r.t. the "
        "Gauss image (mixed areas)",
    ]


def encoded(result: SurfaceResult, file_format: str) -> tuple[bytes, str, dict[str, str]]:
    """(body, media type, headers) of the surface in ``file_format`` (json, obj, ply, vtu, glb);
    files carry a download file name."""
    if file_format == "json":
        return encode_json(document(result)), "application/json", {}
    built = result.surface
    ar = built.arithmetic
    vertices = _vertices(result)
    values = {"K": built.curvature.K, "H": built.curvature.H, "planarity": _planarity(result)}
    _ensure_finite(ar, vertices, *values.values())
    faces = built.layout.faces
    if file_format == "obj":
        shown = _strings(ar, vertices).tolist() if isinstance(ar, MultiPrecision) else vertices
        body = obj_bytes(shown, faces, _comments(result))
    elif file_format in ("ply", "vtu"):
        floats = {k: _floats(ar, v) for k, v in values.items()}
        write = ply_bytes if file_format == "ply" else vtu_bytes
        body = write(_floats(ar, vertices), faces, floats, _comments(result))
    else:
        floats = {k: _floats(ar, v) for k, v in values.items() if k in ("K", "H")}
        extras = {"id": result.kind.id, "parameters": result.parameters}
        body = glb_bytes(_floats(ar, vertices), faces, floats, extras)
    name = f"{result.kind.id}.{file_format}"
    return body, MEDIA_TYPES[file_format], {"Content-Disposition": f'attachment; filename="{name}"'}
