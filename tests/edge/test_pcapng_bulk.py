"""ilahrs.pcapng.BulkReader, the reader `ilahrs decode CAPTURE.pcapng` feeds the columnar path with
(packets as arrays, tests/cli/test_decode_columns_capture.py): the packets before a damaged block
are kept, then its error, as IncrementalReader and `read` report it."""

from __future__ import annotations

import io
import struct

import pytest

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
