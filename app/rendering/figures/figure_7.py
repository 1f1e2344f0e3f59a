"""Figure 7: tractrix d_i, inscribed n_i (18), circumscribed m_i (20) with contact points."""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.rendering.curves import drawable
from app.rendering.figures.common import (
    GAUSS_COLOUR,
    GUIDE_COLOUR,
    STICK_COLOUR,
    TRACTRIX_COLOUR,
    CurveSource,
    panel,
    shown_parameters,
    source_url,
    unit_circle_series,
)
from app.rendering.svg import Panels, Series, describe_parameters, segments

if TYPE_CHECKING:  # the request models are read, not imported at run time
    from app.schemas.figures import Figure7Query


def draw(query: Figure7Query, curves: CurveSource) -> Panels:
    """Figure 7: tractrix d_i, inscribed n_i (18), circumscribed m_i (20) with contact points."""
    curve = curves("d4b", h=query.h, d=query.d, i_min=query.i_min, i_max=query.i_max)
    tractrix = drawable(curve, "tractrix", curve.companions["tractrix"])
    axis = drawable(curve, "axis_points", curve.companions["axis_points"])
    inscribed = drawable(curve, "tractrix_gauss_image", curve.companions["tractrix_gauss_image"])
    contact = drawable(curve, "contact_points", curve.companions["contact_points"])
    circumscribed = drawable(curve, "gauss_image", curve.companions["gauss_image"])
    shown = shown_parameters(curve)
    figures = Panels(
        title="Figure 7: Gauss images of the discrete pseudosphere and catenoid (D4b)",
        subtitle=describe_parameters(shown),
        footnote=f"Data: GET {source_url('d4b', shown)} (tractrix, tractrix_gauss_image, "
        "contact_points, gauss_image)",
    )
    left = panel("Discrete tractrix d_i (Theorem 6)")
    left.add(
        Series(
            "sticks",
            "sticks",
            segments(axis, tractrix),
            kind="segments",
            color=STICK_COLOUR,
            width=1,
            description="x_i d_i, of length h",
        )
    )
    left.add(
        Series("tractrix", "d_i", tractrix, color=TRACTRIX_COLOUR, width=2, description="(16)")
    )
    figures.add("left", left)
    centre = panel("Inscribed Gauss image n_i (Theorem 7)")
    centre.add(unit_circle_series())
    centre.add(
        Series(
            "tractrix_gauss_image",
            "n_i",
            inscribed,
            color=GAUSS_COLOUR,
            width=2,
            description="(18): on the unit circle, edges parallel to d_i",
        )
    )
    figures.add("centre", centre)
    right = panel("Circumscribed Gauss image m_i (Theorem 8)")
    right.add(unit_circle_series())
    right.add(
        Series(
            "chords",
            "ñ_{i−1} ñ_i",
            segments(contact[:-1], contact[1:]),
            kind="segments",
            color=GUIDE_COLOUR,
            width=1,
            description="m_i is the midpoint of this chord reflected in the circle",
        )
    )
    right.add(
        Series(
            "contact_points",
            "ñ_i",
            contact,
            kind="points",
            color="#000000",
            description="(19): where the edges touch the circle",
        )
    )
    right.add(
        Series(
            "gauss_image",
            "m_i",
            circumscribed,
            color=GAUSS_COLOUR,
            width=2,
            description="(20): edges tangent to the circle, parallel to p",
        )
    )
    figures.add("right", right)
    return figures
