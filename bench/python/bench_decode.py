"""Decoding speed on the same frames: the ilahrs binding, the Kaitai parser and construct.

Each engine decodes every frame and then its payload into the payload's table type:

- ilahrs: `Frame.parse` (header, type, length and checksum checks) + the payload class's `parse`;
- kaitai: the Kaitai Python parser compiled from generated/kaitai/ilahrs.ksy by ksc 0.11 (the
  frame type, whose `valid` checks include the checksum) + the payload table's type;
- construct: the same .ksy through ksc's construct target (no checks: construct drops `valid`).

The frames are deterministic (seeded): every payload table in turn with random bytes, the three
output formats (Tables 6.4-6.6) three times as often. Timings use time.perf_counter; each engine
runs REPEAT times over all frames and the best run counts.

Then a capture of one output format (Table 6.4, random payloads, one frame in ten after a few
bytes of noise), decoded end to end from its bytes: a minimal standard-library loop (find AA 55,
length, sum, struct.unpack_from: the reference), what a user writes with the stream decoder
(`feed_iter`, then the payload class's `parse`), `ilahrs.decode_output` (payload objects), and
`ilahrs.columns` (one array per field) with numpy and with the array fallback; and the memory a
256 MiB capture fed at once to `StreamDecoder.feed_iter` adds (ru_maxrss, in a subprocess), and
what `ilahrs.columns` (numpy) adds for the same capture beyond the columns it returns.

Last, `ilahrs decode` of a two-direction pcapng capture to CSV (commands, answers and --two-way
output frames, the device model's): messages/s message by message and with the output decoded
as columns (ColumnarCapture, the packets read as arrays: Source.packets), as `ilahrs decode` does,
the best of --repeat runs each, by the wall clock and in process time (which other work on a busy
machine disturbs less).

    .venv/bin/python bench/python/bench_decode.py [--frames N] [--repeat R] [--rss-mib M] [--two-way N]
"""

from __future__ import annotations

import argparse
import io
import platform
import random
import resource
import struct
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests" / "support")]

import kaitai_support as ks  # noqa: E402
from kaitaistruct import KaitaiStream  # noqa: E402

import ilahrs  # noqa: E402

SEED = 20140311
TARGET_RATIO = 20.0
TARGET_LOOP_RATIO = 0.5
TARGET_COLUMNS_RATIO = 200.0
TARGET_RSS_MIB = 64
OUTPUT_TABLE = "full_output"

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


def output_capture(count: int, rng: random.Random) -> bytes:
    size = ilahrs.PAYLOADS[OUTPUT_TABLE].SIZE
    parts = []
    for index in range(count):
        if index % 10 == 0:
            parts.append(rng.randbytes(rng.randrange(1, 8)))
        parts.append(ilahrs.Frame(ilahrs.MessageType.DATA, rng.randbytes(size)).build())
    return b"".join(parts)


def stdlib_loop(data: bytes) -> int:
    """The reference: find AA 55, read the length, check the sum, unpack the payload's fields."""
    unpack_from = struct.Struct(ilahrs.PAYLOADS[OUTPUT_TABLE]._STRUCT.format).unpack_from  # type: ignore[attr-defined]
    find = data.find
    size = len(data)
    found = []
    pos = find(b"\xaa\x55")
    while pos >= 0:
        end = pos + 2 + (data[pos + 4] | data[pos + 5] << 8)
        if end <= size and sum(data[pos + 2 : end - 2]) & 0xFFFF == data[end - 2] | data[end - 1] << 8:
            found.append(unpack_from(data, pos + 6))
            pos = find(b"\xaa\x55", end)
        else:
            pos = find(b"\xaa\x55", pos + 1)
    return len(found)


def stream_and_parse(data: bytes) -> int:
    cls = ilahrs.PAYLOADS[OUTPUT_TABLE]
    decoder = ilahrs.StreamDecoder()
    found = [cls.parse(e.frame.payload) for e in decoder.feed_iter(data) if e.frame is not None]
    return len(found)


def decode_output(data: bytes) -> int:
    return len(list(ilahrs.decode_output(data, ilahrs.PAYLOADS[OUTPUT_TABLE])))


def columns_numpy(data: bytes) -> int:
    return len(ilahrs.columns(data, ilahrs.PAYLOADS[OUTPUT_TABLE], backend="numpy")["offset"])


def columns_array(data: bytes) -> int:
    return len(ilahrs.columns(data, ilahrs.PAYLOADS[OUTPUT_TABLE], backend="array")["offset"])


def capture_rate(decode: Callable[[bytes], int], data: bytes, count: int, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        found = decode(data)
        best = min(best, time.perf_counter() - start)
    assert found == count, (decode.__name__, found, count)
    return count / best


def rss_child(mib: int) -> int:
    """Feed a `mib` MiB capture at once to StreamDecoder.feed_iter; print the peak RSS growth."""
    block = output_capture(10000, random.Random(SEED))
    data = block * (mib * 2**20 // len(block))
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    decoder = ilahrs.StreamDecoder()
    start = time.perf_counter()
    count = sum(1 for _ in decoder.feed_iter(data))
    count += len(decoder.finish())
    elapsed = time.perf_counter() - start
    growth = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) / 1024
    print(f"{len(data) / 2**20:.0f} {count} {growth:.1f} {len(data) / 2**20 / elapsed:.1f}")
    return 0


def rss_columns_child(mib: int) -> int:
    """`ilahrs.columns` (numpy) of a `mib` MiB capture; print the peak RSS growth and the columns' size."""
    block = output_capture(10000, random.Random(SEED))
    data = block * (mib * 2**20 // len(block))
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    start = time.perf_counter()
    table = ilahrs.columns(data, ilahrs.PAYLOADS[OUTPUT_TABLE], backend="numpy")
    elapsed = time.perf_counter() - start
    growth = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) / 1024
    size = sum(column.nbytes for column in table.values()) / 2**20
    print(f"{len(data) / 2**20:.0f} {len(table['offset'])} {growth:.1f} {size:.1f} {len(data) / 2**20 / elapsed:.1f}")
    return 0


def capture_section(frame_count: int, repeat: int, rss_mib: int) -> None:
    data = output_capture(frame_count, random.Random(SEED))
    cls = ilahrs.PAYLOADS[OUTPUT_TABLE]
    print(f"\ncapture: {frame_count} {OUTPUT_TABLE} frames with noise, {len(data)} bytes, end to end")
    kaitai_work = [(ks.kaitai_type(OUTPUT_TABLE), ilahrs.Frame(1, bytes(cls.SIZE)).build())] * frame_count
    kaitai = rate(decode_kaitai, kaitai_work, repeat)
    print(f"kaitai (frames already split): {kaitai:.0f} frames/s")
    paths = [
        ("stdlib loop (reference)", stdlib_loop),
        ("StreamDecoder.feed_iter + parse", stream_and_parse),
        ("ilahrs.decode_output", decode_output),
        ("ilahrs.columns (numpy)", columns_numpy),
        ("ilahrs.columns (array)", columns_array),
    ]
    rates = {}
    for name, decode in paths:
        rates[name] = capture_rate(decode, data, frame_count, repeat)
        print(f"{name}: {rates[name]:.0f} frames/s, {rates[name] / kaitai:.1f}x kaitai")
    loop = rates["stdlib loop (reference)"]
    for name in ("StreamDecoder.feed_iter + parse", "ilahrs.decode_output"):
        print(f"ratio {name} / stdlib loop: {rates[name] / loop:.2f}")
    ratio = rates["ilahrs.decode_output"] / loop
    verdict = "met" if ratio >= TARGET_LOOP_RATIO else "NOT met"
    print(f"decode_output / stdlib loop: {ratio:.2f} (target >= {TARGET_LOOP_RATIO}: {verdict})")
    ratio = rates["ilahrs.columns (numpy)"] / kaitai
    verdict = "met" if ratio >= TARGET_COLUMNS_RATIO else "NOT met"
    print(f"columns (numpy) / kaitai: {ratio:.0f}x (target >= {TARGET_COLUMNS_RATIO:.0f}x: {verdict})")
    if rss_mib > 0:
        out = subprocess.run(
            [sys.executable, __file__, "--rss-child", str(rss_mib)], check=True, capture_output=True, text=True
        ).stdout.split()
        growth = float(out[2])
        verdict = "met" if growth < TARGET_RSS_MIB else "NOT met"
        print(
            f"StreamDecoder.feed_iter, {out[0]} MiB fed at once: {out[1]} messages, {out[3]} MiB/s, "
            f"RSS growth {growth:.1f} MiB (target < {TARGET_RSS_MIB} MiB: {verdict})"
        )
        out = subprocess.run(
            [sys.executable, __file__, "--rss-columns-child", str(rss_mib)], check=True, capture_output=True, text=True
        ).stdout.split()
        growth, size = float(out[2]), float(out[3])
        besides = growth - size
        print(
            f"ilahrs.columns (numpy), {out[0]} MiB at once: {out[1]} rows, {out[4]} MiB/s, "
            f"RSS growth {growth:.0f} MiB: the columns {size:.0f} MiB and {besides:.0f} MiB besides "
            f"({besides / float(out[0]):.2f}x the capture)"
        )


TARGET_TWO_WAY_RATIO = 10.0


def two_way_capture(count: int) -> bytes:
    """A pcapng capture of both directions: Stop, AHRScont1, `count` output frames (one packet
    each, 10 ms apart), Stop, ReadAHRSPar and the output again, the device model answering."""
    device = ilahrs.Device(seed=1)
    out = io.BytesIO()
    writer = ilahrs.pcapng.PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    now = 1_700_000_000_000_000
    inbound, outbound = ilahrs.pcapng.Direction.INBOUND, ilahrs.pcapng.Direction.OUTBOUND
    for part, commands in enumerate((("Stop", "AHRScont1"), ("Stop", "ReadAHRSPar", "AHRScont1"))):
        for name in commands:
            data = ilahrs.build_command(name)
            writer.write(data, now, outbound)
            answer = device.receive(data)
            now += 4500
            device.advance(0.0045)
            if answer:
                writer.write(answer, now, inbound)
        got = 0
        while got < (count // 2 if part == 0 else count - count // 2):
            data = device.advance(0.01)
            now += 10_000
            if data:
                writer.write(data, now, inbound)
                got += 1
    return out.getvalue()


def two_way_section(count: int, repeat: int = 3) -> None:
    """`ilahrs decode CAPTURE.pcapng --to csv` (output as columns) against message by message, the
    best of `repeat` runs of each."""
    from ilahrs.cli import capture, decode

    data = two_way_capture(count)
    path = Path(subprocess.check_output(["mktemp", "--suffix=.pcapng"], text=True).strip())
    try:
        path.write_bytes(data)
        variant = next(iter(ilahrs.VARIANTS.values()))
        kinds = decode.kinds()

        def messages() -> int:
            decoder = decode.CaptureDecoder(context=True)
            writer = decode.RowWriter(io.StringIO(), "csv", kinds, variant, raw=False)
            for chunk in capture.open_source(str(path)).chunks():
                for message in decoder.feed(chunk):
                    writer.write(message)
            for message in decoder.finish():
                writer.write(message)
            return sum(decoder.counts.values())

        def columnar() -> int:
            decoder = decode.ColumnarCapture(io.StringIO(), kinds, variant, raw=False)
            for found in capture.open_source(str(path)).packets():
                decoder.feed_packets(found)
            decoder.finish()
            return sum(decoder.counts.values())

        print(f"\ntwo-direction pcapng: {count} output frames, {len(data)} bytes, decode --to csv, best of {repeat}")
        found: dict[str, float] = {}
        used: dict[str, float] = {}
        for name, run in (("message by message", messages), ("columns", columnar)):
            best = cpu = float("inf")
            for _ in range(repeat):
                start, start_cpu = time.perf_counter(), time.process_time()
                total = run()
                best = min(best, time.perf_counter() - start)
                cpu = min(cpu, time.process_time() - start_cpu)
            found[name], used[name] = total / best, total / cpu
            print(
                f"{name}: {found[name]:.0f} messages/s ({total} messages, {best:.2f} s; "
                f"{used[name]:.0f} messages/s of process time, {cpu:.2f} s)"
            )
        ratio = found["columns"] / found["message by message"]
        verdict = "met" if ratio >= TARGET_TWO_WAY_RATIO else "NOT met"
        print(
            f"columns / message by message: {ratio:.1f}x (target >= {TARGET_TWO_WAY_RATIO:.0f}x: {verdict}); "
            f"{used['columns'] / used['message by message']:.1f}x in process time"
        )
    finally:
        path.unlink()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", type=int, default=20000, help="frames to decode (default 20000)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per engine; the best counts (default 3)")
    parser.add_argument("--rss-mib", type=int, default=256, help="capture size for the RSS figure (0: skip)")
    parser.add_argument(
        "--two-way", type=int, default=100_000, help="output frames in the two-direction capture (default 100000)"
    )
    parser.add_argument("--rss-child", type=int, default=0, help=argparse.SUPPRESS)
    parser.add_argument("--rss-columns-child", type=int, default=0, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.rss_child:
        return rss_child(args.rss_child)
    if args.rss_columns_child:
        return rss_columns_child(args.rss_columns_child)

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
    capture_section(args.frames * 5, args.repeat, args.rss_mib)
    two_way_section(args.two_way, args.repeat)
    return 0


if __name__ == "__main__":
    sys.exit(main())
