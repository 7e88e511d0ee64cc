"""The device state machine for the Rust templates: events, answers and rows of the spec's table.

Events are the commands (by their `id`) and the spec's other events; answers come from the model
(`spec.state_machine.answers`), timer events from `TIMER_EVENTS`.
"""

from __future__ import annotations

from typing import Any

from generator.model import TIMER_EVENTS, Spec, StateMachine, Transition
from generator.targets import naming

UNKNOWN_EVENT = "unknown"


def _type_name(name: str) -> str:
    return naming.pascal(name.lower())


def _machine(spec: Spec) -> StateMachine:
    if spec.state_machine is None:
        raise ValueError("the spec has no state_machine")
    return spec.state_machine


def _unique(names: list[str], what: str) -> list[str]:
    clashes = sorted({n for n in names if names.count(n) > 1})
    if clashes:
        raise ValueError(f"{what} names clash in Rust: {clashes}")
    return names


def sm_events(spec: Spec) -> list[dict[str, Any]]:
    """Every event of the table, commands first (spec order), then the other events: the Rust
    variant, the name the table uses, the command (or None) and a doc line."""
    events: list[dict[str, Any]] = [
        {
            "variant": _type_name(c.id),
            "name": c.name,
            "command": c,
            "doc": f"The command `{c.name}` ({naming.hex_byte(c.code)}, {c.icd}).",
        }
        for c in spec.commands
    ]
    events += [
        {"variant": _type_name(e.name), "name": e.name, "command": None, "doc": e.doc} for e in _machine(spec).events
    ]
    _unique([e["variant"] for e in events], "event")
    return events


def sm_event(spec: Spec, name: str) -> str:
    """The Rust variant of the table's event `name` (a command's ICD name or another event)."""
    for event in sm_events(spec):
        if event["name"] == name:
            return str(event["variant"])
    raise ValueError(f"the state machine has no event {name!r}")


def sm_timer_event(spec: Spec, timer: str) -> str:
    """The Rust variant of the event a state's `timer` fires."""
    return sm_event(spec, TIMER_EVENTS[timer])


def sm_answers(spec: Spec) -> list[dict[str, Any]]:
    """Every answer the table sends, in first-use order: the Rust variant, the spec name, the payload
    table (or None), the USW mode (or None) and a doc line."""
    answers: list[dict[str, Any]] = []
    for a in _machine(spec).answers:
        payload = next((p for p in spec.payloads if p.name == a.payload), None)
        doc = f"One {payload.name} block ({payload.icd}, {payload.title})." if payload is not None else a.doc
        answers.append({"variant": _type_name(a.name), "name": a.name, "payload": payload, "mode": a.mode, "doc": doc})
    _unique([a["variant"] for a in answers], "answer")
    return answers


def firmware_parts(version: str) -> list[int]:
    """A firmware version as its numeric parts: "4.9.9.0" -> [4, 9, 9, 0]."""
    parts = version.strip().split(".")
    if not all(part.isdigit() for part in parts):
        raise ValueError(f"firmware version {version!r} is not numeric")
    return [int(part) for part in parts]


def sm_rows(spec: Spec) -> list[Transition]:
    """The table's rows sorted by state, then event (declaration order), the rows for older firmware
    before the current row of the same pair."""
    machine = _machine(spec)
    states = [s.name for s in machine.states]
    events = [e["name"] for e in sm_events(spec)]

    def key(t: Transition) -> tuple[int, int, bool, list[int]]:
        return (
            states.index(t.state),
            events.index(t.event),
            t.firmware_before is None,
            firmware_parts(t.firmware_before or "0"),
        )

    rows = sorted(machine.transitions, key=key)
    current = [(t.state, t.event) for t in rows if t.firmware_before is None]
    if len(set(current)) != len(current):
        raise ValueError("the state machine has two current rows for one (state, event)")
    return rows


def sm_max_firmware_parts(spec: Spec) -> int:
    """The most parts a firmware version of the table has."""
    versions = [t.firmware_before for t in _machine(spec).transitions if t.firmware_before]
    return max([len(firmware_parts(v)) for v in versions] or [1])


def sm_code_events(spec: Spec, code: int) -> list[tuple[list[str], str]]:
    """What a command code means in each mode, as (modes, event variant) groups in mode order: the
    command valid in the mode, else the spec's `unknown` event."""
    groups: dict[str, list[str]] = {}
    for mode in spec.modes:
        command = spec.command_in_mode(code, mode.name)
        variant = sm_event(spec, UNKNOWN_EVENT) if command is None else _type_name(command.id)
        groups.setdefault(variant, []).append(mode.name)
    return [(modes, variant) for variant, modes in groups.items()]


GLOBALS: dict[str, Any] = {
    "sm_events": sm_events,
    "sm_event": sm_event,
    "sm_timer_event": sm_timer_event,
    "sm_answers": sm_answers,
    "sm_rows": sm_rows,
    "sm_code_events": sm_code_events,
    "sm_max_firmware_parts": sm_max_firmware_parts,
    "firmware_parts": firmware_parts,
}
