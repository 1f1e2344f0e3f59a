"""Start uvicorn with the service's connection limits: one command for `make run`, the Docker
image and the tests that need a real server (tests/deploy/).

The limits (docs/reliability.md):

- h11 parses requests, so the header block is bounded (``--h11-max-incomplete-event-size``,
  64 KiB: 100 000 headers or one 10 MB header get a 400 before they are buffered);
- idle keep-alive connections close after 5 s;
- on SIGTERM the worker stops accepting, /ready turns 503, and in-flight requests get
  ``--timeout-graceful-shutdown`` seconds (by then every admitted request has met its deadline:
  DCOSH_TIME_LIMIT + DCOSH_HARD_STOP_GRACE) before the rest are cut;
- at most ``--limit-concurrency`` connections per worker (a last resort: admission control in
  app/admission.py answers overload with 503 problems long before).

Request bodies, body and send timeouts and the cost budget are the app's (app/admission.py).
Usage: python -m app.server [--host H] [--port P] [--workers N] [uvicorn options…]
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence

#: uvicorn's options for every deployment of the service.
UVICORN_FLAGS = (
    "--http",
    "h11",
    "--h11-max-incomplete-event-size",
    str(64 * 1024),
    "--timeout-keep-alive",
    "5",
    "--timeout-graceful-shutdown",
    "25",
    "--limit-concurrency",
    "1024",
    "--backlog",
    "1024",
    "--no-server-header",
)


def command(host: str, port: int, workers: int, extra: Sequence[str] = ()) -> list[str]:
    """The uvicorn command line serving the app with the service's limits."""
    return [
        sys.executable,
        "-m",
        "uvicorn",
        "app.main:app",
        "--host",
        host,
        "--port",
        str(port),
        "--workers",
        str(workers),
        *UVICORN_FLAGS,
        *extra,
    ]


def main(argv: Sequence[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--host", default=os.environ.get("HOST", "127.0.0.1"))
    parser.add_argument("--port", type=int, default=int(os.environ.get("PORT", "8000")))
    parser.add_argument("--workers", type=int, default=int(os.environ.get("WORKERS", "1")))
    args, extra = parser.parse_known_args(argv)
    argv_out = command(args.host, args.port, args.workers, extra)
    os.execv(argv_out[0], argv_out)


if __name__ == "__main__":
    main()
