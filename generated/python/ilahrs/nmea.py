# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""The $PAHR sentence (Table 6.7, section 6.2): `$PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC<CR><LF>`.

Values are held as integers scaled by 10**decimals (roll 12.34 deg is 1234), so parsing and
formatting are exact. Building zero-pads each decimal field's integer part to its template
width, the sign counting as a character, and writes hex in upper case; parsing accepts any
number of integer digits, 1 to `decimals` fraction digits and either hex case (E16).
The AHRS sends at most 50 sentences per second. The code is `ilahrs.sentence`'s.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Final

from .sentence import SentenceBase, SentenceField, nmea_checksum, scaled

__all__ = ["MAX_SENTENCE_LENGTH", "NMEA_MAX_RATE_HZ", "PahrSentence", "nmea_checksum"]

IDENTIFIER: Final = "PAHR"
PREFIX: Final = b"$PAHR,"
MAX_SENTENCE_LENGTH: Final = 82
"""Longest sentence, "$" through CR LF (NMEA 0183, E16)."""
NMEA_MAX_RATE_HZ: Final = 50
FIELD_COUNT: Final = 6


@dataclass(frozen=True, slots=True)
class PahrSentence(SentenceBase):
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

    IDENTIFIER: ClassVar[str] = IDENTIFIER
    MAX_LENGTH: ClassVar[int] = MAX_SENTENCE_LENGTH
    FIELDS: ClassVar[tuple[str, ...]] = ("roll", "pitch", "heading", "temperature", "vdd", "usw")
    _SPEC: ClassVar[tuple[SentenceField, ...]] = (
        ("roll", "decimal", 4, 2, -18000, 18000, "deg"),
        ("pitch", "decimal", 3, 2, -9000, 9000, "deg"),
        ("heading", "decimal", 3, 2, 0, 35999, "deg"),
        ("temperature", "decimal", 3, 1, -999, 9999, "degC"),
        ("vdd", "decimal", 1, 2, 0, 999, "V"),
        ("usw", "hex", 4, 0, 0, 65535, ""),
    )

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
            scaled(roll, 100, "roll"),
            scaled(pitch, 100, "pitch"),
            scaled(heading, 100, "heading"),
            scaled(temperature, 10, "temperature"),
            scaled(vdd, 100, "vdd"),
            usw,
        )
        sentence.check()
        return sentence

    def values(self) -> dict[str, float]:
        """Engineering values: roll (deg), pitch (deg), heading (deg), temperature (degC), vdd (V), usw."""
        return {
            "roll": self.roll / 100,
            "pitch": self.pitch / 100,
            "heading": self.heading / 100,
            "temperature": self.temperature / 10,
            "vdd": self.vdd / 100,
            "usw": self.usw,
        }
