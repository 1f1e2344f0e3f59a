"""Pydantic request and response models (the web layer's view of the core's data)."""
