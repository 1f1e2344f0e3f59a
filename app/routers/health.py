"""GET /health: the bare endpoint (no validation, no encoding: precomputed bytes).

It is also the reference of bench/http.py: requests per second of a computational GET are
measured against this endpoint on the same server, through the same middleware.
"""

import orjson
from fastapi import APIRouter, Response

from app import __version__
from app.schemas.catalog import Health

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
