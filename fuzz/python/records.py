"""The input of the Device and Host fuzz targets: a sequence of records, each one step of a session.

A record starts with a tag byte; its top two bits say what it is, its low six bits (ARG) how much:

    00 ARG  bytes: the next ARG + 1 input bytes reach the session (fewer if the input ends)
    01 ARG  command: the command ilahrs.COMMANDS lists at ARG (modulo their number), built by the
            binding (Device: its frame is received; Host: `Host.send`, with the block's default
            values when the command takes a parameter block)
    10 ARG  a short wait: ARG ms pass
    11 ARG  a long wait: ARG seconds pass (Device: until its next timer, if that comes sooner; a
            device sending output at 100 Hz builds a block per 10 ms, which a minute of waiting
            would make thousands of)

The seeds (fuzz/seeds.py) write sessions in this form; the targets (fuzz/python/targets.py) read it.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Final

BYTES: Final = 0
COMMAND: Final = 1
SHORT_WAIT: Final = 2
LONG_WAIT: Final = 3
ARG_LIMIT: Final = 64
SHORT_STEP_S: Final = 0.001


def tag(op: int, arg: int) -> int:
    return (op << 6) | arg


def read(data: bytes) -> Iterator[tuple[int, int, bytes]]:
    """The records of `data`: (op, arg, bytes), bytes only for BYTES records."""
    at = 0
    while at < len(data):
        op, arg = data[at] >> 6, data[at] & (ARG_LIMIT - 1)
        at += 1
        if op == BYTES:
            yield op, arg, data[at : at + arg + 1]
            at += arg + 1
        else:
            yield op, arg, b""


def seconds(op: int, arg: int) -> float:
    return arg * SHORT_STEP_S if op == SHORT_WAIT else float(arg)


def write_bytes(data: bytes) -> bytes:
    out = bytearray()
    for at in range(0, len(data), ARG_LIMIT):
        piece = data[at : at + ARG_LIMIT]
        out += bytes([tag(BYTES, len(piece) - 1)]) + piece
    return bytes(out)


def write_wait(seconds_: float) -> bytes:
    """Waits whose sum is `seconds_` to within 1 ms (rounded up)."""
    out = bytearray()
    whole = int(seconds_)
    rest = math.ceil(round((seconds_ - whole) / SHORT_STEP_S, 6))
    if rest >= ARG_LIMIT:
        whole, rest = whole + 1, 0
    while whole > 0:
        step = min(whole, ARG_LIMIT - 1)
        out.append(tag(LONG_WAIT, step))
        whole -= step
    if rest:
        out.append(tag(SHORT_WAIT, rest))
    return bytes(out)


def write_command(index: int) -> bytes:
    return bytes([tag(COMMAND, index)])


def write_until_timer(seconds_: float) -> bytes:
    """For a Device: long waits that end at its next timer, due in `seconds_`."""
    whole = math.ceil(round(seconds_, 6))
    out = bytearray()
    while True:
        step = min(max(whole, 1), ARG_LIMIT - 1)
        out.append(tag(LONG_WAIT, step))
        whole -= step
        if whole <= 0:
            return bytes(out)
