"""Mesh files written with numpy and struct only: OBJ, binary PLY and glTF 2.0 binary (GLB).

- **OBJ** (text): ``v x y z`` lines and ``f a b c d`` quads (1-based), the quads kept. OBJ has no
  per-face scalars, so K and H are not in it (they are in PLY, GLB and JSON).
- **PLY** (binary_little_endian 1.0): vertex x, y, z as float64; face ``vertex_indices``
  (uchar count, int32 indices) with float64 properties ``K``, ``H`` and ``planarity``.
- **GLB** (glTF 2.0 binary): triangles (each quad split along its diagonal v0 v2), float32.
  Every face has its own four vertices so that per-face values stay constant on it: attributes
  POSITION, NORMAL (the face's unit normal) and the custom attributes ``_K`` and ``_H`` (SCALAR
  float32; three.js's GLTFLoader exposes them as ``geometry.attributes._k`` and ``._h``, since
  it lower-cases names it does not know), indices uint32.
"""

from __future__ import annotations

import json
import struct
from typing import Any

import numpy as np

from app.geometry.errors import NotRepresentableError

GLB_MAGIC = 0x46546C67  # "glTF"
GLB_JSON = 0x4E4F534A  # "JSON"
GLB_BIN = 0x004E4942  # "BIN\0"
FLOAT = 5126
UNSIGNED_INT = 5125
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963
TRIANGLES = 4
FLOAT32_MAX = float(np.finfo(np.float32).max)


def obj_bytes(
    vertices: Any, faces: np.ndarray[Any, np.dtype[np.int64]], header: list[str]
) -> bytes:
    """Wavefront OBJ: ``vertices`` ``(N, 3)`` float64 or rows of decimal strings (mp)."""
    text = "".join(f"# {line}\n" for line in header)
    if isinstance(vertices, np.ndarray) and vertices.dtype != object:
        coordinates = list(map(repr, vertices.reshape(-1).tolist()))
    else:
        coordinates = [value for row in vertices for value in row]
    text += ("v {} {} {}\n" * (len(coordinates) // 3)).format(*coordinates)
    numbers = list(map(str, (faces + 1).reshape(-1).tolist()))
    text += ("f {} {} {} {}\n" * (len(numbers) // 4)).format(*numbers)
    return text.encode()


def ply_bytes(
    vertices: np.ndarray[Any, np.dtype[np.float64]],
    faces: np.ndarray[Any, np.dtype[np.int64]],
    face_values: dict[str, np.ndarray[Any, np.dtype[np.float64]]],
    comments: list[str],
) -> bytes:
    """Binary little-endian PLY with float64 vertices and float64 per-face properties."""
    header = ["ply", "format binary_little_endian 1.0"]
    header += [f"comment {c}" for c in comments]
    header += [
        f"element vertex {len(vertices)}",
        "property double x",
        "property double y",
        "property double z",
        f"element face {len(faces)}",
        "property list uchar int vertex_indices",
    ]
    header += [f"property double {name}" for name in face_values]
    header.append("end_header")
    record = np.dtype(
        [("count", "u1"), ("indices", "<i4", (4,))] + [(name, "<f8") for name in face_values]
    )
    rows = np.empty(len(faces), dtype=record)
    rows["count"] = 4
    rows["indices"] = faces
    for name, values in face_values.items():
        rows[name] = values
    body = np.ascontiguousarray(vertices, dtype="<f8").tobytes() + rows.tobytes()
    return ("\n".join(header) + "\n").encode("ascii") + body


def _float32(name: str, values: np.ndarray[Any, np.dtype[np.float64]]) -> np.ndarray[Any, Any]:
    if values.size and float(np.max(np.abs(values))) > FLOAT32_MAX:
        raise NotRepresentableError(
            "format",
            "values within float32 for format=glb",
            "glb",
            f"{name} exceeds the float32 range; use format=ply (float64) or json",
        )
    return values.astype("<f4")


def glb_bytes(
    vertices: np.ndarray[Any, np.dtype[np.float64]],
    faces: np.ndarray[Any, np.dtype[np.int64]],
    face_values: dict[str, np.ndarray[Any, np.dtype[np.float64]]],
    extras: dict[str, Any],
) -> bytes:
    """glTF 2.0 binary: per-face vertices, triangulated, float32, custom ``_NAME`` attributes."""
    corners = vertices[faces]  # (F, 4, 3)
    normal = np.cross(corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 1])
    length = np.linalg.norm(normal, axis=1)
    normal = np.where(
        length[:, None] > 0, normal / np.where(length > 0, length, 1)[:, None], [0.0, 0.0, 1.0]
    )
    positions = _float32("vertices", corners.reshape(-1, 3))
    normals = normal.repeat(4, axis=0).astype("<f4")
    count = len(faces)
    base = (4 * np.arange(count, dtype=np.uint32))[:, None]
    indices = (base + np.array([0, 1, 2, 0, 2, 3], dtype=np.uint32)).reshape(-1).astype("<u4")
    scalars = {
        "_" + name: _float32(name, np.repeat(values, 4)) for name, values in face_values.items()
    }
    blobs = [positions, normals, *scalars.values(), indices]
    views, accessors, chunks, offset = [], [], [], 0
    for k, blob in enumerate(blobs):
        data = blob.tobytes()
        is_index = k == len(blobs) - 1
        views.append(
            {
                "buffer": 0,
                "byteOffset": offset,
                "byteLength": len(data),
                "target": ELEMENT_ARRAY_BUFFER if is_index else ARRAY_BUFFER,
            }
        )
        chunks.append(data)
        offset += len(data)  # every blob is a multiple of 4 bytes
        accessor: dict[str, Any] = {
            "bufferView": k,
            "componentType": UNSIGNED_INT if is_index else FLOAT,
            "count": len(blob),
            "type": "VEC3" if blob.ndim == 2 else "SCALAR",
        }
        if k == 0:
            accessor["min"] = [float(v) for v in positions.min(axis=0)] if count else [0, 0, 0]
            accessor["max"] = [float(v) for v in positions.max(axis=0)] if count else [0, 0, 0]
        accessors.append(accessor)
    attributes = {"POSITION": 0, "NORMAL": 1}
    attributes.update({name: 2 + k for k, name in enumerate(scalars)})
    document = {
        "asset": {"version": "2.0", "generator": "dcosh"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": extras.get("id", "surface")}],
        "meshes": [
            {
                "primitives": [
                    {"attributes": attributes, "indices": len(blobs) - 1, "mode": TRIANGLES}
                ],
                "extras": extras,
            }
        ],
        "buffers": [{"byteLength": offset}],
        "bufferViews": views,
        "accessors": accessors,
    }
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary = b"".join(chunks)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return b"".join(
        [
            struct.pack("<III", GLB_MAGIC, 2, total),
            struct.pack("<II", len(text), GLB_JSON),
            text,
            struct.pack("<II", len(binary), GLB_BIN),
            binary,
        ]
    )
