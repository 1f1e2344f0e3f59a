"""precision=mp on rigorous balls: every served mp curve is computed with python-flint's ``arb``.

A discretization's ``compute`` runs unchanged on ``ball_arithmetic.Ball``: every number is a
midpoint and a radius that contains the exact value for the exact inputs (the decimals the
client wrote, ``ExactReal``). What that certifies (``checks.check_residuals``,
``checks.printed_residual``):

- a statement's residual is a rigorous *upper* bound, so ``holds: true`` proves it to that
  tolerance on the exact polygon; ``holds: false`` needs a rigorous lower bound above the
  tolerance, and between the two the verdict is ``null`` with the note "undecided";
- an erratum's printed residual is a rigorous *lower* bound: positive certifies that the printed
  formula is false on this polygon (the response says ``"certified": "false"``);
- coordinates are the midpoints with ``digits`` significant digits; ``radius`` is the largest
  radius of any returned coordinate (``Certificate``).

Radii grow along a recursion (the dependency problem of interval arithmetic; for (D4b) about
e^{2|i|L}·ulp while the values shrink like e^{−|i|L}). ``serve`` carries extra digits (a
discretization's estimate, ``EXTRA_DIGITS``) and, while some returned coordinate's radius
exceeds 10^−(digits+1) of the point's size, doubles them and computes again: never a guess.
Where a discretization marks its recursion (``RECURSIONS_MARKED``: D4b's construction runs inside
``Arithmetic.recursion``), the extra digits are carried there only and the closed forms,
companions and checks run at ``digits`` + guard digits (about 1.2× less time for a 1000-vertex
D4b at 50 digits, docs/performance.md); a check that is undecided at that precision has the
whole curve computed again with every digit.

flint's working precision is one process-wide setting (``flint.ctx.prec``; python-flint 0.9 has
no per-call precision for ``arb`` arithmetic). ``serve`` sets it for one computation and
restores it afterwards, holding ``LOCK`` meanwhile, so two concurrent mp requests at different
digits (the server runs requests in a thread pool) never compute with each other's precision.
The computations hold the GIL anyway (python-flint does not release it), so the lock costs no
parallelism; a request waiting for it spends its time limit.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

import flint
import numpy as np

from app.geometry import arb_loops
from app.geometry.ball_arithmetic import Ball, all_balls
from app.geometry.curve import Curve
from app.geometry.d4b import certified as d4b_certified
from app.geometry.errors import NotRepresentableError
from app.geometry.precision import GUARD_DIGITS, Arithmetic, UndecidedError

#: Serializes ball computations: flint's working precision is process-wide (see above).
LOCK = threading.RLock()

#: Raise the precision at most this many times (each doubles the extra digits); past that the
#: curve is served with the radius reached, which ``Certificate.resolved`` reports.
MAX_RAISES = 6

#: The extra digits tried first when a discretization has no estimate.
DEFAULT_EXTRA_DIGITS = 4


@dataclass(frozen=True)
class Certificate:
    """What the balls of one served curve guarantee (the response's ``certified`` object)."""

    radius: str
    """Largest radius of a returned coordinate, a decimal rounded up (a string: radii of long
    ranges leave the float range): each exact coordinate lies within it of its midpoint."""
    relative_radius: str
    """Largest radius of a point's coordinates over the point's size max(|x|, |y|), rounded
    up; below 10^−(digits+1) when ``resolved``."""
    working_digits: int
    """Decimal digits the balls were computed with (``digits`` + guard + extra digits); for a
    discretization of ``RECURSIONS_MARKED`` those of its construction, the rest computed with
    ``digits`` + guard."""
    resolved: bool
    """Whether every returned coordinate's radius is below 10^−(digits+1) of its point's size."""

    def document(self) -> dict[str, Any]:
        return {
            "radius": self.radius,
            "relative_radius": self.relative_radius,
            "working_digits": self.working_digits,
            "resolved": self.resolved,
        }


@contextmanager
def working_precision(bits: int) -> Iterator[None]:
    """flint computes with ``bits`` inside; the previous precision is restored afterwards."""
    with LOCK:
        saved = flint.ctx.prec
        flint.ctx.prec = bits
        try:
            yield
        finally:
            flint.ctx.prec = saved


@contextmanager
def session(ar: Arithmetic) -> Iterator[None]:
    """Compute more with a served curve's arithmetic (e.g. GET /relations' cells): on balls,
    inside its working precision (``working_precision``); otherwise as is."""
    if isinstance(ar, Ball):
        with working_precision(ar.bits):
            yield
    else:
        yield


#: id -> extra digits a discretization's balls lose over ``arguments`` (an estimate; ``serve``
#: raises further if it is short). Every discretization's curve endpoint is served on balls.
EXTRA_DIGITS: dict[str, Callable[[Mapping[str, Any]], int]] = {
    "d4b": d4b_certified.extra_digits,
    # the others start with a few digits and raise them as needed: their radii grow slowly
    # (D1, D3, D4a: about one digit per 20 vertices at worst; bench/mp.py)
    **{
        identifier: lambda arguments: DEFAULT_EXTRA_DIGITS
        for identifier in ("d1", "d3", "d4a", "d2a-quad", "d2a-hex", "d2b")
    },
}


#: Discretizations whose sequential construction runs inside ``Arithmetic.recursion()``: their
#: balls carry the extra digits there only, and compute the rest (closed forms, companions,
#: checks) at ``digits`` + guard digits (``Ball``); the others carry them everywhere.
RECURSIONS_MARKED = frozenset({"d4b"})


def extra_digits(identifier: str, arguments: Mapping[str, Any]) -> int | None:
    """The extra digits ``serve`` starts with for this request (None: not served on balls);
    the work budget prices them (app/limits.py)."""
    if not serves(identifier):
        return None
    return max(0, EXTRA_DIGITS[identifier](arguments))


def serves(identifier: str) -> bool:
    """Whether precision=mp of this discretization is computed on balls."""
    return identifier in EXTRA_DIGITS


def serve(
    identifier: str,
    ar: Arithmetic,
    compute: Callable[[Arithmetic], Curve],
    arguments: Mapping[str, Any],
) -> Curve:
    """``compute`` on balls for an mp request of a discretization served on balls; otherwise
    (float64, or a discretization still on mpmath) ``compute(ar)`` itself."""
    if ar.mode != "mp" or ar.certified or not serves(identifier):
        return compute(ar)
    extra = max(0, EXTRA_DIGITS[identifier](arguments))
    # first with the extra digits in the recursions only, where the discretization marks them;
    # whatever that leaves open (a check undecided, a comparison, a radius too large) is
    # computed again with every digit everywhere
    recursions_only = identifier in RECURSIONS_MARKED
    for attempt in range(MAX_RAISES + 1):
        balls = Ball(ar.digits, extra, recursions_only)
        balls.deadline, balls.limit = ar.deadline, ar.limit
        try:
            with working_precision(balls.bits):
                curve = compute(balls)
        except UndecidedError as undecided:
            recursions_only = False
            if attempt == MAX_RAISES:
                raise NotRepresentableError(
                    undecided.parameter,
                    f"a value for which balls of {ar.digits + GUARD_DIGITS + extra} digits decide "
                    f"{undecided.what}",
                    arguments.get(undecided.parameter),
                    f"undecided: {undecided.what} is closer to a tie than the precision resolves; "
                    "change the parameter or ask for more digits",
                ) from None
            extra = max(2 * extra, DEFAULT_EXTRA_DIGITS)
            continue
        if recursions_only and balls.undecided:
            recursions_only = False  # decide the checks with every digit
            continue
        with working_precision(balls.bits):
            radius, relative, resolved = _radii(curve, ar.digits)
        if resolved or attempt == MAX_RAISES:
            working = ar.digits + GUARD_DIGITS + extra
            balls.certificate = Certificate(radius, relative, working, resolved)
            return curve
        recursions_only = False
        extra = max(2 * extra, DEFAULT_EXTRA_DIGITS)
    raise AssertionError("unreachable")  # pragma: no cover


def _radii(curve: Curve, digits: int) -> tuple[str, str, bool]:
    """(largest radius, largest relative radius, whether every point is resolved), the radii
    as decimals rounded up; compared as exact arb numbers (radii underflow floats).

    The points with the largest radius and relative radius are found in a compiled loop over
    the balls (``arb_loops.largest_radii``: 7000 points at 50 digits in about 1 ms, where numpy's
    loops over the object arrays took 20–25 ms), their values computed from those points alone;
    without it, entry by entry through numpy's loops.
    """
    limit = flint.arb(10) ** (-digits - 1)
    largest, relative = flint.arb(0), flint.arb(0)
    for polyline in (curve.polygon, *curve.companions.values()):
        vertices = polyline.vertices
        if not len(vertices):
            continue
        if arb_loops.AVAILABLE and all_balls(vertices):
            # the winning points found in a compiled loop, their values computed as below
            at_largest, at_relative, reaches_zero, unbounded = arb_loops.largest_radii(
                vertices[:, 0], vertices[:, 1]
            )
            if not unbounded:
                if at_largest >= 0:
                    x, y = vertices[at_largest]
                    largest = largest.max(x.rad().max(y.rad()))
                if reaches_zero:
                    relative = flint.arb("inf")
                if at_relative >= 0:
                    x, y = vertices[at_relative]
                    size = x.abs_lower().max(y.abs_lower())
                    relative = relative.max((x.rad().max(y.rad()) / size).upper())
                continue
        radii = _RADIUS(vertices)
        radius = _LARGER(radii[:, 0], radii[:, 1])  # exact numbers: max is exact
        inexact = np.flatnonzero([not r.is_zero() for r in radius])
        if not len(inexact):
            continue
        lowers = _ABS_LOWER(vertices[inexact])
        size, radius = _LARGER(lowers[:, 0], lowers[:, 1]), radius[inexact]
        largest = largest.max(max(radius))
        positive = np.array([s > 0 for s in size], dtype=bool)
        if not positive.all():
            relative = flint.arb("inf")  # a point whose ball reaches the origin
        if positive.any():
            quotients = radius[positive] / size[positive]
            relative = relative.max(max(q.upper() for q in quotients))
    return _rounded_up(largest), _rounded_up(relative), bool(relative <= limit)


_RADIUS: Any = np.frompyfunc(flint.arb.rad, 1, 1)
_ABS_LOWER: Any = np.frompyfunc(flint.arb.abs_lower, 1, 1)
_LARGER: Any = np.frompyfunc(flint.arb.max, 2, 1)


def _rounded_up(value: Any) -> str:
    """A decimal >= the exact arb ``value`` (3 digits; ``"inf"`` when unbounded)."""
    if value.is_zero():
        return "0"
    if not value.is_finite():
        return "inf"
    return (value * flint.arb("1.01")).upper().str(3, radius=False)


def certificate(ar: Arithmetic) -> Certificate | None:
    """The certificate of a curve's arithmetic (``None``: not computed on balls)."""
    found = getattr(ar, "certificate", None)
    return found if isinstance(found, Certificate) else None
