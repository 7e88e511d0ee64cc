# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""Device variants, the named values of the ICD, and its value encodings: date, declination and calibration
success, each described by the spec's numbers and bound to the code in `ilahrs.valuecodec`."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from enum import IntEnum
from types import MappingProxyType
from typing import Final

from .valuecodec import CalibrationSuccessEncoding, DateEncoding, DeclinationEncoding

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
        "g300_a2_tmga": Variant("g300_a2_tmga", "AHRS-G300-A2-TMGA-C1-V1.1", 100, 10000),
        "g300_a6_tmga": Variant("g300_a6_tmga", "AHRS-G300-A6-TMGA-C1-V1.1", 100, 5000),
        "sn_11ac0001_0009": Variant("sn_11ac0001_0009", "AHRS s/n 11AC0001 - 11AC0009", 50, 10000),
        "g300_a2_tga": Variant("g300_a2_tga", "AHRS-G300-A2-TGA-C1-V1.1", 100, 10000),
    }
)
"""Every known variant by name; the first is the default. g300_a2_tga: assumed, see erratum E11."""


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
DATE: Final = DateEncoding(
    DATE_YEAR_MIN,
    DATE_YEAR_MAX,
    (
        ("year", 0, 1),
        ("month", -1, 12),
        ("day", 0, 365),
    ),
)
"""The date float (Table 6.9, Table 6.10, Table 6.13): Year + (Month - 1)/12 + Day/365, as a float."""
date_is_valid: Final = DATE.is_valid
encode_date: Final = DATE.encode
decode_date: Final = DATE.decode

DECLINATION_COMPUTE_ABOVE: Final = 360.0
"""A declination above this asks the AHRS to compute it from position and date (Table 6.9)."""
DECLINATION_COMPUTE: Final = 999.0
"""The value to send for "compute the declination"."""
DECLINATION_MIN: Final = -180.0
DECLINATION_MAX: Final = 180.0
DECLINATION: Final = DeclinationEncoding(DECLINATION_MIN, DECLINATION_MAX, DECLINATION_COMPUTE_ABOVE)
declination_is_computed: Final = DECLINATION.is_computed
declination_is_valid: Final = DECLINATION.is_valid

CALIBRATION_FAILED: Final = 0
CALIBRATION_NO_ESTIMATE: Final = 255
CALIBRATION_SUCCESS: Final = CalibrationSuccessEncoding(CALIBRATION_FAILED, CALIBRATION_NO_ESTIMATE, 10)
"""The "Calibration success" byte (Tables 6.14, 6.15, 6.17 and the notes below them)."""
calibration_succeeded: Final = CALIBRATION_SUCCESS.succeeded
calibration_accuracy_deg: Final = CALIBRATION_SUCCESS.accuracy_deg
