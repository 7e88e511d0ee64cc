"""How often damage passes the ICD's checksum, with and without strict decoding (E42).

The device model (`ilahrs.Device`) streams one output format; its frames go through the
simulator's fault injection (`ilahrs.edge.simulate.Line` with `Faults`: each byte replaced by another
value with probability `--corrupt-rate`), and two stream decoders read what was written, one
lenient (the default, E6) and one strict. A frame a decoder delivers that is not a frame the
device sent, at that place in the stream, is damage delivered as valid: the 16-bit sum cannot see
two bytes moved by opposite amounts.

    .venv/bin/python tools/checksum_escapes.py                      # 5,000,000 frames, ~2 minutes
    .venv/bin/python tools/checksum_escapes.py --frames 50000 --json

The device model makes about 3,500 frames a second, so it makes `--distinct` frames (50,000 by
default: 500 s of motion at 100 Hz) and the line sends them over and over; each sending is damaged
afresh. Seeded: the same arguments give the same counts. `make checksum-escapes` runs the default.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import asdict, dataclass, field
from itertools import cycle, islice

import ilahrs
from ilahrs.edge.simulate import Faults, Line

_BATCH = 2000
"""Frames written between two looks at the decoders."""


@dataclass
class Count:
    """What one decoder delivered."""

    delivered: int = 0
    intact: int = 0
    damaged: int = 0
    """Frames delivered that are not the frame the device sent at that place."""
    reserved_intact: int = 0
    """Of the damaged ones: those whose reserved byte is what the device sent there."""
    examples: list[dict[str, str]] = field(default_factory=list)


@dataclass
class Result:
    command: str
    payload: str
    frame_size: int
    frames: int
    distinct: int
    corrupt_rate: float
    seed: int
    damaged_sent: int = 0
    lenient: Count = field(default_factory=Count)
    strict: Count = field(default_factory=Count)
    seconds: float = 0.0


def device_frames(command: str, count: int, seed: int) -> list[bytes]:
    """`count` output frames of `command` as the device model sends them (after its alignment)."""
    info = ilahrs.COMMANDS[command]
    table = ilahrs.PAYLOADS[info.starts_output or ""]
    device = ilahrs.Device(seed=seed)
    device.receive(ilahrs.build_command(command))
    decoder = ilahrs.StreamDecoder()
    frames: list[bytes] = []
    while len(frames) < count:
        events = decoder.feed(device.advance(1.0))
        output = [e.raw for e in events if e.frame is not None and len(e.frame.payload) == table.SIZE]
        frames += output[: count - len(frames)]
    return frames


class _Reader:
    """A stream decoder over the written bytes, each delivered frame held against what was sent."""

    def __init__(self, count: Count, strict: bool) -> None:
        self.decoder = ilahrs.StreamDecoder(strict=strict)
        self.count = count
        self.cursor = 0  # where the next delivered frame may start, in the whole stream

    def read(self, new: bytes, written: bytes, sent: bytes, base: int, starts: set[int]) -> None:
        """Feed `new`, the end of `written`; `written` (and the `sent` bytes it damaged) start at
        `base` in the whole stream and begin with the batch before (the decoder holds at most one
        message from it)."""
        for event in self.decoder.feed(new):
            at = written.find(event.raw, self.cursor - base)
            offset = base + at
            self.cursor = offset + len(event.raw)
            self.count.delivered += 1
            if offset in starts and sent[at : at + len(event.raw)] == event.raw:
                self.count.intact += 1
                continue
            self.count.damaged += 1
            reserved = at + ilahrs.frame.RESERVED_OFFSET
            self.count.reserved_intact += written[reserved] == sent[reserved]
            if len(self.count.examples) < 5:
                self.count.examples.append({"sent": sent[at : at + len(event.raw)].hex(), "delivered": event.raw.hex()})


def measure(
    frames: int, *, corrupt_rate: float = 0.01, seed: int = 1, command: str = "AHRScont3", distinct: int = 50_000
) -> Result:
    """Send `frames` output frames of `command` through the simulator's faults; count what each
    decoder delivers."""
    start = time.monotonic()
    pool = device_frames(command, min(distinct, frames), seed)
    info = ilahrs.COMMANDS[command]
    result = Result(command, info.starts_output or "", len(pool[0]), frames, len(pool), corrupt_rate, seed)
    line = Line(ilahrs.Device(seed=seed), Faults(corrupt_rate=corrupt_rate, seed=seed))
    readers = [_Reader(result.lenient, strict=False), _Reader(result.strict, strict=True)]
    sent_tail = written_tail = b""
    base = 0
    messages = cycle(pool)
    remaining = frames
    while remaining:
        batch = list(islice(messages, min(_BATCH, remaining)))
        remaining -= len(batch)
        written = b"".join(line.emit(message) for message in batch)
        sent = b"".join(batch)
        starts = set()
        offset = base + len(written_tail)
        for message in batch:
            starts.add(offset)
            offset += len(message)
        for reader in readers:
            reader.read(written, written_tail + written, sent_tail + sent, base, starts)
        base += len(written_tail)
        sent_tail, written_tail = sent, written
    for reader in readers:
        for event in reader.decoder.finish():  # nothing is held at the end of whole frames
            raise AssertionError(f"a frame after the end: {event.raw.hex()}")
    result.damaged_sent = line.sent - line.intact
    result.seconds = round(time.monotonic() - start, 1)
    return result


def _one_in(part: int, whole: int) -> str:
    return "none" if part == 0 else f"1 in {whole / part:,.0f}"


def report(result: Result) -> list[str]:
    """The lines `checksum_escapes.py` prints."""
    pct = 100 * result.corrupt_rate
    lines = [
        f"{result.frames:,} {result.payload} frames ({result.frame_size} bytes, {result.command}; "
        f"{result.distinct:,} distinct from the device model, seed {result.seed}), "
        f"{pct:g} % of bytes corrupted by the simulator's faults (seed {result.seed}), in {result.seconds} s",
        f"damaged frames sent: {result.damaged_sent:,} ({100 * result.damaged_sent / result.frames:.1f} %)",
    ]
    for name, count in (("lenient (default)", result.lenient), ("strict", result.strict)):
        spread = 2 * math.sqrt(count.damaged) if count.damaged else 0.0
        lines.append(
            f"{name}: {count.damaged} damaged frames delivered as valid (+-{spread:.0f}, 2 sigma): "
            f"{_one_in(count.damaged, result.damaged_sent)} damaged frames, {_one_in(count.damaged, result.frames)} "
            f"frames; reserved byte intact in {count.reserved_intact}"
        )
    intact = result.frames - result.damaged_sent
    lost = f"{intact - result.lenient.intact} lenient, {intact - result.strict.intact} strict"
    lines.append(f"intact frames not delivered: {lost}")
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frames", type=int, default=5_000_000, help="frames sent (default 5,000,000)")
    parser.add_argument("--corrupt-rate", type=float, default=0.01, help="probability of corrupting a byte (0.01)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the motion and of the faults (1)")
    parser.add_argument("--output-format", default="AHRScont3", help="the start command (AHRScont3)")
    parser.add_argument("--distinct", type=int, default=50_000, help="frames the device model makes (50,000)")
    parser.add_argument("--json", action="store_true", help="print the counts as JSON")
    args = parser.parse_args(argv)
    result = measure(
        args.frames,
        corrupt_rate=args.corrupt_rate,
        seed=args.seed,
        command=args.output_format,
        distinct=args.distinct,
    )
    print(json.dumps(asdict(result), indent=1) if args.json else "\n".join(report(result)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
