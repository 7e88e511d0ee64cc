"""Step 3 of the pipeline, the build: validated spec data into the model's immutable objects.

One function per section of the spec, each turning plain data (dicts and lists, as load read
them) into the dataclasses of generator.model. Nothing here checks anything: validate has done
that; nothing here computes placement: that is the layout step's.
"""

from __future__ import annotations

import struct
from typing import Any

from ..load import LoadedSpec, PathKey
from .build_machine import state_machine
from .encodings import (
    CalibrationSuccessEncoding,
    DateEncoding,
    DateTerm,
    DeclinationEncoding,
    Enum,
    EnumValue,
    Nmea,
    NmeaField,
    StatusFlag,
    StatusMode,
    StatusWord,
)
from .fields import PRIMITIVES, Field, Payload, Scale, Unit
from .frame import Command, FormerName, Frame, MessageType, Strict
from .spec import Erratum, ErrorKind, Mode, SerialLine, Spec, Variant, VariantParameter
from .text import prose


def build(loaded: LoadedSpec) -> Spec:
    """Turn validated data into the model. Call generator.validate.validate first."""
    d = loaded.data
    units = {
        key: Unit(key=key, suffix=u["suffix"], doc=prose(u["doc"]), symbol=u.get("symbol", key))
        for key, u in d.get("units", {}).items()
    }
    encodings = d.get("encodings", {})
    date_bounds = _date_bounds(encodings["date"]) if encodings.get("date") else None
    status_word = _status_word(d["status_word"]) if "status_word" in d else None
    variants = d.get("variants", {"parameters": {}, "list": []})
    ack = d.get("acknowledgement", {})
    return Spec(
        name=d["spec"]["name"],
        version=d["spec"]["version"],
        byte_order=d["byte_order"],
        icd_title=d["spec"]["icd"]["title"],
        icd_revision=str(d["spec"]["icd"]["revision"]),
        icd_date=str(d["spec"]["icd"]["date"]),
        file=loaded.file,
        sha256=loaded.sha256,
        errors=tuple(ErrorKind(e["name"], prose(e["doc"])) for e in d["errors"]),
        modes=tuple(Mode(m["name"], prose(m["doc"]), m.get("icd", "")) for m in d.get("modes", [])),
        units=tuple(units.values()),
        variant_parameters=tuple(VariantParameter(k, prose(v["doc"])) for k, v in variants["parameters"].items()),
        variants=tuple(_variant(v) for v in variants["list"]),
        frame=_frame(d["frame"], units),
        commands=tuple(_command(c, i) for i, c in enumerate(d["commands"])),
        ack_payload=ack.get("payload"),
        ack_doc=prose(ack.get("doc")),
        payloads=_payloads(d["payloads"], units, date_bounds),
        enums=tuple(_enum(name, e) for name, e in d.get("enums", {}).items()),
        date=_date(encodings["date"]) if "date" in encodings else None,
        declination=_declination(encodings["declination"]) if "declination" in encodings else None,
        calibration_success=_calibration_success(encodings["calibration_success"])
        if "calibration_success" in encodings
        else None,
        status_word=status_word,
        nmea=_nmea(d["nmea"]) if "nmea" in d else None,
        errata=tuple(
            Erratum(
                e["id"],
                prose(e["where"]),
                prose(e["says"]),
                prose(e["chosen"]),
                prose(e["why"]),
                prose(e["alternative"]) if "alternative" in e else None,
            )
            for e in d.get("errata", [])
        ),
        state_machine=state_machine(
            d["state_machine"],
            [c["name"] for c in d["commands"]],
            {p["name"] for p in d["payloads"]},
            {m.name for m in status_word.modes} if status_word is not None else set(),
        )
        if "state_machine" in d
        else None,
        serial_line=_serial_line(d["serial_line"]) if "serial_line" in d else None,
    )


# Fields, payloads, frame and commands.


def _field(
    raw: dict[str, Any], path: PathKey, units: dict[str, Unit], date_bounds: tuple[float, float] | None = None
) -> Field:
    primitive = PRIMITIVES[raw["type"]]
    size = primitive.size if primitive.size is not None else int(raw["length"])
    scale = None
    if "scale" in raw:
        divisor = raw["scale"].get("divisor", 1)
        scale = Scale(
            multiplier=int(raw["scale"].get("multiplier", 1)),
            divisor=divisor if isinstance(divisor, int) else None,
            divisor_parameter=divisor if isinstance(divisor, str) else None,
        )
    value_range = None
    if "range" in raw:
        value_range = (raw["range"][0], raw["range"][1])
    elif raw.get("encoding") == "date" and date_bounds is not None:
        value_range = date_bounds
    multiplexed = raw.get("multiplexed")
    return Field(
        name=raw["name"],
        icd_name=raw.get("icd_name", raw["name"]),
        type=primitive,
        size=size,
        doc=" ".join(str(raw.get("doc", "")).split()),
        path=path,
        unit=units[raw["unit"]] if "unit" in raw else None,
        scale=scale,
        range=value_range,
        default=raw.get("default"),
        enum=raw.get("enum"),
        encoding=raw.get("encoding"),
        multiplexed_count=multiplexed["count"] if multiplexed else None,
        multiplexed_quantities=tuple(multiplexed.get("quantities", ())) if multiplexed else (),
        erratum=raw.get("erratum"),
        declared_offset=raw.get("offset"),
    )


def _payloads(
    raw: list[dict[str, Any]], units: dict[str, Unit], date_bounds: tuple[float, float] | None
) -> tuple[Payload, ...]:
    return tuple(
        Payload(
            name=p["name"],
            icd=p["icd"],
            title=p["title"],
            direction=p["direction"],
            size=p["size"],
            doc=prose(p.get("doc")),
            fields=tuple(
                _field(f, ("payloads", i, "fields", j), units, date_bounds) for j, f in enumerate(p["fields"])
            ),
            path=("payloads", i),
            erratum=p.get("erratum"),
        )
        for i, p in enumerate(raw)
    )


def _frame(fr: dict[str, Any], units: dict[str, Unit]) -> Frame:
    checksum = _field(
        {"name": "checksum", "icd_name": fr["checksum"].get("icd_name", "checksum"), "type": fr["checksum"]["type"]},
        ("frame", "checksum"),
        units,
    )
    return Frame(
        icd=fr.get("icd", ""),
        header=tuple(fr["header"]),
        fields=tuple(_field(f, ("frame", "fields", i), units) for i, f in enumerate(fr["fields"])),
        checksum=checksum,
        checksum_doc=prose(fr["checksum"].get("doc")),
        checksum_algorithm=fr["checksum"]["algorithm"],
        message_types=tuple(MessageType(t["name"], t["value"], prose(t.get("doc"))) for t in fr["message_types"]),
        min_length=fr["message_length"]["min"],
        max_length=fr["message_length"]["max"],
        path=("frame",),
        strict=_strict(fr),
    )


def _strict(fr: dict[str, Any]) -> Strict | None:
    if "strict" not in fr:
        return None
    raw = fr["strict"]
    value = next(t["value"] for t in fr["message_types"] if t["name"] == raw["message_type"])
    return Strict(raw["message_type"], value, raw["reserved"], raw.get("erratum", ""))


def _command(c: dict[str, Any], index: int) -> Command:
    return Command(
        name=c["name"],
        id=c["id"],
        code=c["code"],
        icd=str(c["icd"]),
        group=c["group"],
        purpose=prose(c["purpose"]),
        valid_in=tuple(c["valid_in"]),
        response_kind=c["response"]["kind"],
        response_payloads=tuple(c["response"].get("payloads", ())),
        path=("commands", index),
        starts_mode=c["starts"]["mode"] if "starts" in c else None,
        starts_output=c["starts"]["output"] if "starts" in c else None,
        parameter_block=c.get("parameter_block"),
        shares_code_with=c.get("shares_code_with"),
        default_for_code=bool(c.get("default_for_code", False)),
        begins_calibration=c.get("begins_calibration"),
        former_names=tuple(
            FormerName(f["name"], f.get("until_firmware", ""), prose(f["doc"])) for f in c.get("former_names", ())
        ),
        erratum=c.get("erratum"),
    )


def _variant(v: dict[str, Any]) -> Variant:
    return Variant(
        name=v["name"],
        part_number=v["part_number"],
        icd=v.get("icd", ""),
        values=tuple(sorted(v["values"].items())),
        erratum=v.get("erratum"),
    )


def _serial_line(raw: dict[str, Any]) -> SerialLine:
    return SerialLine(raw["baud_rate"], raw["data_bits"], raw["parity"], raw["stop_bits"], raw.get("idle_byte_times"))


# Enums and encodings.


def _enum(name: str, raw: dict[str, Any]) -> Enum:
    return Enum(
        name=name,
        icd=raw.get("icd", ""),
        values=tuple(EnumValue(x["name"], x["value"], prose(x.get("doc"))) for x in raw["values"]),
        external_above=raw.get("external_above"),
    )


def _float32_toward(value: float, upward: bool) -> float:
    """The nearest float32 value at or beyond `value` in the given direction."""
    rounded: float = struct.unpack("<f", struct.pack("<f", value))[0]
    if (rounded < value and upward) or (rounded > value and not upward):
        bits = struct.unpack("<i", struct.pack("<f", rounded))[0]
        bits += 1 if (rounded >= 0) == upward else -1
        rounded = struct.unpack("<f", struct.pack("<i", bits))[0]
    return rounded


def _date_bounds(raw: dict[str, Any]) -> tuple[float, float]:
    """The floats a date field may hold: from the encoding of the first day of the first year to
    that of the last day of the last year (E15: Dec 31 encodes past the next year's start),
    widened to float32 values."""

    def encode(year: int, month: int, day: int) -> float:
        parts = {"year": year, "month": month, "day": day}
        return float(sum((parts[t["part"]] + t["offset"]) / t["divisor"] for t in raw["terms"]))

    low, high = raw["year_range"]
    return _float32_toward(encode(low, 1, 1), upward=False), _float32_toward(encode(high, 12, 31), upward=True)


def _date(e: dict[str, Any]) -> DateEncoding:
    return DateEncoding(
        doc=prose(e["doc"]),
        icd=e.get("icd", ""),
        terms=tuple(DateTerm(t["part"], t["offset"], t["divisor"]) for t in e["terms"]),
        year_min=e["year_range"][0],
        year_max=e["year_range"][1],
        decode=e["decode"],
        erratum=e.get("erratum"),
    )


def _declination(e: dict[str, Any]) -> DeclinationEncoding:
    return DeclinationEncoding(
        doc=prose(e["doc"]),
        icd=e.get("icd", ""),
        min=e["range"][0],
        max=e["range"][1],
        compute_above=e["compute_above"],
        compute_value=e["compute_value"],
    )


def _calibration_success(e: dict[str, Any]) -> CalibrationSuccessEncoding:
    return CalibrationSuccessEncoding(
        doc=prose(e["doc"]),
        icd=e.get("icd", ""),
        failed=e["failed"],
        no_estimate=e["no_estimate"],
        accuracy_divisor=e["accuracy_divisor"],
    )


def _status_word(sw: dict[str, Any]) -> StatusWord:
    flags = tuple(
        StatusFlag(f["bit"], f["name"], f.get("icd_name", f["name"]), f["byte"], prose(f.get("doc")))
        for f in sw["flags"]
    )
    byte_masks = {b["name"]: sum(1 << i for i in range(b["bits"][0], b["bits"][1] + 1)) for b in sw.get("bytes", [])}
    return StatusWord(
        icd=sw.get("icd", ""),
        flags=flags,
        mode_bits=tuple(sw["mode"]["bits"]),
        modes=tuple(StatusMode(m["name"], tuple(m["bits"]), prose(m.get("doc"))) for m in sw["mode"]["values"]),
        other_mode=sw["mode"]["other"],
        failure_mask=byte_masks.get("failure", 0),
        warning_mask=byte_masks.get("warning", 0),
    )


def _nmea(n: dict[str, Any]) -> Nmea:
    return Nmea(
        icd=n.get("icd", ""),
        identifier=n["identifier"],
        template=n.get("template", ""),
        max_rate_hz=n["max_rate_hz"],
        max_length=n["max_length"],
        fields=tuple(
            NmeaField(
                name=f["name"],
                icd_name=f.get("icd_name", f["name"]),
                format=f["format"],
                width=f["width"],
                decimals=f.get("decimals", 0),
                unit=f.get("unit", ""),
                min=int(f["range"][0]),
                max=int(f["range"][1]),
                doc=prose(f.get("doc")),
            )
            for f in n["fields"]
        ),
        checksum_doc=prose(n["checksum"].get("doc")),
    )
