# Copied from generator/targets/python/runtime/cli/columnar_capture.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ColumnarCapture`: the CSV rows of a two-direction pcapng capture, the device's continuous
output decoded a stretch at a time as columns, everything else message by message
(`CaptureDecoder`)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from typing import Any, Final, TextIO

from ..columnar import KINDS, Scanner, numpy_for
from ..encodings import Variant
from ..frame import MessageType
from ..payloads import PAYLOADS
from ..pcapng import Direction, Packets
from ..stream import IDLE_TIMEOUT
from .capture import Chunk
from .capture_decoder import CaptureDecoder, Run
from .columnar_csv import Values
from .damage import Regions
from .rows import BASE_COLUMNS, Message, RowWriter, csv_text, decode_columns

__all__ = ["ColumnarCapture"]


_STRETCH: Final = 1 << 20
"""Bytes of the device's output held before they are decoded as columns."""


class ColumnarCapture:
    """The CSV rows of a pcapng capture (both directions) as RowWriter writes those of
    CaptureDecoder(context=True), and its summary, with the device's continuous output decoded as
    columns. The CaptureDecoder follows the commands and every other message; while its host
    waits for nothing but the output its state streams (`Host.streaming`), the device's chunks
    are held (up to _STRETCH bytes, until a chunk from the host or an idle line) and decoded at
    once: the longest run of them whose bytes are whole output frames, back to back, ending with a
    chunk, and in which no deadline passes (`Host.streamed`). Whatever else the run holds (damage,
    another message, a frame across its end, a late output) goes message by message: the rows are
    those of CaptureDecoder either way. Needs numpy (else every chunk goes message by message)."""

    def __init__(
        self,
        out: TextIO,
        selected: Iterable[str],
        variant: Variant,
        *,
        raw: bool,
        output: str | None = None,
        output_known: bool = False,
        strict: bool = False,
        start: str | None = None,
    ) -> None:
        self.decoder = CaptureDecoder(
            context=True, output=output, output_known=output_known, strict=strict, start=start
        )
        self._numpy = numpy_for("auto")
        self._strict = strict
        self._wanted = set(selected)
        self._writer = RowWriter(out, "csv", self._wanted, variant, raw=raw)
        self._columns = [*BASE_COLUMNS, *decode_columns(self._wanted)]
        self._out = out
        self._values = Values(self._numpy, variant, raw)
        self._held = Run()
        self._last_in: float | None = None
        self._misses = 0

    @property
    def counts(self) -> Counter[str]:
        return self.decoder.counts

    @property
    def damage(self) -> Counter[str]:
        return self.decoder.damage

    @property
    def regions(self) -> Regions:
        return self.decoder.regions

    @property
    def errors(self) -> list[str]:
        return self.decoder.errors

    @property
    def discarded(self) -> int:
        return self.decoder.discarded

    def feed(self, chunk: Chunk) -> None:
        inbound = chunk.direction == Direction.INBOUND and chunk.time is not None
        self._packet(chunk.time, inbound, chunk.data, chunk)

    def feed_packets(self, found: Packets) -> None:
        """`feed` of each of the packets `found` (directions INBOUND or OUTBOUND, numbered from
        found.first, as `Source.packets` gives them), with no object made for the packets the
        columns decode."""
        data, ends, stamps, directions = found.data, found.ends, found.stamps, found.directions
        number = found.first
        start = index = 0
        count = len(ends)
        inbound = Direction.INBOUND
        numpy = self._numpy
        arrays = (numpy.frombuffer(ends, numpy.int64), numpy.frombuffer(stamps, numpy.int64)) if numpy else None
        while index < count:
            end = ends[index]
            if self._held.sizes and self._last_in is not None and directions[index] == inbound:
                assert arrays is not None  # only numpy holds packets
                index = self._held_packets(found, arrays, index)
                if index == count:
                    break
                start = ends[index - 1] if index else 0
                end = ends[index]
            when = stamps[index] / 1_000_000
            self._packet(when, directions[index] == inbound, data[start:end], None, number + index)
            start = end
            index += 1

    def _held_packets(self, found: Packets, arrays: tuple[Any, Any], index: int) -> int:
        """`_packet` of the packets from `index` on while held ones are (numpy): each from the
        device is held while the held ones are less than _STRETCH bytes and the line was not idle
        before it (the same rule, decided for the packets at once). Where the packets held end."""
        numpy = self._numpy
        assert numpy is not None  # only numpy holds packets
        data, directions, number = found.data, found.directions, found.first
        ends, stamps = arrays  # found.ends and found.stamps
        held, last = self._held, self._last_in
        origin = self.decoder.start
        assert origin is not None and last is not None
        stop = directions.find(bytes([Direction.OUTBOUND]), index)
        stop = len(directions) if stop < 0 else stop
        high = ends[index:stop]
        low = numpy.concatenate((ends[index - 1 : index] if index else [0], high[:-1]))
        sizes = high - low
        when = stamps[index:stop] / 1_000_000
        steps = numpy.arange(len(sizes))
        latest = numpy.maximum.accumulate(numpy.where(sizes > 0, steps, -1))  # the last packet with bytes
        before = numpy.concatenate(([-1], latest[:-1]))
        previous = numpy.where(before >= 0, when[before], last)
        total = held.total + numpy.concatenate(([0], numpy.cumsum(sizes)[:-1]))
        ends_run = (total >= _STRETCH) | ((when - origin) - (previous - origin) >= IDLE_TIMEOUT)
        taken = int(numpy.argmax(ends_run)) if ends_run.any() else len(sizes)
        if taken:
            held.pieces.append(data[int(low[0]) : int(high[taken - 1])])
            held.sizes += sizes[:taken].tolist()
            held.times += when[:taken].tolist()
            held.packets += range(number + index, number + index + taken)
            held.total = int(total[taken - 1] + sizes[taken - 1])
            if latest[taken - 1] >= 0:
                self._last_in = float(when[latest[taken - 1]])
        return index + taken

    def _packet(
        self, when: float | None, inbound: bool, data: bytes, chunk: Chunk | None, number: int | None = None
    ) -> None:
        held = self._held
        if held.sizes:
            if inbound and held.total < _STRETCH and not self._idle(when):
                self._hold(when, data, chunk.packet if chunk is not None else number)
                return
            self._flush()
        if inbound and self._numpy is not None and self._streaming() is not None and not self._idle(when):
            self._hold(when, data, chunk.packet if chunk is not None else number)
            return
        if chunk is None:
            chunk = Chunk(when, Direction.INBOUND if inbound else Direction.OUTBOUND, data, number)
        self._write(self.decoder.feed(chunk))

    def finish(self) -> None:
        self._flush()
        self._write(self.decoder.finish())

    def _hold(self, when: float | None, data: bytes, packet: int | None) -> None:
        assert when is not None
        self._held.add(when, data, packet)
        if data:
            self._last_in = when

    def _idle(self, when: float | None) -> bool:
        """Whether the device's line was idle before a chunk at `when` (E41): a message cannot span it."""
        decoder = self.decoder
        last = self._last_in if self._held.sizes else None
        if last is None or decoder.start is None:
            return decoder.in_idle(when)
        assert when is not None
        return (when - decoder.start) - (last - decoder.start) >= IDLE_TIMEOUT

    def _write(self, messages: list[Message]) -> None:
        wanted = self._wanted
        for message in messages:
            if message.kind in wanted:
                self._writer.write(message)

    def _streaming(self) -> str | None:
        return self.decoder.streaming()

    def _flush(self) -> None:
        held, self._held, self._last_in = self._held, Run(), None
        while held.sizes:
            done = self._columnar(held)
            if done:
                self._misses = 0
                held = held.after(done)
                continue
            self._misses += 1
            slow = min(len(held.sizes), 1 << min(self._misses, 12))  # damage: fewer rescans of the same bytes
            for chunk in held.chunks(slow):
                self._write(self.decoder.feed(chunk))
            held = held.after(slow)

    def _columnar(self, held: Run) -> int:
        """Decode the leading chunks of `held` as columns, if they are whole output frames that
        arrive in time; how many chunks were decoded (0: none)."""
        decoder = self.decoder
        numpy = self._numpy
        table = decoder.streaming()
        if table is None or numpy is None:
            return 0
        cls = PAYLOADS[table]
        data = held.joined()
        scanner = Scanner(numpy, sentences=False, output=table, strict=self._strict)
        windows = scanner.scan(data, final=True)
        if not windows:
            return 0
        starts = numpy.concatenate([w.starts for w in windows])
        lengths = numpy.concatenate([w.lengths for w in windows])
        types = numpy.concatenate([w.types for w in windows])
        ends = starts + lengths
        kinds = numpy.concatenate([w.kinds for w in windows])
        good = (types == int(MessageType.DATA)) & (kinds == KINDS.index(table))
        good[1:] &= starts[1:] == ends[:-1]
        if len(starts):
            good[0] &= int(starts[0]) == 0
        bad = numpy.flatnonzero(~good)
        count = int(bad[0]) if len(bad) else len(starts)
        if not count:
            return 0
        chunk_ends = numpy.cumsum(numpy.array(held.sizes, dtype=numpy.int64))
        aligned = numpy.flatnonzero(numpy.isin(chunk_ends, ends[:count]) & (chunk_ends > 0))
        if not len(aligned):
            return 0
        used = int(aligned[-1]) + 1
        arrived = numpy.searchsorted(chunk_ends, ends[:count] - 1, side="right")
        per_chunk = numpy.bincount(arrived, minlength=used)[:used].tolist()
        steps = decoder.steps(held.times[:used], numpy)
        used = decoder.stream(steps, per_chunk, apply=False)
        aligned = aligned[aligned < used]
        if not len(aligned):
            return 0
        used = int(aligned[-1]) + 1
        total = int(chunk_ends[used - 1])
        count = int(numpy.searchsorted(ends[:count], total, side="right"))
        base = decoder.inbound_bytes
        taken = held.first(used)
        decoder.stream(steps[:used], per_chunk[:used], apply=True)
        decoder.streamed(taken, table, count, total)
        if table in self._wanted:
            found = {"starts": starts[:count], "lengths": lengths[:count], "arrived": arrived[:count]}
            self._rows(data, taken, **found, cls=cls, base=base)
        return used

    def _rows(
        self, data: bytes, taken: Run, *, starts: Any, lengths: Any, arrived: Any, cls: type[Any], base: int
    ) -> None:
        """The CSV rows of the output frames at `starts` in `data` (the bytes of `taken`, from
        `base` in the device's bytes), each in the chunk `arrived` says."""
        numpy = self._numpy
        start = self.decoder.start
        assert start is not None and numpy is not None
        times, packets = taken.times, taken.packets
        stamps = _stamps(numpy, numpy.array(times, dtype=numpy.float64) - start)
        numbers = list(map(str, packets)) if None not in packets else list(map(csv_text, packets))
        if len(arrived) == len(times) and (len(times) < 2 or bool((numpy.diff(arrived) == 1).all())):
            pass  # a frame per chunk, in order (arrived is 0, 1, ...): the chunks' columns are the rows'
        else:
            at = arrived.tolist()
            stamps, numbers = list(map(stamps.__getitem__, at)), list(map(numbers.__getitem__, at))
        local = starts.tolist()
        values = self._values.texts(data, cls, local)
        sizes = lengths.tolist()
        same = len(set(sizes)) == 1
        # A row is its values and constant fields joined by commas; each run of constant fields is
        # one item (repeated), so each row joins few items.
        layout: list[Any] = [stamps, "in", csv_text(cls.NAME), list(map(str, (starts + base).tolist())), numbers]
        layout += [str(sizes[0]) if same else list(map(str, sizes)), "", ""]
        for name in self._columns[len(BASE_COLUMNS) :]:
            layout.append(values.get(name, ""))
        items: list[Any] = []
        for item in layout:
            if isinstance(item, str) and items and isinstance(items[-1], str):
                items[-1] += "," + item
            else:
                items.append(item)
        count = len(local)
        if count:
            rows = zip(*([item] * count if isinstance(item, str) else item for item in items), strict=True)
            self._out.write("\n".join(map(",".join, rows)) + "\n")


def _stamps(numpy: Any, seconds: Any) -> list[str]:
    """The `time` values of RowWriter, f"{round(t, 6):.6f}", of the float64 `seconds`: "%.6f" of the
    value itself, which is the same text while a millionth is more than a float's step at that
    magnitude (below 2**32 s); RowWriter's expression otherwise."""
    values: list[float] = seconds.tolist()
    if not len(seconds) or float(numpy.abs(seconds).max()) < 2.0**32:
        return list(map("%.6f".__mod__, values))
    return [f"{round(t, 6):.6f}" for t in values]
