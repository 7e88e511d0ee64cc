# Copied from generator/targets/python/runtime/cli/capture.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Reading a capture for `ilahrs decode` and `ilahrs plot`: a pcapng file (`ilahrs.pcapng`, both
directions with timestamps) or a raw byte dump (what a terminal program saves: device-to-host
bytes, no timestamps), from a file or standard input, read in chunks so a large file needs little
memory and a growing one can be followed.

A file that starts with a pcapng Section Header Block is pcapng; any other file is a raw dump if
a frame or a $PAHR sentence is found in its first RAW_PROBE bytes (else it is refused). A pcapng
packet is read only from an interface of link type LINKTYPE_ILAHRS (the bytes of the serial
line); a capture of another link type (Ethernet ...) is refused, naming it, and so is a block
longer than `ilahrs.pcapng.MAX_BLOCK`, before it is read.
"""

from __future__ import annotations

import os
import struct
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import BinaryIO, Final

from ..columnar import numpy_for
from ..pcapng import LINKTYPE_ILAHRS, BulkReader, Direction, IncrementalReader, Packets, PcapngError
from ..stream import StreamDecoder
from .common import CliError

__all__ = ["CHUNK", "RAW_PROBE", "Chunk", "Source", "open_source"]

CHUNK: Final = 1 << 20
"""Bytes read at a time."""
RAW_PROBE: Final = 1 << 16
"""A raw dump must hold a message within this many bytes from its start."""
_FOLLOW_PAUSE: Final = 0.2
_SHB: Final = struct.pack("<I", 0x0A0D0D0A)
_LINKTYPES: Final = {
    0: "NULL (BSD loopback)",
    1: "ETHERNET",
    101: "RAW (IP)",
    105: "IEEE802_11 (Wi-Fi)",
    113: "LINUX_SLL",
    228: "IPV4",
    229: "IPV6",
    276: "LINUX_SLL2",
}
"""Names of the link types most often met, for the error that refuses them."""


@dataclass(frozen=True, slots=True)
class Chunk:
    """Bytes as they crossed the line: `time` in seconds since the epoch (None in a raw dump),
    `direction` INBOUND (device to host) or OUTBOUND (host to device)."""

    time: float | None
    direction: Direction
    data: bytes
    packet: int | None = None
    """The packet's number in a pcapng file, from 1 (Wireshark's frame number); None in a raw dump."""


class Source:
    """An open capture: `kind` is "pcapng" or "raw"; `chunks()` yields its Chunks in order."""

    def __init__(self, name: str, stream: BinaryIO, head: bytes, size: int | None) -> None:
        self.name = name
        self.kind = "pcapng" if head[:4] == _SHB else "raw"
        self.size = size
        """The file's size in bytes (None for a pipe)."""
        self.position = 0
        """Bytes read so far."""
        self.interface = ""
        """The pcapng interface description (port and line settings), once read."""
        self._stream = stream
        self._head = head

    def close(self) -> None:
        if self._stream is not sys.stdin.buffer:
            self._stream.close()

    def _read(self, follow: bool, stop: Callable[[], bool]) -> Iterator[bytes]:
        if self._head:
            head, self._head = self._head, b""
            self.position += len(head)
            yield head
        while True:
            data = self._stream.read(CHUNK)
            if data:
                self.position += len(data)
                yield data
                continue
            if not follow or stop():
                return
            time.sleep(_FOLLOW_PAUSE)

    def chunks(self, *, follow: bool = False, stop: Callable[[], bool] = lambda: False) -> Iterator[Chunk]:
        """Every chunk; with `follow`, keep reading as the file grows until `stop()` says so.
        CliError for a damaged or truncated pcapng file (after the chunks before the damage)."""
        if self.kind == "raw":
            for data in self._read(follow, stop):
                yield Chunk(None, Direction.INBOUND, data)
            return
        reader = IncrementalReader()
        number = 0
        try:
            for data in self._read(follow, stop):
                for packet in reader.feed(data):
                    number += 1
                    interface = reader.capture.interfaces[packet.interface]
                    if interface.linktype != LINKTYPE_ILAHRS:
                        raise CliError(f"{self.name}: {_foreign(interface.linktype, number)}")
                    if not self.interface:
                        self.interface = interface.description or interface.name
                    direction = Direction.OUTBOUND if packet.direction == Direction.OUTBOUND else Direction.INBOUND
                    yield Chunk(packet.timestamp_us / 1_000_000, direction, packet.data, number)
            reader.finish()
        except PcapngError as exc:
            raise CliError(f"{self.name}: {exc}") from exc

    def packets(self) -> Iterator[Packets]:
        """The packets of a pcapng file as arrays (`ilahrs.pcapng.Packets`), a read at a time:
        what `chunks` gives, without an object per packet. Directions are INBOUND or OUTBOUND as
        in a Chunk, `first` counts from 1 (a Chunk's `packet`). Errors as `chunks`'s."""
        reader = BulkReader(numpy_for("auto"))  # long runs of packets read as arrays
        try:
            for data in self._read(False, lambda: True):
                found = reader.feed(data)
                if not len(found):
                    continue
                interfaces = reader.capture.interfaces
                if not self.interface:
                    first = interfaces[found.interfaces[0]]
                    self.interface = first.description or first.name
                foreign = [n for n, i in enumerate(interfaces) if i.linktype != LINKTYPE_ILAHRS]
                cut = len(found)
                if foreign:
                    cut = next((k for k, n in enumerate(found.interfaces) if n in foreign), cut)
                yield _inbound_or_outbound(found, cut)
                if cut < len(found):
                    number = found.first + cut + 1
                    linktype = interfaces[found.interfaces[cut]].linktype
                    raise CliError(f"{self.name}: {_foreign(linktype, number)}")
            reader.finish()
        except PcapngError as exc:
            raise CliError(f"{self.name}: {exc}") from exc


_AS_CHUNKS: Final = bytes(
    Direction.OUTBOUND if bits == Direction.OUTBOUND else Direction.INBOUND for bits in range(256)
)


def _inbound_or_outbound(found: Packets, count: int) -> Packets:
    """The first `count` of `found`, numbered from 1, their directions INBOUND or OUTBOUND."""
    directions = found.directions.translate(_AS_CHUNKS)
    if count == len(found):
        return Packets(
            found.data, found.ends, found.stamps, directions, found.interfaces, found.originals, found.first + 1
        )
    end = found.ends[count - 1] if count else 0
    return Packets(
        found.data[:end],
        found.ends[:count],
        found.stamps[:count],
        directions[:count],
        found.interfaces[:count],
        found.originals[:count],
        found.first + 1,
    )


def _foreign(linktype: int, number: int) -> str:
    name = _LINKTYPES.get(linktype, "")
    named = f"{linktype} ({name})" if name else str(linktype)
    return f"packet {number} has link type {named}, not {LINKTYPE_ILAHRS} (LINKTYPE_USER0, an AHRS serial line)"


def _looks_raw(head: bytes) -> bool:
    decoder = StreamDecoder()
    return bool(decoder.feed(head) or decoder.finish())


def open_source(path: str) -> Source:
    """Open a capture file ("-": standard input) and tell pcapng from raw; CliError for a missing
    or unreadable file, an empty one, or one that is neither."""
    if path == "-":
        stream: BinaryIO = sys.stdin.buffer
        size = None
    else:
        try:
            stream = open(path, "rb")  # noqa: SIM115 - closed by Source.close
            size = os.fstat(stream.fileno()).st_size
        except FileNotFoundError as exc:
            raise CliError(f"{path}: no such file") from exc
        except IsADirectoryError as exc:
            raise CliError(f"{path}: is a directory, not a capture") from exc
        except OSError as exc:
            raise CliError(f"{path}: {exc.strerror or exc}") from exc
    head = stream.read(RAW_PROBE)
    name = "standard input" if path == "-" else path
    if not head:
        if path != "-":
            stream.close()
        raise CliError(f"{name}: empty, not a capture")
    source = Source(name, stream, head, size)
    if source.kind == "raw" and not _looks_raw(head):
        source.close()
        raise CliError(f"{name}: neither pcapng nor a raw capture (no frame or $PAHR sentence in its first bytes)")
    return source
