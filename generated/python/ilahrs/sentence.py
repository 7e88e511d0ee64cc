# Copied from generator/targets/python/runtime/sentence.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The code of an NMEA 0183 sentence class: parse, check and build, read from the class's field
table (`_SPEC`: name, format, width, decimals, bounds and unit of each value), its identifier and
its longest length. `ilahrs.nmea` declares the spec's sentence ($PAHR) with it.

Values are held as integers scaled by 10**decimals, so parsing and formatting are exact.
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, ClassVar, Final, TypeVar

from .errors import ErrorKind, IlahrsError, brief, require_bytes

__all__ = ["SentenceBase", "SentenceField", "nmea_checksum", "scaled"]

SentenceField = tuple[str, str, int, int, int, int, str]
"""(name, format "decimal" or "hex", width, decimals, lowest, highest scaled value, unit)."""

_TAIL: Final = 5  # "*", two checksum digits, CR, LF
_HEX: Final = re.compile(rb"[0-9A-Fa-f]+")


def nmea_checksum(body: bytes) -> int:
    """XOR of the characters between "$" and "*"."""
    value = 0
    for byte in require_bytes(body, "body"):
        value ^= byte
    return value


def scaled(value: float, divisor: int, name: str) -> int:
    """The scaled integer of an engineering value, rounding half away from zero."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 2**63:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{brief(value)} is out of range")
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{brief(value)} is not a finite number")
    product = value * divisor
    if not math.isfinite(product) or abs(product) > 2**63:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{brief(value)} is out of range")
    return math.floor(product + 0.5) if product >= 0 else -math.floor(-product + 0.5)


def _decimal(text: bytes, decimals: int) -> int | None:
    """The scaled integer of `-?digits(.digits)?`, or None if the text does not follow the grammar."""
    negative = text.startswith(b"-")
    body = text[1:] if negative else text
    whole, dot, fraction = body.partition(b".")
    if not whole.isdigit() or not whole.isascii():
        return None
    if dot and not (1 <= len(fraction) <= decimals and fraction.isdigit() and fraction.isascii()):
        return None
    value: int = int(whole) * 10**decimals + (int(fraction.ljust(decimals, b"0")) if fraction else 0)
    return -value if negative else value


def _format_decimal(value: int, width: int, decimals: int) -> str:
    sign = "-" if value < 0 else ""
    whole, fraction = divmod(abs(value), 10**decimals)
    text = sign + str(whole).zfill(width - len(sign))
    return f"{text}.{fraction:0{decimals}d}" if decimals else text


def _as_bytes(text: str | bytes | bytearray | memoryview) -> bytes:
    if not isinstance(text, str):
        return require_bytes(text, "text")
    try:
        return text.encode("latin-1")
    except UnicodeEncodeError as exc:
        raise IlahrsError(ErrorKind.MALFORMED, None, None, "not a byte string") from exc


def _start(data: bytes, prefix: bytes, identifier: str) -> None:
    """Check "$", the identifier and the comma that follows it."""
    size = len(data)
    if size < 1:
        raise IlahrsError(ErrorKind.TRUNCATED, 0, None, "empty input")
    if data[0] != prefix[0]:
        raise IlahrsError(ErrorKind.BAD_HEADER, 0, None, "a sentence starts with $")
    if not data.startswith(prefix[: min(size, len(prefix))]):
        raise IlahrsError(ErrorKind.BAD_HEADER, 1, None, f"not a {identifier} sentence")
    if size < len(prefix):
        raise IlahrsError(ErrorKind.TRUNCATED, size, None, "input ends inside the identifier")


def _end(data: bytes, prefix: bytes, max_length: int) -> int:
    """Check CR LF, the length and the checksum; return the position of "*"."""
    size = len(data)
    crlf = data.find(b"\r\n")
    if crlf < 0:
        if size > max_length:
            raise IlahrsError(ErrorKind.BAD_LENGTH, max_length, None, "no CR LF within the longest sentence")
        raise IlahrsError(ErrorKind.TRUNCATED, size, None, "no CR LF")
    end = crlf + 2
    if end > max_length:
        raise IlahrsError(ErrorKind.BAD_LENGTH, max_length, None, f"{end} characters, at most {max_length}")
    if end < size:
        raise IlahrsError(ErrorKind.TRAILING_DATA, end, None, f"{size - end} bytes after CR LF")
    star = end - _TAIL
    if star < len(prefix) or data[star] != ord("*"):
        raise IlahrsError(ErrorKind.MALFORMED, max(star, 0), None, "no *CC checksum before CR LF")
    digits = data[star + 1 : star + 3]
    if not _HEX.fullmatch(digits):
        raise IlahrsError(ErrorKind.MALFORMED, star + 1, None, "checksum digits are not hex")
    sent = int(digits, 16)
    computed = nmea_checksum(data[1:star])
    if sent != computed:
        raise IlahrsError(ErrorKind.BAD_CHECKSUM, star + 1, None, f"sent {sent:02X}, computed {computed:02X}")
    return star


def _values(parts: list[bytes], fields: tuple[SentenceField, ...], offset: int) -> list[int]:
    """The scaled integers of the comma-separated values, starting at `offset` in the input."""
    if len(parts) != len(fields):
        raise IlahrsError(ErrorKind.MALFORMED, offset, None, f"{len(parts)} fields, expected {len(fields)}")
    values: list[int] = []
    for part, (name, kind, width, decimals, low, high, _unit) in zip(parts, fields, strict=True):
        value: int | None
        if kind == "hex":
            value = int(part, 16) if 1 <= len(part) <= width and _HEX.fullmatch(part) else None
        else:
            value = _decimal(part, decimals)
        if value is None:
            raise IlahrsError(ErrorKind.MALFORMED, offset, name, f"{brief(part)} is not a valid {name}")
        if not low <= value <= high:
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{value} outside {low}..{high}")
        values.append(value)
        offset += len(part) + 1
    return values


_S = TypeVar("_S", bound="SentenceBase")
"""The class `parse` is called on (typing.Self, which needs Python 3.11)."""


class SentenceBase:
    """The code of a sentence class: `parse`, `check` and `build`."""

    __slots__ = ()

    IDENTIFIER: ClassVar[str]
    MAX_LENGTH: ClassVar[int]
    """Longest sentence, "$" through CR LF."""
    _SPEC: ClassVar[tuple[SentenceField, ...]]

    if TYPE_CHECKING:

        def __init__(self, *values: int) -> None: ...

    @classmethod
    def parse(cls: type[_S], text: str | bytes | bytearray | memoryview) -> _S:
        """Decode one sentence, "$" through CR LF; IlahrsError in the order of spec/README.md."""
        data = _as_bytes(text)
        prefix = f"${cls.IDENTIFIER},".encode("ascii")
        _start(data, prefix, cls.IDENTIFIER)
        star = _end(data, prefix, cls.MAX_LENGTH)
        return cls(*_values(data[len(prefix) : star].split(b","), cls._SPEC, len(prefix)))

    def check(self) -> None:
        """Raise IlahrsError(OUT_OF_RANGE) for the first value a builder must refuse."""
        for name, _kind, _width, _decimals, low, high, _unit in self._SPEC:
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int):
                raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{brief(value)} is not an integer")
            if not low <= value <= high:
                raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{value} outside {low}..{high}")

    def build(self) -> str:
        """The sentence, "$" through CR LF."""
        self.check()
        fields = []
        for name, kind, width, decimals, _low, _high, _unit in self._SPEC:
            value = getattr(self, name)
            fields.append(f"{value:0{width}X}" if kind == "hex" else _format_decimal(value, width, decimals))
        body = self.IDENTIFIER + "," + ",".join(fields)
        sentence = f"${body}*{nmea_checksum(body.encode('ascii')):02X}\r\n"
        if len(sentence) > self.MAX_LENGTH:
            detail = f"{len(sentence)} characters, at most {self.MAX_LENGTH}"
            raise IlahrsError(ErrorKind.BAD_LENGTH, None, None, detail)
        return sentence
