"""A discrete hyperbolic cosine into numpy: JSON, .npy, CSV and .npz."""

from __future__ import annotations

import io
import sys
from typing import Any

import numpy as np
from _http import DEFAULT_URL, get, get_json

QUERY = "h=1&d=0.1&i_min=-10&i_max=10"


def main(base: str = DEFAULT_URL) -> dict[str, Any]:
    url = f"{base}/discretizations/d4b?{QUERY}"
    curve = get_json(url)
    vertices = np.array(curve["vertices"])  # (21, 2) float64: JSON numbers in float64 mode

    status, headers, body = get(url + "&format=npy")
    assert status == 200, status
    from_npy = np.load(io.BytesIO(body))  # the same (21, 2) array, 16 bytes a vertex
    first_index = int(headers["x-first-index"])

    _, _, text = get(url + "&format=csv")
    rows = np.genfromtxt(io.StringIO(text.decode()), delimiter=",", names=True, dtype=None)
    p_rows = rows[rows["curve"] == "p"]  # the polygon p; the companions follow it

    _, _, archive = get(url + "&format=npz")
    polylines = np.load(io.BytesIO(archive))  # p and every companion, each with its indices

    failing = [c["id"] for c in curve["checks"] if c["holds"] is False]
    print(f"{len(vertices)} vertices from index {first_index}; lowest point {vertices[:, 1].min()}")
    print(f"npy equals JSON: {np.array_equal(from_npy, vertices)}; npz holds {polylines.files}")
    print(f"checks: {len(curve['checks'])}, failing: {failing or 'none'}")
    return {
        "vertices": vertices,
        "npy": from_npy,
        "first_index": first_index,
        "csv": np.column_stack([p_rows["x"], p_rows["y"]]),
        "npz": {name: polylines[name] for name in polylines.files},
        "failing": failing,
    }


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_URL)
