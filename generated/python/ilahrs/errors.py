# Copied from generator/targets/python/runtime/errors.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Errors: one list of kinds for every ilahrs binding (the spec's `errors`, in `ilahrs.spec`)."""

from __future__ import annotations

import difflib
import math
from collections.abc import Iterable
from typing import Final

from .spec import ErrorKind

__all__ = [
    "MAX_SECONDS",
    "ErrorKind",
    "IlahrsError",
    "brief",
    "require_bytes",
    "require_flag",
    "require_int",
    "require_seconds",
    "suggest",
]

_SHOWN: Final = 40
"""Characters of a bad value an error message shows."""
_DETAIL_LIMIT: Final = 400
"""Longest detail an error carries."""
MAX_SECONDS: Final = 1e9
"""The longest time step or timeout the sans-I/O models take (about 31 years)."""


class IlahrsError(ValueError):
    """Bad input: what (`kind`), where (`offset`, a byte or character index into the input) and,
    where it applies, which `field`."""

    kind: ErrorKind
    offset: int | None
    field: str | None

    def __init__(self, kind: ErrorKind, offset: int | None = None, field: str | None = None, detail: str = "") -> None:
        self.kind = kind
        self.offset = offset
        self.field = field
        self.detail = detail if len(detail) <= _DETAIL_LIMIT else detail[: _DETAIL_LIMIT - 3] + "..."
        super().__init__(str(self))

    def __str__(self) -> str:
        text = str(self.kind.value)
        if self.field is not None:
            text += f" in {self.field}"
        if self.offset is not None:
            text += f" at offset {self.offset}"
        if self.detail:
            text += f": {self.detail}"
        return text

    def __reduce__(self) -> tuple[type[IlahrsError], tuple[ErrorKind, int | None, str | None, str]]:
        return (IlahrsError, (self.kind, self.offset, self.field, self.detail))


def brief(value: object) -> str:
    """A short repr of `value` for an error message: a long text, byte string or container is cut
    before it is shown (a 100 MB value must not make a 100 MB message)."""
    if isinstance(value, (str, bytes, bytearray)) and len(value) > _SHOWN:
        return f"{value[:_SHOWN]!r}... ({len(value)} long)"
    if isinstance(value, (list, tuple, dict, set, frozenset)) and len(value) > 8:
        return f"a {type(value).__name__} of {len(value)} items"
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 128:
        return f"an integer of {value.bit_length()} bits"
    text = repr(value)
    return text if len(text) <= 2 * _SHOWN else text[: 2 * _SHOWN] + "..."


def require_bytes(data: object, field: str | None = None) -> bytes:
    """`data` as bytes if it is a byte string (bytes, bytearray, memoryview); IlahrsError(MALFORMED)
    for anything else (text, None, an integer, a list)."""
    if isinstance(data, bytes):
        return data
    if isinstance(data, (bytearray, memoryview)):
        return bytes(data)
    detail = f"{brief(data)} is not a byte string (bytes, bytearray or memoryview)"
    raise IlahrsError(ErrorKind.MALFORMED, None, field, detail)


def require_flag(value: object, field: str) -> bool:
    """`value` if it is a bool; IlahrsError(MALFORMED) otherwise (an option is True or False)."""
    if not isinstance(value, bool):
        raise IlahrsError(ErrorKind.MALFORMED, None, field, f"{brief(value)} is not True or False")
    return value


def require_int(value: object, field: str, low: int, high: int) -> int:
    """`value` if it is an integer (not a bool) in low..high; IlahrsError(OUT_OF_RANGE) otherwise."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, field, f"{brief(value)} is not an integer")
    if not low <= value <= high:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, field, f"{brief(value)} outside {low}..{high}")
    return value


def require_seconds(value: object, field: str = "seconds", *, infinite: bool = False) -> float:
    """`value` as a float if it is a time in 0..MAX_SECONDS (or infinity, if `infinite`);
    IlahrsError(OUT_OF_RANGE) for NaN, negative, too large or non-numeric values."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, field, f"{brief(value)} is not a number of seconds")
    seconds = float(value) if not isinstance(value, int) or value.bit_length() < 64 else math.inf
    if infinite and seconds == math.inf:
        return seconds
    if not 0 <= seconds <= MAX_SECONDS:
        detail = f"{brief(value)} is not a time in 0..{MAX_SECONDS:g} s"
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, field, detail)
    return seconds


def suggest(name: object, known: Iterable[str]) -> str:
    """ "; did you mean 'X'?" for the known name closest to `name` (case-insensitive), or ""."""
    if not isinstance(name, str):
        return ""
    names = list(known)
    lowered = {n.lower(): n for n in names}
    close = difflib.get_close_matches(name[:_SHOWN].lower(), list(lowered), n=1, cutoff=0.6)
    return f"; did you mean {lowered[close[0]]!r}?" if close else ""
