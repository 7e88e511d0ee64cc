# Copied from generator/targets/python/runtime/cli/record.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs record`: a session recorded to pcapng (ilahrs.cli.device)."""

from __future__ import annotations

import argparse
from typing import Final

from .arguments import PORT_EPILOG, OneLineParser, port_arguments, positive, starting

__all__ = ["add_parser", "run"]

_EPILOG: Final = f"""{PORT_EPILOG}
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


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    rec = commands.add_parser(
        "record",
        help="record a session to pcapng",
        description="Send Stop, check that the device answers, send each --send command and wait for its\n"
        "answers, start the --start output, and record both directions with timestamps until\n"
        "--duration, --count, Ctrl-C or SIGTERM; Stop on exit (also after Ctrl-C and SIGTERM).",
        epilog=_EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    port_arguments(rec)
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
    rec.add_argument("--start", metavar="COMMAND", help=f"start this output after the --send commands ({starting()})")
    rec.add_argument(
        "--duration",
        type=positive(float, "seconds"),
        metavar="S",
        help="record S seconds after the --send commands and the --start output's initial alignment "
        "(default: until Ctrl-C or SIGTERM)",
    )
    rec.add_argument(
        "--count", type=positive(int, "messages"), metavar="N", help="stop after N output messages (default: no limit)"
    )
    return rec


def run(args: argparse.Namespace) -> int:
    from .device import record

    return record(
        args.port, args.baud, args.output, start=args.start, duration=args.duration, count=args.count, sends=args.send
    )
