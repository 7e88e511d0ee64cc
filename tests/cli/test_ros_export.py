"""`ilahrs decode CAPTURE --to rosbag2 DIR` / `--to mcap FILE`: ROS 2 messages by REP 103 and
REP 145 from hand-made captures, read back with two independent readers (rosbags' own reader and
mcap + mcap_ros2's decoder). The orientation is checked by rotating REP 103's body axes (x forward,
y left, z up) into East-North-Up with the quaternion and reading the ICD's heading (clockwise from
North), pitch (nose up) and roll (the right side down) off them, never by the code's own inverse."""

from __future__ import annotations

import dataclasses
import io
import math
import random
import sys
from pathlib import Path
from typing import Any

import pytest

import ilahrs
from ilahrs.__main__ import main
from ilahrs.edge import ros
from ilahrs.encodings import VARIANTS
from ilahrs.pcapng import Direction, PcapngWriter
from ilahrs.statemachine import DEFAULT_ALIGNMENT_TIME_S
from ilahrs.status import UswFlag

rosbag2 = pytest.importorskip("rosbags.rosbag2")
typesys = pytest.importorskip("rosbags.typesys")
mcap_reader = pytest.importorskip("mcap.reader")
mcap_decoder = pytest.importorskip("mcap_ros2.decoder")

START_US = 1_700_000_000_123_456
"""The capture's first timestamp (microseconds since the epoch)."""
PERIOD_US = 10_000
RESOLUTION_DEG = 0.01
"""Heading, pitch and roll are sent in hundredths of a degree (Tables 6.4-6.7)."""
VARIANT = next(iter(VARIANTS.values()))

Vector = tuple[float, float, float]


# --- the checks, independent of the code under test ---------------------------------------------


def rotate(q: tuple[float, float, float, float], v: Vector) -> Vector:
    """q v q* for q = (x, y, z, w)."""
    x, y, z, w = q
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    return (
        v[0] + w * tx + (y * tz - z * ty),
        v[1] + w * ty + (z * tx - x * tz),
        v[2] + w * tz + (x * ty - y * tx),
    )


def angles(q: tuple[float, float, float, float]) -> tuple[float, float, float]:
    """The ICD's heading, pitch and roll of REP 103's body frame rotated by q into ENU."""
    forward = rotate(q, (1.0, 0.0, 0.0))
    left = rotate(q, (0.0, 1.0, 0.0))
    up = rotate(q, (0.0, 0.0, 1.0))
    heading = math.degrees(math.atan2(forward[0], forward[1])) % 360.0  # East over North: clockwise
    pitch = math.degrees(math.asin(max(-1.0, min(1.0, forward[2]))))
    roll = math.degrees(math.atan2(left[2], up[2]))  # the right side (-left) goes down: positive
    return heading, pitch, roll


def angle_error(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def assert_orientation(q: tuple[float, float, float, float], heading: float, pitch: float, roll: float) -> None:
    assert math.isclose(math.fsum(c * c for c in q), 1.0, abs_tol=1e-12)
    found = angles(q)
    assert angle_error(found[1], pitch) < RESOLUTION_DEG / 2, (found, heading, pitch, roll)
    if abs(pitch) < 89.0:  # at +-90 heading and roll are one rotation
        assert angle_error(found[0], heading) < RESOLUTION_DEG / 2, (found, heading, pitch, roll)
        assert angle_error(found[2], roll) < RESOLUTION_DEG / 2, (found, heading, pitch, roll)


# --- the conversions themselves ------------------------------------------------------------------


def test_the_orientation_gives_back_heading_pitch_and_roll() -> None:
    cases = [
        (h, p, r) for h in (0.0, 90.0, 180.0, 270.0) for p in (-60.0, -5.5, 0.0, 5.5, 60.0) for r in (-120.0, 0.0, 30.0)
    ]
    chance = random.Random(145)
    cases += [(chance.uniform(0, 360), chance.uniform(-89, 89), chance.uniform(-180, 180)) for _ in range(2000)]
    cases += [(10.0, 90.0, 0.0), (200.0, -90.0, 0.0), (359.99, 0.0, 180.0), (0.01, 0.0, -180.0)]
    for heading, pitch, roll in cases:
        assert_orientation(ros.orientation(heading, pitch, roll), heading, pitch, roll)


def test_hand_computed_orientations() -> None:
    half = math.sqrt(0.5)
    # heading 0: x forward points North, a quarter turn left of East (REP 103 yaw 90 deg)
    assert ros.orientation(0, 0, 0) == pytest.approx((0.0, 0.0, half, half))
    assert ros.orientation(90, 0, 0) == pytest.approx((0.0, 0.0, 0.0, 1.0))  # facing East: ENU itself
    assert ros.orientation(180, 0, 0) == pytest.approx((0.0, 0.0, -half, half))
    # facing East, nose up 30 deg: a rotation of -30 deg about y (left)
    assert ros.orientation(90, 30, 0) == pytest.approx(
        (0.0, -math.sin(math.radians(15)), 0.0, math.cos(math.radians(15)))
    )
    # facing East, right side down 30 deg: +30 deg about x (forward)
    assert ros.orientation(90, 0, 30) == pytest.approx(
        (math.sin(math.radians(15)), 0.0, 0.0, math.cos(math.radians(15)))
    )


def test_units_and_axes_against_hand_computed_values() -> None:
    assert ros.flu_from_icd((1.0, 2.0, 3.0)) == (2.0, -1.0, 3.0)  # X right, Y forward -> x forward, y left
    assert math.copysign(1.0, ros.flu_from_icd((0.0, 0.0, 0.0))[1]) == 1.0  # no -0.0 in a message
    block = ilahrs.OrientationSensors(
        heading=9000, gyro_x=VARIANT.kg, gyro_y=-2 * VARIANT.kg, gyro_z=3 * VARIANT.kg,  # 1, -2, 3 deg/s
        acc_x=0, acc_y=-VARIANT.ka // 2, acc_z=VARIANT.ka,  # 0, -0.5, 1 g
        mag_x=3000, mag_y=-100, mag_z=-4000,  # 30000, -1000, -40000 nT
        usw=0, utermo=-123,  # -12.3 degC
    )  # fmt: skip
    found = ros.samples(block, VARIANT, 42)
    imu, mag, temperature, status = found
    assert isinstance(imu, ros.Imu) and imu.topic == "/imu/data" and imu.stamp_ns == 42
    assert imu.angular_velocity == pytest.approx((-2 * math.pi / 180, -math.pi / 180, 3 * math.pi / 180))
    assert imu.linear_acceleration == pytest.approx((-0.5 * 9.80665, 0.0, 9.80665))
    assert isinstance(mag, ros.MagneticField) and mag.field == pytest.approx((-1e-6, -3e-5, -4e-5))
    assert isinstance(temperature, ros.Temperature) and temperature.celsius == pytest.approx(-12.3)
    assert isinstance(status, ros.Status) and (status.level, status.message) == (ros.OK, "OK")


def test_each_flag_of_the_status_word_is_named() -> None:
    failure = next(f for f in UswFlag if f & ilahrs.status.USW_FAILURE_FLAGS)
    warning = next(f for f in UswFlag if f & ilahrs.status.USW_WARNING_FLAGS)
    names = [(f.name or "").lower() for f in UswFlag]
    level, message, values = ros.status(warning, "PAHR")
    assert (level, message) == (ros.WARN, (warning.name or "").lower())
    level, message, values = ros.status(failure | warning, "quaternion")
    assert level == ros.ERROR and message == f"{(failure.name or '').lower()}|{(warning.name or '').lower()}"
    assert [key for key, _ in values] == [*names, "mode", "usw", "source"]
    assert {key for key, value in values if value == "true"} == {
        (failure.name or "").lower(),
        (warning.name or "").lower(),
    }
    assert dict(values)["source"] == "quaternion" and dict(values)["mode"] == "readiness"


# --- captures, bags and readers --------------------------------------------------------------------


POSES = [(0.0, 10.0, -20.0), (90.0, -45.5, 170.25), (180.0, 89.0, 0.5), (270.0, -0.01, -179.99), (123.45, 3.21, 45.67)]
"""Heading, pitch, roll of the output blocks of each capture."""


def capture(start: str, blocks: list[bytes]) -> bytes:
    """Stop and `start` sent to the device model, its answers and alignment recorded, then
    `blocks` from the device, one packet each, PERIOD_US apart."""
    device = ilahrs.Device(seed=1)
    out = io.BytesIO()
    writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    now = START_US
    for name in ("Stop", start):
        command = ilahrs.build_command(name)
        writer.write(command, now, Direction.OUTBOUND)
        now += 4_500
        answer = device.receive(command)
        if answer:
            writer.write(answer, now, Direction.INBOUND)
    now += round(DEFAULT_ALIGNMENT_TIME_S * 1e6)
    writer.write(device.advance(DEFAULT_ALIGNMENT_TIME_S), now, Direction.INBOUND)
    for block in blocks:
        now += PERIOD_US
        writer.write(block, now, Direction.INBOUND)
    return out.getvalue()


def frame(payload: ilahrs.codec.Payload) -> bytes:
    return ilahrs.Frame(ilahrs.MessageType.DATA, payload.build()).build()


def stamps(count: int) -> list[int]:
    """The header stamps of the blocks of `capture`: their packets' times, in nanoseconds."""
    first = START_US + 9_000 + round(DEFAULT_ALIGNMENT_TIME_S * 1e6)
    return [(first + PERIOD_US * (k + 1)) * 1000 for k in range(count)]


def requirement() -> str:
    """The one requirement of the package's `ros` extra."""
    text = (Path(ilahrs.__file__).parents[1] / "pyproject.toml").read_text()
    (line,) = [line for line in text.splitlines() if line.startswith("ros = ")]
    return line.split('"')[1]


def decode(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str]:
    code = main(["decode", *args])
    return code, capsys.readouterr().err


def plain(value: Any) -> Any:
    """A message of either reader as nested tuples of its fields (names left out)."""
    if isinstance(value, (str, int, float)):
        return value
    if hasattr(value, "tolist"):
        return tuple(value.tolist())
    if isinstance(value, (list, tuple)):
        return tuple(plain(v) for v in value)
    if dataclasses.is_dataclass(value):  # rosbags: the message's constants (OK, WARN ...) are fields too
        fields = [f.name for f in dataclasses.fields(value) if not f.name.isupper()]
    else:  # mcap_ros2: a SimpleNamespace with the message's fields in __slots__
        fields = list(value.__slots__)
    return tuple(plain(getattr(value, k)) for k in fields if k != "__msgtype__")


def read_rosbags(bag: Path) -> list[tuple[str, int, Any]]:
    store = typesys.get_typestore(typesys.Stores.ROS2_JAZZY)
    with rosbag2.Reader(bag) as reader:
        return [(c.topic, t, store.deserialize_cdr(raw, c.msgtype)) for c, t, raw in reader.messages()]


def read_mcap(path: Path) -> list[tuple[str, int, Any]]:
    with path.open("rb") as stream:
        reader = mcap_reader.make_reader(stream, decoder_factories=[mcap_decoder.DecoderFactory()])
        return [(c.topic, m.log_time, ros_msg) for _s, c, m, ros_msg in reader.iter_decoded_messages()]


def topics(messages: list[tuple[str, int, Any]]) -> dict[str, list[Any]]:
    found: dict[str, list[Any]] = {}
    for topic, _time, message in messages:
        found.setdefault(topic, []).append(message)
    return found


def test_a_bag_of_orientation_and_sensor_outputs(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    blocks = [
        ilahrs.OrientationSensors(
            heading=round(h * 100), pitch=round(p * 100), roll=round(r * 100),
            gyro_x=VARIANT.kg, acc_z=VARIANT.ka, mag_y=1000, utermo=250 + k,
            usw=UswFlag.X_RATE_EXCEEDED if k == 1 else 0,
        )
        for k, (h, p, r) in enumerate(POSES)
    ]  # fmt: skip
    path = tmp_path / "s.pcapng"
    path.write_bytes(capture("AHRScont3", [frame(b) for b in blocks]))
    bag = tmp_path / "bag"
    code, err = decode(capsys, str(path), "--to", "rosbag2", str(bag), "--frame-id", "ahrs_link")
    assert code == 0, err
    assert f"{bag}: 21 ROS 2 messages (/diagnostics 6, /imu/data 5, /imu/mag 5, /imu/temperature 5)" in err
    first = read_rosbags(bag)
    second = read_mcap(bag / "bag.mcap")
    assert [(t, n, plain(m)) for t, n, m in first] == [(t, n, plain(m)) for t, n, m in second]  # the readers agree
    found = topics(first)
    assert sorted(found) == sorted(set(ros.TOPICS) - {"/imu/data_raw"})
    times = [(m.header.stamp.sec * 1_000_000_000 + m.header.stamp.nanosec) for m in found["/imu/data"]]
    assert times == stamps(len(blocks))
    assert [n for t, n, _ in first if t == "/imu/mag"] == times  # the bag's own times too
    for message, (heading, pitch, roll) in zip(found["/imu/data"], POSES, strict=True):
        assert message.header.frame_id == "ahrs_link"
        o = message.orientation
        assert_orientation((o.x, o.y, o.z, o.w), heading, pitch, roll)
        assert (message.angular_velocity.x, message.angular_velocity.y) == pytest.approx((0.0, -math.pi / 180))
        assert message.linear_acceleration.z == pytest.approx(9.80665)
        assert list(message.orientation_covariance) == [0.0] * 9  # unknown
    assert [m.magnetic_field.x for m in found["/imu/mag"]] == pytest.approx([1e-5] * 5)
    assert [m.temperature for m in found["/imu/temperature"]] == pytest.approx([25.0, 25.1, 25.2, 25.3, 25.4])
    status = [m.status[0] for m in found["/diagnostics"]]
    assert [s.level for s in status] == [ros.OK, ros.OK, ros.WARN, ros.OK, ros.OK, ros.OK]
    sources = [next(v.value for v in s.values if v.key == "source") for s in status[:2]]
    assert sources == ["initial_alignment", "orientation_sensors"]
    single = tmp_path / "one.mcap"
    code, err = decode(capsys, str(path), "--to", "mcap", str(single), "--frame-id", "ahrs_link")
    assert code == 0, err
    assert [(t, n, plain(m)) for t, n, m in read_mcap(single)] == [(t, n, plain(m)) for t, n, m in second]


def test_sentences_and_full_output_carry_what_they_have(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    sentences = [
        ilahrs.PahrSentence.from_values(heading=h, pitch=p, roll=r, temperature=-5.5, vdd=5.1, usw=0).build().encode()
        for h, p, r in POSES
    ]
    nmea = tmp_path / "n.pcapng"
    nmea.write_bytes(capture("NMEAcont", sentences))
    code, err = decode(capsys, str(nmea), "--to", "mcap", str(tmp_path / "n.mcap"))
    assert code == 0, err
    found = topics(read_mcap(tmp_path / "n.mcap"))
    assert sorted(found) == ["/diagnostics", "/imu/data", "/imu/temperature"]
    for message, (heading, pitch, roll) in zip(found["/imu/data"], POSES, strict=True):
        o = message.orientation
        assert_orientation((o.x, o.y, o.z, o.w), heading, pitch, roll)
        assert message.angular_velocity_covariance[0] == -1 and message.linear_acceleration_covariance[0] == -1
        assert message.header.frame_id == "imu_link"
    assert [m.temperature for m in found["/imu/temperature"]] == [-5.5] * 5
    full = tmp_path / "f.pcapng"
    full.write_bytes(capture("AHRScont1", [frame(ilahrs.FullOutput(heading=4500, utermo=99)) for _ in range(3)]))
    code, err = decode(capsys, str(full), "--to", "rosbag2", str(tmp_path / "f"), "--types", "full_output")
    assert code == 0, err
    found = topics(read_rosbags(tmp_path / "f"))
    assert sorted(found) == [
        "/diagnostics",
        "/imu/data",
    ]  # raw sensor codes and multiplexed ADC: no mag, no temperature
    assert len(found["/imu/data"]) == 3 and len(found["/diagnostics"]) == 3  # --types: not the alignment's
    assert all(m.angular_velocity_covariance[0] == -1 for m in found["/imu/data"])


def test_what_cannot_be_written_is_one_line(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    path = tmp_path / "s.pcapng"
    data = capture("AHRScont3", [frame(ilahrs.OrientationSensors(heading=100)) for _ in range(3)])
    path.write_bytes(data)
    raw = tmp_path / "dump.bin"
    raw.write_bytes(frame(ilahrs.OrientationSensors()) * 3)
    code, err = decode(capsys, str(raw), "--to", "rosbag2", str(tmp_path / "r"), "--output-format", "AHRScont3")
    assert (code, err) == (
        2,
        f"ilahrs decode: {raw}: a raw dump has no timestamps; --to rosbag2 needs a pcapng capture (ilahrs record)\n",
    )
    code, err = decode(capsys, str(path), "--to", "mcap", str(tmp_path / "r.mcap"), "--raw")
    assert (code, err) == (2, "ilahrs decode: --raw gives values as sent; --to mcap writes SI units\n")
    monkeypatch.setitem(sys.modules, "rosbags", None)  # the extra not installed
    code, err = decode(capsys, str(path), "--to", "rosbag2", str(tmp_path / "r"))
    assert code == 2 and err.count("\n") == 1
    assert err == f"ilahrs decode: a ROS 2 bag needs rosbags (the ros extra): pip install '{requirement()}'\n"
    monkeypatch.delitem(sys.modules, "rosbags")
    existing = tmp_path / "kept"
    existing.mkdir()
    (existing / "a").write_text("mine")
    code, err = decode(capsys, str(path), "--to", "rosbag2", str(existing))
    assert (code, err) == (2, f"ilahrs decode: {existing}: exists and is not empty (--force replaces it)\n")
    assert [p.name for p in existing.iterdir()] == ["a"]
    cut = tmp_path / "cut.pcapng"
    cut.write_bytes(data[:-7])
    code, err = decode(capsys, str(cut), "--to", "rosbag2", str(tmp_path / "cut"))
    assert code == 2 and err.count("\n") == 1 and "file ends inside the block" in err
    assert len(topics(read_rosbags(tmp_path / "cut"))["/imu/data"]) == 2  # the blocks before the damage
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cut", "cut.pcapng", "dump.bin", "kept", "s.pcapng"]
