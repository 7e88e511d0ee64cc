# Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
# Do not edit: change the spec or the generator and run `make generate`.
"""The $PAHR sentence (Table 6.7, section 6.2): `$PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC<CR><LF>`.

Values are held as integers scaled by 10**decimals (roll 12.34 deg is 1234), so parsing and
formatting are exact. Building zero-pads each decimal field's integer part to its template
width, the sign counting as a character, and writes hex in upper case; parsing accepts any
number of integer digits, 1 to `decimals` fraction digits and either hex case (E16).
The AHRS sends at most 50 sentences per second.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import ClassVar, Final

from .errors import ErrorKind, IlahrsError

__all__ = ["MAX_SENTENCE_LENGTH", "NMEA_MAX_RATE_HZ", "PahrSentence", "nmea_checksum"]

IDENTIFIER: Final = 'PAHR'
PREFIX: Final = b"$PAHR,"
MAX_SENTENCE_LENGTH: Final = 82
"""Longest sentence, "$" through CR LF (NMEA 0183, E16)."""
NMEA_MAX_RATE_HZ: Final = 50
FIELD_COUNT: Final = 6
_TAIL: Final = 5  # "*", two checksum digits, CR, LF
_HEX: Final = re.compile(rb"[0-9A-Fa-f]+")


def nmea_checksum(body: bytes) -> int:
    """XOR of the characters between "$" and "*"."""
    value = 0
    for byte in body:
        value ^= byte
    return value


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


@dataclass(frozen=True, slots=True)
class PahrSentence:
    """One $PAHR sentence, each value a scaled integer."""

    roll: int = 0
    """Roll, hundredths of a degree. (RRRR.rr, scale 10**2, range -18000..18000)"""
    pitch: int = 0
    """Pitch, hundredths of a degree. (PPP.pp, scale 10**2, range -9000..9000)"""
    heading: int = 0
    """Heading, hundredths of a degree. (HHH.hh, scale 10**2, range 0..35999)"""
    temperature: int = 0
    """Average accelerometer temperature, tenths of a degree Celsius. (TTT.t, scale 10**1, range -999..9999)"""
    vdd: int = 0
    """AHRS input voltage, hundredths of a volt. (V.vv, scale 10**2, range 0..999)"""
    usw: int = 0
    """Unit Status Word (section 6.5), four hex digits. (SSSS, range 0..65535)"""

    FIELDS: ClassVar[tuple[str, ...]] = ('roll', 'pitch', 'heading', 'temperature', 'vdd', 'usw', )
    _SPEC: ClassVar[tuple[tuple[str, str, int, int, int, int], ...]] = (
        ('roll', 'decimal', 4, 2, -18000, 18000),
        ('pitch', 'decimal', 3, 2, -9000, 9000),
        ('heading', 'decimal', 3, 2, 0, 35999),
        ('temperature', 'decimal', 3, 1, -999, 9999),
        ('vdd', 'decimal', 1, 2, 0, 999),
        ('usw', 'hex', 4, 0, 0, 65535),
    )

    @classmethod
    def parse(cls, text: str | bytes | bytearray | memoryview) -> PahrSentence:
        """Decode one sentence, "$" through CR LF; IlahrsError in the order of spec/README.md."""
        if isinstance(text, str):
            try:
                data = text.encode("latin-1")
            except UnicodeEncodeError as exc:
                raise IlahrsError(ErrorKind.MALFORMED, None, None, "not a byte string") from exc
        else:
            data = bytes(text)
        size = len(data)
        if size < 1:
            raise IlahrsError(ErrorKind.TRUNCATED, 0, None, "empty input")
        if data[0] != PREFIX[0]:
            raise IlahrsError(ErrorKind.BAD_HEADER, 0, None, "a sentence starts with $")
        if not data.startswith(PREFIX[: min(size, len(PREFIX))]):
            raise IlahrsError(ErrorKind.BAD_HEADER, 1, None, f"not a {IDENTIFIER} sentence")
        if size < len(PREFIX):
            raise IlahrsError(ErrorKind.TRUNCATED, size, None, "input ends inside the identifier")
        crlf = data.find(b"\r\n")
        if crlf < 0:
            if size > MAX_SENTENCE_LENGTH:
                detail = "no CR LF within the longest sentence"
                raise IlahrsError(ErrorKind.BAD_LENGTH, MAX_SENTENCE_LENGTH, None, detail)
            raise IlahrsError(ErrorKind.TRUNCATED, size, None, "no CR LF")
        end = crlf + 2
        if end > MAX_SENTENCE_LENGTH:
            detail = f"{end} characters, at most {MAX_SENTENCE_LENGTH}"
            raise IlahrsError(ErrorKind.BAD_LENGTH, MAX_SENTENCE_LENGTH, None, detail)
        if end < size:
            raise IlahrsError(ErrorKind.TRAILING_DATA, end, None, f"{size - end} bytes after CR LF")
        star = end - _TAIL
        if star < len(PREFIX) or data[star] != ord("*"):
            raise IlahrsError(ErrorKind.MALFORMED, max(star, 0), None, "no *CC checksum before CR LF")
        digits = data[star + 1 : star + 3]
        if not _HEX.fullmatch(digits):
            raise IlahrsError(ErrorKind.MALFORMED, star + 1, None, "checksum digits are not hex")
        sent = int(digits, 16)
        computed = nmea_checksum(data[1:star])
        if sent != computed:
            raise IlahrsError(ErrorKind.BAD_CHECKSUM, star + 1, None, f"sent {sent:02X}, computed {computed:02X}")
        parts = data[len(PREFIX) : star].split(b",")
        if len(parts) != FIELD_COUNT:
            raise IlahrsError(ErrorKind.MALFORMED, len(PREFIX), None, f"{len(parts)} fields, expected {FIELD_COUNT}")
        values: list[int] = []
        offset = len(PREFIX)
        for part, (name, kind, width, decimals, low, high) in zip(parts, cls._SPEC, strict=True):
            value: int | None
            if kind == "hex":
                value = int(part, 16) if 1 <= len(part) <= width and _HEX.fullmatch(part) else None
            else:
                value = _decimal(part, decimals)
            if value is None:
                raise IlahrsError(ErrorKind.MALFORMED, offset, name, f"{part!r} is not a valid {name}")
            if not low <= value <= high:
                raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{value} outside {low}..{high}")
            values.append(value)
            offset += len(part) + 1
        return cls(*values)

    def check(self) -> None:
        """Raise IlahrsError(OUT_OF_RANGE) for the first value a builder must refuse."""
        for name, _kind, _width, _decimals, low, high in self._SPEC:
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int):
                raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{value!r} is not an integer")
            if not low <= value <= high:
                raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{value} outside {low}..{high}")

    def build(self) -> str:
        """The sentence, "$" through CR LF."""
        self.check()
        fields = []
        for name, kind, width, decimals, _low, _high in self._SPEC:
            value = getattr(self, name)
            fields.append(f"{value:0{width}X}" if kind == "hex" else _format_decimal(value, width, decimals))
        body = IDENTIFIER + "," + ",".join(fields)
        sentence = f"${body}*{nmea_checksum(body.encode('ascii')):02X}\r\n"
        if len(sentence) > MAX_SENTENCE_LENGTH:
            detail = f"{len(sentence)} characters, at most {MAX_SENTENCE_LENGTH}"
            raise IlahrsError(ErrorKind.BAD_LENGTH, None, None, detail)
        return sentence

    @classmethod
    def from_values(
        cls,
        *,
        roll: float,
        pitch: float,
        heading: float,
        temperature: float,
        vdd: float,
        usw: int,
    ) -> PahrSentence:
        """Build from engineering values, rounding half away from zero; checked like `build()`."""
        sentence = cls(
            _scaled(roll, 100, 'roll'),
            _scaled(pitch, 100, 'pitch'),
            _scaled(heading, 100, 'heading'),
            _scaled(temperature, 10, 'temperature'),
            _scaled(vdd, 100, 'vdd'),
            usw,
        )
        sentence.check()
        return sentence

    def values(self) -> dict[str, float]:
        """Engineering values: roll (deg), pitch (deg), heading (deg), temperature (degC), vdd (V), usw."""
        return {
            'roll': self.roll / 100,
            'pitch': self.pitch / 100,
            'heading': self.heading / 100,
            'temperature': self.temperature / 10,
            'vdd': self.vdd / 100,
            'usw': self.usw,
        }


def _scaled(value: float, divisor: int, name: str) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, name, f"{value!r} is not a finite number")
    scaled = value * divisor
    return math.floor(scaled + 0.5) if scaled >= 0 else -math.floor(-scaled + 0.5)
