"""The pure core: the paper's discretizations, closed forms and checks.

Imports numpy and mpmath only: no web framework, no pydantic, no I/O. Each module is one
concept of the paper; ``discretizations/`` assembles them into the curves the API serves.
"""
