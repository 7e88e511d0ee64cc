# Copied from generator/targets/python/runtime/cli/arguments.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""What the subcommands' parsers share: a parser whose errors are one line, the options of a port,
a variant, strict decoding and an output format, and argparse types."""

from __future__ import annotations

import argparse
import difflib
import math
import re
from collections.abc import Callable, Iterable
from typing import Final, NoReturn

from ..commands import COMMANDS
from ..encodings import VARIANTS
from .common import BAUDRATE

__all__ = [
    "PORT_EPILOG",
    "OneLineParser",
    "output_format_argument",
    "port_arguments",
    "positive",
    "starting",
    "strict_argument",
    "variant_argument",
    "words",
]

PORT_EPILOG: Final = "PORT: a device path (/dev/ttyUSB0, the pty `ilahrs simulate` prints) or socket://HOST:PORT."


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


def port_arguments(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("port", metavar="PORT", help="device path or socket://HOST:PORT")
    sub.add_argument("--baud", type=_baud, default=BAUDRATE, help=f"baud rate (default {BAUDRATE})")


def variant_argument(sub: argparse.ArgumentParser) -> None:
    names = ", ".join(VARIANTS)
    sub.add_argument(
        "--variant", metavar="NAME", help=f"device variant for scaled rates ({names}; default {next(iter(VARIANTS))})"
    )


def words(names: Iterable[str]) -> str:
    """Names for an epilog, wrapped as argparse wraps text."""
    return ", ".join(names)


def strict_argument(sub: argparse.ArgumentParser) -> None:
    sub.add_argument(
        "--strict",
        action="store_true",
        help="refuse data frames whose reserved byte is not the AHRS's: damage the checksum cannot see (E42)",
    )


def starting() -> str:
    """The commands that start output, for a help text."""
    return ", ".join(n for n, i in COMMANDS.items() if i.starts_output is not None)


def output_format_argument(sub: argparse.ArgumentParser, default: str | None) -> None:
    sub.add_argument("--output-format", metavar="COMMAND", default=default, help=f"the start command ({starting()})")


def positive(kind: Callable[[str], float], unit: str) -> Callable[[str], float]:
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
