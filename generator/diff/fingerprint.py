"""The wire fingerprint every binding exports: the wire-relevant view of a spec (`wire_facts`:
command codes, payload layouts, frame, state-machine answers; never names or docs), hashed.
"""

from __future__ import annotations

import hashlib
import json
from typing import Any

from ..model import Field, Payload, Spec
from .rules import DOC_ATTRS, plain_data


def device_answers(spec: Spec) -> dict[tuple[str, str], tuple[str, tuple[str, ...]]]:
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


def scale_of(f: Field, spec: Spec) -> Any:
    if f.scale is None:
        return None
    if f.scale.divisor_parameter is not None:
        divisor: Any = sorted((v.part_number, v.value(f.scale.divisor_parameter)) for v in spec.variants)
    else:
        divisor = f.scale.divisor
    return (f.scale.multiplier, divisor)


def _field_facts(f: Field, spec: Spec) -> list[Any]:
    enum: Any = None
    if f.enum is not None:
        e = spec.enum(f.enum)
        enum = [sorted(v.value for v in e.values), e.external_above]
    return [f.offset, f.size, f.type.name, scale_of(f, spec), f.encoding, enum, f.multiplexed_count]


def _payload_facts(p: Payload, spec: Spec) -> list[Any]:
    return [p.size, p.direction, [_field_facts(f, spec) for f in p.fields]]


def _without_names(value: Any) -> Any:
    """A section's data without documentation or names (a status flag by bit, an NMEA field by position)."""
    plain = plain_data(value)

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
        answers = device_answers(spec)
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
