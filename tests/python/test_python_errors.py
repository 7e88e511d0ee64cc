"""Every public entry point of the Python binding raises IlahrsError (kind, offset, field) for bad
input, never a raw TypeError, ValueError, struct.error, OverflowError, KeyError, AttributeError or
MemoryError; and an error message stays short whatever the size of the bad value. Each entry
point is probed with wrong types, None, negative, huge and non-finite values."""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterator
from typing import Any

import pytest

import ilahrs
from ilahrs import statemachine
from ilahrs.codec import PayloadBase
from ilahrs.encodings import date_is_valid, declination_is_valid
from ilahrs.machine import firmware_version
from ilahrs.sentence import nmea_checksum, scaled
from ilahrs.session.device import Device, default_parameters
from ilahrs.session.host import Host

HUGE_TEXT = "x" * 1_000_000
HUGE_BYTES = b"\xaa" * 1_000_000
BAD: tuple[object, ...] = (
    None,
    "x",
    "aa55",
    "€",
    "4.²",
    b"",
    -1,
    0,
    2**40,
    10**400,
    1.5,
    -1e300,
    1e308,
    math.nan,
    math.inf,
    -math.inf,
    True,
    [],
    [1, 2],
    {},
    {"bogus": 1},
    object(),
    HUGE_TEXT,
    HUGE_BYTES,
)
MESSAGE_LIMIT = 600
"""Longest error message allowed, whatever the value."""

SOME_PAYLOAD = ilahrs.OrientationSensors
VARIANT_ACCESSORS = [
    name
    for name in dir(SOME_PAYLOAD)
    if name.endswith(("_dps", "_g")) and callable(getattr(SOME_PAYLOAD, name)) and not name.startswith("_")
]
SENTENCE = dict.fromkeys(ilahrs.PahrSentence.FIELDS, 0)


def _field_probe(cls: type[ilahrs.Payload], name: str) -> Callable[[Any], object]:
    return lambda value: cls.from_raw({name: value}).build()


def _values_probe(cls: type[ilahrs.Payload]) -> Callable[[Any], object]:
    return lambda value: cls().values(value)


def _accessor_probe(accessor: str) -> Callable[[Any], object]:
    method: Callable[[Any], object] = getattr(SOME_PAYLOAD(), accessor)
    return method


def _codec_probes() -> Iterator[tuple[str, Callable[[Any], object]]]:
    """Frames, sentences, payload tables and their variant accessors."""
    yield "Frame.parse", ilahrs.Frame.parse
    yield "checksum", ilahrs.checksum
    yield "Frame(message_type=v).build", lambda v: ilahrs.Frame(v, b"x").build()
    yield "Frame(payload=v).build", lambda v: ilahrs.Frame(0, v).build()
    yield "Frame(reserved=v).build", lambda v: ilahrs.Frame(0, b"x", v).build()
    yield "Frame(reserved=v).checksum", lambda v: ilahrs.Frame(0, b"x", v).checksum
    yield "StreamDecoder.feed", lambda v: ilahrs.StreamDecoder().feed(v)
    yield "PahrSentence.parse", ilahrs.PahrSentence.parse
    yield "PahrSentence.from_values(roll=v)", lambda v: ilahrs.PahrSentence.from_values(**{**SENTENCE, "roll": v})
    yield "nmea_checksum", nmea_checksum
    yield "scaled", lambda v: scaled(v, 100, "x")
    yield "UnitStatusWord.flags", lambda v: ilahrs.UnitStatusWord(v).flags
    for name, cls in ilahrs.PAYLOADS.items():
        yield f"{name}.parse", cls.parse
        yield f"{name}.from_raw", cls.from_raw
        for info in cls.FIELDS:
            yield f"{name}.from_raw({info.name}=v)", _field_probe(cls, info.name)
        yield f"{name}().values(v)", _values_probe(cls)
    for accessor in VARIANT_ACCESSORS:
        yield f"{SOME_PAYLOAD.NAME}.{accessor}(v)", _accessor_probe(accessor)


def _command_probes() -> Iterator[tuple[str, Callable[[Any], object]]]:
    """Commands, parameter blocks, value encodings and the state-machine table."""
    yield "build_command", ilahrs.build_command
    yield "build_command(reserved=v)", lambda v: ilahrs.build_command("Stop", reserved=v)
    yield "build_parameter_block(v)", lambda v: ilahrs.build_parameter_block(v, {})
    yield "build_parameter_block(block=v)", lambda v: ilahrs.build_parameter_block("LoadAHRSPar", v)
    yield "command_names", ilahrs.command_names
    yield "decode_command", ilahrs.decode_command
    yield "ack_for", ilahrs.ack_for
    yield "encode_date(year=v)", lambda v: ilahrs.encode_date(v, 1, 1)
    yield "encode_date(month=v)", lambda v: ilahrs.encode_date(2020, v, 1)
    yield "decode_date", ilahrs.decode_date
    yield "date_is_valid", lambda v: date_is_valid(v, v, v)
    yield "declination_is_valid", declination_is_valid
    yield "declination_is_computed", ilahrs.declination_is_computed
    yield "calibration_succeeded", ilahrs.calibration_succeeded
    yield "calibration_accuracy_deg", ilahrs.calibration_accuracy_deg
    yield "firmware_version", firmware_version
    yield "lookup(state=v)", lambda v: statemachine.lookup(v, "Stop")
    yield "lookup(event=v)", lambda v: statemachine.lookup("idle", v)
    yield "lookup(firmware=v)", lambda v: statemachine.lookup("runs_ready", "StopClbRun", v)
    yield "command_event(code=v)", lambda v: statemachine.command_event(v, "idle")
    yield "command_event(state=v)", lambda v: statemachine.command_event(0xFE, v)
    yield "timer_transition", statemachine.timer_transition


def _session_probes() -> Iterator[tuple[str, Callable[[Any], object]]]:
    """The device model and the host session."""
    yield "Device(variant=v)", lambda v: Device(variant=v)
    yield "Device(firmware=v)", lambda v: Device(firmware=v)
    yield "Device(firmware_text=v)", lambda v: Device(firmware_text=v)
    yield "Device(seed=v)", lambda v: Device(seed=v)
    yield "Device(device_id=v)", lambda v: Device(device_id=v)
    yield "Device(parameters=v)", lambda v: Device(parameters=v)
    yield "Device.advance", lambda v: Device().advance(v)
    yield "Device.receive", lambda v: Device().receive(v)
    yield "default_parameters", default_parameters
    yield "Host(reply_timeout=v)", lambda v: Host(reply_timeout=v).send("Stop")
    yield "Host(state=v)", lambda v: Host(state=v)
    yield "Host(firmware=v)", lambda v: Host(firmware=v)
    yield "Host(output=v)", lambda v: Host(output=v)
    yield "Host.mid_stream", lambda v: Host.mid_stream(v, firmware=None)
    yield "Host.advance", lambda v: Host().advance(v)
    yield "Host.receive", lambda v: Host().receive(v)
    yield "Host.send", lambda v: Host().send(v)
    yield "Host.send(block=v)", lambda v: Host().send("LoadAHRSPar", v)
    yield "Host.resync", lambda v: Host().resync(v)
    yield "Host.setting", lambda v: Host().setting(v)


PROBES = [*_codec_probes(), *_command_probes(), *_session_probes()]


@pytest.mark.parametrize(("name", "call"), PROBES, ids=[name for name, _ in PROBES])
def test_entry_point_raises_only_ilahrs_errors(name: str, call: Callable[[Any], object]) -> None:
    escaped = []
    for value in BAD:
        try:
            call(value)
        except ilahrs.IlahrsError as exc:
            assert isinstance(exc.kind, ilahrs.ErrorKind)
            assert len(str(exc)) <= MESSAGE_LIMIT, f"{name}: a message of {len(str(exc))} characters"
        except Exception as exc:
            shown = repr(value) if len(repr(value)) < 40 else f"{type(value).__name__} of {len(repr(value))}"
            escaped.append(f"{shown}: {type(exc).__name__}: {str(exc)[:80]}")
    assert not escaped, f"{name} raised non-IlahrsError exceptions:\n" + "\n".join(escaped)


def test_documented_cases_from_the_issues() -> None:
    cases: list[Callable[[], object]] = [
        lambda: ilahrs.Frame.parse("aa55"),  # type: ignore[arg-type]
        lambda: ilahrs.Frame.parse(2**40),  # type: ignore[arg-type]
        lambda: ilahrs.Frame.parse(-1),  # type: ignore[arg-type]
        lambda: ilahrs.PahrSentence.parse(5),  # type: ignore[arg-type]
        lambda: ilahrs.Frame(message_type=1.0, payload=b"x").build(),  # type: ignore[arg-type]
        lambda: ilahrs.build_command("Stop", reserved=1.5),  # type: ignore[arg-type]
        lambda: Device().advance(1e300),
        lambda: Host(reply_timeout=math.nan),
        lambda: Device(variant="bogus"),
        lambda: Host(state="bogus"),
        lambda: ilahrs.command_names(1.5),  # type: ignore[arg-type]
        lambda: ilahrs.decode_date(10**400),
    ]
    for case in cases:
        with pytest.raises(ilahrs.IlahrsError):
            case()
    # A sentence's NUL bytes were once read from an int; an int is not a sentence.
    with pytest.raises(ilahrs.IlahrsError) as info:
        ilahrs.PahrSentence.parse(5)  # type: ignore[arg-type]
    assert info.value.kind == ilahrs.ErrorKind.MALFORMED


def test_firmware_version_parts_that_are_not_ascii_digits_count_as_zero() -> None:
    assert firmware_version("4.²") == (4, 0)
    assert statemachine.lookup("runs_ready", "StopClbRun", "4.²") is not None


def test_a_huge_bad_value_gives_a_short_message() -> None:
    with pytest.raises(ilahrs.IlahrsError) as info:
        ilahrs.OrientationSensors.from_raw({"heading": "h" * 100_000_000})
    assert len(str(info.value)) < 200
    with pytest.raises(ilahrs.IlahrsError) as info:
        ilahrs.build_command("A" * 10_000_000)
    assert len(str(info.value)) < 200


def test_variant_by_name_everywhere_a_variant_is_taken() -> None:
    block = ilahrs.OrientationSensors(gyro_x=100)
    name, variant = next(iter(ilahrs.VARIANTS.items()))
    assert block.values(name) == block.values(variant)
    assert block.gyro_x_dps(name) == block.gyro_x_dps(variant)
    assert "gyro_x" not in block.values()
    assert "gyro_x" in (block.values.__doc__ or "")  # the docstring says what is left out
    with pytest.raises(ilahrs.IlahrsError) as info:
        block.values(name.upper() + "x")
    assert info.value.field == "variant"
    with pytest.raises(ilahrs.IlahrsError):
        block.gyro_x_dps(None)  # type: ignore[arg-type]


def test_json_ready_form_of_every_payload() -> None:
    for cls in ilahrs.PAYLOADS.values():
        text = json.dumps(cls().json(), allow_nan=False)
        assert set(json.loads(text)) == {f.name for f in cls.FIELDS}
        assert issubclass(cls, PayloadBase)


def test_unknown_names_get_the_closest_name() -> None:
    with pytest.raises(ilahrs.IlahrsError, match="did you mean 'AHRScont3'"):
        ilahrs.build_command("AHRSCont3")
    with pytest.raises(ilahrs.IlahrsError, match="did you mean 'AHRScont3'"):
        Host().send("AHRSCont3")
    with pytest.raises(ilahrs.IlahrsError, match="did you mean 'update_rate'"):
        ilahrs.build_parameter_block("LoadAHRSPar", {"update_rat": 50})


def test_parameter_block_from_raw_values_and_misspelt_keys() -> None:
    frame = ilahrs.build_parameter_block("LoadAHRSPar", {"update_rate": 50})
    block = ilahrs.PAYLOADS[ilahrs.COMMANDS["LoadAHRSPar"].parameter_block or ""].from_raw({"update_rate": 50})
    assert frame == ilahrs.Frame(ilahrs.MessageType.DATA, block.build()).build()
    host = Host()
    with pytest.raises(ilahrs.IlahrsError) as info:
        host.send("LoadAHRSPar", {"bogus": 1})
    assert info.value.kind == ilahrs.ErrorKind.MALFORMED
    assert host.owed == () and host.state == "idle"  # nothing was sent or expected
    sent = host.send("LoadAHRSPar", {"update_rate": 50})
    assert sent.endswith(frame)


def test_a_session_can_start_mid_stream() -> None:
    device = Device(seed=3)
    device.receive(ilahrs.build_command("AHRScont3"))
    device.advance(31.0)
    capture = device.advance(1.0)
    host = Host.mid_stream("AHRScont3")
    events = host.receive(capture)
    outputs = [e for e in events if isinstance(e, ilahrs.Output)]
    assert len(outputs) >= 90 and len(outputs) == len(events)
    assert isinstance(outputs[0].data, ilahrs.PAYLOADS[ilahrs.COMMANDS["AHRScont3"].starts_output or ""])
    assert Host(state=host.state, output="AHRScont3").receive(capture) == events


def test_host_events_carry_the_host_clock() -> None:
    device, host = Device(seed=1), Host()
    host.advance(2.5)
    [event] = host.receive(device.receive(host.send("ReadAHRSPar")))
    assert event.at == 2.5
