"""The .ksy's `capture` type against the binding's stream decoder: on a recording of many messages,
$PAHR sentences, garbage and damaged frames, the Kaitai parser finds the same frames at the same
offsets, skips every other byte one at a time, and decodes the payloads whose length alone says
their table exactly as the binding does (E40 says what it leaves to the bindings)."""

from __future__ import annotations

import random

import kaitai_support as ks

import ilahrs

SEED = 20140311
SPEC = ks.spec()
LENGTH_DECIDED = {p.name for p in SPEC.payloads if [q.size for q in SPEC.payloads].count(p.size) == 1}


def _garbage(rng: random.Random) -> bytes:
    """Bytes that start no message, with now and then a header byte or a whole header."""
    data = bytearray(rng.randbytes(rng.randrange(1, 12)))
    if rng.random() < 0.3:
        data += bytes(SPEC.frame.header[:1])
    if rng.random() < 0.2:
        data += bytes(SPEC.frame.header) + rng.randbytes(3)
    return bytes(data)


def _capture(rng: random.Random, count: int) -> tuple[bytes, list[tuple[int, bytes]]]:
    """A recording: frames of every table and command, sentences, garbage and damaged frames, then a
    frame cut off by the end. Also (offset, frame) of every intact frame in it."""
    sentence = (
        ilahrs.PahrSentence.from_values(roll=12.34, pitch=-5.67, heading=123.45, temperature=25.3, vdd=5.02, usw=0)
        .build()
        .encode("ascii")
    )
    data = bytearray()
    frames: list[tuple[int, bytes]] = []
    for _ in range(count):
        choice = rng.random()
        if choice < 0.5:
            table = rng.choice(SPEC.payloads)
            payload = ilahrs.PAYLOADS[table.name].from_raw(ks.valid_raw(table, rng)).build()
            frame = ilahrs.Frame(SPEC.frame.message_type("data").value, payload, rng.randrange(256)).build()
        elif choice < 0.6:
            frame = ilahrs.build_command(rng.choice(SPEC.commands).name)
        else:
            if choice < 0.75:
                data += _garbage(rng)
            elif choice < 0.85:
                data += sentence
            else:  # a frame with one byte changed: its checksum or a check fails
                damaged = bytearray(ilahrs.Frame(1, rng.randbytes(rng.choice(SPEC.payloads).size)).build())
                damaged[rng.randrange(len(damaged))] ^= 1 << rng.randrange(8)
                data += damaged
            continue
        frames.append((len(data), frame))
        data += frame
    data += ilahrs.build_command(SPEC.commands[0].name)[:-1]
    return bytes(data), frames


def test_a_capture_reads_the_frames_the_binding_reads_and_skips_the_rest() -> None:
    rng = random.Random(SEED)
    data, intact = _capture(rng, 400)
    decoder = ilahrs.StreamDecoder()
    events = decoder.feed(data) + decoder.finish()
    ours = [event.raw for event in events if event.frame is not None]
    capture = ks.kaitai_type("capture")(ks.stream(data))
    theirs: list[tuple[int, bytes]] = []
    position = 0
    decoded: dict[str, int] = {}
    for message in capture.messages:
        assert message.start == position
        if not message.is_frame:
            assert getattr(message, "frame", None) is None and message.skipped == data[position]
            position += 1
            continue
        assert getattr(message, "skipped", None) is None
        raw = data[position : position + message.frame.message_length + len(SPEC.frame.header)]
        theirs.append((position, raw))
        position += len(raw)
        frame = ilahrs.Frame.parse(raw)
        assert message.frame.payload == frame.payload
        if frame.message_type == SPEC.frame.message_type("command").value:
            assert int(message.command.code) == frame.payload[0]
        else:
            assert message.command is None
        for table in SPEC.payloads:
            instance = getattr(message, table.name, None) if table.name in LENGTH_DECIDED else None
            if instance is None:
                assert table.name not in LENGTH_DECIDED or len(frame.payload) != table.size or frame.message_type == 0
                continue
            assert len(frame.payload) == table.size
            ours_raw = ilahrs.PAYLOADS[table.name].parse(frame.payload).raw()
            assert ks.same_raw(ks.kaitai_raw(table, instance), ours_raw)
            decoded[table.name] = decoded.get(table.name, 0) + 1
    assert position == len(data)
    assert [raw for _, raw in theirs] == ours
    assert theirs == intact
    assert set(decoded) == LENGTH_DECIDED, "every table its length decides was seen and decoded"
    assert len(intact) > 200
