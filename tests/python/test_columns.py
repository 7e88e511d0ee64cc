"""Whole captures at once: `ilahrs.decode_output` gives the objects a mid-stream host gives, and
`ilahrs.columns` the same values as columns, with numpy and with the array fallback, on clean and
on damaged captures; `StreamDecoder.feed_iter` is `feed` one message at a time."""

from __future__ import annotations

import random
import sys
from typing import Any

import damage_support
import pytest

import ilahrs
from ilahrs.statemachine import OUTPUT_FORMATS

SEED = 20140311
VARIANT = ilahrs.VARIANTS["g300_a2_tmga"]
TABLES = [ilahrs.PAYLOADS[name] for name in OUTPUT_FORMATS.values() if name is not None]
OTHER = ilahrs.PAYLOADS["initial_alignment"]


def frame(cls: type[ilahrs.Payload], rng: random.Random) -> bytes:
    return ilahrs.Frame(ilahrs.MessageType.DATA, rng.randbytes(cls.SIZE)).build()


def clean_capture(cls: type[ilahrs.Payload], count: int, rng: random.Random) -> bytes:
    return b"".join(frame(cls, rng) for _ in range(count))


def damaged_capture(cls: type[ilahrs.Payload], count: int, rng: random.Random) -> bytes:
    """Good frames mixed with noise, false headers, truncated and corrupted frames, frames of another
    table and of the command type, sentences, and a good frame inside a truncated one."""
    parts: list[bytes] = []
    for index in range(count):
        good = frame(cls, rng)
        choice = index % 9
        if choice < damage_support.KINDS:
            parts.append(damage_support.damage(good, choice, rng))
        elif choice == 3:
            parts.append(frame(OTHER, rng) + ilahrs.Frame(ilahrs.MessageType.COMMAND, b"\x83").build())
        elif choice == 4:
            parts.append(b"$PAHR,1,2*00\r\n\xaa\x55\x01")
        elif choice == 5:
            parts.append(good[:9] + frame(cls, rng))
        parts.append(good)
    parts.append(frame(cls, rng)[:-3])
    return b"".join(parts)


def objects(capture: bytes, cls: type[ilahrs.Payload]) -> list[Any]:
    """The blocks of `cls` as the stream decoder and the payload class give them."""
    decoder = ilahrs.StreamDecoder()
    events = decoder.feed(capture) + decoder.finish()
    return [
        cls.parse(event.frame.payload)
        for event in events
        if event.frame is not None
        and event.frame.message_type == ilahrs.MessageType.DATA
        and len(event.frame.payload) == cls.SIZE
    ]


def offsets(capture: bytes, cls: type[ilahrs.Payload]) -> list[int]:
    decoder = ilahrs.StreamDecoder()
    result, at = [], 0
    for event in decoder.feed(capture) + decoder.finish():
        at = capture.index(event.raw, at)
        frame_ = event.frame
        if frame_ is not None and frame_.message_type == ilahrs.MessageType.DATA and len(frame_.payload) == cls.SIZE:
            result.append(at)
        at += len(event.raw)
    return result


def expected_columns(blocks: list[Any], cls: type[ilahrs.Payload]) -> dict[str, list[Any]]:
    result: dict[str, list[Any]] = {}
    for info in cls.FIELDS:
        if info.type in ("char", "reserved"):
            continue
        result[info.name] = [block.values(VARIANT).get(info.name, getattr(block, info.name)) for block in blocks]
    return result


CAPTURES = [("clean", clean_capture), ("damaged", damaged_capture)]


@pytest.mark.parametrize("cls", TABLES, ids=lambda c: c.NAME)
@pytest.mark.parametrize(("kind", "make"), CAPTURES, ids=[k for k, _ in CAPTURES])
def test_decode_output_gives_the_stream_decoders_objects(cls: type[ilahrs.Payload], kind: str, make: Any) -> None:
    capture = make(cls, 300, random.Random(SEED))
    expected = objects(capture, cls)
    assert len(expected) >= 300
    decoded = list(ilahrs.decode_output(capture, cls))
    assert decoded == expected
    assert [type(block) for block in decoded] == [cls] * len(expected)
    assert [hash(block) for block in decoded] == [hash(block) for block in expected]
    assert list(ilahrs.decode_output(bytearray(capture), cls)) == expected
    assert list(ilahrs.decode_output(memoryview(capture), cls)) == expected


def test_decoded_objects_stay_immutable() -> None:
    block = next(ilahrs.decode_output(clean_capture(TABLES[0], 1, random.Random(SEED)), TABLES[0]))
    with pytest.raises(AttributeError):
        block.heading = 1  # type: ignore[attr-defined]


@pytest.mark.parametrize("backend", ["numpy", "array"])
@pytest.mark.parametrize("cls", TABLES, ids=lambda c: c.NAME)
@pytest.mark.parametrize(("kind", "make"), CAPTURES, ids=[k for k, _ in CAPTURES])
def test_columns_hold_the_objects_values(cls: type[ilahrs.Payload], kind: str, make: Any, backend: str) -> None:
    capture = make(cls, 300, random.Random(SEED))
    table = ilahrs.columns(capture, cls, variant=VARIANT, backend=backend)
    expected = expected_columns(objects(capture, cls), cls)
    assert list(table)[:3] == ["time", "kind", "offset"]
    assert set(table) == {"time", "kind", "offset", *expected}
    assert table["offset"].tolist() == offsets(capture, cls)
    for name, values in expected.items():
        column = table[name]
        assert column.tolist() == values, name
        assert [type(value) for value in column.tolist()] == [type(value) for value in values], name


def test_columns_without_variant_leave_variant_fields_out() -> None:
    cls = ilahrs.PAYLOADS["orientation_sensors"]
    capture = clean_capture(cls, 5, random.Random(SEED))
    for backend in ("numpy", "array"):
        table = ilahrs.columns(capture, cls, backend=backend)
        assert "gyro_x" not in table
        assert "heading" in table


def test_columns_fall_back_to_array_without_numpy(monkeypatch: pytest.MonkeyPatch) -> None:
    cls = TABLES[0]
    capture = damaged_capture(cls, 50, random.Random(SEED))
    monkeypatch.setitem(sys.modules, "numpy", None)
    table = ilahrs.columns(capture, cls)
    assert type(table["offset"]).__module__ == "array"
    assert table["heading"].tolist() == expected_columns(objects(capture, cls), cls)["heading"]
    with pytest.raises(ilahrs.IlahrsError) as caught:
        ilahrs.columns(capture, cls, backend="numpy")
    assert caught.value.kind is ilahrs.ErrorKind.MALFORMED


@pytest.mark.parametrize("capture", [b"", b"\xaa", b"\xaa\x55\x01\x00", b"\x00" * 10])
@pytest.mark.parametrize("backend", ["numpy", "array"])
def test_columns_of_captures_without_blocks_are_empty(capture: bytes, backend: str) -> None:
    table = ilahrs.columns(capture, TABLES[0], backend=backend)
    assert all(len(column) == 0 for column in table.values())
    assert list(ilahrs.decode_output(capture, TABLES[0])) == []


@pytest.mark.parametrize(
    ("call", "kind"),
    [
        (lambda: ilahrs.columns("aa55", TABLES[0]), ilahrs.ErrorKind.MALFORMED),  # type: ignore[arg-type]
        (lambda: ilahrs.columns(b"", "full_output"), ilahrs.ErrorKind.MALFORMED),  # type: ignore[arg-type]
        (lambda: ilahrs.columns(b"", TABLES[0], backend="pandas"), ilahrs.ErrorKind.MALFORMED),
        (lambda: ilahrs.columns(b"", TABLES[0], variant="KG"), ilahrs.ErrorKind.OUT_OF_RANGE),
        (lambda: ilahrs.decode_output("aa55", TABLES[0]), ilahrs.ErrorKind.MALFORMED),  # type: ignore[arg-type]
        (lambda: ilahrs.decode_output(b"", int), ilahrs.ErrorKind.MALFORMED),
    ],
)
def test_bad_arguments_are_refused_at_once(call: Any, kind: ilahrs.ErrorKind) -> None:
    with pytest.raises(ilahrs.IlahrsError) as caught:
        call()
    assert caught.value.kind is kind


def test_feed_iter_is_feed_one_message_at_a_time() -> None:
    cls = TABLES[1]
    capture = damaged_capture(cls, 3000, random.Random(SEED))
    whole = ilahrs.StreamDecoder()
    expected = whole.feed(capture)
    streaming = ilahrs.StreamDecoder()
    assert list(streaming.feed_iter(capture)) == expected
    assert (streaming.discarded, streaming.pending) == (whole.discarded, whole.pending)
    assert streaming.finish() == whole.finish()


def test_feed_iter_closed_early_keeps_the_bytes_it_has_not_scanned() -> None:
    cls = TABLES[0]
    capture = clean_capture(cls, 5000, random.Random(SEED))
    decoder = ilahrs.StreamDecoder()
    events = decoder.feed_iter(capture)
    first = next(events)
    events.close()
    assert first.frame is not None
    assert decoder.pending > 0
    rest = decoder.feed(b"") + decoder.finish()
    assert len(rest) < 5000 - 1
    assert rest[-1].raw == capture[-len(rest[-1].raw) :]
    with pytest.raises(ilahrs.IlahrsError):
        decoder.feed_iter("aa55")  # type: ignore[arg-type]
