# Copied from generator/targets/python/runtime/columnar.py for spec/ilahrs.yaml,
# spec hash 78b1daeba1b7bf7f76f1a5c04fb54e25a73744c609525a6a8c577ce8f2cf2b4a.
# Do not edit: change the runtime source and run `make generate`.
"""A whole capture of one payload table as columns: one array per field, for numpy, pandas and
friends.

`columns(capture, FullOutput)` reads the blocks `ilahrs.bulk.decode_output` reads (the frames
the stream decoder accepts, of message type DATA, with the table's payload size) into a dict of
equal-length arrays: `offset`, where each frame starts in the capture; then every scaled field
in engineering units (float64, the value of the block's `values()`), every other number raw
(int64 or float64, as the block holds it: the Unit Status Word, ADC counts). Text and reserved
bytes are left out; a field whose scale is the device variant's needs `variant`. With numpy
installed (the `columns` extra) the arrays are numpy arrays, found and decoded without a Python
loop per frame; without it they are `array.array` ('d' for engineering values, 'q' for
integers). Both give the values the objects give.

>>> from ilahrs.frame import Frame
>>> from ilahrs.payloads import Quaternion
>>> capture = Frame(1, Quaternion(heading=9000, lk0=5000).build()).build()
>>> table = columns(capture, Quaternion, backend="array")
>>> table["offset"].tolist(), table["heading"].tolist(), table["lk0"].tolist()
([0], [90.0], [0.5])
"""

from __future__ import annotations

import struct
from array import array
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any, Final

from .bulk import Capture, _capture, _offsets, _payload_class
from .codec import FieldInfo, Payload, PayloadBase, field_kind, variant_of
from .encodings import VARIANTS, Variant
from .errors import ErrorKind, IlahrsError, brief
from .frame import (
    CHECKSUM_SIZE,
    HEADER,
    HEADER_SIZE,
    LENGTH_BIAS,
    MAX_MESSAGE_LENGTH,
    MESSAGE_LENGTH_OFFSET,
    MESSAGE_TYPE_OFFSET,
    MIN_MESSAGE_LENGTH,
    PAYLOAD_OFFSET,
    MessageType,
)

__all__ = ["BACKENDS", "columns"]

BACKENDS: Final = ("auto", "numpy", "array")
"""`backend` of `columns`: numpy if installed ("auto"), numpy, or the standard library's array."""

Scale = tuple[FieldInfo, int, "int | float | None"]
"""A column's field, multiplier and divisor (None: raw, not scaled)."""


def columns(
    data: Capture, payload: type[Payload], *, variant: Variant | str | None = None, backend: str = "auto"
) -> dict[str, Any]:
    """Every block of table `payload` in the capture `data` as columns (see the module's note).
    IlahrsError(MALFORMED) for a capture that is not a byte string, a `payload` that is not a
    payload class or an unknown backend (or numpy asked for and not installed);
    IlahrsError(OUT_OF_RANGE) for a `variant` that is not one."""
    capture = _capture(data)
    cls = _payload_class(payload)
    found = variant_of(variant)
    if backend not in BACKENDS:
        detail = f"{brief(backend)} is not a backend: one of {', '.join(BACKENDS)}"
        raise IlahrsError(ErrorKind.MALFORMED, None, "backend", detail)
    numpy = _numpy(backend)
    scales = _scales(cls, found)
    if numpy is None:
        return _array_columns(capture, cls, scales)
    return _numpy_columns(numpy, capture, cls, scales)


def _numpy(backend: str) -> ModuleType | None:
    if backend == "array":
        return None
    try:
        import numpy  # optional: the `columns` extra
    except ImportError:
        if backend == "numpy":
            detail = "numpy is not installed (the ilahrs[columns] extra)"
            raise IlahrsError(ErrorKind.MALFORMED, None, "backend", detail) from None
        return None
    return numpy


def _scales(cls: type[Any], variant: Variant | None) -> list[Scale]:
    # The scaled fields are those `values()` gives with a variant (a unit alone does not say).
    scaled = set(cls().values(next(iter(VARIANTS.values()))))
    result: list[Scale] = []
    for info in cls.FIELDS:
        if field_kind(info) not in ("integer", "float"):
            continue
        if info.name not in scaled:
            result.append((info, 1, None))
        elif isinstance(info.divisor, str):
            if variant is not None:
                result.append((info, info.multiplier, getattr(variant, info.divisor.lower())))
        else:
            result.append((info, info.multiplier, info.divisor))
    return result


def _engineering(raw: Sequence[Any], multiplier: int, divisor: int | float) -> list[float]:
    """As the payload classes compute it: raw * multiplier, then / divisor (or float())."""
    if multiplier != 1:
        raw = [value * multiplier for value in raw]
    if divisor != 1:
        return [value / divisor for value in raw]
    return [float(value) for value in raw]


def _array_columns(data: bytes | bytearray, cls: type[PayloadBase], scales: list[Scale]) -> dict[str, Any]:
    offsets = list(_offsets(data, cls.SIZE))
    unpack: Callable[..., tuple[Any, ...]] = struct.Struct(cls._STRUCT.format).unpack_from
    rows = [unpack(data, offset) for offset in offsets]
    fields = list(zip(*rows, strict=True)) if rows else [() for _ in cls.FIELDS]
    index = {info.name: position for position, info in enumerate(cls.FIELDS)}
    result: dict[str, Any] = {"offset": array("q", [offset - PAYLOAD_OFFSET for offset in offsets])}
    for info, multiplier, divisor in scales:
        raw = fields[index[info.name]]
        if divisor is None:
            result[info.name] = array("q", raw) if field_kind(info) == "integer" else array("d", raw)
        else:
            result[info.name] = array("d", _engineering(raw, multiplier, divisor))
    return result


def _dtype(numpy: ModuleType, info: FieldInfo) -> Any:
    letter = {"u": "u", "s": "i", "f": "f"}[info.type[0]]
    return numpy.dtype(f"<{letter}{info.size}")


def _frame_starts(numpy: ModuleType, buf: Any, size: int) -> tuple[Any, Any]:
    """Start and message length of every frame the stream decoder accepts in `buf`."""
    total = len(buf)
    last = total - PAYLOAD_OFFSET + 1
    if last <= 0:
        empty = numpy.zeros(0, dtype=numpy.int64)
        return empty, empty
    mask = buf[:last] == HEADER[0]
    for position in range(1, HEADER_SIZE):
        mask &= buf[position : last + position] == HEADER[position]
    starts = numpy.flatnonzero(mask).astype(numpy.int64)
    types = buf[starts + MESSAGE_TYPE_OFFSET]
    length = (
        buf[starts + MESSAGE_LENGTH_OFFSET].astype(numpy.int64)
        | buf[starts + MESSAGE_LENGTH_OFFSET + 1].astype(numpy.int64) << 8
    )
    ok = numpy.isin(types, [int(t) for t in MessageType])
    ok &= (length >= MIN_MESSAGE_LENGTH) & (length <= MAX_MESSAGE_LENGTH) & (starts + HEADER_SIZE + length <= total)
    starts, length = starts[ok], length[ok]
    sums = numpy.zeros(total + 1, dtype=numpy.uint32)
    numpy.cumsum(buf, dtype=numpy.uint32, out=sums[1:])
    at = starts + HEADER_SIZE + length - CHECKSUM_SIZE
    sent = buf[at].astype(numpy.uint16) | buf[at + 1].astype(numpy.uint16) << 8
    ok = ((sums[at] - sums[starts + HEADER_SIZE]) & 0xFFFF) == sent
    starts, length = starts[ok], length[ok]
    ends = starts + HEADER_SIZE + length
    if len(starts) > 1 and bool(numpy.any(starts[1:] < ends[:-1])):
        keep = []
        reached = 0
        for position, (start, end) in enumerate(zip(starts.tolist(), ends.tolist(), strict=True)):
            if start >= reached:
                keep.append(position)
                reached = end
        starts, length = starts[keep], length[keep]
    return starts, length


def _numpy_columns(
    numpy: ModuleType, data: bytes | bytearray, cls: type[PayloadBase], scales: list[Scale]
) -> dict[str, Any]:
    buf = numpy.frombuffer(data, dtype=numpy.uint8)
    starts, length = _frame_starts(numpy, buf, cls.SIZE)
    types = buf[starts + MESSAGE_TYPE_OFFSET]
    starts = starts[(length == cls.SIZE + LENGTH_BIAS) & (types == int(MessageType.DATA))]
    rows = buf[(starts + PAYLOAD_OFFSET)[:, None] + numpy.arange(cls.SIZE)]
    layout = numpy.dtype(
        {
            "names": [info.name for info, _, _ in scales],
            "formats": [_dtype(numpy, info) for info, _, _ in scales],
            "offsets": [info.offset for info, _, _ in scales],
            "itemsize": cls.SIZE,
        }
    )
    records = rows.view(layout).reshape(len(starts))
    result: dict[str, Any] = {"offset": starts}
    for info, multiplier, divisor in scales:
        wide = numpy.int64 if field_kind(info) == "integer" else numpy.float64
        value = records[info.name].astype(wide)
        if divisor is None:
            result[info.name] = value
            continue
        if multiplier != 1:
            value = value * multiplier
        result[info.name] = value / divisor if divisor != 1 else value.astype(numpy.float64)
    return result
