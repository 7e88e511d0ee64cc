"""payloads: every payload table decoded and encoded, its bounds, its refusals and its sizes.

cases/payloads.json gives, per table, a typical block and a list of cases, each one of
    {"ok": name, "fields": {...}}          a block builders accept: encoded, and decoded back (per
                                           variant: "variants": [null, "g300_a6_tmga", ...] or "all")
    {"decode_raw": name, "fields": {...}}  a block packed without range checks, decoded
    {"encode": name, "fields": {...}}      an encode request with exactly these fields
    {"refuse": name, "fields": {f: v}}     the typical block with one field out of range: refused
with a note; "typical": true starts the fields from the typical block. Each table ends with its
size vectors (truncated, trailing data, and with "empty": true no bytes at all). Field values:
suites/messages.py.
"""

from __future__ import annotations

import struct
from collections.abc import Iterable
from typing import Any

import oracle as o

from .common import Vector, attempt, cases, expand, hx, jsonable, phrases, vec
from .levels import variant_erratum
from .messages import field_values, fill

SUITE = "payloads"


def _raw_pack(table: str, values: dict[str, Any]) -> bytes:
    """Pack without range checks: how a device may fill a block that builders would refuse."""
    data = b""
    for f in o.TABLES[table][2]:
        value = values[f.name]
        if f.type == "f32":
            data += struct.pack("<f", float(value))
        elif f.type == "char":
            data += str(value).encode("latin-1").ljust(f.size, b"\x00")
        elif f.type == "reserved":
            data += bytes.fromhex(value)
        else:
            data += struct.pack(o.INT_TYPES[f.type][0], value)
    return data


def _decode_expect(table: str, data: bytes, variant: str | None) -> Any:
    def run() -> dict[str, Any]:
        raw = o.decode_payload(table, data)
        out: dict[str, Any] = {"fields": {k: jsonable(v) for k, v in raw.items()}}
        values = o.engineering(table, raw, variant)
        if values:
            out["values"] = values
        return out

    return attempt(run)


def _decode_input(table: str, data: bytes, variant: str | None) -> dict[str, Any]:
    out: dict[str, Any] = {"type": table, "hex": hx(data)}
    if variant is not None:
        out["variant"] = variant
    return out


def _encode_input(table: str, fields: dict[str, Any]) -> dict[str, Any]:
    return {"type": table, "fields": {k: jsonable(v) for k, v in fields.items()}}


class PayloadCases:
    """Collects the vectors of one payload table."""

    def __init__(self, table: str, typical: dict[str, Any], tests: str | None = None) -> None:
        self.table = table
        self.typical = typical
        self.layout = tests  # the erratum the table's own fields rest on (every case, not the sizes)
        self.tests: str | None = None  # the erratum the current vectors test
        self.icd, self.size, self.fields = o.TABLES[table]
        self.vectors: list[Vector] = []
        self.offsets = {}
        offset = 0
        for f in self.fields:
            self.offsets[f.name] = offset
            offset += f.size

    def _add(
        self, kind: str, name: str, input_: dict[str, Any], expect: Any, note: str, *, tests: str | None = None
    ) -> None:
        tests = tests or self.tests
        if tests is not None and tests == self.layout and tests not in note:
            note += f"; the table's fields as {tests} lays them out"
        self.vectors.append(vec(f"{kind}/{self.table}/{name}", kind, input_, expect, note, tests=tests))

    def _decode(self, name: str, data: bytes, variant: str | None, note: str) -> None:
        input_ = _decode_input(self.table, data, variant)
        tests = variant_erratum(variant) if variant is not None else None
        if tests is not None:
            note += f"; variant {variant}'s scales are assumed ({tests})"
        self._add("payload_decode", name, input_, _decode_expect(self.table, data, variant), note, tests=tests)

    def ok(self, name: str, note: str, values: dict[str, Any], variants: Iterable[str | None] = (None,)) -> None:
        """A block builders accept: encode it, and decode the bytes back (per variant)."""
        full = fill(self.table, values)
        data = o.encode_payload(self.table, full)
        where = f"{self.icd} ({self.table}); {note}; bytes packed little-endian by the oracle"
        for variant in variants:
            self._decode(f"{name}-{variant}" if variant else name, data, variant, where)
        self._add("payload_encode", name, _encode_input(self.table, full), hx(data), where)

    def encode(self, name: str, note: str, fields: dict[str, Any]) -> None:
        """An encode vector with exactly these fields given (defaults or refusals)."""
        expect = attempt(lambda: hx(o.encode_payload(self.table, fields)))
        where = f"{self.icd} ({self.table}); {note}"
        self._add("payload_encode", name, _encode_input(self.table, fields), expect, where)

    def refuse(self, name: str, note: str, change: dict[str, Any]) -> None:
        """The typical block with one field changed to a value builders refuse (spec/README.md, payload encode)."""
        fields = fill(self.table, {**self.typical, **change})
        expect = attempt(lambda: hx(o.encode_payload(self.table, fields)))
        assert isinstance(expect, dict) and expect["error"] == "out_of_range", (name, expect)
        (field,) = change
        assert expect["field"] == field and expect["offset"] == self.offsets[field]
        where = f"{self.icd} ({self.table}); {note}; refused at the field's offset"
        self._add("payload_encode", name, _encode_input(self.table, fields), expect, where)

    def decode_raw(self, name: str, note: str, values: dict[str, Any]) -> None:
        """Decode a block packed without range checks: decoders never range-check."""
        data = _raw_pack(self.table, fill(self.table, values))
        where = f"{self.icd} ({self.table}); {note}; spec/README.md: decoders do not range-check"
        self._decode(name, data, None, where)

    def sizes(self, empty: bool) -> None:
        """The typical block less its last byte and with one byte more; with `empty`, no bytes."""
        data = o.encode_payload(self.table, fill(self.table, self.typical))
        sizes = [
            ("truncated", data[:-1], f"the typical block without its last byte: truncated at {self.size - 1}"),
            ("trailing-data", data + b"\x00", f"the typical block and one more byte: trailing_data at {self.size}"),
        ]
        if empty:
            sizes.append(("empty", b"", "no bytes at all: truncated at 0"))
        for name, chunk, text in sizes:
            where = f"{self.icd} ({self.table}) is {self.size} bytes; {text} (spec/README.md)"
            self._decode(name, chunk, None, where)

    def case(self, case: dict[str, Any], names: dict[str, str]) -> None:
        """One case of the case file."""
        (action,) = set(case) & {"ok", "decode_raw", "encode", "refuse"}
        fields = field_values(self.table, case.get("fields", {}))
        if case.get("typical"):
            fields = {**self.typical, **fields}
        text = expand(case["note"], names)
        self.tests = case.get("tests", self.layout)
        if action == "ok":
            variants = case.get("variants", [None])
            self.ok(case[action], text, fields, [None, *o.VARIANTS] if variants == "all" else variants)
        else:
            getattr(self, action)(case[action], text, fields)
        self.tests = None


def vectors() -> list[Vector]:
    names = phrases(SUITE)
    out: list[Vector] = []
    for table, spec in cases(SUITE)["tables"].items():
        p = PayloadCases(table, field_values(table, spec["typical"]), spec.get("tests"))
        for case in spec["cases"]:
            p.case(case, names)
        p.sizes(empty=spec.get("empty", False))
        out += p.vectors
    return out
