"""The comparison of two laid-out models (not YAML text): every change, each with its named rule.

Payload tables are matched by name, a renamed table or field by its bytes; commands by name, a
code's meaning followed across renames; the state machine by what the device answers, state by
state and event by event; every other section by the generic walk, classified by section.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import Any

from ..model import Command, Field, Payload, Spec
from .fingerprint import device_answers, scale_of
from .rules import DOC_ATTRS, RULES, SKIPPED_ATTRS, WIRE_SECTIONS, Change, show


def _key(value: Any) -> Any:
    for attr in ("name", "key", "id", "part"):
        if hasattr(value, attr):
            return getattr(value, attr)
    if hasattr(value, "bit"):
        return value.bit
    return None


class _Differ:
    """Collects the changes between two laid-out models."""

    def __init__(self, old: Spec, new: Spec) -> None:
        self.old = old
        self.new = new
        self.changes: list[Change] = []
        self.payload_renames: dict[str, str] = {}
        self.command_renames: dict[str, str] = {}

    def add(self, rule: str, where: str, old: Any = None, new: Any = None) -> None:
        assert rule in RULES, rule
        if isinstance(old, str) and isinstance(new, str) and max(len(old), len(new)) > 60:
            # Long text: from a little before the first difference.
            start = next((i for i, (a, b) in enumerate(zip(old, new, strict=False)) if a != b), min(len(old), len(new)))
            start = max(0, start - 20)
            old, new = ("..." if start else "") + old[start:], ("..." if start else "") + new[start:]
        self.changes.append(Change(rule, where, "" if old is None else show(old), "" if new is None else show(new)))

    def run(self) -> list[Change]:
        self._payloads()
        self._commands()
        self._state_machine()
        handled = {"payloads", "commands", "state_machine", "ack_payload", "name"}
        for f in dataclasses.fields(Spec):
            if f.name in handled or f.name in SKIPPED_ATTRS:
                continue
            self._walk(getattr(self.old, f.name), getattr(self.new, f.name), f.name, f.name)
        old_ack, new_ack = self.old.ack_payload, self.new.ack_payload
        if self.payload_renames.get(old_ack or "", old_ack) != new_ack:
            self.add("COMMAND_RESPONSE_CHANGED", "acknowledgement.payload", old_ack, new_ack)
        return self.changes

    # The generic comparison: named tuples matched by name, values compared, classified by section.

    def _walk(self, old: Any, new: Any, where: str, section: str, attr: str = "") -> None:
        if old == new and not (dataclasses.is_dataclass(old) or isinstance(old, tuple)):
            return
        if attr in DOC_ATTRS:
            self.add("DOC_CHANGED", where, old, new)
            return
        if dataclasses.is_dataclass(old) and dataclasses.is_dataclass(new) and type(old) is type(new):
            for f in dataclasses.fields(old):
                if f.name not in SKIPPED_ATTRS:
                    self._walk(getattr(old, f.name), getattr(new, f.name), f"{where}.{f.name}", section, f.name)
            return
        if (
            isinstance(old, tuple)
            and isinstance(new, tuple)
            and all(_key(v) is not None for v in (*old, *new))
            and (old or new)
            and any(dataclasses.is_dataclass(v) for v in (*old, *new))
        ):
            olds = {_key(v): v for v in old}
            news = {_key(v): v for v in new}
            for k, v in olds.items():
                if k not in news:
                    self._removed(v, f"{where}[{k}]", section)
            for k, v in news.items():
                if k not in olds:
                    self._added(v, f"{where}[{k}]", section)
                else:
                    self._walk(olds[k], v, f"{where}[{k}]", section)
            return
        if old == new:
            return
        self.add(self._changed_rule(section, attr), where, old, new)

    def _changed_rule(self, section: str, attr: str) -> str:
        if section in WIRE_SECTIONS:
            return WIRE_SECTIONS[section]
        if section == "enums":
            return "ENUM_VALUE_CHANGED" if attr == "value" else "ENUM_CHANGED"
        if section == "variants":
            return "VARIANT_VALUE_CHANGED"
        if section == "units":
            return "UNIT_CHANGED"
        if section == "errata":
            return "DOC_CHANGED"
        return "FIELD_TYPE_CHANGED"

    def _removed(self, value: Any, where: str, section: str) -> None:
        if section in WIRE_SECTIONS:
            self.add(WIRE_SECTIONS[section], where, value, None)
        elif section == "errata":
            self.add("DOC_CHANGED", where, value, None)
        else:
            self.add("NAME_REMOVED", where, value, None)

    def _added(self, value: Any, where: str, section: str) -> None:
        if section == "status_word" and ".flags[" in where:
            self.add("NAME_ADDED", where, None, value)
        elif section in WIRE_SECTIONS:
            self.add(WIRE_SECTIONS[section], where, None, value)
        elif section == "errata":
            self.add("DOC_CHANGED", where, None, value)
        elif section == "enums" and ".values[" in where:
            self.add("ENUM_VALUE_ADDED", where, None, value)
        elif section == "variants":
            self.add("VARIANT_ADDED", where, None, value)
        else:
            self.add("NAME_ADDED", where, None, value)

    # Payload tables: fields by name, with renames and reserved areas recognised by their bytes.

    def _payloads(self) -> None:
        olds = {p.name: p for p in self.old.payloads}
        news = {p.name: p for p in self.new.payloads}
        gone = [p for n, p in olds.items() if n not in news]
        fresh = [p for n, p in news.items() if n not in olds]
        for p in gone:
            twin = next((q for q in fresh if _layout(q) == _layout(p) and q.direction == p.direction), None)
            if twin is not None:
                fresh.remove(twin)
                self.payload_renames[p.name] = twin.name
                self.add("NAME_RENAMED", f"payloads[{p.name}]", p.name, twin.name)
                self._payload(p, twin)
            else:
                self.add("NAME_REMOVED", f"payloads[{p.name}]", p.name, None)
        for p in fresh:
            self.add("PAYLOAD_ADDED", f"payloads[{p.name}]", None, f"{p.name} ({p.size} bytes)")
        for name, p in olds.items():
            if name in news:
                self._payload(p, news[name])

    def _payload(self, old: Payload, new: Payload) -> None:
        where = f"payloads[{new.name}]"
        for attr in ("title", "icd", "doc", "erratum"):
            if getattr(old, attr) != getattr(new, attr):
                self.add("DOC_CHANGED", f"{where}.{attr}", getattr(old, attr), getattr(new, attr))
        if old.size != new.size:
            self.add("PAYLOAD_SIZE_CHANGED", f"{where}.size", old.size, new.size)
        if old.direction != new.direction:
            self.add("PAYLOAD_DIRECTION_CHANGED", f"{where}.direction", old.direction, new.direction)
        self._fields(old.fields, new.fields, f"{where}.fields")

    def _fields(self, old: Sequence[Field], new: Sequence[Field], where: str) -> None:
        olds = {f.name: f for f in old if f.kind != "reserved"}
        news = {f.name: f for f in new if f.kind != "reserved"}
        gone = [f for n, f in olds.items() if n not in news]
        fresh = [f for n, f in news.items() if n not in olds]
        for f in list(gone):
            twin = next((g for g in fresh if _field_wire(g) == _field_wire(f)), None)
            if twin is not None:
                gone.remove(f)
                fresh.remove(twin)
                self.add("NAME_RENAMED", f"{where}[{f.name}]", f.name, twin.name)
                self._field(f, twin, f"{where}[{twin.name}]")
        old_reserved = [(f.offset, f.end) for f in old if f.kind == "reserved"]
        new_covered = [(f.offset, f.end) for f in new]
        for f in gone:
            self.add("NAME_REMOVED", f"{where}[{f.name}]", f"{f.name} at {f.offset}", None)
            if not any(a <= f.offset and f.end <= b for a, b in new_covered if (a, b) != (f.offset, f.end)) and not any(
                g.kind == "reserved" and g.offset == f.offset and g.size == f.size for g in new
            ):
                self.add("FIELD_REMOVED_FROM_LAYOUT", f"{where}[{f.name}]", f"{f.size} bytes at {f.offset}", None)
        for f in fresh:
            if any(a <= f.offset and f.end <= b for a, b in old_reserved):
                self.add(
                    "FIELD_ADDED_IN_RESERVED", f"{where}[{f.name}]", None, f"{f.name}: {f.type.name} at {f.offset}"
                )
            else:
                self.add("FIELD_ADDED_TO_LAYOUT", f"{where}[{f.name}]", None, f"{f.name}: {f.type.name} at {f.offset}")
        for name, f in olds.items():
            if name in news:
                self._field(f, news[name], f"{where}[{name}]")

    def _field(self, old: Field, new: Field, where: str) -> None:
        def unit(f: Field) -> str | None:
            return f.unit.key if f.unit else None

        kinds_differ = old.type.kind != new.type.kind
        checks: list[tuple[str, str, Any, Any]] = [
            ("offset", "FIELD_OFFSET_CHANGED", old.offset, new.offset),
            ("size", "FIELD_SIZE_CHANGED", old.size, new.size),
            (
                "type",
                "FIELD_SIGNEDNESS_CHANGED",
                old.type.name if kinds_differ else 0,
                new.type.name if kinds_differ else 0,
            ),
            ("scale", "FIELD_SCALE_CHANGED", *_shared_scales(old, self.old, new, self.new)),
            ("unit", "FIELD_TYPE_CHANGED", unit(old), unit(new)),
            ("default", "FIELD_DEFAULT_CHANGED", old.default, new.default),
        ]
        checks += [
            (a, "FIELD_ENCODING_CHANGED", getattr(old, a), getattr(new, a)) for a in ("encoding", "multiplexed_count")
        ]
        checks += [(a, "FIELD_TYPE_CHANGED", getattr(old, a), getattr(new, a)) for a in ("range", "enum")]
        # What a multiplexed field carries in turn is named in prose: no binding reads the names.
        prose = ("doc", "icd_name", "erratum", "multiplexed_quantities")
        checks += [(a, "DOC_CHANGED", getattr(old, a), getattr(new, a)) for a in prose]
        for attr, rule, a, b in checks:
            if a != b:
                self.add(rule, f"{where}.{attr}", a, b)

    # Commands: by name; a code's meaning is followed across renames.

    def _commands(self) -> None:
        olds = {c.name: c for c in self.old.commands}
        news = {c.name: c for c in self.new.commands}
        new_codes = {c.code for c in self.new.commands}
        old_codes = {c.code for c in self.old.commands}
        fresh = [c for n, c in news.items() if n not in olds]
        for name, c in olds.items():
            if name in news:
                continue
            twin = next((d for d in fresh if d.code == c.code and self._same_meaning(c, d)), None)
            if twin is not None:
                fresh.remove(twin)
                self.command_renames[c.name] = twin.name
                self.add("NAME_RENAMED", f"commands[{c.name}]", c.name, twin.name)
                self._command(c, twin)
                continue
            self.add("NAME_REMOVED", f"commands[{c.name}]", c.name, None)
            if c.code not in new_codes:
                self.add("COMMAND_CODE_REMOVED", f"commands[{c.name}].code", f"{c.code:#04x}", None)
            elif not any(d.code == c.code for d in self.new.commands if d.name in olds):
                taker = next(d for d in self.new.commands if d.code == c.code)
                self.add("COMMAND_CODE_REUSED", f"commands[{c.name}].code", f"{c.code:#04x} {c.name}", f"{taker.name}")
        for c in fresh:
            if c.code in old_codes:
                if not any(o.name not in news and o.code == c.code for o in self.old.commands):
                    self.add("COMMAND_CODE_REUSED", f"commands[{c.name}].code", f"{c.code:#04x}", f"also {c.name}")
            else:
                self.add("COMMAND_ADDED", f"commands[{c.name}]", None, f"{c.name} ({c.code:#04x})")
        for name, c in olds.items():
            if name in news:
                self._command(c, news[name])

    def _same_meaning(self, old: Command, new: Command) -> bool:
        return _command_wire(old, self.old, self.payload_renames) == _command_wire(new, self.new, {})

    def _command(self, old: Command, new: Command) -> None:
        where = f"commands[{new.name}]"
        if old.code != new.code:
            self.add("COMMAND_CODE_CHANGED", f"{where}.code", f"{old.code:#04x}", f"{new.code:#04x}")
            taken = [d.name for d in self.old.commands if d.code == new.code and d.name != old.name]
            if taken:
                self.add("COMMAND_CODE_REUSED", f"{where}.code", f"{new.code:#04x} {', '.join(taken)}", new.name)
        ren = self.payload_renames
        if (old.response_kind, tuple(ren.get(p, p) for p in old.response_payloads)) != (
            new.response_kind,
            new.response_payloads,
        ):
            self.add(
                "COMMAND_RESPONSE_CHANGED",
                f"{where}.response",
                f"{old.response_kind} {list(old.response_payloads)}",
                f"{new.response_kind} {list(new.response_payloads)}",
            )
        for attr in ("valid_in", "starts_mode", "starts_output", "parameter_block", "shares_code_with",
                     "default_for_code", "begins_calibration"):  # fmt: skip
            a, b = getattr(old, attr), getattr(new, attr)
            if attr in ("starts_output", "parameter_block"):
                a = ren.get(a, a) if isinstance(a, str) else a
            if attr == "shares_code_with":
                a = self.command_renames.get(a, a) if isinstance(a, str) else a
            if a != b:
                self.add("COMMAND_BEHAVIOUR_CHANGED", f"{where}.{attr}", a, b)
        if old.id != new.id:
            self.add("NAME_RENAMED", f"{where}.id", old.id, new.id)
        self._walk(old.former_names, new.former_names, f"{where}.former_names", "commands")
        for attr in ("icd", "group", "purpose", "erratum"):
            if getattr(old, attr) != getattr(new, attr):
                self.add("DOC_CHANGED", f"{where}.{attr}", getattr(old, attr), getattr(new, attr))

    # The state machine: what the device answers, state by state, event by event.

    def _state_machine(self) -> None:
        old, new = self.old.state_machine, self.new.state_machine
        if old is None or new is None:
            if old != new:
                self.add(
                    "STATE_MACHINE_CHANGED", "state_machine", "present" if old else None, "present" if new else None
                )
            return
        for attr in ("initial", "parameter_block_timeout_s", "default_alignment_time_s", "default_update_rate_hz",
                     "result_delay_s", "min_successful_runs"):  # fmt: skip
            if getattr(old, attr) != getattr(new, attr):
                self.add("STATE_MACHINE_CHANGED", f"state_machine.{attr}", getattr(old, attr), getattr(new, attr))
        ren = self.payload_renames
        olds = {s.name: s for s in old.states}
        news = {s.name: s for s in new.states}
        for name, s in olds.items():
            if name not in news:
                self.add("NAME_REMOVED", f"state_machine.states[{name}]", name, None)
                continue
            t = news[name]
            if (s.mode, ren.get(s.expects or "", s.expects), s.timer) != (t.mode, t.expects, t.timer):
                self.add("STATE_MACHINE_CHANGED", f"state_machine.states[{name}]",
                         f"mode {s.mode}, expects {s.expects}, timer {s.timer}",
                         f"mode {t.mode}, expects {t.expects}, timer {t.timer}")  # fmt: skip
            for attr in ("doc", "erratum"):
                if getattr(s, attr) != getattr(t, attr):
                    self.add("DOC_CHANGED", f"state_machine.states[{name}].{attr}", getattr(s, attr), getattr(t, attr))
        for name in news:
            if name not in olds:
                self.add("NAME_ADDED", f"state_machine.states[{name}]", None, name)
        self._walk(old.events, new.events, "state_machine.events", "state_machine")
        old_timers = {t.name: (ren.get(t.payload, t.payload), t.field) for t in old.timers}
        new_timers = {t.name: (t.payload, t.field) for t in new.timers}
        if old_timers != new_timers:
            self.add("STATE_MACHINE_CHANGED", "state_machine.timers", old_timers, new_timers)
        self._answer_changes()

    def _answer_changes(self) -> None:
        ren = self.payload_renames
        assert self.old.state_machine is not None and self.new.state_machine is not None
        olds = {s.name for s in self.old.state_machine.states}
        news = {s.name for s in self.new.state_machine.states}
        old_answers = device_answers(self.old)
        new_answers = device_answers(self.new)
        # A code only one spec has is the command rules' (added, removed): before it existed, the
        # device answered it as an unknown code.
        only_one = {f"code {c:#04x}" for c in set(self.old.codes) ^ set(self.new.codes)}
        for key in sorted(set(old_answers) | set(new_answers), key=str):
            state, event = key
            if state not in olds or state not in news or event.split(" (")[0] in only_one:
                continue
            a = old_answers.get(key)
            if a is not None:
                a = (a[0], tuple(ren.get(w, w) for w in a[1]))
            b = new_answers.get(key)
            if a != b:
                self.add("STATE_MACHINE_ANSWER_CHANGED", f"state_machine[{state}, {event}]", _answer(a), _answer(b))


def _answer(a: tuple[str, tuple[str, ...]] | None) -> str:
    return "ignored" if a is None else f"to {a[0]}, send [{', '.join(a[1])}]"


def _field_wire(f: Field) -> tuple[Any, ...]:
    scale = None if f.scale is None else (f.scale.multiplier, f.scale.divisor, f.scale.divisor_parameter)
    return (f.offset, f.size, f.type.name, scale, f.encoding, f.multiplexed_count)


def _layout(p: Payload) -> tuple[Any, ...]:
    return (p.size, tuple(_field_wire(f) for f in p.fields))


def _command_wire(c: Command, spec: Spec, renames: dict[str, str]) -> tuple[Any, ...]:
    return (
        c.response_kind,
        tuple(renames.get(p, p) for p in c.response_payloads),
        renames.get(c.parameter_block or "", c.parameter_block),
        c.starts_mode,
        c.valid_in,
    )


def compare(old: Spec, new: Spec) -> list[Change]:
    """Every change from `old` to `new`, each with its rule."""
    return _Differ(old, new).run()


def _shared_scales(old: Field, old_spec: Spec, new: Field, new_spec: Spec) -> tuple[Any, Any]:
    """The two fields' scales, a divisor taken from a variant parameter compared only over the
    variants both specs have: a variant added or removed is its own rule, not a scale change."""
    a, b = scale_of(old, old_spec), scale_of(new, new_spec)
    if a is None or b is None or not isinstance(a[1], list) or not isinstance(b[1], list):
        return a, b
    shared = {part for part, _ in a[1]} & {part for part, _ in b[1]}
    return (a[0], [x for x in a[1] if x[0] in shared]), (b[0], [x for x in b[1] if x[0] in shared])
