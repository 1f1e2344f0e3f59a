"""The float64 elementary functions are the C library's on every machine (``elementary``).

Python's ``math`` module calls the C library for each of them, so it is the reference: every
value, special ones included, must be the same bits. numpy's own ufuncs are not, in general:
with AVX-512 most of them come from SVML, and ``tanh`` is numpy's own polynomial everywhere.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import mpmath
import numpy as np
import pytest

from app.geometry import elementary
from app.geometry.precision import Float64, MultiPrecision

ROOT = Path(__file__).resolve().parents[2]

SPECIAL = [0.0, -0.0, 5e-324, -5e-324, 1e-300, 1e-17, 1e-8, 0.5, 1.0, 2.0, 20.0, 709.0, 710.0]


def _arguments(low: float, high: float, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    spread = np.concatenate(
        [
            rng.uniform(low, high, 3000),
            rng.uniform(-1, 1, 1000),
            np.exp(rng.uniform(-40, 6, 1000)),
            SPECIAL,
            [-v for v in SPECIAL],
        ]
    )
    return np.clip(spread, low, high)


UNARY = {
    "exp": (math.exp, -745.0, 709.0),
    "expm1": (math.expm1, -745.0, 709.0),
    "log": (math.log, 1e-300, 1e300),
    "log1p": (math.log1p, -0.999999, 1e300),
    "cos": (math.cos, -1e6, 1e6),
    "sin": (math.sin, -1e6, 1e6),
    "cosh": (math.cosh, -710.0, 710.0),
    "sinh": (math.sinh, -710.0, 710.0),
    "tanh": (math.tanh, -40.0, 40.0),
    "atanh": (math.atanh, -0.999999, 0.999999),
    "asinh": (math.asinh, -1e300, 1e300),
    "acosh": (math.acosh, 1.0, 1e300),
}


def _bits(values: np.ndarray) -> np.ndarray:
    return np.asarray(values, dtype=np.float64).view(np.int64)


@pytest.mark.parametrize("name", sorted(UNARY))
def test_each_function_is_the_c_librarys_bit_for_bit(name: str) -> None:
    reference, low, high = UNARY[name]
    x = _arguments(low, high, seed=len(name))
    expected = np.array([reference(float(v)) for v in x])
    np.testing.assert_array_equal(_bits(getattr(elementary, name)(x)), _bits(expected))
    # a strided view and a scalar take the same loop
    np.testing.assert_array_equal(_bits(getattr(elementary, name)(x[::3])), _bits(expected[::3]))
    assert getattr(elementary, name)(float(x[7])) == expected[7]


def test_atan2_and_power_are_the_c_librarys_bit_for_bit() -> None:
    rng = np.random.default_rng(2)
    y = np.concatenate([rng.normal(size=3000) * np.exp(rng.uniform(-30, 30, 3000)), SPECIAL])
    x = np.concatenate([rng.normal(size=3000) * np.exp(rng.uniform(-30, 30, 3000)), SPECIAL[::-1]])
    expected = np.array([math.atan2(a, b) for a, b in zip(y, x, strict=True)])
    np.testing.assert_array_equal(_bits(elementary.atan2(y, x)), _bits(expected))
    assert math.copysign(1.0, float(elementary.atan2(-0.0, 1.0))) == -1.0
    assert float(elementary.atan2(0.0, -1.0)) == math.pi
    base = np.exp(rng.uniform(-3, 3, 3000))
    exponent = rng.uniform(-60, 60, len(base))
    expected = np.array([math.pow(a, b) for a, b in zip(base, exponent, strict=True)])
    np.testing.assert_array_equal(_bits(elementary.power(base, exponent)), _bits(expected))
    # a scalar base with an array of exponents, as the printed forms of (14) and (16) take it
    np.testing.assert_array_equal(
        _bits(elementary.power(0.7, exponent)),
        _bits(np.array([math.pow(0.7, b) for b in exponent])),
    )


def test_out_of_domain_values_warn_as_numpys() -> None:
    with pytest.warns(RuntimeWarning, match="divide by zero"):
        assert elementary.log(np.array([0.0]))[0] == -math.inf
    with pytest.warns(RuntimeWarning, match="invalid value"):
        assert math.isnan(elementary.acosh(np.array([0.5]))[0])
    with pytest.warns(RuntimeWarning, match="overflow"):
        assert elementary.exp(np.array([710.0]))[0] == math.inf
    with np.errstate(all="ignore"):  # numpy's error state governs them as its own ufuncs
        assert math.isnan(elementary.power(np.array([-1.0]), np.array([0.5]))[0])


def test_the_float64_arithmetic_takes_them_and_mp_keeps_mpmath() -> None:
    float64 = Float64()
    for name in (*UNARY, "atan2", "power"):
        expected = getattr(elementary, f"{name}_array" if name in ("exp", "cosh") else name)
        assert getattr(float64, name) is expected, name
    mp = MultiPrecision(30)
    assert str(mp.power(mp.scalar(2), mp.scalar("0.5")))[:12] == "1.4142135623"


#: numpy's float64 ufuncs that take another implementation with AVX-512 (SVML, or numpy's own
#: SIMD code), whose bits then differ from the C library's.
DISPATCHED = (
    "exp|expm1|exp2|log|log1p|log2|log10|cbrt|cos|sin|tan|cosh|sinh|tanh|arccos|arcsin|arctan"
    "|arctan2|arccosh|arcsinh|arctanh|power|float_power"
)


def test_no_float64_path_calls_numpys_dispatched_transcendental_ufuncs() -> None:
    """The service's answers must not depend on the processor: app/ calls ``elementary``'s
    functions instead of these (a reference kept for a test may use numpy's)."""
    pattern = re.compile(rf"\bnp\.({DISPATCHED})\b")
    found = [
        f"{path.relative_to(ROOT)}:{number}: {line.strip()}"
        for path in sorted((ROOT / "app").rglob("*.py"))
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line) and not line.lstrip().startswith("#")
    ]
    assert not found, "\n".join(found)


def test_numba_compiles_the_c_librarys_calls_not_svmls() -> None:
    """With Intel's SVML runtime installed numba would vectorize the kernels' ``math.*`` calls
    with SVML (other bits on every processor); the service's dependencies do not bring it."""
    from numba.core import config

    assert not config.USING_SVML


def _has_fma() -> bool:
    """Whether this processor has FMA: the C library then takes its exp compiled with fused
    multiply-adds, the variant ``exp_into`` writes out (without it glibc's plain variant may
    round a rare value the other way; ``exp_into`` still gives the FMA variant's bits)."""
    from llvmlite import binding

    return bool(binding.get_host_cpu_features().get("fma", False))


def _wide_arguments(seed: int) -> np.ndarray:
    """Arguments over exp's whole domain and its edges: uniform on [−746, 710] and on [−1, 1],
    every binary exponent from 2^-1080 to 2^10 with both signs, the borders of the usual range
    (2^-54, 512) and of the finite results, zeros, subnormals, inf and NaN."""
    rng = np.random.default_rng(seed)
    edges = [2.0**-54, 512.0, 709.782712893384, 709.7827128933841, -708.3964185322641, -745.1332]
    edges += [math.nextafter(v, math.inf) for v in edges]
    edges += [math.nextafter(v, -math.inf) for v in edges]
    return np.concatenate(
        [
            rng.uniform(-746.0, 710.0, 200_000),
            rng.uniform(-1.0, 1.0, 200_000),
            np.ldexp(rng.uniform(-1.0, 1.0, 200_000), rng.integers(-1080, 11, 200_000)),
            edges,
            [-v for v in edges],
            SPECIAL,
            [-v for v in SPECIAL],
            [math.inf, -math.inf, math.nan],
        ]
    )


INTO = {
    "exp": (elementary.exp_into, elementary.exp),
    "cosh": (elementary.cosh_into, elementary.cosh),
}


@pytest.mark.skipif(not _has_fma(), reason="the C library's exp without FMA is another variant")
@pytest.mark.parametrize("name", sorted(INTO))
def test_the_vector_forms_are_the_c_librarys_functions_bit_for_bit(name: str) -> None:
    into, ufunc = INTO[name]
    x = _wide_arguments(seed=29)
    x = np.concatenate([x, [22.0, -22.0, math.nextafter(22.0, 0.0), elementary.COSH_EXP_LEAST]])
    x = np.concatenate([x, [math.nextafter(elementary.COSH_EXP_LEAST, 0.0), 0.3, -0.01]])
    with np.errstate(over="ignore"):
        expected = ufunc(x)
    out = np.full_like(x, 7.0)
    assert into(x, out)  # huge, infinite and NaN arguments are there
    np.testing.assert_array_equal(_bits(out), _bits(expected))
    # in place, and from an offset that splits its chunks differently
    inplace = x[3:].copy()
    into(inplace, inplace)
    np.testing.assert_array_equal(_bits(inplace), _bits(expected[3:]))
    # usual arguments only (the vector loop alone), with a few small ones, and a short block
    usual = np.random.default_rng(5).uniform(-60.0, 60.0, 5000)
    with_small = np.concatenate([usual, [0.0, 1e-300, 0.1]])[::-1].copy()
    for block in (usual, with_small, usual[:3]):
        found = np.empty_like(block)
        assert not into(block, found)
        np.testing.assert_array_equal(_bits(found), _bits(ufunc(block)))


def test_exp_table_is_two_to_the_k_over_128() -> None:
    """Each of the 128 entries is (tail, scale − k·2^45) with scale·(1 + tail) = 2^(k/128) to
    within 2^-100 relative: the table ``exp_into`` rests on, checked against its definition."""
    table = elementary.EXP_TABLE
    for k in range(128):
        tail = float(table[2 * k : 2 * k + 1].view(np.float64)[0])
        scale_bits = table[2 * k + 1] + np.uint64(k << 45)
        scale = float(np.array([scale_bits], dtype=np.uint64).view(np.float64)[0])
        assert 2.0 ** (k / 128) == pytest.approx(scale, rel=2**-52)
        with mpmath.workprec(200):
            exact = mpmath.mpf(2) ** (mpmath.mpf(k) / 128)
            error = abs(mpmath.mpf(scale) * (1 + mpmath.mpf(tail)) - exact) / exact
        assert error < mpmath.mpf(2) ** -100, k


@pytest.mark.skipif(not _has_fma(), reason="the C library's exp without FMA is another variant")
@pytest.mark.parametrize("name", sorted(INTO))
def test_the_array_forms_keep_the_bits_shapes_and_warnings(name: str) -> None:
    _, ufunc = INTO[name]
    array_form = getattr(elementary, f"{name}_array")
    usual = np.random.default_rng(7).uniform(-50.0, 50.0, (40, 3))
    for x in (usual, usual.T, usual[:, 1], usual[5]):  # 2-D, transposed, strided, a row
        found = array_form(x)
        assert found.shape == x.shape
        np.testing.assert_array_equal(_bits(found), _bits(ufunc(x)))
    assert array_form(0.5) == getattr(math, name)(0.5)
    assert array_form(np.float64(0.5)) == getattr(math, name)(0.5)
    # a huge argument takes the ufunc: the same bits, and numpy's overflow warning
    mixed = np.concatenate([usual[:, 0], [0.0, -800.0, math.nan]])
    with np.errstate(over="ignore"):
        np.testing.assert_array_equal(_bits(array_form(mixed)), _bits(ufunc(mixed)))
    with pytest.warns(RuntimeWarning, match="overflow"):
        assert array_form(np.array([1.0, 711.0]))[1] == math.inf
