"""Atheris (libFuzzer for Python) targets on the Python binding, instrumented for coverage.

    python fuzz/python/targets.py TARGET [libFuzzer options] [corpus dirs]

TARGET is one of:

    stream     a byte giving a chunk size (low 7 bits) and the strict option (top bit, E42), then
               bytes: `StreamDecoder` fed whole and in chunks of that size hands out the same
               messages and discards the same bytes; every byte is in one message or discarded;
               every frame parses (strictly too, when strict) and re-builds to its bytes, every
               sentence parses to the same values; with the line idle after each chunk (E41), the
               events are those of each chunk decoded on its own
    payloads   a byte choosing a payload table, then one message: the table parses it (exact size
               only), and what builds re-builds to the same bytes; `Frame.parse`, `decode_command`
               and `ack_for` agree with the builders on it
    sentences  one $PAHR sentence: what parses re-builds to text that parses to the same values, and
               parses the same from bytes and from text
    device     records (fuzz/records.py) of what a host sends to `Device`: every byte the device sends
               is part of a valid message (the rest of the input is left once it has sent 2 KiB)
    host       records of commands sent by `Host` and bytes it receives: the session reports, never
               raises anything but IlahrsError, and what it sends is valid messages

Anything raised that is not an IlahrsError (where the API raises one) is a crash, as is a broken
property (AssertionError). The atheris version is pinned in fuzz/requirements.txt; `make fuzz`
installs it under build/ and runs these (fuzz/run.py).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from pathlib import Path

import atheris  # type: ignore[import-untyped]

sys.path.insert(0, str(Path(__file__).resolve().parent))
import records

with atheris.instrument_imports(include=["ilahrs"]):
    import ilahrs
    from ilahrs.errors import IlahrsError

NAMES = tuple(ilahrs.COMMANDS)
TABLES = tuple(ilahrs.PAYLOADS.values())
DEVICE_OUTPUT = 2048  # bytes a Device may send for one input: output blocks cost time, not coverage


def decode(chunks: list[bytes], strict: bool = False, idle: bool = False) -> tuple[list[ilahrs.StreamEvent], int]:
    """Every chunk fed, the line idle after each one when `idle` (E41), then the end of input."""
    decoder = ilahrs.StreamDecoder(strict=strict)
    events: list[ilahrs.StreamEvent] = []
    for chunk in chunks:
        events += decoder.feed(chunk)
        if idle:
            events += decoder.idle()
    events += decoder.finish()
    return events, decoder.discarded


def valid_messages(data: bytes) -> None:
    """`data` is whole messages, nothing discarded."""
    events, discarded = decode([data])
    assert discarded == 0 and sum(len(e.raw) for e in events) == len(data), data.hex()


def stream(data: bytes) -> None:
    if not data:
        return
    size, strict, line = max(data[0] & 0x7F, 1), data[0] >= 0x80, data[1:]
    whole = decode([line], strict)
    chunks = [line[at : at + size] for at in range(0, len(line), size)]
    assert decode(chunks, strict) == whole
    assert sum(len(e.raw) for e in whole[0]) + whole[1] == len(line)
    segments = [decode([chunk], strict) for chunk in chunks]
    idle = ([e for events, _ in segments for e in events], sum(count for _, count in segments))
    assert decode(chunks, strict, idle=True) == idle
    for event in whole[0]:
        if event.frame is not None:
            assert ilahrs.Frame.parse(event.raw, strict=strict) == event.frame and event.frame.build() == event.raw
        else:
            assert ilahrs.PahrSentence.parse(event.raw) == event.sentence


def payloads(data: bytes) -> None:
    if not data:
        return
    table, rest = TABLES[data[0] % len(TABLES)], data[1:]
    try:
        value = table.parse(rest)
    except IlahrsError:
        assert len(rest) != table.SIZE
    else:
        try:
            assert value.build() == rest
        except IlahrsError as error:
            assert error.kind == ilahrs.ErrorKind.OUT_OF_RANGE
    try:
        frame = ilahrs.Frame.parse(rest)
    except IlahrsError:
        frame = None
    if frame is not None:
        assert frame.build() == rest
        valid_messages(ilahrs.ack_for(rest))
    try:
        code, names = ilahrs.decode_command(rest)
    except IlahrsError:
        return
    assert frame is not None and all(ilahrs.build_command(name, frame.reserved) == rest for name in names), names
    assert all(ilahrs.COMMANDS[name].code == code for name in names)


def sentences(data: bytes) -> None:
    try:
        sentence = ilahrs.PahrSentence.parse(data)
    except IlahrsError:
        return
    assert ilahrs.PahrSentence.parse(data.decode("latin-1")) == sentence
    assert ilahrs.PahrSentence.parse(sentence.build()) == sentence


def device(data: bytes) -> None:
    model, sent = ilahrs.Device(), 0
    for op, arg, raw in records.read(data):
        if sent > DEVICE_OUTPUT:
            return
        if op == records.BYTES:
            out = model.receive(raw)
        elif op == records.COMMAND:
            out = model.receive(ilahrs.build_command(NAMES[arg % len(NAMES)]))
        elif op == records.LONG_WAIT and model.next_event_in is not None:
            out = model.advance(min(records.seconds(op, arg), model.next_event_in))
        else:
            out = model.advance(records.seconds(op, arg))
        valid_messages(out)
        sent += len(out)


def host(data: bytes) -> None:
    session = ilahrs.Host()
    for op, arg, raw in records.read(data):
        if op == records.BYTES:
            session.receive(raw)
        elif op == records.COMMAND:
            name = NAMES[arg % len(NAMES)]
            try:
                sent = session.send(name, {} if ilahrs.COMMANDS[name].parameter_block else None)
            except IlahrsError:
                continue
            valid_messages(sent)
        else:
            session.advance(records.seconds(op, arg))


TARGETS: dict[str, Callable[[bytes], None]] = {
    "stream": stream,
    "payloads": payloads,
    "sentences": sentences,
    "device": device,
    "host": host,
}


def main() -> None:
    if len(sys.argv) < 2 or sys.argv[1] not in TARGETS:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    target = TARGETS[sys.argv[1]]
    # libFuzzer starts itself again for -merge (and -fork): FUZZ_SELF names a program that runs this
    # target with the options it is given (fuzz/run.py writes one).
    program = os.environ.get("FUZZ_SELF", sys.argv[0])
    atheris.Setup([program, *sys.argv[2:]], target)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
