"""An invalid request: the problem+json answer names the parameter; its `type` is a page."""

from __future__ import annotations

import json
import sys
from typing import Any

from _http import DEFAULT_URL, get


def main(base: str = DEFAULT_URL) -> dict[str, Any]:
    status, headers, body = get(f"{base}/discretizations/d4b?d=2")  # d must be below h = 1
    problem = json.loads(body)
    for error in problem["errors"]:
        print(
            f"{status} {problem['title']}: {error['parameter']} must satisfy "
            f"{error['constraint']} (got {error['value']})"
        )
    _, _, page = get(base + problem["type"], "application/json")
    described = json.loads(page)
    print(f"{problem['type']}: {described['description']}")
    return {
        "status": status,
        "content_type": headers["content-type"],
        "problem": problem,
        "type_page": described,
    }


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_URL)
