"""Mesh files written with numpy and struct only: OBJ, PLY, VTU and glTF 2.0 binary (GLB).

- **OBJ** (text): ``v x y z`` lines and ``f a b c d`` quads (1-based), the quads kept. OBJ has no
  per-face scalars, so K and H are not in it (they are in PLY, GLB and JSON).
- **PLY** (ascii 1.0): vertex x, y, z as float64; face ``vertex_indices`` (uchar count, int
  indices) with float64 properties ``K``, ``H`` and ``planarity`` (meshio, trimesh and plyfile
  read them).
- **VTU** (VTK XML UnstructuredGrid, ParaView's format): float64 points, quad cells, ``K``,
  ``H`` and ``planarity`` as float64 cell data.
- **GLB** (glTF 2.0 binary): triangles (each quad split along its diagonal v0 v2), float32.
  Every face has its own four vertices so that per-face values stay constant on it: attributes
  POSITION, NORMAL (the face's unit normal) and the custom attributes ``_K`` and ``_H`` (SCALAR
  float32; three.js's GLTFLoader exposes them as ``geometry.attributes._k`` and ``._h``, since
  it lower-cases names it does not know), indices uint32.
"""

from __future__ import annotations

import base64
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
    """ASCII PLY: float64 vertices, quad faces with float64 per-face properties (K, H, …).

    ASCII rather than binary because meshio's binary PLY reader takes a face element's scalar
    properties as stored after all of its lists (PLY stores them row by row), so it cannot read
    K and H from a binary file; every reader (meshio, trimesh, plyfile) reads them from ASCII.
    Numbers are written with ``repr``: they read back bit for bit.
    """
    header = ["ply", "format ascii 1.0"]
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
    lines = ["\n".join(header)]
    points = np.asarray(vertices, dtype=np.float64).reshape(-1).tolist()
    lines.append(("{!r} {!r} {!r}\n" * len(vertices)).format(*points).rstrip("\n"))
    columns = [np.asarray(faces, dtype=np.int64).tolist()]
    columns += [np.asarray(v, dtype=np.float64).tolist() for v in face_values.values()]
    rows = []
    for face, *scalars in zip(*columns, strict=True):
        rows.append(" ".join(["4", *map(str, face), *map(repr, scalars)]))
    lines.append("\n".join(rows))
    return ("\n".join(line for line in lines if line) + "\n").encode("ascii")


VTK_QUAD = 9


def _vtu_array(name: str, data: np.ndarray[Any, Any], vtk_type: str, components: int) -> str:
    """A binary DataArray: base64 of a UInt64 byte count, then the raw little-endian data."""
    raw = np.ascontiguousarray(data).tobytes()
    encoded = base64.b64encode(struct.pack("<Q", len(raw)) + raw).decode("ascii")
    # scalars without NumberOfComponents: readers then give them as a flat (n,) array
    components_attribute = f' NumberOfComponents="{components}"' if components > 1 else ""
    return (
        f'<DataArray type="{vtk_type}" Name="{name}"{components_attribute} '
        f'format="binary">{encoded}</DataArray>'
    )


def vtu_bytes(
    vertices: np.ndarray[Any, np.dtype[np.float64]],
    faces: np.ndarray[Any, np.dtype[np.int64]],
    face_values: dict[str, np.ndarray[Any, np.dtype[np.float64]]],
    comments: list[str],
) -> bytes:
    """VTK XML UnstructuredGrid (.vtu), ParaView's own format: float64 points, quad cells,
    every face value (K, H, planarity) as float64 cell data. Binary arrays (base64 with a
    UInt64 length header), no compression."""
    count = len(faces)
    connectivity = np.asarray(faces, dtype="<i8").reshape(-1)
    offsets = 4 * np.arange(1, count + 1, dtype="<i8")
    types = np.full(count, VTK_QUAD, dtype="u1")
    cell_data = "".join(
        _vtu_array(name, np.asarray(values, dtype="<f8"), "Float64", 1)
        for name, values in face_values.items()
    )
    note = "".join(f"<!-- {c.replace('--', '-')} -->" for c in comments)
    text = (
        '<?xml version="1.0"?>'
        f"{note}"
        '<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" '
        'header_type="UInt64">'
        "<UnstructuredGrid>"
        f'<Piece NumberOfPoints="{len(vertices)}" NumberOfCells="{count}">'
        "<Points>"
        + _vtu_array("Points", np.asarray(vertices, dtype="<f8"), "Float64", 3)
        + "</Points><Cells>"
        + _vtu_array("connectivity", connectivity, "Int64", 1)
        + _vtu_array("offsets", offsets, "Int64", 1)
        + _vtu_array("types", types, "UInt8", 1)
        + "</Cells>"
        + f'<CellData Scalars="{next(iter(face_values), "")}">{cell_data}</CellData>'
        + "</Piece></UnstructuredGrid></VTKFile>\n"
    )
    return text.encode("ascii")


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
    # float32 first: the normals of larger coordinates would overflow float64 before the check
    positions = _float32("vertices", corners.reshape(-1, 3))
    normal = np.cross(corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 1])
    length = np.linalg.norm(normal, axis=1)
    normal = np.where(
        length[:, None] > 0, normal / np.where(length > 0, length, 1)[:, None], [0.0, 0.0, 1.0]
    )
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
