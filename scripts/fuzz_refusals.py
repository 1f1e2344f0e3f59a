"""The schema-valid requests a fuzzing run saw refused, counted by kind (reads ``FUZZ_LOG`` files).

    FUZZ_LOG=/tmp/fuzz make fuzz
    .venv/bin/python scripts/fuzz_refusals.py /tmp/fuzz.*

One line per (path family, parameter, constraint) with the request count, the constraint's
numbers replaced by N (one kind however large the range), and the parameter's ``x-domain`` in the
document when it has one; then the totals by status and generation mode. What each kind is
(a runtime limit, a coupled domain, a contract bug) is for a person to judge: docs/reliability.md;
the closing table sorts them roughly by the problem's title ("Over the limits", "Over the time
limit": runtime limits), precision wording, and ``x-domain``; "other" is what to look at first.
"""

from __future__ import annotations

import json
import re
import sys
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]


def kind(constraint: str) -> str:
    """The constraint with its request-specific numbers (counts, sizes) replaced by N."""
    text = re.sub(r"\(this range needs \d+ steps\)", "(this range needs N steps)", constraint)
    text = re.sub(r"\(here [^)]*\)", "(here N)", text)
    text = re.sub(r"\(this mesh has \d+ vertices\)", "(this mesh has N vertices)", text)
    return re.sub(r"\|i_(min|max)\| <= \d+", r"|i_\1| <= N", text)[:110]


#: Constraints that are a precision's limits (float64's range, mp's digits, float32 in GLB).
PRECISION = re.compile(
    r"in float64|in mp|with digits=|float32|representable|precision=mp|format=np[yz] needs"
)


def category(title: str, constraint: str, domain: str | None) -> str:
    """Runtime limit, precision limit, coupled domain (stated in ``x-domain``), or other."""
    if title in {"Over the limits", "Over the time limit"}:
        return "runtime limit"
    if PRECISION.search(constraint):
        return "precision limit"
    if domain:
        return "coupled domain (x-domain)"
    return "other"


def domains() -> dict[tuple[str, str], str]:
    """(path, parameter) -> x-domain, from the committed document."""
    spec = json.loads((ROOT / "openapi" / "openapi.json").read_text(encoding="utf-8"))
    found: dict[tuple[str, str], str] = {}
    for path, operations in spec["paths"].items():
        for parameter in operations.get("get", {}).get("parameters", []):
            if "x-domain" in parameter.get("schema", {}):
                found[path, parameter["name"]] = parameter["schema"]["x-domain"]
    return found


def main(paths: list[str]) -> None:
    statuses: Counter[tuple[str, int]] = Counter()
    refused: Counter[tuple[str, str, str]] = Counter()
    titles: dict[tuple[str, str, str], str] = {}
    operations: set[str] = set()
    examples: dict[tuple[str, str, str], str] = {}
    for name in paths:
        for line in Path(name).read_text(encoding="utf-8").splitlines():
            try:
                entry: dict[str, Any] = json.loads(line)
            except ValueError:
                continue  # a line cut off when a run was stopped
            operations.add(entry["operation"])
            statuses[entry["mode"], entry["status"]] += 1
            if entry["mode"] == "negative" or entry["status"] != 422:
                continue
            for error in entry.get("errors") or []:
                key = (entry["operation"], error["parameter"], kind(error["constraint"]))
                refused[key] += 1
                examples.setdefault(key, entry.get("request", ""))
                titles.setdefault(key, entry.get("title", ""))
    x_domain = domains()
    print(f"{sum(statuses.values())} requests, {len(operations)} operations (methods included)")
    for (mode, status), count in sorted(statuses.items()):
        print(f"  {mode:9} {status}: {count}")
    print(f"\n{len(refused)} kinds of schema-valid input refused:")
    categories: Counter[str] = Counter()
    for key, count in sorted(refused.items(), key=lambda i: -i[1]):
        operation, parameter, constraint = key
        path = operation.split(" ", 1)[1]
        domain = x_domain.get((path, parameter))
        categories[category(titles[key], constraint, domain)] += count
        note = f"  [x-domain: {domain}]" if domain else ""
        print(f"{count:6}  {operation}  {parameter}: {constraint}{note}")
    print(f"\n{sum(refused.values())} schema-valid requests refused, by category:")
    for name, count in categories.most_common():
        print(f"{count:6}  {name}")


if __name__ == "__main__":
    main(sys.argv[1:])
