"""``format=svg`` of GET /convergence/{id}: the sup errors of a study on log-log axes.

Each measure is a polyline through (log10 step, log10 error) of its resolved levels (levels
below the rounding resolution drawn as grey points), with its least-squares line dashed; the
legend gives the observed order. Tick labels are the log10 values, so the picture reads like
the JSON.
"""

from __future__ import annotations

import math

import numpy as np

from app.geometry.studies.common import Study
from app.rendering.svg import PALETTE, Plot, Series, describe_parameters


def study_plot(study: Study) -> Plot:
    """The log-log plot of one study."""
    info = study.info
    plot = Plot(
        title=info.title,
        x_label=f"log10 {info.step_name}",
        y_label="log10 sup error",
        equal_aspect=False,
        subtitle=f"{info.reference}; {describe_parameters(study.parameters)}",
        footnote=f"GET /convergence/{info.id} ({study.arithmetic.mode}). Dashed: least-squares "
        "lines; grey points: levels below the rounding resolution (not fitted).",
    )
    for k, measure in enumerate(info.measures):
        colour = PALETTE[k % len(PALETTE)]
        fit = study.fits[measure.id]
        points = [
            (math.log10(level.step), math.log10(error), level.resolved(measure.id))
            for level in study.levels
            if (error := level.errors.get(measure.id)) is not None and error > 0
        ]
        resolved = np.array([(x, y) for x, y, ok in points if ok], dtype=np.float64)
        unresolved = np.array([(x, y) for x, y, ok in points if not ok], dtype=np.float64)
        order = "none" if fit.order is None else f"{fit.order:.3f}"
        label = f"{measure.id}: order {order}"
        if len(resolved):
            plot.add(
                Series(
                    measure.id,
                    label,
                    resolved,
                    color=colour,
                    description=f"expected {measure.expected_order}"
                    if measure.expected_order is not None
                    else "",
                )
            )
        if len(unresolved):
            plot.add(
                Series(
                    f"{measure.id}-unresolved",
                    f"{measure.id} (below resolution)",
                    unresolved,
                    kind="points",
                    color="#999999",
                )
            )
        if fit.order is not None and fit.constant is not None and len(resolved) >= 2:
            xs = resolved[[0, -1], 0]
            ys = math.log10(fit.constant) + fit.order * xs
            plot.add(
                Series(
                    f"{measure.id}-fit",
                    f"{measure.id} fit",
                    np.stack([xs, ys], axis=1),
                    color=colour,
                    markers=False,
                    dashed=True,
                    width=1.0,
                )
            )
    return plot


def study_svg(study: Study) -> bytes:
    """The study as a self-contained SVG document."""
    return study_plot(study).render().encode()
