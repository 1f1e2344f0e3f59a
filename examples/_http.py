"""The one HTTP helper the examples share (standard library only)."""

from __future__ import annotations

import json
import urllib.error
import urllib.request
from typing import Any

DEFAULT_URL = "http://127.0.0.1:8000"


def get(url: str, accept: str = "*/*") -> tuple[int, dict[str, str], bytes]:
    """GET ``url``: status, headers (lower-case names) and body, also for 4xx answers."""
    request = urllib.request.Request(url, headers={"Accept": accept})
    try:
        with urllib.request.urlopen(request, timeout=60) as response:
            headers = {k.lower(): v for k, v in response.headers.items()}
            return response.status, headers, response.read()
    except urllib.error.HTTPError as error:
        headers = {k.lower(): v for k, v in error.headers.items()}
        return error.code, headers, error.read()


def get_json(url: str) -> Any:
    status, _, body = get(url, "application/json")
    if status != 200:
        raise RuntimeError(f"{url}: {status} {body[:300]!r}")
    return json.loads(body)
