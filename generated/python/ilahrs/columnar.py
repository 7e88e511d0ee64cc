# Copied from generator/targets/python/runtime/columnar.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A whole capture as columns: one array per field, for numpy, pandas and friends.

`columns(capture, FullOutput)` reads the blocks `ilahrs.bulk.decode_output` reads (the frames the
stream decoder accepts, of message type DATA, with the table's payload size) into a dict of
equal-length arrays: `time`, `kind` and `offset` (see below), then every scaled field in
engineering units (float64, the value of the block's `values()`), every other number raw (int64 or
float64, as the block holds it: the Unit Status Word, ADC counts). Text and reserved bytes are left
out; a field whose scale is the device variant's needs `variant`.

`columns_by_kind(capture)` decodes every message of a device-to-host capture at once: a dict from
message kind (a payload table's name, or PAHR for the $PAHR sentences) to such a dict of columns.
A frame's table is told as a host without context tells it (`ilahrs decode` on a raw dump): the
table of the output format named by `output` when the payload has its size, else the one
device-to-host table of that size. Frames no table explains (the three 34-byte output formats
without `output`) and command frames are left out; the stream decoder shows them.

Shared columns, the same in every column set:

- `time`: float64, seconds since 1970-01-01 UTC when the message's last byte was recorded, for a
  pcapng capture (`ilahrs record`, `ilahrs simulate --record`; its device-to-host packets are
  read, each byte having its packet's timestamp). A raw byte dump records no time: `time` is NaN
  there (never made up; `offset` orders the rows, and a nominal time is the user's to make).
- `kind`: int16, the message kind as an index into `KINDS` (pandas:
  `pandas.Categorical.from_codes(table["kind"], KINDS)`).
- `offset`: int64, where the message starts in the capture's device-to-host bytes.

`pandas.DataFrame(columns(...))` is one table; `pandas.concat(map(pandas.DataFrame,
columns_by_kind(...).values())).sort_values("offset")` puts every message in capture order (fields
a kind does not have are NaN there).

With numpy installed (the `columns` extra) the arrays are numpy arrays, found and decoded a window
of the capture at a time without a Python loop per frame (memory beyond the capture and the
columns stays a few MiB); without it they are `array.array` ('d' for engineering values and time,
'q' for integers and offsets, 'h' for kinds). Both give the values the objects give.

>>> from ilahrs.frame import Frame
>>> from ilahrs.payloads import Quaternion
>>> capture = Frame(1, Quaternion(heading=9000, lk0=5000).build()).build()
>>> table = columns(capture, Quaternion, backend="array")
>>> table["offset"].tolist(), table["heading"].tolist(), table["lk0"].tolist()
([0], [90.0], [0.5])
>>> KINDS[table["kind"][0]], math.isnan(table["time"][0])
('quaternion', True)
"""

from __future__ import annotations

import io
import math
import struct
from array import array
from bisect import bisect_right
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from itertools import accumulate
from types import ModuleType
from typing import Any, Final

from .bulk import Capture, capture_bytes, payload_class, tables_by_size
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
    RESERVED_OFFSET,
    STRICT_RESERVED,
    MessageType,
    frame_at,
)
from .nmea import MAX_SENTENCE_LENGTH, PREFIX, PahrSentence
from .payloads import PAYLOADS
from .pcapng import Direction, PcapngError, read
from .spec import MAX_MESSAGE_SIZE

__all__ = ["BACKENDS", "KINDS", "Capture", "columns", "columns_by_kind"]

BACKENDS: Final = ("auto", "numpy", "array")
"""`backend` of `columns`: numpy if installed ("auto"), numpy, or the standard library's array."""
KINDS: Final = (*PAYLOADS, PahrSentence.IDENTIFIER)
"""The names the `kind` column's codes stand for: every payload table, then PAHR."""
SENTENCE: Final = len(KINDS) - 1
"""The kind code of a $PAHR sentence."""
COMMAND: Final = len(KINDS)
"""The code `Scanner` gives a command frame (no column set)."""
UNEXPLAINED: Final = len(KINDS) + 1
"""The code `Scanner` gives a frame no table explains (no column set)."""

WINDOW: Final = 1 << 21
"""Bytes scanned at a time (numpy: the running checksum sums take twice this)."""
_SENTENCE_TYPE: Final = -1
"""The message type recorded for a sentence."""
_LF: Final = b"\n"
_DATA: Final = int(MessageType.DATA)
_COMMAND_TYPE: Final = int(MessageType.COMMAND)
_MESSAGE_TYPES: Final = frozenset(int(t) for t in MessageType)
_LENGTH_HIGH: Final = MESSAGE_LENGTH_OFFSET + 1
_SHB: Final = struct.pack("<I", 0x0A0D0D0A)

Scale = tuple[FieldInfo, int, "int | float | None"]
"""A column's field, multiplier and divisor (None: raw, not scaled)."""


def columns(
    data: Capture, payload: type[Payload], *, variant: Variant | str | None = None, backend: str = "auto"
) -> dict[str, Any]:
    """Every block of table `payload` in the capture `data` (raw bytes or a pcapng file's bytes)
    as columns (see the module's note). IlahrsError(MALFORMED) for a capture that is not a byte
    string or a damaged pcapng file, a `payload` that is not a payload class or an unknown backend
    (or numpy asked for and not installed); IlahrsError(OUT_OF_RANGE) for a `variant` that is not
    one."""
    cls = payload_class(payload)
    found = variant_of(variant)
    numpy = numpy_for(backend)
    recording = Recording.of(capture_bytes(data))
    scanner = Scanner(numpy, sentences=False)
    kind = KINDS.index(cls.NAME)
    wanted = HEADER_SIZE + cls.SIZE + LENGTH_BIAS
    sets = _Sets(numpy, {kind: cls}, found)
    for window in scanner.scan(recording.data, final=True):
        sets.add(window, kind, window.select(_DATA, wanted))
    return sets.result(recording)[cls.NAME]


def columns_by_kind(
    data: Capture,
    *,
    output: type[Payload] | None = None,
    variant: Variant | str | None = None,
    backend: str = "auto",
) -> dict[str, dict[str, Any]]:
    """Every payload table's blocks and every $PAHR sentence in the device-to-host capture `data`
    as a column set per kind (see the module's note), in `KINDS` order, kinds not found left out.
    Errors as `columns`'s (a non-payload `output` is MALFORMED)."""
    table = None if output is None else payload_class(output).NAME
    found = variant_of(variant)
    numpy = numpy_for(backend)
    recording = Recording.of(capture_bytes(data))
    scanner = Scanner(numpy, output=table)
    classes = {code: PAYLOADS[name] for code, name in enumerate(KINDS[:SENTENCE])}
    sets = _Sets(numpy, classes, found)
    for window in scanner.scan(recording.data, final=True):
        for kind, rows in window.groups().items():
            if kind <= SENTENCE:
                sets.add(window, kind, rows)
    return sets.result(recording)


def numpy_for(backend: str) -> ModuleType | None:
    """numpy for `backend`, None for the array fallback; IlahrsError(MALFORMED) for an unknown
    backend or numpy asked for and not installed."""
    if backend not in BACKENDS:
        detail = f"{brief(backend)} is not a backend: one of {', '.join(BACKENDS)}"
        raise IlahrsError(ErrorKind.MALFORMED, None, "backend", detail)
    if backend == "array":
        return None
    try:
        import numpy  # optional: the `columns` extra
    except ImportError:
        if backend == "numpy":
            detail = "numpy is not installed (the columns extra: pip install 'numpy>=1.22')"
            raise IlahrsError(ErrorKind.MALFORMED, None, "backend", detail) from None
        return None
    return numpy


# --- The capture: its device-to-host bytes and when they were recorded -----------------------------


@dataclass(frozen=True)
class Recording:
    """A capture's device-to-host bytes and, for pcapng, where each packet ends in them and its
    timestamp (seconds since the epoch)."""

    data: bytes | bytearray
    ends: list[int] | None = None
    stamps: list[float] | None = None

    @classmethod
    def of(cls, data: bytes | bytearray) -> Recording:
        if data[:4] != _SHB:
            return cls(data)
        try:
            capture = read(io.BytesIO(data))
        except PcapngError as exc:
            raise IlahrsError(ErrorKind.MALFORMED, None, "data", f"pcapng: {exc}") from None
        packets = [p for p in capture.packets if p.direction != Direction.OUTBOUND]
        ends = list(accumulate(len(p.data) for p in packets))
        return cls(b"".join(p.data for p in packets), ends, [p.timestamp_us / 1_000_000 for p in packets])

    def times(self, numpy: ModuleType | None, last: Any) -> Any:
        """The timestamp of the packet holding each of the byte offsets `last` (NaN: no time)."""
        if self.ends is None or self.stamps is None:
            return numpy.full(len(last), math.nan) if numpy is not None else array("d", [math.nan]) * len(last)
        stamps = [*self.stamps, math.nan]
        if numpy is not None:
            ends = numpy.array(self.ends, dtype=numpy.int64)
            return numpy.array(stamps)[numpy.searchsorted(ends, last, side="right")]
        return array("d", [stamps[bisect_right(self.ends, at)] for at in last])


# --- Finding messages -------------------------------------------------------------------------------


@dataclass
class Window:
    """The messages the stream decoder accepts that start in one window of the capture, in order:
    `starts` (offsets in the capture), `lengths` (bytes), `types` (a frame's message type, -1 for a
    sentence), `kinds` (codes into KINDS, or COMMAND, UNEXPLAINED); `sentences` by start. numpy
    arrays, or lists without numpy."""

    numpy: ModuleType | None
    data: bytes | bytearray
    starts: Any
    lengths: Any
    types: Any
    kinds: Any = None
    base: int = 0
    """Offset in the capture of `data`'s first byte."""
    sentences: dict[int, PahrSentence] = field(default_factory=dict)

    def select(self, message_type: int, length: int) -> Any:
        """Positions of the messages of this type and length."""
        if self.numpy is not None:
            return self.numpy.flatnonzero((self.types == message_type) & (self.lengths == length))
        return [
            i
            for i, (t, n) in enumerate(zip(self.types, self.lengths, strict=True))
            if t == message_type and n == length
        ]

    def groups(self) -> dict[int, Any]:
        """Positions of the messages of each kind code, in order of first appearance."""
        numpy = self.numpy
        if numpy is not None:
            codes, first = numpy.unique(self.kinds, return_index=True)
            return {int(codes[i]): numpy.flatnonzero(self.kinds == codes[i]) for i in numpy.argsort(first)}
        result: dict[int, list[int]] = {}
        for position, code in enumerate(self.kinds):
            result.setdefault(code, []).append(position)
        return result


class Scanner:
    """The stream decoder's choice of messages ("leftmost valid message") a window at a time.
    `scan(data)` decides the messages starting in `data` up to MAX_MESSAGE_SIZE before its end (all
    of it with `final`), returns them as Windows and says how far it decided (`decided`, relative
    to `data`); the next call continues with the bytes from there. `output` (a table name) gives
    frames of its size that table, as with a host that sent the output's command. `strict`: the
    messages of a `StreamDecoder(strict=True)` (E42)."""

    def __init__(
        self, numpy: ModuleType | None, *, sentences: bool = True, output: str | None = None, strict: bool = False
    ) -> None:
        self.numpy = numpy
        self.sentences = sentences
        self.strict = strict
        self.base = 0
        """Offset in the capture of the next `data` given."""
        self.reached = 0
        """Offset in the capture of the end of the last accepted message."""
        self.decided = 0
        by_length = [UNEXPLAINED] * (max(HEADER_SIZE + MAX_MESSAGE_LENGTH, MAX_MESSAGE_SIZE) + 1)
        for size, names in tables_by_size("device_to_host").items():
            if len(names) == 1:
                by_length[HEADER_SIZE + size + LENGTH_BIAS] = KINDS.index(names[0])
        if output is not None:
            by_length[HEADER_SIZE + PAYLOADS[output].SIZE + LENGTH_BIAS] = KINDS.index(output)
        self._by_length = by_length

    def scan(self, data: bytes | bytearray, *, final: bool) -> list[Window]:
        total = len(data)
        result: list[Window] = []
        low = 0
        numpy = self.numpy
        buf = None if numpy is None else numpy.frombuffer(data, dtype=numpy.uint8)
        while low < total:
            high = min(low + WINDOW, total if final else total - MAX_MESSAGE_SIZE)
            if high <= low:
                break
            end = min(total, high + MAX_MESSAGE_SIZE)
            reached = self.reached - self.base
            if numpy is None:
                window = _scan_stdlib(data, low, high, end, reached, sentences=self.sentences, strict=self.strict)
            else:
                span = (low, high, end)
                window = _scan_numpy(numpy, data, buf, span, reached, sentences=self.sentences, strict=self.strict)
            if len(window.starts):
                self.reached = self.base + int(window.starts[-1]) + int(window.lengths[-1])
            self._finish(window)
            result.append(window)
            low = high
        self.decided = low
        self.base += low
        return result

    def _finish(self, window: Window) -> None:
        """Capture offsets and kind codes."""
        numpy = self.numpy
        if numpy is not None:
            by_length = numpy.array(self._by_length, dtype=numpy.int16)
            kinds = by_length[window.lengths]
            kinds[window.types == _COMMAND_TYPE] = COMMAND
            kinds[window.types == _SENTENCE_TYPE] = SENTENCE
            window.kinds = kinds
            window.starts = window.starts + self.base
            window.base = self.base
        else:
            special = {_COMMAND_TYPE: COMMAND, _SENTENCE_TYPE: SENTENCE}
            by_length = self._by_length
            window.kinds = [special.get(t, by_length[n]) for t, n in zip(window.types, window.lengths, strict=True)]
            window.starts = [start + self.base for start in window.starts]
            window.base = self.base
        window.sentences = {start + self.base: s for start, s in window.sentences.items()}


def _sentence(data: bytes | bytearray, pos: int, end: int) -> PahrSentence | None:
    """The sentence at `pos` if one is valid there (its LF before `end`)."""
    lf = data.find(_LF, pos, min(end, pos + MAX_SENTENCE_LENGTH))
    if lf < 0:
        return None
    try:
        return PahrSentence.parse(bytes(data[pos : lf + 1]))
    except IlahrsError:
        return None


def _scan_stdlib(
    data: bytes | bytearray, low: int, high: int, end: int, reached: int, *, sentences: bool, strict: bool = False
) -> Window:
    """The messages starting in low..high, the bytes up to `end` known, none before `reached`."""
    starts: list[int] = []
    lengths: list[int] = []
    types: list[int] = []
    found: dict[int, PahrSentence] = {}
    find = data.find
    pos = max(low, reached)
    frame_limit = min(end, high + HEADER_SIZE - 1)
    sentence_limit = min(end, high + len(PREFIX) - 1)
    frame = find(HEADER, pos, frame_limit)
    frame = high if frame < 0 else frame
    sentence = find(PREFIX, pos, sentence_limit) if sentences else -1
    sentence = high if sentence < 0 else sentence
    while True:
        at = min(frame, sentence)
        if at >= high:
            break
        used = 0
        if at == frame:
            used = max(frame_at(data, at, end, strict=strict), 0)
            if used:
                types.append(data[at + MESSAGE_TYPE_OFFSET])
        else:
            parsed = _sentence(data, at, end)
            if parsed is not None:
                used = find(_LF, at) + 1 - at
                found[at] = parsed
                types.append(_SENTENCE_TYPE)
        if used:
            starts.append(at)
            lengths.append(used)
            pos = at + used
        else:
            pos = at + 1
        if frame < pos:
            frame = find(HEADER, pos, frame_limit)
            frame = high if frame < 0 else frame
        if sentence < pos:
            sentence = find(PREFIX, pos, sentence_limit)
            sentence = high if sentence < 0 else sentence
    return Window(None, data, starts, lengths, types, sentences=found)


def _matches(numpy: ModuleType, buf: Any, span: tuple[int, int, int], pattern: bytes) -> Any:
    """Where `pattern` starts in low..high, wholly before `end` (`span`: low, high, end)."""
    low, high, end = span
    last = min(high, end - len(pattern) + 1)
    if last <= low:
        return numpy.zeros(0, dtype=numpy.int64)
    mask = buf[low:last] == pattern[0]
    for position in range(1, len(pattern)):
        mask &= buf[low + position : last + position] == pattern[position]
    return numpy.flatnonzero(mask).astype(numpy.int64) + low


def _scan_numpy(
    numpy: ModuleType,
    data: bytes | bytearray,
    buf: Any,
    span: tuple[int, int, int],
    reached: int,
    *,
    sentences: bool,
    strict: bool = False,
) -> Window:
    """_scan_stdlib with numpy: every valid message is found at once, then the leftmost kept. The
    frames are those `frame_at` accepts, its rule checked on every candidate at once (property
    tested against it: tests/test_frame_rule.py)."""
    low, high, end = span
    starts = _matches(numpy, buf, (max(low, reached), high, end), HEADER)
    starts = starts[starts + PAYLOAD_OFFSET <= end]
    types = buf[starts + MESSAGE_TYPE_OFFSET].astype(numpy.int16)
    length = (
        buf[starts + MESSAGE_LENGTH_OFFSET].astype(numpy.int64) | buf[starts + _LENGTH_HIGH].astype(numpy.int64) << 8
    )
    ok = numpy.isin(types, list(_MESSAGE_TYPES))
    ok &= (length >= MIN_MESSAGE_LENGTH) & (length <= MAX_MESSAGE_LENGTH) & (starts + HEADER_SIZE + length <= end)
    starts, types, length = starts[ok], types[ok], length[ok] + HEADER_SIZE
    if len(starts):
        first = int(starts[0])
        # Running sums modulo 2**16 (the checksum's modulus): their differences are the checksums.
        sums = numpy.zeros(end - first + 1, dtype=numpy.uint16)
        numpy.cumsum(buf[first:end], dtype=numpy.uint16, out=sums[1:])
        at = starts + length - CHECKSUM_SIZE
        sent = buf[at].astype(numpy.uint16) | buf[at + 1].astype(numpy.uint16) << 8
        ok = (sums[at - first] - sums[starts + HEADER_SIZE - first]) == sent
        if strict:
            for kind, reserved in STRICT_RESERVED.items():
                ok &= (types != kind) | (buf[starts + RESERVED_OFFSET] == reserved)
        starts, types, length = starts[ok], types[ok], length[ok]
    found: dict[int, PahrSentence] = {}
    if sentences:
        for at in _matches(numpy, buf, (max(low, reached), high, end), PREFIX).tolist():
            parsed = _sentence(data, at, end)
            if parsed is not None:
                found[at] = parsed
    if found:
        spots = numpy.array(list(found), dtype=numpy.int64)
        sizes = numpy.array([data.find(_LF, at) + 1 - at for at in found], dtype=numpy.int64)
        starts = numpy.concatenate([starts, spots])
        length = numpy.concatenate([length, sizes])
        types = numpy.concatenate([types, numpy.full(len(spots), _SENTENCE_TYPE, dtype=numpy.int16)])
        order = numpy.argsort(starts, kind="stable")
        starts, length, types = starts[order], length[order], types[order]
    keep = _leftmost(numpy, starts, starts + length)
    if keep is not None:
        starts, length, types = starts[keep], length[keep], types[keep]
        found = {at: found[at] for at in starts[types == _SENTENCE_TYPE].tolist()}
    return Window(numpy, data, starts, length, types, sentences=found)


def _leftmost(numpy: ModuleType, starts: Any, ends: Any) -> Any:
    """Which of the valid messages (sorted by start) the stream decoder accepts: each one that
    starts at or after the end of the last accepted one. None: all of them."""
    if len(starts) < 2:
        return None
    covered = numpy.maximum.accumulate(ends)
    clash = starts[1:] < covered[:-1]
    if not bool(clash.any()):
        return None
    keep = numpy.ones(len(starts), dtype=bool)
    involved = numpy.zeros(len(starts), dtype=bool)
    involved[1:] |= clash
    involved[:-1] |= clash
    reached = -1
    for position in numpy.flatnonzero(involved).tolist():
        if int(starts[position]) >= reached:
            reached = int(ends[position])
        else:
            keep[position] = False
    return keep


# --- Columns ----------------------------------------------------------------------------------------


def scales(cls: type[Any], variant: Variant | None) -> list[Scale]:
    """The numeric fields of `cls` with their multiplier and divisor (None: raw); a field scaled by
    the variant's rate is left out without a variant."""
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


class _Sets:
    """Column sets: the starts of each kind's messages gathered a window at a time, then every
    column made at its full length and filled ROWS rows at a time (no parts to join)."""

    def __init__(self, numpy: ModuleType | None, classes: dict[int, type[Any]], variant: Variant | None) -> None:
        self.numpy = numpy
        self.classes = classes
        self.scales = {kind: scales(cls, variant) for kind, cls in classes.items()}
        self.picks: dict[int, list[Any]] = {}
        self.sentences: dict[int, tuple[int, PahrSentence]] = {}
        """A sentence's end and value by its start."""

    def add(self, window: Window, kind: int, rows: Any) -> None:
        starts = window.starts[rows] if self.numpy is not None else [window.starts[i] for i in rows]
        self.picks.setdefault(kind, []).append(starts)
        if kind == SENTENCE:
            for i in rows:
                at = int(window.starts[i])
                self.sentences[at] = (at + int(window.lengths[i]), window.sentences[at])

    def result(self, recording: Recording) -> dict[str, dict[str, Any]]:
        """Every kind's columns (an empty set for the one class asked for and not found)."""
        numpy = self.numpy
        result: dict[str, dict[str, Any]] = {}
        for kind in sorted(set(self.picks) | (set(self.classes) if len(self.classes) == 1 else set())):
            pieces = self.picks.pop(kind, [])
            if numpy is not None:
                starts = numpy.concatenate(pieces) if pieces else numpy.zeros(0, dtype=numpy.int64)
            else:
                starts = array("q", [at for piece in pieces for at in piece])
            if kind == SENTENCE:
                found = [self.sentences[at] for at in starts]
                ends = [end for end, _ in found]
                last = numpy.array(ends, dtype=numpy.int64) - 1 if numpy is not None else [at - 1 for at in ends]
            else:
                size = HEADER_SIZE + self.classes[kind].SIZE + LENGTH_BIAS
                last = starts + (size - 1) if numpy is not None else [at + size - 1 for at in starts]
            columns: dict[str, Any] = {"time": recording.times(numpy, last)}
            if numpy is not None:
                columns["kind"] = numpy.full(len(starts), kind, dtype=numpy.int16)
            else:
                columns["kind"] = array("h", [kind]) * len(starts)
            columns["offset"] = starts
            if kind == SENTENCE:
                columns.update(sentence_columns(numpy, [value for _, value in found]))
            else:
                columns.update(_filled(numpy, recording.data, starts, self.classes[kind], self.scales[kind]))
            result[KINDS[kind]] = columns
        return result


ROWS: Final = 1 << 18
"""Rows decoded at a time into the full-length numpy columns."""


def _filled(
    numpy: ModuleType | None, data: bytes | bytearray, starts: Any, cls: type[Any], fields: list[Scale]
) -> dict[str, Any]:
    """table_columns of every frame at `starts`, with numpy ROWS rows at a time into columns made
    at their full length (the peak is the columns and one batch, not the columns twice)."""
    if numpy is None or len(starts) <= ROWS:
        return table_columns(numpy, data, starts, cls, fields)
    result: dict[str, Any] = {}
    for low in range(0, len(starts), ROWS):
        part = table_columns(numpy, data, starts[low : low + ROWS], cls, fields)
        for name, column in part.items():
            if name not in result:
                result[name] = numpy.empty(len(starts), dtype=column.dtype)
            result[name][low : low + len(column)] = column
    return result


def _engineering(raw: Sequence[Any], multiplier: int, divisor: int | float) -> list[float]:
    """As the payload classes compute it: raw * multiplier, then / divisor (or float())."""
    if multiplier != 1:
        raw = [value * multiplier for value in raw]
    if divisor != 1:
        return [value / divisor for value in raw]
    return [float(value) for value in raw]


def table_columns(
    numpy: ModuleType | None, data: bytes | bytearray, starts: Any, cls: type[Any], fields: list[Scale]
) -> dict[str, Any]:
    """The columns of `fields` of the frames of table `cls` starting at `starts` in `data`."""
    if numpy is not None:
        return _numpy_columns(numpy, data, starts, cls, fields)
    unpack: Callable[..., tuple[Any, ...]] = struct.Struct(cls._STRUCT.format).unpack_from
    rows = [unpack(data, start + PAYLOAD_OFFSET) for start in starts]
    values = list(zip(*rows, strict=True)) if rows else [() for _ in cls.FIELDS]
    index = {info.name: position for position, info in enumerate(cls.FIELDS)}
    result: dict[str, Any] = {}
    for info, multiplier, divisor in fields:
        raw = values[index[info.name]]
        if divisor is None:
            result[info.name] = array("q", raw) if field_kind(info) == "integer" else array("d", raw)
        else:
            result[info.name] = array("d", _engineering(raw, multiplier, divisor))
    return result


def _dtype(numpy: ModuleType, info: FieldInfo) -> Any:
    letter = {"u": "u", "s": "i", "f": "f"}[info.type[0]]
    return numpy.dtype(f"<{letter}{info.size}")


def _numpy_columns(
    numpy: ModuleType, data: bytes | bytearray, starts: Any, cls: type[PayloadBase], fields: list[Scale]
) -> dict[str, Any]:
    buf = numpy.frombuffer(data, dtype=numpy.uint8)
    if len(buf) >= cls.SIZE:
        rows = numpy.lib.stride_tricks.sliding_window_view(buf, cls.SIZE)[starts + PAYLOAD_OFFSET]
    else:
        rows = numpy.zeros((0, cls.SIZE), dtype=numpy.uint8)
    layout = numpy.dtype(
        {
            "names": [info.name for info, _, _ in fields],
            "formats": [_dtype(numpy, info) for info, _, _ in fields],
            "offsets": [info.offset for info, _, _ in fields],
            "itemsize": cls.SIZE,
        }
    )
    records = numpy.ascontiguousarray(rows).view(layout).reshape(len(rows))
    result: dict[str, Any] = {}
    for info, multiplier, divisor in fields:
        wide = numpy.int64 if field_kind(info) == "integer" else numpy.float64
        value = records[info.name].astype(wide)
        if divisor is None:
            result[info.name] = value
            continue
        if multiplier != 1:
            value = value * multiplier
        result[info.name] = value / divisor if divisor != 1 else value.astype(numpy.float64)
    return result


_SENTENCE_VALUES: Final = PahrSentence().values()


def sentence_columns(numpy: ModuleType | None, sentences: list[PahrSentence]) -> dict[str, Any]:
    """The $PAHR sentences' `values()` as columns (float64 in engineering units, the USW int64)."""
    values = [sentence.values() for sentence in sentences]
    result: dict[str, Any] = {}
    for name, example in _SENTENCE_VALUES.items():
        column = [entry[name] for entry in values]
        code = "q" if isinstance(example, int) else "d"
        if numpy is not None:
            result[name] = numpy.array(column, dtype=numpy.int64 if code == "q" else numpy.float64)
        else:
            result[name] = array(code, column)
    return result
