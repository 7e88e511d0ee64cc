"""The subcommands of `ilahrs` besides simulate and diagram: record, decode, send, params, monitor,
calibrate and plot. `add_subcommands()` adds their parsers; `run()` runs one and turns bad input
into one line on stderr and exit status 2 (never a traceback)."""

from __future__ import annotations

import argparse
import difflib
import math
import re
import sys
from collections.abc import Callable, Iterable
from typing import Any, Final, NoReturn

from .cli_capture import Chunk, Source, open_source
from .cli_common import BAUDRATE, CliError, lookup, variant_named
from .cli_decode import (
    FORMATS,
    CaptureDecoder,
    ColumnarCapture,
    ColumnarCsv,
    Progress,
    RowWriter,
    kinds,
    output_table,
    summary,
)
from .cli_device import DEFAULT_ACCUMULATION_S
from .cli_plot import plottable
from .commands import COMMANDS
from .encodings import VARIANTS
from .errors import IlahrsError
from .payloads import PAYLOADS
from .roles import LOAD_PARAMETERS
from .statemachine import TIMER_FIELDS

__all__ = ["COMMANDS_RUN", "OneLineParser", "add_subcommands", "run"]

_EPILOG: Final = "PORT: a device path (/dev/ttyUSB0, the pty `ilahrs simulate` prints) or socket://HOST:PORT."
_RECORD_EPILOG: Final = f"""{_EPILOG}
A device path is locked while it is recorded: another ilahrs on the same port is refused.

example:
  ilahrs record /dev/ttyUSB0 -o s.pcapng --send GetBIT --send "LoadAHRSPar update_rate=50" \\
      --start AHRScont3 --duration 10

The capture is written beside FILE.pcapng and renamed onto it when the recording ends; if the
device never answers (a wrong port or --baud), no file is written and FILE.pcapng is untouched.
A one-line summary (messages, discarded bytes and errors, as `ilahrs decode` counts them) goes to
standard error.

exit status: 0 at the end of --duration or --count or after Ctrl-C; 2 after SIGTERM (the capture
kept, the device stopped), when the device is lost or a command fails (the capture kept, a line
after the summary), and for bad input or a device that does not answer (no file written)."""


class OneLineParser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are one line on stderr (exit status 2), with the closest
    valid choice suggested."""

    def error(self, message: str) -> NoReturn:
        match = re.search(r"invalid choice: '([^']*)' \(choose from (.*)\)", message)
        if match:
            choices = re.findall(r"'([^']*)'", match.group(2)) or [c.strip() for c in match.group(2).split(",")]
            close = difflib.get_close_matches(match.group(1), choices, n=1)
            hint = f"; did you mean {close[0]}?" if close else f" (one of {', '.join(choices)})"
            message = f"unknown command {match.group(1)!r}{hint}"
        self.exit(2, f"{self.prog}: {message}\n")


def _baud(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a baud rate (a positive integer such as {BAUDRATE})")
    return value


def _port(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("port", metavar="PORT", help="device path or socket://HOST:PORT")
    sub.add_argument("--baud", type=_baud, default=BAUDRATE, help=f"baud rate (default {BAUDRATE})")


def _variant(sub: argparse.ArgumentParser) -> None:
    names = ", ".join(VARIANTS)
    sub.add_argument(
        "--variant", metavar="NAME", help=f"device variant for scaled rates ({names}; default {next(iter(VARIANTS))})"
    )


def _words(words: Iterable[str]) -> str:
    """Names for an epilog, wrapped as argparse wraps text."""
    return ", ".join(words)


def _strict(sub: argparse.ArgumentParser) -> None:
    sub.add_argument(
        "--strict",
        action="store_true",
        help="refuse data frames whose reserved byte is not the AHRS's: damage the checksum cannot see (E42)",
    )


def _starting() -> str:
    return ", ".join(n for n, i in COMMANDS.items() if i.starts_output is not None)


def _output_format(sub: argparse.ArgumentParser, default: str | None) -> None:
    sub.add_argument("--output-format", metavar="COMMAND", default=default, help=f"the start command ({_starting()})")


def _positive(kind: Callable[[str], float], unit: str) -> Callable[[str], float]:
    """An argparse type: a finite number above zero of `kind` (int or float)."""

    def parse(text: str) -> float:
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a number of {unit}") from None
        if not (math.isfinite(value) and value > 0):
            raise argparse.ArgumentTypeError(f"{text!r}: must be a positive number of {unit}")
        return value

    parse.__name__ = kind.__name__
    return parse


def add_subcommands(commands: argparse._SubParsersAction[OneLineParser]) -> None:
    """Add the parsers of record, decode, send, params, monitor, calibrate and plot."""
    rec = commands.add_parser(
        "record",
        help="record a session to pcapng",
        description="Send Stop, check that the device answers, send each --send command and wait for its\n"
        "answers, start the --start output, and record both directions with timestamps until\n"
        "--duration, --count, Ctrl-C or SIGTERM; Stop on exit (also after Ctrl-C and SIGTERM).",
        epilog=_RECORD_EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    _port(rec)
    rec.add_argument(
        "-o",
        "--output",
        required=True,
        metavar="FILE.pcapng",
        help="the capture to write: replaced only when the recording ends, and only if the device answered",
    )
    rec.add_argument(
        "--send",
        action="append",
        default=[],
        metavar='"COMMAND [key=value ...]"',
        help="send this command (and fields of its parameter block) after Stop and wait for its answers; "
        "repeat for several, sent in order before --start. LoadAHRSPar keeps the device's values "
        "of fields not given (read first with ReadAHRSPar)",
    )
    rec.add_argument("--start", metavar="COMMAND", help=f"start this output after the --send commands ({_starting()})")
    rec.add_argument(
        "--duration",
        type=_positive(float, "seconds"),
        metavar="S",
        help="record S seconds after the --send commands and the --start output's initial alignment "
        "(default: until Ctrl-C or SIGTERM)",
    )
    rec.add_argument(
        "--count", type=_positive(int, "messages"), metavar="N", help="stop after N output messages (default: no limit)"
    )

    dec = commands.add_parser("decode", help="decode a capture (pcapng or raw bytes) to text, CSV or JSON lines")
    dec.add_argument("file", metavar="FILE", help="pcapng file or raw byte dump; - for standard input")
    dec.add_argument("--to", choices=FORMATS, default="text", help="output format (default text)")
    dec.add_argument("--types", metavar="KIND,...", help=f"only these kinds of rows (default all): {_words(kinds())}")
    _variant(dec)
    dec.add_argument("--raw", action="store_true", help="raw field values instead of engineering units")
    dec.add_argument("--follow", action="store_true", help="keep reading a growing file (Ctrl-C ends)")
    _strict(dec)
    starting = ", ".join(n for n, i in COMMANDS.items() if i.starts_output is not None)
    dec.add_argument(
        "--output-format",
        metavar="COMMAND",
        help=f"the command that started the output ({starting}); a capture that begins with the device's"
        " output is decoded as if that command had been sent before it",
    )

    _send_parser(commands)
    _params_parser(commands)

    mon = commands.add_parser("monitor", help="live full-screen view of the output (q quits)", epilog=_EPILOG)
    _port(mon)
    _output_format(mon, "AHRScont3")
    _variant(mon)
    _strict(mon)

    _calibrate_parser(commands)

    fields = ", ".join({name: None for table in plottable().values() for name in table})
    plot = commands.add_parser(
        "plot",
        help="plot fields of a capture to a PNG (needs matplotlib)",
        description="One panel per quantity (by the fields' units; heading 0-360 apart from signed angles), "
        "sharing the time axis; lines break at gaps in the output and where heading wraps; multiplexed fields "
        "(Vdd, Utermo of Table 6.4) are drawn one line per turn.",
        epilog=f"FIELD: {fields}. Example: ilahrs plot s.pcapng -o s.png --fields heading,pitch,roll,gyro_z",
    )
    plot.add_argument("file", metavar="FILE", help="pcapng file or raw byte dump")
    plot.add_argument("-o", "--output", required=True, metavar="OUT.png", help="the PNG to write")
    plot.add_argument(
        "--fields",
        default="heading,pitch,roll",
        metavar="FIELD,...",
        help="fields to plot (default heading,pitch,roll)",
    )
    plot.add_argument("--size", default="1200x800", metavar="WxH", help="image size in pixels (default 1200x800)")
    _variant(plot)
    _output_format(plot, None)


def _send_parser(commands: argparse._SubParsersAction[OneLineParser]) -> None:
    blocks: dict[str, list[str]] = {}
    for name, info in COMMANDS.items():
        if info.parameter_block is not None:
            blocks.setdefault(info.parameter_block, []).append(name)
    keys = "; ".join(
        f"{', '.join(names)}: {_words(f.name for f in PAYLOADS[table].FIELDS if f.type != 'reserved') or 'none'}"
        for table, names in blocks.items()
    )
    snd = commands.add_parser(
        "send",
        help="send one command and print the answer",
        description="Send one command to the device in whatever state it is in and print the decoded answer "
        "(status 2 when the device ignores the command in its state). A command that takes a parameter block "
        "sends the table's defaults for the fields not given, except LoadAHRSPar, which replaces every "
        "parameter: give every field, add --defaults, or use `ilahrs params PORT set key=value`.",
        epilog=f"COMMAND: {_words(COMMANDS)}. key=value: {keys}. {_EPILOG}",
    )
    _port(snd)
    snd.add_argument("name", metavar="COMMAND", help="ICD command name (e.g. GetBIT, AHRScont3)")
    snd.add_argument("assignments", nargs="*", metavar="key=value", help="fields of the command's parameter block")
    snd.add_argument(
        "--defaults", action="store_true", help=f"let {LOAD_PARAMETERS} send the fields not given as their defaults"
    )
    _variant(snd)
    starting = [n for n, i in COMMANDS.items() if i.starts_output is not None]
    snd.add_argument(
        "--output-format",
        metavar="COMMAND",
        help=f"the command that started the device's output, to decode an output block ({', '.join(starting)}; "
        "default: the format the block fits, raw when several do)",
    )


def _params_parser(commands: argparse._SubParsersAction[OneLineParser]) -> None:
    load = PAYLOADS[COMMANDS[LOAD_PARAMETERS].parameter_block or ""]
    par = commands.add_parser(
        "params",
        help="print parameters; `set key=value ...` changes them",
        description="Print the parameters the device stores; `set key=value ...` reads them, changes the keys "
        "given, loads them and reads them back (6.3.6). Floats print as the shortest text of their float32, "
        "dates as YYYY-MM-DD (set takes a date or the raw number).",
        epilog=f"key: {_words(f.name for f in load.FIELDS if f.type != 'reserved')}. {_EPILOG}",
    )
    _port(par)
    par.add_argument("action", nargs="*", metavar="set key=value", help="set key=value ...")
    _variant(par)


def _calibrate_parser(commands: argparse._SubParsersAction[OneLineParser]) -> None:
    cal = commands.add_parser("calibrate", help="guided hard/soft-iron calibration", epilog=_EPILOG)
    _port(cal)
    cal.add_argument("kind", metavar="2d|3d|2d2t", help="calibration type")
    table, field = TIMER_FIELDS["accumulation"]
    span = next(f for f in PAYLOADS[table].FIELDS if f.name == field)
    cal.add_argument(
        "--accumulation",
        type=int,
        default=DEFAULT_ACCUMULATION_S,
        metavar="S",
        help=f"accumulation time per run, seconds, {span.low:g}..{span.high:g}: long enough for a slow full "
        f"turn (default {DEFAULT_ACCUMULATION_S})",
    )
    place = "(default: what the device stores)"
    cal.add_argument("--latitude", type=float, metavar="DEG", help=f"latitude of the calibration {place}")
    cal.add_argument("--longitude", type=float, metavar="DEG", help=f"longitude of the calibration {place}")
    cal.add_argument("--altitude", type=float, metavar="M", help=f"altitude of the calibration {place}")
    cal.add_argument("--date", metavar="YYYY-MM-DD", help=f"date of the calibration {place}")
    cal.add_argument("--runs", type=int, default=2, metavar="N", help="runs of a 2D-2T calibration (default 2)")
    answer = cal.add_mutually_exclusive_group()
    answer.add_argument(
        "--yes", dest="answer", action="store_const", const=True, help="accept without asking (default: ask)"
    )
    answer.add_argument(
        "--no", dest="answer", action="store_const", const=False, help="discard without asking (default: ask)"
    )
    _variant(cal)


def _decode(args: argparse.Namespace) -> int:
    valid = kinds()
    selected = [lookup("message kind", k.strip(), valid) for k in args.types.split(",")] if args.types else valid
    variant_named(args.variant)  # a wrong name is refused before the capture is opened
    table = output_table(args.output_format) if args.output_format else None
    source = open_source(args.file)
    if args.to == "csv" and source.kind == "raw" and not args.follow and not args.strict:
        return _decode_columns(args, source, selected, table)
    if args.to == "csv" and source.kind == "pcapng" and not args.follow:
        return _decode_capture_columns(args, source, selected, table)
    return _decode_messages(args, source, selected, table)


def _decode_messages(args: argparse.Namespace, source: Source, selected: list[str], table: str | None) -> int:
    """`_decode` message by message, following the commands in a pcapng capture."""
    variant = variant_named(args.variant)
    known = args.output_format is not None
    context = source.kind == "pcapng"
    start = args.output_format if known else None
    decoder = CaptureDecoder(context=context, output=table, output_known=known, strict=args.strict, start=start)
    writer = RowWriter(sys.stdout, args.to, selected, variant, raw=args.raw)
    wanted = set(selected)

    def feed(chunk: Chunk) -> None:
        for message in decoder.feed(chunk):
            if message.kind in wanted:
                writer.write(message)

    def finish() -> None:
        for message in decoder.finish():
            if message.kind in wanted:
                writer.write(message)

    failure = _drive(source, feed, finish, follow=args.follow)
    if failure is not None:
        raise failure  # alone: a summary of a capture cut short would read as the whole
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return 0


def _decode_columns(args: argparse.Namespace, source: Source, selected: list[str], table: str | None) -> int:
    """`_decode` of a raw dump to CSV, a window at a time through ilahrs.columnar (lenient decoding
    only: `--strict` goes message by message)."""
    decoder = ColumnarCsv(sys.stdout, selected, variant_named(args.variant), raw=args.raw, output=table)
    failure = _drive(source, lambda chunk: decoder.feed(chunk.data), decoder.finish, follow=False)
    if failure is not None:
        raise failure
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return 0


def _decode_capture_columns(args: argparse.Namespace, source: Source, selected: list[str], table: str | None) -> int:
    """`_decode` of a pcapng capture to CSV: the commands and every other message one by one, the
    device's continuous output a stretch at a time through ilahrs.columnar (ColumnarCapture)."""
    known = args.output_format is not None
    decoder = ColumnarCapture(
        sys.stdout,
        selected,
        variant_named(args.variant),
        raw=args.raw,
        output=table,
        output_known=known,
        strict=args.strict,
        start=args.output_format if known else None,
    )
    failure = _drive(source, decoder.feed_packets, decoder.finish, follow=False, packets=True)
    if failure is not None:
        raise failure
    for line in summary(decoder, "ilahrs decode"):
        print(line, file=sys.stderr)
    return 0


def _drive(
    source: Source, feed: Callable[[Any], None], finish: Callable[[], None], *, follow: bool, packets: bool = False
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
                    sys.stdout.flush()
        except KeyboardInterrupt:
            pass
        except CliError as exc:
            failure = exc
        finish()
        sys.stdout.flush()
    finally:
        progress.done()
        source.close()
    return failure


def _record(args: argparse.Namespace) -> int:
    from .cli_device import record

    return record(
        args.port, args.baud, args.output, start=args.start, duration=args.duration, count=args.count, sends=args.send
    )


def _send(args: argparse.Namespace) -> int:
    from .cli_device import send

    variant = variant_named(args.variant)
    starting = [n for n, i in COMMANDS.items() if i.starts_output is not None]
    return send(
        args.port,
        args.baud,
        args.name,
        args.assignments,
        variant=variant,
        out=sys.stdout,
        defaults=args.defaults,
        output=None if args.output_format is None else lookup("output command", args.output_format, starting),
    )


def _params(args: argparse.Namespace) -> int:
    from .cli_device import params

    action = list(args.action)
    if action:
        lookup("params action", action[0], ["set"])
        if len(action) == 1:
            raise CliError("params set needs at least one key=value")
    return params(args.port, args.baud, action[1:], variant=variant_named(args.variant), out=sys.stdout)


def _calibrate(args: argparse.Namespace) -> int:
    from .cli_device import calibrate, calibration_place

    variant = variant_named(args.variant)
    place = calibration_place(args.latitude, args.longitude, args.altitude, args.date)
    return calibrate(
        args.port,
        args.baud,
        args.kind,
        accumulation=args.accumulation,
        runs=args.runs,
        answer=args.answer,
        variant=variant,
        out=sys.stdout,
        place=place,
    )


def _monitor(args: argparse.Namespace) -> int:
    from .cli_monitor import monitor

    output_table(args.output_format)  # refuse an unknown command before opening the port
    return monitor(args.port, args.baud, args.output_format, variant_named(args.variant), strict=args.strict)


def _plot(args: argparse.Namespace) -> int:
    from .cli_plot import plot

    variant = variant_named(args.variant)
    return plot(
        args.file,
        args.output,
        fields_text=args.fields,
        size_text=args.size,
        variant=variant,
        output_format=args.output_format,
    )


COMMANDS_RUN: Final[dict[str, Callable[[argparse.Namespace], int]]] = {
    "record": _record,
    "decode": _decode,
    "send": _send,
    "params": _params,
    "monitor": _monitor,
    "calibrate": _calibrate,
    "plot": _plot,
}
"""The subcommands this module runs."""


def run(args: argparse.Namespace) -> int:
    """Run the subcommand `args.command`: its exit status; 2 with one line on stderr for bad input."""
    prog = f"ilahrs {args.command}"
    try:
        return COMMANDS_RUN[args.command](args)
    except CliError as exc:
        print(f"{prog}: {exc}", file=sys.stderr)
        return 2
    except IlahrsError as exc:
        print(f"{prog}: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"{prog}: interrupted", file=sys.stderr)
        return 130
