"""The Wireshark target: one Lua dissector, generated/wireshark/ilahrs.lua, with its README and a
description of every display-filter field.

The template writes the spec as Lua tables (frame, commands, payload tables, encodings, status word,
$PAHR sentence, state machine); the dissector itself is hand-written Lua in runtime/ that reads only
those tables, inlined after them so that the dissector is one file to install. Nothing here decides
a protocol fact: the filters turn model objects into Lua literals and name the filter fields.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from typing import Any

from generator.model import TIMER_EVENTS, Command, Field, NmeaField, Spec, StatusWord
from generator.render import Output, Runtime

__all__ = ["FILTERS", "GLOBALS", "outputs"]

# The dissector's hand-written parts, in the order the generated file holds them.
RUNTIME = ("protocol.lua", "stream.lua", "context.lua", "fields.lua", "dissector.lua")

# Wireshark field types of the wire types, and of an engineering value.
FIELD_TYPES = {
    "u8": "uint8",
    "s8": "int8",
    "u16": "uint16",
    "s16": "int16",
    "u32": "uint32",
    "s32": "int32",
    "f32": "float",
    "char": "string",
    "reserved": "bytes",
}
ENGINEERING_TYPE = "double"
# The unit of the predicted accuracy the calibration success byte carries (x accuracy_divisor).
ACCURACY_UNIT = "deg"

_LUA_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
# Lua's reserved words: never a bare record key.
_LUA_KEYWORDS = frozenset(
    [
        "and",
        "break",
        "do",
        "else",
        "elseif",
        "end",
        "false",
        "for",
        "function",
        "goto",
        "if",
        "in",
        "local",
        "nil",
        "not",
        "or",
        "repeat",
        "return",
        "then",
        "true",
        "until",
        "while",
    ]
)


def outputs(spec: Spec) -> list[Output | Runtime]:
    if spec.state_machine is None or spec.nmea is None or spec.status_word is None:
        raise KeyError("the Wireshark dissector needs the spec's state_machine, nmea and status_word")
    return [
        Output(f"wireshark/{spec.name}.lua", "dissector.lua.j2", {"runtime": RUNTIME}),
        Output("wireshark/README.md", "README.md.j2"),
        Output("docs/wireshark.md", "FIELDS.md.j2"),
    ]


def lua(value: object) -> str:
    """A Lua literal: strings double-quoted and escaped, lists as sequences, dicts as records
    (identifier keys bare, others bracketed), None as nil."""
    if value is None:
        return "nil"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{value!r} has no Lua literal")
        return repr(value)
    if isinstance(value, str):
        escaped = value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\r", "\\r")
        return f'"{escaped}"'
    if isinstance(value, (list, tuple)):
        return "{ " + ", ".join(lua(v) for v in value) + " }" if value else "{}"
    if isinstance(value, dict):
        items = [f"{_lua_key(k)} = {lua(v)}" for k, v in value.items() if v is not None]
        return "{ " + ", ".join(items) + " }" if items else "{}"
    raise TypeError(f"no Lua literal for {value!r}")


def _lua_key(key: object) -> str:
    if isinstance(key, str) and _LUA_NAME.match(key) and key not in _LUA_KEYWORDS:
        return key
    return f"[{lua(key)}]"


def field_label(f: Field, fields: Sequence[Field] = ()) -> str:
    """A field's title for Wireshark's tree: the ICD's name, with the last part of the field's name
    ("Ugyro X", "Matrix for soft iron correction 11") when other fields of its table share it."""
    if sum(1 for g in fields if g.icd_name == f.icd_name) > 1:
        return f"{f.icd_name} {f.name.rsplit('_', 1)[-1].upper()}"
    return f.icd_name


def field_row(f: Field, fields: Sequence[Field] = ()) -> dict[str, Any]:
    """What the dissector needs of a payload or frame field (`fields`: its table's, for its label)."""
    scale = f.scale
    return {
        "name": f.name,
        "icd_name": f.icd_name,
        "label": field_label(f, fields),
        "type": f.type.name,
        "offset": f.offset,
        "size": f.size,
        "unit": f.unit.key if f.unit is not None else None,
        "multiplier": scale.multiplier if scale is not None else None,
        "divisor": (scale.divisor_parameter or scale.divisor) if scale is not None else None,
        "enum": f.enum,
        "encoding": f.encoding,
        "multiplexed": f.multiplexed_count,
        "erratum": f.erratum,
        "doc": f.doc,
    }


def nmea_label(f: NmeaField, spec: Spec) -> str:
    """A $PAHR field's title: that of the payload field of the same name (Roll, USW), else its name."""
    for p in spec.payloads:
        for g in p.fields:
            if g.name == f.name:
                return g.icd_name
    return f.name.replace("_", " ").capitalize()


def nmea_row(f: NmeaField, spec: Spec) -> dict[str, Any]:
    """A $PAHR field; its hex field is the Unit Status Word (the only one the sentence has)."""
    return {
        "name": f.name,
        "icd_name": f.icd_name,
        "label": nmea_label(f, spec),
        "format": f.format,
        "width": f.width,
        "decimals": f.decimals,
        "unit": f.unit or None,
        "min": f.min,
        "max": f.max,
        "encoding": "usw" if f.format == "hex" else None,
        "doc": f.doc,
    }


def command_row(c: Command) -> dict[str, Any]:
    return {
        "name": c.name,
        "id": c.id,
        "code": c.code,
        "icd": c.icd,
        "group": c.group,
        "purpose": c.purpose,
        "valid_in": list(c.valid_in),
        "response": c.response_kind,
        "payloads": list(c.response_payloads),
        "starts_output": c.starts_output,
        "parameter_block": c.parameter_block,
        "default_for_code": c.default_for_code,
        "former_names": [f.name for f in c.former_names],
        "erratum": c.erratum,
    }


def encodings(spec: Spec) -> dict[str, Any]:
    """The value encodings the dissector shows decoded: date, declination, calibration success."""
    result: dict[str, Any] = {}
    if spec.date is not None:
        terms = [{"part": t.part, "offset": t.offset, "divisor": t.divisor} for t in spec.date.terms]
        result["date"] = {"terms": terms, "year_min": spec.date.year_min, "year_max": spec.date.year_max}
    if spec.declination is not None:
        d = spec.declination
        result["declination"] = {"min": d.min, "max": d.max, "compute_above": d.compute_above}
    if spec.calibration_success is not None:
        c = spec.calibration_success
        result["calibration_success"] = {
            "failed": c.failed,
            "no_estimate": c.no_estimate,
            "accuracy_divisor": c.accuracy_divisor,
            "accuracy_unit": ACCURACY_UNIT,
        }
    return result


def output_formats(spec: Spec) -> dict[str, str | bool]:
    """Output format a start command chooses -> its payload table, or false for $PAHR sentences."""
    names = {p.name for p in spec.payloads}
    result: dict[str, str | bool] = {}
    for c in spec.commands:
        if c.starts_output is None or c.starts_output in result:
            continue
        if c.starts_output not in names and c.starts_output != "nmea":
            raise KeyError(f"{c.name} starts output {c.starts_output!r}: neither a payload nor the nmea sentence")
        result[c.starts_output] = c.starts_output if c.starts_output in names else False
    return result


def to_dict(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    return dict(pairs)


def usw_modes(sw: StatusWord) -> list[dict[str, Any]]:
    return [{"name": m.name, "pattern": sw.mode_pattern(m), "doc": m.doc} for m in sw.modes]


def field_type(f: Field) -> str:
    return FIELD_TYPES[f.type.name]


def scaled(f: Field) -> bool:
    """The field has an engineering value besides its raw one."""
    return f.scale is not None


def scale_text(f: Field) -> str:
    """raw x multiplier / divisor, as the description of a field says it."""
    s = f.scale
    if s is None:
        return ""
    text = "raw"
    if s.multiplier != 1:
        text += f" x {s.multiplier}"
    divisor = s.divisor_parameter or s.divisor
    if divisor not in (None, 1):
        text += f" / {divisor}"
    return text


# The dissector's own fields and expert infos (runtime/fields.lua), for FIELDS.md; the test holds
# this list against what tshark registers (`tshark -G fields`).
GENERIC_FIELDS = (
    (
        "kind",
        "string",
        "What the message is: command, parameter_block, ack, data, output, unexpected, unknown_command or other.",
    ),
    ("table", "string", "The payload table the context decodes the payload as."),
    ("command", "string", "The command's name in the device's mode."),
    ("command_code", "uint8", "The command code."),
    ("source", "string", "The command, parameter block or timer event that made the device send this message."),
    ("state", "string", "The device's state after this message, as the context follows it."),
    ("request_in", "frame number", "The host message this message answers."),
    ("response_in", "frame number", "A message that answers this host message (known on a second pass)."),
    ("ack_frame", "frame number", "The host message this acknowledgement acknowledges."),
    ("late", "boolean", "Output sent before the device left the state that sends it, received after."),
    ("starts_in", "frame number", "The packet a reassembled message starts in."),
    ("header", "bytes", "The frame header."),
    ("payload", "bytes", "The payload of a damaged frame."),
    ("checksum", "uint16", "The frame checksum as sent."),
    ("checksum.computed", "uint16", "The checksum computed over the received bytes (damaged messages)."),
    ("checksum.status", "uint8", "0: bad, 1: good (frames and sentences)."),
    ("discarded", "bytes", "Bytes that belong to no valid frame or sentence."),
    (
        "damaged",
        "string",
        "Why a frame or sentence was rejected: bad checksum, truncated, or the sentence check it failed.",
    ),
    ("undecoded", "bytes", "A payload no context explains (which table it follows is never guessed)."),
    ("candidates", "string", "The payload tables of an undecoded payload's size."),
    ("usw.mode", "string", "The mode the USW mode bits say."),
    ("expert.bad_checksum", "expert", "Warning: a frame or sentence whose checksum does not match."),
    (
        "expert.damaged",
        "expert",
        "Warning: a truncated frame or sentence (the next message starts inside it), or a $-sentence that "
        "failed a check other than its checksum.",
    ),
    ("expert.discarded", "expert", "Note: bytes discarded."),
    ("expert.unexpected", "expert", "Warning: a device message nothing in the context explains."),
    ("expert.wrong_ack", "expert", "Warning: an acknowledgement that carries another checksum."),
    ("expert.missing", "expert", "Warning: an answer that did not come within the answer timeout."),
    ("expert.ignored", "expert", "Note: a host message the device ignores in its state (no transition)."),
    ("expert.unknown_command", "expert", "Warning: a command code no command has."),
    ("expert.late", "expert", "Chat: output from the state the device has just left."),
    (
        "expert.no_start",
        "expert",
        "Note: output with no start command before it; names the preference for a capture begun mid-stream.",
    ),
)


def generic_fields(spec: Spec) -> list[tuple[str, str, str]]:
    """Filter name, type and meaning of every field that is not a payload or $PAHR field."""
    assert spec.status_word is not None and spec.nmea is not None
    rows = [(f"{spec.name}.{name}", kind, doc) for name, kind, doc in GENERIC_FIELDS]
    rows += [(f"{spec.name}.{f.name}", field_type(f), f.doc) for f in spec.frame.fields]
    rows += [(f"{spec.name}.usw.{f.name}", "boolean", f"USW bit {f.bit}: {f.doc}") for f in spec.status_word.flags]
    sentence = f"{spec.name}.{spec.nmea.identifier.lower()}"
    rows += [
        (f"{sentence}.sentence", "string", "The sentence text, without CR LF."),
        (f"{sentence}.checksum", "uint8", "The sentence checksum as sent."),
        (f"{sentence}.checksum.computed", "uint8", "The checksum computed over the received characters."),
    ]
    return rows


def shared_codes(spec: Spec) -> list[str]:
    """Codes several commands share, with their names: "0xFE: ExitClb, Stop"."""
    shared = [code for code in spec.codes if len(spec.commands_with_code(code)) > 1]
    return [f"0x{code:02X}: {', '.join(c.name for c in spec.commands_with_code(code))}" for code in shared]


def cell(text: object) -> str:
    """Text safe inside a Markdown table cell."""
    return str(text).replace("|", "\\|").replace("\n", " ")


FILTERS: dict[str, Callable[..., Any]] = {
    "lua": lua,
    "field_row": field_row,
    "command_row": command_row,
    "encodings": encodings,
    "output_formats": output_formats,
    "to_dict": to_dict,
    "nmea_row": nmea_row,
    "field_label": field_label,
    "nmea_label": nmea_label,
    "usw_modes": usw_modes,
    "field_type": field_type,
    "scaled": scaled,
    "scale_text": scale_text,
    "cell": cell,
}

GLOBALS: dict[str, Any] = {
    "ENGINEERING_TYPE": ENGINEERING_TYPE,
    "ACCURACY_UNIT": ACCURACY_UNIT,
    "TIMER_EVENTS": TIMER_EVENTS,
    "generic_fields": generic_fields,
    "shared_codes": shared_codes,
}
