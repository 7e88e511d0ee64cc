# Copied from generator/targets/python/runtime/edge/ros.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The AHRS as ROS 2 sees it (REP 103, REP 145): the messages of a capture converted to
sensor_msgs/Imu, MagneticField, Temperature and diagnostic_msgs/DiagnosticArray, and written to a
rosbag2 directory (MCAP storage) by the `rosbags` library (the `ros` extra), imported only here.

Frames (section 1.1, Fig. 1.2, Table 6.6 note 2, Appendix B; `ilahrs.session.motion`): the ICD's
angles are the Euler rotation from East-North-Up to the body frame, heading (clockwise about Up),
pitch (about the new X, nose up), roll (about the new Y, X down); the body frame is X lateral
(right), Y longitudinal (forward), Z vertical (up). REP 103 wants the body frame x forward, y left,
z up in an ENU world: a vector of the AHRS's axes (X, Y, Z) is (Y, -X, Z) in ROS's, and the
orientation is the AHRS's rotation followed by a quarter turn about Up (ROS's x is the AHRS's Y).
Units: deg/s to rad/s, g to m/s^2 with standard gravity, nT to T (E43). Covariances: zeros
("unknown") for what the message carries, -1 in element 0 for what it does not (E43).

Which topics a message fills follows from its fields' units (`ilahrs.payloads`): an output block
(Tables 6.4-6.6, a $PAHR sentence) with heading, pitch and roll gives `/imu/data` (without them:
`/imu/data_raw`), with rates in deg/s and accelerations in g their Imu fields, with a field in nT a
MagneticField, with a temperature in degC (not multiplexed) a Temperature; every message from the
device that carries a Unit Status Word gives a DiagnosticArray on `/diagnostics`, each flag named.
Table 6.5's quaternion (Lk0-Lk3) is not used: the ICD does not say which frames it relates; the
angles of the same block are (section 1.1).

Everything above `BagWriter` is the standard library only, so the conversions are checked without
ROS libraries.
"""

from __future__ import annotations

import math
import os
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any, Final

from ..codec import Payload
from ..encodings import Variant
from ..nmea import PahrSentence
from ..session.motion import quaternion as icd_quaternion
from ..statemachine import OUTPUT_FORMATS
from ..status import UnitStatusWord, UswFlag, UswMode

__all__ = [
    "DIAGNOSTIC_NAME",
    "ERROR",
    "EXTRA",
    "NOT_CARRIED",
    "OK",
    "STANDARD_GRAVITY",
    "TOPICS",
    "UNKNOWN",
    "WARN",
    "BagWriter",
    "Imu",
    "MagneticField",
    "Sample",
    "Status",
    "Temperature",
    "flu_from_icd",
    "orientation",
    "require",
    "samples",
    "status",
]

STANDARD_GRAVITY: Final = 9.80665
"""m/s^2 in one g (E43: the ICD does not say which g; the spec's unit g is standard gravity)."""
_TESLA_PER_NT: Final = 1e-9
UNKNOWN: Final = (0.0,) * 9
"""A covariance that is not known (sensor_msgs: all zeros)."""
NOT_CARRIED: Final = (-1.0,) + (0.0,) * 8
"""The covariance of a quantity the message does not carry (sensor_msgs/Imu: element 0 is -1)."""
EXTRA: Final = "ros"
"""The optional extra of the package that brings the bag library."""

IMU: Final = "/imu/data"
IMU_RAW: Final = "/imu/data_raw"
MAG: Final = "/imu/mag"
TEMPERATURE: Final = "/imu/temperature"
DIAGNOSTICS: Final = "/diagnostics"
TOPICS: Final = {
    IMU: "sensor_msgs/msg/Imu",
    IMU_RAW: "sensor_msgs/msg/Imu",
    MAG: "sensor_msgs/msg/MagneticField",
    TEMPERATURE: "sensor_msgs/msg/Temperature",
    DIAGNOSTICS: "diagnostic_msgs/msg/DiagnosticArray",
}
"""Topic -> ROS 2 message type."""
DIAGNOSTIC_NAME: Final = "ilahrs: unit status word"
"""The name of the DiagnosticStatus that carries the USW."""
OK: Final = 0
WARN: Final = 1
ERROR: Final = 2
"""diagnostic_msgs/DiagnosticStatus levels."""

Vector3 = tuple[float, float, float]
Quaternion = tuple[float, float, float, float]
"""x, y, z, w (geometry_msgs/Quaternion's order)."""

_QUARTER_TURN_UP: Final = (math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5))
"""w, x, y, z: +90 deg about Up, ROS's body axes in the AHRS's (x forward is the AHRS's Y)."""
_OUTPUTS: Final = frozenset(table for table in OUTPUT_FORMATS.values() if table is not None)
_ANGLES: Final = ("heading", "pitch", "roll")
_SENTENCE_USW: Final = [name for name, kind, *_rest in PahrSentence._SPEC if kind == "hex"]
"""The sentence's Unit Status Word (its one hex field)."""


def flu_from_icd(vector: Vector3) -> Vector3:
    """A vector in the AHRS's body axes (X right, Y forward, Z up) in REP 103's (x forward, y
    left, z up)."""
    x, y, z = vector
    return (y, 0.0 - x, z)  # not -x: a zero stays 0.0, not -0.0


def orientation(heading: float, pitch: float, roll: float) -> Quaternion:
    """The orientation of REP 103's body frame (x forward, y left, z up) in East-North-Up, from
    the ICD's heading, pitch and roll in degrees: the AHRS's rotation (`ilahrs.session.motion`)
    followed by a quarter turn about Up. (x, y, z, w), unit norm, w >= 0."""
    a0, a1, a2, a3 = icd_quaternion(heading, pitch, roll)
    b0, b1, b2, b3 = _QUARTER_TURN_UP
    w = a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3
    x = a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2
    y = a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1
    z = a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    sign = 1.0 if w >= 0 else -1.0
    return (sign * x / norm, sign * y / norm, sign * z / norm, sign * w / norm)


@dataclass(frozen=True, slots=True)
class Imu:
    """sensor_msgs/Imu: None for what the block does not carry. SI units, ROS axes."""

    stamp_ns: int
    orientation: Quaternion | None
    angular_velocity: Vector3 | None
    """rad/s."""
    linear_acceleration: Vector3 | None
    """m/s^2, specific force (+g along Up at rest, E43)."""

    @property
    def topic(self) -> str:
        return IMU if self.orientation is not None else IMU_RAW


@dataclass(frozen=True, slots=True)
class MagneticField:
    stamp_ns: int
    field: Vector3
    """Tesla, ROS axes."""
    topic: str = MAG


@dataclass(frozen=True, slots=True)
class Temperature:
    stamp_ns: int
    celsius: float
    topic: str = TEMPERATURE


@dataclass(frozen=True, slots=True)
class Status:
    """diagnostic_msgs/DiagnosticStatus of one USW: `level` (OK, WARN, ERROR), `message` (the
    names of the flags set joined by '|', OK when none), `values` (each flag's name -> true or
    false, then the mode, the word in hex and the message kind it came in)."""

    stamp_ns: int
    level: int
    message: str
    values: tuple[tuple[str, str], ...]
    topic: str = DIAGNOSTICS


Sample = Imu | MagneticField | Temperature | Status


def status(raw: int, source: str) -> tuple[int, str, tuple[tuple[str, str], ...]]:
    """The level, message and values of a USW that came in a message of kind `source`."""
    word = UnitStatusWord(raw)
    names = [(flag.name or "").lower() for flag in UswFlag]
    set_names = [name for flag, name in zip(UswFlag, names, strict=True) if word.flags & flag]
    level = ERROR if word.failures else WARN if word.warnings or word.mode == UswMode.UNKNOWN else OK
    message = "|".join(set_names) or "OK"
    if word.mode != UswMode.READINESS:
        message += f" ({word.mode.value})"
    values = [(name, "true" if word.flags & flag else "false") for flag, name in zip(UswFlag, names, strict=True)]
    values += [("mode", str(word.mode.value)), ("usw", f"0x{raw:04X}"), ("source", source)]
    return level, message, tuple(values)


def _units(data: Payload | PahrSentence) -> dict[str, str | None]:
    if isinstance(data, PahrSentence):
        return {name: unit or None for name, _kind, _w, _d, _lo, _hi, unit in data._SPEC}
    return {f.name: f.unit for f in data.FIELDS if not f.multiplexed}


def _vector(values: dict[str, float], names: list[str], scale: float) -> Vector3 | None:
    if len(names) != 3 or any(name not in values for name in names):
        return None
    return flu_from_icd((values[names[0]] * scale, values[names[1]] * scale, values[names[2]] * scale))


def samples(data: Payload | PahrSentence, variant: Variant, stamp_ns: int) -> list[Sample]:
    """The ROS 2 messages of one message from the device, stamped `stamp_ns` (ns since the
    epoch): the Imu, MagneticField and Temperature of an output block, the Status of any USW."""
    units = _units(data)
    kind = data.IDENTIFIER if isinstance(data, PahrSentence) else data.NAME
    values: dict[str, float] = dict(data.values() if isinstance(data, PahrSentence) else data.values(variant))
    found: list[Sample] = []
    if isinstance(data, PahrSentence) or data.NAME in _OUTPUTS:
        by_unit: dict[str | None, list[str]] = {}
        for name, unit in units.items():
            by_unit.setdefault(unit, []).append(name)
        angles = all(units.get(name) == "deg" for name in _ANGLES)
        rotation = orientation(*(values[name] for name in _ANGLES)) if angles else None
        rates = _vector(values, by_unit.get("deg_per_s", []), math.pi / 180)
        accelerations = _vector(values, by_unit.get("g", []), STANDARD_GRAVITY)
        if rotation is not None or rates is not None or accelerations is not None:
            found.append(Imu(stamp_ns, rotation, rates, accelerations))
        field = _vector(values, by_unit.get("nT", []), _TESLA_PER_NT)
        if field is not None:
            found.append(MagneticField(stamp_ns, field))
        celsius = by_unit.get("degC", [])
        if len(celsius) == 1 and celsius[0] in values:
            found.append(Temperature(stamp_ns, values[celsius[0]]))
    words = _SENTENCE_USW if isinstance(data, PahrSentence) else [f.name for f in data.FIELDS if f.encoding == "usw"]
    for name in words:
        found.append(Status(stamp_ns, *status(getattr(data, name), kind)))
    return found


# --- writing a bag (the `ros` extra) ------------------------------------------------------------


_REQUIREMENT: Final = "rosbags>=0.11,<0.12"
"""What the `ros` extra installs (generated/python/pyproject.toml)."""


def require() -> None:
    """ImportError, naming the extra and the pip command, when the bag library is missing."""
    _library()


def _library() -> Any:
    """numpy and the rosbags modules (ImportError as `require` says when missing)."""
    try:
        import numpy
        from rosbags import rosbag2, typesys
    except ImportError as exc:
        raise ImportError(f"a ROS 2 bag needs rosbags (the {EXTRA} extra): pip install '{_REQUIREMENT}'") from exc
    return numpy, rosbag2, typesys


class BagWriter:
    """A rosbag2 directory at `path` (which must not exist), MCAP storage, rosbag2 metadata
    version 8 (ROS 2 Iron and later read it); `frame_id` in every header. `write` a Sample;
    `close` writes the metadata. `counts`: messages per topic."""

    VERSION: Final = 8

    def __init__(self, path: str | os.PathLike[str], frame_id: str) -> None:
        numpy, rosbag2, typesys = _library()
        self._numpy = numpy
        self._store = typesys.get_typestore(typesys.Stores.ROS2_JAZZY)
        self._types = self._store.types
        self._frame_id = frame_id
        self._writer = rosbag2.Writer(path, version=self.VERSION, storage_plugin=rosbag2.StoragePlugin.MCAP)
        self._writer.open()
        self._connections: dict[str, Any] = {}
        self.counts: Counter[str] = Counter()
        self._build: dict[type, Callable[[Any, Any], Any]] = {
            Imu: self._imu,
            MagneticField: self._mag,
            Temperature: self._temperature,
            Status: self._status,
        }

    def write(self, sample: Sample) -> None:
        topic = sample.topic
        msgtype = TOPICS[topic]
        connection = self._connections.get(topic)
        if connection is None:
            connection = self._writer.add_connection(topic, msgtype, typestore=self._store)
            self._connections[topic] = connection
        header = self._types["std_msgs/msg/Header"](
            stamp=self._types["builtin_interfaces/msg/Time"](
                sec=sample.stamp_ns // 1_000_000_000, nanosec=sample.stamp_ns % 1_000_000_000
            ),
            frame_id=self._frame_id,
        )
        message = self._build[type(sample)](sample, header)
        self._writer.write(connection, sample.stamp_ns, self._store.serialize_cdr(message, msgtype))
        self.counts[topic] += 1

    def write_all(self, found: Iterable[Sample]) -> None:
        for sample in found:
            self.write(sample)

    def close(self) -> None:
        self._writer.close()

    def _covariance(self, values: tuple[float, ...]) -> Any:
        return self._numpy.array(values, dtype=self._numpy.float64)

    def _vector3(self, v: Vector3 | None) -> Any:
        x, y, z = v if v is not None else (0.0, 0.0, 0.0)
        return self._types["geometry_msgs/msg/Vector3"](x=x, y=y, z=z)

    def _imu(self, sample: Imu, header: Any) -> Any:
        x, y, z, w = sample.orientation if sample.orientation is not None else (0.0, 0.0, 0.0, 1.0)

        def covariance(value: object) -> Any:
            return self._covariance(UNKNOWN if value is not None else NOT_CARRIED)

        return self._types["sensor_msgs/msg/Imu"](
            header=header,
            orientation=self._types["geometry_msgs/msg/Quaternion"](x=x, y=y, z=z, w=w),
            orientation_covariance=covariance(sample.orientation),
            angular_velocity=self._vector3(sample.angular_velocity),
            angular_velocity_covariance=covariance(sample.angular_velocity),
            linear_acceleration=self._vector3(sample.linear_acceleration),
            linear_acceleration_covariance=covariance(sample.linear_acceleration),
        )

    def _mag(self, sample: MagneticField, header: Any) -> Any:
        return self._types["sensor_msgs/msg/MagneticField"](
            header=header,
            magnetic_field=self._vector3(sample.field),
            magnetic_field_covariance=self._covariance(UNKNOWN),
        )

    def _temperature(self, sample: Temperature, header: Any) -> Any:
        return self._types["sensor_msgs/msg/Temperature"](header=header, temperature=sample.celsius, variance=0.0)

    def _status(self, sample: Status, header: Any) -> Any:
        key_value = self._types["diagnostic_msgs/msg/KeyValue"]
        entry = self._types["diagnostic_msgs/msg/DiagnosticStatus"](
            level=sample.level,
            name=DIAGNOSTIC_NAME,
            message=sample.message,
            hardware_id=self._frame_id,
            values=[key_value(key=key, value=value) for key, value in sample.values],
        )
        return self._types["diagnostic_msgs/msg/DiagnosticArray"](header=header, status=[entry])
