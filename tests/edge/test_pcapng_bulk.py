"""ilahrs.pcapng.BulkReader, the reader `ilahrs decode CAPTURE.pcapng` feeds the columnar path with
(packets as arrays, tests/cli/test_decode_columns_capture.py): the packets before a damaged block
are kept, then its error, as IncrementalReader and `read` report it."""

from __future__ import annotations

import io
import random
import struct

import pytest

from ilahrs import pcapng
from ilahrs.pcapng import BulkReader, Direction, IncrementalReader, PcapngError, PcapngWriter, read


def test_a_damaged_block_comes_after_the_packets_before_it() -> None:
    """BulkReader and IncrementalReader give the packets before a damaged block read in the same
    piece, then its error (at the next feed or at finish), as `read` reports it."""
    out = io.BytesIO()
    writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    for i in range(3):
        writer.write(bytes([i]) * 5, 1_000_000 + i, Direction.INBOUND)
    good = out.getvalue()
    damaged = good + struct.pack("<II", 6, 40) + bytes(28) + struct.pack("<I", 44)
    with pytest.raises(PcapngError) as expected:
        read(io.BytesIO(damaged))
    incremental = IncrementalReader()
    assert [p.data for p in incremental.feed(damaged)] == [b"\0" * 5, b"\1" * 5, b"\2" * 5]
    with pytest.raises(PcapngError) as raised:
        incremental.finish()
    assert str(raised.value) == str(expected.value) == f"block at offset {len(good)}: its lengths differ (40, 44)"
    bulk = BulkReader()
    found = bulk.feed(damaged)
    assert (found.data, list(found.ends), list(found.stamps)) == (
        b"\0" * 5 + b"\1" * 5 + b"\2" * 5,
        [5, 10, 15],
        [1_000_000, 1_000_001, 1_000_002],
    )
    assert found.directions == bytes([Direction.INBOUND]) * 3
    with pytest.raises(PcapngError, match="its lengths differ"):
        bulk.feed(b"")


def _block(kind: int, body: bytes) -> bytes:
    return struct.pack("<II", kind, 12 + len(body)) + body + struct.pack("<I", 12 + len(body))


def _epb(data: bytes, stamp: int, *, interface: int = 0, options: bytes | None = None) -> bytes:
    """An Enhanced Packet Block; `options` None: epb_flags (inbound) and opt_endofopt, as ilahrs writes."""
    if options is None:
        options = struct.pack("<HHI", 2, 4, int(Direction.INBOUND)) + bytes(4)
    head = struct.pack("<IIIII", interface, stamp >> 32, stamp & 0xFFFFFFFF, len(data), len(data))
    return _block(6, head + data + bytes(-len(data) % 4) + options)


@pytest.mark.parametrize("run", [1 << 16, 512])
def test_runs_of_packets_read_as_arrays_are_those_read_one_by_one(run: int, monkeypatch: pytest.MonkeyPatch) -> None:
    """BulkReader(numpy) reads long runs of the packet blocks ilahrs writes at once: its Packets and
    errors are BulkReader()'s, fed in any pieces, through blocks that end a run (another interface
    with nanosecond stamps, a packet block without options or with other ones, a packet holding a
    whole packet block, which looks like one where it lies) and a damaged block."""
    numpy = pytest.importorskip("numpy")
    monkeypatch.setattr(pcapng, "_RUN", run)  # 512: runs tried through every part of the capture
    out = io.BytesIO()
    writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    rng = random.Random(5)
    for i in range(2500):
        direction = Direction.OUTBOUND if i % 50 == 0 else Direction.INBOUND
        writer.write(rng.randbytes(rng.choice((0, 1, 7, 42, 88))), 1_700_000_000_000_000 + 10_000 * i, direction)
        if i == 1200:  # a second interface, nanoseconds
            nanoseconds = struct.pack("<HH", 9, 1) + bytes([9, 0, 0, 0]) + bytes(4)
            out.write(_block(1, struct.pack("<HHI", 147, 0, 0) + nanoseconds))
            out.write(_epb(b"ns", 1_700_000_000_000_000_123, interface=1))
        if i == 1500:
            out.write(_epb(b"no options", 5, options=b""))
            out.write(_epb(b"flags and a comment", 6, options=struct.pack("<HH", 1, 4) + b"note" + bytes(4)))
        if i == 1800:
            out.write(_epb(_epb(b"inside", 7), 8))
    capture = out.getvalue()
    assert len(capture) > 2 * (1 << 16)
    for damaged in (capture, capture[: len(capture) // 2] + struct.pack("<II", 6, 40) + bytes(36) + capture[-200:]):
        for piece in (len(damaged), 1 << 16, 40_000, 4093):
            results = []
            for reader in (BulkReader(), BulkReader(numpy)):
                found: list[object] = []
                try:
                    for at in range(0, len(damaged), piece):
                        part = reader.feed(damaged[at : at + piece])
                        found.append((part.data, part.ends, part.stamps, part.directions, part.interfaces))
                        found.append((part.originals, part.first))
                    reader.finish()
                except PcapngError as exc:
                    found.append(str(exc))
                results.append(found)
            assert results[1] == results[0]
            assert sum(len(part[1]) for part in results[0] if isinstance(part, tuple) and len(part) == 5) > 1200
