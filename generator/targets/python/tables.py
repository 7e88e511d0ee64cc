"""What the Python target's tables need from the model, derived once, and the pretty-printer of
their text: the state machine's tables (transitions, timers, output formats, calibration types,
effects), the Mermaid drawing of the package README, and the simulator's quantity rule applied to
a model field (for checks of the spec against the device model)."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from generator.model import ANSWER_ACK, ANSWER_OUTPUT, OUTPUT_MODE_PREFIX, TIMER_EVENTS, Field, Spec, Transition

from .runtime import diagram
from .runtime.session import synthetic


def _machine(spec: Spec) -> Any:
    if spec.state_machine is None:
        raise KeyError("the spec has no state_machine")
    return spec.state_machine


def transitions(spec: Spec, legacy: bool = False) -> list[Transition]:
    """The expanded transitions: the current ones (one per (state, event)), or only the rows that
    apply before a firmware version."""
    return [t for t in _machine(spec).transitions if (t.firmware_before is not None) == legacy]


def timer_field(spec: Spec, timer: str) -> tuple[str, str]:
    """(payload, field) of the host-to-device parameter that sets a timer (`state_machine.timers`)."""
    entry = _machine(spec).timer(timer)
    return entry.payload, entry.field


def output_formats(spec: Spec) -> dict[str, str | None]:
    """Output format (a start command's `starts.output`) -> payload name, or None for $PAHR
    sentences (the format named after the spec's `nmea` section)."""
    names = {p.name for p in spec.payloads}
    result: dict[str, str | None] = {}
    for c in spec.commands:
        if c.starts_output is None or c.starts_output in result:
            continue
        if c.starts_output in names:
            result[c.starts_output] = c.starts_output
        elif c.starts_output == "nmea" and spec.nmea is not None:
            result[c.starts_output] = None
        else:
            raise KeyError(f"{c.name} starts output {c.starts_output!r}: neither a payload nor the nmea sentence")
    return result


def default_firmware(spec: Spec) -> str:
    """The newest firmware version the spec mentions: a device that has every current behaviour."""
    sm = spec.state_machine
    versions = [t.firmware_before for t in sm.transitions if t.firmware_before] if sm is not None else []
    for c in spec.commands:
        versions += [f.until_firmware for f in c.former_names if f.until_firmware]
    if not versions:
        return "0"
    return max(versions, key=lambda v: tuple(int(p) for p in v.split(".")))


def machine_tables(spec: Spec) -> dict[str, Any]:
    """The tables of `ilahrs.statemachine` besides states and events, from the model."""
    sm = _machine(spec)
    if sm.min_successful_runs is None:
        raise KeyError("the spec's state_machine has no calibration.min_successful_runs")
    by_name = {v.name: v.value for v in spec.enum("calibration_type").values}
    commands = {c.name for c in spec.commands}
    timers = sorted({s.timer for s in sm.states if s.timer is not None})
    shared: dict[tuple[int, str], str] = {}
    for code in spec.codes:
        if len(spec.commands_with_code(code)) > 1:
            for mode in spec.modes:
                command = spec.command_in_mode(code, mode.name)
                if command is not None:
                    shared[(code, mode.name)] = command.name
    timer_fields = {timer: timer_field(spec, timer) for timer in timers if timer in TIMER_EVENTS}
    rates = {timer: spec.payload(table).field(name).unit for timer, (table, name) in timer_fields.items()}
    return {
        "transitions": transitions(spec),
        "legacy": transitions(spec, True),
        "timer_events": {timer: TIMER_EVENTS[timer] for timer in timers},
        "timer_fields": timer_fields,
        "timer_is_rate": {timer: unit is not None and unit.key == "Hz" for timer, unit in rates.items()},
        "output_formats": output_formats(spec),
        "calibration_types": {c.name: by_name[c.begins_calibration] for c in spec.commands if c.begins_calibration},
        "effects": {t.event: t.effect for t in sm.transitions if t.effect is not None and t.event in commands},
        "min_successful_runs": sm.min_successful_runs,
        "default_firmware": default_firmware(spec),
        "shared_codes": shared,
    }


def mermaid(spec: Spec) -> str:
    """The state machine as a Mermaid state diagram, as `ilahrs diagram` prints it."""
    sm = _machine(spec)
    rows = [*transitions(spec), *transitions(spec, True)]
    modes = {st.name: st.mode for st in sm.states}
    table = [(t.state, t.event, t.to, t.send, t.wildcard, t.firmware_before) for t in rows]
    return diagram.mermaid(sm.initial, table, modes)


def quantity(field: Field) -> tuple[str, ...]:
    """The synthetic quantities the virtual device puts in a model field (`ilahrs.session.synthetic`)."""
    unit = field.unit.key if field.unit is not None else None
    return synthetic.quantity(field.name, unit, field.type.name, field.encoding, field.multiplexed_count or 0)


def py_text(text: str, indent: int, width: int = 116) -> str:
    """A string literal that fits the line length: one literal, or implicitly concatenated pieces
    in parentheses, each on its own line at `indent` (+4) spaces."""
    if indent + len(repr(text)) <= width - 8:
        return repr(text)
    pieces: list[str] = []
    current = ""
    for word in re.split(r"(?<= )(?=[^ ])", text):
        if current and indent + 4 + len(repr(current + word)) > width:
            pieces.append(current)
            current = word
        else:
            current += word
    pieces.append(current)
    pad = " " * (indent + 4)
    return "(\n" + "".join(f"{pad}{piece!r}\n" for piece in pieces) + " " * indent + ")"


FILTERS: dict[str, Callable[..., Any]] = {"py_text": py_text}

GLOBALS: dict[str, Any] = {
    "machine_tables": machine_tables,
    "mermaid": mermaid,
    "answer_ack": ANSWER_ACK,
    "answer_output": ANSWER_OUTPUT,
    "output_mode_prefix": OUTPUT_MODE_PREFIX,
}
