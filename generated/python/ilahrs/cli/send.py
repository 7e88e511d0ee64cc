# Copied from generator/targets/python/runtime/cli/send.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs send`: one command sent and its answer printed (ilahrs.cli.device)."""

from __future__ import annotations

import argparse
import sys

from ..commands import COMMANDS
from ..payloads import PAYLOADS
from ..roles import LOAD_PARAMETERS
from .arguments import PORT_EPILOG, OneLineParser, port_arguments, variant_argument, words
from .common import lookup, variant_named

__all__ = ["add_parser", "run"]


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    blocks: dict[str, list[str]] = {}
    for name, info in COMMANDS.items():
        if info.parameter_block is not None:
            blocks.setdefault(info.parameter_block, []).append(name)
    keys = "; ".join(
        f"{', '.join(names)}: {words(f.name for f in PAYLOADS[table].FIELDS if f.type != 'reserved') or 'none'}"
        for table, names in blocks.items()
    )
    snd = commands.add_parser(
        "send",
        help="send one command and print the answer",
        description="Send one command to the device in whatever state it is in and print the decoded answer "
        "(status 2 when the device ignores the command in its state). A command that takes a parameter block "
        "sends the table's defaults for the fields not given, except LoadAHRSPar, which replaces every "
        "parameter: give every field, add --defaults, or use `ilahrs params PORT set key=value`.",
        epilog=f"COMMAND: {words(COMMANDS)}. key=value: {keys}. {PORT_EPILOG}",
    )
    port_arguments(snd)
    snd.add_argument("name", metavar="COMMAND", help="ICD command name (e.g. GetBIT, AHRScont3)")
    snd.add_argument("assignments", nargs="*", metavar="key=value", help="fields of the command's parameter block")
    snd.add_argument(
        "--defaults", action="store_true", help=f"let {LOAD_PARAMETERS} send the fields not given as their defaults"
    )
    variant_argument(snd)
    starting = [n for n, i in COMMANDS.items() if i.starts_output is not None]
    snd.add_argument(
        "--output-format",
        metavar="COMMAND",
        help=f"the command that started the device's output, to decode an output block ({', '.join(starting)}; "
        "default: the format the block fits, raw when several do)",
    )
    return snd


def run(args: argparse.Namespace) -> int:
    from .device import send

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
