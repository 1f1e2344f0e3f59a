"""Property tests of the core over the valid domains (Hypothesis).

For any admissible parameters: no NaN or Infinity escapes, every theorem that holds holds,
ranges that would overflow float64 are refused before they produce garbage, and mp agrees with
float64 to float64 precision.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.geometry.discretizations import d4b
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import Float64, MultiPrecision

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])

heights = st.floats(1e-3, 1e3)
ratios = st.floats(1e-3, 0.99)
angles = st.one_of(st.none(), st.floats(0.05, math.pi - 0.05))


def finite(curve) -> bool:
    arrays = [curve.polygon.vertices] + [c.vertices for c in curve.companions.values()]
    return all(np.all(np.isfinite(a)) for a in arrays)


@SETTINGS
@given(
    h=heights,
    ratio=ratios,
    beta0=angles,
    i_min=st.integers(-40, 0),
    n=st.integers(4, 40),
    method=st.sampled_from(["construction", "closed-form"]),
)
def test_d4b_float64_is_finite_and_every_theorem_holds(
    h: float, ratio: float, beta0: float | None, i_min: int, n: int, method: str
) -> None:
    try:
        curve = d4b.compute(Float64(), h, h * ratio, beta0, i_min, i_min + n, method)  # type: ignore[arg-type]
    except NotRepresentableError:
        return  # refused up front: allowed, never garbage
    assert finite(curve)
    failing = [c.id for c in curve.checks if c.holds is False]
    assert failing == [], failing
    for check in curve.checks:
        assert check.residual is None or math.isfinite(check.residual)


@SETTINGS
@given(ratio=st.floats(0.05, 0.95), beta0=angles, i_max=st.integers(0, 5000))
def test_d4b_long_ranges_are_refused_or_finite(
    ratio: float, beta0: float | None, i_max: int
) -> None:
    refused: str | None = None
    try:
        curve = d4b.compute(Float64(), 1.0, ratio, beta0, i_max - 3, i_max, "closed-form")
    except NotRepresentableError as error:
        refused = error.parameter
    if refused is not None:
        assert refused in {"i_max", "i_min", "beta0"}
    else:
        assert finite(curve)
        assert np.max(np.abs(curve.polygon.vertices)) <= 1e150


@settings(max_examples=15, deadline=None)
@given(h=st.floats(0.1, 10), ratio=st.floats(0.01, 0.9), beta0=angles)
def test_d4b_mp_agrees_with_float64(h: float, ratio: float, beta0: float | None) -> None:
    d = h * ratio
    fast = d4b.compute(Float64(), h, d, beta0, -6, 6)
    exact = d4b.compute(MultiPrecision(30), h, d, beta0, -6, 6)
    for a, b in [(fast.polygon, exact.polygon)] + [
        (fast.companions[k], exact.companions[k]) for k in fast.companions
    ]:
        reference = np.array([[float(v) for v in point] for point in b.vertices])
        scale = np.maximum(np.hypot(*reference.T), 1e-300)[:, None]
        assert np.max(np.abs(a.vertices - reference) / scale) < 1e-12
