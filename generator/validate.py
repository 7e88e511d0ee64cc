"""Step 2 of the pipeline: reject a spec that is malformed or inconsistent.

First the structure, against spec/schema.json; then what a schema cannot say:
unknown types, names and codes used twice, references to things that do not exist,
scales on non-numeric fields, ranges outside what a type holds. Sizes and offsets are
checked by the layout step, which computes them. Every error names file, line and path.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import jsonschema

from .load import LoadedSpec, PathKey
from .model import FLOAT32_MAX, PRIMITIVES, TIMER_EVENTS, answer_kind

SCHEMA_PATH = Path(__file__).resolve().parent.parent / "spec" / "schema.json"

# The frame fields the bindings rely on, by name and type.
REQUIRED_FRAME_FIELDS = {"message_type": "u8", "reserved": "u8", "message_length": "u16"}

ENCODING_TYPES = {"usw": ("u16",), "date": ("f32",), "declination": ("f32",), "calibration_success": ("u8",)}


def _schema() -> dict[str, Any]:
    result: dict[str, Any] = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    return result


def _check_schema(spec: LoadedSpec) -> None:
    validator = jsonschema.Draft202012Validator(_schema())
    errors = sorted(validator.iter_errors(spec.data), key=lambda e: (len(e.absolute_path), str(e.absolute_path)))
    if errors:
        # Report the most specific error first: the deepest path.
        error = max(errors, key=lambda e: len(e.absolute_path))
        path: PathKey = tuple(error.absolute_path)
        raise spec.error(path, error.message)


def _duplicates(items: Iterable[tuple[PathKey, Any]], what: str, spec: LoadedSpec) -> None:
    seen: dict[Any, PathKey] = {}
    for path, key in items:
        if key in seen:
            raise spec.error(path, f"duplicate {what} {key!r} (first at line {spec.line_of(seen[key])})")
        seen[key] = path


def _unique(spec: LoadedSpec, items: list[Any], prefix: PathKey, key: str, what: str) -> None:
    """Every item of the list at `prefix` has a different `key`."""
    _duplicates((((*prefix, i, key), item[key]) for i, item in enumerate(items)), what, spec)


def _check_field(spec: LoadedSpec, f: dict[str, Any], path: PathKey, ctx: dict[str, Any]) -> None:
    type_name = f["type"]
    if type_name not in PRIMITIVES:
        known = ", ".join(PRIMITIVES)
        raise spec.error((*path, "type"), f"unknown type {type_name!r} (known: {known})")
    primitive = PRIMITIVES[type_name]
    if primitive.size is None and "length" not in f:
        raise spec.error(path, f"a {type_name} field needs a length")
    if primitive.size is not None and "length" in f:
        raise spec.error((*path, "length"), f"a {type_name} field has a fixed size; length is not allowed")
    numeric = primitive.kind in ("unsigned", "signed", "float")
    for key in ("scale", "unit", "range", "enum", "encoding", "multiplexed"):
        if key in f and not numeric:
            raise spec.error((*path, key), f"{key} on non-numeric field {f['name']!r} of type {type_name}")
    if "unit" in f and f["unit"] not in ctx["units"]:
        raise spec.error((*path, "unit"), f"unknown unit {f['unit']!r}")
    if "scale" in f:
        divisor = f["scale"].get("divisor")
        if isinstance(divisor, str) and divisor not in ctx["variant_parameters"]:
            raise spec.error((*path, "scale", "divisor"), f"unknown variant parameter {divisor!r}")
        if "unit" not in f:
            raise spec.error((*path, "scale"), f"scaled field {f['name']!r} has no unit")
    if "enum" in f and f["enum"] not in ctx["enums"]:
        raise spec.error((*path, "enum"), f"unknown enum {f['enum']!r}")
    if "encoding" in f:
        encoding = f["encoding"]
        if encoding != "usw" and encoding not in ctx["encodings"]:
            raise spec.error((*path, "encoding"), f"encoding {encoding!r} is not defined under `encodings`")
        if encoding == "usw" and ctx["status_word"] is None:
            raise spec.error((*path, "encoding"), "encoding 'usw' needs a `status_word` section")
        if type_name not in ENCODING_TYPES[encoding]:
            raise spec.error(
                (*path, "encoding"), f"encoding {encoding!r} needs type {ENCODING_TYPES[encoding][0]}, not {type_name}"
            )
    if "range" in f:
        low, high = f["range"]
        if low > high:
            raise spec.error((*path, "range"), f"range [{low}, {high}] is empty")
        if primitive.kind in ("unsigned", "signed"):
            assert primitive.min is not None and primitive.max is not None
            if not (isinstance(low, int) and isinstance(high, int)):
                raise spec.error((*path, "range"), "the range of an integer field must be integers")
            if low < primitive.min or high > primitive.max:
                raise spec.error(
                    (*path, "range"),
                    f"range [{low}, {high}] does not fit type {type_name} [{primitive.min}, {primitive.max}]",
                )
        elif primitive.kind == "float" and not all(math.isfinite(v) and abs(v) <= FLOAT32_MAX for v in (low, high)):
            raise spec.error((*path, "range"), "the range of a float field must be finite float32 values")
    if "default" in f:
        default = f["default"]
        if primitive.kind == "char":
            if not isinstance(default, str) or len(default.encode("latin-1")) > f["length"]:
                raise spec.error((*path, "default"), "default does not fit the char field")
        elif numeric:
            if not isinstance(default, (int, float)) or isinstance(default, bool):
                raise spec.error((*path, "default"), "default of a numeric field must be a number")
            bounds = f.get("range")
            if bounds is None and primitive.min is not None and primitive.max is not None:
                bounds = [primitive.min, primitive.max]
            if bounds is not None and not bounds[0] <= default <= bounds[1]:
                raise spec.error((*path, "default"), f"default {default} is outside [{bounds[0]}, {bounds[1]}]")
    if "erratum" in f and f["erratum"] not in ctx["errata"]:
        raise spec.error((*path, "erratum"), f"unknown erratum {f['erratum']!r}")


def _check_erratum_refs(spec: LoadedSpec, value: Any, path: PathKey, errata: set[str]) -> None:
    if isinstance(value, dict):
        for key, item in value.items():
            if key == "erratum" and isinstance(item, str) and item not in errata:
                raise spec.error((*path, key), f"unknown erratum {item!r}")
            _check_erratum_refs(spec, item, (*path, key), errata)
    elif isinstance(value, list):
        for index, item in enumerate(value):
            _check_erratum_refs(spec, item, (*path, index), errata)


def validate(spec: LoadedSpec) -> None:
    """Raise SpecError for the first problem found; return quietly for a usable spec."""
    _check_schema(spec)
    d = spec.data

    errata = [e["id"] for e in d.get("errata", [])]
    _duplicates(((("errata", i, "id"), e) for i, e in enumerate(errata)), "erratum id", spec)
    _check_erratum_refs(spec, {k: v for k, v in d.items() if k != "errata"}, (), set(errata))
    _unique(spec, d["errors"], ("errors",), "name", "error kind")
    modes = [m["name"] for m in d.get("modes", [])]
    _duplicates(((("modes", i, "name"), m) for i, m in enumerate(modes)), "mode", spec)

    variants = d.get("variants", {"parameters": {}, "list": []})
    parameters = set(variants["parameters"])
    _unique(
        spec,
        variants["list"],
        ("variants", "list"),
        "name",
        "variant",
    )
    for i, v in enumerate(variants["list"]):
        if set(v["values"]) != parameters:
            raise spec.error(
                ("variants", "list", i, "values"),
                f"variant {v['name']!r} must give exactly the parameters {sorted(parameters)}",
            )

    enums = d.get("enums", {})
    for name, e in enums.items():
        for key, what in (("name", "enum value name"), ("value", "enum value")):
            _unique(spec, e["values"], ("enums", name, "values"), key, what)

    ctx: dict[str, Any] = {
        "units": set(d.get("units", {})),
        "variant_parameters": parameters,
        "enums": set(enums),
        "encodings": set(d.get("encodings", {})),
        "status_word": d.get("status_word"),
        "errata": set(errata),
    }

    # Frame.
    frame = d["frame"]
    for i, f in enumerate(frame["fields"]):
        _check_field(spec, f, ("frame", "fields", i), ctx)
    _unique(
        spec,
        frame["fields"],
        ("frame", "fields"),
        "name",
        "frame field",
    )
    names = {f["name"]: f["type"] for f in frame["fields"]}
    for name, type_name in REQUIRED_FRAME_FIELDS.items():
        if names.get(name) != type_name:
            raise spec.error(("frame", "fields"), f"the frame needs a field {name!r} of type {type_name}")
    if frame["checksum"]["type"] != "u16":
        raise spec.error(("frame", "checksum", "type"), "the sum16 checksum is a u16")
    _unique(
        spec,
        frame["message_types"],
        ("frame", "message_types"),
        "value",
        "message type value",
    )
    _unique(
        spec,
        frame["message_types"],
        ("frame", "message_types"),
        "name",
        "message type name",
    )
    if {t["name"] for t in frame["message_types"]} != {"command", "data"}:
        raise spec.error(("frame", "message_types"), "message types must be exactly `command` and `data`")
    lengths = frame["message_length"]
    if lengths["min"] > lengths["max"]:
        raise spec.error(("frame", "message_length"), f"min {lengths['min']} is above max {lengths['max']}")
    if lengths["max"] > 0xFFFF:
        raise spec.error(("frame", "message_length", "max"), "the message length is a u16")

    # Payloads.
    payload_names = [p["name"] for p in d["payloads"]]
    _duplicates(((("payloads", i, "name"), n) for i, n in enumerate(payload_names)), "payload", spec)
    for i, p in enumerate(d["payloads"]):
        _unique(
            spec,
            p["fields"],
            ("payloads", i, "fields"),
            "name",
            f"field in payload {p['name']!r}:",
        )
        for j, f in enumerate(p["fields"]):
            _check_field(spec, f, ("payloads", i, "fields", j), ctx)

    # Commands.
    command_names = [c["name"] for c in d["commands"]]
    _duplicates(((("commands", i, "name"), n) for i, n in enumerate(command_names)), "command name", spec)
    _unique(spec, d["commands"], ("commands",), "id", "command id")
    by_name = {c["name"]: c for c in d["commands"]}
    by_code: dict[int, list[int]] = {}
    for i, c in enumerate(d["commands"]):
        by_code.setdefault(c["code"], []).append(i)
    for i, c in enumerate(d["commands"]):
        path: PathKey = ("commands", i)
        for j, mode in enumerate(c["valid_in"]):
            if mode not in modes:
                raise spec.error((*path, "valid_in", j), f"unknown mode {mode!r}")
        for j, name in enumerate(c["response"].get("payloads", [])):
            if name not in payload_names:
                raise spec.error((*path, "response", "payloads", j), f"unknown payload {name!r}")
        kind = c["response"]["kind"]
        if (kind == "data") != ("payloads" in c["response"]):
            raise spec.error((*path, "response"), "a `data` response, and only it, names its payloads")
        if "parameter_block" in c and c["parameter_block"] not in payload_names:
            raise spec.error((*path, "parameter_block"), f"unknown payload {c['parameter_block']!r}")
        if "starts" in c:
            if c["starts"]["mode"] not in modes:
                raise spec.error((*path, "starts", "mode"), f"unknown mode {c['starts']['mode']!r}")
            output = c["starts"]["output"]
            if output != "nmea" and output not in payload_names:
                raise spec.error((*path, "starts", "output"), f"unknown output {output!r}")
            if output == "nmea" and "nmea" not in d:
                raise spec.error((*path, "starts", "output"), "output 'nmea' needs an `nmea` section")
        partner = c.get("shares_code_with")
        others = [k for k in by_code[c["code"]] if k != i]
        if partner is not None:
            if partner not in by_name:
                raise spec.error((*path, "shares_code_with"), f"unknown command {partner!r}")
            if by_name[partner]["code"] != c["code"]:
                raise spec.error(
                    (*path, "shares_code_with"),
                    f"{partner!r} has code {by_name[partner]['code']:#04x}, not {c['code']:#04x}",
                )
            if by_name[partner].get("shares_code_with") != c["name"]:
                raise spec.error((*path, "shares_code_with"), f"{partner!r} must declare shares_code_with: {c['name']}")
        for k in others:
            other = d["commands"][k]
            if k < i and partner != other["name"]:
                raise spec.error(
                    (*path, "code"),
                    f"duplicate command code {c['code']:#04x} ({c['name']} and {other['name']})"
                    " not declared with shares_code_with",
                )
        if others and partner is not None:
            group = [c, *(d["commands"][k] for k in others)]
            defaults = [x["name"] for x in group if x.get("default_for_code")]
            if len(defaults) != 1:
                raise spec.error(
                    (*path, "shares_code_with"),
                    f"exactly one of {sorted(x['name'] for x in group)} must be default_for_code (found {defaults})",
                )
        elif c.get("default_for_code"):
            raise spec.error((*path, "default_for_code"), "default_for_code only applies to a shared code")
        if "begins_calibration" in c:
            values = [v["name"] for v in enums.get("calibration_type", {}).get("values", [])]
            if c["begins_calibration"] not in values:
                raise spec.error(
                    (*path, "begins_calibration"), f"{c['begins_calibration']!r} is not a calibration_type value"
                )
        for j, former in enumerate(c.get("former_names", [])):
            if former["name"] in by_name:
                raise spec.error(
                    (*path, "former_names", j, "name"), f"former name {former['name']!r} is a current command name"
                )

    ack = d.get("acknowledgement")
    if ack is not None and ack["payload"] not in payload_names:
        raise spec.error(("acknowledgement", "payload"), f"unknown payload {ack['payload']!r}")

    # Status word.
    sw = d.get("status_word")
    if sw is not None:
        _unique(
            spec,
            sw["flags"],
            ("status_word", "flags"),
            "bit",
            "status bit",
        )
        _unique(
            spec,
            sw["flags"],
            ("status_word", "flags"),
            "name",
            "status flag",
        )
        width = PRIMITIVES[sw["type"]].size if sw["type"] in PRIMITIVES else None
        if width is None or PRIMITIVES[sw["type"]].kind != "unsigned":
            raise spec.error(
                ("status_word", "type"), f"the status word must be an unsigned integer type, not {sw['type']!r}"
            )
        byte_names = {b["name"] for b in sw.get("bytes", [])}
        for i, f in enumerate(sw["flags"]):
            if f["bit"] >= width * 8:
                raise spec.error(("status_word", "flags", i, "bit"), f"bit {f['bit']} is outside a {sw['type']}")
            if f["bit"] in sw["mode"]["bits"]:
                raise spec.error(("status_word", "flags", i, "bit"), f"bit {f['bit']} is a mode bit")
            if f["byte"] not in byte_names:
                raise spec.error(("status_word", "flags", i, "byte"), f"unknown byte {f['byte']!r}")
        for i, m in enumerate(sw["mode"]["values"]):
            if len(m["bits"]) != len(sw["mode"]["bits"]):
                raise spec.error(("status_word", "mode", "values", i, "bits"), "one value per mode bit")
        _unique(
            spec,
            sw["mode"]["values"],
            ("status_word", "mode", "values"),
            "name",
            "status mode",
        )

    # NMEA.
    nmea = d.get("nmea")
    if nmea is not None:
        _unique(
            spec,
            nmea["fields"],
            ("nmea", "fields"),
            "name",
            "sentence field",
        )
        for i, f in enumerate(nmea["fields"]):
            low, high = f["range"]
            if not (isinstance(low, int) and isinstance(high, int)) or low > high:
                raise spec.error(
                    ("nmea", "fields", i, "range"), "the range of a sentence field is a pair of integers, low first"
                )
            if f["format"] == "hex" and (low < 0 or high >= 16 ** f["width"]):
                raise spec.error(("nmea", "fields", i, "range"), f"range does not fit {f['width']} hex digits")

    # State machine.
    sm = d.get("state_machine")
    if sm is not None:
        _check_state_machine(spec, sm, d, modes, payload_names)


def _check_state_machine(
    spec: LoadedSpec, sm: dict[str, Any], d: dict[str, Any], modes: list[str], payload_names: list[str]
) -> None:
    base: PathKey = ("state_machine",)
    _unique(spec, sm["states"], (*base, "states"), "name", "state")
    _unique(spec, sm["events"], (*base, "events"), "name", "event")
    states = {st["name"]: st for st in sm["states"]}
    commands = {c["name"]: c for c in d["commands"]}
    events = {e["name"] for e in sm["events"]}
    for name in events & set(commands):
        raise spec.error((*base, "events"), f"event {name!r} is also a command name")
    if sm["initial"] not in states:
        raise spec.error((*base, "initial"), f"unknown state {sm['initial']!r}")
    for i, st in enumerate(sm["states"]):
        path: PathKey = (*base, "states", i)
        if st["mode"] not in modes:
            raise spec.error((*path, "mode"), f"unknown mode {st['mode']!r}")
        if "expects" in st and st["expects"] not in payload_names:
            raise spec.error((*path, "expects"), f"unknown payload {st['expects']!r}")
    usw_modes = {m["name"] for m in d["status_word"]["mode"]["values"]} if d.get("status_word") else set()
    explicit: dict[tuple[str, str, str | None], PathKey] = {}
    for i, row in enumerate(sm["transitions"]):
        path = (*base, "transitions", i)
        for j, state in enumerate(row["from"]):
            if state not in states:
                raise spec.error((*path, "from", j), f"unknown state {state!r}")
        if row["to"] != "same" and row["to"] not in states:
            raise spec.error((*path, "to"), f"unknown state {row['to']!r}")
        for j, item in enumerate(row["send"]):
            if answer_kind(item, set(payload_names), usw_modes) is None:
                raise spec.error(
                    (*path, "send", j), f"unknown answer {item!r} (ack, output, output_ + a USW mode, or a payload)"
                )
        for j, event in enumerate(row["when"]):
            if event != "*" and event not in commands and event not in events:
                raise spec.error((*path, "when", j), f"unknown event {event!r}: not a command, an event or '*'")
            if event == "*":
                continue
            for state in row["from"]:
                key = (state, event, row.get("firmware_before"))
                if key in explicit:
                    line = spec.line_of(explicit[key])
                    raise spec.error(
                        (*path, "when", j), f"a second row for {event!r} in state {state!r} (first at line {line})"
                    )
                explicit[key] = (*path, "when", j)
                if event in commands and states[state]["mode"] not in commands[event]["valid_in"]:
                    raise spec.error(
                        (*path, "when", j),
                        f"{event} has a transition in state {state!r} (mode {states[state]['mode']}),"
                        f" but its valid_in does not list that mode",
                    )
            if event == "parameter_block":
                for state in row["from"]:
                    if "expects" not in states[state]:
                        raise spec.error((*path, "when", j), f"state {state!r} expects no parameter block")
    for name, command in commands.items():
        for mode in command["valid_in"]:
            if not any(states[st]["mode"] == mode and ev == name for (st, ev, _fw) in explicit):
                raise spec.error(
                    ("commands", list(commands).index(name), "valid_in"),
                    f"{name} is valid in mode {mode!r} but no state of that mode has a transition for it",
                )
    # A code shared by several names is resolved by mode, so their modes must not overlap.
    by_code: dict[int, list[dict[str, Any]]] = {}
    for c in d["commands"]:
        by_code.setdefault(c["code"], []).append(c)
    for group in by_code.values():
        for a_index, a in enumerate(group):
            for b in group[a_index + 1 :]:
                shared = set(a["valid_in"]) & set(b["valid_in"])
                if shared:
                    raise spec.error(
                        ("commands", d["commands"].index(b), "valid_in"),
                        f"{a['name']} and {b['name']} share code {a['code']:#04x}"
                        f" and are both valid in {sorted(shared)}",
                    )
    payloads = {p["name"]: p for p in d["payloads"]}
    timers = {}
    for i, t in enumerate(sm.get("timers", [])):
        path = (*base, "timers", i)
        if t["name"] in timers:
            raise spec.error((*path, "name"), f"duplicate timer {t['name']!r}")
        timers[t["name"]] = t
        if t["payload"] not in payloads:
            raise spec.error((*path, "payload"), f"unknown payload {t['payload']!r}")
        fields = {f["name"]: f for f in payloads[t["payload"]]["fields"]}
        if t["field"] not in fields:
            raise spec.error((*path, "field"), f"payload {t['payload']!r} has no field {t['field']!r}")
        unit = fields[t["field"]].get("unit")
        wanted = "Hz" if t["name"] == "output" else "s"
        if unit != wanted:
            raise spec.error((*path, "field"), f"the {t['name']} timer needs a field in {wanted}, not {unit}")
    for i, st in enumerate(sm["states"]):
        if "timer" in st and "timers" in sm and st["timer"] not in timers:
            raise spec.error((*base, "states", i, "timer"), f"no entry under timers sets the {st['timer']!r} timer")
        needed = []
        if "timer" in st:
            needed.append(TIMER_EVENTS[st["timer"]])
        if "expects" in st:
            needed.append("parameter_block")
        for event in needed:
            if (st["name"], event, None) not in explicit:
                raise spec.error((*base, "states", i), f"state {st['name']!r} has no transition for {event!r}")
