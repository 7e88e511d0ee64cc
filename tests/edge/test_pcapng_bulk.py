"""`ilahrs decode CAPTURE.pcapng --to csv` reads the capture's packets as arrays (Source.packets,
ilahrs.pcapng.BulkReader) and feeds them to ColumnarCapture.feed_packets: the rows and the summary
are those of the message-by-message path, byte for byte, on clean and damaged captures."""

from __future__ import annotations

import io
import struct
from pathlib import Path

import pytest
from test_decode_columns_capture import CAPTURES, VARIANT, message_csv

from ilahrs.cli import columnar_capture
from ilahrs.cli.capture import open_source
from ilahrs.cli.decode import ColumnarCapture, kinds, summary
from ilahrs.pcapng import BulkReader, Direction, IncrementalReader, PcapngError, PcapngWriter, read

pytest.importorskip("numpy")


def bulk_csv(path: Path, selected: list[str], **options: object) -> tuple[str, list[str]]:
    out = io.StringIO()
    decoder = ColumnarCapture(out, selected, VARIANT, raw=False, **options)  # type: ignore[arg-type]
    for found in open_source(str(path)).packets():
        decoder.feed_packets(found)
    decoder.finish()
    return out.getvalue(), summary(decoder, "ilahrs decode")


@pytest.mark.parametrize("strict", [False, True], ids=["lenient", "strict"])
@pytest.mark.parametrize("stretch", [1 << 20, 700], ids=["1MiB", "700B"])
@pytest.mark.parametrize("name", list(CAPTURES))
def test_packets_as_arrays_give_the_rows_and_summary_of_the_messages(
    name: str, stretch: int, strict: bool, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(columnar_capture, "_STRETCH", stretch)
    path = CAPTURES[name]().save(tmp_path / f"{name}.pcapng")
    for selected in (kinds(), ["full_output", "damaged", "Stop"]):
        expected = message_csv(path, selected, strict=strict)
        got = bulk_csv(path, selected, strict=strict)
        assert got[0].count("\n") > (10 if selected == kinds() else 2)
        assert got == expected


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
