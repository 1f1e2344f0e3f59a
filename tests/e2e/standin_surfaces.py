"""A stand-in for GET /surfaces/{id}, used by the browser tests only while the service has no
surfaces endpoint (issue 5 adds the real one; the tests then use it instead).

It serves the contract the explorer expects (design.md, issue 5): glTF 2.0 binary, triangulated,
float32 positions, per-face `_K` and `_H` custom attributes (repeated on the three corners of
each triangle). The mesh is the (D4b) polygon rotated about the x-axis; the `_K` and `_H`
values are SYNTHETIC (K = −1 − row/rows, H = column/columns): they exist to test that the page
reads and colours the attributes, not to be curvatures.
"""

from __future__ import annotations

import json
import struct
from typing import Annotated, Literal

import numpy as np
from fastapi import APIRouter, FastAPI, Path, Query, Response

from app.geometry.d4b import discretization as d4b
from app.geometry.precision import Float64

SURFACES = ("catenoid", "pseudosphere")


def revolve(meridian: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Triangles (unwelded) of the meridian rotated about the x-axis in m steps, with the
    (row, column) of the quad each triangle belongs to."""
    angles = np.linspace(0, 2 * np.pi, m + 1)
    x = np.repeat(meridian[:, 0:1], m + 1, axis=1)
    y = meridian[:, 1:2] * np.cos(angles)
    z = meridian[:, 1:2] * np.sin(angles)
    grid = np.stack([x, y, z], axis=-1)  # (rows + 1, m + 1, 3)
    a, b = grid[:-1, :-1], grid[1:, :-1]
    c, d = grid[1:, 1:], grid[:-1, 1:]
    triangles = np.concatenate([np.stack([a, b, c], 2), np.stack([a, c, d], 2)], axis=1)
    rows, columns = np.meshgrid(np.arange(len(meridian) - 1), np.arange(m), indexing="ij")
    row = np.concatenate([rows, rows], axis=1)
    column = np.concatenate([columns, columns], axis=1)
    return triangles.reshape(-1, 3, 3), row.reshape(-1), column.reshape(-1)


def glb(triangles: np.ndarray, K: np.ndarray, H: np.ndarray) -> bytes:
    """A minimal glTF 2.0 binary: one triangle-list primitive with POSITION, _K and _H."""
    positions = triangles.reshape(-1, 3).astype("<f4")
    k = np.repeat(K, 3).astype("<f4")
    h = np.repeat(H, 3).astype("<f4")
    blobs = [positions.tobytes(), k.tobytes(), h.tobytes()]
    offsets = np.cumsum([0] + [len(b) for b in blobs])
    count = len(positions)
    document = {
        "asset": {"version": "2.0", "generator": "dcosh e2e stand-in"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "_K": 1, "_H": 2}, "mode": 4}]}],
        "buffers": [{"byteLength": int(offsets[-1])}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": int(offsets[i]), "byteLength": len(blobs[i])}
            for i in range(3)
        ],
        "accessors": [
            {
                "bufferView": 0,
                "componentType": 5126,
                "count": count,
                "type": "VEC3",
                "min": positions.min(axis=0).tolist(),
                "max": positions.max(axis=0).tolist(),
            },
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": count, "type": "SCALAR"},
        ],
    }
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    binary = b"".join(blobs)
    binary += b"\0" * (-len(binary) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (
        struct.pack("<4sII", b"glTF", 2, total)
        + struct.pack("<I4s", len(text), b"JSON")
        + text
        + struct.pack("<I4s", len(binary), b"BIN\0")
        + binary
    )


def synthetic_values(row: np.ndarray, column: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    rows, columns = row.max() + 1, column.max() + 1
    return -1 - row / rows, column / columns


def install_standin(app: FastAPI) -> None:
    router = APIRouter(tags=["surfaces"])

    @router.get(
        "/surfaces/{surface_id}",
        summary="Stand-in surface (tests only)",
        description="Synthetic K and H; see tests/e2e/standin_surfaces.py.",
    )
    def surface(
        surface_id: Annotated[Literal["catenoid", "pseudosphere"], Path()],
        h: Annotated[float, Query(gt=0)] = 1.0,
        d: Annotated[float, Query(gt=0)] = 0.1,
        i_min: int = -10,
        i_max: int = 10,
        m: Annotated[int, Query(ge=3, le=256)] = 24,
        format: Literal["glb"] = "glb",
    ) -> Response:
        curve = d4b.compute(Float64(), h, d, None, i_min, i_max)
        meridian = curve.polygon if surface_id == "catenoid" else curve.companions["tractrix"]
        triangles, row, column = revolve(np.asarray(meridian.vertices, dtype=np.float64), m)
        K, H = synthetic_values(row, column)
        return Response(glb(triangles, K, H), media_type="model/gltf-binary")

    app.include_router(router)
