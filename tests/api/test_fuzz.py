"""Schema fuzzing: schemathesis against the app's own OpenAPI document, every check on.

Positive and negative data for every operation; `FUZZ_EXAMPLES` examples per operation
(default 120 in `make test`; `make fuzz` runs thousands). Checks: no server errors, status codes,
content types, response schemas and headers documented, negative data rejected, Allow headers.

Tight budgets (``FUZZ_SETTINGS``): every generated request stays cheap, and many go down the
over-budget 422 paths. Positive (schema-valid) requests may get a 422 for two documented reasons
only: a runtime limit (listed with its value in the OpenAPI description, "Runtime limits"), or
a domain that couples parameters (0 < d < h, i_min <= i_max, format=npy with precision=float64,
…; each parameter's description and ``x-domain``), which a JSON Schema cannot express. Every such
422 is still checked to be problem+json naming a parameter (see `test_api`); ``FUZZ_LOG`` lists
them (docs/reliability.md counts them by kind).
"""

from __future__ import annotations

import json
import os
from typing import Any

import pytest
import schemathesis
from hypothesis import HealthCheck, settings
from schemathesis.config import PositiveDataAcceptanceConfig
from schemathesis.schemas import BaseSchema

from app.main import create_app
from app.settings import Settings

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "120"))
#: ``FUZZ_LOG=path``: one JSON line per request (operation, generation mode, status, and for a
#: positive request refused with 422 the request and the problem's errors), in ``path.<pid>``
#: (one file per xdist worker), to count requests and list the schema-valid inputs refused.
LOG = os.environ.get("FUZZ_LOG")

#: Fuzzing tests that every input gets a correct answer or a clear error, not capacity (that is
#: `make load`): tight budgets keep every generated request cheap, so that thousands run in
#: minutes, and send many of them down the over-budget paths. The OpenAPI document is the same
#: (limits are runtime settings).
FUZZ_SETTINGS = Settings(
    max_vertices=2001,
    max_construction_steps=20_000,
    max_digits=60,
    max_mp_work=20_000,
    max_svg_vertices=2001,
    max_mesh_vertices=20_000,
    max_convergence_levels=6,
    max_convergence_samples=501,
    max_convergence_steps=20_000,
    max_relation_vertices=501,
    time_limit=5.0,
)
#: ``FUZZ_LIMITS=production`` fuzzes the service with its default limits instead (heavier requests,
#: up to the 20 s time limit each: for `make fuzz`, not for `make test`).
LIMITS = os.environ.get("FUZZ_LIMITS", "tight")
assert LIMITS in {"tight", "production"}, f"FUZZ_LIMITS is tight or production, not {LIMITS!r}"
schema: BaseSchema = schemathesis.openapi.from_asgi(
    "/openapi.json", create_app(Settings() if LIMITS == "production" else FUZZ_SETTINGS)
)
#: ``FUZZ_PATHS=regex``: only the operations whose path matches (a rerun after a fix).
PATHS = os.environ.get("FUZZ_PATHS")
if PATHS:
    schema = schema.include(path_regex=PATHS)
schema.config.generation.update(
    modes=[schemathesis.GenerationMode.POSITIVE, schemathesis.GenerationMode.NEGATIVE]
)
schema.config.checks.positive_data_acceptance = PositiveDataAcceptanceConfig(
    expected_statuses=["2xx", "304", "404", "422"]
)


@schema.parametrize()
@pytest.mark.filterwarnings("error::RuntimeWarning")  # a numerical warning is a failed request
@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=list(HealthCheck))
def test_api(case: schemathesis.Case) -> None:
    response = case.call_and_validate()
    if LOG:
        _log(case, response)
    if response.status_code == 422:
        problem = response.json()
        where = case.as_curl_command()
        assert response.headers["content-type"][0] == "application/problem+json", where
        assert problem["errors"], (problem, where)
        assert all(e["parameter"] and e["constraint"] for e in problem["errors"]), (problem, where)


def _log(case: schemathesis.Case, response: Any) -> None:
    meta = case.meta
    mode = "explicit" if meta is None else meta.generation.mode.value
    if meta is not None and any(c.mode.is_negative for c in meta.components.values()):
        mode = "negative"
    line: dict[str, Any] = {
        "operation": f"{case.method} {case.path}",
        "mode": mode,
        "status": response.status_code,
    }
    if response.status_code == 422 and mode != "negative":
        line["request"] = case.as_curl_command()
        line["errors"] = response.json().get("errors")
        line["title"] = response.json().get("title")
    with open(f"{LOG}.{os.getpid()}", "a", encoding="utf-8") as out:
        out.write(json.dumps(line, default=str) + "\n")
