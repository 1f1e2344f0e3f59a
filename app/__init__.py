"""The discrete hyperbolic cosine service."""

__version__ = "0.1.0"
