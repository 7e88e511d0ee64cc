"""A capture as parts of a Parquet dataset: `write_capture(capture, out)` decodes one capture
(pcapng or raw dump) as `ilahrs decode --to csv` does and writes its rows as one Parquet file per
message kind, `out/kind=<kind>/part-<name>.parquet` (hive partitioning: the kind is the folder's,
not a column of the files). It is the map step of `ilahrs decode ... --to parquet` (ilahrs.cli.
to_parquet runs it once per capture, in processes) and of any engine that maps a function over
files, with every capture's parts named apart (`part_name`), so nothing needs to coordinate:

    from dask.distributed import Client
    from ilahrs.cli.dataset import DatasetOptions, write_capture
    client = Client()                                   # or a LocalCluster, or a real cluster
    futures = client.map(write_capture, captures, out=OUT, options=DatasetOptions())
    done = client.gather(futures)                       # one CaptureParts per capture

The rows are those of `--to csv`, decoded the same way (ColumnarCsv for a raw dump, ColumnarCapture
for pcapng, message by message for a raw dump with `--strict`) and read into Arrow columns by
pyarrow's CSV reader a few MiB at a time, so the dataset holds what the CSV holds: every message
and every damaged region (`kind=damaged`, with `reason` and `detail`). Columns, typed:

- `time`: timestamp (microseconds, UTC) when the row's last byte was recorded (null in a raw dump);
- `direction` (in, out), `offset`, `packet` (null in a raw dump), `length`;
- `reason`, `detail`: in the damaged kind only;
- the kind's fields in engineering units (float64; integers that have no scale, int64; the Unit
  Status Word as the names of its flags joined by '|', dates and a calibration's outcome as text,
  as in the CSV), or raw values with `raw` (int64, float64 for float32 fields, text for text);
- `source`: the capture's path, as given.

Each field column carries Arrow field metadata: `unit`, `icd_table` (as "Table 6.4"),
`icd_title` (the table's title), `icd_field` (the field's name in the ICD); with `raw`, `scale`
(the engineering value is raw * multiplier / divisor, in `unit`). Needs pyarrow (the parquet extra:
`pip install "./generated/python[parquet]"` from a checkout, or `pip install 'pyarrow>=14'`)."""

from __future__ import annotations

import hashlib
import importlib
import io
import os
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any, Final

from .. import nmea
from ..codec import field_kind
from ..nmea import PahrSentence
from ..payloads import PAYLOADS
from ..spec import SPEC_VERSION
from .capture import Source, open_source
from .capture_decoder import CaptureDecoder
from .columnar_capture import ColumnarCapture
from .columnar_csv import ColumnarCsv
from .common import SENTENCE_KIND, CliError, lookup, variant_named
from .rows import ACCURACY, BASE_COLUMNS, DAMAGED, RowWriter, decode_columns, kinds

__all__ = [
    "ARROW_MODULES",
    "EXTRA",
    "INSTALL",
    "CaptureParts",
    "DatasetOptions",
    "arrow",
    "kind_schema",
    "part_name",
    "write_capture",
]

EXTRA: Final = "parquet"
INSTALL: Final = "pip install 'pyarrow>=14'"
"""What the parquet extra installs (`pip install "./generated/python[parquet]"` from a checkout)."""
BATCH: Final = 8 << 20
"""CSV text decoded before it is read into Arrow columns and written (bytes)."""
SOURCE: Final = "source"
"""The column naming the capture."""
ARROW_MODULES: Final = ("pyarrow.compute", "pyarrow.csv", "pyarrow.parquet")
"""The pyarrow modules used (a fork server imports them once: ilahrs.cli.to_parquet)."""
_ENCODED_TEXT: Final = ("usw", "date", "calibration_success")
"""Field encodings written as text in engineering units (as in the CSV)."""
_SENTENCE_TABLE: Final = re.search(r"Table [0-9A-Z.]*[0-9]", nmea.__doc__ or "")


@dataclass(frozen=True)
class DatasetOptions:
    """How captures are decoded: the options of `ilahrs decode` of the same names."""

    kinds: tuple[str, ...] = ()
    """The kinds of rows kept (`--types`; empty: every kind)."""
    variant: str | None = None
    """The device variant for scaled rates (None: the first the spec lists)."""
    raw: bool = False
    output_format: str | None = None
    """The command that started the output, for a capture that begins with it."""
    strict: bool = False
    threads: bool = True
    """Let pyarrow use threads (off when several processes share the cores)."""


@dataclass(frozen=True)
class CaptureParts:
    """What `write_capture` wrote for one capture: the files (relative to the dataset's folder),
    the rows per kind, the messages decoded, the damaged rows, and the error that cut the capture
    short (its rows before it are written), if any."""

    capture: str
    parts: tuple[str, ...] = ()
    rows: dict[str, int] = field(default_factory=dict)
    messages: int = 0
    damaged: int = 0
    error: str | None = None


def arrow() -> tuple[ModuleType, ModuleType, ModuleType, ModuleType]:
    """pyarrow, pyarrow.compute, pyarrow.csv and pyarrow.parquet; CliError naming the extra when
    pyarrow is not installed."""
    try:  # optional: the parquet extra (untyped: imported by name)
        found = [importlib.import_module(name) for name in ("pyarrow", *ARROW_MODULES)]
    except ImportError:
        raise CliError(f"--to parquet needs pyarrow, the {EXTRA} extra: {INSTALL}") from None
    return found[0], found[1], found[2], found[3]


def part_name(capture: str) -> str:
    """The file name of a capture's part in each kind's folder: its base name (letters, digits,
    '.', '_' and '-' kept) and 8 hex digits of the SHA-256 of its path, so that two captures of
    the same name in different folders do not meet."""
    base = os.path.basename(capture)
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", os.path.splitext(base)[0]) or "capture"
    digest = hashlib.sha256(os.path.normpath(capture).encode()).hexdigest()[:8]
    return f"part-{stem}-{digest}.parquet"


def _meta(**items: object) -> dict[bytes, bytes]:
    return {key.encode(): str(value).encode() for key, value in items.items() if value not in (None, "")}


def _field_columns(pa: ModuleType, kind: str, variant: str | None, raw: bool) -> list[Any]:
    """The Arrow fields of a kind's own columns, in the order of the CSV's."""
    if kind == SENTENCE_KIND:
        table = _SENTENCE_TABLE.group(0) if _SENTENCE_TABLE else None
        result = []
        for name, form, _width, decimals, _low, _high, unit in PahrSentence._SPEC:
            kind_type = pa.int64() if raw else pa.string() if name == "usw" else pa.float64()
            scale = f"1/{10**decimals}" if raw and form == "decimal" else None
            meta = _meta(
                unit=unit, icd_table=table, icd_title=f"${SENTENCE_KIND} sentence", icd_field=name, scale=scale
            )
            result.append(pa.field(name, kind_type, metadata=meta))
        return result
    if kind not in PAYLOADS:
        return []
    cls = PAYLOADS[kind]
    scaled = set(cls().values(variant_named(variant)))
    result = []
    for info in cls.FIELDS:
        if info.type == "reserved":
            continue
        what = field_kind(info)
        if what == "char":
            kind_type = pa.string()
        elif raw:
            kind_type = pa.int64() if what == "integer" else pa.float64()
        elif info.encoding in _ENCODED_TEXT:
            kind_type = pa.string()
        else:
            kind_type = pa.float64() if info.name in scaled or what == "float" else pa.int64()
        divisor = info.divisor if isinstance(info.divisor, int) else f"{info.divisor} of the variant"
        scale = f"{info.multiplier}/{divisor}" if raw and info.name in scaled else None
        meta = _meta(
            unit=info.unit,
            icd_table=cls.ICD,
            icd_title=cls.TITLE,
            icd_field=info.icd_name,
            scale=scale,
            encoding=info.encoding,
        )
        result.append(pa.field(info.name, kind_type, metadata=meta))
        if info.encoding == "calibration_success":
            note = "predicted accuracy (3 sigma) of a successful calibration"
            meta = _meta(unit="deg", icd_table=cls.ICD, icd_title=cls.TITLE, icd_field=info.icd_name, description=note)
            result.append(pa.field(ACCURACY, pa.float64(), metadata=meta))
    return result


def kind_schema(kind: str, *, variant: str | None = None, raw: bool = False) -> Any:
    """The Arrow schema of the files of `kind` (a pyarrow.Schema): the shared columns, the kind's
    fields with their metadata, `source`."""
    pa = arrow()[0]
    note = {
        "time": "when the row's last byte was recorded",
        "direction": "in: device to host, out: host to device",
        "offset": "of the row's first byte in the bytes of its direction",
        "packet": "the pcapng packet holding the row's last byte, from 1",
        "length": "bytes",
        "reason": "why the bytes are no message",
        "detail": "the damage in words",
    }
    types = {"time": pa.timestamp("us", tz="UTC"), "direction": pa.string(), "reason": pa.string()}
    types.update(detail=pa.string())
    fields = [
        pa.field(name, types.get(name, pa.int64()), metadata=_meta(description=note[name]))
        for name in BASE_COLUMNS
        if name != "kind" and (kind == DAMAGED or name not in ("reason", "detail"))
    ]
    fields += _field_columns(pa, kind, variant, raw)
    fields.append(pa.field(SOURCE, pa.string(), metadata=_meta(description="the capture's path")))
    meta = _meta(kind=kind, ilahrs=SPEC_VERSION, variant=variant_named(variant).name, raw=raw)
    return pa.schema(fields, metadata=meta)


class _Parts:
    """Rows of `--to csv` text in, a Parquet file per kind out (opened at the kind's first row)."""

    def __init__(self, capture: str, out: str, options: DatasetOptions, columns: list[str]) -> None:
        self.pa, self.pc, self.csv, self.pq = arrow()
        self.capture = capture
        self.out = out
        self.options = options
        self.columns = columns
        self.name = part_name(capture)
        self.writers: dict[str, Any] = {}
        self.schemas: dict[str, Any] = {}
        self.rows: dict[str, int] = {}
        self.header = True

    def add(self, text: str, start: float | None) -> None:
        """The CSV rows `text` (the header first, in the first call); `start`: the capture's first
        timestamp (seconds since the epoch; None for a raw dump)."""
        if not text:
            return
        pa, pc, csv = self.pa, self.pc, self.csv
        read = csv.ReadOptions(
            column_names=self.columns, skip_rows=1 if self.header else 0, use_threads=self.options.threads
        )
        self.header = False
        convert = csv.ConvertOptions(
            column_types=dict.fromkeys(self.columns, pa.string()),
            null_values=[""],  # the CSV's None; "nan" is a float, "NA" may be a device's text
            strings_can_be_null=True,
            quoted_strings_can_be_null=False,
        )
        table = csv.read_csv(
            io.BytesIO(text.encode()),
            read_options=read,
            convert_options=convert,
            parse_options=csv.ParseOptions(newlines_in_values=True),
        )
        if not table.num_rows:
            return
        kind_column = table.column("kind")
        for kind in pc.unique(kind_column).to_pylist():
            self._write(kind, table.filter(pc.equal(kind_column, kind)), start)

    def _write(self, kind: str, rows: Any, start: float | None) -> None:
        pa, pc = self.pa, self.pc
        schema = self.schemas.get(kind)
        if schema is None:
            schema = self.schemas[kind] = kind_schema(kind, variant=self.options.variant, raw=self.options.raw)
            folder = os.path.join(self.out, f"kind={kind}")
            os.makedirs(folder, exist_ok=True)
            self.writers[kind] = self.pq.ParquetWriter(os.path.join(folder, self.name), schema, compression="zstd")
        arrays = []
        for column in schema:
            if column.name == SOURCE:
                arrays.append(pa.array([self.capture] * rows.num_rows, pa.string()))
            elif column.name == "time":
                seconds = pc.cast(rows.column("time"), pa.float64())
                micros = pc.cast(pc.round(pc.multiply(seconds, 1_000_000)), pa.int64())
                if start is not None:
                    micros = pc.add(micros, round(start * 1_000_000))
                arrays.append(pc.cast(micros, column.type))
            else:
                arrays.append(pc.cast(rows.column(column.name), column.type))
        self.writers[kind].write_table(pa.Table.from_arrays(arrays, schema=schema))
        self.rows[kind] = self.rows.get(kind, 0) + rows.num_rows

    def close(self) -> tuple[str, ...]:
        for writer in self.writers.values():
            writer.close()
        return tuple(f"kind={kind}/{self.name}" for kind in self.writers)


@dataclass
class _Decoding:
    """A capture's decoder as `ilahrs decode --to csv` chooses it, writing CSV rows to `text`:
    `feed` each of `pieces`, then `finish`; `start()` is the capture's first timestamp."""

    decoder: ColumnarCsv | ColumnarCapture | CaptureDecoder
    feed: Callable[[Any], None]
    finish: Callable[[], None]
    pieces: Iterator[Any]
    start: Callable[[], float | None] = lambda: None

    @classmethod
    def of(cls, source: Source, text: io.StringIO, options: DatasetOptions, selected: list[str]) -> _Decoding:
        variant = variant_named(options.variant)
        table = None
        if options.output_format is not None:
            from .decode import output_table  # decode finds this module's exports: imported when used

            table = output_table(options.output_format)
        known = options.output_format is not None
        if source.kind == "pcapng":
            columnar = ColumnarCapture(
                text,
                selected,
                variant,
                raw=options.raw,
                output=table,
                output_known=known,
                strict=options.strict,
                start=options.output_format,
            )
            found = columnar.decoder
            return cls(columnar, columnar.feed_packets, columnar.finish, source.packets(), lambda: found.start)
        if not options.strict:
            dump = ColumnarCsv(text, selected, variant, raw=options.raw, output=table)
            return cls(dump, lambda chunk: dump.feed(chunk.data), dump.finish, source.chunks())
        messages = CaptureDecoder(
            context=False, output=table, output_known=known, strict=True, start=options.output_format
        )
        writer = RowWriter(text, "csv", selected, variant, raw=options.raw)
        feed, finish = messages.writing(writer.write, selected)
        return cls(messages, feed, finish, source.chunks())


def write_capture(capture: str, out: str, options: DatasetOptions | None = None) -> CaptureParts:
    """Decode the capture at path `capture` into parts of the dataset at folder `out` (created if
    missing): a file per kind found, `out/kind=<kind>/<part_name(capture)>`, replaced if there.
    A capture that cannot be read, or is cut short, is CaptureParts.error (with the rows before
    the damage written); CliError for options that are not valid or pyarrow missing."""
    options = options or DatasetOptions()
    valid = kinds()
    selected = [lookup("message kind", k, valid) for k in options.kinds] or valid
    parts = _Parts(capture, out, options, [*BASE_COLUMNS, *decode_columns(selected)])
    try:
        source = open_source(capture)
    except CliError as exc:
        return CaptureParts(capture, error=str(exc))
    text = io.StringIO()
    error = None
    try:
        run = _Decoding.of(source, text, options, selected)

        def flush() -> None:
            parts.add(text.getvalue(), run.start())
            text.seek(0)
            text.truncate()

        try:
            for piece in run.pieces:
                run.feed(piece)
                if text.tell() >= BATCH:
                    flush()
        except CliError as exc:
            error = str(exc)
        run.finish()
        flush()
    finally:
        source.close()
        written = parts.close()
    counts = run.decoder
    return CaptureParts(capture, written, parts.rows, sum(counts.counts.values()), sum(counts.damage.values()), error)
