"""On demand: what one computation shares, each part computed when a selected check first needs it.

A discretization's checks read the quantities they need (differences, fits, closed forms, Gauss
images, curvatures) from a context, an ``OnDemand`` whose quantities are
``functools.cached_property``: computed when first read, at most once, never when no selected
check reads them. Its statements are a table ``Evaluators`` (statement, the function that checks
it), run for the selected ones by ``Selection.evaluate``; its constants a table ``Constants``
(name, the statements it comes with, how it is read), read by ``Selection.constants``.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Sequence
from functools import cached_property
from typing import Any, Self, TypeVar

from app.geometry.checks import Check, Statement
from app.geometry.precision import Scalar

C = TypeVar("C")

#: Each statement of a discretization with the function that checks it on a context, in the
#: order of the response (``Selection.evaluate``).
Evaluators = Sequence[tuple[Statement, Callable[[C], Check]]]

#: Each constant of a discretization: its name, the statements it comes with, and how it is read
#: from a context (``Selection.constants``).
Constants = Sequence[tuple[str, tuple[Statement, ...], Callable[[C], Scalar | None]]]


class OnDemand:
    """Base of what one computation shares: each quantity a ``functools.cached_property``.

    A quantity is computed when a selected check (or companion) first reads it, and at most
    once; ``computed`` tells which were (the constants reported are those), and ``replaced``
    gives a copy with some quantities swapped (the tests perturb polygons to see checks fail).
    """

    def computed(self, name: str) -> bool:
        """Whether the quantity ``name`` has been computed (or given)."""
        return name in self.__dict__

    def replaced(self, **values: Any) -> Self:
        """A copy with ``values`` in place of the given or computed ones.

        Cached quantities that are not given are dropped from the copy (they may derive from a
        replaced one) and computed again when read.
        """
        clone = copy.copy(self)
        for name in _cached_names(type(self)):
            clone.__dict__.pop(name, None)
        clone.__dict__.update(values)
        return clone


def _cached_names(cls: type) -> set[str]:
    return {
        name
        for klass in cls.__mro__
        for name, value in vars(klass).items()
        if isinstance(value, cached_property)
    }
