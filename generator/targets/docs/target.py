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


def edges(sm: StateMachine) -> list[dict[str, Any]]:
    """The diagram's arrows: one per (from, to, firmware condition), labelled with one line per
    answer listing the events that give it (the folding of `ilahrs diagram`, shared with the Python
    runtime). Wildcard rows read `any other command`."""
    rows = [(t.state, t.event, t.to, t.send, t.wildcard, t.firmware_before) for t in sm.transitions]
    return [
        {"from": e.state, "to": e.to, "label": e.label("\\n"), "legacy": e.firmware is not None}
        for e in diagram.fold(rows)
    ]


FILTERS: dict[str, Callable[..., Any]] = {
    "cell": cell,
    "wire_type": wire_type,
    "scale_text": scale_text,
    "send_text": send_text,
    "edges": edges,
}
