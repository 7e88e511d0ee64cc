"""The docs target: a protocol reference and the state diagram, drawn from the spec."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from generator.model import Field, Spec, StateMachine, Transition
from generator.render import Output
from generator.targets.python.runtime import diagram

# Files in generated/docs/ that are rendered from generated files by make (mk/docs.mk), not by
# templates: the drift check leaves them to `make check-docs`.
DERIVED = ("docs/state-machine.svg",)


def outputs(spec: Spec) -> list[Output]:
    files = [
        Output("docs/protocol.md", "protocol.md.j2"),
        Output("docs/errata.md", "errata.md.j2"),
    ]
    if spec.state_machine is not None:
        files += [
            Output("docs/state-machine.md", "state-machine.md.j2"),
            Output("docs/state-machine.dot", "state-machine.dot.j2"),
        ]
    return files


def cell(text: object) -> str:
    """Text safe inside a Markdown table cell."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def wire_type(field: Field) -> str:
    return f"{field.kind}[{field.size}]" if field.is_bytes else field.type.name


def scale_text(field: Field) -> str:
    if field.scale is None:
        return ""
    s = field.scale
    parts = []
    if s.divisor_parameter is not None:
        parts.append(f"/ {s.divisor_parameter}")
    elif s.divisor not in (None, 1):
        parts.append(f"/ {s.divisor}")
    if s.multiplier != 1:
        parts.append(f"x {s.multiplier}")
    return " ".join(parts)


def send_text(t: Transition) -> str:
    return ", ".join(t.send) if t.send else "nothing"


def _wrap(line: str, width: int = 28) -> str:
    """A label line broken after a comma where it passes `width` characters (Graphviz's newline)."""
    out = ""
    current = ""
    for part in line.split(", "):
        if current and len(current) + 2 + len(part) > width:
            out += current + ",\\n"
            current = part
        else:
            current = f"{current}, {part}" if current else part
    return out + current


def drawing(sm: StateMachine) -> dict[str, list[dict[str, Any]]]:
    """The state diagram: the arrows of `ilahrs diagram` (one per from, to and firmware condition,
    labelled with one line per answer and the events giving it; wildcard rows read `any other
    command`; a transition every state of a mode has drawn once, from a note standing for any state
    of the mode), with each state's self-loop written in its box (`stays`) instead of drawn.
    `states`: name, mode, stays; `notes`: name, mode; `arrows`: from, to, label, legacy."""
    rows = [(t.state, t.event, t.to, t.send, t.wildcard, t.firmware_before) for t in sm.transitions]
    taken = {st.name for st in sm.states}
    notes: dict[str, str] = {}
    stays: dict[str, list[str]] = {}
    arrows = []
    for e in diagram.fold(rows, modes={st.name: st.mode for st in sm.states}):
        if e.whole_mode and e.state not in notes:
            name = f"mode_{e.state}"
            while name in taken:
                name += "_"
            notes[e.state] = name
            taken.add(name)
        lines = [_wrap(line) for line in e.label("\n").split("\n")]
        if e.state == e.to and not e.whole_mode and e.firmware is None:
            stays.setdefault(e.state, []).extend(lines)
            continue
        origin = notes[e.state] if e.whole_mode else e.state
        arrows.append({"from": origin, "to": e.to, "label": "\\n".join(lines), "legacy": e.firmware is not None})
    return {
        "states": [{"name": st.name, "mode": st.mode, "stays": "\\n".join(stays.get(st.name, []))} for st in sm.states],
        "notes": [{"name": name, "mode": mode} for mode, name in notes.items()],
        "arrows": arrows,
    }


FILTERS: dict[str, Callable[..., Any]] = {
    "cell": cell,
    "wire_type": wire_type,
    "scale_text": scale_text,
    "send_text": send_text,
    "drawing": drawing,
}
