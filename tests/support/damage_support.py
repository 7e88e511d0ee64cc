"""Damage that the capture tests apply to a good message: the same three kinds in every test that
builds a damaged capture."""

from __future__ import annotations

import random

KINDS = 3
"""Choices 0 to KINDS - 1 are damage; any other choice is none."""


def damage(good: bytes, choice: int, rng: random.Random) -> bytes:
    """Bytes to put before `good`: 0 noise, 1 a truncated copy, 2 a copy with one bit flipped;
    nothing for any other choice."""
    if choice == 0:
        return rng.randbytes(rng.randrange(1, 40))
    if choice == 1:
        return good[: rng.randrange(1, len(good))]
    if choice == 2:
        spot = rng.randrange(len(good))
        return good[:spot] + bytes([good[spot] ^ 0x10]) + good[spot + 1 :]
    return b""
