# Copied from generator/targets/python/runtime/cli/conformance.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs conformance`: the conformance suite against a runner or, live, a device
(ilahrs.conformance)."""

from __future__ import annotations

import argparse

from ..conformance import add_arguments
from ..conformance import run as run_suites
from .arguments import OneLineParser

__all__ = ["add_parser", "run"]


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    parser = commands.add_parser(
        "conformance",
        help="run the conformance suite against a runner (--command) or a device (--device)",
        description="Run the conformance vectors shipped with the package against a runner that speaks the "
        "runner protocol (--command), or the session flows live against a device (--device).",
    )
    add_arguments(parser)
    return parser


def run(args: argparse.Namespace) -> int:
    return run_suites(args)
