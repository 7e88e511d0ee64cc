# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""Every payload table as an immutable class with exact-inverse `parse` and `build`.

Fields hold raw wire values (integers as sent, floats as float32 values, char fields as text,
reserved bytes verbatim). Engineering values come from the `*_<unit>` accessors and `values()`.
Decoding never range-checks (every byte string of the right size decodes); `build()` and
`from_raw()` refuse out-of-range values with IlahrsError(OUT_OF_RANGE) naming the field.
Which table a 50- or 52-byte payload follows depends on context (E7): see the host session.
The code every class shares is `ilahrs.codec.PayloadBase`; a class holds its table.
"""

from __future__ import annotations

import struct
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import ClassVar, Final

from .codec import FLOAT32_MAX, FieldInfo, Payload, PayloadBase, required_variant, variant_of
from .encodings import Variant, calibration_accuracy_deg, declination_is_computed, decode_date
from .status import UnitStatusWord

__all__ = [
    "PAYLOADS",
    "Acknowledgement",
    "AhrsParametersLoad",
    "AhrsParametersRead",
    "BitResult",
    "CalibrationParameters",
    "CalibrationResult",
    "CalibrationRunParameters",
    "CalibrationRunResult",
    "CalibrationStatus",
    "FieldInfo",
    "FirmwareVersion",
    "FullOutput",
    "InitialAlignment",
    "OrientationSensors",
    "Payload",
    "Quaternion",
]


@dataclass(frozen=True, slots=True)
class FullOutput(PayloadBase):
    """Full Output Data (Table 6.4), 34 bytes, device to host.

    Output block after AHRScont1 / AHRSreq1.
    """

    NAME: ClassVar[str] = "full_output"
    ICD: ClassVar[str] = "Table 6.4"
    TITLE: ClassVar[str] = "Full Output Data"
    SIZE: ClassVar[int] = 34
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("heading", "Heading", 0, 2, "u16", "deg", 1, 100, 0, 35999),
        FieldInfo("pitch", "Pitch", 2, 2, "s16", "deg", 1, 100, -9000, 9000),
        FieldInfo("roll", "Roll", 4, 2, "s16", "deg", 1, 100, -18000, 18000),
        FieldInfo("ugyro_x", "Ugyro", 6, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("ugyro_y", "Ugyro", 8, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("ugyro_z", "Ugyro", 10, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("uacc_x", "Uacc", 12, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("uacc_y", "Uacc", 14, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("uacc_z", "Uacc", 16, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("umag_x", "Umag", 18, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("umag_y", "Umag", 20, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("umag_z", "Umag", 22, 2, "s16", "adc", 1, 1, -32768, 32767),
        FieldInfo("reserved", "Reserved", 24, 4, "reserved", None, 1, 1),
        FieldInfo("usw", "USW", 28, 2, "u16", None, 1, 1, 0, 65535, encoding="usw"),
        FieldInfo("vdd", "Vdd", 30, 2, "u16", "V", 1, 1000, 0, 65535, multiplexed=2),
        FieldInfo("utermo", "Utermo", 32, 2, "s16", "adc", 1, 1, -32768, 32767, multiplexed=7),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<Hhhhhhhhhhhh4sHHh")

    heading: int = 0
    """Heading angle. (u16, at offset 0, raw = deg x 100, range 0..35999, ICD: Heading; erratum E23)"""
    pitch: int = 0
    """Pitch angle. (s16, at offset 2, raw = deg x 100, range -9000..9000, ICD: Pitch)"""
    roll: int = 0
    """Roll angle. (s16, at offset 4, raw = deg x 100, range -18000..18000, ICD: Roll)"""
    ugyro_x: int = 0
    """Raw gyro X sensor data. (s16, at offset 6, unit adc, ICD: Ugyro)"""
    ugyro_y: int = 0
    """Raw gyro Y sensor data. (s16, at offset 8, unit adc, ICD: Ugyro)"""
    ugyro_z: int = 0
    """Raw gyro Z sensor data. (s16, at offset 10, unit adc, ICD: Ugyro)"""
    uacc_x: int = 0
    """Raw accelerometer X sensor data. (s16, at offset 12, unit adc, ICD: Uacc)"""
    uacc_y: int = 0
    """Raw accelerometer Y sensor data. (s16, at offset 14, unit adc, ICD: Uacc)"""
    uacc_z: int = 0
    """Raw accelerometer Z sensor data. (s16, at offset 16, unit adc, ICD: Uacc)"""
    umag_x: int = 0
    """Raw magnetometer X sensor data. (s16, at offset 18, unit adc, ICD: Umag)"""
    umag_y: int = 0
    """Raw magnetometer Y sensor data. (s16, at offset 20, unit adc, ICD: Umag)"""
    umag_z: int = 0
    """Raw magnetometer Z sensor data. (s16, at offset 22, unit adc, ICD: Umag)"""
    reserved: bytes = b"\x00" * 4
    """(reserved[4], at offset 24, ICD: Reserved)"""
    usw: int = 0
    """Unit Status Word (section 6.5). (u16, at offset 28, ICD: USW)"""
    vdd: int = 0
    """Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply
    voltage in turn (Table 6.4 note 2). The frame does not say which. (u16, at offset 30, raw = V x 1000,
    ICD: Vdd; erratum E19) Multiplexed: 2 quantities in successive frames."""
    utermo: int = 0
    """ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame
    does not say which. (s16, at offset 32, unit adc, ICD: Utermo; erratum E19) Multiplexed: 7 quantities
    in successive frames."""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields (heading, pitch, roll, vdd). The Unit Status Word is
        flags, not a scaled value: read `UnitStatusWord(block.usw)`."""
        variant_of(variant)
        result: dict[str, float] = {}
        result["heading"] = self.heading / 100
        result["pitch"] = self.pitch / 100
        result["roll"] = self.roll / 100
        result["vdd"] = self.vdd / 1000
        return result

    @property
    def heading_deg(self) -> float:
        """heading in degrees."""
        return self.heading / 100

    @property
    def pitch_deg(self) -> float:
        """pitch in degrees."""
        return self.pitch / 100

    @property
    def roll_deg(self) -> float:
        """roll in degrees."""
        return self.roll / 100

    @property
    def vdd_v(self) -> float:
        """vdd in volts DC."""
        return self.vdd / 1000

    @property
    def usw_status(self) -> UnitStatusWord:
        """usw decoded: flags and mode."""
        return UnitStatusWord(self.usw)


@dataclass(frozen=True, slots=True)
class Quaternion(PayloadBase):
    """Quaternion of Orientation (Table 6.5), 34 bytes, device to host.

    Output block after AHRScont2 / AHRSreq2.
    """

    NAME: ClassVar[str] = "quaternion"
    ICD: ClassVar[str] = "Table 6.5"
    TITLE: ClassVar[str] = "Quaternion of Orientation"
    SIZE: ClassVar[int] = 34
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("heading", "Heading", 0, 2, "u16", "deg", 1, 100, 0, 35999),
        FieldInfo("pitch", "Pitch", 2, 2, "s16", "deg", 1, 100, -9000, 9000),
        FieldInfo("roll", "Roll", 4, 2, "s16", "deg", 1, 100, -18000, 18000),
        FieldInfo("lk0", "Lk0", 6, 2, "s16", "one", 1, 10000, -10000, 10000),
        FieldInfo("lk1", "Lk1", 8, 2, "s16", "one", 1, 10000, -10000, 10000),
        FieldInfo("lk2", "Lk2", 10, 2, "s16", "one", 1, 10000, -10000, 10000),
        FieldInfo("lk3", "Lk3", 12, 2, "s16", "one", 1, 10000, -10000, 10000),
        FieldInfo("reserved", "Reserved", 14, 14, "reserved", None, 1, 1),
        FieldInfo("usw", "USW", 28, 2, "u16", None, 1, 1, 0, 65535, encoding="usw"),
        FieldInfo("vdd", "Vdd", 30, 2, "u16", "V", 1, 1000, 0, 65535),
        FieldInfo("utermo", "Utermo", 32, 2, "s16", "degC", 1, 10, -32768, 32767),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<Hhhhhhh14sHHh")

    heading: int = 0
    """Heading angle. (u16, at offset 0, raw = deg x 100, range 0..35999, ICD: Heading; erratum E23)"""
    pitch: int = 0
    """Pitch angle. (s16, at offset 2, raw = deg x 100, range -9000..9000, ICD: Pitch)"""
    roll: int = 0
    """Roll angle. (s16, at offset 4, raw = deg x 100, range -18000..18000, ICD: Roll)"""
    lk0: int = 0
    """Quaternion of orientation, scalar component. (s16, at offset 6, raw = value x 10000, range
    -10000..10000, ICD: Lk0)"""
    lk1: int = 0
    """Quaternion of orientation, first vector component. (s16, at offset 8, raw = value x 10000, range
    -10000..10000, ICD: Lk1)"""
    lk2: int = 0
    """Quaternion of orientation, second vector component. (s16, at offset 10, raw = value x 10000, range
    -10000..10000, ICD: Lk2)"""
    lk3: int = 0
    """Quaternion of orientation, third vector component. (s16, at offset 12, raw = value x 10000, range
    -10000..10000, ICD: Lk3)"""
    reserved: bytes = b"\x00" * 14
    """(reserved[14], at offset 14, ICD: Reserved)"""
    usw: int = 0
    """Unit Status Word (section 6.5). (u16, at offset 28, ICD: USW)"""
    vdd: int = 0
    """AHRS input voltage. (u16, at offset 30, raw = V x 1000, ICD: Vdd)"""
    utermo: int = 0
    """Average temperature of the 3 accelerometers. (s16, at offset 32, raw = degC x 10, ICD: Utermo)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields (heading, pitch, roll, lk0, lk1, lk2, lk3, vdd, utermo).
        The Unit Status Word is flags, not a scaled value: read `UnitStatusWord(block.usw)`."""
        variant_of(variant)
        result: dict[str, float] = {}
        result["heading"] = self.heading / 100
        result["pitch"] = self.pitch / 100
        result["roll"] = self.roll / 100
        result["lk0"] = self.lk0 / 10000
        result["lk1"] = self.lk1 / 10000
        result["lk2"] = self.lk2 / 10000
        result["lk3"] = self.lk3 / 10000
        result["vdd"] = self.vdd / 1000
        result["utermo"] = self.utermo / 10
        return result

    @property
    def heading_deg(self) -> float:
        """heading in degrees."""
        return self.heading / 100

    @property
    def pitch_deg(self) -> float:
        """pitch in degrees."""
        return self.pitch / 100

    @property
    def roll_deg(self) -> float:
        """roll in degrees."""
        return self.roll / 100

    @property
    def lk0_value(self) -> float:
        """lk0 in dimensionless."""
        return self.lk0 / 10000

    @property
    def lk1_value(self) -> float:
        """lk1 in dimensionless."""
        return self.lk1 / 10000

    @property
    def lk2_value(self) -> float:
        """lk2 in dimensionless."""
        return self.lk2 / 10000

    @property
    def lk3_value(self) -> float:
        """lk3 in dimensionless."""
        return self.lk3 / 10000

    @property
    def vdd_v(self) -> float:
        """vdd in volts DC."""
        return self.vdd / 1000

    @property
    def utermo_degc(self) -> float:
        """utermo in degrees Celsius."""
        return self.utermo / 10

    @property
    def usw_status(self) -> UnitStatusWord:
        """usw decoded: flags and mode."""
        return UnitStatusWord(self.usw)


@dataclass(frozen=True, slots=True)
class OrientationSensors(PayloadBase):
    """Orientation + Sensor Outputs (Table 6.6), 34 bytes, device to host.

    Output block after AHRScont3 / AHRSreq3 (the default format, section 6.2).
    """

    NAME: ClassVar[str] = "orientation_sensors"
    ICD: ClassVar[str] = "Table 6.6"
    TITLE: ClassVar[str] = "Orientation + Sensor Outputs"
    SIZE: ClassVar[int] = 34
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("heading", "Heading", 0, 2, "u16", "deg", 1, 100, 0, 35999),
        FieldInfo("pitch", "Pitch", 2, 2, "s16", "deg", 1, 100, -9000, 9000),
        FieldInfo("roll", "Roll", 4, 2, "s16", "deg", 1, 100, -18000, 18000),
        FieldInfo("gyro_x", "GyroX", 6, 2, "s16", "deg_per_s", 1, "kg", -32768, 32767),
        FieldInfo("gyro_y", "GyroY", 8, 2, "s16", "deg_per_s", 1, "kg", -32768, 32767),
        FieldInfo("gyro_z", "GyroZ", 10, 2, "s16", "deg_per_s", 1, "kg", -32768, 32767),
        FieldInfo("acc_x", "AccX", 12, 2, "s16", "g", 1, "ka", -32768, 32767),
        FieldInfo("acc_y", "AccY", 14, 2, "s16", "g", 1, "ka", -32768, 32767),
        FieldInfo("acc_z", "AccZ", 16, 2, "s16", "g", 1, "ka", -32768, 32767),
        FieldInfo("mag_x", "MagX", 18, 2, "s16", "nT", 10, 1, -32768, 32767),
        FieldInfo("mag_y", "MagY", 20, 2, "s16", "nT", 10, 1, -32768, 32767),
        FieldInfo("mag_z", "MagZ", 22, 2, "s16", "nT", 10, 1, -32768, 32767),
        FieldInfo("reserved", "Reserved", 24, 4, "reserved", None, 1, 1),
        FieldInfo("usw", "USW", 28, 2, "u16", None, 1, 1, 0, 65535, encoding="usw"),
        FieldInfo("vdd", "Vdd", 30, 2, "u16", "V", 1, 1000, 0, 65535),
        FieldInfo("utermo", "Utermo", 32, 2, "s16", "degC", 1, 10, -32768, 32767),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<Hhhhhhhhhhhh4sHHh")

    heading: int = 0
    """Heading angle. (u16, at offset 0, raw = deg x 100, range 0..35999, ICD: Heading; erratum E23)"""
    pitch: int = 0
    """Pitch angle. (s16, at offset 2, raw = deg x 100, range -9000..9000, ICD: Pitch)"""
    roll: int = 0
    """Roll angle. (s16, at offset 4, raw = deg x 100, range -18000..18000, ICD: Roll)"""
    gyro_x: int = 0
    """Angular rate about X (lateral axis). (s16, at offset 6, raw = deg_per_s x KG, ICD: GyroX)"""
    gyro_y: int = 0
    """Angular rate about Y (longitudinal axis). (s16, at offset 8, raw = deg_per_s x KG, ICD: GyroY)"""
    gyro_z: int = 0
    """Angular rate about Z (vertical axis). (s16, at offset 10, raw = deg_per_s x KG, ICD: GyroZ)"""
    acc_x: int = 0
    """Linear acceleration along X. (s16, at offset 12, raw = g x KA, ICD: AccX)"""
    acc_y: int = 0
    """Linear acceleration along Y. (s16, at offset 14, raw = g x KA, ICD: AccY)"""
    acc_z: int = 0
    """Linear acceleration along Z. (s16, at offset 16, raw = g x KA, ICD: AccZ)"""
    mag_x: int = 0
    """Magnetic field along X. (s16, at offset 18, raw = nT / 10, ICD: MagX)"""
    mag_y: int = 0
    """Magnetic field along Y. (s16, at offset 20, raw = nT / 10, ICD: MagY)"""
    mag_z: int = 0
    """Magnetic field along Z. (s16, at offset 22, raw = nT / 10, ICD: MagZ)"""
    reserved: bytes = b"\x00" * 4
    """(reserved[4], at offset 24, ICD: Reserved)"""
    usw: int = 0
    """Unit Status Word (section 6.5). (u16, at offset 28, ICD: USW)"""
    vdd: int = 0
    """AHRS input voltage. (u16, at offset 30, raw = V x 1000, ICD: Vdd)"""
    utermo: int = 0
    """Average temperature of the 3 accelerometers. (s16, at offset 32, raw = degC x 10, ICD: Utermo)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields (heading, pitch, roll, gyro_x, gyro_y, gyro_z, acc_x,
        acc_y, acc_z, mag_x, mag_y, mag_z, vdd, utermo). Without a `variant` (a Variant or its name)
        gyro_x, gyro_y, gyro_z, acc_x, acc_y, acc_z are left out: their scale is the variant's (Table 6.6
        note 1). The Unit Status Word is flags, not a scaled value: read `UnitStatusWord(block.usw)`."""
        variant = variant_of(variant)
        result: dict[str, float] = {}
        result["heading"] = self.heading / 100
        result["pitch"] = self.pitch / 100
        result["roll"] = self.roll / 100
        if variant is not None:
            result["gyro_x"] = self.gyro_x / variant.kg
        if variant is not None:
            result["gyro_y"] = self.gyro_y / variant.kg
        if variant is not None:
            result["gyro_z"] = self.gyro_z / variant.kg
        if variant is not None:
            result["acc_x"] = self.acc_x / variant.ka
        if variant is not None:
            result["acc_y"] = self.acc_y / variant.ka
        if variant is not None:
            result["acc_z"] = self.acc_z / variant.ka
        result["mag_x"] = float(self.mag_x * 10)
        result["mag_y"] = float(self.mag_y * 10)
        result["mag_z"] = float(self.mag_z * 10)
        result["vdd"] = self.vdd / 1000
        result["utermo"] = self.utermo / 10
        return result

    @property
    def heading_deg(self) -> float:
        """heading in degrees."""
        return self.heading / 100

    @property
    def pitch_deg(self) -> float:
        """pitch in degrees."""
        return self.pitch / 100

    @property
    def roll_deg(self) -> float:
        """roll in degrees."""
        return self.roll / 100

    def gyro_x_dps(self, variant: Variant | str) -> float:
        """gyro_x in degrees per second for `variant`, a Variant or its name (raw / variant.kg)."""
        variant = required_variant(variant)
        return self.gyro_x / variant.kg

    def gyro_y_dps(self, variant: Variant | str) -> float:
        """gyro_y in degrees per second for `variant`, a Variant or its name (raw / variant.kg)."""
        variant = required_variant(variant)
        return self.gyro_y / variant.kg

    def gyro_z_dps(self, variant: Variant | str) -> float:
        """gyro_z in degrees per second for `variant`, a Variant or its name (raw / variant.kg)."""
        variant = required_variant(variant)
        return self.gyro_z / variant.kg

    def acc_x_g(self, variant: Variant | str) -> float:
        """acc_x in standard gravity for `variant`, a Variant or its name (raw / variant.ka)."""
        variant = required_variant(variant)
        return self.acc_x / variant.ka

    def acc_y_g(self, variant: Variant | str) -> float:
        """acc_y in standard gravity for `variant`, a Variant or its name (raw / variant.ka)."""
        variant = required_variant(variant)
        return self.acc_y / variant.ka

    def acc_z_g(self, variant: Variant | str) -> float:
        """acc_z in standard gravity for `variant`, a Variant or its name (raw / variant.ka)."""
        variant = required_variant(variant)
        return self.acc_z / variant.ka

    @property
    def mag_x_nt(self) -> float:
        """mag_x in nanotesla."""
        return float(self.mag_x * 10)

    @property
    def mag_y_nt(self) -> float:
        """mag_y in nanotesla."""
        return float(self.mag_y * 10)

    @property
    def mag_z_nt(self) -> float:
        """mag_z in nanotesla."""
        return float(self.mag_z * 10)

    @property
    def vdd_v(self) -> float:
        """vdd in volts DC."""
        return self.vdd / 1000

    @property
    def utermo_degc(self) -> float:
        """utermo in degrees Celsius."""
        return self.utermo / 10

    @property
    def usw_status(self) -> UnitStatusWord:
        """usw decoded: flags and mode."""
        return UnitStatusWord(self.usw)


@dataclass(frozen=True, slots=True)
class InitialAlignment(PayloadBase):
    """Initial alignment data (Table 6.8), 50 bytes, device to host.

    Sent once when initial alignment completes, before continuous / on-request output or a calibration run
    starts (6.3.1 - 6.3.3, 6.4). Note the ICD order: heading, roll, pitch.
    """

    NAME: ClassVar[str] = "initial_alignment"
    ICD: ClassVar[str] = "Table 6.8"
    TITLE: ClassVar[str] = "Initial alignment data"
    SIZE: ClassVar[int] = 50
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("gyro_bias_x", "Gyros bias", 0, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("gyro_bias_y", "Gyros bias", 4, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("gyro_bias_z", "Gyros bias", 8, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("average_acc_x", "Average acceleration", 12, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("average_acc_y", "Average acceleration", 16, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("average_acc_z", "Average acceleration", 20, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("average_mag_x", "Average magn. field", 24, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("average_mag_y", "Average magn. field", 28, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("average_mag_z", "Average magn. field", 32, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("initial_heading", "Initial Heading", 36, 4, "f32", "deg", 1, 1, 0.0, 360.0),
        FieldInfo("initial_roll", "Initial Roll", 40, 4, "f32", "deg", 1, 1, -180.0, 180.0),
        FieldInfo("initial_pitch", "Initial Pitch", 44, 4, "f32", "deg", 1, 1, -90.0, 90.0),
        FieldInfo("usw", "USW", 48, 2, "u16", None, 1, 1, 0, 65535, encoding="usw"),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<ffffffffffffH")

    gyro_bias_x: float = 0.0
    """Gyro X bias. (f32, at offset 0, unit adc, ICD: Gyros bias)"""
    gyro_bias_y: float = 0.0
    """Gyro Y bias. (f32, at offset 4, unit adc, ICD: Gyros bias)"""
    gyro_bias_z: float = 0.0
    """Gyro Z bias. (f32, at offset 8, unit adc, ICD: Gyros bias)"""
    average_acc_x: float = 0.0
    """Average acceleration along X. (f32, at offset 12, unit adc, ICD: Average acceleration)"""
    average_acc_y: float = 0.0
    """Average acceleration along Y. (f32, at offset 16, unit adc, ICD: Average acceleration)"""
    average_acc_z: float = 0.0
    """Average acceleration along Z. (f32, at offset 20, unit adc, ICD: Average acceleration)"""
    average_mag_x: float = 0.0
    """Average magnetic field along X. (f32, at offset 24, unit adc, ICD: Average magn. field)"""
    average_mag_y: float = 0.0
    """Average magnetic field along Y. (f32, at offset 28, unit adc, ICD: Average magn. field)"""
    average_mag_z: float = 0.0
    """Average magnetic field along Z. (f32, at offset 32, unit adc, ICD: Average magn. field)"""
    initial_heading: float = 0.0
    """Heading at the end of alignment. (f32, at offset 36, unit deg, range 0..360, ICD: Initial Heading)"""
    initial_roll: float = 0.0
    """Roll at the end of alignment. (f32, at offset 40, unit deg, range -180..180, ICD: Initial Roll)"""
    initial_pitch: float = 0.0
    """Pitch at the end of alignment. (f32, at offset 44, unit deg, range -90..90, ICD: Initial Pitch)"""
    usw: int = 0
    """Unit Status Word: 0 after a successful alignment, non-zero otherwise. (u16, at offset 48, ICD: USW;
    erratum E27)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields (). The Unit Status Word is flags, not a scaled value:
        read `UnitStatusWord(block.usw)`."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def usw_status(self) -> UnitStatusWord:
        """usw decoded: flags and mode."""
        return UnitStatusWord(self.usw)


@dataclass(frozen=True, slots=True)
class AhrsParametersLoad(PayloadBase):
    """Parameters to load (Table 6.9), 50 bytes, host to device.

    The data message the host sends right after LoadAHRSPar (6.3.6). Read the block first (ReadAHRSPar),
    change it, send it back.
    """

    NAME: ClassVar[str] = "ahrs_parameters_load"
    ICD: ClassVar[str] = "Table 6.9"
    TITLE: ClassVar[str] = "Parameters to load"
    SIZE: ClassVar[int] = 50
    DIRECTION: ClassVar[str] = "host_to_device"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("update_rate", "Update rate", 0, 2, "u16", "Hz", 1, 1, 1, 100),
        FieldInfo("alignment_time", "Initial alignment time", 2, 2, "u16", "s", 1, 1, 1, 65535),
        FieldInfo(
            "declination",
            "Magnetic declination, Mdec",
            4,
            4,
            "f32",
            "deg",
            1,
            1,
            -FLOAT32_MAX,
            FLOAT32_MAX,
            encoding="declination",
        ),
        FieldInfo("latitude", "Latitude", 8, 4, "f32", "deg", 1, 1, -90.0, 90.0),
        FieldInfo("longitude", "Longitude", 12, 4, "f32", "deg", 1, 1, -180.0, 180.0),
        FieldInfo("altitude", "Altitude", 16, 4, "f32", "m", 1, 1, -20000.0, 100000.0),
        FieldInfo(
            "date",
            "Date (Year, Month, Day)",
            20,
            4,
            "f32",
            "year",
            1,
            1,
            1900.002685546875,
            2200.001708984375,
            encoding="date",
        ),
        FieldInfo("alignment_angle_a1", "Alignment angle A1", 24, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("alignment_angle_a2", "Alignment angle A2", 28, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("alignment_angle_a3", "Alignment angle A3", 32, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("reserved", "Reserved", 36, 14, "reserved", None, 1, 1),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<HHffffffff14s")

    update_rate: int = 100
    """Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz). (u16, at offset 0, unit Hz,
    range 1..100, ICD: Update rate; erratum E22)"""
    alignment_time: int = 30
    """Initial alignment duration; default 30 s, change only in agreement with Inertial Labs. (u16, at offset
    2, unit s, range 1..65535, ICD: Initial alignment time; erratum E30)"""
    declination: float = 0.0
    """Magnetic declination; a value above 360 asks the AHRS to compute it from position and date. (f32, at
    offset 4, unit deg, ICD: Magnetic declination, Mdec)"""
    latitude: float = 0.0
    """Latitude. (f32, at offset 8, unit deg, range -90..90, ICD: Latitude)"""
    longitude: float = 0.0
    """Longitude. (f32, at offset 12, unit deg, range -180..180, ICD: Longitude)"""
    altitude: float = 0.0
    """Altitude. (f32, at offset 16, unit m, range -20000..100000, ICD: Altitude; erratum E31)"""
    date: float = 1900.002685546875
    """Date as Year + (Month - 1)/12 + Day/365. (f32, at offset 20, unit year, range
    1900.002685546875..2200.001708984375, ICD: Date (Year, Month, Day))"""
    alignment_angle_a1: float = 0.0
    """Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its horizontal plane,
    clockwise positive (Appendix B). (f32, at offset 24, unit deg, range -360..360, ICD: Alignment angle
    A1; erratum E31)"""
    alignment_angle_a2: float = 0.0
    """Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up positive
    (Appendix B). (f32, at offset 28, unit deg, range -360..360, ICD: Alignment angle A2; erratum E31)"""
    alignment_angle_a3: float = 0.0
    """Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive (Appendix B). (f32,
    at offset 32, unit deg, range -360..360, ICD: Alignment angle A3; erratum E31)"""
    reserved: bytes = b"\x00" * 14
    """Should be all zeros. (reserved[14], at offset 36, ICD: Reserved)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def declination_computed(self) -> bool:
        """True if the AHRS computes the declination itself (value above the threshold)."""
        return declination_is_computed(self.declination)

    @property
    def date_ymd(self) -> tuple[int, int, int]:
        """date as (year, month, day) (E15)."""
        return decode_date(self.date)


@dataclass(frozen=True, slots=True)
class AhrsParametersRead(PayloadBase):
    """Parameters read (Table 6.10), 50 bytes, device to host.

    The AHRS answer to ReadAHRSPar (6.3.7).
    """

    NAME: ClassVar[str] = "ahrs_parameters_read"
    ICD: ClassVar[str] = "Table 6.10"
    TITLE: ClassVar[str] = "Parameters read"
    SIZE: ClassVar[int] = 50
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("update_rate", "Measurement rate", 0, 2, "u16", "Hz", 1, 1, 1, 100),
        FieldInfo("alignment_time", "Initial alignment time", 2, 2, "u16", "s", 1, 1, 1, 65535),
        FieldInfo(
            "declination",
            "Magnetic declination",
            4,
            4,
            "f32",
            "deg",
            1,
            1,
            -FLOAT32_MAX,
            FLOAT32_MAX,
            encoding="declination",
        ),
        FieldInfo("latitude", "Latitude", 8, 4, "f32", "deg", 1, 1, -90.0, 90.0),
        FieldInfo("longitude", "Longitude", 12, 4, "f32", "deg", 1, 1, -180.0, 180.0),
        FieldInfo("altitude", "Altitude", 16, 4, "f32", "m", 1, 1, -20000.0, 100000.0),
        FieldInfo(
            "date",
            "Date (Year, Month, Day)",
            20,
            4,
            "f32",
            "year",
            1,
            1,
            1900.002685546875,
            2200.001708984375,
            encoding="date",
        ),
        FieldInfo("alignment_angle_a1", "Alignment angle A1", 24, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("alignment_angle_a2", "Alignment angle A2", 28, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("alignment_angle_a3", "Alignment angle A3", 32, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("device_id", "Device ID", 36, 8, "char", None, 1, 1),
        FieldInfo("reserved", "Reserved", 44, 6, "reserved", None, 1, 1),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<HHffffffff8s6s")

    update_rate: int = 1
    """Output data rate. (u16, at offset 0, unit Hz, range 1..100, ICD: Measurement rate; erratum E24)"""
    alignment_time: int = 1
    """Initial alignment duration. (u16, at offset 2, unit s, range 1..65535, ICD: Initial alignment time;
    erratum E30)"""
    declination: float = 0.0
    """Magnetic declination; a value above 360 means the AHRS computes it. (f32, at offset 4, unit deg, ICD:
    Magnetic declination)"""
    latitude: float = 0.0
    """Latitude. (f32, at offset 8, unit deg, range -90..90, ICD: Latitude)"""
    longitude: float = 0.0
    """Longitude. (f32, at offset 12, unit deg, range -180..180, ICD: Longitude)"""
    altitude: float = 0.0
    """Altitude. (f32, at offset 16, unit m, range -20000..100000, ICD: Altitude; erratum E31)"""
    date: float = 1900.002685546875
    """Date as Year + (Month - 1)/12 + Day/365. (f32, at offset 20, unit year, range
    1900.002685546875..2200.001708984375, ICD: Date (Year, Month, Day))"""
    alignment_angle_a1: float = 0.0
    """Mounting angle 1 (Appendix B). (f32, at offset 24, unit deg, range -360..360, ICD: Alignment angle A1;
    erratum E31)"""
    alignment_angle_a2: float = 0.0
    """Mounting angle 2 (Appendix B). (f32, at offset 28, unit deg, range -360..360, ICD: Alignment angle A2;
    erratum E31)"""
    alignment_angle_a3: float = 0.0
    """Mounting angle 3 (Appendix B). (f32, at offset 32, unit deg, range -360..360, ICD: Alignment angle A3;
    erratum E31)"""
    device_id: str = ""
    """Device identifier (read only). (char[8], at offset 36, ICD: Device ID)"""
    reserved: bytes = b"\x00" * 6
    """(reserved[6], at offset 44, ICD: Reserved)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def declination_computed(self) -> bool:
        """True if the AHRS computes the declination itself (value above the threshold)."""
        return declination_is_computed(self.declination)

    @property
    def date_ymd(self) -> tuple[int, int, int]:
        """date as (year, month, day) (E15)."""
        return decode_date(self.date)


@dataclass(frozen=True, slots=True)
class FirmwareVersion(PayloadBase):
    """Firmware version (Table 6.11), 50 bytes, device to host.

    The AHRS answer to GetVerFirmware (6.3.10).
    """

    NAME: ClassVar[str] = "firmware_version"
    ICD: ClassVar[str] = "Table 6.11"
    TITLE: ClassVar[str] = "Firmware version"
    SIZE: ClassVar[int] = 50
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (FieldInfo("version", "Firmware version", 0, 50, "char", None, 1, 1),)
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<50s")

    version: str = ""
    """Firmware version text, NUL-padded. (char[50], at offset 0, ICD: Firmware version)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result


@dataclass(frozen=True, slots=True)
class BitResult(PayloadBase):
    """Built-in test answer (Table 6.12), 4 bytes, device to host.

    The AHRS answer to GetBIT (6.3.11).
    """

    NAME: ClassVar[str] = "bit_result"
    ICD: ClassVar[str] = "Table 6.12"
    TITLE: ClassVar[str] = "Built-in test answer"
    SIZE: ClassVar[int] = 4
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("utermo100", "Utermo100", 0, 2, "s16", "degC", 1, 100, -32768, 32767),
        FieldInfo("usw", "USW", 2, 2, "u16", None, 1, 1, 0, 65535, encoding="usw"),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<hH")

    utermo100: int = 0
    """AHRS temperature in 1/100 degC. (s16, at offset 0, raw = degC x 100, ICD: Utermo100; erratum E4)"""
    usw: int = 0
    """Unit Status Word (section 6.5). (u16, at offset 2, ICD: USW)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields (utermo100). The Unit Status Word is flags, not a scaled
        value: read `UnitStatusWord(block.usw)`."""
        variant_of(variant)
        result: dict[str, float] = {}
        result["utermo100"] = self.utermo100 / 100
        return result

    @property
    def utermo100_degc(self) -> float:
        """utermo100 in degrees Celsius."""
        return self.utermo100 / 100

    @property
    def usw_status(self) -> UnitStatusWord:
        """usw decoded: flags and mode."""
        return UnitStatusWord(self.usw)


@dataclass(frozen=True, slots=True)
class CalibrationParameters(PayloadBase):
    """Calibration parameters (Table 6.13), 22 bytes, host to device.

    The data message the host sends right after Start3DClb, Start2D2TClb or Start2DClb (6.4.1, 6.4.5,
    6.4.8).
    """

    NAME: ClassVar[str] = "calibration_parameters"
    ICD: ClassVar[str] = "Table 6.13"
    TITLE: ClassVar[str] = "Calibration parameters"
    SIZE: ClassVar[int] = 22
    DIRECTION: ClassVar[str] = "host_to_device"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("reference_azimuth", "Reserved", 0, 4, "f32", "deg", 1, 1, -360.0, 360.0),
        FieldInfo("accumulation_time", "Time of data accumulation in one run", 4, 2, "u16", "s", 1, 1, 1, 65535),
        FieldInfo("latitude", "Latitude", 6, 4, "f32", "deg", 1, 1, -90.0, 90.0),
        FieldInfo("longitude", "Longitude", 10, 4, "f32", "deg", 1, 1, -180.0, 180.0),
        FieldInfo("altitude", "Altitude", 14, 4, "f32", "m", 1, 1, -20000.0, 100000.0),
        FieldInfo(
            "date",
            "Date (Year, Month, Day)",
            18,
            4,
            "f32",
            "year",
            1,
            1,
            1900.002685546875,
            2200.001708984375,
            encoding="date",
        ),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<fHffff")

    reference_azimuth: float = 0.0
    """Reference azimuth (6.4.8); no influence on 2D calibration. (f32, at offset 0, unit deg, range
    -360..360, ICD: Reserved; erratum E8)"""
    accumulation_time: int = 1
    """Data accumulation time of one run. (u16, at offset 4, unit s, range 1..65535, ICD: Time of data
    accumulation in one run; erratum E30)"""
    latitude: float = 0.0
    """Latitude. (f32, at offset 6, unit deg, range -90..90, ICD: Latitude)"""
    longitude: float = 0.0
    """Longitude. (f32, at offset 10, unit deg, range -180..180, ICD: Longitude)"""
    altitude: float = 0.0
    """Altitude. (f32, at offset 14, unit m, range -20000..100000, ICD: Altitude; erratum E31)"""
    date: float = 1900.002685546875
    """Date as Year + (Month - 1)/12 + Day/365. (f32, at offset 18, unit year, range
    1900.002685546875..2200.001708984375, ICD: Date (Year, Month, Day))"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def date_ymd(self) -> tuple[int, int, int]:
        """date as (year, month, day) (E15)."""
        return decode_date(self.date)


@dataclass(frozen=True, slots=True)
class CalibrationResult(PayloadBase):
    """Calibration result (Table 6.14), 52 bytes, device to host.

    Sent when a calibration completes (after the accumulation time, StopClbRun, or FinishClb).
    """

    NAME: ClassVar[str] = "calibration_result"
    ICD: ClassVar[str] = "Table 6.14"
    TITLE: ClassVar[str] = "Calibration result"
    SIZE: ClassVar[int] = 52
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("calibration_type", "Type of calibration", 0, 1, "u8", None, 1, 1, 1, 3),
        FieldInfo("runs_used", "Number of used calibration runs", 1, 1, "u8", None, 1, 1, 0, 255),
        FieldInfo("data_used", "Percent of used data points", 2, 1, "u8", "percent", 1, 1, 0, 100),
        FieldInfo("success", "Calibration success", 3, 1, "u8", None, 1, 1, 0, 255, encoding="calibration_success"),
        FieldInfo("tm_c_11", "Matrix for soft iron correction", 4, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_12", "Matrix for soft iron correction", 8, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_13", "Matrix for soft iron correction", 12, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_21", "Matrix for soft iron correction", 16, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_22", "Matrix for soft iron correction", 20, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_23", "Matrix for soft iron correction", 24, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_31", "Matrix for soft iron correction", 28, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_32", "Matrix for soft iron correction", 32, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_33", "Matrix for soft iron correction", 36, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("hm_0_x", "Matrix for hard iron correction", 40, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("hm_0_y", "Matrix for hard iron correction", 44, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("hm_0_z", "Matrix for hard iron correction", 48, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<BBBBffffffffffff")

    calibration_type: int = 1
    """1 for 2D, 2 for 2D-2T, 3 for 3D calibration. (u8, at offset 0, range 1..3, ICD: Type of calibration)"""
    runs_used: int = 0
    """Number of calibration runs used. (u8, at offset 1, ICD: Number of used calibration runs)"""
    data_used: int = 0
    """Percent of data points used (2D and 3D calibrations only). (u8, at offset 2, unit percent, range
    0..100, ICD: Percent of used data points)"""
    success: int = 0
    """0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful without an
    estimate. (u8, at offset 3, ICD: Calibration success; erratum E26)"""
    tm_c_11: float = 0.0
    """Soft-iron matrix Tm_c row 1 column 1. (f32, at offset 4, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_12: float = 0.0
    """Soft-iron matrix Tm_c row 1 column 2. (f32, at offset 8, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_13: float = 0.0
    """Soft-iron matrix Tm_c row 1 column 3. (f32, at offset 12, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_21: float = 0.0
    """Soft-iron matrix Tm_c row 2 column 1. (f32, at offset 16, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_22: float = 0.0
    """Soft-iron matrix Tm_c row 2 column 2. (f32, at offset 20, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_23: float = 0.0
    """Soft-iron matrix Tm_c row 2 column 3. (f32, at offset 24, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_31: float = 0.0
    """Soft-iron matrix Tm_c row 3 column 1. (f32, at offset 28, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_32: float = 0.0
    """Soft-iron matrix Tm_c row 3 column 2. (f32, at offset 32, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_33: float = 0.0
    """Soft-iron matrix Tm_c row 3 column 3. (f32, at offset 36, unit one, ICD: Matrix for soft iron
    correction)"""
    hm_0_x: float = 0.0
    """Hard-iron vector Hm_0 component 1. (f32, at offset 40, unit adc, ICD: Matrix for hard iron correction;
    erratum E1)"""
    hm_0_y: float = 0.0
    """Hard-iron vector Hm_0 component 2. (f32, at offset 44, unit adc, ICD: Matrix for hard iron correction;
    erratum E1)"""
    hm_0_z: float = 0.0
    """Hard-iron vector Hm_0 component 3. (f32, at offset 48, unit adc, ICD: Matrix for hard iron correction;
    erratum E1)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def success_accuracy_deg(self) -> float | None:
        """Predicted 3-sigma heading error in degrees, or None (failed, or no estimate)."""
        return calibration_accuracy_deg(self.success)


@dataclass(frozen=True, slots=True)
class CalibrationRunResult(PayloadBase):
    """2D-2T calibration run result (Table 6.15), 30 bytes, device to host.

    Sent after each run of a 2D-2T calibration (6.4.5).
    """

    NAME: ClassVar[str] = "calibration_run_result"
    ICD: ClassVar[str] = "Table 6.15"
    TITLE: ClassVar[str] = "2D-2T calibration run result"
    SIZE: ClassVar[int] = 30
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("calibration_type", "Type of calibration", 0, 1, "u8", None, 1, 1, 2, 2),
        FieldInfo("run", "Calibration run", 1, 1, "u8", None, 1, 1, 1, 255),
        FieldInfo("data_used", "Percent of used data points", 2, 1, "u8", "percent", 1, 1, 0, 100),
        FieldInfo("success", "Calibration success", 3, 1, "u8", None, 1, 1, 0, 255, encoding="calibration_success"),
        FieldInfo("reserved_1", "Reserved", 4, 4, "reserved", None, 1, 1),
        FieldInfo("average_pitch", "Average pitch, deg", 8, 4, "f32", "deg", 1, 1, -90.0, 90.0),
        FieldInfo("average_roll", "Average roll, deg", 12, 4, "f32", "deg", 1, 1, -180.0, 180.0),
        FieldInfo("reserved_2", "Reserved", 16, 12, "reserved", None, 1, 1),
        FieldInfo("usw", "USW", 28, 2, "u16", None, 1, 1, 0, 65535, encoding="usw"),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<BBBB4sff12sH")

    calibration_type: int = 2
    """2 for 2D-2T calibration. (u8, at offset 0, range 2..2, ICD: Type of calibration)"""
    run: int = 1
    """Number of this run (1, 2, ...). (u8, at offset 1, range 1..255, ICD: Calibration run)"""
    data_used: int = 0
    """Percent of data points used. (u8, at offset 2, unit percent, range 0..100, ICD: Percent of used data
    points)"""
    success: int = 0
    """0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255: successful without
    an estimate. (u8, at offset 3, ICD: Calibration success; erratum E26)"""
    reserved_1: bytes = b"\x00" * 4
    """(reserved[4], at offset 4, ICD: Reserved; erratum E32)"""
    average_pitch: float = 0.0
    """Average pitch during the run. (f32, at offset 8, unit deg, range -90..90, ICD: Average pitch, deg)"""
    average_roll: float = 0.0
    """Average roll during the run. (f32, at offset 12, unit deg, range -180..180, ICD: Average roll, deg)"""
    reserved_2: bytes = b"\x00" * 12
    """(reserved[12], at offset 16, ICD: Reserved; erratum E32)"""
    usw: int = 0
    """Unit Status Word (section 6.5). (u16, at offset 28, ICD: USW)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields (). The Unit Status Word is flags, not a scaled value:
        read `UnitStatusWord(block.usw)`."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def success_accuracy_deg(self) -> float | None:
        """Predicted 3-sigma heading error in degrees, or None (failed, or no estimate)."""
        return calibration_accuracy_deg(self.success)

    @property
    def usw_status(self) -> UnitStatusWord:
        """usw decoded: flags and mode."""
        return UnitStatusWord(self.usw)


@dataclass(frozen=True, slots=True)
class CalibrationRunParameters(PayloadBase):
    """Calibration run parameters (Table 6.16), 6 bytes, host to device.

    The data message the host sends right after StartClbRun (6.4.6); its 6 bytes do not influence 2D-2T
    calibration and may be any, e.g. zeros.
    """

    NAME: ClassVar[str] = "calibration_run_parameters"
    ICD: ClassVar[str] = "Table 6.16"
    TITLE: ClassVar[str] = "Calibration run parameters"
    SIZE: ClassVar[int] = 6
    DIRECTION: ClassVar[str] = "host_to_device"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (FieldInfo("reserved", "Reserved", 0, 6, "reserved", None, 1, 1),)
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<6s")

    reserved: bytes = b"\x00" * 6
    """(reserved[6], at offset 0, ICD: Reserved; erratum E32)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result


@dataclass(frozen=True, slots=True)
class CalibrationStatus(PayloadBase):
    """Calibration results read back (Table 6.17), 52 bytes, device to host.

    The AHRS answer to GetClbRes (6.4.10).
    """

    NAME: ClassVar[str] = "calibration_status"
    ICD: ClassVar[str] = "Table 6.17"
    TITLE: ClassVar[str] = "Calibration results read back"
    SIZE: ClassVar[int] = 52
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (
        FieldInfo("calibration_type", "Type of calibration performed", 0, 1, "u8", None, 1, 1, 0, 255),
        FieldInfo("runs_used", "Number of used calibration runs", 1, 1, "u8", None, 1, 1, 0, 255),
        FieldInfo("reserved", "Reserved", 2, 1, "reserved", None, 1, 1),
        FieldInfo("success", "Calibration success", 3, 1, "u8", None, 1, 1, 0, 255, encoding="calibration_success"),
        FieldInfo("tm_c_11", "Matrix for soft iron correction", 4, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_12", "Matrix for soft iron correction", 8, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_13", "Matrix for soft iron correction", 12, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_21", "Matrix for soft iron correction", 16, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_22", "Matrix for soft iron correction", 20, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_23", "Matrix for soft iron correction", 24, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_31", "Matrix for soft iron correction", 28, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_32", "Matrix for soft iron correction", 32, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("tm_c_33", "Matrix for soft iron correction", 36, 4, "f32", "one", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("hm_0_x", "Matrix for hard iron correction", 40, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("hm_0_y", "Matrix for hard iron correction", 44, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
        FieldInfo("hm_0_z", "Matrix for hard iron correction", 48, 4, "f32", "adc", 1, 1, -FLOAT32_MAX, FLOAT32_MAX),
    )
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<BB1sBffffffffffff")

    calibration_type: int = 0
    """0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D; above 0x80: parameters loaded by other software. (u8, at
    offset 0, ICD: Type of calibration performed)"""
    runs_used: int = 0
    """Number of calibration runs used. (u8, at offset 1, ICD: Number of used calibration runs)"""
    reserved: bytes = b"\x00" * 1
    """(reserved[1], at offset 2, ICD: Reserved; erratum E3)"""
    success: int = 0
    """0: not successful; 1..254: predicted heading error in deg*10; 255: successful without an estimate.
    (u8, at offset 3, ICD: Calibration success; erratum E26)"""
    tm_c_11: float = 0.0
    """Soft-iron matrix Tm_c row 1 column 1. (f32, at offset 4, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_12: float = 0.0
    """Soft-iron matrix Tm_c row 1 column 2. (f32, at offset 8, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_13: float = 0.0
    """Soft-iron matrix Tm_c row 1 column 3. (f32, at offset 12, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_21: float = 0.0
    """Soft-iron matrix Tm_c row 2 column 1. (f32, at offset 16, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_22: float = 0.0
    """Soft-iron matrix Tm_c row 2 column 2. (f32, at offset 20, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_23: float = 0.0
    """Soft-iron matrix Tm_c row 2 column 3. (f32, at offset 24, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_31: float = 0.0
    """Soft-iron matrix Tm_c row 3 column 1. (f32, at offset 28, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_32: float = 0.0
    """Soft-iron matrix Tm_c row 3 column 2. (f32, at offset 32, unit one, ICD: Matrix for soft iron
    correction)"""
    tm_c_33: float = 0.0
    """Soft-iron matrix Tm_c row 3 column 3. (f32, at offset 36, unit one, ICD: Matrix for soft iron
    correction)"""
    hm_0_x: float = 0.0
    """Hard-iron vector Hm_0 component 1. (f32, at offset 40, unit adc, ICD: Matrix for hard iron correction;
    erratum E2)"""
    hm_0_y: float = 0.0
    """Hard-iron vector Hm_0 component 2. (f32, at offset 44, unit adc, ICD: Matrix for hard iron correction;
    erratum E2)"""
    hm_0_z: float = 0.0
    """Hard-iron vector Hm_0 component 3. (f32, at offset 48, unit adc, ICD: Matrix for hard iron correction;
    erratum E2)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result

    @property
    def success_accuracy_deg(self) -> float | None:
        """Predicted 3-sigma heading error in degrees, or None (failed, or no estimate)."""
        return calibration_accuracy_deg(self.success)


@dataclass(frozen=True, slots=True)
class Acknowledgement(PayloadBase):
    """Acknowledgement (6.3.1 (Table 6.2 with a one-word payload)), 2 bytes, device to host.

    The checksum of the message the AHRS received (E12).
    """

    NAME: ClassVar[str] = "acknowledgement"
    ICD: ClassVar[str] = "6.3.1 (Table 6.2 with a one-word payload)"
    TITLE: ClassVar[str] = "Acknowledgement"
    SIZE: ClassVar[int] = 2
    DIRECTION: ClassVar[str] = "device_to_host"
    FIELDS: ClassVar[tuple[FieldInfo, ...]] = (FieldInfo("checksum", "Check sum", 0, 2, "u16", None, 1, 1, 0, 65535),)
    _STRUCT: ClassVar[struct.Struct] = struct.Struct("<H")

    checksum: int = 0
    """Checksum of the acknowledged message, message type through payload. (u16, at offset 0, ICD: Check sum)"""

    def values(self, variant: Variant | str | None = None) -> dict[str, float]:
        """Engineering values of the scaled fields ()."""
        variant_of(variant)
        result: dict[str, float] = {}
        return result


PAYLOADS: Final[Mapping[str, type[Payload]]] = MappingProxyType(
    {
        "full_output": FullOutput,
        "quaternion": Quaternion,
        "orientation_sensors": OrientationSensors,
        "initial_alignment": InitialAlignment,
        "ahrs_parameters_load": AhrsParametersLoad,
        "ahrs_parameters_read": AhrsParametersRead,
        "firmware_version": FirmwareVersion,
        "bit_result": BitResult,
        "calibration_parameters": CalibrationParameters,
        "calibration_result": CalibrationResult,
        "calibration_run_result": CalibrationRunResult,
        "calibration_run_parameters": CalibrationRunParameters,
        "calibration_status": CalibrationStatus,
        "acknowledgement": Acknowledgement,
    }
)
"""Every payload class by spec name."""
