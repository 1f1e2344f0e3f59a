"""`checks` and `companions`: what a request selects, validated against what its source has."""

from __future__ import annotations

from collections.abc import Iterable

from app.geometry.curve import NOTHING, Selection
from app.geometry.errors import DomainError

WORDS = {"checks": "all, none, failed", "companions": "all, none"}


def selection(
    checks: str,
    companions: str,
    statements: Iterable[str],
    companion_names: Iterable[str],
    response_format: str = "json",
) -> Selection:
    """The ``Selection`` of a request's normalized ``checks`` and ``companions`` values.

    ``statements`` and ``companion_names`` are what the source (a discretization, a smooth
    reference, a surface) has; an id outside them is a ``DomainError`` naming the parameter and
    listing them. ``format=npy`` returns the polygon alone, so nothing else is computed for it.
    """
    chosen_checks = chosen("checks", checks, statements)
    chosen_companions = chosen("companions", companions, companion_names)
    if response_format == "npy":
        return NOTHING
    return Selection(chosen_checks, chosen_companions, failed_only=checks == "failed")


def chosen(parameter: str, value: str, valid: Iterable[str]) -> frozenset[str] | None:
    """The ids of one normalized selection (``None``: all), each checked against ``valid``."""
    if value in ("all", "failed"):
        return None
    if value == "none":
        return frozenset()
    known = list(valid)
    ids = frozenset(value.split(","))
    unknown = sorted(ids - set(known))
    if unknown:
        kind = "statement id" if parameter == "checks" else "companion"
        plural = "s" if len(unknown) > 1 else ""
        listed = ", ".join(known) if known else "(none here)"
        raise DomainError(
            parameter,
            f"{WORDS[parameter]}, or a comma-separated list of: {listed}",
            ",".join(unknown),
            f"unknown {kind}{plural} {', '.join(unknown)}",
        )
    return ids
