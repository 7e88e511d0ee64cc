# Copied from generator/targets/python/runtime/cli/__init__.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The `ilahrs` command. Each module of this package that defines `add_parser(subparsers)` and
`run(args)` is one subcommand, named as the module: the parser is built from the folder (in the
modules' alphabetical order), so adding a subcommand is adding a module. `run()` turns bad input
into one line on stderr and exit status 2 (never a traceback)."""

from __future__ import annotations

import argparse
import importlib
import os
import pkgutil
import sys
from collections.abc import Callable, Sequence
from types import ModuleType

from ..errors import IlahrsError
from ..spec import SPEC_VERSION, WIRE_FINGERPRINT
from .arguments import OneLineParser
from .common import CliError

__all__ = ["main", "parser", "run", "subcommands"]


def subcommands() -> dict[str, ModuleType]:
    """Subcommand name -> its module: every module of this package with `add_parser` and `run`."""
    found: dict[str, ModuleType] = {}
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda info: info.name):
        module = importlib.import_module(f"{__name__}.{info.name}")
        if callable(getattr(module, "add_parser", None)) and callable(getattr(module, "run", None)):
            found[info.name] = module
    return found


def parser() -> argparse.ArgumentParser:
    """The parser of `ilahrs` with every subcommand's; `args.run` runs the one chosen."""
    top = OneLineParser(prog="ilahrs", description=f"ilahrs {SPEC_VERSION}: Inertial Labs AHRS tools")
    top.add_argument(
        "--version", action="version", version=f"ilahrs {SPEC_VERSION} (wire fingerprint {WIRE_FINGERPRINT:016x})"
    )
    commands = top.add_subparsers(dest="command", required=True)
    for module in subcommands().values():
        module.add_parser(commands).set_defaults(run=module.run)
    return top


def run(args: argparse.Namespace) -> int:
    """Run the subcommand `args.command`: its exit status; 2 with one line on stderr for bad input."""
    prog = f"ilahrs {args.command}"
    command: Callable[[argparse.Namespace], int] = args.run
    try:
        return command(args)
    except (CliError, IlahrsError) as exc:
        print(f"{prog}: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"{prog}: interrupted", file=sys.stderr)
        return 130


def main(argv: Sequence[str] | None = None) -> int:
    """Run `ilahrs`: its exit status. A closed standard output (`ilahrs params PORT | head -1`)
    ends the command with one line on stderr and status 2, never a traceback."""
    try:
        status = run(parser().parse_args(argv))
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing more to write at exit
        print(f"ilahrs: {_command(argv)}standard output closed", file=sys.stderr)
        return 2
    return status


def _command(argv: Sequence[str] | None) -> str:
    words = list(sys.argv[1:] if argv is None else argv)
    return next((f"{word}: " for word in words if not word.startswith("-")), "")
