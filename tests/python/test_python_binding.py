"""The Python binding: exact inverses, refusals, and the stream decoder's leftmost-valid-message rule."""

from __future__ import annotations

import math
import random
import struct
from collections.abc import Callable
from typing import Any

import pytest

import ilahrs
from generator import build_spec
from generator.model import Field

SPEC = build_spec()
SEED = 20140311


def f32(value: float) -> float:
    result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    return result


def random_value(field: Field, rng: random.Random) -> Any:
    """A valid raw value for `field`."""
    if field.kind == "reserved":
        return bytes(rng.randrange(256) for _ in range(field.size))
    if field.kind == "char":
        return "".join(chr(rng.randrange(0x20, 0x7F)) for _ in range(rng.randrange(field.size + 1))).rstrip("\x00")
    if field.encoding == "date":
        return f32(ilahrs.encode_date(rng.randrange(1990, 2100), rng.randrange(1, 13), rng.randrange(1, 29)))
    if field.encoding == "declination":
        return f32(rng.choice([rng.uniform(-180, 180), ilahrs.DECLINATION_COMPUTE]))
    bounds = field.bounds
    assert bounds is not None
    low, high = bounds
    if field.is_integer:
        return rng.choice([int(low), int(high), rng.randint(int(low), int(high))])
    low, high = max(low, -1e6), min(high, 1e6)
    return f32(rng.choice([low, high, rng.uniform(low, high)]))


def test_appendix_c_commands_build_and_decode() -> None:
    for command in SPEC.commands:
        frame = ilahrs.build_command(command.name)
        checksum = (0x07 + command.code) & 0xFFFF
        assert frame == bytes([0xAA, 0x55, 0, 0, 7, 0, command.code, checksum & 0xFF, checksum >> 8])
        code, names = ilahrs.decode_command(frame)
        assert code == command.code
        assert command.name in names
    assert ilahrs.decode_command(ilahrs.build_command("Stop"))[1] == ("ExitClb", "Stop")


@pytest.mark.parametrize(
    ("data", "kind", "offset"),
    [
        ("", "truncated", 0),
        ("AB", "bad_header", 0),
        ("AA", "truncated", 1),
        ("AA 54", "bad_header", 1),
        ("AA 55 00 00 07", "truncated", 5),
        ("AA 55 02 00 07 00 80 89 00", "bad_message_type", 2),
        ("AA 55 00 00 06 00 80 86 00", "bad_length", 4),
        ("AA 55 00 00 3B 00 80 BB 00", "bad_length", 4),
        ("AA 55 00 00 07 00 80 87", "truncated", 8),
        ("AA 55 00 00 07 00 80 88 00", "bad_checksum", 7),
        ("AA 55 00 00 07 00 80 87 00 00", "trailing_data", 9),
    ],
)
def test_frame_errors(data: str, kind: str, offset: int) -> None:
    with pytest.raises(ilahrs.IlahrsError) as info:
        ilahrs.Frame.parse(bytes.fromhex(data))
    assert info.value.kind == kind
    assert info.value.offset == offset


def test_frame_reserved_byte_is_kept() -> None:
    frame = ilahrs.Frame(ilahrs.MessageType.DATA, b"\x01\x02", reserved=0x5A)
    assert ilahrs.Frame.parse(frame.build()) == frame


def test_frame_build_refuses() -> None:
    for frame, kind in [
        (ilahrs.Frame(2, b"\x00"), "bad_message_type"),
        (ilahrs.Frame(0, b""), "bad_length"),
        (ilahrs.Frame(0, bytes(53)), "bad_length"),
        (ilahrs.Frame(0, b"\x00", reserved=256), "out_of_range"),
    ]:
        with pytest.raises(ilahrs.IlahrsError) as info:
            frame.build()
        assert info.value.kind == kind


def test_ack_is_the_checksum_of_the_message() -> None:
    for command in SPEC.commands:
        message = ilahrs.build_command(command.name)
        ack = ilahrs.Frame.parse(ilahrs.ack_for(message))
        assert ack.message_type == ilahrs.MessageType.DATA
        assert ack.payload == message[-2:]


@pytest.mark.parametrize("name", [p.name for p in SPEC.payloads])
def test_payload_round_trips(name: str) -> None:
    cls = ilahrs.PAYLOADS[name]
    payload = SPEC.payload(name)
    rng = random.Random(f"{SEED}-{name}")
    for _ in range(200):
        values = {f.name: random_value(f, rng) for f in payload.fields}
        obj = cls.from_raw(values)
        data = obj.build()
        assert len(data) == cls.SIZE
        again = cls.parse(data)
        assert again == obj
        assert again.build() == data
        assert list(again.raw()) == [f.name for f in payload.fields]


@pytest.mark.parametrize("name", [p.name for p in SPEC.payloads])
def test_payload_decode_accepts_any_bytes_and_rebuilds_them(name: str) -> None:
    cls = ilahrs.PAYLOADS[name]
    payload = SPEC.payload(name)
    rng = random.Random(f"{SEED}-bytes-{name}")
    for _ in range(200):
        data = bytearray(rng.randrange(256) for _ in range(cls.SIZE))
        obj = cls.parse(bytes(data))
        try:
            obj.check()
        except ilahrs.IlahrsError as exc:
            assert exc.field in {f.name for f in payload.fields}
            continue
        assert obj.build() == bytes(data)


@pytest.mark.parametrize("name", [p.name for p in SPEC.payloads])
def test_payload_size_errors(name: str) -> None:
    cls = ilahrs.PAYLOADS[name]
    with pytest.raises(ilahrs.IlahrsError) as info:
        cls.parse(bytes(cls.SIZE - 1))
    assert (info.value.kind, info.value.offset) == ("truncated", cls.SIZE - 1)
    with pytest.raises(ilahrs.IlahrsError) as info:
        cls.parse(bytes(cls.SIZE + 1))
    assert (info.value.kind, info.value.offset) == ("trailing_data", cls.SIZE)


def _refusals(field: Field) -> list[Any]:
    if field.kind == "reserved":
        return [bytes(field.size + 1), bytes(field.size - 1) if field.size > 1 else b""]
    if field.kind == "char":
        return ["x" * (field.size + 1), "\u20ac"]
    bad: list[Any] = ["1"]
    if field.is_float:
        bad += [math.nan, math.inf, -math.inf]
    if field.encoding == "declination":
        return [*bad, 200.0, -181.0, 360.0]
    if field.encoding == "date":
        return [*bad, 1800.0]
    bounds = field.bounds
    assert bounds is not None
    if field.is_integer:
        bad += [int(bounds[0]) - 1, int(bounds[1]) + 1, 1.5, True]
    elif field.range is not None:
        bad += [bounds[0] - 1, bounds[1] + 1]
    else:
        bad += [4e38]
    return bad


@pytest.mark.parametrize("name", [p.name for p in SPEC.payloads])
def test_payload_builders_refuse_out_of_range(name: str) -> None:
    cls = ilahrs.PAYLOADS[name]
    for field in SPEC.payload(name).fields:
        for value in _refusals(field):
            with pytest.raises(ilahrs.IlahrsError) as info:
                cls.from_raw({field.name: value})
            assert info.value.kind == "out_of_range", (field.name, value)
            assert info.value.field == field.name
            assert info.value.offset == field.offset


def test_engineering_values_and_variants() -> None:
    data = ilahrs.OrientationSensors(
        heading=35999, pitch=-9000, gyro_x=-150, acc_z=10000, mag_x=-3, vdd=5987, utermo=-400
    )
    assert data.heading_deg == pytest.approx(359.99)
    assert data.pitch_deg == -90.0
    assert data.gyro_x_dps(ilahrs.VARIANTS["g300_a2_tmga"]) == -1.5
    assert data.gyro_x_dps(ilahrs.VARIANTS["sn_11ac0001_0009"]) == -3.0
    assert data.acc_z_g(ilahrs.VARIANTS["g300_a6_tmga"]) == 2.0
    assert data.mag_x_nt == -30.0
    assert data.vdd_v == pytest.approx(5.987)
    assert data.utermo_degc == -40.0
    assert "gyro_x" not in data.values()
    assert data.values(ilahrs.VARIANTS["g300_a2_tmga"])["acc_z"] == 1.0
    bit = ilahrs.BitResult.parse(struct.pack("<hH", -4000, 0))
    assert bit.utermo100_degc == -40.0


def test_parameter_read_modify_write_as_the_readme_shows() -> None:
    read = ilahrs.AhrsParametersRead(
        update_rate=100, alignment_time=30, latitude=38.9, date=f32(2014.2), device_id="ID"
    )
    params = ilahrs.AhrsParametersRead.parse(read.build())
    shared = {f.name for f in ilahrs.AhrsParametersLoad.FIELDS} - {"reserved"}
    block = ilahrs.AhrsParametersLoad.from_raw(
        {k: v for k, v in params.raw().items() if k in shared} | {"update_rate": 50}
    )
    assert (block.update_rate, block.alignment_time, block.date) == (50, 30, params.date)
    assert block.reserved == bytes(14)


def test_unit_status_word() -> None:
    usw = ilahrs.UnitStatusWord(0x8181)
    assert usw.mode == ilahrs.UswMode.SLEEP
    assert usw.initial_alignment_failed
    assert usw.low_supply_voltage
    assert not usw.ok
    assert usw.failures == ilahrs.UswFlag.INITIAL_ALIGNMENT_FAILED
    assert ilahrs.UnitStatusWord(0x0080).mode == ilahrs.UswMode.UNKNOWN
    assert ilahrs.UnitStatusWord(0x0000).mode == ilahrs.UswMode.READINESS
    assert ilahrs.UnitStatusWord(0x0080).ok


def test_calibration_success_encoding() -> None:
    assert ilahrs.calibration_accuracy_deg(5) == 0.5
    assert ilahrs.calibration_accuracy_deg(255) is None
    assert not ilahrs.calibration_succeeded(0)


def test_every_date_survives_float32() -> None:
    for year in (1990, 2000, 2014, 2024, 2099):
        for month in range(1, 13):
            for day in range(1, 32):
                if not ilahrs.encodings.date_is_valid(year, month, day):
                    continue
                assert ilahrs.decode_date(f32(ilahrs.encode_date(year, month, day))) == (year, month, day)
    with pytest.raises(ilahrs.IlahrsError):
        ilahrs.encode_date(2014, 2, 29)


@pytest.mark.parametrize(
    ("text", "values"),
    [
        ("$PAHR,-012.34,005.50,359.99,-05.5,6.00,0080*10\r\n", (-1234, 550, 35999, -55, 600, 0x80)),
        ("$PAHR,-12.34,5.5,359.99,-5.5,6,80*10\r\n", (-1234, 550, 35999, -55, 600, 0x80)),
    ],
)
def test_nmea_decodes(text: str, values: tuple[int, ...]) -> None:
    body = text[1 : text.index("*")]
    checksum = 0
    for char in body.encode():
        checksum ^= char
    text = f"${body}*{checksum:02x}\r\n"
    sentence = ilahrs.PahrSentence.parse(text)
    assert vars_of(sentence) == values


def vars_of(sentence: ilahrs.PahrSentence) -> tuple[int, ...]:
    return tuple(getattr(sentence, name) for name in sentence.FIELDS)


def test_nmea_build_format() -> None:
    sentence = ilahrs.PahrSentence.from_values(
        roll=-12.34, pitch=5.5, heading=359.99, temperature=-5.5, vdd=6.0, usw=0x80
    )
    assert sentence.build() == "$PAHR,-012.34,005.50,359.99,-05.5,6.00,0080*10\r\n"
    assert ilahrs.PahrSentence.parse(sentence.build()) == sentence


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("$PAHR,-012.34,005.50,359.99,-05.5,6.00,0080*11\r\n", "bad_checksum"),
        ("$GPGGA,1*00\r\n", "bad_header"),
        ("PAHR\r\n", "bad_header"),
        ("$PAHR,-012.34,005.50,359.99,-05.5,6.00,0080*10", "truncated"),
        ("$PAHR,-012.34,005.50,359.99,-05.5,6.00,0080*10\r\nX", "trailing_data"),
        ("$PAHR," + "1" * 90 + "\r\n", "bad_length"),
    ],
)
def test_nmea_errors(text: str, kind: str) -> None:
    with pytest.raises(ilahrs.IlahrsError) as info:
        ilahrs.PahrSentence.parse(text)
    assert info.value.kind == kind


def test_nmea_field_errors() -> None:
    def sentence(body: str) -> str:
        checksum = 0
        for char in body.encode():
            checksum ^= char
        return f"${body}*{checksum:02X}\r\n"

    for body, kind, field in [
        ("PAHR,1,2,3,4,5", "malformed", None),
        ("PAHR,1,2,3,4,5,6,7", "malformed", None),
        ("PAHR,1.234,2,3,4,5,6", "malformed", "roll"),
        ("PAHR,1,2,360.00,4,5,6", "out_of_range", "heading"),
        ("PAHR,1,2,3,4,5,12345", "malformed", "usw"),
        ("PAHR,1,2,3,4,5,G", "malformed", "usw"),
        ("PAHR,1,-,3,4,5,6", "malformed", "pitch"),
        ("PAHR,99999999999999999999,2,3,4,5,6", "out_of_range", "roll"),
    ]:
        with pytest.raises(ilahrs.IlahrsError) as info:
            ilahrs.PahrSentence.parse(sentence(body))
        assert (info.value.kind, info.value.field) == (kind, field), body


def test_nmea_refuses_out_of_range() -> None:
    with pytest.raises(ilahrs.IlahrsError) as info:
        ilahrs.PahrSentence.from_values(roll=180.01, pitch=0, heading=0, temperature=0, vdd=0, usw=0)
    assert info.value.field == "roll"
    with pytest.raises(ilahrs.IlahrsError):
        ilahrs.PahrSentence.from_values(roll=math.nan, pitch=0, heading=0, temperature=0, vdd=0, usw=0)


# --- the stream decoder --------------------------------------------------------------------


def messages(rng: random.Random, count: int) -> list[bytes]:
    """Valid frames and sentences of every kind."""
    result = []
    for index in range(count):
        choice = index % 4
        if choice == 0:
            result.append(ilahrs.build_command(rng.choice(SPEC.commands).name))
        elif choice == 1:
            payload = rng.choice(SPEC.payloads)
            values = {f.name: random_value(f, rng) for f in payload.fields}
            result.append(ilahrs.Frame(1, ilahrs.PAYLOADS[payload.name].from_raw(values).build()).build())
        elif choice == 2:
            result.append(ilahrs.ack_for(ilahrs.build_command("AHRScont1")))
        else:
            sentence = ilahrs.PahrSentence(
                roll=rng.randint(-18000, 18000), heading=rng.randint(0, 35999), usw=rng.randrange(65536)
            )
            result.append(sentence.build().encode())
    return result


def decode(chunks: list[bytes]) -> tuple[list[bytes], int]:
    decoder = ilahrs.StreamDecoder()
    raws: list[bytes] = []
    for chunk in chunks:
        raws += [e.raw for e in decoder.feed(chunk)]
        assert decoder.pending <= ilahrs.MAX_MESSAGE_SIZE
    raws += [e.raw for e in decoder.finish()]
    return raws, decoder.discarded


def chunked(data: bytes, sizes: Callable[[], int]) -> list[bytes]:
    chunks, pos = [], 0
    while pos < len(data):
        size = sizes()
        chunks.append(data[pos : pos + size])
        pos += size
    return chunks


def fixed(size: int) -> Callable[[], int]:
    return lambda: size


def test_stream_whole_byte_by_byte_and_random_chunks() -> None:
    rng = random.Random(SEED)
    msgs = messages(rng, 200)
    data = b"".join(msgs)
    assert decode([data]) == (msgs, 0)
    assert decode([data[i : i + 1] for i in range(len(data))]) == (msgs, 0)
    assert decode(chunked(data, lambda: rng.randint(1, 100))) == (msgs, 0)


def test_stream_never_loses_a_message_to_garbage() -> None:
    rng = random.Random(SEED + 1)
    for _ in range(30):
        msgs = messages(rng, 40)
        parts: list[bytes] = []
        garbage_total = 0
        for msg in msgs:
            garbage = bytes(
                rng.choice([0xAA, 0x55, 0x24, 0x00, 0x07, rng.randrange(256)]) for _ in range(rng.randrange(6))
            )
            parts += [garbage, msg]
            garbage_total += len(garbage)
        data = b"".join(parts)
        raws, discarded = decode(chunked(data, lambda: rng.randint(1, 64)))
        # Every message is still there, in order (the garbage may add messages of its own only
        # if it happens to form one, which this garbage cannot: a frame needs a valid checksum
        # and length, a sentence a CR LF).
        it = iter(raws)
        assert all(any(r == m for r in it) for m in msgs)
        assert discarded + sum(len(r) for r in raws) == len(data)
        assert len(raws) == len(msgs)
        assert discarded == garbage_total


@pytest.mark.parametrize(
    ("prefix", "name"),
    [
        ("AA 55 00 00 FF FF", "false header with length 0xFFFF"),
        ("AA 55 01 00 30 00", "false header whose plausible length covers the next frame"),
        ("AA AA 55", "AA AA 55"),
        ("AA 55 00 00 07 00 80 87 01", "a corrupted frame"),
        ("24 50 41 48 52 2C 31", "a sentence cut short"),
    ],
)
def test_stream_false_starts_cost_nothing(prefix: str, name: str) -> None:
    good = ilahrs.build_command("GetBIT")
    junk = bytes.fromhex(prefix)
    data = junk + good + good
    for size in range(1, len(data) + 1):
        raws, discarded = decode(chunked(data, fixed(size)))
        assert raws == [good, good], name
        assert discarded == len(junk), name


def test_stream_header_inside_a_payload() -> None:
    inner = ilahrs.build_command("Stop")
    outer = ilahrs.Frame(1, inner + b"\x00").build()
    assert decode([outer]) == ([outer], 0)
    broken = outer[:-1] + bytes([outer[-1] ^ 1])
    assert decode([broken]) == ([inner], len(broken) - len(inner))


def test_stream_holds_at_most_the_longest_message() -> None:
    decoder = ilahrs.StreamDecoder()
    decoder.feed(b"$PAHR," + b"1" * 200)
    assert decoder.pending < ilahrs.MAX_MESSAGE_SIZE
    decoder.feed(b"\xaa\x55\x01\x00\x3a\x00" + bytes(40))
    assert decoder.pending <= ilahrs.MAX_MESSAGE_SIZE
