"""The device state machine as compact C tables, derived from `spec.state_machine`.

The C library looks a (state, event) pair up in a sparse table whose cells index a short list of
distinct outcomes (next state, answer sequence); sequences index one flat list of answers. Most
events do the same in a state (nothing, or, while a parameter block is awaited, back to idle),
so each state has a default cell and the table lists only the cells that differ from their
state's default, as packed (state, event, cell) entries. Rows marked `firmware_before` go to a
separate list checked first. Events are the commands in `ilahrs_command_t` order (so a command's
event has the command's value), then the spec's other events. Nothing here is written by hand:
states, events, answers and every cell come from the model, in the model's order.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from generator.model import TIMER_EVENTS, Spec

IGNORED = 0
"""Cell value of a (state, event) pair without a transition (E33)."""

# The C documentation of the answers that are not payload tables (the model defines the words).
ACK_DOC = "The acknowledgement of the message just received (ilahrs_ack_build(), E12)."
OUTPUT_DOC = "One block of the output format the start command chose (a frame, or a $PAHR sentence)."


@dataclass(frozen=True)
class Outcome:
    to: int  # state index
    sequence: int  # index into Machine.sequences


@dataclass(frozen=True)
class LegacyRow:
    state: int
    event: int
    outcome: int  # index into Machine.outcomes
    version: tuple[int, ...]
    erratum: str | None


@dataclass(frozen=True)
class Answer:
    name: str
    payload: str | None  # the payload table it sends, if it is one
    usw_mode: str | None  # output_<mode>: the USW mode the output block reports
    doc: str


@dataclass(frozen=True)
class MachinePacking:
    """Bit widths of the packed C tables: an exception is (state * events + event) << cell_bits |
    cell; an outcome is state << sequence_bits | sequence."""

    cell_bits: int
    key_bits: int
    exception_type: str
    sequence_bits: int
    outcome_type: str


def bits_for(count: int) -> int:
    """Bits that hold the values 0 .. count - 1 (at least one)."""
    return max(1, (count - 1).bit_length())


def packed_type(bits: int, what: str) -> str:
    if bits > 32:
        raise ValueError(f"the state machine's {what} need {bits} bits: more than the C table's 32")
    return "uint8_t" if bits <= 8 else "uint16_t" if bits <= 16 else "uint32_t"


def machine_packing(states: int, events: int, outcomes: int, sequences: int) -> MachinePacking:
    cell_bits = bits_for(outcomes + 1)  # outcome index + 1, 0: ignored
    key_bits = bits_for(states * events)
    sequence_bits = bits_for(sequences)
    return MachinePacking(
        cell_bits=cell_bits,
        key_bits=key_bits,
        exception_type=packed_type(key_bits + cell_bits, "table cells"),
        sequence_bits=sequence_bits,
        outcome_type=packed_type(bits_for(states) + sequence_bits, "outcomes"),
    )


@dataclass
class Machine:
    states: list[str]
    events: list[str]  # commands (ICD names) first, then the other events
    extra_events: list[str]
    answers: list[Answer]
    sequences: list[tuple[int, ...]]  # answer indices
    sequence_start: list[int]  # offset of each sequence in flat_answers
    flat_answers: list[int]
    outcomes: list[Outcome]
    cells: list[list[int]]  # [state][event] -> outcome index + 1, or IGNORED
    defaults: list[int]  # per state: its most frequent cell
    exceptions: list[tuple[int, int, int]]  # (state, event, cell) of the cells that differ from their default
    packing: MachinePacking
    legacy: list[LegacyRow]
    send_max: int
    versions: list[tuple[int, ...]]
    version_parts_max: int
    timer_events: list[int | None]  # per state: the event its timer fires
    expects: list[str | None]  # per state: the payload table it waits for
    wildcard_note: dict[tuple[int, int], bool]


def parse_version(text: str) -> tuple[int, ...]:
    parts = text.split(".")
    if not all(p.isdigit() for p in parts):
        raise ValueError(f"firmware version {text!r} is not numeric parts separated by '.'")
    return tuple(int(p) for p in parts)


def build_machine(spec: Spec) -> Machine | None:
    sm = spec.state_machine
    if sm is None:
        return None
    states = [s.name for s in sm.states]
    if states[0] != sm.initial:
        # The C enum gives the initial state the value 0 so that a zeroed device is at power-up.
        states.remove(sm.initial)
        states.insert(0, sm.initial)
    extra = [e.name for e in sm.events]
    events = [c.name for c in spec.commands] + extra
    answers: list[Answer] = []
    for a in sm.answers:
        if a.payload is not None:
            p = spec.payload(a.payload)
            answers.append(Answer(a.name, a.payload, None, f"One {p.name} data block ({p.title}, {p.icd})."))
        else:
            doc = {"ack": ACK_DOC, "output": OUTPUT_DOC}.get(a.kind, a.doc)
            answers.append(Answer(a.name, None, a.mode, doc))
    answer_index = {a.name: k for k, a in enumerate(answers)}
    sequences: list[tuple[int, ...]] = []
    outcomes: list[Outcome] = []

    def outcome_of(to: str, send: tuple[str, ...]) -> int:
        seq = tuple(answer_index[a] for a in send)
        if seq not in sequences:
            sequences.append(seq)
        o = Outcome(states.index(to), sequences.index(seq))
        if o not in outcomes:
            outcomes.append(o)
        return outcomes.index(o)

    cells = [[IGNORED] * len(events) for _ in states]
    legacy: list[LegacyRow] = []
    wildcard: dict[tuple[int, int], bool] = {}
    for t in sm.transitions:
        s, e = states.index(t.state), events.index(t.event)
        k = outcome_of(t.to, t.send)
        if t.firmware_before is not None:
            legacy.append(LegacyRow(s, e, k, parse_version(t.firmware_before), t.erratum))
        elif cells[s][e] == IGNORED:
            cells[s][e] = k + 1
            wildcard[(s, e)] = t.wildcard
    defaults: list[int] = []
    exceptions: list[tuple[int, int, int]] = []
    for s, state_cells in enumerate(cells):
        counts = Counter(state_cells)
        default = max(sorted(counts), key=lambda cell: counts[cell])  # the most frequent, lowest on a tie
        defaults.append(default)
        exceptions.extend((s, e, cell) for e, cell in enumerate(state_cells) if cell != default)
    starts: list[int] = []
    flat: list[int] = []
    for seq in sequences:
        starts.append(len(flat))
        flat.extend(seq)
    versions: list[tuple[int, ...]] = []
    for row in legacy:
        if row.version not in versions:
            versions.append(row.version)
    by_name = {s.name: s for s in sm.states}
    return Machine(
        states=states,
        events=events,
        extra_events=extra,
        answers=answers,
        sequences=sequences,
        sequence_start=starts,
        flat_answers=flat,
        outcomes=outcomes,
        cells=cells,
        defaults=defaults,
        exceptions=exceptions,
        packing=machine_packing(len(states), len(events), len(outcomes), len(sequences)),
        legacy=legacy,
        send_max=max([1, *(len(s) for s in sequences)]),
        versions=versions,
        version_parts_max=max([4, *(len(v) for v in versions)]),
        timer_events=[_timer_event(by_name[s].timer, events) for s in states],
        expects=[by_name[s].expects for s in states],
        wildcard_note=wildcard,
    )


def _timer_event(timer: str | None, events: list[str]) -> int | None:
    return None if timer is None else events.index(TIMER_EVENTS[timer])
