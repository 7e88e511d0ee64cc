"""The model's state machine: states, events, timers, the expanded transition table and the
answers it sends (part of generator.model).

The protocol words a transition uses (timer events, answer kinds) are defined here once and
read by validate, the model build and every target.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SmState:
    """A state of the device: its operating mode, and what it waits for."""

    name: str
    mode: str
    doc: str
    expects: str | None = None  # the parameter block (payload name) this state waits for
    timer: str | None = None  # alignment, accumulation or output
    erratum: str | None = None


@dataclass(frozen=True)
class SmEvent:
    """An event besides the commands: a message that is not a command, or a timer."""

    name: str
    doc: str


@dataclass(frozen=True)
class Transition:
    """One cell of the table: in `state`, on `event`, go to `to` and send `send`."""

    state: str
    event: str  # a command name or an SmEvent name
    to: str
    send: tuple[str, ...]
    wildcard: bool = False  # from a `*` row
    firmware_before: str | None = None  # only on firmware older than this
    erratum: str | None = None
    effect: str | None = None  # store_parameters, save_calibration, clear_calibration


@dataclass(frozen=True)
class SmTimer:
    """A timer of the device and the parameter field that sets it (seconds, or Hz for output)."""

    name: str
    payload: str
    field: str


TIMER_EVENTS = {"alignment": "alignment_done", "accumulation": "accumulation_done", "output": "output_due"}

# The words a transition's `send` list is made of (spec/README.md): the acknowledgement, one block of
# the current output format, one output block whose USW reports a given mode (OUTPUT_MODE_PREFIX +
# the mode's name), or a payload table's name. Every target reads them from here.
ANSWER_ACK = "ack"
ANSWER_OUTPUT = "output"
OUTPUT_MODE_PREFIX = "output_"


@dataclass(frozen=True)
class Answer:
    """One kind of answer the state machine sends: `kind` is "ack", "output", "output_mode" (`mode`
    set) or "payload" (`payload` set)."""

    name: str
    kind: str
    doc: str
    payload: str | None = None
    mode: str | None = None


def answer_kind(name: str, payloads: set[str], usw_modes: set[str]) -> Answer | None:
    """What a `send` word means, or None if it is none of the words above."""
    if name in payloads:
        return Answer(name, "payload", f"One {name} data block.", payload=name)
    if name == ANSWER_ACK:
        return Answer(name, "ack", "The acknowledgement of the message just received.")
    if name == ANSWER_OUTPUT:
        return Answer(name, "output", "One block of the output format chosen by the start command.")
    mode = name.removeprefix(OUTPUT_MODE_PREFIX)
    if name.startswith(OUTPUT_MODE_PREFIX) and mode in usw_modes:
        return Answer(name, "output_mode", f"One output block whose USW reports mode {mode} (E35).", mode=mode)
    return None


@dataclass(frozen=True)
class StateMachine:
    icd: str
    initial: str
    states: tuple[SmState, ...]
    events: tuple[SmEvent, ...]
    transitions: tuple[Transition, ...]  # expanded: one per (state, event), explicit rows first
    parameter_block_timeout_s: float
    default_alignment_time_s: float
    default_update_rate_hz: float
    result_delay_s: float
    timers: tuple[SmTimer, ...] = ()
    min_successful_runs: int | None = None
    answers: tuple[Answer, ...] = ()  # every answer the table sends, in first-use order (`sends`)

    def timer(self, name: str) -> SmTimer:
        for t in self.timers:
            if t.name == name:
                return t
        raise KeyError(name)

    def state(self, name: str) -> SmState:
        for s in self.states:
            if s.name == name:
                return s
        raise KeyError(name)

    @property
    def sends(self) -> tuple[str, ...]:
        """Every kind of answer the table uses, in first-use order."""
        seen: list[str] = []
        for t in self.transitions:
            for item in t.send:
                if item not in seen:
                    seen.append(item)
        return tuple(seen)

    def lookup(self, state: str, event: str, legacy: bool = False) -> Transition | None:
        """The transition for `event` in `state`, or None (ignored). `legacy`: firmware older than
        a row's `firmware_before` (such rows take precedence there)."""
        if legacy:
            for t in self.transitions:
                if t.state == state and t.event == event and t.firmware_before is not None:
                    return t
        for t in self.transitions:
            if t.state == state and t.event == event and t.firmware_before is None:
                return t
        return None

    def rows(self, state: str) -> tuple[Transition, ...]:
        return tuple(t for t in self.transitions if t.state == state)
