# Copied from generator/targets/python/runtime/bulk.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A whole capture at once: every block of one payload table as payload objects, fast.

`decode_output(capture, FullOutput)` gives what a host session started mid-stream in that output
format gives as its `Output` blocks: the frames the stream decoder accepts ("leftmost valid
message", input ended), those of message type DATA whose payload is the table's size, each parsed
by the table's `parse`. It walks the capture's bytes in place (no copy of a bytes or bytearray
capture, no per-message event objects; the blocks are made in batches with the garbage
collector paused), so it suits long logs; `payload_offsets` gives where the
payloads are, for a reader of its own (`ilahrs.columnar` reads them into columns). `strict`
accepts the frames a `StreamDecoder(strict=True)` accepts (E42).

>>> from ilahrs.frame import Frame
>>> from ilahrs.payloads import Quaternion
>>> capture = b"\\x00" + Frame(1, Quaternion(heading=9000).build()).build() + b"\\xaa\\x55"
>>> [block.heading_deg for block in decode_output(capture, Quaternion)]
[90.0]
"""

from __future__ import annotations

import gc
from collections.abc import Iterator
from functools import partial
from itertools import islice, starmap
from typing import Any, Final, TypeVar

from .codec import PayloadBase, maker
from .errors import ErrorKind, IlahrsError, brief, require_flag
from .frame import (
    HEADER,
    HEADER_SIZE,
    LENGTH_BIAS,
    MESSAGE_TYPE_OFFSET,
    PAYLOAD_OFFSET,
    MessageType,
    frame_at,
)
from .payloads import PAYLOADS

__all__ = ["capture_bytes", "decode_output", "payload_class", "payload_offsets", "tables_by_size"]

_P = TypeVar("_P")
_DATA: Final = int(MessageType.DATA)
_BATCH: Final = 4096
"""decode_output makes the blocks in batches of this many."""

Capture = bytes | bytearray | memoryview


def tables_by_size(direction: str) -> dict[int, tuple[str, ...]]:
    """The payload tables sent in `direction` ("device_to_host" or "host_to_device") by payload
    size: the one place a frame's size is mapped to the tables it may hold."""
    sizes: dict[int, tuple[str, ...]] = {}
    for name, table in PAYLOADS.items():
        if direction == table.DIRECTION:
            sizes[table.SIZE] = (*sizes.get(table.SIZE, ()), name)
    return sizes


def capture_bytes(data: object) -> bytes | bytearray:
    """A capture given as a byte string, as bytes or bytearray; IlahrsError(MALFORMED) for
    anything else."""
    if isinstance(data, (bytes, bytearray)):
        return data
    if isinstance(data, memoryview):
        return data.tobytes()
    detail = f"{brief(data)} is not a byte string (bytes, bytearray or memoryview)"
    raise IlahrsError(ErrorKind.MALFORMED, None, "data", detail)


def payload_class(payload: object) -> type[Any]:
    """`payload` if it is a payload class; IlahrsError(MALFORMED) otherwise."""
    if isinstance(payload, type) and issubclass(payload, PayloadBase):
        return payload
    raise IlahrsError(ErrorKind.MALFORMED, None, "payload", f"{brief(payload)} is not a payload class")


def payload_offsets(data: Capture, size: int, *, strict: bool = False) -> Iterator[int]:
    """Where the payload of each accepted DATA frame with a `size`-byte payload starts in `data`,
    in order. The frames are those `StreamDecoder(strict=strict)` accepts when fed `data` and
    finished: a valid $PAHR sentence never holds a frame header, so frames alone decide."""
    return _offsets(capture_bytes(data), size, require_flag(strict, "strict"))


def _offsets(data: bytes | bytearray, size: int, strict: bool = False) -> Iterator[int]:
    find = data.find
    total = len(data)
    wanted = HEADER_SIZE + size + LENGTH_BIAS
    pos = find(HEADER)
    while pos >= 0:
        used = frame_at(data, pos, total, strict=strict)
        if used > 0:
            if used == wanted and data[pos + MESSAGE_TYPE_OFFSET] == _DATA:
                yield pos + PAYLOAD_OFFSET
            pos = find(HEADER, pos + used)
        else:
            pos = find(HEADER, pos + 1)


def decode_output(data: Capture, payload: type[_P], *, strict: bool = False) -> Iterator[_P]:
    """Every block of table `payload` (a payload class) in the capture `data`, as payload objects
    equal to `payload.parse` of each (see the module's note for which frames count; `strict`:
    refuse data frames whose reserved byte is not the AHRS's, E42).
    IlahrsError(MALFORMED) at once for a capture that is not a byte string or a `payload` that is
    not a payload class."""
    capture = capture_bytes(data)
    cls = payload_class(payload)
    return _decode(capture, cls, require_flag(strict, "strict"))


def _decode(data: bytes | bytearray, cls: type[Any], strict: bool) -> Iterator[Any]:
    size = cls.SIZE
    if cls._TEXT:
        parse = cls.parse
        for offset in _offsets(data, size, strict):
            yield parse(data[offset : offset + size])
        return
    offsets = _offsets(data, size, strict)
    blocks = starmap(maker(cls), map(partial(cls._STRUCT.unpack_from, data), offsets))
    while True:
        # The collector, run every few hundred new objects, costs more than the decoding when the
        # caller keeps the blocks: it is paused while a batch is made (never while the caller runs).
        paused = gc.isenabled()
        gc.disable()
        try:
            batch = list(islice(blocks, _BATCH))
        finally:
            if paused:
                gc.enable()
        if not batch:
            return
        yield from batch
