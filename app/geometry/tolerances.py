"""One place for the tolerances and limits every check and representability guard shares.

Tolerances are multiples of the working precision (``Arithmetic.tolerance(steps)``, with the
safety factor ``precision.TOLERANCE_SAFETY`` per step); what differs between checks is how many
rounding steps a residual accumulates, and the constants here say how many.
"""

from __future__ import annotations

LOCAL_STEPS = 16
"""A local check combines a handful of neighbouring values: its tolerance allows this many
rounding steps (``ar.tolerance(LOCAL_STEPS)``)."""

FLOAT64_COORDINATE_LIMIT = 1e150
"""Float64 results keep every coordinate below this size, so that the checks, which multiply two
coordinates (areas, dot products), stay finite; beyond it a request is refused before any work
(use precision=mp)."""

RESOLUTION_MARGIN = 100
"""A second difference Δ²p^y of relative size r is resolved when r exceeds the working precision
by this factor squared (D4b: Δ²p^y/p^y ≈ (2d/h)², so d/h >= 100·√eps in float64)."""

NOT_CONSTRUCTED = "method=closed-form: the construction was not run to compare"
"""The note of a construction-against-closed-form check when the closed form is all there is."""
