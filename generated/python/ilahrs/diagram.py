# Copied from generator/targets/python/runtime/diagram.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The state machine drawn: its transitions folded into one arrow per (state, next state, firmware
condition), labelled with one line per answer that lists the events giving it. Given the states'
modes, a transition that every state of a mode has (same event, next state outside the mode, answer
and condition; Stop and ExitClb) is drawn once, from the mode.

The same folding draws the Mermaid diagram (`ilahrs diagram`, the package README) and the Graphviz
diagram of the docs (generated/docs/state-machine.dot). This module uses the standard library only
and no other module of the package, so the generator's docs target imports it as it is.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

__all__ = ["Edge", "Row", "fold", "mermaid"]

Row = tuple[str, str, str, tuple[str, ...], bool, str | None]
"""One transition: (state, event, next state, what the AHRS sends, from a `*` row, the firmware
version before which it applies or None)."""


@dataclass(frozen=True, slots=True)
class Edge:
    """One arrow: every transition from `state` to `to` under the same firmware condition."""

    state: str
    """A state, or a mode when `whole_mode`."""
    to: str
    firmware: str | None
    """The firmware version before which the arrow applies, or None: it always does."""
    lines: tuple[tuple[tuple[str, ...], tuple[str, ...]], ...]
    """(events, what they make the AHRS send), one per distinct answer, in table order."""
    whole_mode: bool = False
    """The arrow leaves every state of the mode `state`."""

    def label(self, newline: str) -> str:
        """The arrow's text: `events / answer` lines joined by `newline`, then the firmware condition."""
        text = newline.join(
            ", ".join(events) + (" / " + ", ".join(send) if send else "") for events, send in self.lines
        )
        if self.firmware:
            text += f"{newline}(firmware < {self.firmware})"
        return text


def _mode_wide(rows: list[Row], modes: Mapping[str, str]) -> set[tuple[str, str, str, tuple[str, ...], str | None]]:
    """(mode, event, next state, answer, firmware) of the transitions every state of a mode of two
    or more states has, leaving the mode; wildcard rows excepted."""
    members: dict[str, set[str]] = {}
    for state, mode in modes.items():
        members.setdefault(mode, set()).add(state)
    found: dict[tuple[str, str, str, tuple[str, ...], str | None], set[str]] = {}
    for state, event, to, send, is_wildcard, firmware in rows:
        own = modes.get(state)
        if own is not None and not is_wildcard and modes.get(to) != own:
            found.setdefault((own, event, to, send, firmware), set()).add(state)
    return {key for key, states in found.items() if len(members[key[0]]) > 1 and states == members[key[0]]}


def fold(
    rows: Iterable[Row], wildcard: str = "any other command", modes: Mapping[str, str] | None = None
) -> list[Edge]:
    """The arrows of `rows`, in order of first appearance; transitions of a `*` row read `wildcard`.
    With `modes` (state -> mode), a transition every state of a mode has is one arrow from the mode."""
    rows = list(rows)
    common = _mode_wide(rows, modes) if modes else set()
    grouped: dict[tuple[str, str, str | None, bool], dict[tuple[str, ...], list[str]]] = {}
    for state, event, to, send, is_wildcard, firmware in rows:
        mode = modes.get(state, "") if modes else ""
        whole = not is_wildcard and (mode, event, to, send, firmware) in common
        events = grouped.setdefault((mode if whole else state, to, firmware, whole), {}).setdefault(send, [])
        name = wildcard if is_wildcard else event
        if name not in events:
            events.append(name)
    return [
        Edge(state, to, firmware, tuple((tuple(events), send) for send, events in lines.items()), whole)
        for (state, to, firmware, whole), lines in grouped.items()
    ]


def mermaid(initial: str, rows: Iterable[Row], modes: Mapping[str, str] | None = None) -> str:
    """A Mermaid state diagram of `rows`, starting in `initial`; with `modes` (state -> mode), a
    transition every state of a mode has is one arrow from a state named "any state of mode M"."""
    edges = fold(rows, modes=modes)
    lines = ["stateDiagram-v2", f"    [*] --> {initial}"]
    taken = set(modes or ()) | {e.state for e in edges if not e.whole_mode} | {e.to for e in edges}
    names: dict[str, str] = {}
    for edge in edges:
        if edge.whole_mode and edge.state not in names:
            name = f"mode_{edge.state}"
            while name in taken:
                name += "_"
            names[edge.state] = name
            taken.add(name)
            lines.append(f'    state "any state of mode {edge.state}" as {name}')
    lines += [
        f"    {names.get(e.state, e.state) if e.whole_mode else e.state} --> {e.to}: {e.label('; ')}" for e in edges
    ]
    return "\n".join(lines) + "\n"
