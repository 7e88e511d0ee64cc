"""The named rules a spec change is classified by, their classes, and a change as reported.

Every change the comparison reports names one rule, and the rule puts it in one of four classes:

    wire-breaking  an old device and a new host (or the reverse) disagree about bytes
    api-breaking   code written against the old bindings stops compiling or means something else
    additive       something new; what existed is unchanged
    docs           documentation only: no byte and no identifier changes
"""

from __future__ import annotations

import dataclasses
import json
from typing import Any

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
    "ENUM_CHANGED": (WIRE, "an enum's range of external values changed: a byte on the line means another thing"),
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


def show(value: Any) -> str:
    if value is None:
        return "none"
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        shown = (
            {k: v for k, v in plain_data(value).items() if k not in DOC_ATTRS}
            if isinstance(plain_data(value), dict)
            else value
        )
        return json.dumps(shown, sort_keys=True, default=str)
    if isinstance(value, tuple):
        return "[" + ", ".join(show(v) for v in value) + "]"
    if isinstance(value, str):
        return repr(value if len(value) <= 60 else value[:57] + "...")
    return str(value)


def plain_data(value: Any) -> Any:
    """A model value as JSON-able data, without source paths."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {
            f.name: plain_data(getattr(value, f.name)) for f in dataclasses.fields(value) if f.name not in SKIPPED_ATTRS
        }
    if isinstance(value, (tuple, list)):
        return [plain_data(v) for v in value]
    return value
