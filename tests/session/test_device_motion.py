"""The virtual object's attitude over many start/stop sessions: a function of the time since
power-up, within the motion's amplitude, never ratcheting up session after session."""

from __future__ import annotations

import statistics

import ilahrs
from ilahrs.roles import ParameterBlock
from ilahrs.session.device import Device, default_parameters

SESSIONS = 300


def _device(seed: int) -> Device:
    raw = default_parameters().raw()
    raw.update({"alignment_time": 1, "update_rate": 10})
    return Device(seed=seed, parameters=ParameterBlock.from_raw(raw))


def _angles(data: bytes) -> list[tuple[float, float, float]]:
    """(time order) pitch, roll and heading of every output block in `data`."""
    found = []
    for message in ilahrs.StreamDecoder().feed(data):
        frame = message.frame
        if frame is not None and len(frame.payload) == ilahrs.OrientationSensors.SIZE:
            block = ilahrs.OrientationSensors.parse(frame.payload)
            found.append((block.pitch_deg, block.roll_deg, block.heading_deg))
    return found


def test_attitude_does_not_ratchet_over_hundreds_of_sessions() -> None:
    for seed in (0, 1, 7):
        device = _device(seed)
        per_session: list[list[tuple[float, float, float]]] = []
        for _ in range(SESSIONS):
            device.receive(ilahrs.build_command("AHRScont3"))
            per_session.append(_angles(device.advance(3.0)))  # 1 s alignment, 2 s of output
            device.receive(ilahrs.build_command("Stop"))
            device.advance(0.5)
        pitches = [a[0] for session in per_session for a in session]
        rolls = [a[1] for session in per_session for a in session]
        assert len(pitches) >= SESSIONS * 19
        # Within the motion's amplitude (at most 8 deg pitch, 10 deg roll about a mean within 3 deg).
        assert max(abs(p) for p in pitches) < 12.0, seed
        assert max(abs(r) for r in rolls) < 14.0, seed
        first = statistics.fmean(pitches[: len(pitches) // 5])
        last = statistics.fmean(pitches[-len(pitches) // 5 :])
        assert abs(last - first) < 3.0, (seed, first, last)
        first = statistics.fmean(rolls[: len(rolls) // 5])
        last = statistics.fmean(rolls[-len(rolls) // 5 :])
        assert abs(last - first) < 3.0, (seed, first, last)


def test_attitude_is_a_function_of_time_since_power_up() -> None:
    """Long enough into a session, a device that was stopped and started many times shows the
    attitude of one that has streamed since power-up."""
    cycled, steady = _device(5), _device(5)
    steady.receive(ilahrs.build_command("AHRScont3"))
    for _ in range(40):
        cycled.receive(ilahrs.build_command("AHRScont3"))
        cycled.advance(2.0)
        cycled.receive(ilahrs.build_command("Stop"))
        cycled.advance(0.5)
    steady.advance(cycled.now)
    cycled.receive(ilahrs.build_command("AHRScont3"))
    cycled.advance(10.0)  # alignment and settling
    steady.advance(10.0)
    a, b = _angles(cycled.advance(3.0)), _angles(steady.advance(3.0))
    assert len(a) == len(b) >= 29
    for (pitch_a, roll_a, heading_a), (pitch_b, roll_b, heading_b) in zip(a, b, strict=True):
        assert abs(pitch_a - pitch_b) < 0.2 and abs(roll_a - roll_b) < 0.2
        assert abs((heading_a - heading_b + 180) % 360 - 180) < 0.3
