"""What changed between two specs, and what it means for a user who vendors the bindings.

`python -m generator diff --against REV_OR_FILE` compares the model of the spec (loaded,
validated and laid out: offsets and sizes, not YAML text) with the model of another version of
it: a spec file, or a git revision (the spec's path at that revision). Every change is reported
with the named rule that classifies it, in one of four classes:

    wire-breaking  an old device and a new host (or the reverse) disagree about bytes
    api-breaking   code written against the old bindings stops compiling or means something else
    additive       something new; what existed is unchanged
    docs           documentation only: no byte and no identifier changes

The required version bump follows (major for a breaking change, minor for an additive one,
patch for documentation; before 1.0.0 a breaking change needs a minor bump), and
`--check-version` fails when the spec's `version` does not bump at least that much.

The same wire-relevant view of the model (`wire_facts`: command codes, payload layouts, frame,
state-machine answers; never names or docs) gives the wire fingerprint every binding exports.
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import json
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from ..load import SpecError
from ..model import Command, Field, Payload, Spec

WIRE = "wire-breaking"
API = "api-breaking"
ADDITIVE = "additive"
DOCS = "docs"
CLASSES = (WIRE, API, ADDITIVE, DOCS)
BUMPS = ("major", "minor", "patch")

# Each rule: its name -> (class, what it means). Every change the comparison reports names one.
RULES: dict[str, tuple[str, str]] = {
    # wire-breaking
    "COMMAND_CODE_REMOVED": (WIRE, "no command has this code any more: a device or host still sending it is ignored"),
    "COMMAND_CODE_REUSED": (WIRE, "a code now means another command than it did"),
    "COMMAND_CODE_CHANGED": (WIRE, "a command is sent with another code"),
    "COMMAND_RESPONSE_CHANGED": (WIRE, "a command is answered with another kind of message or table"),
    "COMMAND_BEHAVIOUR_CHANGED": (
        WIRE,
        "a command is valid in other modes, starts another mode or output, or takes another block",
    ),
    "PAYLOAD_SIZE_CHANGED": (WIRE, "a payload table has another length"),
    "PAYLOAD_DIRECTION_CHANGED": (WIRE, "a payload table travels the other way"),
    "FIELD_OFFSET_CHANGED": (WIRE, "a field sits at another offset"),
    "FIELD_SIZE_CHANGED": (WIRE, "a field has another size"),
    "FIELD_SIGNEDNESS_CHANGED": (
        WIRE,
        "a field's bytes are read as another kind of number (signed, unsigned, float, text)",
    ),
    "FIELD_SCALE_CHANGED": (WIRE, "a field's raw value maps to another engineering value"),
    "FIELD_ENCODING_CHANGED": (WIRE, "a field's bytes are encoded another way (date, declination, multiplexing)"),
    "FIELD_REMOVED_FROM_LAYOUT": (WIRE, "bytes that carried a field are gone from the table"),
    "FIELD_ADDED_TO_LAYOUT": (WIRE, "a field takes bytes that were not in the table"),
    "ENUM_VALUE_CHANGED": (WIRE, "an enum name stands for another number"),
    "FRAME_CHANGED": (WIRE, "the frame (header, fields, checksum, message types, length bounds) changed"),
    "BYTE_ORDER_CHANGED": (WIRE, "the byte order changed"),
    "SERIAL_LINE_CHANGED": (WIRE, "the serial line settings changed"),
    "ENCODING_CHANGED": (WIRE, "a value encoding (date, declination, calibration, status word, $PAHR) changed"),
    "VARIANT_VALUE_CHANGED": (WIRE, "a variant's scale parameter changed"),
    "STATE_MACHINE_ANSWER_CHANGED": (
        WIRE,
        "the device answers a command or event differently, or goes to another state",
    ),
    "STATE_MACHINE_CHANGED": (WIRE, "a state's mode, awaited block or timer, a timer's field or a timing changed"),
    # api-breaking
    "NAME_REMOVED": (API, "a name a binding exports is gone"),
    "NAME_RENAMED": (API, "a name a binding exports is spelt differently; the bytes are the same"),
    "FIELD_TYPE_CHANGED": (API, "a field's type, unit, enum or accepted range changed without changing its bytes"),
    "FIELD_DEFAULT_CHANGED": (API, "a builder fills a field with another value when none is given"),
    "UNIT_CHANGED": (API, "a unit's suffix (part of accessor names) changed"),
    "ENUM_CHANGED": (API, "an enum's range of external values changed"),
    # additive
    "COMMAND_ADDED": (ADDITIVE, "a new command on a new code"),
    "PAYLOAD_ADDED": (ADDITIVE, "a new payload table"),
    "FIELD_ADDED_IN_RESERVED": (ADDITIVE, "a field now names bytes that were reserved"),
    "ENUM_VALUE_ADDED": (ADDITIVE, "a new enum value"),
    "VARIANT_ADDED": (ADDITIVE, "a new device variant"),
    "NAME_ADDED": (ADDITIVE, "a new name (enum, error kind, mode, unit, state, event, former name, ...)"),
    # documentation only
    "DOC_CHANGED": (DOCS, "documentation, ICD references or errata only"),
}

# Attributes that are documentation: never a byte, never an identifier.
DOC_ATTRS = frozenset(
    {
        "doc",
        "purpose",
        "title",
        "icd",
        "icd_title",
        "icd_revision",
        "icd_date",
        "icd_name",
        "checksum_doc",
        "ack_doc",
        "says",
        "chosen",
        "why",
        "where",
        "erratum",
        "group",
        "until_firmware",
        "symbol",  # a unit's symbol: what follows a value shown to a person
    }
)
# Never compared: where a value sits in the file, and what the version says (checked on its own).
SKIPPED_ATTRS = frozenset({"path", "file", "sha256", "version", "declared_offset", "wire_fingerprint"})
# Top-level sections whose every non-doc change is a wire change, with the rule.
WIRE_SECTIONS = {
    "frame": "FRAME_CHANGED",
    "byte_order": "BYTE_ORDER_CHANGED",
    "serial_line": "SERIAL_LINE_CHANGED",
    "date": "ENCODING_CHANGED",
    "declination": "ENCODING_CHANGED",
    "calibration_success": "ENCODING_CHANGED",
    "status_word": "ENCODING_CHANGED",
    "nmea": "ENCODING_CHANGED",
}


@dataclasses.dataclass(frozen=True)
class Change:
    rule: str
    where: str
    old: str
    new: str

    @property
    def cls(self) -> str:
        return RULES[self.rule][0]

    def line(self) -> str:
        what = (
            f"{self.old} -> {self.new}"
            if self.old and self.new
            else (f"removed {self.old}" if self.old else f"added {self.new}")
        )
        return f"{self.cls:<13}  {self.rule:<28}  {self.where}: {what}"


def _show(value: Any) -> str:
    if value is None:
        return "none"
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        shown = (
            {k: v for k, v in _plain(value).items() if k not in DOC_ATTRS} if isinstance(_plain(value), dict) else value
        )
        return json.dumps(shown, sort_keys=True, default=str)
    if isinstance(value, tuple):
        return "[" + ", ".join(_show(v) for v in value) + "]"
    if isinstance(value, str):
        return repr(value if len(value) <= 60 else value[:57] + "...")
    return str(value)


def _plain(value: Any) -> Any:
    """A model value as JSON-able data, without source paths."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {
            f.name: _plain(getattr(value, f.name)) for f in dataclasses.fields(value) if f.name not in SKIPPED_ATTRS
        }
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    return value


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
        self.changes.append(Change(rule, where, "" if old is None else _show(old), "" if new is None else _show(new)))

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
            ("scale", "FIELD_SCALE_CHANGED", _scale(old, self.old), _scale(new, self.new)),
            ("unit", "FIELD_TYPE_CHANGED", unit(old), unit(new)),
            ("default", "FIELD_DEFAULT_CHANGED", old.default, new.default),
        ]
        checks += [
            (a, "FIELD_ENCODING_CHANGED", getattr(old, a), getattr(new, a))
            for a in ("encoding", "multiplexed_count", "multiplexed_quantities")
        ]
        checks += [(a, "FIELD_TYPE_CHANGED", getattr(old, a), getattr(new, a)) for a in ("range", "enum")]
        checks += [(a, "DOC_CHANGED", getattr(old, a), getattr(new, a)) for a in ("doc", "icd_name", "erratum")]
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
        old_answers = _answers(self.old)
        new_answers = _answers(self.new)
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


def _answers(spec: Spec) -> dict[tuple[str, str], tuple[str, tuple[str, ...]]]:
    """(state, event) -> (next state, what the device sends): a command event keyed by its code
    (what the device receives), the others by name; legacy rows under "<event> (old firmware)"."""
    sm = spec.state_machine
    assert sm is not None
    table: dict[tuple[str, str], tuple[str, tuple[str, ...]]] = {}
    for s in sm.states:
        events: list[tuple[str, str]] = []
        for code in spec.codes:
            c = spec.command_in_mode(code, s.mode)
            if c is not None:
                events.append((f"code {code:#04x}", c.name))
        events.extend((e.name, e.name) for e in sm.events)
        for label, event in events:
            for legacy in (False, True):
                t = sm.lookup(s.name, event, legacy=legacy)
                if t is None or (legacy and t.firmware_before is None):
                    continue
                key = (s.name, label + (f" (firmware before {t.firmware_before})" if legacy else ""))
                table[key] = (t.to, t.send)
    return table


def _scale(f: Field, spec: Spec) -> Any:
    if f.scale is None:
        return None
    if f.scale.divisor_parameter is not None:
        divisor: Any = sorted((v.part_number, v.value(f.scale.divisor_parameter)) for v in spec.variants)
    else:
        divisor = f.scale.divisor
    return (f.scale.multiplier, divisor)


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


# The required bump and the version check.


def _version(text: str) -> tuple[int, int, int]:
    parts = text.split("-", maxsplit=1)[0].split("+", maxsplit=1)[0].split(".")
    return int(parts[0]), int(parts[1]) if len(parts) > 1 else 0, int(parts[2]) if len(parts) > 2 else 0


def required_bump(changes: Sequence[Change], old_version: str) -> str | None:
    """major, minor or patch (None: no change). Before 1.0.0 a breaking change needs a minor bump."""
    classes = {c.cls for c in changes}
    if not classes:
        return None
    if classes & {WIRE, API}:
        return "major" if _version(old_version)[0] > 0 else "minor"
    if ADDITIVE in classes:
        return "minor" if _version(old_version)[0] > 0 else "patch"
    return "patch"


def actual_bump(old_version: str, new_version: str) -> str | None:
    a, b = _version(old_version), _version(new_version)
    if b <= a:
        return None
    if b[0] > a[0]:
        return "major"
    if b[1] > a[1]:
        return "minor"
    return "patch"


def bump_is_enough(required: str | None, actual: str | None) -> bool:
    if required is None:
        return True
    return actual is not None and BUMPS.index(actual) <= BUMPS.index(required)


# The wire fingerprint: the wire-relevant view of a spec, hashed.


def _field_facts(f: Field, spec: Spec) -> list[Any]:
    enum: Any = None
    if f.enum is not None:
        e = spec.enum(f.enum)
        enum = [sorted(v.value for v in e.values), e.external_above]
    return [f.offset, f.size, f.type.name, _scale(f, spec), f.encoding, enum, f.multiplexed_count]


def _payload_facts(p: Payload, spec: Spec) -> list[Any]:
    return [p.size, p.direction, [_field_facts(f, spec) for f in p.fields]]


def _without_names(value: Any) -> Any:
    """A section's data without documentation or names (a status flag by bit, an NMEA field by position)."""
    plain = _plain(value)

    def strip(v: Any) -> Any:
        if isinstance(v, dict):
            return {k: strip(x) for k, x in v.items() if k not in DOC_ATTRS and k not in ("name", "other_mode")}
        if isinstance(v, list):
            return [strip(x) for x in v]
        return v

    return strip(plain)


def wire_facts(spec: Spec) -> dict[str, Any]:
    """What a device and a host must agree on, and nothing else: byte order, serial line, frame,
    each code's meaning (answer kind and table layouts), payload layouts (offsets, sizes, types,
    scales, enum numbers), encodings and the state machine's answers, states numbered in the order
    they are reached from the initial one. No documentation, no identifier."""
    layouts = {p.name: _payload_facts(p, spec) for p in spec.payloads}

    def word(w: str | None) -> Any:
        return layouts.get(w, w) if w is not None else None

    fr = spec.frame
    facts: dict[str, Any] = {
        "byte_order": spec.byte_order,
        "serial_line": _without_names(spec.serial_line),
        "frame": {
            "header": list(fr.header),
            "fields": [_field_facts(f, spec) for f in fr.fields],
            "checksum": [fr.checksum.size, fr.checksum.type.name, fr.checksum_algorithm],
            "message_types": sorted(t.value for t in fr.message_types),
            "length": [fr.min_length, fr.max_length],
            "strict": None if fr.strict is None else [fr.strict.message_type_value, fr.strict.reserved],
        },
        "ack": word(spec.ack_payload),
        "codes": [
            [
                [
                    c.response_kind,
                    [word(p) for p in c.response_payloads],
                    word(c.parameter_block),
                    word(c.starts_output),
                ]
                for c in spec.commands_with_code(code)
            ]
            for code in spec.codes
        ],
        "code_values": list(spec.codes),
        "payloads": sorted(json.dumps(v, sort_keys=True) for v in layouts.values()),
        "encodings": [
            _without_names(x)
            for x in (spec.date, spec.declination, spec.calibration_success, spec.status_word, spec.nmea)
        ],
    }
    if spec.nmea is not None:
        facts["encodings"][-1]["template"] = spec.nmea.template
    sm = spec.state_machine
    if sm is not None:
        answers = _answers(spec)
        order: list[str] = [sm.initial]
        i = 0
        while i < len(order):
            for key in sorted(k for k in answers if k[0] == order[i]):
                to = answers[key][0]
                if to not in order:
                    order.append(to)
            i += 1
        order += sorted(s.name for s in sm.states if s.name not in order)
        number = {name: n for n, name in enumerate(order)}
        facts["state_machine"] = {
            "timing": [
                sm.parameter_block_timeout_s,
                sm.default_alignment_time_s,
                sm.default_update_rate_hz,
                sm.result_delay_s,
                sm.min_successful_runs,
            ],
            "timers": sorted(
                [t.name, word(t.payload), spec.payload(t.payload).field(t.field).offset] for t in sm.timers
            ),
            "states": [
                [
                    sm.state(name).mode,
                    word(sm.state(name).expects),
                    sm.state(name).timer,
                    sorted(
                        [event, number[to], [json.dumps(word(w), sort_keys=True) for w in send]]
                        for (state, event), (to, send) in answers.items()
                        if state == name
                    ),
                ]
                for name in order
            ],
        }
    return facts


def wire_fingerprint(spec: Spec) -> int:
    """64 bits of the SHA-256 of `wire_facts`: equal for two specs that agree on every byte."""
    text = json.dumps(wire_facts(spec), sort_keys=True, separators=(",", ":"), default=str)
    return int.from_bytes(hashlib.sha256(text.encode("utf-8")).digest()[:8], "big")


# The command line.


def _spec_at(against: str, spec_path: Path, tmp: Path) -> Path:
    """A file: itself. Otherwise a git revision: the spec's path at that revision."""
    candidate = Path(against)
    if candidate.is_file():
        return candidate
    spec_path = spec_path.resolve()
    try:
        top = subprocess.run(
            ["git", "-C", str(spec_path.parent), "rev-parse", "--show-toplevel"],
            capture_output=True, text=True, check=True,
        ).stdout.strip()  # fmt: skip
    except (OSError, subprocess.CalledProcessError) as exc:
        raise SpecError(against, None, (), f"neither a file nor a git revision (no git repository: {exc})") from exc
    rel = spec_path.relative_to(Path(top).resolve()).as_posix()
    shown = subprocess.run(["git", "-C", top, "show", f"{against}:{rel}"], capture_output=True, check=False)
    if shown.returncode != 0:
        message = shown.stderr.decode("utf-8", "replace").strip().splitlines()
        raise SpecError(
            against, None, (), f"neither a file nor a git revision holding {rel}: {message[-1] if message else ''}"
        )
    out = tmp / f"{against.replace('/', '_')}.yaml"
    out.write_bytes(shown.stdout)
    return out


def write_junit(path: Path, changes: Sequence[Change], required: str | None, enough: bool, checked: bool) -> None:
    suite = ET.Element("testsuite", name="spec-compatibility", tests=str(len(changes) + 1))
    failures = 0
    for c in changes:
        case = ET.SubElement(suite, "testcase", classname=f"spec.{c.cls}", name=f"{c.rule} {c.where}")
        breaking = (
            checked
            and not enough
            and c.cls != DOCS
            and BUMPS.index(_bump_of(c.cls)) <= BUMPS.index(required or "patch")
        )
        if breaking:
            failures += 1
            ET.SubElement(case, "failure", message=RULES[c.rule][1], type=c.rule).text = c.line()
        else:
            ET.SubElement(case, "system-out").text = c.line()
    case = ET.SubElement(suite, "testcase", classname="spec.version", name="version bump")
    if checked and not enough:
        failures += 1
        ET.SubElement(case, "failure", message=f"a {required} version bump is required", type="VERSION_BUMP")
    suite.set("failures", str(failures))
    tree = ET.ElementTree(suite)
    ET.indent(tree)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tree.write(tmp, encoding="utf-8", xml_declaration=True)
    tmp.replace(path)


def _bump_of(cls: str) -> str:
    return {WIRE: "major", API: "major", ADDITIVE: "minor", DOCS: "patch"}[cls]


def main(argv: list[str] | None = None, build: Callable[[Path], Spec] | None = None) -> int:
    from .. import DEFAULT_SPEC, build_spec

    build = build or build_spec
    parser = argparse.ArgumentParser(
        prog="python -m generator diff",
        description="Every change between two specs, classified by named rules (wire-breaking, api-breaking,"
        " additive, docs), and the version bump it requires.",
        epilog="example: python -m generator diff --against v1.0.0 --check-version --junit build/spec-diff.xml",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter,
    )
    parser.add_argument("--against", metavar="REV_OR_FILE", help="the older spec: a spec file or a git revision")
    parser.add_argument("--spec", type=Path, default=DEFAULT_SPEC, help="the newer spec file")
    parser.add_argument(
        "--check-version", action="store_true", help="exit 1 if the spec's version does not bump enough"
    )
    parser.add_argument("--junit", type=Path, metavar="FILE", help="also write the result as JUnit XML")
    parser.add_argument("--rules", action="store_true", help="list the rules and stop")
    args = parser.parse_args(argv)
    if args.rules:
        for name, (cls, what) in RULES.items():
            print(f"{cls:<13}  {name:<28}  {what}")
        return 0
    if args.against is None:
        parser.error("--against REV_OR_FILE is required")
    try:
        with tempfile.TemporaryDirectory(prefix="ilahrs-diff-") as tmp:
            old = build(_spec_at(args.against, args.spec, Path(tmp)))
        new = build(args.spec)
    except SpecError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    changes = compare(old, new)
    for c in changes:
        print(c.line())
    required = required_bump(changes, old.version)
    actual = actual_bump(old.version, new.version)
    enough = bump_is_enough(required, actual)
    counts = ", ".join(f"{sum(c.cls == k for c in changes)} {k}" for k in CLASSES)
    print(f"{len(changes)} changes ({counts})")
    fp_old, fp_new = wire_fingerprint(old), wire_fingerprint(new)
    print(f"wire fingerprint {fp_old:#018x} -> {fp_new:#018x}" + (" (same)" if fp_old == fp_new else ""))
    print(
        f"required bump: {required or 'none'}; version {old.version} -> {new.version} ({actual or 'no bump'})"
        + ("" if enough else ": NOT ENOUGH")
    )
    if args.junit is not None:
        try:
            write_junit(args.junit, changes, required, enough, args.check_version)
        except OSError as exc:
            print(f"error: cannot write {args.junit}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    if args.check_version and not enough:
        print(
            f"error: spec version {new.version} must be at least a {required} bump over {old.version}", file=sys.stderr
        )
        return 1
    return 0
