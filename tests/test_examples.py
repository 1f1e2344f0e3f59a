"""examples/: every script runs against the service under uvicorn, and what it computes agrees
with the JSON answers."""

from __future__ import annotations

import importlib
import socket
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

import mpmath
import numpy as np
import pytest
import uvicorn

from app.main import create_app
from app.settings import Settings

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def base_url() -> Iterator[str]:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = int(s.getsockname()[1])
    config = uvicorn.Config(
        create_app(Settings()), host="127.0.0.1", port=port, log_level="warning"
    )
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 30
    while not server.started:
        assert thread.is_alive() and time.monotonic() < deadline, "uvicorn did not start"
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(timeout=10)


def example(name: str) -> ModuleType:
    sys.path.insert(0, str(EXAMPLES))
    try:
        return importlib.import_module(name)
    finally:
        sys.path.remove(str(EXAMPLES))


def test_curve_to_numpy(base_url: str) -> None:
    found = example("curve_to_numpy").main(base_url)
    assert found["vertices"].shape == (21, 2)
    np.testing.assert_array_equal(found["npy"], found["vertices"])
    np.testing.assert_array_equal(found["csv"], found["vertices"])
    np.testing.assert_array_equal(found["npz"]["p_vertices"], found["vertices"])
    np.testing.assert_array_equal(found["npz"]["p_indices"], np.arange(-10, 11))
    assert found["first_index"] == -10
    # Theorem 5: p_i^x = (2i - 1) d with d = 0.1
    np.testing.assert_allclose(found["vertices"][:, 0], (2 * np.arange(-10, 11) - 1) * 0.1)


def test_mp_to_mpmath(base_url: str) -> None:
    found = example("mp_to_mpmath").main(base_url)
    assert found["digits"] == 50
    assert found["worst"] < mpmath.mpf("1e-45")
    assert found["points"][1][0] == found["d"]  # p_1 = (d, h)


def test_mesh_readers(base_url: str) -> None:
    found = example("mesh_readers").main(base_url)
    ply, vtu = found["ply"], found["vtu"]
    np.testing.assert_array_equal(ply["points"], vtu["points"])
    np.testing.assert_array_equal(ply["quads"], vtu["quads"])
    np.testing.assert_array_equal(ply["K"], vtu["K"])
    np.testing.assert_array_equal(found["trimesh"]["K"], ply["K"])
    assert found["trimesh"]["triangles"] == 2 * len(ply["quads"])
    assert np.all(ply["K"] < 0)  # the catenoid has negative Gaussian curvature
    assert np.abs(ply["H"]).max() < 1e-9  # and vanishing mean curvature (Theorem 8)


def test_problems(base_url: str) -> None:
    found = example("problems").main(base_url)
    assert found["status"] == 422
    assert found["content_type"] == "application/problem+json"
    assert found["problem"]["errors"][0]["parameter"] == "d"
    assert found["type_page"]["title"] == found["problem"]["title"]
