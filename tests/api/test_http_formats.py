"""Interop: every mesh format read back by the libraries people use (meshio, trimesh, plyfile)
with K and H; VTU for ParaView; curves as .npz with every polyline; checks as CSV."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import meshio
import numpy as np
import plyfile
import pytest
import trimesh
from fastapi.testclient import TestClient

QUERY = "m=6&i_min=0&i_max=6"


def mesh_json(client: TestClient, surface: str) -> dict:
    response = client.get(f"/surfaces/{surface}?{QUERY}")
    assert response.status_code == 200
    return response.json()


@pytest.mark.parametrize("surface", ["catenoid", "pseudosphere"])
@pytest.mark.parametrize("fmt", ["ply", "vtu"])
def test_meshio_reads_k_and_h_as_cell_data(
    client: TestClient, tmp_path: Path, surface: str, fmt: str
) -> None:
    body = mesh_json(client, surface)
    response = client.get(f"/surfaces/{surface}?{QUERY}&format={fmt}")
    assert response.status_code == 200
    path = tmp_path / f"{surface}.{fmt}"
    path.write_bytes(response.content)
    mesh = meshio.read(path)
    np.testing.assert_array_equal(mesh.points, np.array(body["vertices"]))
    assert [block.type for block in mesh.cells] == ["quad"]
    np.testing.assert_array_equal(mesh.cells[0].data, np.array(body["faces"]))
    for name in ("K", "H", "planarity"):
        np.testing.assert_array_equal(
            np.ravel(mesh.cell_data[name][0]), np.array(body["face_values"][name])
        )


def test_vtu_is_a_vtk_unstructured_grid_for_paraview(client: TestClient) -> None:
    response = client.get(f"/surfaces/catenoid?{QUERY}&format=vtu")
    assert response.headers["content-disposition"] == 'attachment; filename="catenoid.vtu"'
    text = response.text
    assert '<VTKFile type="UnstructuredGrid"' in text and 'byte_order="LittleEndian"' in text
    assert '<CellData Scalars="K">' in text


def test_ply_reads_in_plyfile_and_trimesh_with_k_and_h(client: TestClient) -> None:
    body = mesh_json(client, "catenoid")
    content = client.get(f"/surfaces/catenoid?{QUERY}&format=ply").content
    face = plyfile.PlyData.read(io.BytesIO(content))["face"]
    loaded = trimesh.load(io.BytesIO(content), file_type="ply", process=False)
    raw = loaded.metadata["_ply_raw"]["face"]["data"]  # where trimesh keeps face properties
    for name in ("K", "H"):
        expected = np.array(body["face_values"][name])
        np.testing.assert_array_equal(face[name], expected)
        np.testing.assert_array_equal(np.ravel(raw[name]), expected)


def test_npz_bundles_every_polyline_with_its_indices(client: TestClient) -> None:
    body = client.get("/discretizations/d4b").json()
    archive = np.load(io.BytesIO(client.get("/discretizations/d4b?format=npz").content))
    np.testing.assert_array_equal(archive["p_indices"], body["indices"])
    np.testing.assert_array_equal(archive["p_vertices"], body["vertices"])
    for name, polyline in body["companions"].items():
        np.testing.assert_array_equal(archive[f"{name}_indices"], polyline["indices"])
        np.testing.assert_array_equal(archive[f"{name}_vertices"], polyline["vertices"])
    assert set(archive.files) == {
        f"{name}_{part}" for name in ["p", *body["companions"]] for part in ("indices", "vertices")
    }
    refused = client.get("/discretizations/d4b?format=npz&precision=mp")
    assert refused.status_code == 422


def test_checks_as_csv(client: TestClient) -> None:
    body = client.get("/discretizations/d4b").json()
    response = client.get("/discretizations/d4b?format=checks-csv")
    assert response.headers["content-type"].startswith("text/csv")
    rows = list(csv.DictReader(io.StringIO(response.text)))
    assert [r["id"] for r in rows] == [c["id"] for c in body["checks"]]
    for row, check in zip(rows, body["checks"], strict=True):
        assert row["reference"] == check["reference"]
        assert row["holds"] == {True: "true", False: "false", None: ""}[check["holds"]]
        if check["residual"] is not None:
            assert float(row["residual"]) == check["residual"]
        assert row["erratum"] == (check["erratum"]["id"] if check["erratum"] else "")
