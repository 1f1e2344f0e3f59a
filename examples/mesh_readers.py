"""A discrete catenoid read by meshio (PLY and VTU) and trimesh (PLY), with K and H per face."""

from __future__ import annotations

import io
import sys
import tempfile
from pathlib import Path
from typing import Any

import meshio
import numpy as np
import trimesh
from _http import DEFAULT_URL, get

QUERY = "m=8&i_min=-4&i_max=4"


def main(base: str = DEFAULT_URL) -> dict[str, Any]:
    found: dict[str, Any] = {}
    with tempfile.TemporaryDirectory() as folder:
        for fmt in ("ply", "vtu"):
            status, _, body = get(f"{base}/surfaces/catenoid?{QUERY}&format={fmt}")
            assert status == 200, status
            path = Path(folder) / f"catenoid.{fmt}"
            path.write_bytes(body)  # ParaView opens catenoid.vtu as it is
            mesh = meshio.read(path)
            found[fmt] = {
                "points": mesh.points,
                "quads": mesh.cells_dict["quad"],
                "K": np.ravel(mesh.cell_data["K"][0]),
                "H": np.ravel(mesh.cell_data["H"][0]),
            }
            print(
                f"{fmt}: {len(mesh.points)} points, {len(mesh.cells_dict['quad'])} quads, "
                f"mean curvature up to {np.abs(found[fmt]['H']).max():.2e}"
            )
        # trimesh splits quads into triangles; the per-face properties of the file stay in its
        # raw PLY data
        loaded = trimesh.load(
            io.BytesIO(get(f"{base}/surfaces/catenoid?{QUERY}&format=ply")[2]),
            file_type="ply",
            process=False,
        )
        raw = loaded.metadata["_ply_raw"]["face"]["data"]
        found["trimesh"] = {"triangles": len(loaded.faces), "K": np.ravel(raw["K"])}
    return found


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_URL)
