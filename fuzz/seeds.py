"""Seed corpora and libFuzzer dictionaries for every fuzz target, made from the spec's generated tables.

Nothing here is written by hand: the messages come from the Python binding's builders and its device
model (`ilahrs.Device`, `ilahrs.Host`), and the dictionary words from the binding's tables (frame
header, message types, lengths of every payload table, command codes, the $PAHR prefix and
separators). Sessions are seeded random walks through the state machine (a command valid in the
device's mode, most of the time; its parameter block when it takes one; time passed to the device's
next timer), kept when they reach a state transition or a kind of message no kept session reached.

Each fuzz target reads its input in one of these shapes (fuzz/README.md), and gets the seeds and the
dictionary of its shape:

    selector    a byte choosing a payload table (modulo their number), then one message:
                c-fuzz_parsers, rust-payloads, python-payloads
    stream      bytes as they come down the line: c-fuzz_stream
    cut-stream  a byte giving a chunk size, then the line's bytes: rust-stream, python-stream
    sentence    one $PAHR sentence: python-sentences
    device      records of what a host sends (fuzz/python/records.py): python-device
    host        records of a host's commands and the device's answers: python-host

    python fuzz/seeds.py OUT        writes OUT/seeds/SHAPE/* and OUT/dict/SHAPE.dict

The output depends only on the spec (seeded walks, files named by the SHA-1 of their bytes).
"""

from __future__ import annotations

import hashlib
import random
import shutil
import struct
import sys
from dataclasses import dataclass, field
from pathlib import Path

import ilahrs
from ilahrs import nmea, spec
from ilahrs.errors import IlahrsError

sys.path.insert(0, str(Path(__file__).resolve().parent / "python"))
import records

SHAPES = ("selector", "stream", "cut-stream", "sentence", "device", "host")
WALKS = 400
STEPS = 8
MAX_STREAM = 512  # the fuzzers take at most 512 bytes of a stream or a session (fuzz/run.py)
PER_KIND = 3
NAMES = tuple(ilahrs.COMMANDS)


@dataclass
class Session:
    """One walk: what the host sent and the device answered, in order, and what it reached."""

    device_records: bytearray = field(default_factory=bytearray)
    host_records: bytearray = field(default_factory=bytearray)
    line: bytearray = field(default_factory=bytearray)  # both directions, in order
    answers: bytearray = field(default_factory=bytearray)  # what the device sent
    reached: set[tuple[object, ...]] = field(default_factory=set)


def message_kind(event: ilahrs.StreamEvent) -> tuple[object, ...]:
    if event.frame is None:
        return ("sentence",)
    return ("frame", event.frame.message_type, len(event.frame.payload))


def walk(rng: random.Random) -> Session:
    device, host, session = ilahrs.Device(seed=rng.randrange(1 << 16)), ilahrs.Host(), Session()

    def answer(data: bytes, when: str) -> None:
        session.answers += data
        session.line += data
        session.host_records += records.write_bytes(data)
        try:
            host.receive(data)
        except IlahrsError:
            session.reached.add(("host refuses", when))
        session.reached.update(message_kind(e) for e in ilahrs.StreamDecoder().feed(data))

    for _ in range(rng.randrange(1, STEPS)):
        valid = [n for n in NAMES if device.mode in ilahrs.COMMANDS[n].valid_in]
        name = rng.choice(valid) if valid and rng.random() < 0.85 else rng.choice(NAMES)
        table = ilahrs.COMMANDS[name].parameter_block
        before = device.state
        sent = ilahrs.build_command(name) + (ilahrs.build_parameter_block(name, {}) if table else b"")
        try:
            host.send(name, {} if table else None)
        except IlahrsError:
            session.reached.add(("host refuses", name))
        session.host_records += records.write_command(NAMES.index(name))
        session.device_records += records.write_command(NAMES.index(name))
        if table:
            session.device_records += records.write_bytes(sent[-ilahrs.PAYLOADS[table].SIZE - spec.FRAME_OVERHEAD :])
        session.line += sent
        answer(device.receive(sent), name)
        session.reached.add((before, name, device.state))
        for _ in range(rng.choice((0, 1, 1, 2, 3))):
            wait = device.next_event_in
            if wait is None or len(session.answers) > MAX_STREAM:
                break
            before = device.state
            session.device_records += records.write_until_timer(wait)
            session.host_records += records.write_wait(wait)
            answer(device.advance(wait), "wait")
            try:
                host.advance(wait)
            except IlahrsError:
                session.reached.add(("host refuses", "wait"))
            session.reached.add((before, "timer", device.state))
    return session


def sessions() -> list[Session]:
    """Seeded walks, each kept if it reached something no walk kept before it did."""
    rng, seen, kept = random.Random(0x1A5), set[tuple[object, ...]](), []
    for _ in range(WALKS):
        session = walk(rng)
        if session.reached - seen:
            seen |= session.reached
            kept.append(session)
    return kept


def messages(data: bytes) -> list[bytes]:
    decoder = ilahrs.StreamDecoder()
    return [e.raw for e in decoder.feed(data) + decoder.finish()]


def selector_seeds(kept: list[Session]) -> set[bytes]:
    """A payload table's index and one of its payloads; a table's index and a whole message."""
    tables = list(ilahrs.PAYLOADS.values())
    found: dict[tuple[int, ...], list[bytes]] = {}
    for msg in sorted({m for s in kept for m in messages(bytes(s.line))}):
        command = msg[: spec.HEADER_SIZE] == spec.HEADER and msg[spec.MESSAGE_TYPE_OFFSET] == ilahrs.MessageType.COMMAND
        kinds = found.setdefault((msg[0], len(msg), msg[spec.PAYLOAD_OFFSET] if command else -1), [])
        kinds += [msg][: PER_KIND - len(kinds)]
    out = {bytes([i]) + cls().build() for i, cls in enumerate(tables)}
    for i, msg in enumerate(m for kind in sorted(found) for m in found[kind]):
        out.add(bytes([i % len(tables)]) + msg)
        if msg[: spec.HEADER_SIZE] == spec.HEADER:
            payload = msg[spec.PAYLOAD_OFFSET : -spec.CHECKSUM_SIZE]
            out.update(bytes([t]) + payload for t, cls in enumerate(tables) if len(payload) == cls.SIZE)
    return out


def sentence_seeds(kept: list[Session]) -> set[bytes]:
    found = {m for s in kept for m in messages(bytes(s.answers)) if m[:1] == nmea.PREFIX[:1]}
    return found | {ilahrs.PahrSentence().build().encode("latin-1")}


def stream_seeds(kept: list[Session]) -> set[bytes]:
    return {bytes(s.answers)[:MAX_STREAM] for s in kept if s.answers} | {bytes(s.line)[:MAX_STREAM] for s in kept}


def shape_seeds(shape: str, kept: list[Session]) -> set[bytes]:
    if shape == "selector":
        return selector_seeds(kept)
    if shape == "stream":
        return stream_seeds(kept)
    if shape == "cut-stream":
        return {bytes([1 + i * 13 % 97]) + s[: MAX_STREAM - 1] for i, s in enumerate(sorted(stream_seeds(kept)))}
    if shape == "sentence":
        return sentence_seeds(kept)
    if shape == "device":
        return {bytes(s.device_records)[:MAX_STREAM] for s in kept}
    return {bytes(s.host_records)[:MAX_STREAM] for s in kept}


def words() -> dict[str, bytes]:
    """Dictionary words: the frame's and the sentence's building blocks, from the spec's tables."""
    out: dict[str, bytes] = {"header": spec.HEADER}
    length = struct.Struct("<" + spec.FRAME_FORMAT[-1])
    sizes = sorted({cls.SIZE for cls in ilahrs.PAYLOADS.values()} | {1})
    for kind in ilahrs.MessageType:
        prefix = spec.HEADER + bytes([kind, 0])
        out[f"type_{kind.name.lower()}"] = prefix
        for size in sizes:
            out[f"prefix_{kind.name.lower()}_{size}"] = prefix + length.pack(size + spec.LENGTH_BIAS)
    for size in sizes:
        out[f"length_{size}"] = length.pack(size + spec.LENGTH_BIAS)
    for name, info in ilahrs.COMMANDS.items():
        out[f"code_{name}"] = bytes([info.code])
        out[f"command_{name}"] = ilahrs.build_command(name)
    sentence = ilahrs.PahrSentence().build().encode("latin-1")
    star = sentence.rindex(b"*")
    out.update(prefix=nmea.PREFIX, start=nmea.PREFIX[:1], separator=b",", star=b"*", end=sentence[-2:])
    out["tail"] = sentence[star:]
    out.update({f"field_{i}": text for i, text in enumerate(sentence[len(nmea.PREFIX) : star].split(b","))})
    return out


def escape(value: bytes) -> str:
    return "".join(f"\\x{b:02X}" for b in value)


def dictionary(shape: str) -> str:
    entries = words()
    if shape == "sentence":
        entries = {
            k: v
            for k, v in entries.items()
            if not k.startswith(("header", "type", "prefix_", "length", "code", "command"))
        }
    if shape in ("device", "host"):
        entries.update({f"record_{name}": records.write_command(i) for i, name in enumerate(NAMES)})
        entries["record_bytes_frame"] = bytes([records.tag(records.BYTES, spec.MAX_FRAME_SIZE - 1)])
    lines = [f"# {shape}: made by fuzz/seeds.py from the spec's tables (spec {spec.SPEC_VERSION})"]
    lines += [f'{name}="{escape(value)}"' for name, value in entries.items()]
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(argv[1])
    kept = sessions()
    (out / "dict").mkdir(parents=True, exist_ok=True)
    for shape in SHAPES:
        directory = out / "seeds" / shape
        shutil.rmtree(directory, ignore_errors=True)
        directory.mkdir(parents=True)
        seeds = shape_seeds(shape, kept)
        for seed in seeds:
            (directory / hashlib.sha1(seed).hexdigest()).write_bytes(seed)
        text = dictionary(shape)
        (out / "dict" / f"{shape}.dict").write_text(text)
        print(f"{shape}: {len(seeds)} seeds, {sum(map(len, seeds))} bytes, {len(text.splitlines()) - 1} words")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
