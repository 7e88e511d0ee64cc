# Copied from generator/targets/python/runtime/cli/diagram.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs diagram`: the state machine as a Mermaid diagram."""

from __future__ import annotations

import argparse
import sys

from ..statemachine import mermaid
from .arguments import OneLineParser

__all__ = ["add_parser", "run"]


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    return commands.add_parser(
        "diagram",
        help="print the device state machine as a Mermaid diagram",
        description="Print the device's state machine (ilahrs.statemachine, from the spec) as a Mermaid "
        "stateDiagram on standard output: every state, and every transition with the event and what "
        "the AHRS sends.",
    )


def run(args: argparse.Namespace) -> int:
    sys.stdout.write(mermaid())
    return 0
