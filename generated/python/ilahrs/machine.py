# Copied from generator/targets/python/runtime/machine.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The device's state table, interpreted: the types of its rows and the lookups every reader of
the table makes (the device model and the host session). `ilahrs.statemachine` holds the spec's
table in a Machine and binds these methods to its functions (`lookup`, `command_event`, ...).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from . import diagram

__all__ = ["Machine", "StateInfo", "Transition", "firmware_is_valid", "firmware_version"]


@dataclass(frozen=True, slots=True)
class StateInfo:
    """A state of the device: its operating mode, the parameter block it waits for, its timer."""

    name: str
    mode: str
    expects: str | None
    """The payload table of the parameter block this state waits for (E34), if any."""
    timer: str | None
    """alignment, accumulation or output: the timer running in this state, if any."""
    doc: str


@dataclass(frozen=True, slots=True)
class Transition:
    """One cell of the table: go to `to` and send `send`."""

    to: str
    send: tuple[str, ...]
    wildcard: bool = False
    """From a `*` row: any command without a row of its own."""
    erratum: str | None = None


def firmware_version(text: str) -> tuple[int, ...]:
    """The version of a firmware text: "4.9.9.0" -> (4, 9, 9, 0); parts that are not ASCII digits count as 0."""
    if not isinstance(text, str):
        return ()
    return tuple(int(part) if part.isascii() and part.isdigit() else 0 for part in text.strip().split("."))


def firmware_is_valid(text: object) -> bool:
    """A firmware version as the AHRS reports it: one to eight dot-separated numbers of ASCII
    digits ("4.9.9.0")."""
    if not isinstance(text, str) or not 0 < len(text) <= 64:
        return False
    parts = text.split(".")
    return len(parts) <= 8 and all(0 < len(p) <= 6 and p.isascii() and p.isdigit() for p in parts)


@dataclass(frozen=True, slots=True, eq=False)
class Machine:
    """A state table: the states, the transitions of the current firmware, the rows that replace
    them on older firmware, the command codes, which name a shared code has in each mode, and the
    event each timer fires."""

    initial: str
    states: Mapping[str, StateInfo]
    transitions: Mapping[tuple[str, str], Transition]
    legacy: Mapping[tuple[str, str], tuple[str, Transition]]
    codes: Mapping[int, tuple[str, ...]]
    shared_codes: Mapping[tuple[int, str], str]
    timer_events: Mapping[str, str]

    def lookup(self, state: str, event: str, firmware: str | None = None) -> Transition | None:
        """The transition for `event` in `state` on the given firmware version (default: current), or
        None: the device ignores the event (E33)."""
        if firmware is not None:
            legacy = self.legacy.get((state, event)) if isinstance(state, str) and isinstance(event, str) else None
            if legacy is not None and firmware_version(firmware) < firmware_version(legacy[0]):
                return legacy[1]
        if not isinstance(state, str) or not isinstance(event, str):
            return None
        return self.transitions.get((state, event))

    def command_event(self, code: int, state: str) -> str | None:
        """The command a code means in `state`: of the names sharing a code, the one valid in the
        state's mode, else the code's default name (0xFE is ExitClb in calibration, Stop elsewhere,
        E14); None for a code no command has."""
        names = self.codes.get(code) if isinstance(code, int) else None
        if names is None:
            return None
        if len(names) == 1:
            return names[0]
        info = self.states.get(state) if isinstance(state, str) else None
        return None if info is None else self.shared_codes.get((code, info.mode))

    def timer_transition(self, state: str) -> tuple[str, Transition] | None:
        """(event, transition) of the timer running in `state`, if any."""
        info = self.states.get(state) if isinstance(state, str) else None
        timer = None if info is None else info.timer
        if timer is None:
            return None
        event = self.timer_events[timer]
        transition = self.transitions.get((state, event))
        return None if transition is None else (event, transition)

    def rows(self) -> list[diagram.Row]:
        """Every transition as a diagram row: the current ones, then the legacy ones."""
        rows: list[diagram.Row] = [(s, e, t.to, t.send, t.wildcard, None) for (s, e), t in self.transitions.items()]
        rows += [(s, e, t.to, t.send, t.wildcard, firmware) for (s, e), (firmware, t) in self.legacy.items()]
        return rows

    def mermaid(self) -> str:
        """The table as a Mermaid state diagram (`ilahrs diagram`)."""
        return diagram.mermaid(self.initial, self.rows(), {name: info.mode for name, info in self.states.items()})
