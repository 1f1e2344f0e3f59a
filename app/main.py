"""The FastAPI application: ``create_app()`` and the module-level ``app``."""

import sys
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import Any

import anyio
import anyio.to_thread
import orjson
from fastapi import Depends, FastAPI
from fastapi.middleware.cors import CORSMiddleware

from app import __version__, errors
from app.admission import (
    SPARE_THREADS,
    SWITCH_INTERVAL,
    Admission,
    AdmissionGate,
    drain_on_sigterm,
)
from app.bounded_io import BoundedIO
from app.compression import Compress
from app.fast_lane import FastLane
from app.negotiation import Negotiation
from app.response_cache import FastPath, ResponseCache
from app.routers import (
    convergence,
    discretizations,
    docs,
    errata,
    explorer,
    figures,
    health,
    problems,
    relations,
    smooth,
    surfaces,
    theorems,
)
from app.schemas.openapi_document import refine
from app.security import SecurityHeaders
from app.settings import Settings, get_settings

DESCRIPTION = """\
Every discretization of the hyperbolic cosine (and of the tractrix) from *Discretizations of the
hyperbolic cosine*, computed from its definition, with the paper's claims checked on the result.
Each curve response carries `checks`: for every statement, the residual, the tolerance that fits
the precision, the verdict and, where the printed formula is wrong, the erratum (its page:
GET /errata/{id}).

Conventions: indices are the paper's; Δ²y_i = y_{i+2} − 2y_{i+1} + y_i; l_i = |p_{i+1} − p_i|;
A_i is the signed trapezoid area under the edge p_i p_{i+1}. `precision=mp` computes with
`digits` significant digits and returns coordinates as decimal strings. Errors are
`application/problem+json` (RFC 9457) naming the parameter and its constraint; each problem's
`type` is a page of this service (GET /problems). HEAD is answered wherever GET is. The
representation is chosen by `format`; a GET without it gets the one its `Accept` header prefers
among those of the endpoint (406 if none; see each `format` parameter).
"""

TAGS = [
    {"name": "discretizations", "description": "Discrete hyperbolic cosines and companions."},
    {"name": "theorems", "description": "The paper's statements, checked on computed data."},
    {
        "name": "relations",
        "description": "Section 4: every discretization against every property.",
    },
    {
        "name": "convergence",
        "description": "Section 6: refinement studies, sup errors and observed orders.",
    },
    {"name": "figures", "description": "The paper's figures, redrawn from computed data."},
    {"name": "surfaces", "description": "Catenoids, pseudosphere and Gauss images as meshes."},
    {"name": "smooth", "description": "Smooth references of Section 2: catenary and tractrix."},
    {"name": "errata", "description": "The paper's printed formulas found wrong (docs/errata.md)."},
    {
        "name": "service",
        "description": "Liveness, readiness, and the problem types of error responses.",
    },
]


@asynccontextmanager
async def lifespan(app: FastAPI) -> AsyncIterator[None]:
    """Bound the threads that run computations (FastAPI runs sync endpoints in a thread pool;
    a few spare threads keep catalogs answering while every compute thread is busy), and turn
    /ready to 503 on SIGTERM."""
    limiter = anyio.to_thread.current_default_thread_limiter()
    limiter.total_tokens = app.state.settings.compute_threads + SPARE_THREADS
    # the event loop (parsing, /health, refusals) needs the GIL between computations' bytecodes:
    # a shorter switch interval than the default 5 ms gives it back sooner
    sys.setswitchinterval(SWITCH_INTERVAL)
    drain_on_sigterm(app.state.admission)
    yield


#: The refined OpenAPI documents built in this process, as JSON, by settings and routes. The
#: document depends on nothing else, and building it costs 0.6-0.9 s (pydantic's schemas of
#: every model): a second app with the same settings (the tests build hundreds) parses it
#: instead (≈ 11 ms).
DOCUMENTS: dict[tuple[str, tuple[tuple[str, str, tuple[str, ...]], ...]], bytes] = {}


def route_signature(app: FastAPI) -> tuple[tuple[str, str, tuple[str, ...]], ...]:
    """The app's routes as (name, path, methods): a document is reused only for the same ones."""
    return tuple(
        (getattr(r, "name", ""), getattr(r, "path", ""), tuple(sorted(getattr(r, "methods", ()))))
        for r in app.routes
    )


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the application with the given settings (default: from the environment)."""
    app = FastAPI(
        lifespan=lifespan,
        title="Discrete hyperbolic cosine service",
        version=__version__,
        description=DESCRIPTION,
        openapi_tags=TAGS,
        docs_url=None,  # served by app.routers.docs with self-hosted scripts
        redoc_url=None,
        dependencies=[
            Depends(errors.refuse_undeclared_query),
            Depends(errors.enforce_digits_limit),
        ],
    )
    app.state.settings = settings or get_settings()
    app.state.response_cache = ResponseCache(
        app.state.settings.response_cache_bytes, app.state.settings.response_cache_entry_bytes
    )
    app.state.admission = Admission(app.state.settings)
    # innermost: the gate bounds the computational requests that the cache does not answer
    app.add_middleware(AdmissionGate, admission=app.state.admission)
    # cached answers still pass CORS and the security headers
    flights: dict[tuple[str, bytes], anyio.Event] = {}
    app.add_middleware(
        FastPath, cache=app.state.response_cache, settings=app.state.settings, flights=flights
    )
    app.add_middleware(Negotiation)  # Accept → format, before the cache sees the query
    app.add_middleware(Compress, settings=app.state.settings)  # what the cache did not compress
    app.add_middleware(
        CORSMiddleware,
        allow_origins=app.state.settings.cors_origins,
        allow_methods=["GET", "HEAD", "POST"],
        allow_headers=["Content-Type", "If-None-Match"],
        expose_headers=["ETag", "X-First-Index"],
    )
    app.add_middleware(SecurityHeaders)
    app.add_middleware(errors.HeadAsGet)  # HEAD is GET everywhere inside
    if app.state.settings.fast_lane_seconds > 0:
        # small computed curve GETs, answered here with the chain's exact bytes (app/fast_lane.py)
        app.add_middleware(
            FastLane,
            cache=app.state.response_cache,
            settings=app.state.settings,
            admission=app.state.admission,
            flights=flights,
        )
    # outermost: deadlines from arrival, capped bodies, body and send timeouts
    app.add_middleware(BoundedIO, admission=app.state.admission)
    errors.install(app)
    app.include_router(health.router)
    app.include_router(discretizations.router)
    app.include_router(theorems.router)
    app.include_router(smooth.router)
    app.include_router(surfaces.router)
    app.include_router(relations.router)
    app.include_router(convergence.router)
    app.include_router(figures.router)
    app.include_router(errata.router)
    app.include_router(problems.router)
    explorer.install(app)
    docs.install(app)
    generate = app.openapi

    def openapi() -> dict[str, Any]:
        if app.openapi_schema is None:
            key = (app.state.settings.model_dump_json(), route_signature(app))
            built = DOCUMENTS.get(key)
            if built is None:
                built = DOCUMENTS[key] = orjson.dumps(refine(generate(), app.state.settings))
            app.openapi_schema = orjson.loads(built)  # this app's own copy
        return app.openapi_schema

    app.openapi = openapi  # type: ignore[method-assign]
    return app


app = create_app()
