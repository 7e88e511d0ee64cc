"""Validation of the state machine (part of generator.validate): every state, event, answer and
timer a row names exists, no cell is given twice, every command is handled wherever its modes
say it is valid, and every state that waits for something has a row for it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..load import LoadedSpec, PathKey
from ..model.machine import TIMER_EVENTS, answer_kind
from .common import Names, unique

BASE: PathKey = ("state_machine",)

# A cell given by an explicit row: (state, event, firmware_before) -> where the row names the event.
Cells = dict[tuple[str, str, str | None], PathKey]


@dataclass(frozen=True)
class _Table:
    """The names a row of the table may use."""

    spec: LoadedSpec
    states: dict[str, dict[str, Any]]
    commands: dict[str, dict[str, Any]]
    events: set[str]
    payloads: set[str]
    usw_modes: set[str]


def check_state_machine(spec: LoadedSpec, sm: dict[str, Any], names: Names) -> None:
    """Raise SpecError for the first problem with the state machine section `sm`."""
    table = _check_states(spec, sm, names)
    cells: Cells = {}
    for i, row in enumerate(sm["transitions"]):
        _check_row(table, row, (*BASE, "transitions", i), cells)
    _check_valid_in_handled(table, cells)
    _check_shared_codes(spec)
    timers = _check_timers(spec, sm)
    for i, st in enumerate(sm["states"]):
        if "timer" in st and "timers" in sm and st["timer"] not in timers:
            raise spec.error((*BASE, "states", i, "timer"), f"no entry under timers sets the {st['timer']!r} timer")
        needed = []
        if "timer" in st:
            needed.append(TIMER_EVENTS[st["timer"]])
        if "expects" in st:
            needed.append("parameter_block")
        for event in needed:
            if (st["name"], event, None) not in cells:
                raise spec.error((*BASE, "states", i), f"state {st['name']!r} has no transition for {event!r}")


def _check_states(spec: LoadedSpec, sm: dict[str, Any], names: Names) -> _Table:
    """States and events named once, no event named like a command, an initial state that exists,
    and every state in a known mode waiting for a known payload."""
    unique(spec, sm["states"], (*BASE, "states"), "name", "state")
    unique(spec, sm["events"], (*BASE, "events"), "name", "event")
    states = {st["name"]: st for st in sm["states"]}
    commands = {c["name"]: c for c in spec.data["commands"]}
    events = {e["name"] for e in sm["events"]}
    for name in events & set(commands):
        raise spec.error((*BASE, "events"), f"event {name!r} is also a command name")
    if sm["initial"] not in states:
        raise spec.error((*BASE, "initial"), f"unknown state {sm['initial']!r}")
    for i, st in enumerate(sm["states"]):
        path: PathKey = (*BASE, "states", i)
        if st["mode"] not in names.modes:
            raise spec.error((*path, "mode"), f"unknown mode {st['mode']!r}")
        if "expects" in st and st["expects"] not in names.payloads:
            raise spec.error((*path, "expects"), f"unknown payload {st['expects']!r}")
    sw = spec.data.get("status_word")
    usw_modes = {m["name"] for m in sw["mode"]["values"]} if sw else set()
    return _Table(spec, states, commands, events, set(names.payloads), usw_modes)


def _check_row(table: _Table, row: dict[str, Any], path: PathKey, cells: Cells) -> None:
    """Known states and answers; each event known and given once per state; record its cells."""
    spec = table.spec
    for j, state in enumerate(row["from"]):
        if state not in table.states:
            raise spec.error((*path, "from", j), f"unknown state {state!r}")
    if row["to"] != "same" and row["to"] not in table.states:
        raise spec.error((*path, "to"), f"unknown state {row['to']!r}")
    for j, item in enumerate(row["send"]):
        if answer_kind(item, table.payloads, table.usw_modes) is None:
            raise spec.error(
                (*path, "send", j), f"unknown answer {item!r} (ack, output, output_ + a USW mode, or a payload)"
            )
    for j, event in enumerate(row["when"]):
        if event != "*" and event not in table.commands and event not in table.events:
            raise spec.error((*path, "when", j), f"unknown event {event!r}: not a command, an event or '*'")
        if event != "*":
            _add_cells(table, row, event, (*path, "when", j), cells)


def _add_cells(table: _Table, row: dict[str, Any], event: str, where: PathKey, cells: Cells) -> None:
    """The cells `row` gives `event`: none given before, a command only in a mode it is valid in, a
    parameter block only in a state that expects one."""
    spec = table.spec
    for state in row["from"]:
        key = (state, event, row.get("firmware_before"))
        if key in cells:
            line = spec.line_of(cells[key])
            raise spec.error(where, f"a second row for {event!r} in state {state!r} (first at line {line})")
        cells[key] = where
        mode = table.states[state]["mode"]
        if event in table.commands and mode not in table.commands[event]["valid_in"]:
            raise spec.error(
                where,
                f"{event} has a transition in state {state!r} (mode {mode}), but its valid_in does not list that mode",
            )
    if event == "parameter_block":
        for state in row["from"]:
            if "expects" not in table.states[state]:
                raise spec.error(where, f"state {state!r} expects no parameter block")


def _check_valid_in_handled(table: _Table, cells: Cells) -> None:
    """A command valid in a mode has an explicit row in some state of that mode."""
    for name, command in table.commands.items():
        for mode in command["valid_in"]:
            if not any(table.states[st]["mode"] == mode and ev == name for (st, ev, _fw) in cells):
                raise table.spec.error(
                    ("commands", list(table.commands).index(name), "valid_in"),
                    f"{name} is valid in mode {mode!r} but no state of that mode has a transition for it",
                )


def _check_shared_codes(spec: LoadedSpec) -> None:
    """A code shared by several names is resolved by mode, so their modes must not overlap."""
    commands = spec.data["commands"]
    by_code: dict[int, list[dict[str, Any]]] = {}
    for c in commands:
        by_code.setdefault(c["code"], []).append(c)
    for group in by_code.values():
        for a_index, a in enumerate(group):
            for b in group[a_index + 1 :]:
                shared = set(a["valid_in"]) & set(b["valid_in"])
                if shared:
                    raise spec.error(
                        ("commands", commands.index(b), "valid_in"),
                        f"{a['name']} and {b['name']} share code {a['code']:#04x}"
                        f" and are both valid in {sorted(shared)}",
                    )


def _check_timers(spec: LoadedSpec, sm: dict[str, Any]) -> dict[str, dict[str, Any]]:
    """Timers named once, each set by an existing payload field in seconds (Hz for output)."""
    payloads = {p["name"]: p for p in spec.data["payloads"]}
    timers: dict[str, dict[str, Any]] = {}
    for i, t in enumerate(sm.get("timers", [])):
        path = (*BASE, "timers", i)
        if t["name"] in timers:
            raise spec.error((*path, "name"), f"duplicate timer {t['name']!r}")
        timers[t["name"]] = t
        if t["payload"] not in payloads:
            raise spec.error((*path, "payload"), f"unknown payload {t['payload']!r}")
        fields = {f["name"]: f for f in payloads[t["payload"]]["fields"]}
        if t["field"] not in fields:
            raise spec.error((*path, "field"), f"payload {t['payload']!r} has no field {t['field']!r}")
        unit = fields[t["field"]].get("unit")
        wanted = "Hz" if t["name"] == "output" else "s"
        if unit != wanted:
            raise spec.error((*path, "field"), f"the {t['name']} timer needs a field in {wanted}, not {unit}")
    return timers
