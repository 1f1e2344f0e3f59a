"""Errors of the geometry core; ``app/errors.py`` turns them into problem+json responses."""

from __future__ import annotations

from typing import Any


class GeometryError(ValueError):
    """Base class: the input is outside what the mathematics allows."""


class DomainError(GeometryError):
    """A parameter lies outside the domain of a construction or a formula.

    ``parameter`` is the public parameter name, ``constraint`` the condition it violates in the
    paper's notation, ``value`` what was received.
    """

    def __init__(self, parameter: str, constraint: str, value: Any, detail: str | None = None):
        self.parameter = parameter
        self.constraint = constraint
        self.value = value
        self.detail = detail
        message = f"{parameter} must satisfy {constraint}, got {value!r}"
        super().__init__(f"{message}: {detail}" if detail else message)


class NotRepresentableError(DomainError):
    """A requested value exists mathematically but does not fit the chosen precision."""


class TimeLimitError(DomainError):
    """A computation ran past its time limit (``Arithmetic.start_clock``) and was stopped."""
