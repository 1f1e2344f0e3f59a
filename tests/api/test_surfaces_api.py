"""GET/POST /surfaces/{id}: JSON, and OBJ, PLY, GLB read back with independent readers."""

from __future__ import annotations

import io
import json
import struct

import numpy as np
import plyfile
import pytest
import trimesh
from fastapi.testclient import TestClient

from app.main import create_app
from app.schemas.surfaces import SurfaceResponse
from app.settings import Settings

SMALL = "m=3&i_min=-3&i_max=3&d=0.3"


def _json(client: TestClient, surface: str, query: str) -> dict:
    response = client.get(f"/surfaces/{surface}?{query}")
    assert response.status_code == 200, response.text
    body = response.json()
    SurfaceResponse.model_validate(body)
    return body


@pytest.mark.parametrize(
    ("surface", "claim"),
    [
        ("catenoid", "vanishing-mean-curvature"),
        ("catenoid-gauss-image", "vanishing-mean-curvature"),
        ("pseudosphere", "theorem-7"),
        ("pseudosphere-gauss-image", "theorem-7"),
    ],
)
def test_json_meshes_hold_their_claims(client: TestClient, surface: str, claim: str) -> None:
    body = _json(client, surface, SMALL)
    assert body["layout"] == {
        "rows": 7,
        "columns": 6,
        "closed": True,
        "m": 3,
        "steps": 6,
        "meridian_indices": list(range(-3, 4)),
    }
    assert len(body["vertices"]) == 42 and len(body["faces"]) == 36
    checks = {c["id"]: c for c in body["checks"]}
    assert set(checks) == {"face-planarity", "face-parallelity", "equation-17", claim}
    assert all(c["holds"] for c in checks.values())
    if claim == "theorem-7":
        np.testing.assert_allclose(body["face_values"]["K"], -1.0, rtol=1e-12)
    else:
        H = np.array(body["face_values"]["H"])
        assert np.max(np.abs(H)) < 1e-13


def test_catenoid_vertices_are_the_rotated_d4b_meridian(client: TestClient) -> None:
    body = _json(client, "catenoid", "m=2&i_min=0&i_max=1&h=1&d=0.5")
    curve = client.get("/discretizations/d4b?i_min=0&i_max=1&h=1&d=0.5").json()
    (x0, y0), (x1, y1) = curve["vertices"]
    # 4 columns: angles 0, π/2, π, 3π/2, exact at quarter turns
    assert body["vertices"][:4] == [[x0, y0, 0.0], [x0, 0.0, y0], [x0, -y0, 0.0], [x0, 0.0, -y0]]
    assert body["vertices"][4] == [x1, y1, 0.0]
    gauss = _json(client, "catenoid-gauss-image", "m=2&i_min=0&i_max=1&h=1&d=0.5")
    m0 = curve["companions"]["gauss_image"]["vertices"][0]
    assert gauss["vertices"][0] == [m0[0], m0[1], 0.0]
    assert gauss["face_values"]["K"] == body["face_values"]["K"]


def test_open_sweep_and_d2b_catenoid(client: TestClient) -> None:
    body = _json(client, "catenoid", "discretization=d2b&sequence=remark-13&j=4&m=8&steps=3")
    assert body["layout"]["columns"] == 4 and body["layout"]["closed"] is False
    assert body["discretization"] == "d2b" and body["parameters"]["gauss_image"] == "auto"
    assert all(c["holds"] for c in body["checks"])


def test_circumscribed_gauss_image_of_the_d2b_meridian_is_not_minimal(client: TestClient) -> None:
    body = _json(
        client,
        "catenoid",
        "discretization=d2b&sequence=remark-13&j=6&i_min=-1&i_max=6&m=4&gauss_image=circumscribed",
    )
    checks = {c["id"]: c["holds"] for c in body["checks"]}
    assert checks["vanishing-mean-curvature"] is False and checks["face-parallelity"] is True


def test_mp_json_has_decimal_strings(client: TestClient) -> None:
    body = _json(client, "pseudosphere", "m=2&i_min=0&i_max=2&precision=mp&digits=30")
    assert isinstance(body["vertices"][0][0], str)
    K = [float(k) for k in body["face_values"]["K"]]
    np.testing.assert_allclose(K, -1.0, rtol=1e-25)
    assert all(c["holds"] for c in body["checks"])


def test_obj_keeps_the_quads(client: TestClient) -> None:
    body = _json(client, "catenoid", SMALL)
    response = client.get(f"/surfaces/catenoid?{SMALL}&format=obj")
    assert response.status_code == 200
    assert response.headers["content-type"] == "model/obj"
    assert 'filename="catenoid.obj"' in response.headers["content-disposition"]
    text = response.text
    quads = [line.split()[1:] for line in text.splitlines() if line.startswith("f ")]
    assert all(len(q) == 4 for q in quads)
    np.testing.assert_array_equal(np.array(quads, dtype=int) - 1, body["faces"])
    mesh = trimesh.load(io.StringIO(text), file_type="obj", process=False, maintain_order=True)
    np.testing.assert_array_equal(mesh.vertices, np.array(body["vertices"]))
    assert len(mesh.faces) == 2 * len(body["faces"])  # trimesh splits each quad


def test_ply_has_float64_vertices_and_per_face_k_h(client: TestClient) -> None:
    body = _json(client, "pseudosphere", SMALL)
    response = client.get(f"/surfaces/pseudosphere?{SMALL}&format=ply")
    assert response.status_code == 200
    data = plyfile.PlyData.read(io.BytesIO(response.content))
    assert data.text is True  # ASCII: meshio reads per-face properties only from ASCII PLY
    vertex, face = data["vertex"], data["face"]
    assert vertex["x"].dtype.kind == "f" and vertex["x"].dtype.itemsize == 8
    got = np.stack([vertex["x"], vertex["y"], vertex["z"]], axis=1)
    np.testing.assert_array_equal(got, np.array(body["vertices"]))
    np.testing.assert_array_equal(np.stack(face["vertex_indices"]), body["faces"])
    for name in ("K", "H", "planarity"):
        np.testing.assert_array_equal(face[name], body["face_values"][name])
    loaded = trimesh.load(io.BytesIO(response.content), file_type="ply", process=False)
    np.testing.assert_array_equal(loaded.vertices, got)


def test_glb_is_gltf_2_with_float32_and_custom_attributes(client: TestClient) -> None:
    body = _json(client, "catenoid", SMALL)
    response = client.get(f"/surfaces/catenoid?{SMALL}&format=glb")
    assert response.status_code == 200
    assert response.headers["content-type"] == "model/gltf-binary"
    content = response.content
    magic, version, length = struct.unpack_from("<III", content)
    assert (magic, version, length) == (0x46546C67, 2, len(content))
    chunk_length, chunk_type = struct.unpack_from("<II", content, 12)
    document = json.loads(content[20 : 20 + chunk_length])
    assert chunk_type == 0x4E4F534A and document["asset"]["version"] == "2.0"
    primitive = document["meshes"][0]["primitives"][0]
    assert set(primitive["attributes"]) == {"POSITION", "NORMAL", "_K", "_H"}
    scene = trimesh.load(io.BytesIO(content), file_type="glb", process=False)
    mesh = next(iter(scene.geometry.values()))
    faces = np.array(body["faces"])
    vertices = np.array(body["vertices"])
    # four vertices per face, in face order, as float32
    np.testing.assert_array_equal(mesh.vertices, vertices[faces].reshape(-1, 3).astype(np.float32))
    assert len(mesh.faces) == 2 * len(faces)
    for name in ("K", "H"):
        per_vertex = np.asarray(mesh.vertex_attributes["_" + name]).reshape(-1)
        np.testing.assert_array_equal(
            per_vertex, np.repeat(body["face_values"][name], 4).astype(np.float32)
        )
    # triangles are counter-clockwise around the face normal stored in NORMAL
    normals = np.asarray(mesh.vertex_normals)[::4]
    corners = vertices[faces]
    expected = np.cross(corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 1])
    expected /= np.linalg.norm(expected, axis=1)[:, None]
    np.testing.assert_allclose(normals, expected, atol=1e-6)


def test_post_body_gives_the_same_mesh(client: TestClient) -> None:
    got = client.get("/surfaces/catenoid?discretization=d2b&m=3&j=3").json()
    posted = client.post("/surfaces/catenoid", json={"discretization": "d2b", "m": 3, "j": 3})
    assert posted.status_code == 200 and posted.json() == got
    custom = client.post(
        "/surfaces/catenoid",
        json={"discretization": "d2b", "sequence": "custom", "s": [0, 0.3, 0.6], "format": "ply"},
    )
    assert custom.status_code == 200
    assert plyfile.PlyData.read(io.BytesIO(custom.content))["vertex"].count == 3 * 32


def test_etag_and_304(client: TestClient) -> None:
    first = client.get(f"/surfaces/catenoid?{SMALL}&format=glb")
    etag = first.headers["etag"]
    again = client.get(f"/surfaces/catenoid?{SMALL}&format=glb", headers={"If-None-Match": etag})
    assert again.status_code == 304
    other = client.get(f"/surfaces/catenoid?{SMALL}&format=ply", headers={"If-None-Match": etag})
    assert other.status_code == 200


def test_catalog_lists_the_surfaces(client: TestClient) -> None:
    body = client.get("/surfaces").json()
    assert [s["id"] for s in body] == [
        "catenoid",
        "catenoid-gauss-image",
        "pseudosphere",
        "pseudosphere-gauss-image",
    ]


def _problem(response, status: int = 422) -> dict:
    assert response.status_code == status, response.text
    assert response.headers["content-type"] == "application/problem+json"
    return response.json()


@pytest.mark.parametrize(
    ("query", "parameter", "constraint"),
    [
        ("m=0", "m", "m >= 1"),
        ("m=2&steps=5", "steps", "1 <= steps <= 2m"),
        ("format=stl", "format", "format is one of"),
        ("gauss_image=inscribed", "gauss_image", "gauss_image is one of"),
        ("i_min=2&i_max=2", "i_max", "i_max >= i_min + 1"),
        ("d=2", "d", "0 < d < h"),
        ("m=600&i_min=-500&i_max=500", "m", "meridian vertices × vertices around <= 1000000"),
        ("precision=mp&digits=1000&m=50", "digits", "digits × mesh vertices"),
        ("color=red", "color", "not a parameter of this endpoint"),
        (
            "discretization=d2b&sequence=example-12&gauss_image=circumscribed",
            "gauss_image",
            "i_min − 1",
        ),
        ("h=1e-30&d=1e-31", "format", "float32"),
    ],
)
def test_bad_surface_queries_are_422(
    client: TestClient, query: str, parameter: str, constraint: str
) -> None:
    fmt = "&format=glb" if parameter == "format" and "float32" in constraint else ""
    body = _problem(client.get(f"/surfaces/catenoid?{query}{fmt}"))
    named = {e["parameter"]: e["constraint"] for e in body["errors"]}
    assert parameter in named, body
    assert constraint in named[parameter], body


def test_pseudosphere_needs_a_tractrix(client: TestClient) -> None:
    body = _problem(client.get("/surfaces/pseudosphere?discretization=d2b"))
    assert body["errors"][0]["parameter"] == "discretization"
    body = _problem(client.get("/surfaces/klein-bottle"), 404)
    assert "catenoid" in body["valid"]
    body = _problem(client.get("/surfaces/catenoid?discretization=d9"), 404)
    assert "d4b" in body["valid"]


def test_mesh_limit_comes_from_settings() -> None:
    small = TestClient(create_app(Settings(max_mesh_vertices=100)))
    body = _problem(small.get("/surfaces/catenoid?m=16"))  # 21 × 32 vertices
    assert "<= 100" in body["errors"][0]["constraint"]
    assert small.get("/surfaces/catenoid?m=2&i_min=0&i_max=5").status_code == 200
