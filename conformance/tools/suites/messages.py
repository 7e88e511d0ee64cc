"""The notation the case files write bytes in, and the payload field values they give.

A *message* in a case file (the bytes of an input, of a chunk, of an expected event) is one of:

    "AA 55 00"                                  hex digits, spaces ignored ("" is no bytes)
    "@name", "@name[a:b]"                       a named message, or a Python slice of it
    [message, ...]                              the items one after the other
    {"text": "$PAHR,"}                          text, one Latin-1 byte per character
    {"repeat": message, "times": n}             the message n times
    {"counting": [a, b]}                        the bytes a, a + 1, ..., b - 1
    {"payload": table, "fields": {...}}         a payload block packed by the oracle; fields not given
                                                take the builders' default (field values: see below)
    {"frame": message, "type": "command" | "data", "reserved": n}
                                                a Table 6.2 frame around the payload, built by the
                                                oracle (length and checksum computed; reserved 0
                                                unless given)
    {"ack": message}                            the oracle's acknowledgement of a message (E12)
    {"sentence": {field: scaled integer}}       a $PAHR sentence written by the oracle (Table 6.7, E16;
                                                the USW may be written "0x8080")
    {"nmea": "PAHR,...", "checksum": "xy"}      "$" + the body + "*" + the checksum the oracle computes
                                                (or the one given) + CR LF
    {"replace": message, "old": text, "new": text}   the message with every `old` made `new`
    {"flip": message, "byte": i, "bit": b}      the message with one bit inverted

Any of the objects may add "length": n, the length the result must have (checked).

Field values are JSON values as the vectors write them, with these readings for strings in a
number field: "0x8080" is a number in hex, "nan", "inf", "-inf" are those floats, and in an f32
field "YYYY-MM-DD" is a date by the E15 formula Year + (Month - 1)/12 + Day/365 (char fields are
text and reserved fields hex digits, as in the vectors).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from typing import Any, ClassVar

import oracle as o

_REF = re.compile(r"@([\w.-]+)(?:\[(-?\d*):(-?\d*)\])?")
_DATE = re.compile(r"(\d{4})-(\d{2})-(\d{2})")
_TYPES = {"command": o.COMMAND, "data": o.DATA}


def number(value: Any) -> Any:
    """A number of a case file: "0x8080" is one in hex; "nan", "inf", "-inf" are those floats."""
    if not isinstance(value, str):
        return value
    return int(value, 16) if value.startswith("0x") else float(value)


def field_value(table: str, name: str, value: Any) -> Any:
    """A payload field value of a case file as the oracle takes it (see the module's note)."""
    field_type = {f.name: f.type for f in o.TABLES[table][2]}[name]
    date = _DATE.fullmatch(value) if field_type == "f32" and isinstance(value, str) else None
    if date is not None:
        year, month, day = (int(part) for part in date.groups())
        return year + (month - 1) / 12 + day / 365
    return number(value) if field_type == "f32" or field_type in o.INT_TYPES else value


def field_values(table: str, fields: Mapping[str, Any]) -> dict[str, Any]:
    return {name: field_value(table, name, value) for name, value in fields.items()}


def fill(table: str, values: Mapping[str, Any]) -> dict[str, Any]:
    """Every field of the table, from `values`, the rest their defaults (the vectors name every field)."""
    out: dict[str, Any] = {}
    for f in o.TABLES[table][2]:
        out[f.name] = values.get(f.name, f.default_value)
    assert set(values) <= set(out), set(values) - set(out)
    return out


def sentence_values(values: Mapping[str, Any]) -> dict[str, Any]:
    """$PAHR field values of a case file (numbers: see `number`)."""
    return {name: number(value) for name, value in values.items()}


def _payload(table: str, fields: Mapping[str, Any]) -> bytes:
    return o.encode_payload(table, fill(table, field_values(table, fields)))


class Messages:
    """Reads messages in the notation above; `named` holds the messages "@name" refers to."""

    def __init__(self, named: Mapping[str, Any] | None = None) -> None:
        self.named: dict[str, bytes] = {}
        for name, spec in (named or {}).items():
            self.named[name] = self.build(spec)

    def text(self, spec: Any) -> str:
        """A message that is text ($PAHR sentences): its bytes read as Latin-1."""
        return self.build(spec).decode("latin-1")

    def build(self, spec: Any) -> bytes:
        if isinstance(spec, str):
            return self._ref(spec) if spec.startswith("@") else bytes.fromhex(spec)
        if isinstance(spec, list):
            return b"".join(self.build(item) for item in spec)
        (key,) = set(spec) & set(self._BUILDERS)
        data = self._BUILDERS[key](self, spec)
        assert "length" not in spec or len(data) == spec["length"], (spec, len(data))
        return data

    def _ref(self, spec: str) -> bytes:
        match = _REF.fullmatch(spec)
        assert match is not None, spec
        name, start, stop = match.groups()
        data = self.named[name]
        if match.group(2) is None:
            return data
        return data[int(start) if start else None : int(stop) if stop else None]

    def _frame(self, spec: Mapping[str, Any]) -> bytes:
        return o.frame(_TYPES[spec["type"]], self.build(spec["frame"]), spec.get("reserved", 0))

    def _flip(self, spec: Mapping[str, Any]) -> bytes:
        data = bytearray(self.build(spec["flip"]))
        data[spec["byte"]] ^= 1 << spec["bit"]
        return bytes(data)

    def _shift(self, spec: Mapping[str, Any]) -> bytes:
        """One byte moved by a signed amount (never wrapped): with an opposite shift elsewhere in
        the summed bytes, the 16-bit checksum stays the same (E42)."""
        data = bytearray(self.build(spec["shift"]))
        value = data[spec["byte"]] + spec["by"]
        assert 0 <= value <= 0xFF, spec
        data[spec["byte"]] = value
        return bytes(data)

    def _nmea(self, spec: Mapping[str, Any]) -> bytes:
        return o.sentence(spec["nmea"], spec.get("checksum")).encode("latin-1")

    def _replace(self, spec: Mapping[str, Any]) -> bytes:
        old, new = (spec[key].encode("latin-1") for key in ("old", "new"))
        return self.build(spec["replace"]).replace(old, new)

    _BUILDERS: ClassVar[dict[str, Callable[[Messages, Mapping[str, Any]], bytes]]] = {
        "text": lambda self, spec: spec["text"].encode("latin-1"),
        "repeat": lambda self, spec: self.build(spec["repeat"]) * spec["times"],
        "counting": lambda self, spec: bytes(range(*spec["counting"])),
        "payload": lambda self, spec: _payload(spec["payload"], spec.get("fields", {})),
        "frame": _frame,
        "ack": lambda self, spec: o.ack(self.build(spec["ack"])),
        "sentence": lambda self, spec: o.build_sentence(sentence_values(spec["sentence"])).encode("latin-1"),
        "nmea": _nmea,
        "replace": _replace,
        "flip": _flip,
        "shift": _shift,
    }
