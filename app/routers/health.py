"""GET /health."""

from fastapi import APIRouter

from app import __version__
from app.schemas.catalog import Health

router = APIRouter(tags=["service"])


@router.get(
    "/health",
    summary="Liveness",
    description='Answers `{"status": "ok"}` with the service version when the process serves.',
    response_model=Health,
)
def health() -> Health:
    return Health(status="ok", version=__version__)
