"""Pictures of computed data: a small SVG plot writer, curve plots and the paper's figures.

Nothing here computes geometry: it draws what ``app.geometry`` returns.
"""
