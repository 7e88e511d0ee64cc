# Copied from generator/targets/python/runtime/cli/columnar_csv.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ColumnarCsv`: the CSV rows of a raw dump decoded a window at a time into columns
(ilahrs.columnar), and `Values`, the CSV values of one table's fields decoded as columns, as
`row_fields` gives them."""

from __future__ import annotations

import csv
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from typing import Any, TextIO

from ..codec import FieldInfo, field_kind
from ..columnar import (
    COMMAND,
    KINDS,
    SENTENCE,
    UNEXPLAINED,
    Scale,
    Scanner,
    Window,
    numpy_for,
    scales,
    table_columns,
)
from ..encodings import Variant
from ..frame import PAYLOAD_OFFSET
from ..payloads import PAYLOADS
from ..statemachine import INITIAL
from .damage import REASONS, Damage, Regions
from .rows import (
    ACCURACY,
    BASE_COLUMNS,
    DAMAGED,
    UNDETERMINED,
    accuracy_value,
    command_name,
    csv_text,
    decode_columns,
    outcome_value,
    row_fields,
    usw_value,
)

__all__ = ["ColumnarCsv", "Values"]


class ColumnarCsv:
    """The CSV rows of a raw dump (device-to-host bytes, no context) as RowWriter writes those of
    CaptureDecoder(context=False), and its summary (`counts`, `damage`, `regions`, `discarded`,
    `errors`), decoded a window at a time into columns. `feed` bytes, then `finish`."""

    def __init__(
        self, out: TextIO, selected: Iterable[str], variant: Variant, *, raw: bool, output: str | None = None
    ) -> None:
        self._numpy = numpy_for("auto")
        self._scanner = Scanner(self._numpy, output=output)
        self._variant = variant
        self._raw = raw
        self._wanted = set(selected)
        self._columns = [*BASE_COLUMNS, *decode_columns(self._wanted)]
        self._csv = csv.writer(out, lineterminator="\n")
        self._csv.writerow(self._columns)
        self._blank = ("",) * (len(self._columns) - len(BASE_COLUMNS))
        self._pending: bytes = b""
        self._end = 0
        self._damage = Damage()
        self.discarded = 0
        self.counts: Counter[str] = Counter()
        self.damage: Counter[str] = Counter()
        """Damaged rows by reason."""
        self.regions = Regions()
        self.errors: list[str] = []
        self._values = Values(self._numpy, variant, raw)

    def feed(self, data: bytes) -> None:
        buffer = self._pending + data if self._pending else data
        base = self._scanner.base
        for window in self._scanner.scan(buffer, final=False):
            self._window(window)
        self._discard(buffer, base)
        self._csv.writerows(row for _, row in self._damaged())
        self._pending = buffer[self._scanner.decided :]

    def finish(self) -> None:
        base = self._scanner.base
        for window in self._scanner.scan(self._pending, final=True):
            self._window(window)
        self._discard(self._pending, base)
        self._damage.close()
        self._csv.writerows(row for _, row in self._damaged())
        self._pending = b""

    def _discard(self, buffer: bytes, base: int) -> None:
        """The bytes decided after the last message (`buffer` starts at `base`) are damage."""
        total = self._scanner.base
        if total > self._end:
            self._gap(buffer, base, self._end, total)
            self._end = total

    def _gap(self, data: bytes | bytearray, base: int, start: int, end: int) -> None:
        self.discarded += end - start
        self._damage.add(start, memoryview(data)[start - base : end - base])

    def _damaged(self) -> list[tuple[int, Sequence[Any]]]:
        """The damaged rows decided so far, by offset."""
        rows: list[tuple[int, Sequence[Any]]] = []
        for at, raw, reason in self._damage.take():
            self.damage[reason] += 1
            self.regions.add("in", at, len(raw), reason)
            if DAMAGED in self._wanted:
                detail = f"{len(raw)} bytes: {REASONS[reason]}"
                rows.append((at, ("", "in", DAMAGED, at, "", len(raw), reason, detail, *self._blank)))
        return rows

    def _window(self, window: Window) -> None:
        starts = window.starts.tolist() if self._numpy is not None else window.starts
        lengths = window.lengths.tolist() if self._numpy is not None else window.lengths
        self._gaps(window, starts, lengths)
        parts: list[tuple[list[int], Iterable[Sequence[Any]]]] = []
        seen: dict[str, list[int]] = {}
        errors: list[tuple[int, str]] = []
        for code, positions in window.groups().items():
            places = positions.tolist() if self._numpy is not None else positions
            if code in (COMMAND, UNEXPLAINED):
                names = [self._frame_kind(window, starts[i], lengths[i], code) for i in places]
                chosen: list[tuple[int, str]] = []
                for i, name in zip(places, names, strict=True):
                    seen.setdefault(name, [i, 0])[1] += 1
                    if name == UNDETERMINED:
                        errors.append(
                            (i, f"in offset {starts[i]}: a {lengths[i]}-byte frame no table in context explains")
                        )
                    if name in self._wanted:
                        chosen.append((i, name))
                if chosen:
                    made = [("", "in", name, starts[i], "", lengths[i], "", "", *self._blank) for i, name in chosen]
                    parts.append(([starts[i] for i, _ in chosen], made))
                continue
            name = KINDS[code]
            seen[name] = [places[0], len(places)]
            if name in self._wanted:
                at = [starts[i] for i in places]
                parts.append((at, self._rows(window, code, name, at, [lengths[i] for i in places])))
        for name, (_first, count) in sorted(seen.items(), key=lambda item: item[1][0]):
            self.counts[name] += count
        self.errors += [text for _, text in sorted(errors)]
        damaged = self._damaged()
        if len(parts) == 1 and not damaged:
            self._csv.writerows(parts[0][1])
        elif parts or damaged:
            ordered = [(at, row) for places, rows in parts for at, row in zip(places, rows, strict=True)]
            ordered.sort(key=lambda item: item[0])
            self._csv.writerows(row for _, row in sorted([*ordered, *damaged], key=lambda item: item[0]))

    def _gaps(self, window: Window, starts: list[int], lengths: list[int]) -> None:
        """The bytes between the messages of `window` are damage: each run ends at a message."""
        end = self._end
        damage = self._damage
        for start, length in zip(starts, lengths, strict=True):
            if start > end:
                self._gap(window.data, window.base, end, start)
            if damage.held:
                damage.close()
            end = start + length
        self._end = end

    @staticmethod
    def _frame_kind(window: Window, start: int, length: int, code: int) -> str:
        if code == UNEXPLAINED:
            return UNDETERMINED
        at = start - window.base
        return command_name(bytes(window.data[at : at + length]), INITIAL)

    def _rows(
        self, window: Window, code: int, name: str, starts: list[int], lengths: list[int]
    ) -> Iterable[Sequence[Any]]:
        """The CSV rows of the messages of kind `code` starting at `starts`."""
        count = len(starts)
        if code == SENTENCE:
            made = [row_fields(window.sentences[at], self._variant, raw=self._raw) for at in starts]
            names = made[0] if made else {}
            values = {column: [row[column] for row in made] for column in names}
        else:
            values = self._table_values(window, PAYLOADS[name], starts)
        blank = [""] * count
        base = [blank, ["in"] * count, [name] * count, starts, blank, lengths, blank, blank]
        return zip(*base, *(values.get(c, blank) for c in self._columns[len(BASE_COLUMNS) :]), strict=True)

    def _table_values(self, window: Window, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        return self._values.of(window.data, window.base, cls, starts)


class Values:
    """The CSV values of the fields of frames of one table, decoded as columns, as row_fields
    gives them (each distinct USW or calibration byte turned into text once)."""

    def __init__(self, numpy: Any, variant: Variant, raw: bool) -> None:
        self._numpy = numpy
        self._variant = variant
        self._raw = raw
        self._known: dict[Callable[[Any], object], dict[Any, object]] = {}
        self._tables: dict[tuple[str, str], tuple[int, Any, Any]] = {}

    def of(self, data: bytes | bytearray, base: int, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        """Each column's values for the frames of table `cls` at `starts` (`data` starts at `base`)."""
        if not _simple(cls):
            here = [at - base + PAYLOAD_OFFSET for at in starts]
            blocks = [cls.parse(data[at : at + cls.SIZE]) for at in here]
            made = [row_fields(block, self._variant, raw=self._raw) for block in blocks]
            return {column: [row[column] for row in made] for column in made[0]} if made else {}
        fields = scales(cls, self._variant)  # every field, also with --raw
        if self._raw:
            fields = [(info, 1, None) for info, _, _ in fields]
        local = [at - base for at in starts]
        offsets = self._numpy.array(local, dtype=self._numpy.int64) if self._numpy is not None else local
        columns = table_columns(self._numpy, data, offsets, cls, fields)
        values: dict[str, list[Any]] = {}
        for info, _, _ in fields:
            column = columns[info.name].tolist()
            if info.encoding == "calibration_success":
                raw = self._raw
                values[ACCURACY] = [None] * len(column) if raw else self._mapped(column, accuracy_value)
                column = column if raw else self._mapped(column, outcome_value)
            elif not self._raw and info.encoding == "usw":
                column = self._mapped(column, usw_value)
            values[info.name] = column
        return values

    def texts(self, data: bytes | bytearray, cls: type[Any], starts: list[int]) -> dict[str, list[Any]]:
        """`of` (`data` from 0) as csv.writer writes the values (`csv_text`), each distinct
        value of a column written once (numpy; else as `of`)."""
        numpy = self._numpy
        if numpy is None or not _simple(cls):
            return {name: list(map(csv_text, column)) for name, column in self.of(data, 0, cls, starts).items()}
        fields = scales(cls, self._variant)  # every field, also with --raw
        if self._raw:
            fields = [(info, 1, None) for info, _, _ in fields]
        offsets = numpy.array(starts, dtype=numpy.int64)
        tabled = [field for field in fields if _tabled(field[0])]
        sent = table_columns(numpy, data, offsets, cls, [(info, 1, None) for info, _, _ in tabled])
        others = [field for field in fields if not _tabled(field[0])]
        columns = table_columns(numpy, data, offsets, cls, others) if others else {}
        values: dict[str, list[Any]] = {}
        for info, multiplier, divisor in fields:
            if _tabled(info):
                values[info.name] = self._tabled(cls, (info, multiplier, divisor), sent[info.name])
                continue
            distinct, where = numpy.unique(columns[info.name], return_inverse=True)
            known = distinct.tolist()
            if info.encoding == "calibration_success" and not self._raw:
                values[ACCURACY] = _spread(numpy, [csv_text(accuracy_value(v)) for v in known], where)
                values[info.name] = _spread(numpy, [csv_text(outcome_value(v)) for v in known], where)
                continue
            if info.encoding == "calibration_success":
                values[ACCURACY] = [""] * len(starts)
            if info.encoding == "usw" and not self._raw:
                values[info.name] = _spread(numpy, [csv_text(usw_value(v)) for v in known], where)
            else:
                values[info.name] = _spread(numpy, [str(v) for v in known], where)
        return values

    def _tabled(self, cls: type[Any], field: Scale, sent: Any) -> list[str]:
        """The texts of a column of an integer field of at most 16 bits (`sent`: the values as
        sent, int64), each value's text made once and kept in a table indexed by the value."""
        numpy = self._numpy
        info, multiplier, divisor = field
        key = (cls.NAME, info.name)
        if key not in self._tables:
            bits = 8 * info.size
            low = -(1 << (bits - 1)) if info.type.startswith("s") else 0
            self._tables[key] = (low, numpy.full(1 << bits, None, dtype=object), numpy.zeros(1 << bits, dtype=bool))
        low, texts, made = self._tables[key]
        index = sent - low
        fresh = index[~made[index]]
        if len(fresh):
            fresh = numpy.unique(fresh)
            value = fresh + low  # then as table_columns scales it
            if divisor is not None:
                if multiplier != 1:
                    value = value * multiplier
                value = value / divisor if divisor != 1 else value.astype(numpy.float64)
            if info.encoding == "usw" and not self._raw:
                made_texts = [csv_text(usw_value(v)) for v in value.tolist()]
            else:
                made_texts = list(map(str, value.tolist()))
            texts[fresh] = numpy.array(made_texts, dtype=object)
            made[fresh] = True
        result: list[str] = texts[index].tolist()
        return result

    def _mapped(self, column: list[Any], function: Callable[[Any], object]) -> list[Any]:
        """`function` of each value, each distinct value computed once."""
        known = self._known.setdefault(function, {})
        known.update((value, function(value)) for value in set(column).difference(known))
        return list(map(known.__getitem__, column))


def _simple(cls: type[Any]) -> bool:
    """Whether the fields of `cls` are numbers with no encoding but the USW's and a calibration's."""
    simple = all(info.type == "reserved" or field_kind(info) in ("integer", "float") for info in cls.FIELDS)
    return simple and all(info.encoding in (None, "usw", "calibration_success") for info in cls.FIELDS)


def _tabled(info: FieldInfo) -> bool:
    """Whether a field's texts are kept in a table by value (`Values._tabled`): an integer of at
    most 16 bits, not a calibration's success (two columns)."""
    return info.type[0] in "us" and info.size <= 2 and info.encoding in (None, "usw")


def _spread(numpy: Any, texts: list[str], where: Any) -> list[str]:
    """texts[i] for each i in `where`."""
    result: list[str] = numpy.array(texts, dtype=object)[where].tolist()
    return result
