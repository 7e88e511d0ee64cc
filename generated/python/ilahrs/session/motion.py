# Copied from generator/targets/python/runtime/session/motion.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A seeded motion profile and the sensors that see it: the synthetic data of the virtual AHRS.

Frames (section 1.1, Fig. 1.2, Table 6.6 note 2). The Earth-level frame is East-North-Up (ENU).
The body frame has X lateral (to the right), Y longitudinal (forward), Z vertical (up); at zero
angles it coincides with ENU. Orientation is the Euler rotation from ENU to body, heading first,
then pitch, then roll (section 1.1, Appendix B):

- heading psi: about Up, clockwise seen from above (Y towards East is +90 deg), 0 to 360;
- pitch theta: about the new X axis, nose (Y) up positive, -90 to 90;
- roll phi: about the new Y axis, positive when the X axis moves down, -180 to 180.

The body axes in ENU are the columns of A = Rz(-psi) Rx(theta) Ry(phi) (right-handed active
rotations), and the body components of an ENU vector are v_body = A^T v_enu. The quaternion of
Table 6.5 (Lk0 scalar, Lk1..Lk3 vector) is the same rotation, Hamilton convention:
q = qz(-psi) * qx(theta) * qy(phi), q0 >= 0, so v_body = conj(q) * v_enu * q.

The sensors see the true motion: accelerometers the specific force of gravity, +1 g along Up
(acc_y = sin(theta), acc_x = -sin(phi) cos(theta), acc_z = cos(phi) cos(theta), in g); gyros the
body angular rate (from the quaternion's rate of change, deg/s); magnetometers the Earth field
(a dipole model: horizontal B0 cos(lat) towards magnetic north, which lies `declination` degrees
east of true north, and 2 B0 sin(lat) downwards, nT) rotated into the body frame. The heading
reported is true heading. Noise is seeded; nothing here reads a clock.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Final

__all__ = [
    "EARTH_FIELD_NT",
    "Motion",
    "Sensors",
    "angles_from_matrix",
    "body_from_enu",
    "matrix",
    "quaternion",
]

EARTH_FIELD_NT: Final = 30000.0
"""Equatorial field strength of the dipole model, nT."""
GYRO_RANGE_DPS: Final = 300.0
"""Gyro measurement range (Table 3.1); the virtual object never turns faster than 80 % of it."""
SETTLE_S: Final = 4.0
"""Seconds over which a moving phase eases from where the object was held onto the gentle motion
that is a function of the time since power-up."""

Vector = tuple[float, float, float]
Matrix = tuple[Vector, Vector, Vector]
Quaternion = tuple[float, float, float, float]


def _rx(a: float) -> Matrix:
    c, s = math.cos(a), math.sin(a)
    return ((1.0, 0.0, 0.0), (0.0, c, -s), (0.0, s, c))


def _ry(a: float) -> Matrix:
    c, s = math.cos(a), math.sin(a)
    return ((c, 0.0, s), (0.0, 1.0, 0.0), (-s, 0.0, c))


def _rz(a: float) -> Matrix:
    c, s = math.cos(a), math.sin(a)
    return ((c, -s, 0.0), (s, c, 0.0), (0.0, 0.0, 1.0))


def _row(a: Matrix, b: Matrix, i: int) -> Vector:
    return (
        a[i][0] * b[0][0] + a[i][1] * b[1][0] + a[i][2] * b[2][0],
        a[i][0] * b[0][1] + a[i][1] * b[1][1] + a[i][2] * b[2][1],
        a[i][0] * b[0][2] + a[i][1] * b[1][2] + a[i][2] * b[2][2],
    )


def _mul(a: Matrix, b: Matrix) -> Matrix:
    return (_row(a, b, 0), _row(a, b, 1), _row(a, b, 2))


def matrix(heading: float, pitch: float, roll: float) -> Matrix:
    """A = Rz(-heading) Rx(pitch) Ry(roll), angles in degrees: body axes (columns) in ENU."""
    return _mul(_mul(_rz(-math.radians(heading)), _rx(math.radians(pitch))), _ry(math.radians(roll)))


def body_from_enu(a: Matrix, v: Vector) -> Vector:
    """The body components of an ENU vector: A^T v."""
    return (
        a[0][0] * v[0] + a[1][0] * v[1] + a[2][0] * v[2],
        a[0][1] * v[0] + a[1][1] * v[1] + a[2][1] * v[2],
        a[0][2] * v[0] + a[1][2] * v[1] + a[2][2] * v[2],
    )


def angles_from_matrix(a: Matrix) -> tuple[float, float, float]:
    """(heading 0..360, pitch, roll) in degrees of A (the inverse of `matrix`)."""
    pitch = math.degrees(math.asin(max(-1.0, min(1.0, a[2][1]))))
    roll = math.degrees(math.atan2(-a[2][0], a[2][2]))
    heading = math.degrees(math.atan2(a[0][1], a[1][1])) % 360.0
    return heading, pitch, roll


def _qmul(a: Quaternion, b: Quaternion) -> Quaternion:
    return (
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    )


def quaternion(heading: float, pitch: float, roll: float) -> Quaternion:
    """q = qz(-heading) * qx(pitch) * qy(roll), scalar first, q0 >= 0 (angles in degrees)."""
    h, p, r = -math.radians(heading) / 2, math.radians(pitch) / 2, math.radians(roll) / 2
    qz = (math.cos(h), 0.0, 0.0, math.sin(h))
    qx = (math.cos(p), math.sin(p), 0.0, 0.0)
    qy = (math.cos(r), 0.0, math.sin(r), 0.0)
    q = _qmul(_qmul(qz, qx), qy)
    return q if q[0] >= 0 else (-q[0], -q[1], -q[2], -q[3])


@dataclass(frozen=True, slots=True)
class _Phase:
    kind: str  # still, moving or turning
    start: float
    heading: float
    pitch: float
    roll: float
    turn_rate: float = 0.0


class Motion:
    """The virtual object's orientation over time: still (alignment), moving gently (operation)
    or turning at a constant rate with constant pitch and roll (a calibration run). Each phase
    starts where the previous one left the object, except that a turning phase may be given a new
    pitch and roll (the operator sets the object before the run, 6.4.5).

    The gentle motion is a function of the time since power-up (`gentle(t)`), not of the time
    since the phase began: a moving phase eases from where the object was held onto it within
    SETTLE_S seconds, so any number of start/stop sessions leaves pitch and roll within the
    motion's amplitude around a level mean."""

    def __init__(self, seed: int) -> None:
        rng = random.Random(seed)
        self._amplitude = (rng.uniform(10, 30), rng.uniform(3, 8), rng.uniform(4, 10))
        self._frequency = tuple(2 * math.pi * rng.uniform(0.05, 0.2) for _ in range(3))
        self._drift = rng.choice((-1, 1)) * rng.uniform(1, 5)
        self._mean = (rng.uniform(0, 360), rng.uniform(-3, 3), rng.uniform(-3, 3))
        self._phase = _Phase("still", 0.0, *self._mean)

    @property
    def kind(self) -> str:
        return self._phase.kind

    def start(
        self, kind: str, t: float, *, pitch: float | None = None, roll: float | None = None, turn_rate: float = 0.0
    ) -> None:
        """Begin a phase at time t (seconds)."""
        heading, now_pitch, now_roll = self.angles(t)
        self._phase = _Phase(
            kind,
            t,
            heading,
            now_pitch if pitch is None else pitch,
            now_roll if roll is None else roll,
            max(-GYRO_RANGE_DPS * 0.8, min(GYRO_RANGE_DPS * 0.8, turn_rate)),
        )

    def angles(self, t: float) -> tuple[float, float, float]:
        """(heading 0..360, pitch, roll) in degrees at time t (seconds, not before the phase)."""
        p = self._phase
        tau = max(0.0, t - p.start)
        if p.kind == "moving":
            heading, pitch, roll = self.gentle(max(t, p.start))
            if tau < SETTLE_S:
                x = tau / SETTLE_S
                weight = x * x * (3 - 2 * x)  # smoothstep: no jump in angle or rate
                turn = (heading - p.heading + 180.0) % 360.0 - 180.0
                heading = p.heading + weight * turn
                pitch = p.pitch + weight * (pitch - p.pitch)
                roll = p.roll + weight * (roll - p.roll)
        elif p.kind == "turning":
            heading = p.heading + p.turn_rate * tau
            pitch, roll = p.pitch, p.roll
        else:
            heading, pitch, roll = p.heading, p.pitch, p.roll
        return heading % 360.0, max(-89.0, min(89.0, pitch)), roll

    def gentle(self, t: float) -> tuple[float, float, float]:
        """(heading, pitch, roll) in degrees of the gentle motion at t seconds since power-up."""
        a, w, mean = self._amplitude, self._frequency, self._mean
        heading = mean[0] + a[0] * math.sin(w[0] * t) + self._drift * t
        return heading % 360.0, mean[1] + a[1] * math.sin(w[1] * t), mean[2] + a[2] * math.sin(w[2] * t)

    def turned(self, t: float) -> float:
        """Degrees of heading turned since the phase began (turning phases)."""
        return abs(self._phase.turn_rate) * max(0.0, t - self._phase.start)

    def rate(self, t: float) -> Vector:
        """Body angular rate (deg/s) at time t: 2 vec(conj(q(t-h)) q(t+h)) / 2h."""
        h = 1e-3
        t0 = max(self._phase.start, t - h)
        q0, q1 = quaternion(*self.angles(t0)), quaternion(*self.angles(t0 + 2 * h))
        dq = _qmul((q0[0], -q0[1], -q0[2], -q0[3]), q1)
        sign = 1.0 if dq[0] >= 0 else -1.0
        return (
            math.degrees(2 * sign * dq[1] / (2 * h)),
            math.degrees(2 * sign * dq[2] / (2 * h)),
            math.degrees(2 * sign * dq[3] / (2 * h)),
        )


class Sensors:
    """What the AHRS sensors put out for a motion: every synthetic quantity by name, in the units
    of the fields they fill (deg, deg/s, g, nT, V, degC, ADC codes)."""

    # ADC model of the raw sensor data of Table 6.4 (codes per unit), and the noise of Table 3.1.
    GYRO_ADC: Final = 100.0
    ACC_ADC: Final = 4000.0
    MAG_ADC: Final = 0.4
    TEMP_ADC: Final = 20.0

    def __init__(self, seed: int) -> None:
        rng = random.Random(seed ^ 0x5EED)
        self._noise = random.Random(seed ^ 0xA5A5)
        self.gyro_offset = tuple(rng.uniform(-300, 300) for _ in range(3))
        self.acc_offset = tuple(rng.uniform(-200, 200) for _ in range(3))
        self.mag_offset = tuple(rng.uniform(-300, 300) for _ in range(3))
        self.temp_offset = tuple(rng.uniform(-500, 500) for _ in range(7))
        self.temperature0 = rng.uniform(22, 27)
        self.vdd = rng.uniform(5.9, 6.1)
        # The carrier's soft and hard iron, which a calibration estimates (6.4).
        self.soft_iron = tuple(
            tuple((1.0 if i == j else 0.0) + rng.uniform(-0.04, 0.04) for j in range(3)) for i in range(3)
        )
        self.hard_iron = tuple(rng.uniform(-400, 400) for _ in range(3))

    def earth_field(self, latitude: float, declination: float) -> Vector:
        """The dipole-model Earth field in ENU, nT."""
        lat, dec = math.radians(latitude), math.radians(declination)
        horizontal = EARTH_FIELD_NT * math.cos(lat)
        return (horizontal * math.sin(dec), horizontal * math.cos(dec), -2 * EARTH_FIELD_NT * math.sin(lat))

    def temperature(self, t: float) -> float:
        """Average accelerometer temperature, degC: warming up after power-on."""
        return self.temperature0 + 3.0 * (1.0 - math.exp(-t / 600.0))

    def sample(
        self, motion: Motion, t: float, *, latitude: float = 0.0, declination: float = 0.0, noise: bool = True
    ) -> dict[str, float]:
        """Every quantity at time t (seconds)."""
        gauss = self._noise.gauss if noise else (lambda _mu, _sigma: 0.0)
        heading, pitch, roll = motion.angles(t)
        a = matrix(heading, pitch, roll)
        acc = body_from_enu(a, (0.0, 0.0, 1.0))
        mag = body_from_enu(a, self.earth_field(latitude, declination))
        rate = motion.rate(t)
        # Output noise as a small rotation, so that angles and quaternion stay consistent.
        out_heading = (heading + gauss(0, 0.02)) % 360.0
        out_pitch = max(-90.0, min(90.0, pitch + gauss(0, 0.01)))
        out_roll = roll + gauss(0, 0.01)
        q = quaternion(out_heading, out_pitch, out_roll)
        values: dict[str, float] = {"heading": out_heading, "pitch": out_pitch, "roll": out_roll}
        values.update({f"q{i}": q[i] for i in range(4)})
        temperature = self.temperature(t)
        for i, axis in enumerate("xyz"):
            gyro = rate[i] + gauss(0, 0.05)
            accel = acc[i] + gauss(0, 0.0005)
            field = mag[i] + gauss(0, 20.0)
            values[f"rate_{axis}"] = gyro
            values[f"acc_{axis}"] = accel
            values[f"mag_{axis}"] = field
            values[f"adc_gyro_{axis}"] = self.gyro_offset[i] + gyro * self.GYRO_ADC
            values[f"adc_acc_{axis}"] = self.acc_offset[i] + accel * self.ACC_ADC
            values[f"adc_mag_{axis}"] = self.mag_offset[i] + field * self.MAG_ADC
        for i in range(7):
            values[f"adc_temp_{i + 1}"] = 8000 + self.temp_offset[i] + self.TEMP_ADC * (temperature + gauss(0, 0.05))
        values["temperature"] = temperature + gauss(0, 0.05)
        values["vdd_input"] = self.vdd + gauss(0, 0.005)
        values["vdd_sensors"] = 5.0 + gauss(0, 0.002)
        return values
