"""Service settings: limits and CORS origins, read from DCOSH_* environment variables."""

from __future__ import annotations

from functools import lru_cache

from pydantic import Field
from pydantic_settings import BaseSettings, SettingsConfigDict


class Settings(BaseSettings):
    """Every limit here is checked before any computation starts (see app/limits.py)."""

    model_config = SettingsConfigDict(env_prefix="DCOSH_", extra="ignore")

    max_vertices: int = Field(
        1_000_001, ge=1, description="Most vertices of one polygon (i_max − i_min + 1)."
    )
    max_construction_steps: int = Field(
        2_000_000,
        ge=1,
        description="Most recursion steps of a construction (constructions start at index 0 and "
        "walk to i_min and i_max).",
    )
    max_digits: int = Field(
        1000,
        ge=1,
        description="Most significant digits in precision=mp (on balls, 801 D4b vertices "
        "with every check, the most the work budget admits at 1000 digits, take about 1.7 s "
        "of CPU; surfaces, studies and smooth references still compute mp with mpmath, "
        "several times dearer, and their checks are undecided beyond 300 digits).",
    )
    max_mp_work: int = Field(
        1_000_000,
        ge=1,
        description="Most (digits + 200) × steps in precision=mp (the cost of mp grows with "
        "both; for D4b on balls with every check 1.3–1.7 s of CPU at the limit, 3–4.5 s of wall "
        "time on a loaded 2-core machine; see docs/performance.md).",
    )
    max_svg_vertices: int = Field(
        20_001,
        ge=2,
        description="Most vertices of one polygon drawn as SVG (format=svg and /figures): a "
        "picture holds every vertex, and more than the pixels can show only adds bytes.",
    )
    max_mesh_vertices: int = Field(
        1_000_000,
        ge=4,
        description="Most vertices of one surface mesh: meridian vertices × vertices around "
        "(2m for a closed surface, steps + 1 otherwise). GLB stores 4 vertices per face.",
    )
    max_convergence_levels: int = Field(
        16, ge=2, description="Most refinement levels of one study (GET /convergence/{id})."
    )
    max_convergence_samples: int = Field(
        10_001,
        ge=2,
        description="Most sample points per level of one study (the smooth curve is measured "
        "there).",
    )
    max_convergence_steps: int = Field(
        500_000,
        ge=1,
        description="Most construction steps of one study, summed over its levels (each level "
        "builds its polygon from the definition; about 1 s at the limit in float64).",
    )
    max_relation_vertices: int = Field(
        100_001,
        ge=3,
        description="Most vertices of one row of GET /relations (every discretization is "
        "computed for the matrix).",
    )
    compute_threads: int = Field(
        4,
        ge=1,
        le=64,
        description="Threads per worker that run requests (computations hold the GIL, so more "
        "threads add memory, not throughput; requests beyond wait their turn).",
    )
    compute_processes: int = Field(
        2,
        ge=0,
        le=64,
        description="Child processes per worker that compute and render heavy requests (those "
        "estimated at DCOSH_POOL_MIN_SECONDS or more), so that the worker's event loop keeps "
        "answering; a child past its deadline is killed and replaced (0: every request computes "
        "in the worker).",
    )
    pool_min_seconds: float = Field(
        0.05,
        ge=0,
        description="Estimated seconds from which a request computes in a child process "
        "(cheaper ones compute in the worker: the round trip would cost more than it saves; "
        "precision=mp curves always compute in a child).",
    )
    time_limit: float = Field(
        20.0,
        gt=0,
        description="Seconds from a request's arrival to its answer: waiting counts; a request "
        "that cannot finish in time now is refused before it starts (503; a 422 when its "
        "estimate alone on a free core exceeds the limit), and a computation "
        "that overruns stops with a 422 (the time-limit problem type).",
    )
    admission_seconds: float = Field(
        12.0,
        gt=0,
        description="Estimated seconds of computation one worker admits at once (the sum over "
        "the requests it is computing); beyond it a request gets a 503 with Retry-After. A "
        "single request estimated above it is refused with a 422 (it could never be admitted).",
    )
    admission_bytes: int = Field(
        1536 * 2**20,
        ge=2**20,
        description="Estimated bytes of working memory one worker admits at once (default sized "
        "for 2 workers on a 4 GiB host: 2 × (1.5 GiB + the response cache + ~100 MiB of "
        "interpreter) ≈ 3.7 GiB); "
        "a single request estimated above it is refused with a 422.",
    )
    admission_queue: int = Field(
        8,
        ge=0,
        description="Computational requests a worker lets wait for a compute thread; the next "
        "one gets a 503 at once (never an unbounded queue).",
    )
    hard_stop_grace: float = Field(
        0.5,
        gt=0,
        description="Seconds past its deadline after which a computation still running is "
        "stopped from outside (an exception raised in its thread).",
    )
    max_body_bytes: int = Field(
        8 * 2**20,
        ge=1024,
        description="Largest request body (declared or chunked): a 413 before it is read, or as "
        "soon as a chunked body passes it.",
    )
    body_timeout: float = Field(
        10.0,
        gt=0,
        description="Seconds a request body may take to arrive (slow clients get a 408).",
    )
    send_timeout: float = Field(
        30.0,
        gt=0,
        description="Seconds one write of a response may wait for a client that does not read "
        "before the connection is dropped.",
    )
    cors_origins: list[str] = Field(
        default_factory=lambda: ["*"],
        description="Origins allowed to call the API from a browser (JSON list; ['*'] for any).",
    )
    cache_max_age: int = Field(
        86_400, ge=0, description="Cache-Control max-age of computational GETs, in seconds."
    )
    response_cache_bytes: int = Field(
        256 * 2**20,
        ge=0,
        description="Bytes of encoded responses kept in each worker's in-process cache (least "
        "recently used out first; 0 disables the cache).",
    )
    response_cache_entry_bytes: int = Field(
        64 * 2**20,
        ge=0,
        description="Largest encoded response the cache keeps (bigger ones are served, not kept).",
    )
    fast_lane_seconds: float = Field(
        0.002,
        ge=0,
        description="Estimated seconds up to which a small float64 curve GET is computed on the "
        "event loop by the fast lane (app/fast_lane.py); 0 turns the lane off.",
    )
    gzip_level: int = Field(
        1, ge=0, le=9, description="gzip level for clients that accept it (0: never compress)."
    )
    gzip_min_bytes: int = Field(
        1024, ge=0, description="Smallest text body that is compressed (smaller ones gain little)."
    )
    gzip_max_bytes: int = Field(
        8 * 2**20,
        ge=0,
        description="Largest text body that is compressed: level 1 runs at about 80 MB/s, so "
        "bigger bodies would wait longer for gzip than for the network (use format=npy).",
    )


@lru_cache(maxsize=1)
def get_settings() -> Settings:
    """The settings of this process (read once from the environment)."""
    return Settings()
