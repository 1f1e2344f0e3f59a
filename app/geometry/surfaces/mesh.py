"""Discrete surfaces of revolution, eq. (15): a meridian polygon rotated about the x-axis.

(15) maps (i, j) to R_{jπ/m} (p_i^x, p_i^y, 0), R_θ the rotation about the x-axis by θ. A full
turn takes 2m steps. The mesh here has one vertex per meridian vertex i and angle index j, and
one quad per meridian edge and angle step; every quad is an isosceles trapezoid, hence planar.

Layout: vertex (i, j) has number k·columns + j, k = i − i_min the local meridian index; a closed
mesh (steps = 2m) has 2m columns and its last faces wrap around to column 0, an open one has
steps + 1 columns. The quad of edge k and step j is

    (k, j), (k, j+1), (k+1, j+1), (k+1, j),

which is counter-clockwise seen from outside (normal pointing away from the axis) when the
meridian runs towards +x. A Gauss image mesh uses the same layout, so faces correspond by number.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from app.geometry.errors import DomainError
from app.geometry.precision import Arithmetic, Array


@dataclass(frozen=True)
class MeshLayout:
    """Connectivity of a rotational mesh: the same for a surface and its Gauss image."""

    rows: int
    """Meridian vertices."""
    columns: int
    """Vertices around (2m when closed, steps + 1 otherwise)."""
    m: int
    steps: int
    closed: bool
    faces: np.ndarray[Any, np.dtype[np.int64]]
    """``(F, 4)`` vertex numbers, F = (rows − 1)·steps, face number (k, j) -> k·steps + j."""


def layout(rows: int, m: int, steps: int) -> MeshLayout:
    """Quads of a meridian of ``rows`` vertices rotated in ``steps`` steps of π/m (15)."""
    if m < 1:
        raise DomainError("m", "m >= 1 (the rotation step is π/m)", m)
    if not 1 <= steps <= 2 * m:
        raise DomainError("steps", "1 <= steps <= 2m (2m steps close the surface)", steps)
    if rows < 2:
        raise DomainError("i_max", "i_max >= i_min + 1 (a surface needs a meridian edge)", rows)
    closed = steps == 2 * m
    columns = steps if closed else steps + 1
    k = np.arange(rows - 1, dtype=np.int64)[:, None]
    j = np.arange(steps, dtype=np.int64)[None, :]
    j_next = (j + 1) % columns
    a = k * columns + j
    b = k * columns + j_next
    c = (k + 1) * columns + j_next
    d = (k + 1) * columns + j
    faces = np.stack([a, b, c, d], axis=-1).reshape(-1, 4)
    return MeshLayout(rows, columns, m, steps, closed, faces)


def rotation(ar: Arithmetic, m: int, columns: int) -> tuple[Array, Array]:
    """cos and sin of the angles jπ/m, j = 0 .. columns − 1 (exact at multiples of π/2)."""
    j = np.arange(columns)
    angle = ar.pi * ar.array(j.tolist()) / m
    cos, sin = ar.cos(angle), ar.sin(angle)
    quarter = (2 * j) % m == 0  # jπ/m is a multiple of π/2
    exact_cos = {0: 1, 1: 0, 2: -1, 3: 0}
    exact_sin = {0: 0, 1: 1, 2: 0, 3: -1}
    for index in np.flatnonzero(quarter):
        turn = int((2 * int(index)) // m) % 4
        cos[index], sin[index] = ar.scalar(exact_cos[turn]), ar.scalar(exact_sin[turn])
    return cos, sin


def revolve(ar: Arithmetic, meridian: Array, mesh: MeshLayout) -> Array:
    """Vertices R_{jπ/m}(p_i^x, p_i^y, 0) of (15) in the mesh layout; ``(rows·columns, 3)``."""
    cos, sin = rotation(ar, mesh.m, mesh.columns)
    x = np.repeat(meridian[:, 0], mesh.columns)
    y = np.outer(meridian[:, 1], cos).reshape(-1)
    z = np.outer(meridian[:, 1], sin).reshape(-1)
    return np.stack([x, y, z], axis=1)


def face_vertices(vertices: Array, mesh: MeshLayout) -> Array:
    """The four corners of every face; ``(F, 4, 3)``."""
    return vertices[mesh.faces]


def ring_faces(ar: Arithmetic, start: Array, end: Array, cos: Any, sin: Any) -> Array:
    """One face per meridian edge start_k end_k, between the angles 0 and θ; ``(F, 4, 3)``.

    The corners are (start, 0), (start, θ), (end, θ), (end, 0) in the vertex order of the
    mesh layout; ``cos``/``sin`` are those of θ. Used to evaluate the face-wise statements on
    one ring (every ring of a surface of revolution is congruent).
    """
    zero = ar.zeros(len(start))

    def at(points: Array, c: Any, s: Any) -> Array:
        return np.stack([points[:, 0], points[:, 1] * c, points[:, 1] * s], axis=1)

    one = ar.scalar(1)
    return np.stack(
        [
            at(start, one, zero),
            at(start, cos, sin),
            at(end, cos, sin),
            at(end, one, zero),
        ],
        axis=1,
    )
