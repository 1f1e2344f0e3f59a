"""The paper's figures, one module per figure, drawn from the data they are given.

Each ``figure_<n>.draw(query, curves)`` takes the validated request and a curve source (the
service's ``app.services.figures.curve``) and returns a ``Plot`` or ``Panels``; nothing here
reads the registry or computes a discretization.
"""

from app.rendering.figures.common import CurveSource

__all__ = ["CurveSource"]
