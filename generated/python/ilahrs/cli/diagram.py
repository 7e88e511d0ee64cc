# Copied from generator/targets/python/runtime/cli/diagram.py for spec/ilahrs.yaml,
# spec hash e075094c86a09f5e6758923635c18e3bbdff7468c7c93495887a7d5071ed5862.
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
