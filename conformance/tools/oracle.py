"""An independent model of the AHRS protocol, written from the ICD tables, for computing vectors.

It deliberately shares nothing with the generator or any binding: its own checksum, its own
payload layouts (with the ICD byte numbers asserted), its own $PAHR grammar and its own
stream scan. Where the ICD is silent or wrong it follows the errata of spec/ilahrs.yaml (named
by id) and the semantics of spec/README.md. Standard library only.
"""

from __future__ import annotations

import math
import re
import struct
from dataclasses import dataclass

# --- Table 6.2 / 6.3: the frame ---------------------------------------------------------------

HEADER = b"\xaa\x55"
HEAD_SIZE = 6  # header, message type, reserved, message length
MIN_LENGTH = 7  # E17: a one-byte command
MAX_LENGTH = 58  # E17: a 52-byte payload (Tables 6.14, 6.17)
MIN_PAYLOAD = MIN_LENGTH - 6
MAX_PAYLOAD = MAX_LENGTH - 6
COMMAND = 0
DATA = 1
DEVICE_RESERVED = 0  # E42: the reserved byte this AHRS writes in its data frames
# E41: a message never spans an idle line; 1152 byte times at 115200 baud, 10 bits a byte (8N1).
IDLE_US = 1152 * 10 * 1_000_000 // 115200


class OracleError(Exception):
    """A refusal: error kind (spec `errors`), byte offset or None, field name or None."""

    def __init__(self, kind: str, offset: int | None = None, field: str | None = None) -> None:
        super().__init__(f"{kind} at {offset} ({field})")
        self.kind = kind
        self.offset = offset
        self.field = field

    def expect(self) -> dict[str, object]:
        out: dict[str, object] = {"error": self.kind}
        if self.offset is not None:
            out["offset"] = self.offset
        if self.field is not None:
            out["field"] = self.field
        return out


def checksum(data: bytes) -> int:
    """Table 6.2: the arithmetic sum of the bytes, modulo 2^16 (E28)."""
    total = 0
    for byte in data:
        total = (total + byte) & 0xFFFF
    return total


def frame(message_type: int, payload: bytes, reserved: int = 0) -> bytes:
    """Table 6.2: AA 55, type, reserved, length (type through checksum), payload, checksum."""
    if message_type not in (COMMAND, DATA):
        raise OracleError("bad_message_type", None, "message_type")
    if not 0 <= reserved <= 0xFF:
        raise OracleError("out_of_range", None, "reserved")
    if not MIN_PAYLOAD <= len(payload) <= MAX_PAYLOAD:
        raise OracleError("bad_length", None, "payload")
    body = bytes([message_type, reserved]) + struct.pack("<H", len(payload) + 6) + payload
    return HEADER + body + struct.pack("<H", checksum(body))


def decode_frame(data: bytes, strict: bool = False) -> tuple[int, int, bytes]:
    """One whole frame, checks in the order of spec/README.md; returns (type, reserved, payload).
    Strict (E42): after every other check, a data frame's reserved byte must be DEVICE_RESERVED."""
    if len(data) < 1:
        raise OracleError("truncated", 0)
    if data[0] != HEADER[0]:
        raise OracleError("bad_header", 0, "header")
    if len(data) < 2:
        raise OracleError("truncated", 1)
    if data[1] != HEADER[1]:
        raise OracleError("bad_header", 1, "header")
    if len(data) < HEAD_SIZE:
        raise OracleError("truncated", len(data))
    if data[2] not in (COMMAND, DATA):
        raise OracleError("bad_message_type", 2, "message_type")
    length = struct.unpack_from("<H", data, 4)[0]
    if not MIN_LENGTH <= length <= MAX_LENGTH:
        raise OracleError("bad_length", 4, "message_length")
    if len(data) < length + 2:
        raise OracleError("truncated", len(data))
    if checksum(data[2:length]) != struct.unpack_from("<H", data, length)[0]:
        raise OracleError("bad_checksum", length, "checksum")
    if len(data) > length + 2:
        raise OracleError("trailing_data", length + 2)
    if strict and data[2] == DATA and data[3] != DEVICE_RESERVED:
        raise OracleError("bad_reserved", 3, "reserved")
    return data[2], data[3], data[HEAD_SIZE:length]


def ack(message: bytes) -> bytes:
    """E12: a data frame whose payload is the received message's checksum, low byte first."""
    decode_frame(message)
    length = struct.unpack_from("<H", message, 4)[0]
    return frame(DATA, struct.pack("<H", checksum(message[2:length])))


# --- Appendix C, Table C.1, copied from the ICD -------------------------------------------------

TABLE_C1 = """\
AHRScont1 0x80 AA 55 00 00 07 00 80 87 00
AHRScont2 0x82 AA 55 00 00 07 00 82 89 00
AHRScont3 0x83 AA 55 00 00 07 00 83 8A 00
AHRSreq1 0x84 AA 55 00 00 07 00 84 8B 00
AHRSreq2 0x86 AA 55 00 00 07 00 86 8D 00
AHRSreq3 0x87 AA 55 00 00 07 00 87 8E 00
NMEAcont 0x88 AA 55 00 00 07 00 88 8F 00
NMEAreq 0x89 AA 55 00 00 07 00 89 90 00
GetDataReq 0xCA AA 55 00 00 07 00 CA D1 00
Stop 0xFE AA 55 00 00 07 00 FE 05 01
LoadAHRSPar 0x40 AA 55 00 00 07 00 40 47 00
ReadAHRSPar 0x41 AA 55 00 00 07 00 41 48 00
LowPowerOn 0xB0 AA 55 00 00 07 00 B0 B7 00
LowPowerOff 0xBA AA 55 00 00 07 00 BA C1 00
GetVerFirmware 0x1F AA 55 00 00 07 00 1F 26 00
GetBIT 0x1A AA 55 00 00 07 00 1A 21 00
Start2DClb 0x21 AA 55 00 00 07 00 21 28 00
Start2D2TClb 0x22 AA 55 00 00 07 00 22 29 00
Start3DClb 0x23 AA 55 00 00 07 00 23 2A 00
StartClbRun 0x2B AA 55 00 00 07 00 2B 32 00
StopClbRun 0x20 AA 55 00 00 07 00 20 27 00
FinishClb 0x2C AA 55 00 00 07 00 2C 33 00
AcceptClb 0x2E AA 55 00 00 07 00 2E 35 00
ExitClb 0xFE AA 55 00 00 07 00 FE 05 01
ClearClb 0x2F AA 55 00 00 07 00 2F 36 00
GetClbRes 0x2A AA 55 00 00 07 00 2A 31 00
"""


@dataclass(frozen=True)
class CommandRow:
    name: str
    code: int
    icd_hex: str  # the exact structure, as printed in Table C.1


def table_c1() -> list[CommandRow]:
    rows = []
    for line in TABLE_C1.splitlines():
        name, code, structure = line.split(" ", 2)
        row = CommandRow(name, int(code, 16), structure)
        # The ICD's bytes must be what the Table 6.2 rules give; if not, the oracle is wrong.
        assert frame(COMMAND, bytes([row.code])) == bytes.fromhex(structure), row
        rows.append(row)
    assert len(rows) == 26
    return rows


def command_names(code: int) -> list[str]:
    return sorted(row.name for row in table_c1() if row.code == code)


# --- Payload tables (Tables 6.4-6.17), with the ICD byte numbers ---------------------------------

F32_MAX = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]

VARIANTS: dict[str, dict[str, int]] = {
    # Table 6.6 note 1, and E11 for g300_a2_tga
    "g300_a2_tmga": {"KG": 100, "KA": 10000},
    "g300_a6_tmga": {"KG": 100, "KA": 5000},
    "sn_11ac0001_0009": {"KG": 50, "KA": 10000},
    "g300_a2_tga": {"KG": 100, "KA": 10000},
}

Raw = int | float | str  # char: text; reserved: hex digits

INT_TYPES = {"u8": ("<B", 0, 0xFF), "u16": ("<H", 0, 0xFFFF), "s16": ("<h", -0x8000, 0x7FFF)}


@dataclass(frozen=True)
class Field:
    name: str
    type: str  # u8 u16 s16 f32 char reserved
    icd_offset: int  # the first byte number printed in the ICD table (after the errata)
    length: int = 0  # char and reserved
    lo: float | None = None
    hi: float | None = None
    default: float | None = None
    multiplier: int = 1
    divisor: int | str = 1  # or a variant parameter
    rule: str = ""  # "declination" (Table 6.9, encodings.declination)

    @property
    def size(self) -> int:
        return self.length if self.type in ("char", "reserved") else {"u8": 1, "u16": 2, "s16": 2, "f32": 4}[self.type]

    @property
    def default_value(self) -> Raw:
        """What builders use for a field not given: its default, else 0 (zeros, empty text) when
        the range allows it, else the lowest value of the range."""
        if self.type == "char":
            return ""
        if self.type == "reserved":
            return "00" * self.size
        value: float = self.default if self.default is not None else 0
        if self.default is None and self.lo is not None and self.hi is not None and not self.lo <= 0 <= self.hi:
            value = self.lo
        return float(value) if self.type == "f32" else int(value)

    @property
    def scaled(self) -> bool:
        return self.multiplier != 1 or self.divisor != 1


def _angles(offset: int) -> list[Field]:
    return [
        Field("heading", "u16", offset, lo=0, hi=35999, divisor=100),  # E23
        Field("pitch", "s16", offset + 2, lo=-9000, hi=9000, divisor=100),
        Field("roll", "s16", offset + 4, lo=-18000, hi=18000, divisor=100),
    ]


def _tail(offset: int, vdd_divisor: int, utermo_divisor: int) -> list[Field]:
    return [
        Field("usw", "u16", offset),
        Field("vdd", "u16", offset + 2, divisor=vdd_divisor),
        Field("utermo", "s16", offset + 4, divisor=utermo_divisor),
    ]


def _xyz(prefix: str, type_: str, offset: int, step: int, **kw: object) -> list[Field]:
    return [Field(f"{prefix}{axis}", type_, offset + i * step, **kw) for i, axis in enumerate("xyz")]  # type: ignore[arg-type]


def f32_toward(value: float, upward: bool) -> float:
    """The nearest float32 at or beyond `value` in the given direction."""
    rounded: float = struct.unpack("<f", struct.pack("<f", value))[0]
    if (upward and rounded < value) or (not upward and rounded > value):
        bits: int = struct.unpack("<i", struct.pack("<f", rounded))[0]
        bits += 1 if (rounded >= 0) == upward else -1
        rounded = struct.unpack("<f", struct.pack("<i", bits))[0]
    return rounded


# encodings.date: year_range [1900, 2199]; Year + (Month - 1)/12 + Day/365 (E15). A raw date float
# lies between the encodings of the first real date, 1900-01-01, and the last, 2199-12-31 (above
# 2200.0 because Day/365 overlaps the next year, E15), widened outward to float32 values
# (spec/README.md, payload encode).
DATE_MIN = f32_toward(1900 + (1 - 1) / 12 + 1 / 365, upward=False)
DATE_MAX = f32_toward(2199 + (12 - 1) / 12 + 31 / 365, upward=True)


def _location(offset: int) -> list[Field]:
    return [
        Field("latitude", "f32", offset, lo=-90, hi=90),
        Field("longitude", "f32", offset + 4, lo=-180, hi=180),
        Field("altitude", "f32", offset + 8, lo=-20000, hi=100000),  # E31
        Field("date", "f32", offset + 12, lo=DATE_MIN, hi=DATE_MAX),  # E15
    ]


def _parameters(update_default: float | None, alignment_default: float | None) -> list[Field]:
    return [
        Field("update_rate", "u16", 0, lo=1, hi=100, default=update_default),  # E22, E24
        Field("alignment_time", "u16", 2, lo=1, hi=65535, default=alignment_default),  # E30
        Field("declination", "f32", 4, rule="declination"),
        *_location(8),
        Field("alignment_angle_a1", "f32", 24, lo=-360, hi=360),  # E31
        Field("alignment_angle_a2", "f32", 28, lo=-360, hi=360),
        Field("alignment_angle_a3", "f32", 32, lo=-360, hi=360),
    ]


def _matrices() -> list[Field]:
    soft = [Field(f"tm_c_{r}{c}", "f32", 4 + 4 * (3 * (r - 1) + c - 1)) for r in (1, 2, 3) for c in (1, 2, 3)]
    return [*soft, *_xyz("hm_0_", "f32", 40, 4)]  # E1, E2: bytes 40-51


# Laid out as the ICD prints the tables, fields in byte order (kept out of the formatter).
# fmt: off
TABLES: dict[str, tuple[str, int, list[Field]]] = {
    "full_output": ("Table 6.4", 34, [
        *_angles(0),
        *_xyz("ugyro_", "s16", 6, 2), *_xyz("uacc_", "s16", 12, 2), *_xyz("umag_", "s16", 18, 2),
        Field("reserved", "reserved", 24, length=4),
        *_tail(28, 1000, 1),
    ]),
    "quaternion": ("Table 6.5", 34, [
        *_angles(0),
        *[Field(f"lk{i}", "s16", 6 + 2 * i, lo=-10000, hi=10000, divisor=10000) for i in range(4)],
        Field("reserved", "reserved", 14, length=14),
        *_tail(28, 1000, 10),
    ]),
    "orientation_sensors": ("Table 6.6", 34, [
        *_angles(0),
        *_xyz("gyro_", "s16", 6, 2, divisor="KG"), *_xyz("acc_", "s16", 12, 2, divisor="KA"),
        *_xyz("mag_", "s16", 18, 2, multiplier=10),
        Field("reserved", "reserved", 24, length=4),
        *_tail(28, 1000, 10),
    ]),
    "initial_alignment": ("Table 6.8", 50, [
        *_xyz("gyro_bias_", "f32", 0, 4), *_xyz("average_acc_", "f32", 12, 4), *_xyz("average_mag_", "f32", 24, 4),
        Field("initial_heading", "f32", 36, lo=0, hi=360),  # E21: heading, roll, pitch
        Field("initial_roll", "f32", 40, lo=-180, hi=180),
        Field("initial_pitch", "f32", 44, lo=-90, hi=90),
        Field("usw", "u16", 48),  # E27
    ]),
    "ahrs_parameters_load": ("Table 6.9", 50, [
        *_parameters(100, 30),
        Field("reserved", "reserved", 36, length=14),
    ]),
    "ahrs_parameters_read": ("Table 6.10", 50, [
        *_parameters(None, None),
        Field("device_id", "char", 36, length=8),
        Field("reserved", "reserved", 44, length=6),
    ]),
    "firmware_version": ("Table 6.11", 50, [Field("version", "char", 0, length=50)]),
    "bit_result": ("Table 6.12", 4, [
        Field("utermo100", "s16", 0, divisor=100),  # E4: signed
        Field("usw", "u16", 2),
    ]),
    "calibration_parameters": ("Table 6.13", 22, [
        Field("reference_azimuth", "f32", 0, lo=-360, hi=360, default=0),  # E8
        Field("accumulation_time", "u16", 4, lo=1, hi=65535),  # E30
        *_location(6),
    ]),
    "calibration_result": ("Table 6.14", 52, [
        Field("calibration_type", "u8", 0, lo=1, hi=3),
        Field("runs_used", "u8", 1),
        Field("data_used", "u8", 2, lo=0, hi=100),
        Field("success", "u8", 3),  # E26
        *_matrices(),
    ]),
    "calibration_run_result": ("Table 6.15", 30, [
        Field("calibration_type", "u8", 0, lo=2, hi=2),
        Field("run", "u8", 1, lo=1, hi=255),
        Field("data_used", "u8", 2, lo=0, hi=100),
        Field("success", "u8", 3),
        Field("reserved_1", "reserved", 4, length=4),  # E32
        Field("average_pitch", "f32", 8, lo=-90, hi=90),
        Field("average_roll", "f32", 12, lo=-180, hi=180),
        Field("reserved_2", "reserved", 16, length=12),  # E32
        Field("usw", "u16", 28),
    ]),
    "calibration_run_parameters": ("Table 6.16", 6, [Field("reserved", "reserved", 0, length=6)]),  # E32
    "calibration_status": ("Table 6.17", 52, [
        Field("calibration_type", "u8", 0),
        Field("runs_used", "u8", 1),
        Field("reserved", "reserved", 2, length=1),  # E3
        Field("success", "u8", 3),
        *_matrices(),
    ]),
    "acknowledgement": ("6.3.1 (Table 6.2, one-word payload)", 2, [Field("checksum", "u16", 0)]),
}
# fmt: on


def _check_tables() -> None:
    for name, (_, size, fields) in TABLES.items():
        offset = 0
        for f in fields:
            assert f.icd_offset == offset, (name, f.name, f.icd_offset, offset)
            offset += f.size
        assert offset == size, (name, offset, size)


_check_tables()


def decode_payload(table: str, data: bytes) -> dict[str, Raw]:
    _, size, fields = TABLES[table]
    if len(data) < size:
        raise OracleError("truncated", len(data))
    if len(data) > size:
        raise OracleError("trailing_data", size)
    out: dict[str, Raw] = {}
    offset = 0
    for f in fields:
        chunk = data[offset : offset + f.size]
        if f.type == "f32":
            out[f.name] = struct.unpack("<f", chunk)[0]
        elif f.type == "char":
            out[f.name] = chunk.rstrip(b"\x00").decode("latin-1")
        elif f.type == "reserved":
            out[f.name] = chunk.hex()
        else:
            out[f.name] = struct.unpack(INT_TYPES[f.type][0], chunk)[0]
        offset += f.size
    return out


def engineering(table: str, raw: dict[str, Raw], variant: str | None) -> dict[str, float]:
    """Scaled fields: raw x multiplier / divisor; variant-scaled ones only with a variant."""
    out: dict[str, float] = {}
    for f in TABLES[table][2]:
        if not f.scaled:
            continue
        if isinstance(f.divisor, str):
            if variant is None:
                continue
            divisor = VARIANTS[variant][f.divisor]
        else:
            divisor = f.divisor
        value = raw[f.name]
        assert isinstance(value, int)
        out[f.name] = value * f.multiplier / divisor
    return out


def encode_payload(table: str, values: dict[str, Raw]) -> bytes:
    _, _, fields = TABLES[table]
    out = b""
    offset = 0
    for f in fields:
        given = values.get(f.name)
        out += _encode_field(f, f.default_value if given is None else given, offset)
        offset += f.size
    return out


def _encode_field(f: Field, value: Raw, offset: int) -> bytes:
    def refuse() -> OracleError:
        return OracleError("out_of_range", offset, f.name)

    if f.type == "char":
        assert isinstance(value, str)
        data = value.encode("latin-1")
        if len(data) > f.length:
            raise refuse()
        return data.ljust(f.length, b"\x00")
    if f.type == "reserved":
        assert isinstance(value, str)
        data = bytes.fromhex(value)
        if len(data) != f.length:
            raise refuse()
        return data
    if f.type == "f32":
        number = float(value)
        if not math.isfinite(number) or abs(number) > F32_MAX:
            raise refuse()
        if f.rule == "declination":
            if not (-180 <= number <= 180 or number > 360):
                raise refuse()
        elif f.lo is not None and f.hi is not None and not f.lo <= number <= f.hi:
            raise refuse()
        return struct.pack("<f", number)
    assert isinstance(value, int)
    fmt, lo, hi = INT_TYPES[f.type]
    lo = int(f.lo) if f.lo is not None else lo
    hi = int(f.hi) if f.hi is not None else hi
    if not lo <= value <= hi:
        raise refuse()
    return struct.pack(fmt, value)


def f32(value: float) -> float:
    """The float32 nearest to value, as a Python float."""
    return float(struct.unpack("<f", struct.pack("<f", value))[0])


# --- Table 6.7: the $PAHR sentence ----------------------------------------------------------------

MAX_SENTENCE = 82  # E16


@dataclass(frozen=True)
class NmeaField:
    name: str
    width: int  # integer digits of the template, the sign counting as one (E16)
    decimals: int  # 0 for the hex USW
    lo: int
    hi: int


NMEA_FIELDS = [
    NmeaField("roll", 4, 2, -18000, 18000),  # RRRR.rr
    NmeaField("pitch", 3, 2, -9000, 9000),  # PPP.pp
    NmeaField("heading", 3, 2, 0, 35999),  # HHH.hh, E23
    NmeaField("temperature", 3, 1, -999, 9999),  # TTT.t
    NmeaField("vdd", 1, 2, 0, 999),  # V.vv
    NmeaField("usw", 4, 0, 0, 0xFFFF),  # SSSS, hex
]


def nmea_xor(text: bytes) -> int:
    value = 0
    for byte in text:
        value ^= byte
    return value


def format_field(f: NmeaField, value: int) -> str:
    if f.decimals == 0:
        return f"{value:04X}"
    sign = "-" if value < 0 else ""
    whole, frac = divmod(abs(value), 10**f.decimals)
    return f"{sign}{str(whole).zfill(f.width - len(sign))}.{str(frac).zfill(f.decimals)}"


def build_sentence(values: dict[str, int]) -> str:
    """Table 6.7 with the E16 formatting; values are the scaled integers."""
    for f in NMEA_FIELDS:
        if not f.lo <= values[f.name] <= f.hi:
            raise OracleError("out_of_range", None, f.name)
    body = "PAHR," + ",".join(format_field(f, values[f.name]) for f in NMEA_FIELDS)
    return f"${body}*{nmea_xor(body.encode()):02X}\r\n"


def sentence(body: str, cs: str | None = None) -> str:
    """'$' + body + '*' + checksum (computed unless given) + CR LF."""
    if cs is None:
        cs = f"{nmea_xor(body.encode('latin-1')):02X}"
    return f"${body}*{cs}\r\n"


_DECIMAL = {d: re.compile(rb"(-?)([0-9]+)(?:\.([0-9]{1,%d}))?" % d) for d in (1, 2)}
_HEX = re.compile(rb"[0-9A-Fa-f]{1,4}")
_HEXDIGITS = b"0123456789ABCDEFabcdef"


def decode_sentence(data: bytes) -> dict[str, int]:
    """The checks of spec/README.md ($PAHR sentences), in order; returns the scaled integers."""
    star = _sentence_frame(data)
    parts = data[6:star].split(b",")
    if len(parts) != len(NMEA_FIELDS):
        raise OracleError("malformed")
    out: dict[str, int] = {}
    for f, text in zip(NMEA_FIELDS, parts, strict=True):
        value = _sentence_field(f, text)
        if not f.lo <= value <= f.hi:
            raise OracleError("out_of_range", None, f.name)
        out[f.name] = value
    return out


def _sentence_frame(data: bytes) -> int:
    """Header, end, length and checksum of a sentence, in that order; returns the index of the *."""
    if data[:1] != b"$":
        raise OracleError("bad_header", 0)
    if data[1:6] != b"PAHR,":
        raise OracleError("bad_header", 1)
    crlf = data.find(b"\r\n")
    if crlf < 0:
        if len(data) > MAX_SENTENCE:
            raise OracleError("bad_length", MAX_SENTENCE)
        raise OracleError("truncated", len(data))
    end = crlf + 2
    if end > MAX_SENTENCE:
        raise OracleError("bad_length", MAX_SENTENCE)
    if end < len(data):
        raise OracleError("trailing_data", end)
    star = crlf - 3
    if star < 6 or data[star] != ord("*") or any(b not in _HEXDIGITS for b in data[star + 1 : crlf]):
        raise OracleError("malformed")
    if nmea_xor(data[1:star]) != int(data[star + 1 : crlf], 16):
        raise OracleError("bad_checksum", star + 1)
    return star


def _sentence_field(f: NmeaField, text: bytes) -> int:
    """One field's text as its scaled integer, by the E16 grammar (the range is checked by the caller)."""
    if f.decimals == 0:
        if not _HEX.fullmatch(text):
            raise OracleError("malformed", None, f.name)
        return int(text, 16)
    m = _DECIMAL[f.decimals].fullmatch(text)
    if m is None:
        raise OracleError("malformed", None, f.name)
    frac = (m.group(3) or b"").ljust(f.decimals, b"0")
    value: int = int(m.group(2)) * 10**f.decimals + int(frac)
    return -value if m.group(1) else value


def sentence_values(raw: dict[str, int]) -> dict[str, float | int]:
    """Engineering values of a decoded sentence (degrees, degrees Celsius, volts; USW as is)."""
    return {f.name: raw[f.name] if f.decimals == 0 else raw[f.name] / 10**f.decimals for f in NMEA_FIELDS}


# --- The stream decoder: leftmost valid message (spec/README.md) ---------------------------------


def scan_segments(segments: list[bytes], strict: bool = False) -> tuple[list[tuple[str, bytes]], int]:
    """`scan` of input cut by idle lines (E41): no message spans an idle gap, so each segment
    between two gaps is scanned on its own, as if the input ended there."""
    events: list[tuple[str, bytes]] = []
    discarded = 0
    for segment in segments:
        more, count = scan(segment, strict)
        events += more
        discarded += count
    return events, discarded


def scan(data: bytes, strict: bool = False) -> tuple[list[tuple[str, bytes]], int]:
    """Events ("frame" | "nmea", bytes) and the discarded count, for the whole input at once.

    Chunking never changes the result, so the whole input is looked at in one piece; a candidate
    that would need bytes beyond the end is discarded one byte at a time, as `finish` does.
    Strict: data frames whose reserved byte is not DEVICE_RESERVED are not messages (E42).
    """
    events: list[tuple[str, bytes]] = []
    discarded = 0
    pos = 0
    while pos < len(data):
        first = data[pos]
        size = _frame_at(data, pos, strict) if first == HEADER[0] else _sentence_at(data, pos) if first == 0x24 else 0
        if size:
            events.append(("frame" if data[pos] == HEADER[0] else "nmea", data[pos : pos + size]))
            pos += size
        else:
            discarded += 1
            pos += 1
    return events, discarded


def _frame_at(data: bytes, pos: int, strict: bool) -> int:
    if len(data) - pos < HEAD_SIZE:
        return 0
    length: int = struct.unpack_from("<H", data, pos + 4)[0]
    try:
        decode_frame(data[pos : pos + length + 2], strict)
    except OracleError:
        return 0
    return length + 2


def _sentence_at(data: bytes, pos: int) -> int:
    window = data[pos : pos + MAX_SENTENCE]
    lf = window.find(b"\n")
    if lf < 0:
        return 0
    try:
        decode_sentence(window[: lf + 1])
    except OracleError:
        return 0
    return lf + 1
