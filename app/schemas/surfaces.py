"""Request and response models of /surfaces (documentation and validation only)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, Field, field_validator

from app.schemas.common import StrictModel, normalized_selection
from app.schemas.curve import CheckModel, Coordinate, ParameterValue, PrecisionInfo

SURFACES_DESCRIPTION = """\
A discrete surface of revolution (eq. (15)): the meridian polygon of a discretization rotated
about the x-axis in steps of π/m, with its Gauss image, the mixed-area curvatures K = A(n)/A(f)
and H = −A(f,n)/A(f) (Bobenko–Pottmann–Wallner) on every face, and the planarity of every face.

Surfaces: `catenoid` (meridian: the discrete hyperbolic cosine p of `discretization`, default
`d4b`; Gauss image: the discretization's own `gauss_image` companion (d4b: the circumscribed m of
Theorem 8; d2b: the inscribed n) or, with `gauss_image=circumscribed`, the polygon tangent to the
unit circle with edges parallel to p, built from p on i_min − 1 .. i_max + 1); `pseudosphere`
(meridian: the discrete tractrix, Gauss image n of (18); Theorem 7); `catenoid-gauss-image`
and `pseudosphere-gauss-image`: the Gauss image meshes, with the same per-face K and H.

Layout: vertex (i, j) is number k·columns + j with k = i − i_min; the quad of meridian edge k and
step j is number k·steps + j, with corners (k, j), (k, j+1), (k+1, j+1), (k+1, j). A closed
surface (steps = 2m, the default) has 2m columns, an open one steps + 1.

Formats: `json`; `obj` (quads kept, geometry only); `ply` (ASCII, float64 vertices, per-face
K, H, planarity); `vtu` (VTK XML unstructured grid, K, H and planarity as cell data); `glb`
(glTF 2.0 binary, triangulated, float32, four vertices per face, attributes POSITION, NORMAL,
`_K`, `_H`; three.js's GLTFLoader shows them as `geometry.attributes._k` and `._h`). Besides
the parameters below, every parameter of the chosen discretization is accepted (see GET
/discretizations). Mesh size (meridian vertices × vertices around) is limited by
DCOSH_MAX_MESH_VERTICES (default 10^6).
"""


class SurfaceQuery(StrictModel):
    """The parameters /surfaces adds to those of the discretization."""

    discretization: str = Field("d4b", description="Discretization giving the meridian.")
    m: int = Field(
        16, ge=1, le=1_000_000, description="Rotation step π/m of eq. (15); 2m steps close it."
    )
    steps: int | None = Field(
        None,
        ge=1,
        le=2_000_000,
        description="Rotation steps, 1 <= steps <= 2m (default 2m).",
        json_schema_extra={"x-domain": "1 <= steps <= 2m"},
    )
    gauss_image: Literal["auto", "circumscribed"] = Field(
        "auto",
        description="Catenoid only: `auto` (the discretization's own Gauss image, else the "
        "circumscribed one) or `circumscribed`. The circumscribed one is built from p on "
        "i_min − 1 .. i_max + 1: the discretization's parameters must allow those two indices "
        "too.",
        json_schema_extra={"x-domain": "p defined on i_min − 1 .. i_max + 1 (circumscribed)"},
    )
    format: Literal["json", "obj", "ply", "vtu", "glb"] = Field(
        "json",
        description="`json`; `obj` (quads, no per-face values); `ply` (ASCII, float64, K, H "
        "and planarity as face properties: meshio, trimesh, plyfile); `vtu` (VTK XML, "
        "ParaView: K, H and planarity as cell data); `glb` (glTF binary, float32, for viewers; "
        "a mesh with values beyond float32's range, about 3.4e38, is refused).",
    )
    checks: str = Field(
        "all",
        max_length=4096,
        description="Which checks of the meshes to compute and return: `all` (default), `none`, "
        "`failed`, or a comma-separated list of statement ids (face-planarity, "
        "face-parallelity, equation-17, and vanishing-mean-curvature for catenoids or theorem-7 "
        "for the pseudosphere). A surface has no companions: its response holds the mesh and "
        "its face values.",
    )

    @field_validator("checks", mode="before")
    @classmethod
    def _selection(cls, value: Any) -> str:
        """One canonical spelling (it is part of the cache key and the ETag)."""
        return normalized_selection(value, "checks")


class SurfaceLayout(BaseModel):
    rows: int = Field(description="Meridian vertices.")
    columns: int = Field(description="Vertices around (2m if closed, steps + 1 otherwise).")
    closed: bool
    m: int
    steps: int
    meridian_indices: list[int] = Field(description="Paper index i of each row.")


class SurfaceResponse(BaseModel):
    id: str
    title: str
    reference: str
    mesh: Literal["surface", "gauss_image"]
    discretization: str
    parameters: dict[str, ParameterValue]
    precision: PrecisionInfo
    layout: SurfaceLayout
    vertices: list[tuple[Coordinate, Coordinate, Coordinate]]
    faces: list[tuple[int, int, int, int]]
    face_values: dict[str, list[Coordinate]] = Field(
        description="Per face: K, H (of the surface with respect to its Gauss image) and the "
        "planarity of this mesh."
    )
    checks: list[CheckModel]


class SurfaceEntry(BaseModel):
    id: str
    title: str
    reference: str
    url: str
