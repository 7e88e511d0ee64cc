"""Decoding speed on the same frames: the ilahrs binding, the Kaitai parser and construct.

Each engine decodes every frame and then its payload into the payload's table type:

- ilahrs: `Frame.parse` (header, type, length and checksum checks) + the payload class's `parse`;
- kaitai: the Kaitai Python parser compiled from generated/kaitai/ilahrs.ksy by ksc 0.11 (the
  frame type, whose `valid` checks include the checksum) + the payload table's type;
- construct: the same .ksy through ksc's construct target (no checks: construct drops `valid`).

The frames are deterministic (seeded): every payload table in turn with random bytes, the three
output formats (Tables 6.4-6.6) three times as often. Timings use time.perf_counter; each engine
runs REPEAT times over all frames and the best run counts.

    .venv/bin/python bench/python/bench_decode.py [--frames N] [--repeat R]
"""

from __future__ import annotations

import argparse
import io
import platform
import random
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

import kaitai_support as ks  # noqa: E402
from kaitaistruct import KaitaiStream  # noqa: E402

import ilahrs  # noqa: E402

SEED = 20140311
TARGET_RATIO = 20.0

Decoder = Callable[[list[tuple[Any, bytes]]], int]


def frames(count: int) -> list[tuple[str, bytes]]:
    rng = random.Random(SEED)
    return [(table.name, ilahrs.Frame(1, payload).build()) for table, payload in ks.random_frame_payloads(rng, count)]


def decode_ilahrs(work: list[tuple[Any, bytes]]) -> int:
    parse_frame = ilahrs.Frame.parse
    for cls, data in work:
        cls.parse(parse_frame(data).payload)
    return len(work)


def decode_kaitai(work: list[tuple[Any, bytes]]) -> int:
    frame_type = ks.kaitai_root()
    for cls, data in work:
        frame = frame_type(KaitaiStream(io.BytesIO(data)))
        cls(KaitaiStream(io.BytesIO(frame.payload)))
    return len(work)


def decode_construct(work: list[tuple[Any, bytes]]) -> int:
    frame_type = ks.construct_type()
    for con, data in work:
        con.parse(frame_type.parse(data).payload)
    return len(work)


def rate(decode: Decoder, work: list[tuple[Any, bytes]], repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        decode(work)
        best = min(best, time.perf_counter() - start)
    return len(work) / best


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", type=int, default=20000, help="frames to decode (default 20000)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per engine; the best counts (default 3)")
    args = parser.parse_args()

    data = frames(args.frames)
    sizes = sorted({len(d) for _, d in data})
    print(
        f"{len(data)} frames of {len(ks.spec().payloads)} payload tables ({sizes[0]} to {sizes[-1]} bytes), "
        f"Python {platform.python_version()}, best of {args.repeat}"
    )
    engines: list[tuple[str, Decoder, list[tuple[Any, bytes]]]] = [
        ("ilahrs", decode_ilahrs, [(ilahrs.PAYLOADS[name], d) for name, d in data]),
        ("kaitai", decode_kaitai, [(ks.kaitai_type(name), d) for name, d in data]),
        ("construct", decode_construct, [(ks.construct_type(name), d) for name, d in data]),
    ]
    rates: dict[str, float] = {}
    for name, decode, work in engines:
        rates[name] = rate(decode, work, args.repeat)
        print(f"{name}: {rates[name]:.0f} frames/s")
    ratio = rates["ilahrs"] / rates["kaitai"]
    verdict = "met" if ratio >= TARGET_RATIO else "NOT met"
    print(f"ratio ilahrs/kaitai: {ratio:.1f}x (target >= {TARGET_RATIO:.0f}x: {verdict})")
    print(f"ratio ilahrs/construct: {rates['ilahrs'] / rates['construct']:.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
