"""Whole captures of several kinds as columns: `ilahrs.columns_by_kind` gives the kinds, offsets,
times and values the message-by-message path gives (numpy and the array fallback, raw dumps and
pcapng with timestamps, clean and damaged), and `ilahrs decode --to csv` of a raw dump writes the
same bytes and summary through the columnar path as through the messages."""

from __future__ import annotations

import io
import math
import random
import subprocess
import sys
from typing import Any

import damage_support
import pytest

import ilahrs
from ilahrs import columnar
from ilahrs.cli.capture import Chunk
from ilahrs.cli.decode import BASE_COLUMNS, CaptureDecoder, ColumnarCsv, RowWriter, decode_columns, kinds, summary
from ilahrs.pcapng import Direction, PcapngWriter

SEED = 20140311
VARIANT = ilahrs.VARIANTS["g300_a2_tmga"]
INBOUND = [cls for cls in ilahrs.PAYLOADS.values() if cls.DIRECTION == "device_to_host"]
OUTPUT = ilahrs.PAYLOADS["full_output"]


def sentence(rng: random.Random) -> bytes:
    values = {"roll": rng.randrange(-18000, 18001), "pitch": rng.randrange(-9000, 9001)}
    values |= {"heading": rng.randrange(36000), "usw": rng.randrange(65536), "vdd": rng.randrange(1000)}
    return ilahrs.PahrSentence(**values).build().encode("ascii")


def message(rng: random.Random) -> bytes:
    """A frame of any device-to-host table (the output format most often), a command frame or a
    $PAHR sentence."""
    pick = rng.randrange(10)
    if pick < 4:
        return ilahrs.Frame(ilahrs.MessageType.DATA, rng.randbytes(OUTPUT.SIZE)).build()
    if pick < 7:
        cls = rng.choice(INBOUND)
        return ilahrs.Frame(ilahrs.MessageType.DATA, rng.randbytes(cls.SIZE)).build()
    if pick == 7:
        return ilahrs.build_command(rng.choice(list(ilahrs.COMMANDS)))
    if pick == 8:
        return ilahrs.Frame(ilahrs.MessageType.COMMAND, rng.randbytes(rng.randrange(1, 4))).build()
    return sentence(rng)


def bench_capture(count: int, rng: random.Random) -> bytes:
    """As `make bench` builds it: output-format frames, a few bytes of noise before one in ten."""
    parts = []
    for index in range(count):
        if index % 10 == 0:
            parts.append(rng.randbytes(rng.randrange(1, 8)))
        parts.append(ilahrs.Frame(ilahrs.MessageType.DATA, rng.randbytes(OUTPUT.SIZE)).build())
    return b"".join(parts)


def mixed_capture(count: int, rng: random.Random) -> bytes:
    """Messages of every kind with damage: noise, truncated and corrupted messages, false headers,
    a message inside a cut one, and a cut one at the end."""
    parts: list[bytes] = []
    for index in range(count):
        good = message(rng)
        choice = index % 11
        if choice < damage_support.KINDS:
            parts.append(damage_support.damage(good, choice, rng))
        elif choice == 3:
            parts.append(b"\xaa\x55\x01\x00\xff\x00" + b"$PAHR,1*00\r\n")
        elif choice == 4:
            parts.append(good[:9] + message(rng))
        parts.append(good)
    parts.append(message(rng)[:-3])
    return b"".join(parts)


CAPTURES = [("bench", bench_capture), ("mixed", mixed_capture)]


def reference(data: bytes, output: str | None) -> list[tuple[str, int, Any]]:
    """(kind, offset, payload or sentence) of every message, message by message."""
    decoder = CaptureDecoder(context=False, output=output, output_known=output is not None)
    messages = decoder.feed(Chunk(None, Direction.INBOUND, data)) + decoder.finish()
    return [(m.kind, m.offset, m.data) for m in messages]


def expected_sets(messages: list[tuple[str, int, Any]], times: list[float]) -> dict[str, dict[str, list[Any]]]:
    result: dict[str, dict[str, list[Any]]] = {}
    for (kind, offset, data), when in zip(messages, times, strict=True):
        if kind not in columnar.KINDS:
            continue
        row: dict[str, Any] = {"time": when, "kind": columnar.KINDS.index(kind), "offset": offset}
        if isinstance(data, ilahrs.PahrSentence):
            row |= data.values()
        else:
            values = data.values(VARIANT)
            for info in data.FIELDS:
                if info.type not in ("char", "reserved"):
                    row[info.name] = values.get(info.name, getattr(data, info.name))
        table = result.setdefault(kind, {})
        for name, value in row.items():
            table.setdefault(name, []).append(value)
    return {kind: result[kind] for kind in columnar.KINDS if kind in result}


def same(column: Any, values: list[Any]) -> None:
    got = column.tolist()
    assert len(got) == len(values)
    for a, b in zip(got, values, strict=True):
        assert a == b or (isinstance(a, float) and math.isnan(a) and math.isnan(b)), (a, b)
        assert type(a) is type(b), (a, b)


def check(table: dict[str, dict[str, Any]], expected: dict[str, dict[str, list[Any]]]) -> None:
    assert list(table) == list(expected)
    for kind, columns in expected.items():
        assert list(table[kind])[:3] == ["time", "kind", "offset"]
        assert set(table[kind]) == set(columns), kind
        for name, values in columns.items():
            same(table[kind][name], values)


@pytest.mark.parametrize("backend", ["numpy", "array"])
@pytest.mark.parametrize("output", [None, "full_output"])
@pytest.mark.parametrize(("name", "make"), CAPTURES, ids=[k for k, _ in CAPTURES])
def test_columns_by_kind_of_a_raw_dump_are_the_messages(
    name: str, make: Any, output: str | None, backend: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(columnar, "WINDOW", 997)  # many windows, messages across their edges
    monkeypatch.setattr(columnar, "ROWS", 101)  # columns filled in many batches
    data = make(1500, random.Random(SEED))
    messages = reference(data, output)
    assert len({kind for kind, _, _ in messages}) >= (1 if name == "bench" else 6)
    expected = expected_sets(messages, [math.nan] * len(messages))
    cls = None if output is None else ilahrs.PAYLOADS[output]
    check(ilahrs.columns_by_kind(data, output=cls, variant=VARIANT, backend=backend), expected)


def pcapng(data: bytes, rng: random.Random) -> tuple[bytes, list[tuple[int, int]]]:
    """`data` as device-to-host packets of random sizes with timestamps (µs), a host-to-device
    packet now and then; also (end offset, timestamp) of each device-to-host packet."""
    out = io.BytesIO()
    writer = PcapngWriter(out, port="socket://test", baud=115200)
    stamp, at, ends = 1_700_000_000_000_000, 0, []
    while at < len(data):
        size = rng.randrange(1, 300)
        stamp += rng.randrange(1, 20000)
        writer.write(data[at : at + size], stamp, Direction.INBOUND)
        at = min(len(data), at + size)
        ends.append((at, stamp))
        if rng.randrange(5) == 0:
            writer.write(ilahrs.build_command("GetBIT"), stamp + 1, Direction.OUTBOUND)
    return out.getvalue(), ends


@pytest.mark.parametrize("backend", ["numpy", "array"])
@pytest.mark.parametrize(("name", "make"), CAPTURES, ids=[k for k, _ in CAPTURES])
def test_columns_of_pcapng_carry_the_packets_timestamps(
    name: str, make: Any, backend: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(columnar, "WINDOW", 1499)
    rng = random.Random(SEED)
    data = make(800, rng)
    capture, ends = pcapng(data, rng)
    messages = reference(data, "full_output")
    times = []
    for _kind, offset, payload in messages:
        size = len(payload.build().encode("ascii")) if isinstance(payload, ilahrs.PahrSentence) else None
        last = offset + (size if size is not None else len(_raw(data, offset))) - 1
        times.append(next(stamp for end, stamp in ends if end > last) / 1_000_000)
    expected = expected_sets(messages, times)
    check(ilahrs.columns_by_kind(capture, output=OUTPUT, variant=VARIANT, backend=backend), expected)
    table = ilahrs.columns(capture, OUTPUT, variant=VARIANT, backend=backend)
    for column in ("time", "kind", "offset", "heading"):
        same(table[column], expected["full_output"][column])


def _raw(data: bytes, offset: int) -> bytes:
    length = data[offset + 4] | data[offset + 5] << 8
    return data[offset : offset + 2 + length]


def test_columns_without_numpy_give_arrays(monkeypatch: pytest.MonkeyPatch) -> None:
    data = mixed_capture(300, random.Random(SEED))
    expected = expected_sets(reference(data, None), [math.nan] * len(reference(data, None)))
    monkeypatch.setitem(sys.modules, "numpy", None)
    table = ilahrs.columns_by_kind(data, variant=VARIANT)
    assert {type(c).__module__ for t in table.values() for c in t.values()} == {"array"}
    check(table, expected)


def test_kind_codes_name_their_tables() -> None:
    assert (*ilahrs.PAYLOADS, "PAHR") == columnar.KINDS
    assert ilahrs.columns_by_kind(b"") == {}
    with pytest.raises(ilahrs.IlahrsError) as caught:
        ilahrs.columns_by_kind(b"\x0a\x0d\x0d\x0a\x00\x00")
    assert caught.value.kind is ilahrs.ErrorKind.MALFORMED


def message_csv(
    data: bytes, selected: list[str], output: str | None, *, raw: bool, chunk: int
) -> tuple[str, list[str]]:
    out = io.StringIO()
    decoder = CaptureDecoder(context=False, output=output, output_known=output is not None)
    writer = RowWriter(out, "csv", selected, VARIANT, raw=raw)
    wanted = set(selected)
    for at in range(0, len(data), chunk):
        for m in decoder.feed(Chunk(None, Direction.INBOUND, data[at : at + chunk])):
            if m.kind in wanted:
                writer.write(m)
    for m in decoder.finish():
        if m.kind in wanted:
            writer.write(m)
    return out.getvalue(), summary(decoder, "ilahrs decode")


def columnar_csv(
    data: bytes, selected: list[str], output: str | None, *, raw: bool, chunk: int
) -> tuple[str, list[str]]:
    out = io.StringIO()
    decoder = ColumnarCsv(out, selected, VARIANT, raw=raw, output=output)
    for at in range(0, len(data), chunk):
        decoder.feed(data[at : at + chunk])
    decoder.finish()
    return out.getvalue(), summary(decoder, "ilahrs decode")


SELECTIONS = [("all", None), ("some", ["full_output", "PAHR", "GetBIT", "frame", "bit_result"])]


@pytest.mark.parametrize("backend", ["numpy", "array"])
@pytest.mark.parametrize("raw", [False, True], ids=["units", "raw"])
@pytest.mark.parametrize("chosen", [c for _, c in SELECTIONS], ids=[k for k, _ in SELECTIONS])
@pytest.mark.parametrize("make", [m for _, m in CAPTURES], ids=[k for k, _ in CAPTURES])
def test_decode_csv_through_columns_is_byte_for_byte_the_messages(
    make: Any, chosen: list[str] | None, raw: bool, backend: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(columnar, "WINDOW", 1021)
    if backend == "array":
        monkeypatch.setitem(sys.modules, "numpy", None)
    data = make(1200, random.Random(SEED))
    selected = chosen or kinds()
    for output, chunk in ((None, 4096), ("full_output", 333)):
        expected = message_csv(data, selected, output, raw=raw, chunk=chunk)
        got = columnar_csv(data, selected, output, raw=raw, chunk=chunk)
        assert got[0].splitlines()[0].split(",")[len(BASE_COLUMNS) :] == decode_columns(selected)
        assert got[0].count("\n") > 100
        assert got == expected


def test_ilahrs_decode_to_csv_of_a_raw_dump_goes_the_columnar_way(tmp_path: Any) -> None:
    data = mixed_capture(600, random.Random(SEED))
    dump = tmp_path / "dump.bin"
    dump.write_bytes(data)
    command = [sys.executable, "-m", "ilahrs", "decode", str(dump), "--to", "csv", "--output-format", "AHRScont1"]
    result = subprocess.run(command, capture_output=True, text=True, check=True)
    text, lines = message_csv(data, kinds(), "full_output", raw=False, chunk=1 << 20)
    assert result.stdout == text
    assert result.stderr.splitlines() == lines
