"""The service layer: what a request computes, between the routers (HTTP) and the core.

Routers parse a request, call a service and shape the response; services check budgets, pick
what to compute (``selection``), run the core (``app.geometry``) and encode documents and
files as bytes. Nothing here imports FastAPI.
"""
