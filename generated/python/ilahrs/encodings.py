# Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
# Do not edit: change the spec or the generator and run `make generate`.
"""Device variants and the value encodings the ICD defines: date, declination, calibration success."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from enum import IntEnum
from types import MappingProxyType
from typing import Final

from .errors import ErrorKind, IlahrsError

__all__ = [
    "CALIBRATION_FAILED",
    "CALIBRATION_NO_ESTIMATE",
    "DATE_YEAR_MAX",
    "DATE_YEAR_MIN",
    "DECLINATION_COMPUTE",
    "DECLINATION_COMPUTE_ABOVE",
    "DECLINATION_MAX",
    "DECLINATION_MIN",
    "VARIANTS",
    "CalibrationStatusType",
    "CalibrationType",
    "Variant",
    "calibration_accuracy_deg",
    "calibration_succeeded",
    "date_is_valid",
    "declination_is_computed",
    "declination_is_valid",
    "decode_date",
    "encode_date",
]


@dataclass(frozen=True, slots=True)
class Variant:
    """A device variant: the scale factors that depend on the part number (Table 6.6, note 1)."""

    name: str
    part_number: str
    kg: int
    """Gyro scale factor of Table 6.6, LSB per deg/s."""
    ka: int
    """Accelerometer scale factor of Table 6.6, LSB per g."""


VARIANTS: Final[Mapping[str, Variant]] = MappingProxyType(
    {
        'g300_a2_tmga': Variant('g300_a2_tmga', 'AHRS-G300-A2-TMGA-C1-V1.1', 100, 10000),
        'g300_a6_tmga': Variant('g300_a6_tmga', 'AHRS-G300-A6-TMGA-C1-V1.1', 100, 5000),
        'sn_11ac0001_0009': Variant('sn_11ac0001_0009', 'AHRS s/n 11AC0001 - 11AC0009', 50, 10000),
        'g300_a2_tga': Variant('g300_a2_tga', 'AHRS-G300-A2-TGA-C1-V1.1', 100, 10000),
    }
)
"""Every known variant by name. g300_a2_tga: assumed, see erratum E11."""


class CalibrationType(IntEnum):
    """Named values (Table 6.14, Table 6.15)."""

    TWO_D = 1
    """2D calibration"""
    TWO_D_TWO_T = 2
    """2D-2T calibration"""
    THREE_D = 3
    """3D calibration"""


class CalibrationStatusType(IntEnum):
    """Named values (Table 6.17). Values above 0x80 mean calibrated by other software."""

    NOT_CALIBRATED = 0
    """The AHRS is not calibrated"""
    TWO_D = 1
    """2D calibration"""
    TWO_D_TWO_T = 2
    """2D-2T calibration"""
    THREE_D = 3
    """3D calibration"""

DATE_YEAR_MIN: Final = 1900
DATE_YEAR_MAX: Final = 2199
_DAYS: Final = (31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31)


def _days_in_month(year: int, month: int) -> int:
    leap = year % 4 == 0 and (year % 100 != 0 or year % 400 == 0)
    return 29 if month == 2 and leap else _DAYS[month - 1]


def date_is_valid(year: int, month: int, day: int) -> bool:
    """True for a calendar date with a year in DATE_YEAR_MIN..DATE_YEAR_MAX."""
    return DATE_YEAR_MIN <= year <= DATE_YEAR_MAX and 1 <= month <= 12 and 1 <= day <= _days_in_month(year, month)


def _encode(year: int, month: int, day: int) -> float:
    parts = {"year": year, "month": month, "day": day}
    return (parts['year'] + 0) / 1 + (parts['month'] + -1) / 12 + (parts['day'] + 0) / 365

def encode_date(year: int, month: int, day: int) -> float:
    """The date float of Table 6.9, Table 6.10, Table 6.13: Year + (Month - 1)/12 + Day/365, as a float."""
    if not date_is_valid(year, month, day):
        detail = f"{year:04d}-{month:02d}-{day:02d} is not a valid date"
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", detail)
    return _encode(year, month, day)


def decode_date(value: float) -> tuple[int, int, int]:
    """(year, month, day) of a date float: the valid date whose encoding is nearest (E15)."""
    if not math.isfinite(value) or not DATE_YEAR_MIN - 1 <= value <= DATE_YEAR_MAX + 2:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", f"{value!r} is not a date float")
    best: tuple[float, int, int, int] | None = None
    base = math.floor(value)
    for year in (base - 1, base):
        if not DATE_YEAR_MIN <= year <= DATE_YEAR_MAX:
            continue
        for month in range(1, 13):
            for day in range(1, _days_in_month(year, month) + 1):
                distance = abs(_encode(year, month, day) - value)
                if best is None or distance < best[0]:
                    best = (distance, year, month, day)
    if best is None:
        detail = f"{value!r} is outside the years {DATE_YEAR_MIN}..{DATE_YEAR_MAX}"
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", detail)
    return best[1], best[2], best[3]

DECLINATION_COMPUTE_ABOVE: Final = 360.0
"""A declination above this asks the AHRS to compute it from position and date (Table 6.9)."""
DECLINATION_COMPUTE: Final = 999.0
"""The value to send for "compute the declination"."""
DECLINATION_MIN: Final = -180.0
DECLINATION_MAX: Final = 180.0


def declination_is_computed(value: float) -> bool:
    """True if the AHRS computes the declination itself."""
    return value > DECLINATION_COMPUTE_ABOVE


def declination_is_valid(value: float) -> bool:
    """A declination in DECLINATION_MIN..DECLINATION_MAX, or the compute request; never NaN or infinite."""
    if not math.isfinite(value) or abs(value) > 3.4028234663852886e38:
        return False
    return DECLINATION_MIN <= value <= DECLINATION_MAX or value > DECLINATION_COMPUTE_ABOVE

CALIBRATION_FAILED: Final = 0
CALIBRATION_NO_ESTIMATE: Final = 255


def calibration_succeeded(success: int) -> bool:
    """The "Calibration success" byte says the calibration (or run) succeeded.

    Tables 6.14, 6.15, 6.17 and the notes below them.
    """
    return success != CALIBRATION_FAILED


def calibration_accuracy_deg(success: int) -> float | None:
    """The predicted 3-sigma heading error in degrees, or None (failed, or no estimate)."""
    if success in (CALIBRATION_FAILED, CALIBRATION_NO_ESTIMATE):
        return None
    return success / 10
