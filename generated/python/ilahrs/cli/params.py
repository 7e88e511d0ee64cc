# Copied from generator/targets/python/runtime/cli/params.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs params`: the stored parameters printed, or changed with `set key=value ...`
(ilahrs.cli.device)."""

from __future__ import annotations

import argparse
import sys

from ..commands import COMMANDS
from ..payloads import PAYLOADS
from ..roles import LOAD_PARAMETERS
from .arguments import PORT_EPILOG, OneLineParser, port_arguments, variant_argument, words
from .common import CliError, lookup, variant_named

__all__ = ["add_parser", "run"]


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    load = PAYLOADS[COMMANDS[LOAD_PARAMETERS].parameter_block or ""]
    par = commands.add_parser(
        "params",
        help="print parameters; `set key=value ...` changes them",
        description="Print the parameters the device stores; `set key=value ...` reads them, changes the keys "
        "given, loads them and reads them back (6.3.6). Floats print as the shortest text of their float32, "
        "dates as YYYY-MM-DD (set takes a date or the raw number).",
        epilog=f"key: {words(f.name for f in load.FIELDS if f.type != 'reserved')}. {PORT_EPILOG}",
    )
    port_arguments(par)
    par.add_argument("action", nargs="*", metavar="set key=value", help="set key=value ...")
    variant_argument(par)
    return par


def run(args: argparse.Namespace) -> int:
    from .device import params

    action = list(args.action)
    if action:
        lookup("params action", action[0], ["set"])
        if len(action) == 1:
            raise CliError("params set needs at least one key=value")
    return params(args.port, args.baud, action[1:], variant=variant_named(args.variant), out=sys.stdout)
