"""Write the conformance suites, conformance/vectors/*.json, from the oracle in oracle.py.

    python3 conformance/tools/make_vectors.py            # rewrite conformance/vectors/
    python3 conformance/tools/make_vectors.py --check    # exit 1 if the committed files differ

Every vector is written here, with a note saying where its bytes come from: an ICD table, an
erratum of spec/ilahrs.yaml, a rule of spec/README.md, or how it was computed. Expected answers
are computed by the oracle, never by the generator or a binding. The output is deterministic
(fixed seeds, sorted nothing that depends on hashing), so the committed JSON is exactly what
this script writes: edit the script, never the JSON.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import struct

import device_oracle as d
import oracle as o

VECTORS_DIR = Path(__file__).resolve().parent.parent / "vectors"
ICD = "Inertial Labs AHRS ICD rev 1.7"

Vector = dict[str, Any]


def hx(data: bytes) -> str:
    """Bytes as the ICD prints them: upper-case hex, one space between bytes."""
    return " ".join(f"{b:02X}" for b in data)


def vec(id_: str, kind: str, input_: Any, expect: Any, note: str) -> Vector:
    return {"id": id_, "kind": kind, "input": input_, "expect": expect, "note": note}


def jsonable(value: object) -> object:
    """NaN and infinities are not JSON numbers: the suites write them as "nan", "inf", "-inf"."""
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    return value


def attempt(fn: Callable[[], Any]) -> Any:
    """The oracle's answer, or its refusal as an expected error."""
    try:
        return fn()
    except o.OracleError as err:
        return err.expect()


# --- appendix-c ----------------------------------------------------------------------------------


def suite_appendix_c() -> list[Vector]:
    out: list[Vector] = []
    for row in o.table_c1():
        note = f"{ICD}, Table C.1 row {row.name} (code 0x{row.code:02X}), exact structure as printed"
        out.append(vec(f"command_encode/{row.name}", "command_encode", {"command": row.name}, row.icd_hex, note))
    for row in o.table_c1():
        names = o.command_names(row.code)
        note = f"{ICD}, Table C.1 row {row.name}, exact structure as printed"
        if len(names) > 1:
            note += "; code 0x{:02X} is shared by {} (E14), names sorted".format(row.code, " and ".join(names))
        out.append(
            vec(f"command_decode/{row.name}", "command_decode", row.icd_hex, {"code": row.code, "names": names}, note)
        )
    cmd = "spec/README.md (Commands)"
    out += [
        vec(
            "command_encode/unknown-name",
            "command_encode",
            {"command": "GetVersion"},
            {"error": "unknown_command"},
            f"{cmd}: a name that is not in Table C.1",
        ),
        vec(
            "command_encode/former-name-StopClb",
            "command_encode",
            {"command": "StopClb"},
            {"error": "unknown_command"},
            f"E29: StopClb is the pre-4.9.9.0 name of 0x20 and not a row of Table C.1; {cmd}",
        ),
        vec(
            "command_decode/unknown-code-00",
            "command_decode",
            hx(o.frame(o.COMMAND, b"\x00")),
            {"error": "unknown_command", "offset": 6},
            f"{cmd}: code 0x00 is not in Table C.1; frame built by Table 6.2",
        ),
        vec(
            "command_decode/unknown-code-FF",
            "command_decode",
            hx(o.frame(o.COMMAND, b"\xff")),
            {"error": "unknown_command", "offset": 6},
            f"{cmd}: code 0xFF is not in Table C.1; frame built by Table 6.2",
        ),
        vec(
            "command_decode/former-code-StopClb",
            "command_decode",
            hx(o.frame(o.COMMAND, b"\x20")),
            {"code": 0x20, "names": ["StopClbRun"]},
            "E29: 0x20 decodes to the current name only",
        ),
        vec(
            "command_decode/data-frame",
            "command_decode",
            hx(o.frame(o.DATA, b"\x80")),
            {"error": "bad_message_type", "offset": 2},
            f"{cmd}: a command must be message type 0 (Table 6.2); AHRScont1's code sent as data",
        ),
        vec(
            "command_decode/two-byte-payload",
            "command_decode",
            hx(o.frame(o.COMMAND, b"\x80\x00")),
            {"error": "bad_length", "offset": 4},
            f"{cmd}: a command payload is one byte (6.3)",
        ),
        vec(
            "command_decode/reserved-nonzero",
            "command_decode",
            hx(o.frame(o.COMMAND, b"\x80", reserved=0x5A)),
            {"code": 0x80, "names": ["AHRScont1"]},
            "E6: any reserved byte is accepted; frame built by Table 6.2",
        ),
        vec(
            "command_decode/bad-checksum",
            "command_decode",
            "AA 55 00 00 07 00 80 88 00",
            {"error": "bad_checksum", "offset": 7, "field": "checksum"},
            "Table C.1 AHRScont1 with the checksum low byte off by one (87 -> 88)",
        ),
        vec(
            "command_decode/truncated",
            "command_decode",
            "AA 55 00 00 07 00 80 87",
            {"error": "truncated", "offset": 8},
            "Table C.1 AHRScont1 without its last byte",
        ),
    ]
    return out


# --- checksum ------------------------------------------------------------------------------------


def suite_checksum() -> list[Vector]:
    rule = "Table 6.2 / E28: the sum of the bytes modulo 2^16"
    longest = bytes([o.DATA, 0xFF]) + (o.MAX_LENGTH).to_bytes(2, "little") + b"\xff" * o.MAX_PAYLOAD
    cases: list[tuple[str, bytes, str]] = [
        ("empty", b"", f"{rule}; the sum of no bytes is 0"),
        ("AHRScont1", bytes.fromhex("0000070080"), "Table C.1 AHRScont1, bytes 2..6; the ICD's checksum is 87 00"),
        ("GetDataReq", bytes.fromhex("00000700CA"), "Table C.1 GetDataReq, bytes 2..6; the ICD's checksum is D1 00"),
        (
            "Stop-carries",
            bytes.fromhex("00000700FE"),
            "Table C.1 Stop, bytes 2..6; the sum 0x105 carries into the high byte (ICD: 05 01)",
        ),
        ("one-byte", b"\xff", rule),
        ("all-byte-values", bytes(range(256)), f"{rule}: 0 + 1 + ... + 255 = 32640"),
        (
            "longest-frame-max",
            longest,
            f"{rule}: type 1, reserved FF, length 58, 52 bytes FF, the largest sum of a legal frame (E28)",
        ),
        ("largest-before-wrap", b"\xff" * 257, f"{rule}: 257 x 0xFF = 0xFFFF"),
        ("wraps-to-zero", b"\xff" * 257 + b"\x01", f"{rule}: 257 x 0xFF + 1 = 0x10000 wraps to 0"),
        ("wraps-past", b"\xff" * 300, f"{rule}: 300 x 0xFF = 76500 wraps to 10964"),
    ]
    return [vec(f"checksum/{name}", "checksum", hx(data), o.checksum(data), note) for name, data, note in cases]


# --- payload tables ------------------------------------------------------------------------------

DATE_2014_03_11 = 2014 + (3 - 1) / 12 + 11 / 365  # the ICD's own date, E15 formula
DATE_2199_12_01 = 2199 + (12 - 1) / 12 + 1 / 365
DATE_2199_12_31 = 2199 + (12 - 1) / 12 + 31 / 365  # above 2200.0 (E15)
DEFAULTS = (
    "fields not given take the builders' default: the field's default, else 0 (zeros, empty text) "
    "when its range allows, else the lowest value of its range (a date: the float32 at or below 1900-01-01)"
)
HERNDON = (38.9586, -77.357)  # the ICD's address, Herndon VA


def _fill(table: str, **values: Any) -> dict[str, Any]:
    """Every field of the table, from `values`, the rest their defaults (the vectors name every field)."""
    out: dict[str, Any] = {}
    for f in o.TABLES[table][2]:
        out[f.name] = values.get(f.name, f.default_value)
    assert set(values) <= set(out), set(values) - set(out)
    return out


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


class PayloadCases:
    """Collects the vectors of one payload table."""

    def __init__(self, table: str) -> None:
        self.table = table
        self.icd, self.size, self.fields = o.TABLES[table]
        self.vectors: list[Vector] = []
        self.offsets = {}
        offset = 0
        for f in self.fields:
            self.offsets[f.name] = offset
            offset += f.size

    def ok(self, name: str, note: str, values: dict[str, Any], variants: Iterable[str | None] = (None,)) -> None:
        """A block builders accept: encode it, and decode the bytes back (per variant)."""
        full = _fill(self.table, **values)
        data = o.encode_payload(self.table, full)
        where = f"{self.icd} ({self.table}); {note}; bytes packed little-endian by the oracle"
        for variant in variants:
            suffix = f"-{variant}" if variant else ""
            self.vectors.append(
                vec(
                    f"payload_decode/{self.table}/{name}{suffix}",
                    "payload_decode",
                    _decode_input(self.table, data, variant),
                    _decode_expect(self.table, data, variant),
                    where,
                )
            )
        self.vectors.append(
            vec(
                f"payload_encode/{self.table}/{name}",
                "payload_encode",
                {"type": self.table, "fields": {k: jsonable(v) for k, v in full.items()}},
                hx(data),
                where,
            )
        )

    def encode(self, name: str, note: str, fields: dict[str, Any]) -> None:
        """An encode vector with exactly these fields given (defaults or refusals)."""
        expect = attempt(lambda: hx(o.encode_payload(self.table, fields)))
        self.vectors.append(
            vec(
                f"payload_encode/{self.table}/{name}",
                "payload_encode",
                {"type": self.table, "fields": {k: jsonable(v) for k, v in fields.items()}},
                expect,
                f"{self.icd} ({self.table}); {note}",
            )
        )

    def refuse(self, name: str, note: str, base: dict[str, Any], **change: Any) -> None:
        """`base` with one field changed to a value builders refuse (spec/README.md, payload encode)."""
        fields = _fill(self.table, **{**base, **change})
        expect = attempt(lambda: hx(o.encode_payload(self.table, fields)))
        assert isinstance(expect, dict) and expect["error"] == "out_of_range", (name, expect)
        (field,) = change
        assert expect["field"] == field and expect["offset"] == self.offsets[field]
        self.vectors.append(
            vec(
                f"payload_encode/{self.table}/{name}",
                "payload_encode",
                {"type": self.table, "fields": {k: jsonable(v) for k, v in fields.items()}},
                expect,
                f"{self.icd} ({self.table}); {note}; refused at the field's offset",
            )
        )

    def decode_raw(self, name: str, note: str, values: dict[str, Any], variant: str | None = None) -> None:
        """Decode a block packed without range checks: decoders never range-check."""
        data = _raw_pack(self.table, _fill(self.table, **values))
        self.vectors.append(
            vec(
                f"payload_decode/{self.table}/{name}",
                "payload_decode",
                _decode_input(self.table, data, variant),
                _decode_expect(self.table, data, variant),
                f"{self.icd} ({self.table}); {note}; spec/README.md: decoders do not range-check",
            )
        )

    def sizes(self, typical: dict[str, Any], empty: bool = False) -> None:
        data = o.encode_payload(self.table, _fill(self.table, **typical))
        cases = [
            ("truncated", data[:-1], f"the typical block without its last byte: truncated at {self.size - 1}"),
            ("trailing-data", data + b"\x00", f"the typical block and one more byte: trailing_data at {self.size}"),
        ]
        if empty:
            cases.append(("empty", b"", "no bytes at all: truncated at 0"))
        for name, chunk, note in cases:
            self.vectors.append(
                vec(
                    f"payload_decode/{self.table}/{name}",
                    "payload_decode",
                    _decode_input(self.table, chunk, None),
                    _decode_expect(self.table, chunk, None),
                    f"{self.icd} ({self.table}) is {self.size} bytes; {note} (spec/README.md)",
                )
            )


def suite_payloads() -> list[Vector]:
    out: list[Vector] = []
    all_variants = list(o.VARIANTS)

    # Table 6.4
    p = PayloadCases("full_output")
    typical: dict[str, Any] = {
        "heading": 12345,
        "pitch": -1234,
        "roll": 4567,
        "ugyro_x": 100,
        "ugyro_y": -200,
        "ugyro_z": 300,
        "uacc_x": -16384,
        "uacc_y": 50,
        "uacc_z": 16000,
        "umag_x": 1234,
        "umag_y": -2345,
        "umag_z": 3456,
        "usw": 0,
        "vdd": 5012,
        "utermo": 2048,
    }
    p.ok("typical", "heading 123.45, pitch -12.34, roll 45.67 deg, raw sensors, Vdd 5.012 V", typical)
    p.ok(
        "maximum",
        "upper bounds: heading 359.99 (E23), pitch 90.00, roll 180.00, every word at its maximum, reserved FF FF FF FF",
        {
            "heading": 35999,
            "pitch": 9000,
            "roll": 18000,
            "ugyro_x": 32767,
            "ugyro_y": 32767,
            "ugyro_z": 32767,
            "uacc_x": 32767,
            "uacc_y": 32767,
            "uacc_z": 32767,
            "umag_x": 32767,
            "umag_y": 32767,
            "umag_z": 32767,
            "reserved": "ffffffff",
            "usw": 0xFFFF,
            "vdd": 65535,
            "utermo": 32767,
        },
    )
    p.ok(
        "minimum",
        "lower bounds: heading 0, pitch -90.00, roll -180.00, every sword at -32768, reserved "
        "DE AD BE EF kept verbatim, USW 0x8080 (sleep, Table 6.19)",
        {
            "heading": 0,
            "pitch": -9000,
            "roll": -18000,
            "ugyro_x": -32768,
            "ugyro_y": -32768,
            "ugyro_z": -32768,
            "uacc_x": -32768,
            "uacc_y": -32768,
            "uacc_z": -32768,
            "umag_x": -32768,
            "umag_y": -32768,
            "umag_z": -32768,
            "reserved": "deadbeef",
            "usw": 0x8080,
            "vdd": 0,
            "utermo": -32768,
        },
    )
    p.decode_raw(
        "heading-36000",
        "raw heading 36000 (360.00 deg) is outside the builder range (E23)",
        {**typical, "heading": 36000},
    )
    p.decode_raw(
        "heading-65535-pitch-32767",
        "raw heading 65535 and pitch 32767 (327.67 deg)",
        {**typical, "heading": 65535, "pitch": 32767},
    )
    p.refuse("refuse-heading-36000", "heading 36000 is 360.00 deg (E23: 0..35999)", typical, heading=36000)
    p.refuse("refuse-pitch-9001", "pitch range -9000..9000", typical, pitch=9001)
    p.refuse("refuse-pitch-minus-9001", "pitch range -9000..9000", typical, pitch=-9001)
    p.refuse("refuse-roll-18001", "roll range -18000..18000", typical, roll=18001)
    p.refuse("refuse-roll-minus-18001", "roll range -18000..18000", typical, roll=-18001)
    p.refuse("refuse-ugyro-y-32768", "a sword holds -32768..32767", typical, ugyro_y=32768)
    p.refuse("refuse-umag-z-minus-32769", "a sword holds -32768..32767", typical, umag_z=-32769)
    p.refuse("refuse-reserved-3-bytes", "the reserved field is 4 bytes", typical, reserved="000000")
    p.refuse("refuse-reserved-5-bytes", "the reserved field is 4 bytes", typical, reserved="0000000000")
    p.refuse("refuse-usw-65536", "a word holds 0..65535", typical, usw=65536)
    p.refuse("refuse-usw-minus-1", "a word holds 0..65535 (never wrapped to 65535)", typical, usw=-1)
    p.refuse("refuse-vdd-65536", "a word holds 0..65535", typical, vdd=65536)
    p.refuse("refuse-utermo-32768", "a sword holds -32768..32767", typical, utermo=32768)
    p.sizes(typical)
    out += p.vectors

    # Table 6.5
    p = PayloadCases("quaternion")
    typical = {
        "heading": 9000,
        "pitch": 1000,
        "roll": -500,
        "lk0": 7071,
        "lk1": 0,
        "lk2": 0,
        "lk3": 7071,
        "usw": 0,
        "vdd": 12000,
        "utermo": 253,
    }
    p.ok("typical", "heading 90, pitch 10, roll -5 deg, quaternion (0.7071, 0, 0, 0.7071), 12 V, 25.3 degC", typical)
    p.ok(
        "bounds",
        "quaternion components at +-1.0000 (-10000..10000), heading 359.99, reserved 01..0E, -40.0 degC",
        {
            "heading": 35999,
            "pitch": -9000,
            "roll": 18000,
            "lk0": 10000,
            "lk1": -10000,
            "lk2": 10000,
            "lk3": -10000,
            "reserved": "0102030405060708090a0b0c0d0e",
            "usw": 0x0101,
            "vdd": 65535,
            "utermo": -400,
        },
    )
    p.ok(
        "negative",
        "negative components and temperature",
        {
            "heading": 1,
            "pitch": 9000,
            "roll": -18000,
            "lk0": -1,
            "lk1": -9999,
            "lk2": -5000,
            "lk3": -1234,
            "usw": 0x0080,
            "vdd": 1,
            "utermo": -32768,
        },
    )
    p.decode_raw("lk0-32767", "raw lk0 32767 (3.2767) is outside the builder range", {**typical, "lk0": 32767})
    p.refuse("refuse-lk0-10001", "quaternion components -10000..10000", typical, lk0=10001)
    p.refuse("refuse-lk3-minus-10001", "quaternion components -10000..10000", typical, lk3=-10001)
    p.refuse("refuse-heading-36000", "heading 0..35999 (E23)", typical, heading=36000)
    p.refuse("refuse-reserved-13-bytes", "the reserved field is 14 bytes", typical, reserved="00" * 13)
    p.refuse("refuse-utermo-32768", "a sword holds -32768..32767", typical, utermo=32768)
    p.sizes(typical, empty=True)
    out += p.vectors

    # Table 6.6
    p = PayloadCases("orientation_sensors")
    typical = {
        "heading": 27000,
        "pitch": -250,
        "roll": 125,
        "gyro_x": 1500,
        "gyro_y": -1500,
        "gyro_z": 50,
        "acc_x": 0,
        "acc_y": 0,
        "acc_z": 10000,
        "mag_x": 2000,
        "mag_y": -1500,
        "mag_z": 4500,
        "usw": 0,
        "vdd": 12000,
        "utermo": 251,
    }
    p.ok(
        "typical",
        "heading 270, pitch -2.5, roll 1.25 deg; gyro deg/s*KG, acc g*KA (variant scales of note 1), mag nT/10",
        typical,
        variants=[None, *all_variants],
    )
    p.ok(
        "extremes",
        "every sword at its extreme; gyro 32767/KG, acc -32768/KA, mag 327670 nT",
        {
            "heading": 35999,
            "pitch": 9000,
            "roll": -18000,
            "gyro_x": 32767,
            "gyro_y": -32768,
            "gyro_z": -1,
            "acc_x": -32768,
            "acc_y": 32767,
            "acc_z": -10000,
            "mag_x": 32767,
            "mag_y": -32768,
            "mag_z": 0,
            "reserved": "a5a5a5a5",
            "usw": 0xFFFF,
            "vdd": 65535,
            "utermo": -32768,
        },
        variants=[None, *all_variants],
    )
    p.ok(
        "level",
        "level and still: acc_z = 1 g is KA counts (5000 for A6)",
        {"heading": 0, "pitch": 0, "roll": 0, "acc_z": 5000, "usw": 0x8080, "vdd": 4990, "utermo": -405},
        variants=["g300_a6_tmga"],
    )
    p.refuse("refuse-heading-36000", "heading 0..35999 (E23)", typical, heading=36000)
    p.refuse("refuse-gyro-x-32768", "a sword holds -32768..32767", typical, gyro_x=32768)
    p.refuse("refuse-acc-z-minus-32769", "a sword holds -32768..32767", typical, acc_z=-32769)
    p.refuse("refuse-mag-y-40000", "a sword holds -32768..32767", typical, mag_y=40000)
    p.refuse("refuse-reserved-empty", "the reserved field is 4 bytes", typical, reserved="")
    p.sizes(typical)
    out += p.vectors

    # Table 6.8
    p = PayloadCases("initial_alignment")
    typical = {
        "gyro_bias_x": 12.5,
        "gyro_bias_y": -3.25,
        "gyro_bias_z": 0.0625,
        "average_acc_x": 1.5,
        "average_acc_y": -2.0,
        "average_acc_z": 16384.0,
        "average_mag_x": 1000.25,
        "average_mag_y": -2000.5,
        "average_mag_z": 3000.75,
        "initial_heading": 123.45,
        "initial_roll": -1.5,
        "initial_pitch": 2.25,
        "usw": 0,
    }
    p.ok(
        "typical",
        "floats in ADC codes and degrees (E21: heading, roll, pitch); 123.45 is stored as the nearest float32",
        typical,
    )
    p.ok(
        "bounds",
        "initial heading 360.0, roll -180.0, pitch 90.0 (inclusive ranges), +-FLT_MAX, the smallest "
        "subnormal float32, USW 1: alignment failed (E27)",
        {
            "gyro_bias_x": o.F32_MAX,
            "gyro_bias_y": -o.F32_MAX,
            "gyro_bias_z": o.f32(1e-45),
            "initial_heading": 360.0,
            "initial_roll": -180.0,
            "initial_pitch": 90.0,
            "usw": 1,
        },
    )
    p.ok(
        "negative-zero",
        "initial heading 0.0, roll 180.0, pitch -90.0, -0.0 kept as 00 00 00 80",
        {"average_acc_x": -0.0, "initial_heading": 0.0, "initial_roll": 180.0, "initial_pitch": -90.0, "usw": 0xFFFF},
    )
    p.decode_raw(
        "nan-and-infinity",
        "NaN (00 00 C0 7F) in gyro_bias_x, +inf in average_mag_z, heading 400.0",
        {**typical, "gyro_bias_x": math.nan, "average_mag_z": math.inf, "initial_heading": 400.0},
    )
    p.refuse("refuse-nan", "a float must be finite (E31)", typical, gyro_bias_x=math.nan)
    p.refuse("refuse-infinity", "a float must be finite (E31)", typical, average_mag_z=math.inf)
    p.refuse("refuse-minus-infinity", "a float must be finite (E31)", typical, average_acc_y=-math.inf)
    p.refuse("refuse-beyond-float32", "1e39 does not fit a float32", typical, gyro_bias_y=1e39)
    p.refuse("refuse-heading-360.5", "initial heading 0..360", typical, initial_heading=360.5)
    p.refuse("refuse-heading-minus-0.5", "initial heading 0..360", typical, initial_heading=-0.5)
    p.refuse("refuse-roll-180.5", "initial roll -180..180", typical, initial_roll=180.5)
    p.refuse("refuse-pitch-minus-90.5", "initial pitch -90..90", typical, initial_pitch=-90.5)
    p.refuse("refuse-usw-65536", "a word holds 0..65535", typical, usw=65536)
    p.sizes(typical)
    out += p.vectors

    # Table 6.9
    p = PayloadCases("ahrs_parameters_load")
    typical = {
        "update_rate": 50,
        "alignment_time": 30,
        "declination": -10.5,
        "latitude": HERNDON[0],
        "longitude": HERNDON[1],
        "altitude": 120.0,
        "date": DATE_2014_03_11,
        "alignment_angle_a1": 0.0,
        "alignment_angle_a2": 0.0,
        "alignment_angle_a3": 180.0,
    }
    p.ok(
        "typical",
        "50 Hz, 30 s, declination -10.5, Herndon VA (the ICD's address), date 2014-03-11 as "
        "2014 + 2/12 + 11/365 (E15), alignment angles 0, 0, 180 (Fig. B.1 b)",
        typical,
    )
    p.ok(
        "compute-declination",
        "declination 999 (> 360: the AHRS computes it, encodings.declination), update "
        "100 Hz, alignment 65535 s (E30), bounds of every range, reserved bytes FF kept verbatim",
        {
            "update_rate": 100,
            "alignment_time": 65535,
            "declination": 999.0,
            "latitude": 90.0,
            "longitude": -180.0,
            "altitude": -20000.0,
            "date": DATE_2199_12_01,
            "alignment_angle_a1": -360.0,
            "alignment_angle_a2": 360.0,
            "alignment_angle_a3": 90.0,
            "reserved": "ff" * 14,
        },
    )
    p.ok(
        "lower-bounds",
        "1 Hz, 1 s (E30), declination 180 and -180 bounds, altitude 100000 m (E31), "
        "alignment angles 180, -90, 0 (Fig. B.1 d)",
        {
            "update_rate": 1,
            "alignment_time": 1,
            "declination": 180.0,
            "latitude": -90.0,
            "longitude": 180.0,
            "altitude": 100000.0,
            "date": 1900 + 0 / 12 + 1 / 365,
            "alignment_angle_a1": 180.0,
            "alignment_angle_a2": -90.0,
        },
    )
    p.ok(
        "declination-just-above-360",
        "declination 360.5 is above compute_above (360)",
        {**typical, "declination": 360.5},
    )
    p.encode(
        "defaults", f"no field given: update rate 100 Hz and alignment 30 s (the Table 6.9 defaults), {DEFAULTS}", {}
    )
    p.ok(
        "date-2199-12-31",
        "date 2199-12-31, the last real date of year_range [1900, 2199], is "
        "2199 + 11/12 + 31/365 = 2200.0016 (E15: Day/365 overlaps the next year); spec/README.md: a real calendar "
        "date inside year_range",
        {**typical, "date": DATE_2199_12_31},
    )
    p.ok(
        "date-1900-01-01",
        "date 1900-01-01 = 1900 + 0/12 + 1/365, the first real date of year_range (encodings.date)",
        {**typical, "date": 1900 + 0 / 12 + 1 / 365},
    )
    p.refuse(
        "refuse-date-1900.0",
        "raw date 1900.0 is day 0 of 1900, below the encoding of 1900-01-01 (spec/README.md)",
        typical,
        date=1900.0,
    )
    p.refuse("refuse-date-1899.5", "a date float below year_range [1900, 2199] (encodings.date)", typical, date=1899.5)
    p.refuse("refuse-date-2201", "a date float above year_range [1900, 2199] (encodings.date)", typical, date=2201.0)
    p.refuse("refuse-date-0", "0.0 is no date inside year_range [1900, 2199] (encodings.date)", typical, date=0.0)
    p.decode_raw(
        "out-of-range",
        "update rate 0, declination NaN, latitude 91: a device's block decodes as is",
        {**typical, "update_rate": 0, "declination": math.nan, "latitude": 91.0},
    )
    p.refuse("refuse-update-rate-0", "update rate 1..100 Hz (Table 6.9)", typical, update_rate=0)
    p.refuse("refuse-update-rate-101", "update rate 1..100 Hz (Table 6.9)", typical, update_rate=101)
    p.refuse("refuse-alignment-time-0", "alignment time 1..65535 s (E30)", typical, alignment_time=0)
    p.refuse(
        "refuse-declination-360",
        "declination -180..180 or above 360 (encodings.declination)",
        typical,
        declination=360.0,
    )
    p.refuse("refuse-declination-200", "declination -180..180 or above 360", typical, declination=200.0)
    p.refuse("refuse-declination-minus-180.5", "declination -180..180 or above 360", typical, declination=-180.5)
    p.refuse("refuse-declination-nan", "a float must be finite (E31)", typical, declination=math.nan)
    p.refuse(
        "refuse-declination-infinity", "a float must be finite (E31), even above 360", typical, declination=math.inf
    )
    p.refuse("refuse-latitude-90.5", "latitude -90..90", typical, latitude=90.5)
    p.refuse("refuse-longitude-minus-180.5", "longitude -180..180", typical, longitude=-180.5)
    p.refuse("refuse-altitude-100000.5", "altitude -20000..100000 m (E31)", typical, altitude=100000.5)
    p.refuse("refuse-altitude-minus-20000.5", "altitude -20000..100000 m (E31)", typical, altitude=-20000.5)
    p.refuse("refuse-date-nan", "a float must be finite (E31)", typical, date=math.nan)
    p.refuse("refuse-date-infinity", "a float must be finite (E31)", typical, date=-math.inf)
    p.refuse("refuse-angle-a1-minus-360.5", "alignment angles -360..360 (E31)", typical, alignment_angle_a1=-360.5)
    p.refuse("refuse-angle-a3-360.5", "alignment angles -360..360 (E31)", typical, alignment_angle_a3=360.5)
    p.refuse("refuse-reserved-13-bytes", "the reserved field is 14 bytes", typical, reserved="00" * 13)
    p.refuse("refuse-reserved-15-bytes", "the reserved field is 14 bytes", typical, reserved="00" * 15)
    p.sizes(typical)
    out += p.vectors

    # Table 6.10
    p = PayloadCases("ahrs_parameters_read")
    typical_read = {**typical, "device_id": "11AC0001"}
    p.ok(
        "typical",
        "as the Table 6.9 typical block, device ID 11AC0001 (a serial number of Table 6.6 note 1) filling all 8 bytes",
        typical_read,
    )
    p.ok(
        "short-id",
        "device ID 'AHRS1' NUL-padded, reserved bytes non-zero and kept",
        {**typical, "update_rate": 100, "device_id": "AHRS1", "reserved": "010203040506"},
    )
    p.ok("latin-1-id", "device ID 'ID' and the Latin-1 byte E9", {**typical, "device_id": "ID\xe9"})
    p.decode_raw(
        "embedded-nul",
        "device ID bytes 41 42 00 43 44 00 00 00: only trailing NULs are removed",
        {**typical, "device_id": "AB\x00CD"},
    )
    p.decode_raw("empty-id", "device ID of eight NULs reads as the empty string", {**typical, "device_id": ""})
    p.refuse("refuse-device-id-9", "device ID is 8 chars", typical_read, device_id="11AC00019")
    p.refuse("refuse-update-rate-101", "update rate 1..100 Hz", typical_read, update_rate=101)
    p.refuse("refuse-reserved-5-bytes", "the reserved field is 6 bytes", typical_read, reserved="00" * 5)
    p.encode(
        "defaults",
        f"only the alignment time and device ID given; Table 6.10 has no default update rate, so it is 1; {DEFAULTS}",
        {"alignment_time": 30, "device_id": "X"},
    )
    p.sizes(typical_read)
    out += p.vectors

    # Table 6.11
    p = PayloadCases("firmware_version")
    fifty = "AHRS-G300-A2-TMGA-C1-V1.1 firmware 4.9.9.0 build 17"[:50]
    assert len(fifty) == 50
    p.ok("typical", "version 4.9.9.0 (6.4.7), NUL-padded to 50 bytes", {"version": "4.9.9.0"})
    p.ok("fifty-chars", "a version filling all 50 bytes, no NUL", {"version": fifty})
    p.ok("empty", "50 NUL bytes read as the empty string", {"version": ""})
    p.ok("latin-1", "a version with the Latin-1 bytes B0 and FF and a space", {"version": "v4.9 \xb0C \xff"})
    p.decode_raw(
        "embedded-nul", "4.9.9.0 NUL build NUL...: only trailing NULs are removed", {"version": "4.9.9.0\x00build"}
    )
    p.decode_raw("trailing-spaces", "trailing spaces are not NULs and are kept", {"version": "4.9.9.0   "})
    p.refuse(
        "refuse-51-chars", "the version is at most 50 bytes; never truncated", {"version": ""}, version=fifty + "x"
    )
    p.refuse("refuse-60-chars", "the version is at most 50 bytes; never truncated", {"version": ""}, version="9" * 60)
    p.sizes({"version": "4.9.9.0"})
    out += p.vectors

    # Table 6.12
    p = PayloadCases("bit_result")
    typical = {"utermo100": 2512, "usw": 0}
    p.ok("typical", "Utermo100 2512 is 25.12 degC", typical)
    p.ok(
        "minus-40",
        "Utermo100 -4000 is -40.00 degC, sent as 60 F0 (E4: signed); USW bit 2 gyro failure",
        {"utermo100": -4000, "usw": 0x0004},
    )
    p.ok("maximum", "327.67 degC, USW FFFF", {"utermo100": 32767, "usw": 0xFFFF})
    p.ok("minimum", "-327.68 degC, USW 0x8080 (sleep, Table 6.19)", {"utermo100": -32768, "usw": 0x8080})
    p.refuse("refuse-utermo100-32768", "a sword holds -32768..32767 (E4)", typical, utermo100=32768)
    p.refuse("refuse-utermo100-minus-32769", "a sword holds -32768..32767 (E4)", typical, utermo100=-32769)
    p.refuse("refuse-usw-65536", "a word holds 0..65535", typical, usw=65536)
    p.refuse("refuse-usw-minus-1", "a word holds 0..65535", typical, usw=-1)
    p.sizes(typical, empty=True)
    out += p.vectors

    # Table 6.13
    p = PayloadCases("calibration_parameters")
    typical = {
        "reference_azimuth": 0.0,
        "accumulation_time": 120,
        "latitude": HERNDON[0],
        "longitude": HERNDON[1],
        "altitude": 120.0,
        "date": DATE_2014_03_11,
    }
    p.ok("typical", "reference azimuth 0 (E8), 120 s accumulation, Herndon VA, 2014-03-11 (E15)", typical)
    p.ok(
        "bounds-low",
        "reference azimuth -360 (E8), 1 s (E30), latitude -90, longitude -180, altitude -20000 m, 1900-01-01",
        {
            "reference_azimuth": -360.0,
            "accumulation_time": 1,
            "latitude": -90.0,
            "longitude": -180.0,
            "altitude": -20000.0,
            "date": 1900 + 1 / 365,
        },
    )
    p.ok(
        "bounds-high",
        "reference azimuth 360, 65535 s, latitude 90, longitude 180, altitude 100000 m",
        {
            "reference_azimuth": 360.0,
            "accumulation_time": 65535,
            "latitude": 90.0,
            "longitude": 180.0,
            "altitude": 100000.0,
            "date": DATE_2199_12_01,
        },
    )
    p.ok(
        "date-2199-12-31",
        "date 2199-12-31 = 2200.0016, the last real date of year_range (E15, encodings.date)",
        {**typical, "date": DATE_2199_12_31},
    )
    p.encode(
        "defaults",
        f"only the accumulation time given: reference azimuth defaults to 0 (E8); {DEFAULTS}",
        {"accumulation_time": 60},
    )
    p.encode(
        "defaults-accumulation-time",
        f"no accumulation time given: it is 1 (0 is outside 1..65535, E30); {DEFAULTS}",
        {"latitude": 10.0},
    )
    p.refuse("refuse-date-2201", "a date float above year_range [1900, 2199] (encodings.date)", typical, date=2201.0)
    p.refuse("refuse-reference-azimuth-360.5", "reference azimuth -360..360 (E8)", typical, reference_azimuth=360.5)
    p.refuse("refuse-accumulation-0", "accumulation time 1..65535 s (E30)", typical, accumulation_time=0)
    p.refuse("refuse-accumulation-65536", "a word holds 0..65535", typical, accumulation_time=65536)
    p.refuse("refuse-latitude-minus-90.5", "latitude -90..90", typical, latitude=-90.5)
    p.refuse("refuse-longitude-180.5", "longitude -180..180", typical, longitude=180.5)
    p.refuse("refuse-altitude-infinity", "a float must be finite (E31)", typical, altitude=math.inf)
    p.refuse("refuse-date-nan", "a float must be finite (E31)", typical, date=math.nan)
    p.sizes(typical)
    out += p.vectors

    # Table 6.14 (E1: Hm_0 at bytes 40-51)
    p = PayloadCases("calibration_result")
    typical = {
        "calibration_type": 3,
        "runs_used": 1,
        "data_used": 95,
        "success": 5,
        "tm_c_11": 1.0,
        "tm_c_12": 0.0125,
        "tm_c_13": -0.0025,
        "tm_c_21": 0.0125,
        "tm_c_22": 0.98,
        "tm_c_23": 0.001,
        "tm_c_31": -0.0025,
        "tm_c_32": 0.001,
        "tm_c_33": 1.02,
        "hm_0_x": 12.5,
        "hm_0_y": -7.25,
        "hm_0_z": 3.0,
    }
    p.ok(
        "typical-3d",
        "3D calibration, 95 % of points, success 5 = +-0.5 deg (the note's example, E26), Hm_0 at bytes 40-51 (E1)",
        typical,
    )
    p.ok(
        "2d-no-estimate",
        "2D, 100 %, success 255: successful without an estimate (E26)",
        {**typical, "calibration_type": 1, "data_used": 100, "success": 255, "hm_0_z": -1e-3},
    )
    p.ok(
        "2d2t-failed",
        "2D-2T, 255 runs, 0 %, success 0: not successful; negative matrix",
        {
            **typical,
            "calibration_type": 2,
            "runs_used": 255,
            "data_used": 0,
            "success": 0,
            "tm_c_11": -1.0,
            "tm_c_22": -1.0,
            "tm_c_33": -1.0,
        },
    )
    p.decode_raw(
        "type-0",
        "calibration type 0 and 200 % used: a device's block decodes as is",
        {**typical, "calibration_type": 0, "data_used": 200},
    )
    p.refuse("refuse-type-0", "calibration type 1..3 (Table 6.14)", typical, calibration_type=0)
    p.refuse("refuse-type-4", "calibration type 1..3 (Table 6.14)", typical, calibration_type=4)
    p.refuse("refuse-runs-256", "a byte holds 0..255", typical, runs_used=256)
    p.refuse("refuse-data-used-101", "percent 0..100", typical, data_used=101)
    p.refuse("refuse-success-256", "a byte holds 0..255 (E26)", typical, success=256)
    p.refuse("refuse-tm-c-22-nan", "a float must be finite (E31)", typical, tm_c_22=math.nan)
    p.refuse("refuse-hm-0-x-beyond-float32", "-1e39 does not fit a float32", typical, hm_0_x=-1e39)
    p.refuse("refuse-hm-0-z-infinity", "a float must be finite (E31)", typical, hm_0_z=math.inf)
    p.sizes(typical)
    out += p.vectors

    # Table 6.15
    p = PayloadCases("calibration_run_result")
    typical = {
        "calibration_type": 2,
        "run": 1,
        "data_used": 80,
        "success": 12,
        "average_pitch": -10.5,
        "average_roll": 2.25,
        "usw": 0,
    }
    p.ok("typical", "2D-2T run 1, 80 %, success 12 = +-1.2 deg (E26), pitch -10.5, roll 2.25 deg", typical)
    p.ok(
        "bounds",
        "run 255, 100 %, success 255, pitch 90, roll -180; reserved bytes 00 00 80 3F (a float 1.0, "
        "E32: kept verbatim) and 0x11..0x1C",
        {
            "calibration_type": 2,
            "run": 255,
            "data_used": 100,
            "success": 255,
            "reserved_1": "0000803f",
            "average_pitch": 90.0,
            "average_roll": -180.0,
            "reserved_2": "3c3b3a393837363534333231",
            "usw": 0xFFFF,
        },
    )
    p.ok(
        "failed-run",
        "run 2 not successful (success 0), pitch -90, roll 180",
        {
            "calibration_type": 2,
            "run": 2,
            "data_used": 0,
            "success": 0,
            "average_pitch": -90.0,
            "average_roll": 180.0,
            "usw": 1,
        },
    )
    p.refuse("refuse-type-1", "calibration type is 2 for 2D-2T (Table 6.15)", typical, calibration_type=1)
    p.refuse("refuse-type-3", "calibration type is 2 for 2D-2T (Table 6.15)", typical, calibration_type=3)
    p.refuse("refuse-run-0", "run 1..255", typical, run=0)
    p.refuse("refuse-data-used-101", "percent 0..100", typical, data_used=101)
    p.refuse("refuse-reserved-1-3-bytes", "reserved_1 is 4 bytes (E32)", typical, reserved_1="000000")
    p.refuse("refuse-pitch-90.5", "average pitch -90..90", typical, average_pitch=90.5)
    p.refuse("refuse-roll-nan", "a float must be finite (E31)", typical, average_roll=math.nan)
    p.refuse("refuse-reserved-2-13-bytes", "reserved_2 is 12 bytes (E32)", typical, reserved_2="00" * 13)
    p.refuse("refuse-usw-65536", "a word holds 0..65535", typical, usw=65536)
    p.sizes(typical)
    out += p.vectors

    # Table 6.16
    p = PayloadCases("calibration_run_parameters")
    p.ok("zeros", "6.4.6: the 6 bytes may be any, for example zeros", {})
    p.ok("any-bytes", "6.4.6: any 6 bytes, kept verbatim (E32)", {"reserved": "010203040506"})
    p.ok(
        "nan-float-bytes",
        "a NaN float pattern 00 00 C0 7F in bytes 0-3 stays verbatim (E32)",
        {"reserved": "0000c07fffff"},
    )
    p.refuse("refuse-5-bytes", "the block is 6 bytes", {}, reserved="0000000000")
    p.refuse("refuse-7-bytes", "the block is 6 bytes", {}, reserved="00000000000000")
    p.sizes({}, empty=True)
    out += p.vectors

    # Table 6.17 (E2, E3)
    p = PayloadCases("calibration_status")
    typical = {
        "calibration_type": 3,
        "runs_used": 1,
        "success": 5,
        "tm_c_11": 1.0,
        "tm_c_22": 1.0,
        "tm_c_33": 1.0,
        "hm_0_x": -3.5,
        "hm_0_y": 0.25,
        "hm_0_z": 100.0,
    }
    p.ok("not-calibrated", "type 0: the AHRS is not calibrated; all zeros", {})
    p.ok("typical-3d", "3D calibration, success 5, Hm_0 at bytes 40-51 (E2)", typical)
    p.ok(
        "external",
        "type 0x81 (> 0x80: loaded by other software), reserved byte 5F kept and not a percentage (E3), success 255",
        {**typical, "calibration_type": 0x81, "runs_used": 0, "reserved": "5f", "success": 255},
    )
    p.refuse("refuse-type-256", "a byte holds 0..255", typical, calibration_type=256)
    p.refuse("refuse-reserved-2-bytes", "the reserved field is 1 byte (E3)", typical, reserved="0000")
    p.refuse("refuse-reserved-empty", "the reserved field is 1 byte (E3)", typical, reserved="")
    p.refuse("refuse-success-minus-1", "a byte holds 0..255", typical, success=-1)
    p.refuse("refuse-tm-c-11-infinity", "a float must be finite (E31)", typical, tm_c_11=-math.inf)
    p.sizes(typical)
    out += p.vectors

    # The acknowledgement (6.3.1, E12)
    p = PayloadCases("acknowledgement")
    p.ok("AHRScont1", "the checksum of Table C.1 AHRScont1 (87 00)", {"checksum": 0x87})
    p.ok("Stop", "the checksum of Table C.1 Stop (05 01)", {"checksum": 0x105})
    p.ok("maximum", "checksum FFFF", {"checksum": 0xFFFF})
    p.refuse("refuse-65536", "a word holds 0..65535", {}, checksum=65536)
    p.refuse("refuse-minus-1", "a word holds 0..65535", {}, checksum=-1)
    p.sizes({"checksum": 0x87}, empty=True)
    out += p.vectors

    return out


# --- acks ----------------------------------------------------------------------------------------


def suite_acks() -> list[Vector]:
    out: list[Vector] = []
    rule = "E12: a data frame (type 1) whose payload is the received message's checksum, low byte first"
    for row in o.table_c1():
        msg = bytes.fromhex(row.icd_hex)
        out.append(
            vec(
                f"ack/{row.name}",
                "ack",
                row.icd_hex,
                hx(o.ack(msg)),
                f"{ICD}, Table C.1 row {row.name} as printed; {rule} (6.3.1)",
            )
        )
    blocks: list[tuple[str, str, bytes, int, int]] = [
        (
            "LoadAHRSPar-block",
            "Table 6.9 block (50 Hz, 30 s, Herndon VA, 2014-03-11) sent as data, type 1 (E5)",
            o.encode_payload(
                "ahrs_parameters_load",
                _fill(
                    "ahrs_parameters_load",
                    update_rate=50,
                    alignment_time=30,
                    declination=999.0,
                    latitude=HERNDON[0],
                    longitude=HERNDON[1],
                    altitude=120.0,
                    date=DATE_2014_03_11,
                ),
            ),
            o.DATA,
            0,
        ),
        (
            "LoadAHRSPar-defaults",
            "Table 6.9 defaults block (100 Hz, 30 s) sent as data, type 1 (E5)",
            o.encode_payload("ahrs_parameters_load", {}),
            o.DATA,
            0,
        ),
        (
            "Start3DClb-block",
            "Table 6.13 block (120 s, Herndon VA, 2014-03-11) sent as data, type 1 (E5)",
            o.encode_payload(
                "calibration_parameters",
                _fill(
                    "calibration_parameters",
                    accumulation_time=120,
                    latitude=HERNDON[0],
                    longitude=HERNDON[1],
                    altitude=120.0,
                    date=DATE_2014_03_11,
                ),
            ),
            o.DATA,
            0,
        ),
        ("StartClbRun-zeros", "Table 6.16 block of six zeros (6.4.6) sent as data, type 1 (E5)", bytes(6), o.DATA, 0),
        (
            "StartClbRun-any",
            "Table 6.16 block 01..06 (6.4.6: any bytes) sent as data, type 1 (E5)",
            bytes(range(1, 7)),
            o.DATA,
            0,
        ),
        (
            "block-as-type-0",
            "Table 6.16 block of six zeros sent with message type 0, the other reading of E5",
            bytes(6),
            o.COMMAND,
            0,
        ),
        (
            "reserved-nonzero",
            "AHRScont1 (Table C.1) with reserved byte 0x10: the checksum covers it (E6)",
            b"\x80",
            o.COMMAND,
            0x10,
        ),
        ("longest", "a 52-byte block of FF, the longest message (E17)", b"\xff" * 52, o.DATA, 0xFF),
    ]
    for name, note, payload, mtype, reserved in blocks:
        msg = o.frame(mtype, payload, reserved)
        out.append(vec(f"ack/{name}", "ack", hx(msg), hx(o.ack(msg)), f"{note}, framed by Table 6.2; {rule}"))
    bad = [
        ("bad-checksum", "AA 55 00 00 07 00 FE 05 02", "Table C.1 Stop with checksum high byte 02"),
        ("truncated", "AA 55 00 00 07 00 FE 05", "Table C.1 Stop without its last byte"),
        ("bad-header", "55 AA 00 00 07 00 FE 05 01", "Table C.1 Stop with the header bytes swapped"),
    ]
    for name, text, note in bad:
        out.append(
            vec(
                f"ack/{name}",
                "ack",
                text,
                attempt(lambda t=text: o.ack(bytes.fromhex(t))),  # type: ignore[misc]
                f"{note}: only a message that decodes is acknowledged (spec/README.md, frame decode)",
            )
        )
    return out


# --- frames --------------------------------------------------------------------------------------


def suite_frames() -> list[Vector]:
    order = "spec/README.md, frame decode check"
    good = bytes.fromhex("AA5500000700808700")  # Table C.1 AHRScont1
    longest = o.frame(o.DATA, bytes(range(0x80, 0x80 + 52)))
    decode_cases: list[tuple[str, bytes, str]] = [
        ("AHRScont1", good, "Table C.1 AHRScont1 as printed: the shortest legal frame (E17, length 7)"),
        (
            "Stop",
            bytes.fromhex("AA5500000700FE0501"),
            "Table C.1 Stop as printed; checksum 05 01 carries into the high byte",
        ),
        ("longest", longest, "a data frame with a 52-byte payload 80..B3: the longest legal frame (E17, length 58)"),
        (
            "reserved-nonzero",
            o.frame(o.COMMAND, b"\x80", reserved=0x7F),
            "AHRScont1 with reserved byte 7F, checksum recomputed: accepted and returned (E6)",
        ),
        ("reserved-ff", o.frame(o.DATA, b"\x87\x00", reserved=0xFF), "the AHRScont1 ack with reserved FF (E6)"),
        ("data-ack", o.frame(o.DATA, b"\x87\x00"), "the acknowledgement of AHRScont1 (E12): 87 00 in a data frame"),
        (
            "payload-with-header-bytes",
            o.frame(o.DATA, b"\xaa\x55\x00\x00\x07\x00"),
            "AA 55 inside a payload is data, not a header",
        ),
        ("empty", b"", f"{order} 1: no bytes, truncated at 0"),
        ("bad-header-0", b"\xab" + good[1:], f"{order} 1: byte 0 is AB, not AA"),
        ("bad-header-0-swapped", bytes.fromhex("55AA00000700808700"), f"{order} 1: header bytes swapped"),
        ("truncated-1", b"\xaa", f"{order} 2: only the first header byte, truncated at 1"),
        ("bad-header-1", b"\xaa\x56" + good[2:], f"{order} 2: byte 1 is 56, not 55"),
        ("bad-header-1-short", b"\xaa\xaa", f"{order} 2: AA AA, bad header before anything else"),
        ("truncated-3", good[:3], f"{order} 3: AA 55 00, truncated at the input length 3"),
        ("truncated-5", good[:5], f"{order} 3: five bytes, truncated at 5"),
        ("truncated-before-type", bytes.fromhex("AA5507"), f"{order} 3 comes before 4: type 07 but only 3 bytes"),
        ("bad-message-type-2", bytes.fromhex("AA5502000700808900"), f"{order} 4: message type 2 (Table 6.2: 0 or 1)"),
        ("bad-message-type-ff", bytes.fromhex("AA55FF000700808900"), f"{order} 4: message type FF"),
        ("bad-type-before-length", bytes.fromhex("AA550500FFFF"), f"{order} 4 comes before 5: type 5 and length FFFF"),
        ("bad-length-6", bytes.fromhex("AA55000006008000"), f"{order} 5: length 6 is below 7 (E17)"),
        ("bad-length-0", bytes.fromhex("AA550000000080"), f"{order} 5: length 0 (E17)"),
        (
            "bad-length-59",
            bytes.fromhex("AA5501003B00") + bytes(55),
            f"{order} 5: length 59 is above 58 (E17), even with the bytes present",
        ),
        ("bad-length-ffff", bytes.fromhex("AA550000FFFF"), f"{order} 5: length FFFF (E17), six bytes"),
        ("bad-length-high-byte", bytes.fromhex("AA5500000701808700"), f"{order} 5: length 0x0107 = 263 (E17)"),
        ("truncated-6", good[:6], f"{order} 6: header complete, payload missing, truncated at 6"),
        ("truncated-8", good[:8], f"{order} 6: the checksum's high byte missing, truncated at 8"),
        ("truncated-longest", longest[:59], f"{order} 6: the longest frame less one byte, truncated at 59"),
        ("bad-checksum-low", bytes.fromhex("AA5500000700808800"), f"{order} 7: checksum 88 00, sum is 87 00"),
        ("bad-checksum-high", bytes.fromhex("AA5500000700808701"), f"{order} 7: checksum 87 01, sum is 87 00"),
        (
            "bad-checksum-payload",
            bytes.fromhex("AA5500000700818700"),
            f"{order} 7: payload 81 with AHRScont1's checksum 87 00",
        ),
        (
            "bad-checksum-before-trailing",
            bytes.fromhex("AA550000070080880000"),
            f"{order} 7 comes before 8: bad checksum and a trailing byte",
        ),
        ("trailing-data", good + b"\x00", f"{order} 8: one byte after the frame, at 9"),
        ("trailing-frame", good + good, f"{order} 8: two frames are not one, trailing_data at 9"),
    ]
    out = [
        vec(f"frame_decode/{name}", "frame_decode", hx(data), _frame_expect(data), note)
        for name, data, note in decode_cases
    ]
    encode_cases: list[tuple[str, dict[str, Any], str]] = [
        (
            "AHRScont1",
            {"message_type": 0, "payload": "80"},
            "Table C.1 AHRScont1: the builder fills length and checksum; reserved defaults to 0",
        ),
        ("Stop", {"message_type": 0, "payload": "FE", "reserved": 0}, "Table C.1 Stop, checksum 05 01"),
        ("ack", {"message_type": 1, "payload": "87 00"}, "the acknowledgement of AHRScont1 (E12)"),
        ("reserved-ff", {"message_type": 1, "payload": "87 00", "reserved": 255}, "reserved 255 is written (E6)"),
        (
            "longest",
            {"message_type": 1, "payload": hx(bytes(range(0x80, 0x80 + 52)))},
            "a 52-byte payload, the longest (E17)",
        ),
        ("bad-message-type-2", {"message_type": 2, "payload": "80"}, "message type 0 or 1 (Table 6.2)"),
        ("bad-message-type-minus-1", {"message_type": -1, "payload": "80"}, "message type 0 or 1 (Table 6.2)"),
        ("bad-message-type-256", {"message_type": 256, "payload": "80"}, "message type 0 or 1, never wrapped"),
        ("reserved-256", {"message_type": 0, "payload": "80", "reserved": 256}, "reserved 0..255, never wrapped"),
        ("reserved-minus-1", {"message_type": 0, "payload": "80", "reserved": -1}, "reserved 0..255"),
        ("empty-payload", {"message_type": 0, "payload": ""}, "payload 1..52 bytes (E17)"),
        ("payload-53", {"message_type": 1, "payload": hx(bytes(53))}, "payload 1..52 bytes (E17)"),
    ]
    for name, input_, note in encode_cases:

        def build(i: dict[str, Any] = input_) -> str:
            return hx(o.frame(i["message_type"], bytes.fromhex(i["payload"]), i.get("reserved", 0)))

        out.append(
            vec(f"frame_encode/{name}", "frame_encode", input_, attempt(build), f"{note}; spec/README.md, frame encode")
        )
    return out


def _frame_expect(data: bytes) -> Any:
    def run() -> dict[str, Any]:
        mtype, reserved, payload = o.decode_frame(data)
        return {"message_type": mtype, "reserved": reserved, "payload": hx(payload)}

    return attempt(run)


# --- nmea ----------------------------------------------------------------------------------------


def _nmea_expect(text: str) -> Any:
    return attempt(lambda: o.sentence_values(o.decode_sentence(text.encode("latin-1"))))


def _lower_checksum_sentence() -> str:
    """A builder sentence whose checksum has a letter digit, found by stepping the roll."""
    for roll in range(1234, 18000):
        s = o.build_sentence(
            {"roll": roll, "pitch": -567, "heading": 12345, "temperature": 253, "vdd": 502, "usw": 0xA}
        )
        cs = s[-4:-2]
        if cs[1] in "ABCDEF":  # XOR of ASCII is below 0x80: only the low digit can be a letter
            return s
    raise AssertionError("no sentence with a letter checksum")


def suite_nmea() -> list[Vector]:
    t67 = "Table 6.7 template $PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC"
    order = "spec/README.md ($PAHR sentences) decode check"
    typical = {"roll": 1234, "pitch": -567, "heading": 12345, "temperature": 253, "vdd": 502, "usw": 0}
    s_typ = o.build_sentence(typical)
    star = s_typ.index("*")
    long82 = o.sentence("PAHR," + "0" * (82 - len(s_typ) + 0) + s_typ[6:star])
    assert len(long82) == 82, len(long82)
    long83 = o.sentence("PAHR,0" + long82[6 : long82.index("*")])
    assert len(long83) == 83
    lower = _lower_checksum_sentence()
    bad_cs = s_typ[: star + 1] + ("00" if s_typ[star + 1 : star + 3] != "00" else "01") + "\r\n"
    body = s_typ[1:star]

    def with_field(index: int, text: str) -> str:
        parts = body.split(",")
        parts[index + 1] = text
        return o.sentence(",".join(parts))

    decode: list[tuple[str, str, str]] = [
        ("typical", s_typ, f"{t67}, fields written by the E16 rule; checksum XOR (Table 6.7 note 4)"),
        (
            "negative",
            o.build_sentence({"roll": -17999, "pitch": -9000, "heading": 0, "temperature": -400, "vdd": 475, "usw": 1}),
            f"{t67}: roll -179.99, pitch -90.00, heading 0, -40.0 degC, sign counts in the width (E16)",
        ),
        (
            "maximum",
            o.build_sentence(
                {"roll": 18000, "pitch": 9000, "heading": 35999, "temperature": 9999, "vdd": 999, "usw": 0xFFFF}
            ),
            f"{t67}: every field at its maximum (heading 359.99, E23)",
        ),
        (
            "minimum",
            o.build_sentence({"roll": -18000, "pitch": -9000, "heading": 0, "temperature": -999, "vdd": 0, "usw": 0}),
            f"{t67}: every field at its minimum",
        ),
        (
            "no-zero-padding",
            o.sentence("PAHR,12.34,-5.67,123.45,25.3,5.02,0"),
            "E16: decoders accept any number of integer digits; same values as the typical sentence",
        ),
        (
            "fewer-decimals",
            o.sentence("PAHR,12.3,-5,0.5,25,5,AB"),
            "E16: 0 to the template's fraction digits (12.3, -5, 0.5, 25, 5) and a two-digit USW",
        ),
        (
            "many-leading-zeros",
            o.sentence("PAHR,0000012.34,-0005.67,00123.45,0025.3,005.02,0000"),
            "E16: extra leading zeros are accepted",
        ),
        ("minus-zero", o.sentence("PAHR,-0.00,-0,0.00,-0.0,0.00,0"), "-0.00 is zero (integers scaled by 10^decimals)"),
        ("upper-case-checksum", lower, f"{t67}: checksum digits upper case as built (E16)"),
        (
            "lower-case-checksum",
            lower[:-4] + lower[-4:-2].lower() + "\r\n",
            "E16: checksum hex digits in lower case are accepted",
        ),
        (
            "lower-case-usw",
            o.sentence("PAHR,0012.34,-05.67,123.45,025.3,5.02,80ab"),
            "E16: USW hex digits in lower case (sleep bits 7 and 15 set, Table 6.19)",
        ),
        ("one-digit-usw", o.sentence("PAHR,0012.34,-05.67,123.45,025.3,5.02,F"), "USW of 1 hex digit"),
        ("length-82", long82, "E16: a sentence of exactly 82 characters, $ through CR LF (leading zeros in roll)"),
        ("bad-header-0", s_typ[1:], f"{order}: no $"),
        ("bad-header-other-talker", o.sentence("GPHDT,123.45,T"), f"{order}: $GPHDT is not $PAHR"),
        ("bad-header-lower-case", "$pahr" + s_typ[5:], f"{order}: the identifier is PAHR in capitals"),
        ("bad-header-semicolon", "$PAHR;" + s_typ[6:], f"{order}: $PAHR must be followed by a comma"),
        ("truncated-no-end", s_typ[:-2], f"{order}: no CR LF"),
        ("truncated-lf-only", s_typ[:-2] + "\n", f"{order}: LF without CR is no CR LF end"),
        ("truncated-cr-only", s_typ[:-1], f"{order}: CR without LF"),
        ("truncated-half", s_typ[:20], f"{order}: the first 20 characters"),
        ("bad-length-83", long83, f"{order}: 83 characters $ through CR LF, more than 82 (E16)"),
        ("bad-length-no-end", long83[:-2] + "000", f"{order}: 84 characters and no CR LF: already too long"),
        ("trailing-data", s_typ + "X", f"{order}: a character after CR LF"),
        ("trailing-sentence", s_typ + s_typ, f"{order}: two sentences are not one"),
        ("bad-checksum", bad_cs, f"{order}: checksum digits changed; offset of the first digit"),
        (
            "bad-checksum-field-changed",
            s_typ.replace("0012.34", "0012.35"),
            f"{order}: roll changed after the checksum was computed",
        ),
        ("no-star", "$" + body + "\r\n", f"{order}: no * and checksum (malformed)"),
        ("one-checksum-digit", "$" + body + "*7\r\n", f"{order}: one checksum digit (malformed)"),
        ("non-hex-checksum", "$" + body + "*G1\r\n", f"{order}: checksum digit G (malformed)"),
        ("five-fields", o.sentence("PAHR,0012.34,-05.67,123.45,025.3,5.02"), f"{order}: five fields (malformed)"),
        (
            "seven-fields",
            o.sentence("PAHR,0012.34,-05.67,123.45,025.3,5.02,0000,0"),
            f"{order}: seven fields (malformed)",
        ),
        ("empty-roll", with_field(0, ""), f"{order}: empty roll (malformed, field roll)"),
        ("plus-sign", with_field(0, "+12.34"), f"{order}: + is not in the grammar"),
        ("three-decimals", with_field(0, "12.345"), f"{order}: roll has at most 2 decimals"),
        ("trailing-point", with_field(1, "5."), f"{order}: a point needs digits after it"),
        ("leading-point", with_field(1, ".5"), f"{order}: digits needed before the point"),
        ("exponent", with_field(2, "1e2"), f"{order}: no exponent"),
        (
            "vdd-sign-without-digits",
            with_field(4, "-.00"),
            f"{order}: a sign needs digits before the point; every field still at its template width",
        ),
        ("pitch-sign-only", with_field(1, "-"), f"{order}: a lone sign is no number"),
        ("roll-double-sign", with_field(0, "--12.34"), f"{order}: one sign at most; roll at its template width"),
        ("roll-sign-point", with_field(0, "-.50"), f"{order}: digits needed between the sign and the point"),
        ("space", with_field(2, " 123.45"), f"{order}: no spaces"),
        ("temperature-two-decimals", with_field(3, "25.35"), f"{order}: temperature has 1 decimal (TTT.t)"),
        ("degree-sign", with_field(3, "25.3\xb0"), f"{order}: a Latin-1 byte B0 in the temperature"),
        ("vdd-letter", with_field(4, "5.0x"), f"{order}: a letter in vdd"),
        ("usw-five-digits", with_field(5, "10000"), f"{order}: USW has 1 to 4 hex digits"),
        ("usw-empty", with_field(5, ""), f"{order}: USW has 1 to 4 hex digits"),
        ("usw-prefix", with_field(5, "0x12"), f"{order}: no 0x prefix"),
        ("usw-negative", with_field(5, "-1"), f"{order}: no sign in the USW"),
        ("roll-180.01", with_field(0, "180.01"), f"{order}: roll range -180.00..180.00 (out_of_range)"),
        ("roll-minus-180.01", with_field(0, "-180.01"), f"{order}: roll range -180.00..180.00"),
        (
            "roll-huge",
            with_field(0, "99999999999999999999999999.99"),
            f"{order}: grammatical but far beyond any integer type: out_of_range, never wrapped",
        ),
        ("pitch-90.01", with_field(1, "90.01"), f"{order}: pitch range -90.00..90.00"),
        ("pitch-minus-90.01", with_field(1, "-90.01"), f"{order}: pitch range -90.00..90.00"),
        ("heading-360", with_field(2, "360.00"), f"{order}: heading range 0..359.99 (E23)"),
        ("heading-negative", with_field(2, "-0.01"), f"{order}: heading range 0..359.99"),
        ("temperature-minus-100", with_field(3, "-100.0"), f"{order}: temperature range -99.9..999.9 (TTT.t)"),
        ("temperature-1000", with_field(3, "1000.0"), f"{order}: temperature range -99.9..999.9 (TTT.t)"),
        ("vdd-negative", with_field(4, "-0.01"), f"{order}: vdd range 0..9.99 (V.vv)"),
        ("vdd-10", with_field(4, "10.00"), f"{order}: vdd range 0..9.99 (V.vv)"),
    ]
    out = [vec(f"nmea_decode/{name}", "nmea_decode", text, _nmea_expect(text), note) for name, text, note in decode]
    # Offsets for truncated, trailing_data and malformed are not stated by spec/README.md: not checked.
    for v in out:
        if isinstance(v["expect"], dict) and v["expect"].get("error") in ("truncated", "trailing_data", "malformed"):
            v["expect"].pop("offset", None)

    rule = "spec/README.md ($PAHR): build with the integer part zero-padded to the template width (E16)"
    encode: list[tuple[str, dict[str, float | int], str]] = [
        (
            "typical",
            {"roll": 12.34, "pitch": -5.67, "heading": 123.45, "temperature": 25.3, "vdd": 5.02, "usw": 0},
            rule,
        ),
        (
            "readme-example-negative",
            {"roll": -12.34, "pitch": 5.5, "heading": 0.0, "temperature": -5.5, "vdd": 0.0, "usw": 0xABCD},
            f"{rule}: roll -12.34 is -012.34 (the README's example), the sign counting in the width; USW upper case",
        ),
        (
            "readme-example-padding",
            {"roll": 5.5, "pitch": -0.5, "heading": 7.0, "temperature": 0.5, "vdd": 0.05, "usw": 0xB},
            f"{rule}: roll 5.5 is 0005.50 (the README's example)",
        ),
        (
            "maximum",
            {"roll": 180.0, "pitch": 90.0, "heading": 359.99, "temperature": 999.9, "vdd": 9.99, "usw": 0xFFFF},
            rule,
        ),
        ("minimum", {"roll": -180.0, "pitch": -90.0, "heading": 0.0, "temperature": -99.9, "vdd": 0.0, "usw": 0}, rule),
        (
            "round-half-away",
            {"roll": 0.125, "pitch": -0.125, "heading": 0.375, "temperature": 0.25, "vdd": 0.625, "usw": 1},
            "spec/README.md: engineering to raw rounds half away from zero (exact binary halves: 12.5 -> 13, "
            "-12.5 -> -13, 37.5 -> 38, 2.5 -> 3, 62.5 -> 63)",
        ),
        (
            "round-negative-half",
            {"roll": -0.125, "pitch": 0.0, "heading": 1.0, "temperature": -0.25, "vdd": 1.0, "usw": 0x10},
            "spec/README.md: half away from zero, negative side: -12.5 -> -13, -2.5 -> -3",
        ),
        (
            "tiny-negative-is-zero",
            {"roll": -0.001, "pitch": -0.004, "heading": 0.004, "temperature": -0.04, "vdd": 0.001, "usw": 0},
            "values that round to 0 are written without a sign (integers have no -0)",
        ),
        (
            "heading-360",
            {"roll": 0.0, "pitch": 0.0, "heading": 360.0, "temperature": 0.0, "vdd": 0.0, "usw": 0},
            "heading range 0..359.99 (E23)",
        ),
        (
            "heading-rounds-to-360",
            {"roll": 0.0, "pitch": 0.0, "heading": 359.996, "temperature": 0.0, "vdd": 0.0, "usw": 0},
            "359.996 rounds to 36000, then the range check refuses it (spec/README.md)",
        ),
        (
            "roll-180.01",
            {"roll": 180.01, "pitch": 0.0, "heading": 0.0, "temperature": 0.0, "vdd": 0.0, "usw": 0},
            "roll range -180..180",
        ),
        (
            "pitch-minus-90.01",
            {"roll": 0.0, "pitch": -90.01, "heading": 0.0, "temperature": 0.0, "vdd": 0.0, "usw": 0},
            "pitch range -90..90",
        ),
        (
            "temperature-1000",
            {"roll": 0.0, "pitch": 0.0, "heading": 0.0, "temperature": 1000.0, "vdd": 0.0, "usw": 0},
            "temperature range -99.9..999.9 (TTT.t)",
        ),
        (
            "vdd-10",
            {"roll": 0.0, "pitch": 0.0, "heading": 0.0, "temperature": 0.0, "vdd": 10.0, "usw": 0},
            "vdd range 0..9.99",
        ),
        (
            "vdd-negative",
            {"roll": 0.0, "pitch": 0.0, "heading": 0.0, "temperature": 0.0, "vdd": -0.01, "usw": 0},
            "vdd range 0..9.99",
        ),
        (
            "usw-65536",
            {"roll": 0.0, "pitch": 0.0, "heading": 0.0, "temperature": 0.0, "vdd": 0.0, "usw": 65536},
            "USW 0..FFFF, never wrapped",
        ),
        (
            "usw-negative",
            {"roll": 0.0, "pitch": 0.0, "heading": 0.0, "temperature": 0.0, "vdd": 0.0, "usw": -1},
            "USW 0..FFFF",
        ),
        (
            "roll-nan",
            {"roll": math.nan, "pitch": 0.0, "heading": 0.0, "temperature": 0.0, "vdd": 0.0, "usw": 0},
            "NaN is no value in range (as for payload floats, spec/README.md)",
        ),
    ]
    for name, values, note in encode:
        out.append(
            vec(
                f"nmea_encode/{name}",
                "nmea_encode",
                {k: jsonable(v) for k, v in values.items()},
                attempt(lambda v=values: o.build_sentence(_nmea_raw(v))),  # type: ignore[misc]
                note,
            )
        )
    return out


def _nmea_raw(values: dict[str, float | int]) -> dict[str, int]:
    """Engineering values to scaled integers, rounding half away from zero."""
    out: dict[str, int] = {}
    for f in o.NMEA_FIELDS:
        value = values[f.name]
        if f.decimals == 0:
            out[f.name] = int(value)
            continue
        if math.isnan(value):
            raise o.OracleError("out_of_range", None, f.name)
        scaled = value * 10**f.decimals
        out[f.name] = int(math.copysign(math.floor(abs(scaled) + 0.5), scaled))
    return out


# --- streams -------------------------------------------------------------------------------------


def _stream_vec(
    id_: str,
    chunks: list[bytes],
    note: str,
    *,
    compact: bool = False,
    expect_events: list[tuple[str, bytes]] | None = None,
    expect_discarded: int | None = None,
) -> Vector:
    events, discarded = o.scan(b"".join(chunks))
    if expect_events is not None:  # the intended answer, cross-checked against the oracle's scan
        assert events == expect_events, (id_, events, expect_events)
    if expect_discarded is not None:
        assert discarded == expect_discarded, (id_, discarded, expect_discarded)
    show = (lambda b: b.hex().upper()) if compact else hx
    return vec(
        id_,
        "stream",
        {"chunks": [show(c) for c in chunks]},
        {
            "events": [
                {"frame": show(data)} if kind == "frame" else {"nmea": data.decode("latin-1")} for kind, data in events
            ],
            "discarded": discarded,
        },
        note,
    )


def _split(data: bytes, size: int) -> list[bytes]:
    return [data[i : i + size] for i in range(0, len(data), size)]


def suite_streams() -> list[Vector]:
    rule = "spec/README.md, stream decoder (leftmost valid message); expected answer by the oracle's whole-input scan"
    data_payload = o.encode_payload(
        "orientation_sensors",
        _fill(
            "orientation_sensors",
            heading=27000,
            pitch=-250,
            roll=125,
            gyro_x=1500,
            gyro_y=-1500,
            gyro_z=50,
            acc_z=10000,
            mag_x=2000,
            mag_y=-1500,
            mag_z=4500,
            vdd=12000,
            utermo=251,
        ),
    )
    data = o.frame(o.DATA, data_payload)  # 42 bytes, Table 6.6
    longest = o.frame(
        o.DATA,
        o.encode_payload(
            "calibration_result",
            _fill(
                "calibration_result",
                calibration_type=3,
                runs_used=1,
                data_used=95,
                success=5,
                tm_c_11=1.0,
                tm_c_22=1.0,
                tm_c_33=1.0,
                hm_0_x=12.5,
            ),
        ),
    )  # 60 bytes, Table 6.14
    cont1 = bytes.fromhex("AA5500000700808700")
    ack1 = o.ack(cont1)
    s1 = o.build_sentence(
        {"roll": 1234, "pitch": -567, "heading": 12345, "temperature": 253, "vdd": 502, "usw": 0}
    ).encode()
    s2 = o.build_sentence(
        {"roll": -1, "pitch": 2, "heading": 35999, "temperature": -400, "vdd": 999, "usw": 0x8080}
    ).encode()
    f_ = "frame"
    n_ = "nmea"
    out: list[Vector] = []

    for size in range(1, len(data) + 1):
        out.append(
            _stream_vec(
                f"stream/sweep-data-frame-{size}",
                _split(data, size),
                f"a Table 6.6 data frame (42 bytes) in chunks of {size}; {rule}",
                expect_events=[(f_, data)],
                expect_discarded=0,
            )
        )
    for size in range(1, len(longest) + 1):
        out.append(
            _stream_vec(
                f"stream/sweep-longest-frame-{size}",
                _split(longest, size),
                f"a Table 6.14 frame (60 bytes, the longest, E17) in chunks of {size}; {rule}",
                expect_events=[(f_, longest)],
                expect_discarded=0,
            )
        )
    mixed = ack1 + s1
    for size in range(1, len(mixed) + 1):
        out.append(
            _stream_vec(
                f"stream/sweep-ack-sentence-{size}",
                _split(mixed, size),
                f"the AHRScont1 ack (E12) then a $PAHR sentence (Table 6.7), chunks of {size}; {rule}",
                expect_events=[(f_, ack1), (n_, s1)],
                expect_discarded=0,
            )
        )

    false_span = bytes.fromhex("AA5501003400")  # length 52: span of 54 bytes
    out_of_range = o.sentence("PAHR,0190.00,00.00,000.00,000.0,0.00,0000").encode()
    too_long = o.sentence("PAHR,0" + s1[6 : s1.index(b"*")].decode() + "0" * 40).encode()
    assert len(too_long) > o.MAX_SENTENCE and len(s1) <= 52
    cases: list[tuple[str, list[bytes], str, list[tuple[str, bytes]], int]] = [
        ("empty", [b""], "no input at all", [], 0),
        ("garbage-only", [b"\x00\x01\x02\xfe\xff"], "five bytes that start nothing", [], 5),
        (
            "garbage-between",
            [b"\x01\x02" + cont1 + b"\x03\x04\x05" + data + b"\x06"],
            "garbage before, between and after two frames",
            [(f_, cont1), (f_, data)],
            6,
        ),
        (
            "aa-aa-55",
            [b"\xaa" + cont1],
            "AA then AA 55 ...: the first AA is not a header (byte 1 is AA)",
            [(f_, cont1)],
            1,
        ),
        (
            "aa-55-aa-55",
            [b"\xaa\x55" + cont1],
            "a lone AA 55 before a frame: its type byte AA is not 0 or 1",
            [(f_, cont1)],
            2,
        ),
        (
            "false-header-ffff",
            [bytes.fromhex("AA550000FFFF") + cont1],
            "a false header with length FFFF (E17 bound), then a real frame",
            [(f_, cont1)],
            6,
        ),
        (
            "false-header-covers-frame",
            [false_span + cont1 + data],
            "a false header whose length 52 spans the next frames; its checksum fails, both real frames survive",
            [(f_, cont1), (f_, data)],
            6,
        ),
        (
            "false-header-covers-frame-at-end",
            [false_span + cont1],
            "a false header whose span is never complete: at the end of input the frame inside it is still emitted",
            [(f_, cont1)],
            6,
        ),
        (
            "false-header-one-byte-chunks",
            _split(false_span + cont1 + data, 1),
            "the same false header fed one byte at a time",
            [(f_, cont1), (f_, data)],
            6,
        ),
        (
            "header-in-payload",
            [o.frame(o.DATA, b"\xaa\x55\x00\x00\x07\x00\x80\x87\x00") + cont1],
            "AA 55 and a whole command inside a payload belong to the outer frame",
            [(f_, o.frame(o.DATA, b"\xaa\x55\x00\x00\x07\x00\x80\x87\x00")), (f_, cont1)],
            0,
        ),
        (
            "sentence-in-payload",
            [o.frame(o.DATA, s1)],
            "a whole $PAHR sentence inside a payload belongs to the frame",
            [(f_, o.frame(o.DATA, s1))],
            0,
        ),
        (
            "corrupted-then-good",
            [data[:10] + bytes([data[10] ^ 0x01]) + data[11:] + data],
            "a data frame with one payload bit flipped (checksum fails), then the same frame intact",
            [(f_, data)],
            42,
        ),
        (
            "truncated-then-good",
            [data[:30] + data],
            "the first 30 bytes of a frame, then a whole frame",
            [(f_, data)],
            30,
        ),
        ("ends-inside-frame", [cont1, data[:20]], "a frame, then input ends 20 bytes into the next", [(f_, cont1)], 20),
        ("ends-inside-header", [cont1 + b"\xaa\x55\x01"], "input ends inside a header", [(f_, cont1)], 3),
        (
            "ends-inside-sentence",
            [s1 + s2[:-1]],
            "input ends before the LF of the second sentence",
            [(n_, s1)],
            len(s2) - 1,
        ),
        (
            "acks-then-sentences",
            [ack1, o.ack(bytes.fromhex("AA5500000700888F00")), s1, s2, s1],
            "the acks of AHRScont1 and NMEAcont (E12), then $PAHR sentences as NMEAcont output (6.3.3)",
            [(f_, ack1), (f_, o.ack(bytes.fromhex("AA5500000700888F00"))), (n_, s1), (n_, s2), (n_, s1)],
            0,
        ),
        (
            "bad-checksum-sentence",
            [s1.replace(b"0012.34", b"0012.35") + s2],
            "a sentence whose roll changed after its checksum, then a good one",
            [(n_, s2)],
            len(s1),
        ),
        (
            "out-of-range-sentence",
            [out_of_range + s2],
            "a sentence with roll 190.00 (out of range) is no valid message",
            [(n_, s2)],
            len(out_of_range),
        ),
        ("lf-only-sentence", [s1[:-2] + b"\n" + s2], "a sentence ending in LF without CR", [(n_, s2)], len(s1) - 1),
        ("dollar-without-lf", [b"$PAHR," + b"0" * 100 + s1], "a $ with no LF within 82 bytes", [(n_, s1)], 106),
        (
            "long-sentence",
            [too_long + s1],
            "a sentence longer than 82 characters is no valid message",
            [(n_, s1)],
            len(too_long),
        ),
        (
            "frame-inside-sentence",
            [s1[:20] + cont1 + s1[20:]],
            "a frame in the middle of a sentence: the broken sentence is discarded, the frame kept",
            [(f_, cont1)],
            len(s1),
        ),
        (
            "sentence-then-frame-no-gap",
            [s1 + cont1 + s2 + data],
            "sentences and frames back to back",
            [(n_, s1), (f_, cont1), (n_, s2), (f_, data)],
            0,
        ),
        ("type-2-frame", [bytes.fromhex("AA5502000700808900") + cont1], "message type 2 is no frame", [(f_, cont1)], 9),
        (
            "length-6-frame",
            [bytes.fromhex("AA550000060080") + cont1],
            "message length 6 is no frame (E17)",
            [(f_, cont1)],
            7,
        ),
        (
            "reserved-nonzero",
            [o.frame(o.COMMAND, b"\x80", reserved=0x33)],
            "a non-zero reserved byte (E6)",
            [(f_, o.frame(o.COMMAND, b"\x80", reserved=0x33))],
            0,
        ),
    ]
    for name, chunks, note, events, discarded in cases:
        out.append(
            _stream_vec(f"stream/{name}", chunks, f"{note}; {rule}", expect_events=events, expect_discarded=discarded)
        )
    out.append(_soak("stream/soak-2500", 2500, seed=20240601, chunk_sizes=(1, 64), rule=rule))
    out.append(_soak("stream/soak-400-small-chunks", 400, seed=7, chunk_sizes=(1, 3), rule=rule))
    return out


def _soak(id_: str, count: int, *, seed: int, chunk_sizes: tuple[int, int], rule: str) -> Vector:
    """Thousands of messages with garbage and corrupted frames between them, chunked at random."""
    min_chunk, max_chunk = chunk_sizes
    rng = random.Random(seed)
    tables = sorted(name for name in o.TABLES if o.TABLES[name][1] <= o.MAX_PAYLOAD)
    stream = b""
    intended: list[tuple[str, bytes]] = []
    garbage = 0
    for _ in range(count):
        roll = rng.random()
        if roll < 0.55:
            size = o.TABLES[rng.choice(tables)][1]
            msg = o.frame(o.DATA, bytes(rng.randrange(256) for _ in range(size)), rng.choice([0, 0, 0, 0x42]))
            intended.append(("frame", msg))
        elif roll < 0.70:
            msg = o.frame(o.COMMAND, bytes([rng.choice(o.table_c1()).code]))
            intended.append(("frame", msg))
        elif roll < 0.85:
            msg = o.build_sentence(
                {
                    "roll": rng.randint(-18000, 18000),
                    "pitch": rng.randint(-9000, 9000),
                    "heading": rng.randint(0, 35999),
                    "temperature": rng.randint(-999, 9999),
                    "vdd": rng.randint(0, 999),
                    "usw": rng.randrange(0x10000),
                }
            ).encode()
            intended.append(("nmea", msg))
        elif roll < 0.93:
            good = o.frame(o.DATA, bytes(rng.randrange(256) for _ in range(rng.randint(1, 52))))
            i = rng.randrange(2, len(good))
            msg = good[:i] + bytes([good[i] ^ (1 << rng.randrange(8))]) + good[i + 1 :]
            garbage += len(msg)
        else:
            msg = rng.choice([b"\xaa", b"\xaa\x55", b"$", b"$PAHR,", bytes.fromhex("AA550000FFFF")])
            msg += bytes(rng.randrange(256) for _ in range(rng.randint(0, 6)))
            garbage += len(msg)
        stream += msg
    chunks = []
    pos = 0
    while pos < len(stream):
        size = rng.randint(min_chunk, max_chunk)
        chunks.append(stream[pos : pos + size])
        pos += size
    frames = sum(1 for kind, _ in intended if kind == "frame")
    note = (
        f"seeded soak (seed {seed}): {count} messages ({frames} valid frames, {len(intended) - frames} "
        f"sentences, the rest corrupted frames and false starts), random chunks of {min_chunk}..{max_chunk} "
        f"bytes; chunking never changes the result; computed by conformance/tools/make_vectors.py; {rule}"
    )
    return _stream_vec(id_, chunks, note, compact=True, expect_events=intended, expect_discarded=garbage)


# --- sessions ------------------------------------------------------------------------------------

_CODES = {row.name: row.code for row in o.table_c1()}


def cmd(name: str) -> d.Input:
    """A command frame of Table C.1, by ICD name."""
    return ("command", _CODES[name])


def code(value: int) -> d.Input:
    return ("command", value)


def block(table: str) -> d.Input:
    """A data message with a payload of the table's size (sizes as printed in the ICD tables)."""
    return ("data", o.TABLES[table][1])


def data(size: int) -> d.Input:
    return ("data", size)


def ev(name: str) -> d.Input:
    return ("event", name)


LOAD = block("ahrs_parameters_load")  # Table 6.9, 50 bytes
CALIBRATION = block("calibration_parameters")  # Table 6.13, 22 bytes
RUN = block("calibration_run_parameters")  # Table 6.16, 6 bytes
ALIGNED = ev("alignment_done")
ACCUMULATED = ev("accumulation_done")
DUE = ev("output_due")
TIMEOUT = ev("block_timeout")


def _input_json(item: d.Input) -> dict[str, Any]:
    kind, value = item
    if kind == "command":
        assert isinstance(value, int)
        return {"command": f"0x{value:02X}"}
    return {kind: value}


def _input_label(item: d.Input) -> str:
    kind, value = item
    if kind == "command":
        assert isinstance(value, int)
        return f"0x{value:02X}"
    return f"data-{value}" if kind == "data" else str(value)


def _session_vec(
    id_: str, items: list[d.Input], note: str, *, firmware: str | None = None, ends: str | None = None
) -> Vector:
    device = d.Device(firmware)
    steps = device.run(items)
    if ends is not None:  # the intended end of the flow, cross-checked against the oracle
        assert device.state == ends, (id_, device.state, ends)
    input_: dict[str, Any] = {} if firmware is None else {"firmware": firmware}
    input_["events"] = [_input_json(item) for item in items]
    return vec(id_, "session", input_, {"steps": [s.expect() for s in steps], "state": device.state}, note)


def _describe(items: list[d.Input]) -> str:
    device = d.Device()
    return ", ".join(step.event for step in device.run(items)) or "power-up"


def _single_steps() -> list[Vector]:
    """Every input in every state: the shortest way there, then one input."""
    out: list[Vector] = []
    for state, path in d.reach().items():
        for item in d.inputs():
            device = d.Device()
            device.run(path)
            step = device.feed(item)
            if d.react(state, step.event) is None:
                outcome = f"{step.event} is ignored: no answer, no change (E33)"
            else:
                sent = " + ".join(step.send) or "nothing"
                outcome = f"{step.event} goes to {step.state} and sends {sent}"
            note = f"ICD {d.SOURCES[state]}; {state} (mode {d.MODES[state]}) by {_describe(path)}; then {outcome}"
            out.append(_session_vec(f"step/{state}/{_input_label(item)}", [*path, item], note))
    return out


def _flows() -> list[Vector]:
    out: list[Vector] = []

    def flow(id_: str, items: list[d.Input], note: str, *, firmware: str | None = None, ends: str) -> None:
        out.append(_session_vec(f"flow/{id_}", items, f"{ICD} {note}", firmware=firmware, ends=ends))

    # Continuous and on-request output, every format.
    for start in ("AHRScont1", "AHRScont2", "AHRScont3", "NMEAcont"):
        table = "Table 6.7 $PAHR sentences" if start == "NMEAcont" else "Table 6.4/6.5/6.6 blocks"
        flow(
            f"continuous/{start}",
            [cmd(start), DUE, cmd("GetDataReq"), ALIGNED, DUE, DUE, DUE, cmd("GetBIT"), cmd("GetDataReq"), cmd(start),
             cmd("Stop"), DUE],
            f"6.3.1, 6.3.3: {start} is acknowledged at once (E12), nothing is output during the initial alignment, "
            f"then the Table 6.8 block and {table} at the update rate; GetDataReq (6.3.4) and GetBIT (6.3.11) are not "
            "valid in continuous mode and a second start command is not either (6.3.5: Stop first), so they are "
            "ignored (E33); Stop goes to idle without an answer (6.3.5, E14) and output ends",
            ends=d.IDLE,
        )
    for start in ("AHRSreq1", "AHRSreq2", "AHRSreq3", "NMEAreq"):
        table = "a Table 6.7 $PAHR sentence" if start == "NMEAreq" else "one Table 6.4/6.5/6.6 block"
        flow(
            f"on-request/{start}",
            [cmd(start), cmd("GetDataReq"), cmd("GetBIT"), ALIGNED, cmd("GetDataReq"), cmd("GetDataReq"),
             cmd("GetBIT"), DUE, cmd("GetDataReq"), cmd("Stop"), cmd("GetDataReq")],
            f"6.3.2, 6.3.3: {start} is acknowledged at once (E12); GetDataReq and GetBIT during the initial alignment "
            "are ignored (E39; 6.3.2: the AHRS goes to On Request mode after the alignment); then each GetDataReq "
            f"gets {table} (6.3.4) and GetBIT the Table 6.12 block (6.3.11, E25); no timer output in this mode; after "
            "Stop (6.3.5, E14) GetDataReq is ignored (6.3.4: valid after a request command only)",
            ends=d.IDLE,
        )

    # 0xFE in every state, then GetVerFirmware to show where the device is.
    for state, path in d.reach().items():
        meaning = "ExitClb, acknowledged (6.4.4)" if d.MODES[state] == "calibration" else "Stop (6.3.5), no answer"
        if state == d.SLEEP:
            meaning = "Stop, which Sleep mode does not hear (6.3.8: only the command to exit Sleep)"
        elif state == d.AWAITING_PARAMETERS:
            meaning = "Stop, which abandons the awaited Table 6.9 block without an answer (E34)"
        flow(
            f"0xFE/{state}",
            [*path, code(0xFE), cmd("GetVerFirmware")],
            f"Table C.1 and E14: 0xFE is ExitClb in calibration mode and Stop in every other mode; in {state} "
            f"(mode {d.MODES[state]}, reached by {_describe(path)}) it is {meaning}; GetVerFirmware then answers "
            "only in idle (6.3.10)",
            ends=d.SLEEP if state == d.SLEEP else d.IDLE,
        )

    # Codes not in Table C.1.
    flow(
        "unknown/idle",
        [code(0x00), code(0xFF), code(0x81), code(0x2D), cmd("GetBIT")],
        "codes 0x00, 0xFF, 0x81 and 0x2D are not in Table C.1: ignored (E33), the device still answers GetBIT (6.3.11)",
        ends=d.IDLE,
    )
    flow(
        "unknown/continuous",
        [cmd("AHRScont1"), ALIGNED, code(0x81), DUE, code(0xFF), DUE],
        "6.3.1; an unknown code in continuous mode is ignored (E33) and output goes on",
        ends=d.CONTINUOUS,
    )
    flow(
        "unknown/calibration",
        [cmd("Start3DClb"), CALIBRATION, ALIGNED, ACCUMULATED, code(0x2D), cmd("AcceptClb")],
        "6.4.1; an unknown code while the result waits for AcceptClb is ignored (E33); AcceptClb then saves (6.4.3)",
        ends=d.IDLE,
    )
    for start, parameters in (("LoadAHRSPar", LOAD), ("Start3DClb", CALIBRATION), ("Start2D2TClb", CALIBRATION)):
        flow(
            f"unknown/instead-of-block/{start}",
            [cmd(start), code(0xFF), parameters],
            f"E34: after {start} a block of the expected size is acknowledged and \"anything else (no block, a "
            "command, a data message of another size) abandons the command without an answer\": a command frame "
            "with code 0xFF (not in Table C.1) is something else, so the command is abandoned and the block that "
            "follows is a data message idle mode ignores (E33)",
            ends=d.IDLE,
        )
    flow(
        "unknown/instead-of-block/StartClbRun",
        [cmd("Start2D2TClb"), CALIBRATION, cmd("StartClbRun"), code(0x00), RUN, cmd("FinishClb")],
        "E34: after StartClbRun anything but its Table 6.16 block abandons it \"to between-runs\": a command frame "
        "with code 0x00 (not in Table C.1) is something else; the block that follows is ignored there (E33) and "
        "FinishClb still finishes (6.4.7, E37)",
        ends=d.CALIBRATION_DECIDING,
    )

    # LoadAHRSPar and its block (6.3.6).
    flow(
        "load-parameters/block",
        [cmd("LoadAHRSPar"), LOAD, cmd("ReadAHRSPar")],
        "6.3.6: LoadAHRSPar gets no answer (E13), its Table 6.9 block (50 bytes) is acknowledged (E12) and the "
        "device is in idle; ReadAHRSPar answers Table 6.10 (6.3.7)",
        ends=d.IDLE,
    )
    flow(
        "load-parameters/block-then-start",
        [cmd("LoadAHRSPar"), LOAD, cmd("AHRScont3"), ALIGNED, DUE, cmd("Stop")],
        "6.3.6 then 6.3.1: after the acknowledged block the device takes start commands",
        ends=d.IDLE,
    )
    for size in (22, 6, 49, 51, 1):
        flow(
            f"load-parameters/wrong-size-{size}",
            [cmd("LoadAHRSPar"), data(size), LOAD, cmd("ReadAHRSPar")],
            f"E34: a data message of {size} bytes is not the 50-byte Table 6.9 block: LoadAHRSPar is abandoned without "
            "an answer; the 50-byte message after it finds idle mode and is ignored (E33)",
            ends=d.IDLE,
        )
    flow(
        "load-parameters/command-instead",
        [cmd("LoadAHRSPar"), cmd("ReadAHRSPar"), cmd("ReadAHRSPar")],
        "E34: a command instead of the block abandons LoadAHRSPar and is not executed itself (no answer); the next "
        "ReadAHRSPar is answered (6.3.7)",
        ends=d.IDLE,
    )
    flow(
        "load-parameters/start-command-instead",
        [cmd("LoadAHRSPar"), cmd("AHRScont1"), DUE, ALIGNED],
        "E34: AHRScont1 instead of the block abandons LoadAHRSPar and does not start output (no ack, no alignment)",
        ends=d.IDLE,
    )
    flow(
        "load-parameters/twice",
        [cmd("LoadAHRSPar"), cmd("LoadAHRSPar"), LOAD],
        "E34: a second LoadAHRSPar instead of the block abandons the first and is not executed; the block then "
        "finds idle mode and is ignored (E33)",
        ends=d.IDLE,
    )
    flow(
        "load-parameters/timeout",
        [cmd("LoadAHRSPar"), TIMEOUT, LOAD, cmd("GetVerFirmware")],
        "E34: no block within 1 s abandons LoadAHRSPar without an answer; a late block is ignored in idle (E33)",
        ends=d.IDLE,
    )

    # 3D and 2D calibration: one run (6.4.1, 6.4.8).
    for start in ("Start3DClb", "Start2DClb"):
        section = "6.4.1" if start == "Start3DClb" else "6.4.8"
        for stop, stop_name in ((ACCUMULATED, "accumulation-done"), (cmd("StopClbRun"), "StopClbRun")):
            how = "at the set time" if stop == ACCUMULATED else "early on StopClbRun (6.4.2)"
            for decision in ("AcceptClb", "ExitClb"):
                then = "AcceptClb saves it (6.4.3)" if decision == "AcceptClb" else "ExitClb drops it (6.4.4)"
                flow(
                    f"calibration/{start}/{stop_name}/{decision}",
                    [cmd(start), CALIBRATION, cmd("StopClbRun"), cmd("AcceptClb"), ALIGNED, cmd("AcceptClb"), DUE,
                     stop, cmd("StopClbRun"), cmd(decision), cmd("GetClbRes")],
                    f"{section}: {start} gets no answer (E13), its Table 6.13 block (22 bytes) is acknowledged, the "
                    f"initial alignment ends with the Table 6.8 block, accumulation ends {how} with the Table 6.14 "
                    f"result (E38: at once), and {then}, acknowledged, to idle; StopClbRun before accumulation or "
                    "after the result, AcceptClb before the result and the output timer are ignored (E33); GetClbRes "
                    "answers Table 6.17 in idle (6.4.10)",
                    ends=d.IDLE,
                )
    for start in ("Start3DClb", "Start2DClb"):
        flow(
            f"calibration/{start}/block-timeout",
            [cmd(start), TIMEOUT, CALIBRATION],
            f"E34: no Table 6.13 block within 1 s of {start}: abandoned without an answer; a late block is ignored",
            ends=d.IDLE,
        )
        flow(
            f"calibration/{start}/wrong-block",
            [cmd(start), LOAD, ALIGNED],
            f"E34: a 50-byte message is not the 22-byte Table 6.13 block: {start} is abandoned, nothing aligns",
            ends=d.IDLE,
        )
        flow(
            f"calibration/{start}/exit-instead-of-block",
            [cmd(start), cmd("ExitClb"), CALIBRATION],
            f"E34: \"ExitClb is still acknowledged in calibration\": ExitClb instead of the block after {start} is "
            "answered (6.4.4) and goes to idle; the late block is ignored",
            ends=d.IDLE,
        )
        flow(
            f"calibration/{start}/exit-during-alignment",
            [cmd(start), CALIBRATION, cmd("ExitClb"), ALIGNED],
            "6.4.4: ExitClb during the initial alignment is acknowledged and goes to idle; no alignment block follows",
            ends=d.IDLE,
        )
        flow(
            f"calibration/{start}/exit-during-accumulation",
            [cmd(start), CALIBRATION, ALIGNED, cmd("ExitClb"), ACCUMULATED],
            "6.4.4: ExitClb during accumulation is acknowledged, nothing is computed: no result follows",
            ends=d.IDLE,
        )

    # 2D-2T calibration: several runs (6.4.5 - 6.4.7).
    setup = [cmd("Start2D2TClb"), CALIBRATION]
    run_full = [cmd("StartClbRun"), RUN, ALIGNED, ACCUMULATED]
    run_stopped = [cmd("StartClbRun"), RUN, ALIGNED, cmd("StopClbRun")]
    flow(
        "2d2t/three-runs-finish-accept",
        [*setup, ALIGNED, ACCUMULATED, *run_full, *run_stopped, *run_full, cmd("FinishClb"), cmd("AcceptClb")],
        "6.4.5, 6.4.6: Start2D2TClb's Table 6.13 block is acknowledged and the device waits for the first "
        "StartClbRun with no alignment (E36: alignment and accumulation timers are ignored there); each StartClbRun "
        "gets no answer (E13), its Table 6.16 block (6 bytes) is acknowledged, the run aligns (Table 6.8) and "
        "accumulates until the set time or StopClbRun (6.4.2), then sends its Table 6.15 result; FinishClb sends "
        "the Table 6.14 result (6.4.7) and AcceptClb saves it (6.4.3)",
        ends=d.IDLE,
    )
    flow(
        "2d2t/two-runs-finish-exit",
        [*setup, *run_full, *run_full, cmd("FinishClb"), cmd("StartClbRun"), cmd("ExitClb")],
        "6.4.5, 6.4.7: after FinishClb's Table 6.14 result only AcceptClb or ExitClb are heard (StartClbRun is "
        "ignored, E33); ExitClb leaves without saving, acknowledged (6.4.4)",
        ends=d.IDLE,
    )
    flow(
        "2d2t/exit-between-runs",
        [*setup, *run_full, cmd("ExitClb"), cmd("StartClbRun"), cmd("FinishClb")],
        "6.4.5 choice 3: ExitClb between runs ends the calibration, acknowledged (6.4.4); StartClbRun and FinishClb "
        "are then ignored in idle (E33)",
        ends=d.IDLE,
    )
    flow(
        "2d2t/exit-during-run",
        [*setup, cmd("StartClbRun"), RUN, ALIGNED, cmd("ExitClb"), ACCUMULATED],
        "6.4.4: ExitClb during a run's accumulation is acknowledged; no run result follows",
        ends=d.IDLE,
    )
    flow(
        "2d2t/finish-without-runs",
        [*setup, cmd("FinishClb"), cmd("AcceptClb")],
        "E37: \"FinishClb is accepted between runs at any time\", even before any run; the Table 6.14 result reports "
        "the failure (6.4.5: two successful runs are needed)",
        ends=d.IDLE,
    )
    flow(
        "2d2t/commands-between-runs",
        [*setup, *run_full, cmd("AcceptClb"), cmd("StopClbRun"), cmd("GetDataReq"), cmd("Start2D2TClb"), ACCUMULATED,
         cmd("FinishClb")],
        "6.4.5: between runs the device waits for StartClbRun, FinishClb or ExitClb; AcceptClb (no result yet), "
        "StopClbRun (no run to stop, 6.4.2, current firmware), GetDataReq, a new Start2D2TClb and a timer are "
        "ignored (E33)",
        ends=d.CALIBRATION_DECIDING,
    )
    flow(
        "2d2t/run-block-timeout",
        [*setup, cmd("StartClbRun"), TIMEOUT, RUN, *run_full, cmd("FinishClb"), cmd("ExitClb")],
        "E34: no Table 6.16 block within 1 s of StartClbRun abandons it \"to between-runs\" without an answer; the "
        "late block is ignored there and a new StartClbRun with its block runs",
        ends=d.IDLE,
    )
    flow(
        "2d2t/run-block-wrong-size",
        [*setup, cmd("StartClbRun"), CALIBRATION, ALIGNED, *run_full, cmd("FinishClb"), cmd("AcceptClb")],
        "E34: a 22-byte message is not the 6-byte Table 6.16 block: StartClbRun is abandoned to between runs, "
        "nothing aligns",
        ends=d.IDLE,
    )
    flow(
        "2d2t/run-command-instead-of-block",
        [*setup, cmd("StartClbRun"), cmd("FinishClb"), cmd("FinishClb"), cmd("AcceptClb")],
        "E34: FinishClb instead of the Table 6.16 block abandons StartClbRun and is not executed itself; the next "
        "FinishClb finishes (6.4.7)",
        ends=d.IDLE,
    )
    flow(
        "2d2t/run-exit-instead-of-block",
        [*setup, cmd("StartClbRun"), cmd("ExitClb"), RUN],
        "E34: ExitClb instead of the Table 6.16 block is still acknowledged (6.4.4) and goes to idle",
        ends=d.IDLE,
    )
    flow(
        "2d2t/first-block-timeout",
        [cmd("Start2D2TClb"), TIMEOUT, cmd("StartClbRun")],
        "E34: no Table 6.13 block within 1 s of Start2D2TClb: abandoned to idle, where StartClbRun is ignored (E33)",
        ends=d.IDLE,
    )

    # The former StopClb (0x20) of firmware before 4.9.9.0 (6.4.5 note, 6.4.7 important note, E29).
    legacy = [*setup, *run_stopped, *run_full, cmd("StopClbRun"), cmd("AcceptClb")]
    flow(
        "stopclb/4.9.8.0-finishes-2d2t",
        legacy,
        "6.4.5 note and 6.4.7: \"In AHRS firmware before v.4.9.9.0 to finish the 2D-2T calibration the StopClb "
        "command (code 0x20) was used instead of FinishClb\"; with firmware 4.9.8.0 0x20 still stops a run early "
        "(revision 1.5: it did both) and, between runs, finishes the calibration with the Table 6.14 result (E29)",
        firmware="4.9.8.0",
        ends=d.IDLE,
    )
    for firmware, why in ((None, "current firmware"), ("4.9.9.0", "firmware 4.9.9.0, the first with FinishClb"),
                          ("4.10.0.0", "firmware 4.10.0.0 (versions compare part by part as numbers: 4.10 > 4.9)")):
        flow(
            f"stopclb/{firmware or 'current'}-ignored-between-runs",
            [*legacy, cmd("FinishClb"), cmd("AcceptClb")],
            f"6.4.2, 6.4.7, E29: with {why} 0x20 (StopClbRun) only stops a run in progress; between runs it is "
            "ignored (E33) and so is AcceptClb before a result; FinishClb finishes",
            firmware=firmware,
            ends=d.IDLE,
        )
    flow(
        "stopclb/4.9.8.0-finishes-without-runs",
        [*setup, cmd("StopClbRun"), cmd("ExitClb")],
        "6.4.5 note, E29, E37: with firmware 4.9.8.0 StopClb right after the Start2D2TClb block finishes the 2D-2T "
        "calibration like FinishClb, before any run",
        firmware="4.9.8.0",
        ends=d.IDLE,
    )
    flow(
        "stopclb/4.9.8.0-3d-stops-accumulation",
        [cmd("Start3DClb"), CALIBRATION, cmd("StopClbRun"), ALIGNED, cmd("StopClbRun"), cmd("StopClbRun"),
         cmd("AcceptClb")],
        "6.4.1, 6.4.2, E29: with firmware 4.9.8.0 0x20 stops 3D accumulation early as StopClbRun does; before "
        "accumulation and after the result it is ignored (E33)",
        firmware="4.9.8.0",
        ends=d.IDLE,
    )
    flow(
        "stopclb/4.9.8.0-idle-ignored",
        [cmd("StopClbRun"), cmd("FinishClb"), cmd("GetBIT")],
        "E29, E33: with firmware 4.9.8.0 StopClb and FinishClb outside a calibration are ignored",
        firmware="4.9.8.0",
        ends=d.IDLE,
    )
    flow(
        "stopclb/4.9.8.0-finishclb",
        [*setup, *run_full, cmd("FinishClb"), cmd("AcceptClb")],
        "E9: \"the spec does not gate commands by firmware version except StopClb (E29)\": FinishClb (0x2C) finishes a "
        "2D-2T calibration with firmware 4.9.8.0 too (6.4.7 says older firmware used StopClb instead; the decision "
        "is not to refuse FinishClb there)",
        firmware="4.9.8.0",
        ends=d.IDLE,
    )

    # Sleep (6.3.8, 6.3.9, Table 6.19, E35).
    flow(
        "sleep/from-idle",
        [cmd("LowPowerOff"), cmd("LowPowerOn"), cmd("AHRScont1"), cmd("GetDataReq"), cmd("GetBIT"), cmd("ReadAHRSPar"),
         cmd("GetVerFirmware"), cmd("LoadAHRSPar"), LOAD, cmd("Start3DClb"), cmd("ClearClb"), cmd("LowPowerOn"),
         code(0x00), DUE, ALIGNED, ACCUMULATED, TIMEOUT, cmd("LowPowerOff"), cmd("GetVerFirmware")],
        "6.3.9: LowPowerOff in idle is ignored (E33); 6.3.8: LowPowerOn from idle sleeps without an answer (E35); "
        "in Sleep \"its microprocessor only waits command ... to exit from the Sleep mode\" (6.1 (5)): every other "
        "command (0xFE: see flow/0xFE/sleep), data and timer is ignored; LowPowerOff wakes to idle without an answer "
        "(6.3.9), where GetVerFirmware is answered (6.3.10)",
        ends=d.IDLE,
    )
    for start in ("AHRScont2", "NMEAcont"):
        what = "$PAHR sentence (Table 6.7)" if start == "NMEAcont" else "Table 6.5 block"
        flow(
            f"sleep/from-continuous/{start}",
            [cmd(start), ALIGNED, DUE, cmd("LowPowerOn"), DUE, cmd("LowPowerOff"), DUE, cmd("GetBIT")],
            f"Table 6.19: USW bits 7 and 15 are 1 \"in the last data block sent by the AHRS before it went to Sleep "
            f"mode\"; E35: LowPowerOn in continuous mode sends one last {what} with those bits, then sleeps; no "
            "output in Sleep or after waking to idle (6.3.9)",
            ends=d.IDLE,
        )
    flow(
        "sleep/from-on-request",
        [cmd("AHRSreq1"), ALIGNED, cmd("GetDataReq"), cmd("LowPowerOn"), cmd("GetDataReq"), cmd("LowPowerOff"),
         cmd("GetDataReq")],
        "E35: \"from idle and on-request mode it sleeps without a block\"; GetDataReq is ignored in Sleep and in "
        "idle after waking (6.3.4)",
        ends=d.IDLE,
    )
    flow(
        "sleep/during-alignment",
        [cmd("AHRScont1"), cmd("LowPowerOn"), cmd("AHRSreq1"), cmd("LowPowerOn"), ALIGNED, cmd("LowPowerOn")],
        "6.3.1, 6.3.2: the AHRS goes to the Continuous or On Request operating mode after the initial alignment, "
        "so LowPowerOn during the alignment is ignored (E33; E35: valid in idle, continuous and on-request mode); "
        "a start command there is ignored too (6.3.5); after the alignment block LowPowerOn sends the last output "
        "block with the sleep bits set (E35, Table 6.19)",
        ends=d.SLEEP,
    )
    flow(
        "sleep/in-calibration",
        [cmd("Start3DClb"), CALIBRATION, cmd("LowPowerOn"), ALIGNED, cmd("LowPowerOn"), cmd("ExitClb")],
        "E35: LowPowerOn is valid in idle, continuous and on-request mode only: ignored in calibration (E33)",
        ends=d.IDLE,
    )
    flow(
        "sleep/instead-of-block",
        [cmd("LoadAHRSPar"), cmd("LowPowerOn"), cmd("LowPowerOn"), cmd("LowPowerOff")],
        "E34: LowPowerOn instead of the Table 6.9 block abandons LoadAHRSPar and is not executed; the next "
        "LowPowerOn sleeps (6.3.8) and LowPowerOff wakes (6.3.9)",
        ends=d.IDLE,
    )
    return out


def suite_sessions() -> list[Vector]:
    return _single_steps() + _flows()


# --- output --------------------------------------------------------------------------------------

SUITES: list[tuple[str, str, Callable[[], list[Vector]]]] = [
    (
        "appendix-c",
        f"{ICD}, Appendix C Table C.1 (all 26 rows, bytes as printed); spec/README.md (Commands)",
        suite_appendix_c,
    ),
    ("checksum", f"{ICD}, Table 6.2 and 6.3; erratum E28", suite_checksum),
    ("acks", f"{ICD}, sections 6.3.1-6.4.9, Tables 6.9, 6.13, 6.16; errata E5, E6, E12", suite_acks),
    ("payloads", f"{ICD}, Tables 6.4-6.6 and 6.8-6.17; spec/README.md (payload decode and encode)", suite_payloads),
    ("frames", f"{ICD}, Table 6.2; spec/README.md (frame decode, frame encode); errata E6, E17", suite_frames),
    ("streams", "spec/README.md (stream decoder: leftmost valid message)", suite_streams),
    ("nmea", f"{ICD}, Table 6.7; spec/README.md ($PAHR sentences); erratum E16", suite_nmea),
    (
        "sessions",
        f"{ICD}, sections 6, 6.1, 6.3, 6.4, Table 6.19; errata E9, E12-E14, E25, E29, E33-E39; spec/README.md "
        "(the device state machine); expected steps by conformance/tools/device_oracle.py",
        suite_sessions,
    ),
]


def render(suite: str, source: str, vectors: list[Vector]) -> str:
    """One vector per line, so that a diff shows which vectors changed."""
    ids = [v["id"] for v in vectors]
    assert len(ids) == len(set(ids)), [i for i in ids if ids.count(i) > 1]
    lines = [json.dumps(v, ensure_ascii=True, allow_nan=False) for v in vectors]
    head = f'{{"suite": {json.dumps(suite)}, "source": {json.dumps(source)}, "vectors": [\n'
    return head + ",\n".join(lines) + "\n]}\n"


def build_all() -> dict[str, str]:
    """File name -> text, for every suite."""
    return {f"{name}.json": render(name, source, fn()) for name, source, fn in SUITES}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=VECTORS_DIR, help="where to write (default: conformance/vectors)")
    parser.add_argument("--check", action="store_true", help="compare with the files in --out instead of writing")
    args = parser.parse_args(argv)
    files = build_all()
    if args.check:
        stale = [
            name
            for name, text in files.items()
            if not (args.out / name).is_file() or (args.out / name).read_text(encoding="utf-8") != text
        ]
        extra = sorted(p.name for p in args.out.glob("*.json") if p.name not in files)
        for name in stale:
            print(f"{args.out / name}: differs from what {Path(__file__).name} writes", file=sys.stderr)
        for name in extra:
            print(f"{args.out / name}: not written by {Path(__file__).name}", file=sys.stderr)
        return 1 if stale or extra else 0
    args.out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (args.out / name).write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
