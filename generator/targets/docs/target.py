"""The docs target: a protocol reference and the state diagram, drawn from the spec."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from generator.model import Field, Spec, StateMachine, Transition
from generator.render import Output

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
    answer listing the events that give it. Wildcard rows read `any other command`."""
    grouped: dict[tuple[str, str, str | None], dict[tuple[str, ...], list[str]]] = {}
    for t in sm.transitions:
        lines = grouped.setdefault((t.state, t.to, t.firmware_before), {})
        events = lines.setdefault(t.send, [])
        name = "any other command" if t.wildcard else t.event
        if name not in events:
            events.append(name)
    result = []
    for (state, to, firmware), lines in grouped.items():
        label = "\\n".join(
            ", ".join(events) + (" / " + ", ".join(send) if send else "") for send, events in lines.items()
        )
        if firmware:
            label += f"\\n(firmware < {firmware})"
        result.append({"from": state, "to": to, "label": label, "legacy": firmware is not None})
    return result


FILTERS: dict[str, Callable[..., Any]] = {
    "cell": cell,
    "wire_type": wire_type,
    "scale_text": scale_text,
    "send_text": send_text,
    "edges": edges,
}
