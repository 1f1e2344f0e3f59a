"""Exact inputs: a real parameter carried as the decimal the client wrote (``ExactReal``)."""

from __future__ import annotations

from typing import Any


class ExactReal(float):
    """A real parameter as the client wrote it: a float (its nearest double) with the exact text.

    Validation, comparisons and float64 use the double; ``MultiPrecision.scalar`` reads
    ``text``, so precision=mp computes with the decimal the client wrote, carried at the
    working precision (``d=0.12345678901234567890123`` is not rounded to 17 digits first).
    ``text`` is a plain decimal (``[-]digits[.digits][E[+-]digits]``, as ``decimal.Decimal``
    prints it), which is also a valid JSON number: responses echo it as written.
    """

    text: str

    def __new__(cls, text: str) -> ExactReal:
        value = super().__new__(cls, text)
        value.text = text
        return value

    def __reduce__(self) -> tuple[Any, ...]:
        return (ExactReal, (self.text,))
