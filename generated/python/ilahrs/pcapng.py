# Copied from generator/targets/python/runtime/pcapng.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A capture file of a serial line: pcapng with one Enhanced Packet Block per chunk read or written.

The format (IETF draft-ietf-opsawg-pcapng) is small: a Section Header Block, one Interface
Description Block per port, then one Enhanced Packet Block per chunk. What this module writes:

- the link type LINKTYPE_ILAHRS = 147 (LINKTYPE_USER0, "reserved for private use"): the packet data
  are the bytes exactly as they crossed the serial line, frames and $PAHR sentences alike, split
  wherever the reads and writes split them;
- an interface named after the port (`if_name`), described as the port and its line settings
  (`if_description`, e.g. "/dev/ttyUSB0, 115200 baud 8N1"), with microsecond timestamps
  (`if_tsresol` 6);
- per packet, the time the chunk was read or written and its direction in `epb_flags` bits 0-1:
  INBOUND (1) = device to host, OUTBOUND (2) = host to device.

The reader accepts either byte order, any timestamp resolution, several interfaces and skips
blocks it does not know; a damaged or truncated file raises PcapngError naming the offset, and so
does a block longer than MAX_BLOCK, before its bytes are read (a reader's memory stays within that
bound, whatever a damaged or hostile length field says). Every
block is written whole with one call and flushed, so a file cut short by an interrupted writer is
readable up to its last complete block (`read(..., partial=True)`). Standard library only.

>>> import io
>>> out = io.BytesIO()
>>> writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
>>> writer.write(bytes.fromhex("AA 55 00 00 07 00 FE 05 01"), 1_000_000, Direction.OUTBOUND)
>>> [(p.timestamp_us, p.direction.name, p.data.hex()) for p in read(io.BytesIO(out.getvalue())).packets]
[(1000000, 'OUTBOUND', 'aa5500000700fe0501')]
"""

from __future__ import annotations

import operator
import struct
from array import array
from collections.abc import Iterator
from dataclasses import dataclass, field
from enum import IntEnum
from itertools import accumulate
from types import ModuleType
from typing import Any, BinaryIO, Final

__all__ = [
    "LINKTYPE_ILAHRS",
    "MAX_BLOCK",
    "BulkReader",
    "Capture",
    "Direction",
    "IncrementalReader",
    "Interface",
    "Packet",
    "Packets",
    "PcapngError",
    "PcapngWriter",
    "line_description",
    "read",
]

LINKTYPE_ILAHRS: Final = 147
"""LINKTYPE_USER0: the bytes of the serial line as read or written (Wireshark's DLT_USER0)."""

MAX_BLOCK: Final = 16 << 20
"""The longest block read (16 MiB): far above any chunk of a serial line (a read at 115200 baud
that waited a whole minute holds 700 KB); a longer length field is damage, refused unread."""

_SHB: Final = 0x0A0D0D0A
_IDB: Final = 0x00000001
_SPB: Final = 0x00000003
_EPB: Final = 0x00000006
_MAGIC: Final = 0x1A2B3C4D
_OPT_END: Final = 0
_SHB_USERAPPL: Final = 4
_IF_NAME: Final = 2
_IF_DESCRIPTION: Final = 3
_IF_TSRESOL: Final = 9
_EPB_FLAGS: Final = 2
_DIRECTION_MASK: Final = 0x3
_MICROSECONDS: Final = 6
_SNAPLEN: Final = 0  # no limit
_PARITY: Final = {"none": "N", "even": "E", "odd": "O", "mark": "M", "space": "S"}


class PcapngError(ValueError):
    """The file is not pcapng, or a block is damaged or cut short."""


class Direction(IntEnum):
    """`epb_flags` bits 0-1."""

    UNKNOWN = 0
    INBOUND = 1
    """Device to host (read from the port)."""
    OUTBOUND = 2
    """Host to device (written to the port)."""


@dataclass(frozen=True, slots=True)
class Interface:
    """One Interface Description Block: the port."""

    linktype: int
    name: str = ""
    description: str = ""
    resolution: int = 1_000_000
    """Timestamp units per second."""


@dataclass(frozen=True, slots=True)
class Packet:
    """One chunk of bytes as it crossed the line."""

    timestamp_us: int
    direction: Direction
    data: bytes
    interface: int = 0
    original_length: int = -1

    @property
    def timestamp(self) -> float:
        """Seconds since 1970-01-01 UTC."""
        return self.timestamp_us / 1_000_000


@dataclass(slots=True)
class Capture:
    """What a file holds: its interfaces and packets, in file order."""

    interfaces: list[Interface] = field(default_factory=list)
    packets: list[Packet] = field(default_factory=list)
    application: str = ""
    truncated: bool = False
    """The file ends inside a block (read with partial=True)."""


def _option(code: int, value: bytes) -> bytes:
    return struct.pack("<HH", code, len(value)) + value + bytes(-len(value) % 4)


def _block(kind: int, body: bytes) -> bytes:
    length = 12 + len(body)
    return struct.pack("<II", kind, length) + body + struct.pack("<I", length)


def line_description(port: str, baud: int, data_bits: int = 8, parity: str = "none", stop_bits: int = 1) -> str:
    """The interface description: "/dev/ttyUSB0, 115200 baud 8N1"."""
    return f"{port}, {baud} baud {data_bits}{_PARITY.get(parity, '?')}{stop_bits}"


class PcapngWriter:
    """Writes a Section Header and one Interface Description on creation, then one Enhanced Packet
    Block per `write`. Each block goes out with one `write` call and is flushed."""

    def __init__(
        self,
        stream: BinaryIO,
        *,
        port: str,
        baud: int,
        data_bits: int = 8,
        parity: str = "none",
        stop_bits: int = 1,
        application: str = "ilahrs",
        linktype: int = LINKTYPE_ILAHRS,
    ) -> None:
        self._stream = stream
        section = struct.pack("<IHHq", _MAGIC, 1, 0, -1)
        section += _option(_SHB_USERAPPL, application.encode()) + _option(_OPT_END, b"")
        description = line_description(port, baud, data_bits, parity, stop_bits)
        interface = struct.pack("<HHI", linktype, 0, _SNAPLEN)
        interface += _option(_IF_NAME, port.encode()) + _option(_IF_DESCRIPTION, description.encode())
        interface += _option(_IF_TSRESOL, bytes([_MICROSECONDS])) + _option(_OPT_END, b"")
        self._put(_block(_SHB, section) + _block(_IDB, interface))

    def write(self, data: bytes | bytearray | memoryview, timestamp_us: int, direction: Direction) -> None:
        """One chunk: its bytes, when it was read or written (microseconds since the epoch), and
        which way it went."""
        if timestamp_us < 0:
            raise ValueError(f"timestamp {timestamp_us} before 1970")
        payload = bytes(data)
        body = struct.pack("<IIIII", 0, timestamp_us >> 32, timestamp_us & 0xFFFFFFFF, len(payload), len(payload))
        body += payload + bytes(-len(payload) % 4)
        if direction != Direction.UNKNOWN:
            body += _option(_EPB_FLAGS, struct.pack("<I", int(direction))) + _option(_OPT_END, b"")
        self._put(_block(_EPB, body))

    def _put(self, data: bytes) -> None:
        self._stream.write(data)
        self._stream.flush()


def _options(data: bytes, order: str, at: int) -> Iterator[tuple[int, bytes]]:
    pos = 0
    while pos + 4 <= len(data):
        code, length = struct.unpack_from(order + "HH", data, pos)
        if code == _OPT_END:
            return
        if pos + 4 + length > len(data):
            raise PcapngError(f"option {code} at offset {at + pos} runs past its block")
        yield code, data[pos + 4 : pos + 4 + length]
        pos += 4 + length + (-length % 4)


def _resolution(value: bytes) -> int:
    base = 2 if value[0] & 0x80 else 10
    units: int = base ** (value[0] & 0x7F)
    return units


class _Reader:
    def __init__(self, data: bytes) -> None:
        self.data = data
        self.order = "<"
        self.capture = Capture()

    def section(self, at: int, body: bytes) -> None:
        if len(body) < 16:
            raise PcapngError(f"section header at offset {at} is too short")
        (magic,) = struct.unpack_from("<I", body)
        if magic == _MAGIC:
            self.order = "<"
        elif magic == 0x4D3C2B1A:
            self.order = ">"
        else:
            raise PcapngError(f"section header at offset {at} has no byte-order magic")
        major, _minor = struct.unpack_from(self.order + "HH", body, 4)
        if major != 1:
            raise PcapngError(f"pcapng version {major} at offset {at} is not supported")
        self.capture.interfaces = []
        for code, value in _options(body[16:], self.order, at + 24):
            if code == _SHB_USERAPPL:
                self.capture.application = value.decode("utf-8", "replace")

    def interface(self, at: int, body: bytes) -> None:
        if len(body) < 8:
            raise PcapngError(f"interface description at offset {at} is too short")
        (linktype,) = struct.unpack_from(self.order + "H", body)
        name = description = ""
        resolution = 1_000_000
        for code, value in _options(body[8:], self.order, at + 16):
            if code == _IF_NAME:
                name = value.decode("utf-8", "replace")
            elif code == _IF_DESCRIPTION:
                description = value.decode("utf-8", "replace")
            elif code == _IF_TSRESOL and value:
                resolution = _resolution(value)
        self.capture.interfaces.append(Interface(linktype, name, description, resolution))

    def packet(self, at: int, body: bytes) -> None:
        if len(body) < 20:
            raise PcapngError(f"enhanced packet block at offset {at} is too short")
        interface, high, low, captured, original = struct.unpack_from(self.order + "IIIII", body)
        if interface >= len(self.capture.interfaces):
            raise PcapngError(f"packet at offset {at} names interface {interface}, which is not described")
        if 20 + captured > len(body):
            raise PcapngError(f"packet at offset {at} holds {captured} bytes but its block is shorter")
        direction = Direction.UNKNOWN
        options = body[20 + captured + (-captured % 4) :]
        for code, value in _options(options, self.order, at + 28 + captured):
            if code == _EPB_FLAGS and len(value) == 4:
                (flags,) = struct.unpack(self.order + "I", value)
                bits = flags & _DIRECTION_MASK
                direction = Direction(bits) if bits in (Direction.INBOUND, Direction.OUTBOUND) else Direction.UNKNOWN
        resolution = self.capture.interfaces[interface].resolution
        ticks = high << 32 | low
        timestamp_us = ticks * 1_000_000 // resolution
        data = body[20 : 20 + captured]
        self.capture.packets.append(Packet(timestamp_us, direction, data, interface, original))

    def simple_packet(self, at: int, body: bytes) -> None:
        if len(body) < 4 or not self.capture.interfaces:
            raise PcapngError(f"simple packet block at offset {at} without an interface")
        (original,) = struct.unpack_from(self.order + "I", body)
        data = body[4 : 4 + original]
        self.capture.packets.append(Packet(0, Direction.UNKNOWN, data, 0, original))


def _check_length(at: int, length: int) -> None:
    if length < 12 or length % 4:
        raise PcapngError(f"block at offset {at} has an impossible length {length}")
    if length > MAX_BLOCK:
        raise PcapngError(f"block at offset {at} claims {length} bytes, more than the {MAX_BLOCK >> 20} MiB allowed")


@dataclass(frozen=True, slots=True)
class Packets:
    """Consecutive packets of a file as arrays, no object per packet: `data` holds their bytes
    back to back, packet i's being data[ends[i - 1]:ends[i]] (from 0 for the first); `stamps`
    their timestamps (microseconds since the epoch), `directions` their Direction values (one
    byte each), `interfaces` their interface numbers and `originals` their lengths on the line.
    `first`: the number of the first one in the file, from 0."""

    data: bytes
    ends: array[int]
    stamps: array[int]
    directions: bytes
    interfaces: array[int]
    originals: array[int]
    first: int = 0

    def __len__(self) -> int:
        return len(self.ends)

    def packet(self, index: int) -> Packet:
        """Packet `index` (from 0 in these) as an object."""
        start = self.ends[index - 1] if index else 0
        data = self.data[start : self.ends[index]]
        direction = Direction(self.directions[index])
        return Packet(self.stamps[index], direction, data, self.interfaces[index], self.originals[index])


_BLOCK_HEAD: Final = {order: struct.Struct(order + "II") for order in "<>"}
_EPB_HEAD: Final = {order: struct.Struct(order + "IIIII") for order in "<>"}
_WORD: Final = {order: struct.Struct(order + "I") for order in "<>"}
_MAGICS: Final = {struct.pack("<I", _MAGIC): "<", struct.pack(">I", _MAGIC): ">"}
_FLAGS: Final = {order: struct.Struct(order + "HHII") for order in "<>"}
"""An Enhanced Packet Block's options as ilahrs writes them: epb_flags, then opt_endofopt."""
_FAST_EPB: Final = {order: struct.Struct(order + "IIIIIII") for order in "<>"}
"""An Enhanced Packet Block's head: block type and length, then interface, timestamp, lengths."""
_FAST_TAIL: Final = {order: struct.Struct(order + "HHIII") for order in "<>"}
"""An Enhanced Packet Block's end as ilahrs writes it: epb_flags, opt_endofopt, the length again."""
_DIRECTIONS: Final = bytes(
    bits if bits in (Direction.INBOUND, Direction.OUTBOUND) else Direction.UNKNOWN for bits in range(4)
)


class _Found:
    """Packets found in a reader's buffer: where their bytes are, and the rest of `Packets`."""

    __slots__ = ("directions", "interfaces", "originals", "stamps", "starts", "stops")

    def __init__(self) -> None:
        self.starts: list[int] = []
        self.stops: list[int] = []
        self.stamps: array[int] = array("q")
        self.directions = bytearray()
        self.interfaces: array[int] = array("L")
        self.originals: array[int] = array("q")


_MANY: Final = 1000
"""Packets from which `BulkReader` given numpy gathers their bytes with a mask."""
_RUN: Final = 1 << 16
"""Bytes of packet blocks from which `BulkReader` given numpy reads them as arrays."""


class BulkReader:
    """A pcapng file block by block, as its bytes arrive, its packets given as arrays (`Packets`):
    for a reader of many packets (a long capture), with every check `read` makes and its error
    messages. `feed(data)` returns the packets of the blocks it completes; the bytes of an
    unfinished block are held (`pending`). A damaged block gives the packets before it, and its
    PcapngError comes at the next `feed` or at `finish`, naming offsets in the whole file.
    `numpy` (optional): long runs of the packet blocks ilahrs writes are read as numpy arrays."""

    def __init__(self, numpy: ModuleType | None = None) -> None:
        self._numpy = numpy
        self._reader = _Reader(b"")
        self._buffer = bytearray()
        self._offset = 0
        self._count = 0
        self._error: PcapngError | None = None

    @property
    def capture(self) -> Capture:
        """The interfaces and application seen so far (packets are returned, not kept)."""
        return self._reader.capture

    @property
    def pending(self) -> int:
        """Bytes of a block not yet complete."""
        return len(self._buffer)

    @property
    def offset(self) -> int:
        """File offset of the first byte not yet part of a complete block."""
        return self._offset

    def feed(self, data: bytes | bytearray | memoryview) -> Packets:
        if self._error is not None:
            raise self._error
        self._buffer += data
        buffer = self._buffer
        found = _Found()
        pos = 0
        try:
            pos = self._walk(found)
        except PcapngError as exc:
            self._error = exc
            pos = exc.args[1]
            exc.args = exc.args[:1]
        joined = self._joined(found) if self._numpy is not None and len(found.starts) > _MANY else b""
        if not joined:
            view = memoryview(buffer)
            try:
                joined = b"".join(map(view.__getitem__, map(slice, found.starts, found.stops)))
            finally:
                view.release()
        del buffer[:pos]
        self._offset += pos
        ends = array("q", accumulate(map(operator.sub, found.stops, found.starts)))
        packets = Packets(
            joined, ends, found.stamps, bytes(found.directions), found.interfaces, found.originals, self._count
        )
        self._count += len(ends)
        if self._error is not None and not len(ends):
            raise self._error
        return packets

    def _walk(self, found: _Found) -> int:  # noqa: PLR0912, PLR0915 - one loop per packet, no call
        """Read the complete blocks in the buffer into `found`; where the first incomplete one
        starts. A PcapngError carries, as its second argument, where the damaged block starts."""
        reader, buffer = self._reader, self._buffer
        size = len(buffer)
        if self._offset == 0 and size >= 4 and _WORD["<"].unpack_from(buffer)[0] != _SHB:
            raise PcapngError("not a pcapng file (no section header block at offset 0)", 0)
        head, word = _BLOCK_HEAD[reader.order], _WORD[reader.order]
        epb, flags = _EPB_HEAD[reader.order], _FLAGS[reader.order]
        known = reader.capture.interfaces
        starts, stops, stamps = found.starts, found.stops, found.stamps
        directions, interfaces, originals = found.directions, found.interfaces, found.originals
        fast, tail = _FAST_EPB[reader.order], _FAST_TAIL[reader.order]
        resolutions = [interface.resolution for interface in known]
        pos = 0
        tried = 0 if self._numpy is not None else size  # where runs are read as arrays next (numpy)
        while size - pos >= 12:
            if pos >= tried and size - pos >= _RUN:
                moved = self._run(found, pos, size, resolutions)
                # after a long run, again past the block that ended it; else _RUN bytes on (so
                # that the bytes are scanned a bounded number of times)
                tried = moved + 1 if moved - pos >= _RUN else moved + _RUN
                pos = moved
            # Enhanced Packet Blocks as ilahrs writes them (microseconds, the epb_flags option alone):
            # two unpacks each; any other block, or any check failing, goes the whole way below.
            while size - pos >= 44 and pos < tried:
                kind, length, interface, high, low, captured, original = fast.unpack_from(buffer, pos)
                start = pos + 28
                options = start + captured + (-captured % 4)
                if kind != _EPB or options + 16 != pos + length or length > size - pos or length > MAX_BLOCK:
                    break
                if interface >= len(resolutions) or resolutions[interface] != 1_000_000:
                    break
                code, width, value, end, trailer = tail.unpack_from(buffer, options)
                if trailer != length or code != _EPB_FLAGS or width != 4 or end != _OPT_END:
                    break
                starts.append(start)
                stops.append(start + captured)
                stamps.append(high << 32 | low)
                directions.append(_DIRECTIONS[value & _DIRECTION_MASK])
                interfaces.append(interface)
                originals.append(original)
                pos += length
            if size - pos < 12:
                break
            at = self._offset + pos
            try:
                kind, length = head.unpack_from(buffer, pos)  # the SHB's type reads the same either way
                if kind == _SHB:
                    magic = bytes(buffer[pos + 8 : pos + 12])
                    if magic not in _MAGICS:
                        raise PcapngError(f"section header at offset {at} has no byte-order magic")
                    reader.order = _MAGICS[magic]
                    head, word = _BLOCK_HEAD[reader.order], _WORD[reader.order]
                    epb, flags = _EPB_HEAD[reader.order], _FLAGS[reader.order]
                    fast, tail = _FAST_EPB[reader.order], _FAST_TAIL[reader.order]
                    kind, length = head.unpack_from(buffer, pos)
                if length < 12 or length % 4 or length > MAX_BLOCK:
                    _check_length(at, length)
                if pos + length > size:
                    break
                (trailer,) = word.unpack_from(buffer, pos + length - 4)
                if trailer != length:
                    raise PcapngError(f"block at offset {at}: its lengths differ ({length}, {trailer})")
                if kind == _EPB and length >= 32:
                    # _Reader.packet, its checks in its order, into `found`
                    interface, high, low, captured, original = epb.unpack_from(buffer, pos + 8)
                    if interface >= len(known):
                        raise PcapngError(f"packet at offset {at} names interface {interface}, which is not described")
                    if 32 + captured > length:
                        raise PcapngError(f"packet at offset {at} holds {captured} bytes but its block is shorter")
                    start = pos + 28
                    options = start + captured + (-captured % 4)
                    stop = pos + length - 4
                    bits: int = Direction.UNKNOWN
                    if stop - options == 12:
                        code, width, value, end = flags.unpack_from(buffer, options)
                        if code == _EPB_FLAGS and width == 4 and end == _OPT_END:
                            bits = _DIRECTIONS[value & _DIRECTION_MASK]
                        else:
                            bits = _packet_direction(bytes(buffer[options:stop]), reader.order, at + 28 + captured)
                    elif stop != options:
                        bits = _packet_direction(bytes(buffer[options:stop]), reader.order, at + 28 + captured)
                    resolution = known[interface].resolution
                    ticks = high << 32 | low
                    starts.append(start)
                    stops.append(start + captured)
                    stamps.append(ticks if resolution == 1_000_000 else ticks * 1_000_000 // resolution)
                    directions.append(bits)
                    interfaces.append(interface)
                    originals.append(original)
                else:
                    self._other(found, kind, pos, length, at)
                    known = reader.capture.interfaces
                    resolutions = [interface.resolution for interface in known]
            except PcapngError as exc:
                exc.args = (*exc.args[:1], pos)
                raise
            pos += length
        return pos

    def _joined(self, found: _Found) -> bytes:
        """The bytes of the packets `found`, back to back (numpy: a mask over the buffer)."""
        numpy: Any = self._numpy
        ends = found.stops[-1]
        edges = numpy.zeros(ends + 1, dtype=numpy.int8)
        edges[numpy.array(found.starts, dtype=numpy.int64)] += 1  # packets never overlap
        edges[numpy.array(found.stops, dtype=numpy.int64)] -= 1
        inside = numpy.cumsum(edges[:-1], dtype=numpy.int8).view(bool)
        buffer = numpy.frombuffer(self._buffer[:ends], dtype=numpy.uint8)
        joined: bytes = buffer[inside].tobytes()
        return joined

    def _run(self, found: _Found, pos: int, size: int, resolutions: list[int]) -> int:
        """The loop of `_walk` over Enhanced Packet Blocks as ilahrs writes them, for the blocks
        from `pos` at once (numpy): the blocks that pass every check of that loop, each where the
        one before it ends, into `found`; where the last ends (`pos`: none)."""
        numpy: Any = self._numpy
        order = self._reader.order
        count = (size - pos) // 4
        words = numpy.frombuffer(self._buffer[pos : pos + 4 * count], dtype=numpy.dtype(order + "u4")).astype(
            numpy.int64
        )
        at = numpy.flatnonzero(words[: max(count - 10, 0)] == _EPB)  # in words from pos; 44 bytes at least
        length, captured = words[at + 1], words[at + 5]
        fits = (length >= 44) & (length <= MAX_BLOCK) & (4 * at + length <= 4 * count) & (words[at + 3] < 1 << 31)
        fits &= 28 + captured + (-captured % 4) + 16 == length
        at, length, captured = at[fits], length[fits], captured[fits]
        tail = at + length // 4 - 4  # epb_flags, its value, opt_endofopt, the length again
        option = _EPB_FLAGS | 4 << 16 if order == "<" else _EPB_FLAGS << 16 | 4
        fits = (words[tail] == option) & (words[tail + 2] == _OPT_END) & (words[tail + 3] == length)
        usable = numpy.array([resolution == 1_000_000 for resolution in resolutions] + [False], dtype=bool)
        interface = words[at + 2]
        fits &= usable[numpy.minimum(interface, len(resolutions))]
        at, length, captured, tail, interface = at[fits], length[fits], captured[fits], tail[fits], interface[fits]
        if not len(at) or at[0] != 0:
            return pos
        after = at + length // 4
        breaks = numpy.flatnonzero(after[:-1] != at[1:])
        last = int(breaks[0]) + 1 if len(breaks) else len(at)
        at, captured, tail, interface = at[:last], captured[:last], tail[:last], interface[:last]
        starts = pos + 28 + 4 * at
        found.starts += starts.tolist()
        found.stops += (starts + captured).tolist()
        found.stamps.frombytes((words[at + 3] << 32 | words[at + 4]).astype(numpy.int64).tobytes())
        directions = numpy.frombuffer(_DIRECTIONS, dtype=numpy.uint8)[words[tail + 1] & _DIRECTION_MASK]
        found.directions += directions.tobytes()
        found.interfaces.frombytes(interface.astype(f"u{found.interfaces.itemsize}").tobytes())
        found.originals.frombytes(words[at + 6].astype(numpy.int64).tobytes())
        return pos + 4 * int(after[last - 1])

    def _other(self, found: _Found, kind: int, pos: int, length: int, at: int) -> None:
        """A block other than a whole Enhanced Packet Block: read by _Reader (a Simple Packet
        Block's packet into `found`), skipped if unknown."""
        reader, buffer = self._reader, self._buffer
        body = bytes(buffer[pos + 8 : pos + length - 4])
        if kind in (_SHB, _IDB, _EPB):
            {_SHB: reader.section, _IDB: reader.interface, _EPB: reader.packet}[kind](at, body)
        elif kind == _SPB:
            reader.simple_packet(at, body)
            (original,) = _WORD[reader.order].unpack_from(buffer, pos + 8)
            reader.capture.packets.clear()
            found.starts.append(pos + 12)
            found.stops.append(min(pos + 12 + original, pos + length - 4))
            found.stamps.append(0)
            found.directions.append(Direction.UNKNOWN)
            found.interfaces.append(0)
            found.originals.append(original)

    def finish(self, *, partial: bool = False) -> None:
        """The input has ended: the error of a damaged block, if any; PcapngError if the input
        ends inside a block (unless `partial`, which marks the capture truncated)."""
        if self._error is not None:
            raise self._error
        if self._offset == 0 and len(self._buffer) < 12:
            raise PcapngError("not a pcapng file (no section header block at offset 0)")
        if self._buffer:
            if not partial:
                raise PcapngError(f"file ends inside the block at offset {self._offset} ({len(self._buffer)} bytes)")
            self._reader.capture.truncated = True


def _packet_direction(options: bytes, order: str, at: int) -> int:
    """The direction an Enhanced Packet Block's options give (the last epb_flags option)."""
    direction = Direction.UNKNOWN
    for code, value in _options(options, order, at):
        if code == _EPB_FLAGS and len(value) == 4:
            (flags,) = struct.unpack(order + "I", value)
            direction = Direction(_DIRECTIONS[flags & _DIRECTION_MASK])
    return direction


class IncrementalReader:
    """A pcapng file block by block, as its bytes arrive (a file that is still being written, a
    pipe, a large file read in chunks): `feed(data)` returns the packets of the blocks it
    completes; the bytes of an unfinished block are held (`pending`). Raises PcapngError as `read`
    does, naming offsets in the whole file: for a damaged block, after the packets before it
    (at the next `feed`, or at `finish`). `BulkReader` gives the packets as arrays."""

    def __init__(self) -> None:
        self._bulk = BulkReader()

    @property
    def capture(self) -> Capture:
        """The interfaces and application seen so far (packets are returned, not kept)."""
        return self._bulk.capture

    @property
    def pending(self) -> int:
        """Bytes of a block not yet complete."""
        return self._bulk.pending

    @property
    def offset(self) -> int:
        """File offset of the first byte not yet part of a complete block."""
        return self._bulk.offset

    def feed(self, data: bytes | bytearray | memoryview) -> list[Packet]:
        found = self._bulk.feed(data)
        return [found.packet(index) for index in range(len(found))]

    def finish(self, *, partial: bool = False) -> None:
        """The input has ended: PcapngError if it ends inside a block (unless `partial`, which
        marks the capture truncated)."""
        self._bulk.finish(partial=partial)


def read(stream: BinaryIO, *, partial: bool = False) -> Capture:
    """Every interface and packet of a pcapng file. `partial`: a file cut short inside its last
    block (a writer that was interrupted) gives what precedes that block instead of an error."""
    reader = _Reader(stream.read())
    data = reader.data
    if len(data) < 12 or struct.unpack_from("<I", data)[0] != _SHB:
        raise PcapngError("not a pcapng file (no section header block at offset 0)")
    pos = 0
    while pos < len(data):
        if pos + 12 > len(data):
            if partial:
                reader.capture.truncated = True
                break
            raise PcapngError(f"file ends inside the block at offset {pos}")
        (kind,) = struct.unpack_from("<I", data, pos)
        if kind == _SHB:
            magic = data[pos + 8 : pos + 12]
            if magic not in (struct.pack("<I", _MAGIC), struct.pack(">I", _MAGIC)):
                raise PcapngError(f"section header at offset {pos} has no byte-order magic")
            reader.order = "<" if magic == struct.pack("<I", _MAGIC) else ">"
        kind, length = struct.unpack_from(reader.order + "II", data, pos)
        _check_length(pos, length)
        if pos + length > len(data):
            if partial:
                reader.capture.truncated = True
                break
            raise PcapngError(f"file ends inside the block at offset {pos} ({length} bytes)")
        (trailer,) = struct.unpack_from(reader.order + "I", data, pos + length - 4)
        if trailer != length:
            raise PcapngError(f"block at offset {pos}: its lengths differ ({length}, {trailer})")
        body = data[pos + 8 : pos + length - 4]
        handler = {_SHB: reader.section, _IDB: reader.interface, _EPB: reader.packet, _SPB: reader.simple_packet}
        if kind in handler:
            handler[kind](pos, body)
        pos += length
    return reader.capture
