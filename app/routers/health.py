"""GET /health (liveness: precomputed bytes, no validation) and GET /ready (admission).

It is also the reference of bench/http.py: requests per second of a computational GET are
measured against this endpoint on the same server, through the same middleware.
"""

import orjson
from fastapi import APIRouter, Request, Response

from app import __version__
from app.schemas.catalog import Health, Readiness
from app.schemas.common import Problem

router = APIRouter(tags=["service"])

BODY = orjson.dumps(Health(status="ok", version=__version__).model_dump())


@router.get(
    "/health",
    summary="Liveness",
    description='Answers `{"status": "ok"}` with the service version when the process serves.',
    response_model=Health,
)
async def health() -> Response:
    return Response(BODY, media_type="application/json")


READY_BODY = orjson.dumps({"status": "ready"})


@router.get(
    "/ready",
    summary="Readiness",
    description='200 `{"status": "ready"}` while this worker admits new work; 503 '
    "problem+json with Retry-After while its admitted work is at its budget or once it is "
    "shutting down (SIGTERM). A load balancer sends work elsewhere on 503; `/health` stays "
    "200 as long as the process serves.",
    response_model=Readiness,
    responses={
        200: {"content": {"application/json": {"example": {"status": "ready"}}}},
        503: {
            "model": Problem,
            "description": "Not admitting work now.",
            "content": {"application/problem+json": {}},
            "headers": {
                "Retry-After": {"description": "Seconds to wait.", "schema": {"type": "integer"}}
            },
        },
    },
)
async def ready(request: Request) -> Response:
    admission = request.app.state.admission
    cache = request.app.state.response_cache
    # what this worker's response cache holds now (bench/load.py tells its filling from a leak)
    held = {CACHE_BYTES_HEADER: str(cache.bytes + cache.alias_bytes)}
    if admission.ready():
        return Response(READY_BODY, media_type="application/json", headers={**NO_STORE, **held})
    reason = "shutting down" if admission.draining else "busy: its admitted work is at its budget"
    body = orjson.dumps(
        {
            "type": "/problems/overloaded",
            "title": "Overloaded",
            "status": 503,
            "detail": f"This worker does not admit work now ({reason}).",
            "errors": [],
        }
    )
    return Response(
        body,
        status_code=503,
        media_type="application/problem+json",
        headers={**NO_STORE, **held, "Retry-After": str(admission.retry_after())},
    )


NO_STORE = {"Cache-Control": "no-store"}

#: Bytes the worker's response cache holds (bodies, keys and per-entry overhead as it charges
#: them against DCOSH_RESPONSE_CACHE_BYTES).
CACHE_BYTES_HEADER = "X-Response-Cache-Bytes"
