# Copied from generator/targets/python/runtime/diagram.py for spec/ilahrs.yaml,
# spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
# Do not edit: change the runtime source and run `make generate`.
"""The state machine drawn: its transitions folded into one arrow per (state, next state, firmware
condition), labelled with one line per answer that lists the events giving it.

The same folding draws the Mermaid diagram (`ilahrs diagram`, the package README) and the Graphviz
diagram of the docs (generated/docs/state-machine.dot). This module uses the standard library only
and no other module of the package, so the generator's docs target imports it as it is.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

__all__ = ["Edge", "Row", "fold", "mermaid"]

Row = tuple[str, str, str, tuple[str, ...], bool, str | None]
"""One transition: (state, event, next state, what the AHRS sends, from a `*` row, the firmware
version before which it applies or None)."""


@dataclass(frozen=True, slots=True)
class Edge:
    """One arrow: every transition from `state` to `to` under the same firmware condition."""

    state: str
    to: str
    firmware: str | None
    """The firmware version before which the arrow applies, or None: it always does."""
    lines: tuple[tuple[tuple[str, ...], tuple[str, ...]], ...]
    """(events, what they make the AHRS send), one per distinct answer, in table order."""

    def label(self, newline: str) -> str:
        """The arrow's text: `events / answer` lines joined by `newline`, then the firmware condition."""
        text = newline.join(
            ", ".join(events) + (" / " + ", ".join(send) if send else "") for events, send in self.lines
        )
        if self.firmware:
            text += f"{newline}(firmware < {self.firmware})"
        return text


def fold(rows: Iterable[Row], wildcard: str = "any other command") -> list[Edge]:
    """The arrows of `rows`, in order of first appearance; transitions of a `*` row read `wildcard`."""
    grouped: dict[tuple[str, str, str | None], dict[tuple[str, ...], list[str]]] = {}
    for state, event, to, send, is_wildcard, firmware in rows:
        events = grouped.setdefault((state, to, firmware), {}).setdefault(send, [])
        name = wildcard if is_wildcard else event
        if name not in events:
            events.append(name)
    return [
        Edge(state, to, firmware, tuple((tuple(events), send) for send, events in lines.items()))
        for (state, to, firmware), lines in grouped.items()
    ]


def mermaid(initial: str, rows: Iterable[Row]) -> str:
    """A Mermaid state diagram of `rows`, starting in `initial`."""
    lines = ["stateDiagram-v2", f"    [*] --> {initial}"]
    lines += [f"    {edge.state} --> {edge.to}: {edge.label('; ')}" for edge in fold(rows)]
    return "\n".join(lines) + "\n"
