"""detail=true in precision=mp (issue 15): per-index residuals are decimal strings, each a
rigorous upper bound rounded up; as floats they left the float range from 324 digits on
(shown as the smallest positive float, or 0). float64 keeps numbers."""

from __future__ import annotations

from decimal import Decimal

import pytest
from fastapi.testclient import TestClient

from app.schemas.curve import CurveResponse, CurveResponseMP


@pytest.mark.parametrize("digits", [30, 500])
def test_per_index_residuals_are_decimal_bounds_in_mp(client: TestClient, digits: int) -> None:
    query = f"precision=mp&digits={digits}&detail=true&i_min=-4&i_max=4"
    body = client.get(f"/discretizations/d4b?{query}").json()
    CurveResponseMP.model_validate(body)
    shown = 0
    for check in body["checks"]:
        per_index = check["per_index"]
        if check["residual"] is None:
            continue
        assert per_index is not None and len(per_index["indices"]) == len(per_index["residuals"])
        bounds = [Decimal(value) for value in per_index["residuals"]]
        assert all(isinstance(value, str) for value in per_index["residuals"])
        # none above the check's residual, and the largest is it (or one unit below)
        largest, residual = max(bounds), Decimal(check["residual"])
        assert largest <= residual, check["id"]
        assert residual - largest <= residual * Decimal("1e-9"), check["id"]
        if check["holds"] is True and residual > 0:
            shown += 1
            # at rounding level: about 10^-(digits + 10), far below the float range at 500
            assert Decimal(10) ** -(digits + 20) < largest < Decimal(10) ** -(digits - 5)
    assert shown >= 10


def test_per_index_residuals_stay_numbers_in_float64(client: TestClient) -> None:
    body = client.get("/discretizations/d4b?detail=true&i_min=-4&i_max=4").json()
    CurveResponse.model_validate(body)
    for check in body["checks"]:
        if check["per_index"] is not None:
            assert all(isinstance(value, float) for value in check["per_index"]["residuals"])


def test_a_theorem_with_detail_in_mp(client: TestClient) -> None:
    body = client.get("/theorems/theorem-1?precision=mp&digits=400&detail=true").json()
    check = body["check"]
    assert check["holds"] is True
    bounds = [Decimal(value) for value in check["per_index"]["residuals"]]
    assert bounds and max(bounds) <= Decimal(check["residual"]) < Decimal("1e-395")
