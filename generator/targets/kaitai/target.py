"""Kaitai Struct target: one .ksy describing the frame, the payload tables and the enums."""

from __future__ import annotations

from generator.model import Spec
from generator.render import Output

from .filters import FILTERS, GLOBALS, check_names

__all__ = ["FILTERS", "GLOBALS", "outputs"]


def outputs(spec: Spec) -> list[Output]:
    check_names(spec)
    return [
        Output(path=f"kaitai/{spec.name}.ksy", template="ksy.j2"),
        Output(path="kaitai/README.md", template="readme.md.j2"),
    ]
