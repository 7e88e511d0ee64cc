"""The build of the state machine (part of the model build, generator/model/build.py): the spec's
rows expanded into one transition per (state, event), and the answers the table sends."""

from __future__ import annotations

from typing import Any

from .machine import Answer, SmEvent, SmState, SmTimer, StateMachine, Transition, answer_kind
from .text import prose


def _transition(state: str, event: str, row: dict[str, Any], wildcard: bool) -> Transition:
    """The cell a spec row gives `event` in `state`; a `*` row carries no firmware bound or effect."""
    return Transition(
        state=state,
        event=event,
        to=state if row["to"] == "same" else row["to"],
        send=tuple(row["send"]),
        wildcard=wildcard,
        firmware_before=None if wildcard else row.get("firmware_before"),
        erratum=row.get("erratum"),
        effect=None if wildcard else row.get("effect"),
    )


def _transitions(rows: list[dict[str, Any]], commands: list[str]) -> list[Transition]:
    """Expand the rows of the spec into one transition per (state, event): explicit rows first, then
    each `*` row for every command its states have no explicit row for."""
    explicit: list[Transition] = []
    wildcards: list[tuple[str, dict[str, Any]]] = []
    for row in rows:
        for state in row["from"]:
            for event in row["when"]:
                if event == "*":
                    wildcards.append((state, row))
                else:
                    explicit.append(_transition(state, event, row, wildcard=False))
    covered = {(t.state, t.event) for t in explicit if t.firmware_before is None}
    expanded = list(explicit)
    for state, row in wildcards:
        for command in commands:
            if (state, command) not in covered:
                covered.add((state, command))
                expanded.append(_transition(state, command, row, wildcard=True))
    return expanded


def _answers(transitions: list[Transition], payloads: set[str], usw_modes: set[str]) -> tuple[Answer, ...]:
    """Every answer the transitions send, in first-use order (validate has checked each word)."""
    seen: dict[str, Answer] = {}
    for t in transitions:
        for item in t.send:
            answer = answer_kind(item, payloads, usw_modes)
            if answer is None:
                raise ValueError(f"the state machine sends {item!r}: neither ack, output, output_MODE nor a payload")
            seen.setdefault(item, answer)
    return tuple(seen.values())


def state_machine(raw: dict[str, Any], commands: list[str], payloads: set[str], usw_modes: set[str]) -> StateMachine:
    expanded = _transitions(raw["transitions"], commands)
    timing = raw["timing"]
    return StateMachine(
        icd=raw.get("icd", ""),
        initial=raw["initial"],
        states=tuple(
            SmState(
                name=st["name"],
                mode=st["mode"],
                doc=prose(st["doc"]),
                expects=st.get("expects"),
                timer=st.get("timer"),
                erratum=st.get("erratum"),
            )
            for st in raw["states"]
        ),
        events=tuple(SmEvent(e["name"], prose(e["doc"])) for e in raw["events"]),
        transitions=tuple(expanded),
        parameter_block_timeout_s=float(timing["parameter_block_timeout_s"]),
        default_alignment_time_s=float(timing["default_alignment_time_s"]),
        default_update_rate_hz=float(timing["default_update_rate_hz"]),
        result_delay_s=float(timing["result_delay_s"]),
        timers=tuple(SmTimer(t["name"], t["payload"], t["field"]) for t in raw.get("timers", ())),
        min_successful_runs=raw["calibration"]["min_successful_runs"] if "calibration" in raw else None,
        answers=_answers(expanded, payloads, usw_modes),
    )
