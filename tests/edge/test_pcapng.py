"""ilahrs.pcapng: the capture file of a serial line (tshark reads it in `make test-wireshark`)."""

from __future__ import annotations

import io
import struct

import pytest

from ilahrs.pcapng import LINKTYPE_ILAHRS, Direction, PcapngError, PcapngWriter, line_description, read


def written(*packets: tuple[bytes, int, Direction]) -> bytes:
    out = io.BytesIO()
    writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    for data, timestamp, direction in packets:
        writer.write(data, timestamp, direction)
    return out.getvalue()


def test_round_trip_keeps_bytes_time_direction_and_interface() -> None:
    packets = [
        (b"\xaa\x55\x00\x00\x07\x00\x83\x8a\x00", 1_700_000_000_000_001, Direction.OUTBOUND),
        (b"\xaa", 1_700_000_000_500_000, Direction.INBOUND),
        (b"$PAHR", (1 << 40) + 3, Direction.UNKNOWN),
        (b"", 5, Direction.INBOUND),
    ]
    capture = read(io.BytesIO(written(*packets)))
    assert [(p.data, p.timestamp_us, p.direction) for p in capture.packets] == packets
    (interface,) = capture.interfaces
    assert interface.linktype == LINKTYPE_ILAHRS == 147
    assert interface.name == "/dev/ttyUSB0"
    assert interface.description == line_description("/dev/ttyUSB0", 115200) == "/dev/ttyUSB0, 115200 baud 8N1"
    assert interface.resolution == 1_000_000
    assert capture.application == "ilahrs"
    assert capture.packets[0].timestamp == pytest.approx(1_700_000_000.000001)


def test_blocks_are_whole_and_aligned() -> None:
    data = written((b"\x01\x02\x03", 10, Direction.INBOUND))
    pos = 0
    kinds = []
    while pos < len(data):
        kind, length = struct.unpack_from("<II", data, pos)
        assert length % 4 == 0 and struct.unpack_from("<I", data, pos + length - 4)[0] == length
        kinds.append(kind)
        pos += length
    assert kinds == [0x0A0D0D0A, 1, 6]


def test_a_file_cut_short_is_an_error_or_what_precedes_the_cut() -> None:
    data = written((b"first", 1, Direction.INBOUND), (b"second", 2, Direction.OUTBOUND))
    cut = data[:-7]
    with pytest.raises(PcapngError, match="file ends inside the block at offset"):
        read(io.BytesIO(cut))
    capture = read(io.BytesIO(cut), partial=True)
    assert capture.truncated
    assert [p.data for p in capture.packets] == [b"first"]


@pytest.mark.parametrize(
    ("data", "message"),
    [
        (b"", "not a pcapng file"),
        (b"\xd4\xc3\xb2\xa1" + bytes(20), "not a pcapng file"),
        (struct.pack("<II", 0x0A0D0D0A, 28) + bytes(16) + struct.pack("<I", 28), "no byte-order magic"),
        (struct.pack("<IIIHHq", 0x0A0D0D0A, 30, 0x1A2B3C4D, 1, 0, -1) + bytes(6), "impossible length"),
        (struct.pack("<IIIHHqI", 0x0A0D0D0A, 28, 0x1A2B3C4D, 2, 0, -1, 28), "version 2"),
        (struct.pack("<IIIHHqI", 0x0A0D0D0A, 28, 0x1A2B3C4D, 1, 0, -1, 32), "lengths differ"),
    ],
)
def test_what_is_not_pcapng_is_refused(data: bytes, message: str) -> None:
    with pytest.raises(PcapngError, match=message):
        read(io.BytesIO(data))


def test_packets_of_an_undescribed_interface_are_refused() -> None:
    data = bytearray(written((b"x", 1, Direction.INBOUND)))
    epb = len(data) - struct.unpack_from("<I", data, len(data) - 4)[0]
    assert struct.unpack_from("<I", data, epb)[0] == 6
    data[epb + 8 : epb + 12] = struct.pack("<I", 3)
    with pytest.raises(PcapngError, match="names interface 3"):
        read(io.BytesIO(bytes(data)))


def big_endian_file() -> bytes:
    """A big-endian section with nanosecond timestamps, an unknown block and a packet without flags."""

    def block(kind: int, body: bytes) -> bytes:
        return struct.pack(">II", kind, 12 + len(body)) + body + struct.pack(">I", 12 + len(body))

    shb = block(0x0A0D0D0A, struct.pack(">IHHq", 0x1A2B3C4D, 1, 0, -1))
    options = struct.pack(">HH", 9, 1) + bytes([9, 0, 0, 0]) + struct.pack(">HH", 0, 0)
    idb = block(1, struct.pack(">HHI", 147, 0, 0) + options)
    unknown = block(0x0BAD, b"\x00" * 8)
    ticks = 1_500_000_000_123_456_789
    epb = block(6, struct.pack(">IIIII", 0, ticks >> 32, ticks & 0xFFFFFFFF, 2, 2) + b"\xaa\x55\x00\x00")
    return shb + idb + unknown + epb


def test_big_endian_sections_and_other_resolutions_are_read() -> None:
    capture = read(io.BytesIO(big_endian_file()))
    (packet,) = capture.packets
    assert packet.data == b"\xaa\x55"
    assert packet.timestamp_us == 1_500_000_000_123_456
    assert packet.direction == Direction.UNKNOWN
    assert capture.interfaces[0].resolution == 1_000_000_000


def test_negative_time_is_refused() -> None:
    writer = PcapngWriter(io.BytesIO(), port="p", baud=9600)
    with pytest.raises(ValueError, match="before 1970"):
        writer.write(b"x", -1, Direction.INBOUND)
