"""sessions: the device from power-up, fed commands, data messages and timers; the expected steps
come from device_oracle.py.

Two parts: every input in every state (the shortest way there, then one input), and the flows of
cases/sessions.json. A flow's inputs are words:
    "AHRScont1"            the command frame of that Table C.1 row
    "0x2D"                 a command frame with that code (in Table C.1 or not)
    "ahrs_parameters_load" a data message of that payload table's size (Table 6.9: 50 bytes)
    "data-49"              a data message of 49 bytes
    "output_due"           a timer event: output_due, alignment_done, accumulation_done, block_timeout
    "@setup"               the inputs of the named sequence ("sequences"), or of "@path": the way
                           to the state in a flow written for every state
A flow ends in a state, checked against the oracle, and may name the device's firmware. A family
of flows gives rows ("each") whose values fill the {names} of its flows' ids, inputs and notes (a
row may also set "firmware" and "ends"); a family written for every state ("each_state") fills
{state}, {mode}, {path} (the way there, described) and, from its tables keyed by a state,
"mode <mode>" or "default", the rest.
"""

from __future__ import annotations

from typing import Any

import device_oracle as d
import oracle as o

from .common import ICD, Vector, cases, vec

SUITE = "sessions"


def _input_json(item: d.Input) -> dict[str, Any]:
    kind, value = item
    if kind == "command":
        assert isinstance(value, int)
        return {"command": f"0x{value:02X}"}
    return {kind: value}


def input_label(item: d.Input) -> str:
    """How a vector id names an input: 0x80, data-50, output_due."""
    kind, value = item
    if kind == "command":
        assert isinstance(value, int)
        return f"0x{value:02X}"
    return f"data-{value}" if kind == "data" else str(value)


def _session_vec(
    id_: str, items: list[d.Input], note: str, *, firmware: str | None = None, ends: str | None = None
) -> Vector:
    """The steps the oracle's device takes on `items` from power-up; `ends`: the state it must end in."""
    device = d.Device(firmware)
    steps = device.run(items)
    if ends is not None:  # the intended end of the flow, cross-checked against the oracle
        assert device.state == ends, (id_, device.state, ends)
    input_: dict[str, Any] = {} if firmware is None else {"firmware": firmware}
    input_["events"] = [_input_json(item) for item in items]
    return vec(id_, "session", input_, {"steps": [s.expect() for s in steps], "state": device.state}, note)


def _describe(items: list[d.Input]) -> str:
    device = d.Device()
    return ", ".join(step.event for step in device.run(items)) or "power-up"


def _single_steps() -> list[Vector]:
    """Every input in every state: the shortest way there, then one input."""
    out: list[Vector] = []
    for state, path in d.reach().items():
        for item in d.inputs():
            device = d.Device()
            device.run(path)
            step = device.feed(item)
            if d.react(state, step.event) is None:
                outcome = f"{step.event} is ignored: no answer, no change (E33)"
            else:
                sent = " + ".join(step.send) or "nothing"
                outcome = f"{step.event} goes to {step.state} and sends {sent}"
            note = f"ICD {d.SOURCES[state]}; {state} (mode {d.MODES[state]}) by {_describe(path)}; then {outcome}"
            out.append(_session_vec(f"step/{state}/{input_label(item)}", [*path, item], note))
    return out


class Flows:
    """Reads the flows of the case file into vectors."""

    def __init__(self, sequences: dict[str, list[str]]) -> None:
        self.sequences = sequences
        self.codes = {row.name: row.code for row in o.table_c1()}
        self.out: list[Vector] = []

    def inputs(self, words: list[str], paths: dict[str, list[d.Input]]) -> list[d.Input]:
        items: list[d.Input] = []
        for word in words:
            if word.startswith("@"):
                name = word[1:]
                items += paths[name] if name in paths else self.inputs(self.sequences[name], paths)
            else:
                items.append(self._input(word))
        return items

    def _input(self, word: str) -> d.Input:
        if word.startswith("0x"):
            return ("command", int(word, 16))
        if word in d.EVENTS:
            return ("event", word)
        if word in o.TABLES:
            return ("data", o.TABLES[word][1])  # sizes as printed in the ICD tables
        if word.startswith("data-"):
            return ("data", int(word[5:]))
        return ("command", self.codes[word])

    def flow(self, flow: dict[str, Any], row: dict[str, Any], paths: dict[str, list[d.Input]]) -> None:
        """One flow; `row` fills the {names} of a family's id, inputs and note."""
        words = [word.format_map(row) for word in flow["inputs"]]
        firmware = row.get("firmware", flow.get("firmware"))
        note = f"{ICD} {flow['note'].format_map(row)}"
        ends = row["ends"] if "ends" in row else flow["ends"]  # every flow says where it must end
        vector = _session_vec(
            f"flow/{flow['id'].format_map(row)}", self.inputs(words, paths), note, firmware=firmware, ends=ends
        )
        self.out.append(vector)

    def entry(self, entry: dict[str, Any]) -> None:
        """A flow, or a family: "flows" written once per row of "each", or once per state ("each_state")."""
        if "each" in entry:
            for row in entry["each"]:
                for flow in entry["flows"]:
                    self.flow(flow, row, {})
        elif "each_state" in entry:
            for state, path in d.reach().items():
                row = {"state": state, "mode": d.MODES[state], "path": _describe(path)}
                row |= {key: _by_state(table, state) for key, table in entry["each_state"].items()}
                for flow in entry["flows"]:
                    self.flow(flow, row, {"path": path})
        else:
            self.flow(entry, {}, {})


def _by_state(table: dict[str, str], state: str) -> str:
    """A value for the state: keyed by the state, else by "mode <its mode>", else "default"."""
    return table.get(state, table.get(f"mode {d.MODES[state]}", table["default"]))


def vectors() -> list[Vector]:
    data = cases(SUITE)
    flows = Flows(data["sequences"])
    for entry in data["flows"]:
        flows.entry(entry)
    return _single_steps() + flows.out
