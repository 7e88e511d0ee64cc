# Copied from generator/targets/python/runtime/valuecodec.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The value encodings the ICD defines: the date float, the declination that asks the AHRS to
compute it, and the calibration success byte. `ilahrs.encodings` describes each one with the
spec's numbers and binds these methods to its public functions (`encode_date`, ...)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final

from .errors import ErrorKind, IlahrsError, brief

__all__ = ["FLOAT32_MAX", "CalibrationSuccessEncoding", "DateEncoding", "DeclinationEncoding"]

FLOAT32_MAX: Final = 3.4028234663852886e38
"""The largest finite float32."""
_DAYS: Final = (31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31)


def _days_in_month(year: int, month: int) -> int:
    leap = year % 4 == 0 and (year % 100 != 0 or year % 400 == 0)
    return 29 if month == 2 and leap else _DAYS[month - 1]


@dataclass(frozen=True, slots=True)
class DateEncoding:
    """A date as one float: the sum of (part + offset) / divisor over `terms` (part is "year",
    "month" or "day"), for years `year_min`..`year_max`."""

    year_min: int
    year_max: int
    terms: tuple[tuple[str, int, int], ...]

    def is_valid(self, year: int, month: int, day: int) -> bool:
        """True for a calendar date with a year in DATE_YEAR_MIN..DATE_YEAR_MAX (integers only)."""
        if not all(isinstance(part, int) and not isinstance(part, bool) for part in (year, month, day)):
            return False
        return self.year_min <= year <= self.year_max and 1 <= month <= 12 and 1 <= day <= _days_in_month(year, month)

    def _value(self, year: int, month: int, day: int) -> float:
        parts = {"year": year, "month": month, "day": day}
        value = 0.0
        for part, offset, divisor in self.terms:
            value += (parts[part] + offset) / divisor
        return value

    def encode(self, year: int, month: int, day: int) -> float:
        """The date float of a calendar date; IlahrsError(OUT_OF_RANGE) for an invalid date."""
        if not self.is_valid(year, month, day):
            detail = f"{brief(year)}-{brief(month)}-{brief(day)} is not a valid date"
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", detail)
        return self._value(year, month, day)

    def decode(self, value: float) -> tuple[int, int, int]:
        """(year, month, day) of a date float: the valid date whose encoding is nearest (E15)."""
        numeric = isinstance(value, (int, float)) and not isinstance(value, bool)
        if not numeric or not self.year_min - 1 <= value <= self.year_max + 2 or not math.isfinite(value):
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", f"{brief(value)} is not a date float")
        best: tuple[float, int, int, int] | None = None
        base = math.floor(value)
        for year in (base - 1, base):
            if not self.year_min <= year <= self.year_max:
                continue
            for month in range(1, 13):
                for day in range(1, _days_in_month(year, month) + 1):
                    distance = abs(self._value(year, month, day) - value)
                    if best is None or distance < best[0]:
                        best = (distance, year, month, day)
        if best is None:
            detail = f"{value!r} is outside the years {self.year_min}..{self.year_max}"
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", detail)
        return best[1], best[2], best[3]


@dataclass(frozen=True, slots=True)
class DeclinationEncoding:
    """A magnetic declination in `low`..`high`, or any value above `compute_above`: "compute it"."""

    low: float
    high: float
    compute_above: float

    def is_computed(self, value: float) -> bool:
        """True if the AHRS computes the declination itself."""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "declination", f"{brief(value)} is not a number")
        return value > self.compute_above

    def is_valid(self, value: float) -> bool:
        """A declination in DECLINATION_MIN..DECLINATION_MAX, or the compute request; never NaN or infinite."""
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return False
        if isinstance(value, int):
            value = float(value) if value.bit_length() < 1024 else math.inf
        if not math.isfinite(value) or abs(value) > FLOAT32_MAX:
            return False
        return self.low <= value <= self.high or value > self.compute_above


@dataclass(frozen=True, slots=True)
class CalibrationSuccessEncoding:
    """The "Calibration success" byte: `failed`, `no_estimate` (successful, no accuracy), or the
    predicted 3-sigma heading error times `accuracy_divisor`."""

    failed: int
    no_estimate: int
    accuracy_divisor: int

    def succeeded(self, success: int) -> bool:
        """The "Calibration success" byte says the calibration (or run) succeeded."""
        return success != self.failed

    def accuracy_deg(self, success: int) -> float | None:
        """The predicted 3-sigma heading error in degrees, or None (failed, or no estimate)."""
        if isinstance(success, bool) or not isinstance(success, int):
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "success", f"{brief(success)} is not an integer")
        if not 0 <= success <= 0xFF:
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "success", f"{brief(success)} is not a byte")
        if success in (self.failed, self.no_estimate):
            return None
        return success / self.accuracy_divisor
