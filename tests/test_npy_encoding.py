"""format=npy: the encoder writes exactly what ``np.save`` writes, with one copy of the data."""

from __future__ import annotations

import io

import numpy as np
import pytest

from app.responses import npy_bytes


@pytest.mark.parametrize(
    "array",
    [
        np.arange(14.0).reshape(7, 2),
        np.zeros((0, 2)),
        np.arange(40.0).reshape(10, 4)[::2, 1:3],  # a strided view
        np.arange(6, dtype=np.int64).reshape(3, 2),  # converted to <f8
    ],
)
def test_npy_bytes_are_those_of_np_save(array: np.ndarray) -> None:
    expected = io.BytesIO()
    np.save(expected, array.astype("<f8"), allow_pickle=False)
    body = npy_bytes(array)
    assert isinstance(body, bytes) and body == expected.getvalue()
    assert np.load(io.BytesIO(body)).tolist() == array.astype(float).tolist()
