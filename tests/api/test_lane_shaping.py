"""The answer-shaping shortcuts of the fast lane give what the general code gives."""

from __future__ import annotations

import numpy as np
import pytest

from app.geometry.precision import Float64
from app.response_cache import Reply
from app.responses import not_finite


@pytest.mark.parametrize(
    "values",
    [
        [[0.0, 1.0], [2.0, -3.0]],
        [[1e308, 1e308], [1e308, 1e308]],  # finite, but the sum overflows
        [[-1e308, -1e308], [np.nan, 0.0]],
        [[np.inf, 0.0], [0.0, 0.0]],
        [[np.inf, -np.inf], [0.0, 0.0]],
        [[0.0, 0.0], [0.0, -np.inf]],
    ],
)
@pytest.mark.parametrize("rows", [2, 40_000])  # a small curve and a long one before q
def test_the_finiteness_test_agrees_with_isfinite(values: list[list[float]], rows: int) -> None:
    array = np.array(values, dtype=np.float64)
    expected = None if np.isfinite(array).all() else "q"
    named = [("p", np.zeros((rows, 2))), ("q", array), ("r", np.ones((3, 2)))]
    assert not_finite(Float64(), named) == expected
    assert not_finite(Float64(), named[1:]) == expected
    assert not_finite(Float64(), [("q", array)]) == expected
    assert not_finite(Float64(), [("q", array.T)]) == expected  # a view with other strides


@pytest.mark.parametrize(
    "reply",
    [
        Reply(200, {"Content-Type": "application/json", "ETag": '"x"'}, b"{}"),
        Reply(200, {"content-length": "7", "Vary": "Accept-Encoding"}, b"1234567"),
        Reply(304, {"ETag": '"x"', "Cache-Control": "public"}, b""),
        Reply(200, {}, b""),
    ],
)
def test_raw_headers_are_those_of_the_response(reply: Reply) -> None:
    assert reply.raw_headers() == reply.response().raw_headers
