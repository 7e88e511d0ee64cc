# Copied from generator/targets/python/runtime/conformance/protocol.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The runner protocol: a vector as a request line, an answer line as tokens."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from .vectors import (
    SPECIAL_FLOATS,
    SuiteError,
    Vector,
    int_value,
    latin1,
    name_token,
    parse_hex,
    session,
)

__all__ = [
    "Answer",
    "hex_token",
    "keyed",
    "num_token",
    "parse_answer",
    "read_hex_token",
    "read_text_token",
    "request",
    "text_token",
    "value_token",
]

_HEX_RE = re.compile(r"(?:[0-9A-Fa-f]{2})*")


def hex_token(data: bytes) -> str:
    return data.hex().upper() if data else "-"


def read_hex_token(token: str) -> bytes | None:
    if token == "-":
        return b""
    if not _HEX_RE.fullmatch(token):
        return None
    return bytes.fromhex(token)


def text_token(data: bytes) -> str:
    """Percent-encoding: bytes outside 0x21..0x7E, and % , =, as %XX."""
    return "".join(chr(b) if 0x21 <= b <= 0x7E and b not in b"%,=" else f"%{b:02X}" for b in data)


def read_text_token(token: str) -> bytes | None:
    out = bytearray()
    i = 0
    while i < len(token):
        if token[i] == "%":
            pair = token[i + 1 : i + 3]
            if len(pair) != 2 or not _HEX_RE.fullmatch(pair):
                return None
            out.append(int(pair, 16))
            i += 3
        else:
            if ord(token[i]) > 0xFF:
                return None
            out.append(ord(token[i]))
            i += 1
    return bytes(out)


def num_token(value: object, where: str) -> str:
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise SuiteError(f"{where}: not a number: {value!r}")
    if isinstance(value, str):
        if value not in SPECIAL_FLOATS:
            raise SuiteError(f"{where}: not a number: {value!r}")
        return value
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    return repr(value)


def value_token(value: object, where: str) -> str:
    """A payload field value: INT, NUM, or a string sent as TEXT (char text, reserved hex, nan/inf)."""
    if isinstance(value, str):
        return text_token(latin1(value, where))
    return num_token(value, where)


def _object(i: object, w: str) -> dict[str, Any]:
    if not isinstance(i, dict):
        raise SuiteError(f"{w}: input must be an object")
    return i


def _hex_request(kind: str, i: object, w: str) -> str:
    return f"{kind} {hex_token(parse_hex(i, w))}"


def _frame_encode(i: object, w: str) -> str:
    i = _object(i, w)
    line = f"frame_encode {int_value(i.get('message_type'), w)} {hex_token(parse_hex(i.get('payload', ''), w))}"
    return line + (f" {int_value(i['reserved'], w)}" if "reserved" in i else "")


def _command_encode(i: object, w: str) -> str:
    return f"command_encode {name_token(_object(i, w).get('command'), w)}"


def _payload_decode(i: object, w: str) -> str:
    i = _object(i, w)
    line = f"payload_decode {name_token(i.get('type'), w)} {hex_token(parse_hex(i.get('hex', ''), w))}"
    return line + (f" {name_token(i['variant'], w)}" if "variant" in i else "")


def _payload_encode(i: object, w: str) -> str:
    i = _object(i, w)
    fields = i.get("fields", {})
    if not isinstance(fields, dict):
        raise SuiteError(f"{w}: fields must be an object")
    parts = [f"{name_token(k, w)}={value_token(x, w)}" for k, x in fields.items()]
    variant = name_token(i["variant"], w) if "variant" in i else "-"
    return " ".join(["payload_encode", name_token(i.get("type"), w), variant, *parts])


def _nmea_decode(i: object, w: str) -> str:
    if not isinstance(i, str):
        raise SuiteError(f"{w}: input must be the sentence as a string")
    return f"nmea_decode {text_token(latin1(i, w))}"


def _nmea_encode(i: object, w: str) -> str:
    parts = [f"{name_token(k, w)}={num_token(x, w)}" for k, x in _object(i, w).items()]
    return " ".join(["nmea_encode", *parts])


def _stream(i: object, w: str) -> str:
    i = _object(i, w)
    chunks = i.get("chunks")
    if not isinstance(chunks, list) or not chunks:
        raise SuiteError(f"{w}: chunks must be a non-empty list of hex strings")
    line = "stream " + ",".join(hex_token(parse_hex(c, w)) for c in chunks)
    if "idle" in i:
        line += " " + _idle_token(i["idle"], len(chunks), w)
    return line


def _idle_token(gaps: object, chunks: int, w: str) -> str:
    """`idle=AFTER:US,...`: after chunk AFTER (from 0) the line is quiet for US microseconds (E41)."""
    if not isinstance(gaps, list) or not gaps:
        raise SuiteError(f'{w}: idle must be a non-empty list of {{"after": i, "us": n}}')
    parts = []
    for gap in gaps:
        if not isinstance(gap, dict) or set(gap) != {"after", "us"}:
            raise SuiteError(f'{w}: an idle gap is {{"after": i, "us": n}}')
        after, us = int_value(gap["after"], w), int_value(gap["us"], w)
        if not 0 <= after < chunks or us < 0:
            raise SuiteError(f"{w}: idle after chunk {after} of {chunks}, {us} us")
        parts.append(f"{after}:{us}")
    return "idle=" + ",".join(parts)


def _session(i: object, w: str) -> str:
    checked = session(i, w)
    return f"session {checked.firmware or '-'} " + ",".join(event.token for event in checked.events)


_REQUESTS: dict[str, Callable[[object, str], str]] = {
    "checksum": lambda i, w: _hex_request("checksum", i, w),
    "frame_decode": lambda i, w: _hex_request("frame_decode", i, w),
    "command_decode": lambda i, w: _hex_request("command_decode", i, w),
    "ack": lambda i, w: _hex_request("ack", i, w),
    "frame_encode": _frame_encode,
    "command_encode": _command_encode,
    "payload_decode": _payload_decode,
    "payload_encode": _payload_encode,
    "nmea_decode": _nmea_decode,
    "nmea_encode": _nmea_encode,
    "stream": _stream,
    "session": _session,
}


def request(v: Vector) -> str:
    """The request line for a vector (the runner protocol, requests), its options last. Options
    this harness does not know are left out: such a vector must fail (`Vector.unknown_options`)."""
    translate = _REQUESTS.get(v.kind)
    if translate is None:
        raise SuiteError(f"{v.where}: unknown kind {v.kind!r}")
    line = translate(v.input, v.where)
    for name, value in v.options.items():
        if not isinstance(value, bool):
            raise SuiteError(f"{v.where}: option {name} must be true or false")
        if value and name not in v.unknown_options:
            line += f" {name}"
    return line


@dataclass
class Answer:
    status: str  # ok, error, unsupported, invalid
    tokens: list[str]
    line: str


def parse_answer(line: str) -> Answer:
    tokens = line.split(" ")
    if tokens[0] == "ok":
        return Answer("ok", tokens[1:], line)
    if tokens[0] == "error" and len(tokens) == 4:
        return Answer("error", tokens[1:], line)
    if line == "unsupported":
        return Answer("unsupported", [], line)
    return Answer("invalid", tokens, line)


def keyed(tokens: list[str]) -> dict[str, str] | None:
    out: dict[str, str] = {}
    for token in tokens:
        key, sep, value = token.partition("=")
        if not sep or key in out:
            return None
        out[key] = value
    return out
