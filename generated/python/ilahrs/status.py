# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""The Unit Status Word (6.5, Table 6.18, Table 6.19)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntFlag
from typing import Final

from .compat import StrEnum
from .errors import ErrorKind, IlahrsError, brief

__all__ = [
    "USW_FAILURE_FLAGS",
    "USW_MODES",
    "USW_MODE_MASK",
    "USW_WARNING_FLAGS",
    "UnitStatusWord",
    "UswFlag",
    "UswMode",
]


class UswFlag(IntFlag):
    """The status bits of the USW (mode bits excluded)."""

    INITIAL_ALIGNMENT_FAILED = 0x0001
    """Bit 0, failure byte (Initial Alignment): Unsuccessful initial alignment (AHRS moved or the magnetic
    field changed)."""
    PARAMETERS_INCORRECT = 0x0002
    """Bit 1, failure byte (AHRS Parameters): The AHRS parameters are incorrect."""
    GYRO_FAILURE = 0x0004
    """Bit 2, failure byte (Gyroscope Unit): Gyroscope unit failure detected."""
    ACCELEROMETER_FAILURE = 0x0008
    """Bit 3, failure byte (Accelerometer Unit): Accelerometer unit failure detected."""
    MAGNETOMETER_FAILURE = 0x0010
    """Bit 4, failure byte (Magnetometer Unit): Magnetometer unit failure detected."""
    ELECTRONICS_FAILURE = 0x0020
    """Bit 5, failure byte (Electronics): Electronics failure detected."""
    SOFTWARE_FAILURE = 0x0040
    """Bit 6, failure byte (Software): Software failure detected."""
    LOW_SUPPLY_VOLTAGE = 0x0100
    """Bit 8, warning byte (Incorrect Power Supply): Supply voltage below the minimum level."""
    HIGH_SUPPLY_VOLTAGE = 0x0200
    """Bit 9, warning byte (Incorrect Power Supply): Supply voltage above the maximum level."""
    X_RATE_EXCEEDED = 0x0400
    """Bit 10, warning byte (Angular Rate Exceeding Detect): X angular rate out of range."""
    Y_RATE_EXCEEDED = 0x0800
    """Bit 11, warning byte (Angular Rate Exceeding Detect): Y angular rate out of range."""
    Z_RATE_EXCEEDED = 0x1000
    """Bit 12, warning byte (Angular Rate Exceeding Detect): Z angular rate out of range."""
    LARGE_MAGNETIC_FIELD = 0x2000
    """Bit 13, warning byte (Large Magnetic Field Detect): Total magnetic field limit exceeded."""
    TEMPERATURE_OUT_OF_RANGE = 0x4000
    """Bit 14, warning byte (Environmental Temperature): Temperature outside the operating range."""


class UswMode(StrEnum):
    """The mode shown by USW bits 7 and 15 (Table 6.19)."""

    READINESS = "readiness"
    """Normal operation."""
    SLEEP = "sleep"
    """In the last data block the AHRS sends before it goes to Sleep mode."""
    UNKNOWN = "unknown"
    """A combination of mode bits the ICD does not define (E18)."""


USW_FAILURE_FLAGS: Final = UswFlag(0x007F)
"""The flags of the failure (low) byte."""
USW_WARNING_FLAGS: Final = UswFlag(0x7F00)
"""The flags of the warning (high) byte."""
USW_MODE_MASK: Final = 0x8080
USW_MODES: Final = {
    0x0000: UswMode.READINESS,
    0x8080: UswMode.SLEEP,
}
"""The mode bits of the USW (under USW_MODE_MASK) -> the mode they name."""


@dataclass(frozen=True, slots=True)
class UnitStatusWord:
    """A decoded USW. `raw` is the word as received (an integer: IlahrsError otherwise)."""

    raw: int

    def __post_init__(self) -> None:
        if isinstance(self.raw, bool) or not isinstance(self.raw, int):
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "usw", f"{brief(self.raw)} is not an integer")

    @property
    def flags(self) -> UswFlag:
        """Every status flag that is set."""
        return UswFlag(self.raw & (USW_FAILURE_FLAGS | USW_WARNING_FLAGS))

    @property
    def failures(self) -> UswFlag:
        """The failure flags that are set; empty when the AHRS operates correctly."""
        return UswFlag(self.raw & USW_FAILURE_FLAGS)

    @property
    def warnings(self) -> UswFlag:
        """The warning flags that are set."""
        return UswFlag(self.raw & USW_WARNING_FLAGS)

    @property
    def mode(self) -> UswMode:
        """The mode from bits 7 and 15."""
        return USW_MODES.get(self.raw & USW_MODE_MASK, UswMode.UNKNOWN)

    @property
    def ok(self) -> bool:
        """No failure flag is set."""
        return not self.failures

    @property
    def initial_alignment_failed(self) -> bool:
        """Bit 0: Unsuccessful initial alignment (AHRS moved or the magnetic field changed)."""
        return bool(self.raw & 0x0001)

    @property
    def parameters_incorrect(self) -> bool:
        """Bit 1: The AHRS parameters are incorrect."""
        return bool(self.raw & 0x0002)

    @property
    def gyro_failure(self) -> bool:
        """Bit 2: Gyroscope unit failure detected."""
        return bool(self.raw & 0x0004)

    @property
    def accelerometer_failure(self) -> bool:
        """Bit 3: Accelerometer unit failure detected."""
        return bool(self.raw & 0x0008)

    @property
    def magnetometer_failure(self) -> bool:
        """Bit 4: Magnetometer unit failure detected."""
        return bool(self.raw & 0x0010)

    @property
    def electronics_failure(self) -> bool:
        """Bit 5: Electronics failure detected."""
        return bool(self.raw & 0x0020)

    @property
    def software_failure(self) -> bool:
        """Bit 6: Software failure detected."""
        return bool(self.raw & 0x0040)

    @property
    def low_supply_voltage(self) -> bool:
        """Bit 8: Supply voltage below the minimum level."""
        return bool(self.raw & 0x0100)

    @property
    def high_supply_voltage(self) -> bool:
        """Bit 9: Supply voltage above the maximum level."""
        return bool(self.raw & 0x0200)

    @property
    def x_rate_exceeded(self) -> bool:
        """Bit 10: X angular rate out of range."""
        return bool(self.raw & 0x0400)

    @property
    def y_rate_exceeded(self) -> bool:
        """Bit 11: Y angular rate out of range."""
        return bool(self.raw & 0x0800)

    @property
    def z_rate_exceeded(self) -> bool:
        """Bit 12: Z angular rate out of range."""
        return bool(self.raw & 0x1000)

    @property
    def large_magnetic_field(self) -> bool:
        """Bit 13: Total magnetic field limit exceeded."""
        return bool(self.raw & 0x2000)

    @property
    def temperature_out_of_range(self) -> bool:
        """Bit 14: Temperature outside the operating range."""
        return bool(self.raw & 0x4000)
