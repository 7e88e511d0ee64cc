"""Validation of the spec's sections besides commands and the state machine (part of
generator.validate): errata, error kinds, modes, variants, enums, the frame, the payloads, the
acknowledgement, the unit status word and the $PAHR sentence."""

from __future__ import annotations

from typing import Any

from ..load import LoadedSpec, PathKey
from ..model.fields import PRIMITIVES
from .common import Names, duplicates, unique
from .fields import check_field

# The frame fields the bindings rely on, by name and type.
REQUIRED_FRAME_FIELDS = {"message_type": "u8", "reserved": "u8", "message_length": "u16"}
MESSAGE_LENGTH_MAX = 0xFFFF  # what message_length, a u16, holds
# The longest frame the C runtime holds: its stream decoder keeps the bytes of an incomplete frame
# with a uint8_t start and count (ilahrs_stream_t, generator/targets/c/runtime/api_stream.h), and
# stream.c asserts ILAHRS_FRAME_MAX_SIZE <= 255 at compile time. Python and Rust hold any u16 length.
C_FRAME_MAX_SIZE = 0xFF


def check_names(spec: LoadedSpec) -> Names:
    """Errata, error kinds, modes, variants and enum values are each named once (and every erratum
    named elsewhere exists); return what the other sections may refer to."""
    d = spec.data
    errata = [e["id"] for e in d.get("errata", [])]
    duplicates(((("errata", i, "id"), e) for i, e in enumerate(errata)), "erratum id", spec)
    for i, e in enumerate(d.get("errata", [])):
        _check_erratum_side(spec, e, ("errata", i))
    _check_erratum_refs(spec, {k: v for k, v in d.items() if k != "errata"}, (), set(errata))
    unique(spec, d["errors"], ("errors",), "name", "error kind")
    modes = [m["name"] for m in d.get("modes", [])]
    duplicates(((("modes", i, "name"), m) for i, m in enumerate(modes)), "mode", spec)
    parameters = _check_variants(spec, d.get("variants", {"parameters": {}, "list": []}))
    enums = d.get("enums", {})
    for name, e in enums.items():
        for key, what in (("name", "enum value name"), ("value", "enum value")):
            unique(spec, e["values"], ("enums", name, "values"), key, what)
    return Names(
        units=set(d.get("units", {})),
        variant_parameters=parameters,
        enums=enums,
        encodings=set(d.get("encodings", {})),
        status_word=d.get("status_word"),
        errata=set(errata),
        modes=modes,
        payloads=[p["name"] for p in d["payloads"]],
    )


def _check_erratum_side(spec: LoadedSpec, erratum: dict[str, Any], path: PathKey) -> None:
    """An erratum says whether an implementation may take another side: `alternative` (that other
    reading, in one sentence), or none (`correction: true`, or nothing: only one reading); not both."""
    if "alternative" not in erratum:
        return
    if erratum.get("correction") is True:
        raise spec.error((*path, "correction"), "an erratum with an alternative is no correction: give one of them")
    if not str(erratum["alternative"]).strip():
        raise spec.error((*path, "alternative"), "an empty alternative: write the other reading, or 'correction: true'")


def _check_erratum_refs(spec: LoadedSpec, value: Any, path: PathKey, errata: set[str]) -> None:
    if isinstance(value, dict):
        for key, item in value.items():
            if key == "erratum" and isinstance(item, str) and item not in errata:
                raise spec.error((*path, key), f"unknown erratum {item!r}")
            _check_erratum_refs(spec, item, (*path, key), errata)
    elif isinstance(value, list):
        for index, item in enumerate(value):
            _check_erratum_refs(spec, item, (*path, index), errata)


def _check_variants(spec: LoadedSpec, variants: dict[str, Any]) -> set[str]:
    """Variants named once, each giving exactly the declared parameters; return the parameters."""
    parameters = set(variants["parameters"])
    unique(spec, variants["list"], ("variants", "list"), "name", "variant")
    for i, v in enumerate(variants["list"]):
        if set(v["values"]) != parameters:
            raise spec.error(
                ("variants", "list", i, "values"),
                f"variant {v['name']!r} must give exactly the parameters {sorted(parameters)}",
            )
    return parameters


def check_frame(spec: LoadedSpec, frame: dict[str, Any], names: Names) -> None:
    """Valid fields, among them the ones the bindings rely on; a sum16 checksum; the message types
    `command` and `data`; length bounds a u16 holds, low first."""
    for i, f in enumerate(frame["fields"]):
        check_field(spec, f, ("frame", "fields", i), names)
    unique(spec, frame["fields"], ("frame", "fields"), "name", "frame field")
    types = {f["name"]: f["type"] for f in frame["fields"]}
    for name, type_name in REQUIRED_FRAME_FIELDS.items():
        if types.get(name) != type_name:
            raise spec.error(("frame", "fields"), f"the frame needs a field {name!r} of type {type_name}")
    if frame["checksum"]["type"] != "u16":
        raise spec.error(("frame", "checksum", "type"), "the sum16 checksum is a u16")
    unique(spec, frame["message_types"], ("frame", "message_types"), "value", "message type value")
    unique(spec, frame["message_types"], ("frame", "message_types"), "name", "message type name")
    if {t["name"] for t in frame["message_types"]} != {"command", "data"}:
        raise spec.error(("frame", "message_types"), "message types must be exactly `command` and `data`")
    lengths = frame["message_length"]
    if lengths["min"] > lengths["max"]:
        raise spec.error(("frame", "message_length"), f"min {lengths['min']} is above max {lengths['max']}")
    if lengths["max"] > MESSAGE_LENGTH_MAX:
        raise spec.error(("frame", "message_length", "max"), "the message length is a u16")
    c_limit = C_FRAME_MAX_SIZE - len(frame["header"])
    if lengths["max"] > c_limit:
        raise spec.error(
            ("frame", "message_length", "max"),
            f"{lengths['max']} is above {c_limit}: the C runtime holds frames of at most {C_FRAME_MAX_SIZE} bytes "
            f"(header {len(frame['header'])} + message length; ilahrs_stream_t counts held bytes in a uint8_t)",
        )
    strict = frame.get("strict")
    if strict is not None and strict["message_type"] not in {t["name"] for t in frame["message_types"]}:
        raise spec.error(("frame", "strict", "message_type"), f"unknown message type {strict['message_type']!r}")


def check_payloads(spec: LoadedSpec, payloads: list[dict[str, Any]], names: Names) -> None:
    """Payloads named once, each with valid fields named once."""
    duplicates(((("payloads", i, "name"), p["name"]) for i, p in enumerate(payloads)), "payload", spec)
    for i, p in enumerate(payloads):
        unique(spec, p["fields"], ("payloads", i, "fields"), "name", f"field in payload {p['name']!r}:")
        for j, f in enumerate(p["fields"]):
            check_field(spec, f, ("payloads", i, "fields", j), names)


def check_acknowledgement(spec: LoadedSpec, ack: dict[str, Any] | None, names: Names) -> None:
    if ack is not None and ack["payload"] not in names.payloads:
        raise spec.error(("acknowledgement", "payload"), f"unknown payload {ack['payload']!r}")


def check_status_word(spec: LoadedSpec, sw: dict[str, Any]) -> None:
    """Flags with distinct bits and names inside an unsigned word, none on a mode bit, each in a
    declared byte; one value per mode bit in each mode, modes named once."""
    base: PathKey = ("status_word",)
    unique(spec, sw["flags"], (*base, "flags"), "bit", "status bit")
    unique(spec, sw["flags"], (*base, "flags"), "name", "status flag")
    width = PRIMITIVES[sw["type"]].size if sw["type"] in PRIMITIVES else None
    if width is None or PRIMITIVES[sw["type"]].kind != "unsigned":
        raise spec.error((*base, "type"), f"the status word must be an unsigned integer type, not {sw['type']!r}")
    byte_names = {b["name"] for b in sw.get("bytes", [])}
    for i, f in enumerate(sw["flags"]):
        if f["bit"] >= width * 8:
            raise spec.error((*base, "flags", i, "bit"), f"bit {f['bit']} is outside a {sw['type']}")
        if f["bit"] in sw["mode"]["bits"]:
            raise spec.error((*base, "flags", i, "bit"), f"bit {f['bit']} is a mode bit")
        if f["byte"] not in byte_names:
            raise spec.error((*base, "flags", i, "byte"), f"unknown byte {f['byte']!r}")
    for i, m in enumerate(sw["mode"]["values"]):
        if len(m["bits"]) != len(sw["mode"]["bits"]):
            raise spec.error((*base, "mode", "values", i, "bits"), "one value per mode bit")
    unique(spec, sw["mode"]["values"], (*base, "mode", "values"), "name", "status mode")


def check_nmea(spec: LoadedSpec, nmea: dict[str, Any]) -> None:
    """Sentence fields named once, each with an integer range (low first) its digits can print, and
    their widths alone within the sentence's maximum length ("$ID", a comma before each field, "*hh" CR LF)."""
    unique(spec, nmea["fields"], ("nmea", "fields"), "name", "sentence field")
    shortest = 1 + len(nmea["identifier"]) + 5
    for i, f in enumerate(nmea["fields"]):
        shortest += 1 + f["width"]
        limit = nmea.get("max_length")
        if limit is not None and shortest > limit:
            message = f"the sentence is at least {shortest} characters up to this field, above max_length {limit}"
            raise spec.error(("nmea", "fields", i, "width"), message)
        low, high = f["range"]
        if not (isinstance(low, int) and isinstance(high, int)) or low > high:
            raise spec.error(
                ("nmea", "fields", i, "range"), "the range of a sentence field is a pair of integers, low first"
            )
        if f["format"] == "hex" and (low < 0 or high >= 16 ** f["width"]):
            raise spec.error(("nmea", "fields", i, "range"), f"range does not fit {f['width']} hex digits")
