"""The reference device model against the state machine of the spec, the ICD's flows and physics.

The oracle for "what the device does" is the generator's model of the spec
(`spec.state_machine.lookup`, `spec.command_in_mode`), not the generated table the device reads,
so these tests also check that the generated table says what the spec says.
"""

from __future__ import annotations

import copy
import doctest
import math
import random

import pytest
from device_support import Pair, apply, kinds, messages, quick_parameters, reachable

import ilahrs
from generator import build_spec
from generator.model import TIMER_EVENTS
from generator.targets.python import tables as behaviour
from ilahrs import statemachine as sm
from ilahrs.encodings import CALIBRATION_FAILED, CALIBRATION_NO_ESTIMATE
from ilahrs.session import device as device_module
from ilahrs.session import host as host_module
from ilahrs.session import motion
from ilahrs.session.device import Device
from ilahrs.session.host import Acknowledged, DataBlock, Output

SPEC = build_spec()
MODEL = SPEC.state_machine
assert MODEL is not None
SEED = 20140311
KNOWN_SENDS = {"ack", "output", "output_sleep"}


def test_doctests() -> None:
    for module in (sm, device_module, host_module):
        result = doctest.testmod(module)
        assert result.failed == 0, module.__name__


def test_generated_table_is_the_spec_table() -> None:
    assert MODEL is not None
    current = {(t.state, t.event): t for t in MODEL.transitions if t.firmware_before is None}
    assert set(sm.TRANSITIONS) == set(current)
    for key, t in current.items():
        assert sm.TRANSITIONS[key].to == t.to
        assert sm.TRANSITIONS[key].send == t.send
    legacy = {(t.state, t.event): t for t in MODEL.transitions if t.firmware_before is not None}
    assert {k: (v[0], v[1].to, v[1].send) for k, v in sm.LEGACY_TRANSITIONS.items()} == {
        k: (t.firmware_before, t.to, t.send) for k, t in legacy.items()
    }
    assert [s.name for s in MODEL.states] == list(sm.STATES)
    for s in MODEL.states:
        info = sm.STATES[s.name]
        assert (info.mode, info.expects, info.timer) == (s.mode, s.expects, s.timer)
    assert dict(sm.TIMER_EVENTS) == {k: v for k, v in TIMER_EVENTS.items() if k in sm.TIMER_EVENTS}


def test_every_state_is_reachable() -> None:
    assert MODEL is not None
    assert set(reachable()) == {s.name for s in MODEL.states}


def _expected_messages(device: Device, command_frame: bytes | None, send: tuple[str, ...]) -> list[str]:
    """The message kinds a transition's `send` list means for this device."""
    out = []
    for item in send:
        if item == "ack":
            out.append(f"frame:1:{ilahrs.Acknowledgement.SIZE}")
        elif item.startswith("output"):
            table = sm.OUTPUT_FORMATS[device.output_format or ""]
            out.append("sentence" if table is None else f"frame:1:{ilahrs.PAYLOADS[table].SIZE}")
        else:
            out.append(f"frame:1:{ilahrs.PAYLOADS[item].SIZE}")
    del command_frame
    return out


@pytest.mark.parametrize("state", [s.name for s in MODEL.states])
def test_every_command_in_every_state(state: str) -> None:
    """Each of the 26 commands in this state: the answer and the next state are the table's."""
    assert MODEL is not None
    start = reachable()[state]
    mode = sm.STATES[state].mode
    for command in SPEC.commands:
        device = copy.deepcopy(start)
        frame = ilahrs.build_command(command.name)
        out = device.receive(frame)
        resolved = SPEC.command_in_mode(command.code, mode)
        assert resolved is not None
        transition = MODEL.lookup(state, resolved.name)
        if transition is None:
            assert out == b"", (state, command.name)
            assert device.state == state, (state, command.name)
            assert device.ignored == start.ignored + 1
            continue
        assert device.state == transition.to, (state, command.name)
        got = messages(out)
        assert kinds(got) == _expected_messages(device, frame, transition.send), (state, command.name)
        for item, message in zip(transition.send, got, strict=True):
            if item == "ack":
                assert message.raw == ilahrs.ack_for(frame)
            elif item == "output_sleep":
                if message.sentence is not None:
                    usw = message.sentence.usw
                else:
                    assert message.frame is not None
                    table = sm.OUTPUT_FORMATS[device.output_format or ""]
                    value = ilahrs.PAYLOADS[table or ""].parse(message.frame.payload).raw()["usw"]
                    assert isinstance(value, int)
                    usw = value
                assert ilahrs.UnitStatusWord(usw).mode == ilahrs.UswMode.SLEEP


@pytest.mark.parametrize(
    ("state", "event"),
    [
        (t.state, t.event)
        for t in MODEL.transitions
        if t.event not in {c.name for c in SPEC.commands} and t.firmware_before is None
    ],
)
def test_every_other_event(state: str, event: str) -> None:
    """Parameter blocks, other messages, block timeouts and timers: next state and answer."""
    assert MODEL is not None
    device = copy.deepcopy(reachable()[state])
    transition = MODEL.lookup(state, event)
    assert transition is not None
    if event in TIMER_EVENTS.values() or event == sm.BLOCK_TIMEOUT:
        timers = [e for e in (sm.BLOCK_TIMEOUT, *TIMER_EVENTS.values()) if MODEL.lookup(state, e)]
        assert event in timers
    out = apply(device, event)
    assert device.state == transition.to
    got = messages(out)
    assert kinds(got) == _expected_messages(device, None, transition.send)


def test_events_without_a_row_are_ignored() -> None:
    """A data message in a state that expects none, and time in a state without a timer."""
    devices = reachable()
    for name, device in devices.items():
        info = sm.STATES[name]
        if info.expects is None:
            copy_ = copy.deepcopy(device)
            assert apply(copy_, sm.OTHER_MESSAGE) == b""
            assert copy_.state == name
        if info.timer is None and info.expects is None:
            copy_ = copy.deepcopy(device)
            assert copy_.advance(100.0) == b""
            assert copy_.state == name


# --- What the ICD says, checked by hand ------------------------------------------------------------

def test_icd_answers_by_hand() -> None:
    device = Device(seed=SEED, parameters=quick_parameters())
    # 6.3.7: ReadAHRSPar -> a data message with the 50-byte Table 6.10 payload.
    (answer,) = messages(device.receive(bytes.fromhex("AA 55 00 00 07 00 41 48 00")))
    assert answer.frame is not None and answer.frame.message_type == 1 and len(answer.frame.payload) == 50
    # 6.3.6, E13: LoadAHRSPar gets no answer; the block gets the acknowledgement of its checksum.
    assert device.receive(bytes.fromhex("AA 55 00 00 07 00 40 47 00")) == b""
    block = ilahrs.Frame(1, ilahrs.AhrsParametersLoad(update_rate=10, alignment_time=1).build()).build()
    (ack,) = messages(device.receive(block))
    assert ack.raw == ilahrs.ack_for(block)
    # 6.3.1: AHRScont3 is acknowledged at once with 0x008A (Appendix C: checksum 8A 00).
    assert device.receive(bytes.fromhex("AA 55 00 00 07 00 83 8A 00")) == bytes.fromhex("AA 55 01 00 08 00 8A 00 93 00")
    # E39: GetDataReq during alignment is ignored; 6.3.5, E14: Stop gets no answer.
    assert device.receive(ilahrs.build_command("GetDataReq")) == b""
    assert device.receive(bytes.fromhex("AA 55 00 00 07 00 FE 05 01")) == b""
    assert device.state == "idle"
    # 6.4.4, E14: the same bytes in calibration are ExitClb, acknowledged.
    device.receive(ilahrs.build_command("Start2D2TClb"))
    device.receive(ilahrs.Frame(1, ilahrs.CalibrationParameters(accumulation_time=5).build()).build())
    assert device.mode == "calibration"
    exit_clb = bytes.fromhex("AA 55 00 00 07 00 FE 05 01")
    assert device.receive(exit_clb) == ilahrs.ack_for(ilahrs.build_command("ExitClb"))
    assert device.state == "idle"


def test_parameter_block_as_command_type_is_accepted() -> None:
    """E5: the device accepts a parameter block with message type 0 as well as 1."""
    device = Device(seed=SEED)
    device.receive(ilahrs.build_command("LoadAHRSPar"))
    block = ilahrs.Frame(0, ilahrs.AhrsParametersLoad(update_rate=20).build()).build()
    assert device.receive(block) == ilahrs.ack_for(block)
    assert device.parameters.update_rate == 20


def test_parameter_block_timeout_and_wrong_block() -> None:
    """E34: no block within 1 s, or a block of another size: abandoned, no answer, idle."""
    device = Device(seed=SEED)
    device.receive(ilahrs.build_command("LoadAHRSPar"))
    assert device.advance(sm.PARAMETER_BLOCK_TIMEOUT_S * 0.99) == b""
    assert device.state == "awaiting_parameters"
    assert device.advance(sm.PARAMETER_BLOCK_TIMEOUT_S * 0.02) == b""
    assert device.state == "idle"
    late = ilahrs.Frame(1, ilahrs.AhrsParametersLoad(update_rate=20).build()).build()
    assert device.receive(late) == b""
    assert device.parameters.update_rate == 100
    device.receive(ilahrs.build_command("LoadAHRSPar"))
    assert device.receive(ilahrs.Frame(1, ilahrs.CalibrationParameters().build()).build()) == b""
    assert device.state == "idle"
    device.receive(ilahrs.build_command("StartClbRun"))  # not valid in idle: ignored
    assert device.state == "idle"


def test_out_of_range_block_is_acknowledged_but_not_stored() -> None:
    device = Device(seed=SEED)
    device.receive(ilahrs.build_command("LoadAHRSPar"))
    payload = bytearray(ilahrs.AhrsParametersLoad(update_rate=20).build())
    payload[0:2] = (500).to_bytes(2, "little")  # 500 Hz: outside 1..100
    block = ilahrs.Frame(1, bytes(payload)).build()
    assert device.receive(block) == ilahrs.ack_for(block)
    assert device.rejected_blocks == 1
    assert device.parameters.update_rate == 100


# --- Flows, host and device back to back -----------------------------------------------------------

def _blocks(events: list[ilahrs.HostEvent], kind: type) -> list[ilahrs.HostEvent]:
    return [e for e in events if isinstance(e, kind)]


def test_parameter_read_modify_write_and_output_rate() -> None:
    pair = Pair(seed=SEED, alignment_time=5)
    (read,) = pair.send("ReadAHRSPar")
    assert isinstance(read, DataBlock) and isinstance(read.payload, ilahrs.AhrsParametersRead)
    raw = read.payload.raw()
    del raw["device_id"], raw["reserved"]
    raw.update(update_rate=25, alignment_time=2)
    (ack,) = pair.send("LoadAHRSPar", ilahrs.AhrsParametersLoad.from_raw(raw))
    assert isinstance(ack, Acknowledged) and ack.message == "ahrs_parameters_load"
    (again,) = pair.send("ReadAHRSPar")
    assert isinstance(again, DataBlock)
    assert again.payload.raw() == read.payload.raw() | {"update_rate": 25, "alignment_time": 2}
    assert isinstance(pair.send("AHRScont3")[0], Acknowledged)
    early = pair.wait(1.99)
    assert early == []
    events = pair.wait(2.01)
    assert isinstance(events[0], DataBlock) and isinstance(events[0].payload, ilahrs.InitialAlignment)
    outputs = _blocks(events, Output)
    assert len(outputs) == 50  # 2 s at 25 Hz
    assert all(isinstance(o, Output) and isinstance(o.data, ilahrs.OrientationSensors) for o in outputs)
    assert pair.host.state == "continuous"
    assert not [e for e in events if isinstance(e, ilahrs.ProtocolError)]


def test_nmea_output_is_capped_at_50_hz() -> None:
    """E22: NMEA output at min(update rate, 50) Hz; every sentence valid (Table 6.7)."""
    pair = Pair(seed=SEED, update_rate=100)
    pair.send("NMEAcont")
    events = pair.wait(3.0)
    sentences = [e.data for e in _blocks(events, Output) if isinstance(e, Output)]
    assert len(sentences) == 100  # 2 s after the 1 s alignment, at 50 Hz
    assert all(isinstance(s, ilahrs.PahrSentence) for s in sentences)
    raw = b"".join(pair.wire)
    assert raw.count(b"$PAHR,") == 100
    pair.send("Stop")
    assert pair.host.state == "idle"
    pair.send("NMEAreq")
    pair.wait(1.1)
    for _ in range(3):
        (answer,) = pair.send("GetDataReq")
        assert isinstance(answer, Output) and isinstance(answer.data, ilahrs.PahrSentence)
    (bit,) = pair.send("GetBIT")
    assert isinstance(bit, DataBlock) and isinstance(bit.payload, ilahrs.BitResult)


def test_on_request_output_formats() -> None:
    for command, cls in (("AHRSreq1", ilahrs.FullOutput), ("AHRSreq2", ilahrs.Quaternion),
                         ("AHRSreq3", ilahrs.OrientationSensors)):
        pair = Pair(seed=SEED)
        pair.send(command)
        assert pair.wait(0.5) == []
        (alignment,) = pair.wait(0.6)
        assert isinstance(alignment, DataBlock)
        assert pair.wait(2.0) == []  # nothing without a request
        (answer,) = pair.send("GetDataReq")
        assert isinstance(answer, Output) and isinstance(answer.data, cls)


def test_sleep_and_wake() -> None:
    pair = Pair(seed=SEED)
    assert pair.send("LowPowerOn") == []
    assert pair.device.state == pair.host.state == "sleep"
    for command in ("ReadAHRSPar", "AHRScont3", "GetBIT", "Stop"):  # only LowPowerOff is heard
        assert pair.device.receive(ilahrs.build_command(command)) == b""
    assert pair.device.state == "sleep"
    assert pair.send("LowPowerOff") == []
    assert pair.device.state == "idle"
    # E35: from continuous output, one last block with the sleep mode bits.
    pair.send("AHRScont1")
    pair.wait(1.5)
    events = pair.send("LowPowerOn")
    (last,) = events
    assert isinstance(last, Output) and isinstance(last.data, ilahrs.FullOutput)
    assert last.usw.mode == ilahrs.UswMode.SLEEP
    assert pair.host.state == "sleep"
    assert pair.wait(1.0) == []
    pair.send("LowPowerOff")
    # From on-request mode: no block.
    pair.send("AHRSreq2")
    pair.wait(1.1)
    assert pair.send("LowPowerOn") == []
    assert pair.device.state == "sleep"


def _calibrate(pair: Pair, start: str, seconds: int = 4) -> ilahrs.HostEvent:
    (ack,) = pair.send(start, ilahrs.CalibrationParameters(accumulation_time=seconds, latitude=45.0))
    assert isinstance(ack, Acknowledged) and ack.message == "calibration_parameters"
    events = pair.wait(1.0 + seconds + 0.05)
    alignment, result = events
    assert isinstance(alignment, DataBlock) and isinstance(alignment.payload, ilahrs.InitialAlignment)
    return result


@pytest.mark.parametrize(("start", "kind"), [("Start3DClb", 3), ("Start2DClb", 1)])
def test_single_run_calibration_accept(start: str, kind: int) -> None:
    pair = Pair(seed=SEED)
    result = _calibrate(pair, start)
    assert isinstance(result, DataBlock) and isinstance(result.payload, ilahrs.CalibrationResult)
    assert result.source == "accumulation_done"
    calibration = result.payload
    assert calibration.calibration_type == kind and calibration.runs_used == 1
    assert ilahrs.calibration_succeeded(calibration.success) and 90 <= calibration.data_used <= 100
    accuracy = ilahrs.calibration_accuracy_deg(calibration.success)
    assert accuracy is not None and 0 < accuracy < 1
    assert pair.host.state == "calibration_deciding"
    (ack,) = pair.send("AcceptClb")
    assert isinstance(ack, Acknowledged) and pair.host.state == "idle"
    (status,) = pair.send("GetClbRes")
    assert isinstance(status, DataBlock) and isinstance(status.payload, ilahrs.CalibrationStatus)
    same = ("calibration_type", "runs_used", "success", "tm_c_11", "tm_c_23", "hm_0_z")
    assert {k: status.payload.raw()[k] for k in same} == {k: calibration.raw()[k] for k in same}


def test_stop_run_early_fails_and_exit_keeps_old_calibration() -> None:
    pair = Pair(seed=SEED)
    (before,) = pair.send("GetClbRes")
    assert isinstance(before, DataBlock) and before.payload.raw()["calibration_type"] == 0  # not calibrated
    pair.send("Start2DClb", ilahrs.CalibrationParameters(accumulation_time=10))
    pair.wait(1.0 + 2.0)  # alignment, then 2 s of a 10 s accumulation: a quarter turn
    (result,) = pair.send("StopClbRun")
    assert isinstance(result, DataBlock) and isinstance(result.payload, ilahrs.CalibrationResult)
    assert result.payload.success == CALIBRATION_FAILED and result.payload.data_used < 50
    (ack,) = pair.send("ExitClb")
    assert isinstance(ack, Acknowledged) and pair.device.state == "idle"
    (after,) = pair.send("GetClbRes")
    assert isinstance(after, DataBlock) and after.payload.raw() == before.payload.raw()


def _run(pair: Pair, stop_after: float | None = None) -> ilahrs.CalibrationRunResult:
    (ack,) = pair.send("StartClbRun", ilahrs.CalibrationRunParameters())
    assert isinstance(ack, Acknowledged) and ack.message == "calibration_run_parameters"
    seconds = pair.host.setting("accumulation")
    if stop_after is None:
        alignment, result = pair.wait(1.0 + seconds + 0.05)
    else:
        (alignment,) = pair.wait(1.0 + stop_after)
        (result,) = pair.send("StopClbRun")
    assert isinstance(alignment, DataBlock) and isinstance(alignment.payload, ilahrs.InitialAlignment)
    assert isinstance(result, DataBlock) and isinstance(result.payload, ilahrs.CalibrationRunResult)
    return result.payload


def test_2d2t_calibration_with_a_failed_run() -> None:
    pair = Pair(seed=SEED)
    (ack,) = pair.send("Start2D2TClb", ilahrs.CalibrationParameters(accumulation_time=3))
    assert isinstance(ack, Acknowledged) and pair.host.state == "runs_ready"  # E36: no alignment yet
    runs = [_run(pair), _run(pair, stop_after=0.5), _run(pair)]
    assert [r.run for r in runs] == [1, 2, 3]
    assert [ilahrs.calibration_succeeded(r.success) for r in runs] == [True, False, True]
    assert len({round(r.average_pitch) for r in runs}) == 3  # a different pitch for each run
    (final,) = pair.send("FinishClb")
    assert isinstance(final, DataBlock) and isinstance(final.payload, ilahrs.CalibrationResult)
    assert final.payload.calibration_type == 2 and final.payload.runs_used == 2  # the failed run is excluded
    assert ilahrs.calibration_succeeded(final.payload.success)
    (ack,) = pair.send("AcceptClb")
    assert isinstance(ack, Acknowledged)
    (status,) = pair.send("GetClbRes")
    assert isinstance(status, DataBlock) and status.payload.raw()["calibration_type"] == 2
    assert status.payload.raw()["runs_used"] == 2
    (cleared,) = pair.send("ClearClb")
    assert isinstance(cleared, Acknowledged)
    (status,) = pair.send("GetClbRes")
    assert isinstance(status, DataBlock) and status.payload.raw()["calibration_type"] == 0


def test_2d2t_with_fewer_than_two_good_runs_fails() -> None:
    """E37: FinishClb is answered, with calibration success 0."""
    pair = Pair(seed=SEED)
    pair.send("Start2D2TClb", ilahrs.CalibrationParameters(accumulation_time=3))
    _run(pair)
    _run(pair, stop_after=0.2)
    (final,) = pair.send("FinishClb")
    assert isinstance(final, DataBlock) and isinstance(final.payload, ilahrs.CalibrationResult)
    assert final.payload.success == CALIBRATION_FAILED and final.payload.runs_used == 1
    (ack,) = pair.send("ExitClb")
    assert isinstance(ack, Acknowledged)


def test_legacy_stopclb_finishes_2d2t() -> None:
    """E29: before firmware 4.9.9.0, 0x20 between runs finished the calibration (then StopClb)."""
    pair = Pair(seed=SEED, firmware="4.9.8.7")
    pair.send("Start2D2TClb", ilahrs.CalibrationParameters(accumulation_time=2))
    _run(pair)
    _run(pair)
    (final,) = pair.send("StopClbRun")
    assert isinstance(final, DataBlock) and isinstance(final.payload, ilahrs.CalibrationResult)
    assert final.payload.success == CALIBRATION_NO_ESTIMATE  # no accuracy estimate before 4.9.9.0
    assert pair.device.state == "calibration_deciding"
    current = Pair(seed=SEED)
    current.send("Start2D2TClb", ilahrs.CalibrationParameters(accumulation_time=2))
    _run(current)
    assert current.device.receive(ilahrs.build_command("StopClbRun")) == b""  # ignored between runs now
    assert current.device.state == "runs_ready"


def test_exit_from_every_calibration_state() -> None:
    for name, device in reachable().items():
        if sm.STATES[name].mode != "calibration":
            continue
        copy_ = copy.deepcopy(device)
        frame = ilahrs.build_command("ExitClb")
        assert copy_.receive(frame) == ilahrs.ack_for(frame), name
        assert copy_.state == "idle"


# --- Physics -----------------------------------------------------------------------------------------

def _outputs(command: str, seconds: float = 2.0, variant: str = "g300_a2_tmga") -> list[ilahrs.Payload]:
    pair = Pair(seed=SEED, variant=variant)
    pair.send(command)
    return [e.data for e in pair.wait(1.0 + seconds) if isinstance(e, Output)]  # type: ignore[misc]


def test_quaternion_matches_angles() -> None:
    """Table 6.5: Lk0..Lk3 and heading/pitch/roll describe the same orientation (module convention)."""
    for block in _outputs("AHRScont2"):
        assert isinstance(block, ilahrs.Quaternion)
        q = (block.lk0 / 1e4, block.lk1 / 1e4, block.lk2 / 1e4, block.lk3 / 1e4)
        assert abs(math.sqrt(sum(c * c for c in q)) - 1) < 3e-4
        expected = motion.quaternion(block.heading_deg, block.pitch_deg, block.roll_deg)
        assert max(abs(a - b) for a, b in zip(q, expected, strict=True)) < 2e-4


def test_sensors_see_gravity_earth_field_and_rotation() -> None:
    variant = ilahrs.VARIANTS["g300_a2_tmga"]
    blocks = _outputs("AHRScont3")
    assert len(blocks) == 200
    values = []
    for block in blocks:
        assert isinstance(block, ilahrs.OrientationSensors)
        v = block.values(variant)
        values.append(v)
        acc = (v["acc_x"], v["acc_y"], v["acc_z"])
        assert abs(math.hypot(*acc) - 1.0) < 0.01  # 1 g: gravity only
        assert abs(math.degrees(math.asin(acc[1])) - v["pitch"]) < 0.3
        assert abs(math.degrees(math.atan2(-acc[0], acc[2])) - v["roll"]) < 0.3
        a = motion.matrix(v["heading"], v["pitch"], v["roll"])
        mag = (v["mag_x"], v["mag_y"], v["mag_z"])
        enu = tuple(sum(a[i][j] * mag[j] for j in range(3)) for i in range(3))
        field = motion.Sensors(0).earth_field(0.0, 0.0)
        assert all(abs(enu[i] - field[i]) < 150 for i in range(3))  # nT, after 10 nT rounding and noise
    # The gyros see the body rate the orientation changes at: over 0.1 s spans, the rotation between
    # the reported orientations (2 vec(conj(q0) q1) / dt) equals the mean gyro output.
    span = 10
    for i in range(0, len(values) - span, span):
        q0 = motion.quaternion(values[i]["heading"], values[i]["pitch"], values[i]["roll"])
        q1 = motion.quaternion(values[i + span]["heading"], values[i + span]["pitch"], values[i + span]["roll"])
        dq = (
            q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3],
            q0[0] * q1[1] - q0[1] * q1[0] - q0[2] * q1[3] + q0[3] * q1[2],
            q0[0] * q1[2] + q0[1] * q1[3] - q0[2] * q1[0] - q0[3] * q1[1],
            q0[0] * q1[3] - q0[1] * q1[2] + q0[2] * q1[1] - q0[3] * q1[0],
        )
        sign = 1 if dq[0] >= 0 else -1
        for axis, name in enumerate(("gyro_x", "gyro_y", "gyro_z")):
            rate = math.degrees(2 * sign * dq[axis + 1] / (span * 0.01))
            mean = sum(values[k][name] for k in range(i, i + span + 1)) / (span + 1)
            assert abs(rate - mean) < 0.6, (i, name, rate, mean)
    assert {b.usw for b in blocks} == {0}  # type: ignore[attr-defined]
    assert all(5.5 <= b.vdd_v <= 6.5 and 15 < b.values()["utermo"] < 35 for b in blocks)  # type: ignore[attr-defined]


def test_variant_scales_accelerations_and_rates() -> None:
    pair2 = Pair(seed=SEED, variant="g300_a6_tmga")
    pair4 = Pair(seed=SEED, variant="sn_11ac0001_0009")
    for pair in (pair2, pair4):
        pair.send("AHRSreq3")
        pair.wait(1.1)
    (x,) = pair2.send("GetDataReq")
    (y,) = pair4.send("GetDataReq")
    assert isinstance(x, Output) and isinstance(y, Output)
    assert isinstance(x.data, ilahrs.OrientationSensors) and isinstance(y.data, ilahrs.OrientationSensors)
    assert 4950 <= x.data.acc_z <= 5000  # KA 5000 LSB/g (Table 6.6 note 1)
    assert 9900 <= y.data.acc_z <= 10000  # KA 10000
    assert abs(x.data.values(ilahrs.VARIANTS["g300_a6_tmga"])["gyro_z"]
               - y.data.values(ilahrs.VARIANTS["sn_11ac0001_0009"])["gyro_z"]) < 0.5


def test_full_output_multiplexes_vdd_and_utermo() -> None:
    """Table 6.4 notes 2 and 3: Vdd alternates input and stabilised voltage; Utermo cycles 7 sensors."""
    blocks = _outputs("AHRScont1", 0.5)
    assert len(blocks) == 50
    vdd = [b.vdd_v for b in blocks]  # type: ignore[attr-defined]
    assert all(5.8 < v < 6.2 for v in vdd[0::2]) and all(4.9 < v < 5.1 for v in vdd[1::2])
    codes = [b.utermo for b in blocks]  # type: ignore[attr-defined]
    for i in range(7):
        cycle = codes[i::7]
        assert max(cycle) - min(cycle) < 10  # the same sensor every 7 frames
    assert len({round(c, -1) for c in codes[:7]}) > 1


def test_same_seed_same_bytes_and_any_time_steps() -> None:
    def run(steps: list[float]) -> bytes:
        device = Device(seed=5, parameters=quick_parameters())
        out = device.receive(ilahrs.build_command("AHRScont2"))
        for step in steps:
            out += device.advance(step)
        return out

    one = run([3.0])
    assert one == run([3.0])
    assert one == run([0.001] * 3000)
    assert one == run([0.7, 0.3, 1.9999, 0.0001])
    assert run([3.0]) != Device(seed=6).receive(b"") + b"x"


def test_garbage_never_breaks_the_device() -> None:
    rng = random.Random(SEED)
    for state, device in reachable().items():
        copy_ = copy.deepcopy(device)
        for _ in range(20):
            copy_.receive(bytes(rng.randrange(256) for _ in range(rng.randrange(1, 80))))
            copy_.advance(rng.uniform(0, 0.3))
        assert copy_.state in sm.STATES, state


# --- The filters that connect the model to the device ----------------------------------------------

def test_every_output_field_has_a_quantity_the_device_provides() -> None:
    device = Device(seed=SEED)
    sample = set(motion.Sensors(0).sample(motion.Motion(0), 0.0))
    provided = sample | set(device.parameters.raw()) | {
        "usw", "calibration_type", "run", "runs_used", "data_used", "success", "pitch", "roll", "version",
    }
    provided |= {f"soft_iron_{i}{j}" for i in range(1, 4) for j in range(1, 4)} | {f"hard_iron_{a}" for a in "xyz"}
    for payload in SPEC.payloads:
        if payload.direction != "device_to_host" or payload.name == SPEC.ack_payload:
            continue
        for field in payload.fields:
            for quantity in behaviour.quantity(field):
                assert quantity in provided, (payload.name, field.name, quantity)


def test_behaviour_filters() -> None:
    assert behaviour.quantity(SPEC.payload("full_output").field("vdd")) == ("vdd_input", "vdd_sensors")
    assert behaviour.quantity(SPEC.payload("quaternion").field("utermo")) == ("temperature",)
    assert len(behaviour.quantity(SPEC.payload("full_output").field("utermo"))) == 7
    assert behaviour.quantity(SPEC.payload("initial_alignment").field("initial_roll")) == ("roll",)
    assert behaviour.quantity(SPEC.payload("orientation_sensors").field("gyro_y")) == ("rate_y",)
    assert behaviour.quantity(SPEC.payload("calibration_result").field("hm_0_x")) == ("hard_iron_x",)
    assert behaviour.quantity(SPEC.payload("quaternion").field("reserved")) == ()
    assert behaviour.timer_field(SPEC, "output") == ("ahrs_parameters_load", "update_rate")
    assert behaviour.default_firmware(SPEC) == "4.9.9.0"
    assert behaviour.py_text("short", 4) == "'short'"
    long = "word " * 40
    assert eval(behaviour.py_text(long, 8)) == long
    assert "Stop" in behaviour.mermaid(SPEC)
