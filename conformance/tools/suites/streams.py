"""streams: the stream decoder (leftmost valid message) fed chunk by chunk; the expected events
come from the oracle's scan of the whole input, and each case's intended answer is checked
against it.

cases/streams.json: "messages" names frames and sentences (suites/messages.py); a sweep feeds one
input in every chunk size; a case gives its chunks, the events it means to produce and the number
of bytes discarded, and may say that the line is idle after a chunk for a number of microseconds
("idle", E41) or that the decoder is strict ("strict", E42); a soak is a seeded random mix of
thousands of messages. Every note ends with the rule ("phrases").
"""

from __future__ import annotations

import random
from typing import Any

import oracle as o

from .common import Vector, cases, expand, hx, phrases, vec
from .messages import Messages

SUITE = "streams"

Event = tuple[str, bytes]


def _segments(chunks: list[bytes], idle: list[dict[str, int]]) -> list[bytes]:
    """The input cut where the line is idle for at least the E41 threshold after a chunk."""
    cuts = {gap["after"] for gap in idle if gap["us"] >= o.IDLE_US}
    segments = [b""]
    for index, chunk in enumerate(chunks):
        segments[-1] += chunk
        if index in cuts:
            segments.append(b"")
    return segments


def _stream_vec(
    id_: str,
    chunks: list[bytes],
    note: str,
    intended: list[Event],
    discarded: int,
    *,
    compact: bool = False,
    idle: list[dict[str, int]] | None = None,
    strict: bool = False,
    tests: str | None = None,
) -> Vector:
    """A stream vector: the oracle's scan of the whole input (cut at idle gaps) must give the
    intended events and count."""
    events, scanned = o.scan_segments(_segments(chunks, idle or []), strict)
    assert events == intended, (id_, events, intended)  # the intended answer, cross-checked against the oracle
    assert scanned == discarded, (id_, scanned, discarded)
    show = (lambda b: b.hex().upper()) if compact else hx
    expect = [{"frame": show(data)} if kind == "frame" else {"nmea": data.decode("latin-1")} for kind, data in events]
    input_: dict[str, Any] = {"chunks": [show(c) for c in chunks]}
    if idle:
        input_["idle"] = idle
    out = vec(id_, "stream", input_, {"events": expect, "discarded": discarded}, note, tests=tests)
    if strict:
        out["options"] = {"strict": True}
    return out


def _split(data: bytes, size: int) -> list[bytes]:
    return [data[i : i + size] for i in range(0, len(data), size)]


def _events(messages: Messages, events: list[list[Any]]) -> list[Event]:
    return [(kind, messages.build(spec)) for kind, spec in events]


def _sweeps(data: dict[str, Any], messages: Messages, names: dict[str, str]) -> list[Vector]:
    """Each sweep's input in chunks of every size from 1 to its length."""
    out: list[Vector] = []
    for sweep in data["sweeps"]:
        whole = messages.build(sweep["input"])
        events = _events(messages, sweep["events"])
        for size in range(1, len(whole) + 1):
            text = f"{expand(sweep['note'], {**names, 'size': size})}; {names['rule']}"
            out.append(_stream_vec(f"stream/{sweep['name']}-{size}", _split(whole, size), text, events, 0))
    return out


def _cases(data: dict[str, Any], messages: Messages, names: dict[str, str]) -> list[Vector]:
    out: list[Vector] = []
    for case in data["cases"]:
        chunks = [messages.build(chunk) for chunk in case["chunks"]]
        if "chunk_size" in case:
            chunks = _split(b"".join(chunks), case["chunk_size"])
        text = f"{expand(case['note'], names)}; {names['rule']}"
        intended = _events(messages, case["events"])
        idle, strict, tests = case.get("idle"), case.get("strict", False), case.get("tests")
        out.append(
            _stream_vec(
                f"stream/{case['name']}",
                chunks,
                text,
                intended,
                case["discarded"],
                idle=idle,
                strict=strict,
                tests=tests,
            )
        )
    return out


def _random_bytes(rng: random.Random, count: int) -> bytes:
    return bytes(rng.randrange(256) for _ in range(count))


def _soak_message(rng: random.Random, tables: list[str]) -> tuple[bytes, str | None]:
    """One message of a soak and its kind, or None for a corrupted frame or a false start."""
    roll = rng.random()
    if roll < 0.55:
        size = o.TABLES[rng.choice(tables)][1]
        return o.frame(o.DATA, _random_bytes(rng, size), rng.choice([0, 0, 0, 0x42])), "frame"
    if roll < 0.70:
        return o.frame(o.COMMAND, bytes([rng.choice(o.table_c1()).code])), "frame"
    if roll < 0.85:
        values = {
            "roll": rng.randint(-18000, 18000),
            "pitch": rng.randint(-9000, 9000),
            "heading": rng.randint(0, 35999),
            "temperature": rng.randint(-999, 9999),
            "vdd": rng.randint(0, 999),
            "usw": rng.randrange(0x10000),
        }
        return o.build_sentence(values).encode(), "nmea"
    if roll < 0.93:
        good = o.frame(o.DATA, _random_bytes(rng, rng.randint(1, 52)))
        i = rng.randrange(2, len(good))
        return good[:i] + bytes([good[i] ^ (1 << rng.randrange(8))]) + good[i + 1 :], None
    start = rng.choice([b"\xaa", b"\xaa\x55", b"$", b"$PAHR,", bytes.fromhex("AA550000FFFF")])
    return start + _random_bytes(rng, rng.randint(0, 6)), None


def _soak(soak: dict[str, Any], rule: str) -> Vector:
    """Thousands of messages with garbage and corrupted frames between them, chunked at random."""
    count, seed = soak["count"], soak["seed"]
    min_chunk, max_chunk = soak["chunk_sizes"]
    rng = random.Random(seed)
    tables = sorted(name for name in o.TABLES if o.TABLES[name][1] <= o.MAX_PAYLOAD)
    stream = b""
    intended: list[Event] = []
    garbage = 0
    reserved = 0  # data frames with a non-zero reserved byte, accepted (E6)
    for _ in range(count):
        msg, kind = _soak_message(rng, tables)
        if kind is None:
            garbage += len(msg)
        else:
            intended.append((kind, msg))
            reserved += kind == "frame" and msg[3] != 0
        stream += msg
    chunks = []
    pos = 0
    while pos < len(stream):
        size = rng.randint(min_chunk, max_chunk)
        chunks.append(stream[pos : pos + size])
        pos += size
    frames = sum(1 for kind, _ in intended if kind == "frame")
    text = (
        f"seeded soak (seed {seed}): {count} messages ({frames} valid frames, {len(intended) - frames} "
        f"sentences, the rest corrupted frames and false starts), random chunks of {min_chunk}..{max_chunk} "
        f"bytes; {reserved} valid frames carry reserved byte 42, accepted (E6); chunking never changes the result; "
        f"computed by conformance/tools/make_vectors.py; {rule}"
    )
    tests = "E6" if reserved else None
    return _stream_vec(f"stream/{soak['name']}", chunks, text, intended, garbage, compact=True, tests=tests)


def vectors() -> list[Vector]:
    data = cases(SUITE)
    names = phrases(SUITE)
    messages = Messages(data["messages"])
    soaks = [_soak(soak, names["rule"]) for soak in data["soaks"]]
    return _sweeps(data, messages, names) + _cases(data, messages, names) + soaks
