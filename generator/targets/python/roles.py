"""The part each command plays in the flows of the serial client and the device model, found from
the spec's structure (what a command answers in the initial state, which block it takes and where
that leads, the effects of its transitions, the timers), never from its name.

The generated `ilahrs.roles` lists the result; the runtime reads the tables a role points to
(`COMMANDS[READ_PARAMETERS].response_payloads`, ...). A spec in which a role is missing or
ambiguous is refused here, when the package is generated.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from generator.model import ANSWER_OUTPUT, TIMER_EVENTS, Spec, StateMachine, Transition

_BLOCK_EVENT = "parameter_block"
"""The spec's event for the parameter block a state waits for."""


@dataclass(frozen=True)
class Role:
    name: str
    command: str
    doc: str


def _one(found: Iterable[str], role: str) -> str:
    names = sorted(set(found))
    if len(names) != 1:
        raise KeyError(f"the Python runtime needs exactly one command that {role}; the spec has {names or 'none'}")
    return names[0]


class _Structure:
    """The state machine and commands, with the questions the roles ask of them."""

    def __init__(self, spec: Spec) -> None:
        if spec.state_machine is None:
            raise KeyError("the spec has no state_machine")
        self.spec = spec
        self.sm: StateMachine = spec.state_machine
        self.payloads = {p.name: p for p in spec.payloads}

    def current(self, state: str, event: str) -> Transition | None:
        t = self.sm.lookup(state, event)
        return None if t is None or t.wildcard else t

    def from_state(self, state: str) -> dict[str, Transition]:
        """Command -> its own (not `*`) transition in `state`."""
        found = {c.name: self.current(state, c.name) for c in self.spec.commands}
        return {name: t for name, t in found.items() if t is not None}

    def after_block(self, state: str) -> str:
        """The state a parameter block leads to from the state that waits for it."""
        t = self.current(state, _BLOCK_EVENT)
        assert t is not None, f"{state} waits for a block but has no {_BLOCK_EVENT} row"
        return t.to

    def idle_answers(self) -> dict[str, str]:
        """Command -> the payload table of the one data block it answers in the initial state."""
        answers = {}
        for name, t in self.from_state(self.sm.initial).items():
            if len(t.send) == 1 and t.send[0] in self.payloads:
                answers[name] = t.send[0]
        return answers

    def answering(self, test: str, role: str) -> str:
        """The command whose initial-state answer has a field passing `test` (an encoding, or "text")."""
        found = []
        for name, table in self.idle_answers().items():
            fields = [f for f in self.payloads[table].fields if f.kind != "reserved"]
            if [f.kind for f in fields] == ["char"] if test == "text" else any(f.encoding == test for f in fields):
                found.append(name)
        return _one(found, role)

    def with_effect(self, effect: str) -> list[Transition]:
        return [t for t in self.sm.transitions if t.effect == effect]


def _parameters(s: _Structure) -> tuple[str, str]:
    """(load, read): the command whose block is stored (effect store_parameters) and the command
    answering in the initial state with a block that holds every value the load block carries."""
    stored = {t.state for t in s.with_effect("store_parameters")}
    load = _one(
        (name for name, t in s.from_state(s.sm.initial).items() if t.to in stored),
        "takes the parameter block that is stored (effect store_parameters)",
    )
    block = s.spec.command(load).parameter_block
    assert block is not None
    values = {f.name for f in s.payloads[block].fields if f.kind != "reserved"}
    read = _one(
        (name for name, table in s.idle_answers().items() if values <= {f.name for f in s.payloads[table].fields}),
        f"answers with every value of {block}",
    )
    return load, read


def _stop(s: _Structure) -> str:
    """The command that brings every state of an output mode back to the initial state."""
    modes = {c.starts_mode for c in s.spec.commands if c.starts_mode is not None}
    states = [st.name for st in s.sm.states if st.mode in modes]
    found = []
    for c in s.spec.commands:
        targets = {t.to if t is not None else None for t in (s.current(st, c.name) for st in states)}
        if targets == {s.sm.initial}:
            found.append(c.name)
    return _one(found, "brings every output state back to the initial state")


def _low_power(s: _Structure) -> tuple[str, str]:
    """(on, off): the command from the initial state to the one state that neither waits for a
    block nor runs a timer, and the command back."""
    plain = {st.name for st in s.sm.states if st.expects is None and st.timer is None and st.name != s.sm.initial}
    on = _one((n for n, t in s.from_state(s.sm.initial).items() if t.to in plain), "enters low power")
    asleep = s.from_state(s.sm.initial)[on].to
    off = _one((n for n, t in s.from_state(asleep).items() if t.to == s.sm.initial), "leaves low power")
    return on, off


def _calibration(s: _Structure) -> dict[str, str]:
    """The multi-run calibration: the start command whose block leads to a state between runs
    (no timer), the command there that starts a run (it takes a block), the one that finishes
    (it leads to the state where the result is accepted), the one that stops a run's accumulation
    early (it does what the accumulation timer does), and accept and clear (their effects)."""
    accept = _one((t.event for t in s.with_effect("save_calibration")), "saves the calibration")
    clear = _one((t.event for t in s.with_effect("clear_calibration")), "clears the calibration")
    starts: dict[str, str] = {}
    for c in s.spec.commands:
        t = s.current(s.sm.initial, c.name)
        if c.begins_calibration and t is not None and s.sm.state(t.to).expects is not None:
            starts[c.name] = s.after_block(t.to)
    multi = _one((n for n, st in starts.items() if s.sm.state(st).timer is None), "starts a multi-run calibration")
    between = starts[multi]
    deciding = {t.state for t in s.sm.transitions if t.event == accept and not t.wildcard}
    here = s.from_state(between)
    run = _one((n for n in here if s.spec.command(n).parameter_block is not None), "starts a calibration run")
    finish = _one((n for n, t in here.items() if t.to in deciding), "finishes a multi-run calibration")
    stop_run = []
    for st in s.sm.states:
        timed = s.current(st.name, TIMER_EVENTS["accumulation"]) if st.timer == "accumulation" else None
        for name, t in s.from_state(st.name).items():
            if timed is not None and (t.to, t.send) == (timed.to, timed.send):
                stop_run.append(name)
    return {
        "start_runs": multi,
        "start_run": run,
        "stop_run": _one(stop_run, "ends an accumulation early"),
        "finish": finish,
        "accept": accept,
        "clear_calibration": clear,
    }


def roles(spec: Spec) -> dict[str, object]:
    """Every role with its command, and the table of the parameter memory (what READ_PARAMETERS answers)."""
    s = _Structure(spec)
    load, read = _parameters(s)
    on, off = _low_power(s)
    commands = {c.name for c in spec.commands}
    output = [t.event for t in s.sm.transitions if t.send == (ANSWER_OUTPUT,) and t.event in commands]
    found = {
        "stop": (_stop(s), "Back to the initial state from every output state (its code also leaves calibration)."),
        "read_parameters": (read, "Read the parameter memory: the block with every value the load block carries."),
        "load_parameters": (load, "Load the parameter block that the device stores."),
        "firmware": (s.answering("text", "answers with one text field"), "Read the firmware version text."),
        "built_in_test": (s.answering("usw", "answers with the USW in idle"), "Read the built-in test and USW."),
        "calibration_results": (
            s.answering("calibration_success", "answers with the saved calibration"),
            "Read the results of the last calibration.",
        ),
        "get_data": (_one(output, "asks for one output block"), "Ask for one output block (on-request mode)."),
        "low_power_on": (on, "Enter the low-power state."),
        "low_power_off": (off, "Leave the low-power state."),
    }
    docs = {
        "start_runs": "Start a multi-run (2D-2T) calibration.",
        "start_run": "Start one run of a multi-run calibration.",
        "stop_run": "End a run's data accumulation early.",
        "finish": "Finish a multi-run calibration and compute its result.",
        "accept": "Accept and save the calibration result (effect save_calibration).",
        "clear_calibration": "Clear the saved calibration (effect clear_calibration).",
    }
    found |= {role: (name, docs[role]) for role, name in _calibration(s).items()}
    parameter_block = spec.command(read).response_payloads[0]
    return {
        "commands": [Role(role, name, doc) for role, (name, doc) in found.items()],
        "parameter_block": spec.payload(parameter_block),
    }
