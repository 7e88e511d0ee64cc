"""`ilahrs decode`: a capture as one row per message, in text, CSV or JSON lines.

Messages are told apart by context, as the host session does. With both directions recorded
(pcapng), the commands in the capture drive a `Host`, so the 50- and 52-byte blocks and the three
34-byte output layouts are decoded as the table the device was asked for. With device-to-host
bytes only (a raw dump), `--output-format` names the command that started the output; other
frames are decoded when their size fits one table only, and are of kind "frame" otherwise.

Output goes to standard output, or with `--to FORMAT PATH` to a file written whole and renamed
onto PATH (a capture cut short still leaves the rows before the damage there, and the error).
Formats whose libraries write files of their own (a ROS 2 bag, a Parquet dataset) are the `to_*`
modules beside this one (`ilahrs.cli.exports`).

A raw dump written as CSV goes the columnar way (`ColumnarCsv`, `ilahrs.columnar`): a window of
the capture at a time, its frames found and decoded into columns (numpy when installed, else the
standard library's array), then written row by row, the same rows as message by message.

Rows: `time` (seconds since the first chunk of the capture, when the row's last byte was
recorded; empty in a raw dump), `direction` (in: device to host, out: host to device), `kind` (a
payload table's name, a command's name, PAHR for a $PAHR sentence, frame for a frame whose table
cannot be told, damaged for damage), `offset` (of the row's first byte in the bytes of its
direction), `packet` (the pcapng packet holding its last byte, from 1; empty in a raw dump),
`length` (bytes), `reason` and `detail` (damaged rows only), then every field in engineering units
(raw values with `--raw`): the Unit Status Word as the names of its flags joined by '|' (OK when
none is set), dates as YYYY-MM-DD, a calibration's `success` as succeeded or failed with its
predicted `accuracy` in degrees beside it (empty when the device gives none).

Every stretch of bytes that is no message is a row of kind damaged, one per region: a frame whose
checksum fails (`bad_checksum`; `bad_reserved` with `--strict`), a frame or sentence cut short
(`truncated`), bytes that start no frame (`no_frame_start`; a run longer than 64 KiB is reported
in pieces). With both directions, what the host session finds is a row too: a message nothing in
its state explains (`unexpected`), an acknowledgement with another checksum (`wrong`), an answer
owed and never received (`missing`, length 0, at the offset where it was due).
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable
from typing import Any, Final, TextIO

from ..commands import COMMANDS
from ..statemachine import OUTPUT_FORMATS
from .arguments import OneLineParser, strict_argument, variant_argument, words
from .capture import Source, open_source
from .capture_decoder import CaptureDecoder
from .columnar_capture import ColumnarCapture
from .columnar_csv import ColumnarCsv
from .common import CliError, lookup, variant_named
from .damage import LISTED, damage_regions
from .exports import export_modules, exports, replacing, text_output
from .rows import (
    BASE_COLUMNS,
    DAMAGED,
    FORMATS,
    UNDETERMINED,
    Message,
    RowWriter,
    decode_columns,
    kinds,
    row_fields,
)

# The rows, the damage and the decoders are the modules beside this one (rows, damage,
# capture_decoder, columnar_csv, columnar_capture); their names stay importable from here.
__all__ = [
    "BASE_COLUMNS",
    "DAMAGED",
    "FORMATS",
    "UNDETERMINED",
    "CaptureDecoder",
    "ColumnarCapture",
    "ColumnarCsv",
    "Message",
    "RowWriter",
    "damage_regions",
    "decode_columns",
    "kinds",
    "output_table",
    "row_fields",
]


_PROGRESS_SIZE: Final = 8 << 20
_PROGRESS_PERIOD: Final = 0.5


def output_table(command: str) -> str | None:
    """The payload table of the output `command` starts (None: $PAHR sentences); CliError for a
    command that starts no output."""
    starting = [name for name, info in COMMANDS.items() if info.starts_output is not None]
    name = lookup("output command", command, starting)
    return OUTPUT_FORMATS[COMMANDS[name].starts_output or ""]


class Progress:
    """A progress line on stderr for a large file, when stderr is a terminal."""

    def __init__(self, source: Source, stream: TextIO = sys.stderr, clock: Callable[[], float] = time.monotonic):
        size = source.size
        self._on = size is not None and size >= _PROGRESS_SIZE and stream.isatty()
        self._source = source
        self._stream = stream
        self._clock = clock
        self._next = clock()

    def update(self) -> None:
        if not self._on or self._clock() < self._next:
            return
        self._next = self._clock() + _PROGRESS_PERIOD
        size = self._source.size or 1
        done = self._source.position
        self._stream.write(f"\rdecoding {self._source.name}: {100 * done // size}% of {size >> 20} MiB")
        self._stream.flush()

    def done(self) -> None:
        if self._on:
            self._stream.write("\r\033[K")
            self._stream.flush()


def summary(decoder: CaptureDecoder | ColumnarCsv | ColumnarCapture, prog: str) -> list[str]:
    """The lines of the summary: messages per kind, discarded bytes in damaged regions (the first
    with their offsets and reasons), damaged rows per reason, errors."""
    total = sum(decoder.counts.values())
    per_kind = ", ".join(f"{kind} {count}" for kind, count in decoder.counts.most_common())
    lines = [f"{prog}: {total} messages" + (f" ({per_kind})" if per_kind else "")]
    regions = decoder.regions
    if regions.count:
        listed = ", ".join(regions.listed)
        more = f" and {regions.count - len(regions.listed)} more" if regions.count > len(regions.listed) else ""
        lines.append(f"{prog}: {decoder.discarded} bytes discarded in {regions.count} regions: {listed}{more}")
    else:
        lines.append(f"{prog}: {decoder.discarded} bytes discarded")
    damaged = sum(decoder.damage.values())
    per_reason = ", ".join(f"{reason} {count}" for reason, count in decoder.damage.most_common())
    lines.append(f"{prog}: {damaged} damaged" + (f" ({per_reason})" if per_reason else ""))
    lines.append(f"{prog}: {len(decoder.errors)} decode errors")
    lines += [f"{prog}:   {error}" for error in decoder.errors[:LISTED]]
    if len(decoder.errors) > LISTED:
        lines.append(f"{prog}:   and {len(decoder.errors) - LISTED} more")
    return lines


# --- the subcommand -------------------------------------------------------------------------------


class _Formatter(argparse.HelpFormatter):
    """`--to FORMAT [PATH]` in the usage line (argparse would say `FORMAT [PATH ...]`)."""

    def _format_args(self, action: argparse.Action, default_metavar: str) -> str:
        if action.dest == "to":
            return "FORMAT [PATH]"
        return super()._format_args(action, default_metavar)


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    dec = commands.add_parser(
        "decode", help="decode a capture (pcapng or raw bytes) to text, CSV or JSON lines", formatter_class=_Formatter
    )
    found = exports()
    many = ", ".join(name for name, e in found.items() if e.many)
    dec.add_argument(
        "files",
        metavar="FILE",
        nargs="+",
        help="pcapng file or raw byte dump; - for standard input"
        + (f" (several, or directories of captures, for {many})" if many else ""),
    )
    listed = "; ".join(
        f"{name} {'DIR' if e.target == 'directory' else 'FILE'} ({e.help}; with the {e.extra} extra)"
        for name, e in found.items()
    )
    dec.add_argument(
        "--to",
        nargs="+",
        metavar=("FORMAT", "PATH"),
        default=["text"],
        help=f"output format and where it goes (default text to standard output): {', '.join(FORMATS)}"
        " to standard output or to PATH (written whole, then renamed onto it)" + (f"; {listed}" if listed else ""),
    )
    dec.add_argument("--force", action="store_true", help="replace an existing output directory")
    dec.add_argument("--types", metavar="KIND,...", help=f"only these kinds of rows (default all): {words(kinds())}")
    variant_argument(dec)
    dec.add_argument("--raw", action="store_true", help="raw field values instead of engineering units")
    dec.add_argument("--follow", action="store_true", help="keep reading a growing file (Ctrl-C ends)")
    strict_argument(dec)
    starting = ", ".join(n for n, i in COMMANDS.items() if i.starts_output is not None)
    dec.add_argument(
        "--output-format",
        metavar="COMMAND",
        help=f"the command that started the output ({starting}); a capture that begins with the device's"
        " output is decoded as if that command had been sent before it",
    )
    for module in export_modules():
        options = getattr(module, "add_options", None)
        if callable(options):
            options(dec)
    return dec


def destination(to: list[str]) -> tuple[str, str | None]:
    """`--to FORMAT [PATH]` -> the format (a name of FORMATS or of an export) and the path (None:
    standard output); CliError for an unknown format, a missing or extra path."""
    found = exports()
    if len(to) > 2:
        raise CliError(f"--to takes a format and at most one path, not {' '.join(to)!r}; put the captures before --to")
    name = lookup("output format", to[0], [*FORMATS, *found])
    path = to[1] if len(to) == 2 else None
    export = found.get(name)
    if export is not None and path is None:
        raise CliError(f"--to {name} needs the {export.target} to write: --to {name} PATH")
    return name, path


def run(args: argparse.Namespace) -> int:
    """`ilahrs decode`."""
    valid = kinds()
    selected = [lookup("message kind", k.strip(), valid) for k in args.types.split(",")] if args.types else valid
    variant_named(args.variant)  # a wrong name is refused before the capture is opened
    table = output_table(args.output_format) if args.output_format else None
    args.to, args.out = destination(args.to)
    export = exports().get(args.to)
    if len(args.files) > 1 and not (export is not None and export.many):
        many = [name for name, e in exports().items() if e.many]
        also = f" (several captures go to one dataset with --to {' or '.join(many)})" if many else ""
        raise CliError(f"--to {args.to} decodes one capture, not {len(args.files)}{also}")
    if export is not None:
        if args.follow:
            raise CliError(f"--follow writes rows as they come; --to {args.to} writes a whole {export.target}")
        args.selected = selected
        with replacing(args.out, directory=export.target == "directory", force=args.force) as temporary:
            return export.write(args, temporary)
    args.file = args.files[0]
    if args.out is not None and args.follow:
        raise CliError("--follow writes to standard output (a file would only appear at the end)")
    source = open_source(args.file)
    with text_output(args.out) as out:
        if args.to == "csv" and source.kind == "raw" and not args.follow and not args.strict:
            failure = _decode_columns(args, source, selected, table, out)
        elif args.to == "csv" and source.kind == "pcapng" and not args.follow:
            failure = _decode_capture_columns(args, source, selected, table, out)
        else:
            failure = _decode_messages(args, source, selected, table, out)
    if failure is not None:
        raise failure  # after the rows before it are in place: a capture cut short loses nothing it held
    return 0


def _decode_messages(
    args: argparse.Namespace, source: Source, selected: list[str], table: str | None, out: TextIO
) -> CliError | None:
    """`_decode` message by message, following the commands in a pcapng capture."""
    variant = variant_named(args.variant)
    known = args.output_format is not None
    context = source.kind == "pcapng"
    start = args.output_format if known else None
    decoder = CaptureDecoder(context=context, output=table, output_known=known, strict=args.strict, start=start)
    writer = RowWriter(out, args.to, selected, variant, raw=args.raw)
    feed, finish = decoder.writing(writer.write, selected)
    failure = _drive(source, feed, finish, out, follow=args.follow)
    if failure is not None:
        return failure  # alone: a summary of a capture cut short would read as the whole
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return None


def _decode_columns(
    args: argparse.Namespace, source: Source, selected: list[str], table: str | None, out: TextIO
) -> CliError | None:
    """`_decode` of a raw dump to CSV, a window at a time through ilahrs.columnar (lenient decoding
    only: `--strict` goes message by message)."""
    decoder = ColumnarCsv(out, selected, variant_named(args.variant), raw=args.raw, output=table)
    failure = _drive(source, lambda chunk: decoder.feed(chunk.data), decoder.finish, out, follow=False)
    if failure is not None:
        return failure
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return None


def _decode_capture_columns(
    args: argparse.Namespace, source: Source, selected: list[str], table: str | None, out: TextIO
) -> CliError | None:
    """`_decode` of a pcapng capture to CSV: the commands and every other message one by one, the
    device's continuous output a stretch at a time through ilahrs.columnar (ColumnarCapture)."""
    known = args.output_format is not None
    decoder = ColumnarCapture(
        out,
        selected,
        variant_named(args.variant),
        raw=args.raw,
        output=table,
        output_known=known,
        strict=args.strict,
        start=args.output_format if known else None,
    )
    failure = _drive(source, decoder.feed_packets, decoder.finish, out, follow=False, packets=True)
    if failure is not None:
        return failure
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return None


def _drive(
    source: Source,
    feed: Callable[[Any], None],
    finish: Callable[[], None],
    out: TextIO,
    *,
    follow: bool,
    packets: bool = False,
) -> CliError | None:
    """Every chunk of `source` to `feed` with progress shown, then `finish`; Ctrl-C ends the input; a
    closed pipe (BrokenPipeError) goes on to `ilahrs.__main__.main`, as in every subcommand. Returns
    the error that cut the capture short, if any (the messages before it are written).
    `packets`: feed the packets of a pcapng file as arrays (`Source.packets`), not as Chunks."""
    progress = Progress(source)
    failure: CliError | None = None
    try:
        try:
            for chunk in source.packets() if packets else source.chunks(follow=follow):
                feed(chunk)
                progress.update()
                if follow:
                    out.flush()
        except KeyboardInterrupt:
            pass
        except CliError as exc:
            failure = exc
        finish()
        out.flush()
    finally:
        progress.done()
        source.close()
    return failure
