# Copied from generator/targets/python/runtime/conformance/__init__.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""The conformance suite: run the vectors against a runner and compare its answers.

    ilahrs conformance --command "./my_runner"                  # every vector shipped with the package
    ilahrs conformance --command "./my_runner" --kinds checksum,frame_decode --junit report.xml
    ilahrs conformance --bindings-dir conformance/bindings      # runners registered as NAME.json
    ilahrs conformance --device /dev/ttyUSB0                    # a device, live (ilahrs.conformance.live)

The suites (`vectors/*.json` in this package, the same files as the repository's
conformance/vectors) hold every request and expectation; a runner only turns request lines into
answer lines (the runner protocol of the package README). Each runner is started once and fed
every vector. Standard library only. Exit status: 0 when nothing failed, 1 when something failed,
2 when the suites or the registrations cannot be read.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import queue
import re
import shlex
import shutil
import struct
import subprocess
import sys
import threading
import time
from collections import deque
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any
from xml.etree import ElementTree

__all__ = [
    "KINDS",
    "OPTIONS",
    "VECTORS_DIR",
    "Answer",
    "Binding",
    "BindingError",
    "Case",
    "Result",
    "Suite",
    "SuiteError",
    "Vector",
    "add_arguments",
    "compare",
    "junit_xml",
    "load_bindings",
    "load_suites",
    "main",
    "parse_answer",
    "request",
    "run",
]

VECTORS_DIR = Path(__file__).resolve().parent.parent / "vectors"
"""The suites shipped with the package."""
KINDS = (
    "checksum",
    "frame_decode",
    "frame_encode",
    "command_encode",
    "command_decode",
    "ack",
    "payload_decode",
    "payload_encode",
    "nmea_decode",
    "nmea_encode",
    "stream",
    "session",
)
LATER_KINDS: tuple[str, ...] = ()  # kinds of the format this harness does not translate yet
OPTIONS: dict[str, tuple[str, ...]] = {"strict": ("frame_decode", "stream")}
"""The vector options this harness sends (`"options"` of a vector), and the kinds each applies to.
A vector with an option not listed here fails: it is never sent without it."""
_VERSION_RE = re.compile(r"[0-9]+(?:\.[0-9]+)*")
SPECIAL_FLOATS = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}
REL_TOL = 1e-9  # engineering values and NMEA numbers
ABS_TOL = 1e-12
_HEX_RE = re.compile(r"(?:[0-9A-Fa-f]{2})*")
_NAME_RE = re.compile(r"[^\s=,%]+")
_INT_RE = re.compile(r"-?[0-9]+")


class SuiteError(Exception):
    """A suite file that does not follow the vector format."""


class BindingError(Exception):
    """A binding registration that cannot be used."""


# --- the token forms of the runner protocol -------------------------------------------------------


def parse_hex(text: object, where: str) -> bytes:
    """Vector hex: two hex digits per byte, either case, spaces allowed."""
    if not isinstance(text, str) or not _HEX_RE.fullmatch(text.replace(" ", "")):
        raise SuiteError(f"{where}: not a hex string: {text!r}")
    return bytes.fromhex(text.replace(" ", ""))


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


def latin1(text: str, where: str) -> bytes:
    try:
        return text.encode("latin-1")
    except UnicodeEncodeError:
        raise SuiteError(f"{where}: text must be Latin-1 (one byte per character): {text!r}") from None


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


def name_token(value: object, where: str) -> str:
    if not isinstance(value, str) or not _NAME_RE.fullmatch(value):
        raise SuiteError(f"{where}: not a name: {value!r}")
    return value


def int_value(value: object, where: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise SuiteError(f"{where}: not an integer: {value!r}")
    return value


# --- vectors to request lines -------------------------------------------------------------------


@dataclass
class Vector:
    suite: str
    id: str
    kind: str
    input: Any
    expect: Any
    note: str | None
    options: dict[str, Any] = field(default_factory=dict)

    @property
    def where(self) -> str:
        return f"{self.suite}:{self.id}"

    @property
    def unknown_options(self) -> list[str]:
        """Options this harness cannot send (not in OPTIONS, or not for this kind)."""
        return [k for k in self.options if self.kind not in OPTIONS.get(k, ())]


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


def _session_event(event: object, w: str) -> str:
    if not isinstance(event, dict) or len(event) != 1:
        raise SuiteError(f'{w}: an event is {{"command": code}}, {{"data": size}} or {{"event": name}}')
    ((key, value),) = event.items()
    if key == "command":
        code = int(value, 16) if isinstance(value, str) else int_value(value, w)
        if not 0 <= code <= 0xFF:
            raise SuiteError(f"{w}: a command code is a byte")
        return f"C:{code:02X}"
    if key == "data":
        return f"D:{int_value(value, w)}"
    if key == "event":
        return f"E:{name_token(value, w)}"
    raise SuiteError(f"{w}: unknown session event {key!r}")


def _session(i: object, w: str) -> str:
    i = _object(i, w)
    firmware = i.get("firmware", "-")
    if firmware != "-" and not (isinstance(firmware, str) and _VERSION_RE.fullmatch(firmware)):
        raise SuiteError(f"{w}: firmware is a version like 4.9.8.0")
    events = i.get("events")
    if not isinstance(events, list) or not events:
        raise SuiteError(f"{w}: events must be a non-empty list")
    return f"session {firmware} " + ",".join(_session_event(event, w) for event in events)


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


# --- answers against expectations -----------------------------------------------------------------


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


def as_int(token: str | None) -> int | None:
    if token is None or not _INT_RE.fullmatch(token):
        return None
    return int(token)


def as_float(token: str | None) -> float | None:
    if token is None:
        return None
    try:
        return float(token)
    except ValueError:
        return None


def f32_bits(value: float) -> bytes | None:
    if math.isnan(value):
        return b"nan"
    try:
        return struct.pack("<f", value)
    except OverflowError:
        return None


def same_hex(expected: object, token: str | None, where: str) -> bool:
    if not isinstance(expected, str):
        raise SuiteError(f"{where}: expected a hex string, got {expected!r}")
    actual = None if token is None else read_hex_token(token)
    return actual is not None and actual == parse_hex(expected, where)


def same_number(expected: object, token: str | None, where: str) -> bool:
    """Engineering values and NMEA numbers: within 1e-9 relative (an integer expectation is exact)."""
    if isinstance(expected, str) and expected in SPECIAL_FLOATS:
        expected = SPECIAL_FLOATS[expected]
    if isinstance(expected, bool) or not isinstance(expected, (int, float)):
        raise SuiteError(f"{where}: expected a number, got {expected!r}")
    actual = as_float(token)
    if actual is None:
        return False
    if math.isnan(expected) or math.isnan(actual):
        return math.isnan(expected) and math.isnan(actual)
    return math.isclose(actual, expected, rel_tol=REL_TOL, abs_tol=ABS_TOL)


def _same_text_or_hex(expected: str, token: str, where: str) -> bool:
    text = read_text_token(token)
    if text is not None and text == latin1(expected, where):
        return True
    compact = expected.replace(" ", "")
    actual_hex = read_hex_token(token)
    return (
        bool(compact)
        and actual_hex is not None
        and _HEX_RE.fullmatch(compact) is not None
        and actual_hex == bytes.fromhex(compact)
    )


def same_raw(expected: object, token: str | None, where: str) -> bool:
    """A raw payload field: integer exact, f32 as float32, char as text, reserved as hex bytes."""
    if token is None:
        return False
    if isinstance(expected, bool):
        raise SuiteError(f"{where}: a field value cannot be a boolean")
    if isinstance(expected, int):
        actual = as_int(token)
        if actual is not None:
            return actual == expected
        value = as_float(token)
        return value is not None and f32_bits(value) == f32_bits(float(expected))
    if isinstance(expected, float) or (isinstance(expected, str) and expected in SPECIAL_FLOATS):
        value = as_float(token)
        want = SPECIAL_FLOATS[expected] if isinstance(expected, str) else expected
        return value is not None and f32_bits(value) is not None and f32_bits(value) == f32_bits(want)
    if isinstance(expected, str):
        return _same_text_or_hex(expected, token, where)
    raise SuiteError(f"{where}: unsupported field value {expected!r}")


def _compare_error(exp: dict[str, Any], answer: Answer, w: str) -> str | None:
    if answer.status != "error":
        return f"expected error {exp['error']}, got {answer.status}"
    kind, offset, fld = answer.tokens
    if kind != exp["error"]:
        return f"error kind {kind}, expected {exp['error']}"
    if "offset" in exp:
        want = "-" if exp["offset"] is None else str(int_value(exp["offset"], w))
        if offset != want:
            return f"error offset {offset}, expected {want}"
    if "field" in exp:
        want = "-" if exp["field"] is None else exp["field"]
        if fld != want:
            return f"error field {fld}, expected {want}"
    return None


def _compare_bytes(exp: object, toks: list[str], w: str) -> str | None:
    return None if len(toks) == 1 and same_hex(exp, toks[0], w) else "bytes differ"


def _compare_checksum(exp: object, toks: list[str], w: str) -> str | None:
    return None if len(toks) == 1 and as_int(toks[0]) == int_value(exp, w) else "checksum differs"


def _compare_nmea_encode(exp: object, toks: list[str], w: str) -> str | None:
    if not isinstance(exp, str):
        raise SuiteError(f"{w}: expected the sentence as a string")
    text = read_text_token(toks[0]) if len(toks) == 1 else None
    return None if text == latin1(exp, w) else "sentence differs"


def _compare_frame_decode(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    for key in ("message_type", "reserved"):
        if key in exp and as_int(got.get(key)) != int_value(exp[key], w):
            return f"{key} differs"
    if "payload" in exp and not same_hex(exp["payload"], got.get("payload"), w):
        return "payload differs"
    return None


def _compare_command_decode(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    if "code" in exp and as_int(got.get("code")) != int_value(exp["code"], w):
        return "code differs"
    if "names" in exp and (got.get("names") or "-").split(",") != (exp["names"] or ["-"]):
        return "names differ"
    return None


def _compare_nmea_decode(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    for key, want in exp.items():
        same = as_int(got.get(key)) == want if key == "usw" else same_number(want, got.get(key), w)
        if not same:
            return f"{key} differs"
    return None


def _session_steps(tokens: str) -> list[dict[str, Any]] | str:
    steps: list[dict[str, Any]] = []
    for token in tokens.split(","):
        parts = token.split(">")
        if len(parts) != 3:
            return f"step {token!r} is not EVENT>STATE>SENDS"
        steps.append({"event": parts[0], "state": parts[1], "send": [] if parts[2] == "-" else parts[2].split("+")})
    return steps


def _compare_session(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    tokens = got.get("steps")
    if tokens is None:
        return "steps missing"
    steps = _session_steps(tokens)
    if isinstance(steps, str):
        return steps
    if "state" in exp and steps[-1]["state"] != exp["state"]:
        return f"final state {steps[-1]['state']}, expected {exp['state']}"
    if "steps" not in exp:
        return None
    if not isinstance(exp["steps"], list):
        raise SuiteError(f"{w}: steps must be a list")
    if len(steps) != len(exp["steps"]):
        return f"{len(steps)} steps, expected {len(exp['steps'])}"
    for n, (want, step) in enumerate(zip(exp["steps"], steps, strict=True)):
        for key in ("event", "state", "send"):
            if key in want and want[key] != step[key]:
                return f"step {n}: {key} {step[key]}, expected {want[key]}"
    return None


def _compare_payload(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    for key, want in exp.get("fields", {}).items():
        token = got.get(f"f.{key}")
        if token is None:
            return f"field {key} missing"
        if not same_raw(want, token, w):
            return f"field {key} differs"
    for key, want in exp.get("values", {}).items():
        token = got.get(f"v.{key}")
        if token is None:
            return f"value {key} missing"
        if not same_number(want, token, w):
            return f"value {key} differs"
    return None


def _stream_event_same(want: dict[str, Any], token: str, w: str) -> bool:
    if "frame" in want:
        return token.startswith("F:") and same_hex(want["frame"], token[2:], w)
    if "nmea" in want:
        return token.startswith("N:") and read_text_token(token[2:]) == latin1(want["nmea"], w)
    raise SuiteError(f'{w}: an event is {{"frame": hex}} or {{"nmea": sentence}}')


def _compare_stream(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    if "discarded" in exp and as_int(got.get("discarded")) != int_value(exp["discarded"], w):
        return f"discarded {got.get('discarded')}, expected {exp['discarded']}"
    if "events" not in exp:
        return None
    tokens = got.get("events")
    if tokens is None:
        return "events missing"
    actual = [] if tokens == "-" else tokens.split(",")
    for n, (want, token) in enumerate(zip(exp["events"], actual, strict=False)):
        if not _stream_event_same(want, token, w):
            return f"event {n} differs: expected {json.dumps(want)}, got {token[:120]}"
    if len(actual) != len(exp["events"]):
        return f"{len(actual)} events, expected {len(exp['events'])}"
    return None


_TOKEN_COMPARES: dict[str, Callable[[Any, list[str], str], str | None]] = {
    "frame_encode": _compare_bytes,
    "command_encode": _compare_bytes,
    "ack": _compare_bytes,
    "payload_encode": _compare_bytes,
    "checksum": _compare_checksum,
    "nmea_encode": _compare_nmea_encode,
}
_KEYED_COMPARES: dict[str, Callable[[dict[str, Any], dict[str, str], str], str | None]] = {
    "frame_decode": _compare_frame_decode,
    "command_decode": _compare_command_decode,
    "payload_decode": _compare_payload,
    "nmea_decode": _compare_nmea_decode,
    "stream": _compare_stream,
    "session": _compare_session,
}


def compare(v: Vector, answer: Answer) -> str | None:
    """None when the answer meets the expectation, else why not."""
    exp, w = v.expect, v.where
    if isinstance(exp, dict) and "error" in exp:
        return _compare_error(exp, answer, w)
    if answer.status != "ok":
        return f"expected a result, got {answer.status}"
    by_tokens = _TOKEN_COMPARES.get(v.kind)
    if by_tokens is not None:
        return by_tokens(exp, answer.tokens, w)
    by_keys = _KEYED_COMPARES.get(v.kind)
    if by_keys is None:
        raise SuiteError(f"{w}: unknown kind {v.kind!r}")
    got = keyed(answer.tokens)
    if got is None:
        return "answer is not KEY=VALUE tokens"
    if not isinstance(exp, dict):
        raise SuiteError(f"{w}: expected an object")
    return by_keys(exp, got, w)


# --- suites ---------------------------------------------------------------------------------------


@dataclass
class Suite:
    name: str
    path: Path
    vectors: list[Vector]


def _suite_vectors(path: Path, name: str, raws: list[object]) -> list[Vector]:
    vectors: list[Vector] = []
    seen: set[str] = set()
    for n, raw in enumerate(raws):
        if not isinstance(raw, dict) or not all(k in raw for k in ("id", "kind", "input", "expect")):
            raise SuiteError(f"{path}: vector {n} needs id, kind, input and expect")
        if not isinstance(raw["id"], str) or raw["id"] in seen:
            raise SuiteError(f"{path}: vector {n}: id missing or repeated: {raw['id']!r}")
        if raw["kind"] not in KINDS + LATER_KINDS:
            raise SuiteError(f"{path}: {raw['id']}: unknown kind {raw['kind']!r}")
        options = raw.get("options", {})
        if not isinstance(options, dict):
            raise SuiteError(f"{path}: {raw['id']}: options must be an object")
        seen.add(raw["id"])
        vector = Vector(name, raw["id"], raw["kind"], raw["input"], raw["expect"], raw.get("note"), options)
        vectors.append(vector)
    return vectors


def load_suites(directory: Path) -> list[Suite]:
    paths = sorted(directory.glob("*.json"))
    if not paths:
        raise SuiteError(f"{directory}: no *.json suites")
    suites = []
    for path in paths:
        try:
            doc = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as err:
            raise SuiteError(f"{path}: {err}") from None
        if (
            not isinstance(doc, dict)
            or not isinstance(doc.get("suite"), str)
            or not isinstance(doc.get("vectors"), list)
        ):
            raise SuiteError(f'{path}: a suite is {{"suite": str, "source": str, "vectors": [...]}}')
        suites.append(Suite(doc["suite"], path, _suite_vectors(path, doc["suite"], doc["vectors"])))
    return suites


# --- bindings and runners -------------------------------------------------------------------------


@dataclass
class Binding:
    name: str
    command: list[str]
    kinds: list[str] | None  # None: an ad-hoc runner, its own `unsupported` answers decide
    build: str | None
    options: list[str] | None = None  # the vector options it knows; None: every one (OPTIONS)
    root: Path | None = None
    """Where its command runs and relative paths in it resolve: a registration's "root", relative to
    the registration's folder (that folder when absent); None (an ad-hoc runner): --root or the
    current directory."""


def _binding(path: Path) -> Binding:
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        raise BindingError(f"{path}: {err}") from None
    command = doc.get("command") if isinstance(doc, dict) else None
    if (
        not isinstance(doc, dict)
        or not isinstance(doc.get("name"), str)
        or not isinstance(command, list)
        or not command
        or not all(isinstance(c, str) for c in command)
        or not isinstance(doc.get("kinds"), list)
    ):
        raise BindingError(f'{path}: a binding is {{"name": str, "command": [str, ...], "kinds": [...], "build": str}}')
    unknown = [k for k in doc["kinds"] if k not in KINDS + LATER_KINDS]
    if unknown:
        raise BindingError(f"{path}: unknown kinds {unknown}")
    options = doc.get("options")
    if options is not None and (not isinstance(options, list) or any(o not in OPTIONS for o in options)):
        raise BindingError(f"{path}: options must be a list of {', '.join(OPTIONS)}")
    root = doc.get("root", ".")
    if not isinstance(root, str):
        raise BindingError(f"{path}: root must be a directory relative to the registration, such as ../..")
    base = (path.parent / root).resolve()
    return Binding(doc["name"], command, list(doc["kinds"]), doc.get("build"), options, base)


def load_bindings(directory: Path, only: list[str] | None) -> list[Binding]:
    found: dict[str, Binding] = {}
    for path in sorted(directory.glob("*.json")):
        binding = _binding(path)
        found[binding.name] = binding
    if only is None:
        return list(found.values())
    missing = [n for n in only if n not in found]
    if missing:
        raise BindingError(
            f"no registration for {', '.join(missing)} in {directory} (registered: {', '.join(found) or 'none'})"
        )
    return [found[n] for n in only]


class RunnerGoneError(Exception):
    pass


class Runner:
    """One runner process: a line in, a line out, with a time limit per answer."""

    def __init__(self, command: list[str], cwd: Path) -> None:
        self.proc = subprocess.Popen(
            command, cwd=cwd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        self.lines: queue.Queue[bytes | None] = queue.Queue()
        self.stderr: deque[str] = deque(maxlen=20)
        assert self.proc.stdout is not None and self.proc.stderr is not None
        threading.Thread(target=self._pump, args=(self.proc.stdout,), daemon=True).start()
        threading.Thread(target=self._drain, args=(self.proc.stderr,), daemon=True).start()

    def _pump(self, stream: IO[bytes]) -> None:
        for line in stream:
            self.lines.put(line)
        self.lines.put(None)

    def _drain(self, stream: IO[bytes]) -> None:
        for line in stream:
            self.stderr.append(line.decode("utf-8", "replace").rstrip())

    def ask(self, line: str, timeout: float) -> str:
        """Send one request and wait for its answer, both within `timeout` seconds."""
        stdin = self.proc.stdin
        assert stdin is not None
        deadline = time.monotonic() + timeout
        failed: list[OSError] = []

        def write() -> None:  # in a thread: a runner that stops reading must not block the harness
            try:
                stdin.write(line.encode("ascii") + b"\n")
                stdin.flush()
            except OSError as err:
                failed.append(err)

        writer = threading.Thread(target=write, daemon=True)
        writer.start()
        writer.join(timeout)
        if writer.is_alive():
            self.kill()
            raise RunnerGoneError(f"did not read its request within {timeout:g} s")
        if failed:
            raise RunnerGoneError(self._why("closed its input"))
        try:
            answer = self.lines.get(timeout=max(0.0, deadline - time.monotonic()))
        except queue.Empty:
            self.kill()
            raise RunnerGoneError(f"no answer within {timeout:g} s") from None
        if answer is None:
            raise RunnerGoneError(self._why("exited"))
        return answer.decode("latin-1").rstrip("\r\n")

    def kill(self) -> None:
        self.proc.kill()
        self.proc.wait()

    def _why(self, what: str) -> str:
        try:
            code = self.proc.wait(timeout=2)
        except subprocess.TimeoutExpired:
            code = None
        time.sleep(0.05)  # let the stderr thread catch up
        tail = " | ".join(list(self.stderr)[-5:])
        return f"runner {what} (exit status {code})" + (f"; stderr: {tail}" if tail else "")

    def close(self) -> None:
        if self.proc.stdin is not None:
            with contextlib.suppress(OSError):
                self.proc.stdin.close()
        try:
            self.proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


def resolve_command(binding: Binding, root: Path) -> list[str] | None:
    """The command with {python} replaced by this interpreter and a program path relative to
    `root` made absolute; None when its program does not exist."""
    command = [sys.executable if part == "{python}" else part for part in binding.command]
    program = command[0]
    if "/" in program:
        path = Path(program) if Path(program).is_absolute() else root / program
        return [str(path), *command[1:]] if path.exists() else None
    return command if shutil.which(program) else None


# --- running --------------------------------------------------------------------------------------


@dataclass
class Failure:
    binding: str
    vector: Vector
    reason: str
    request: str
    answer: str


@dataclass
class Cell:
    passed: int = 0
    failed: int = 0
    unsupported: int = 0


@dataclass
class Case:
    """One test case of a report: a vector run against a binding, or a flow run against a device.
    `status`: passed, failed or skipped; `detail`: what was sent, expected and received."""

    group: str
    name: str
    status: str
    message: str = ""
    detail: str = ""
    seconds: float = 0.0


@dataclass
class Result:
    cells: dict[tuple[str, str], Cell] = field(default_factory=dict)
    failures: list[Failure] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)  # a binding that could not run at all
    cases: list[Case] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.failures and not self.problems and not any(c.failed for c in self.cells.values())


MAX_CONSECUTIVE_CRASHES = 5


def _failure_detail(v: Vector, line: str, answer: str) -> str:
    lines = [f"note:     {v.note}"] if v.note else []
    lines += [f"request:  {line}", f"expected: {json.dumps(v.expect)}", f"actual:   {answer or '(no answer)'}"]
    return "\n".join(lines)


class _BindingRun:
    """One binding against the suites: the runner process, restarted after a crash."""

    def __init__(self, binding: Binding, command: list[str], root: Path, timeout: float, result: Result) -> None:
        self.binding = binding
        self.command = command
        self.root = root
        self.timeout = timeout
        self.result = result
        self.runner: Runner | None = None
        self.crashes = 0

    def fail(self, cell: Cell, v: Vector, reason: str, *, line: str, answer: str = "", seconds: float = 0.0) -> None:
        cell.failed += 1
        self.result.failures.append(Failure(self.binding.name, v, reason, line, answer))
        detail = _failure_detail(v, line, answer)
        self.result.cases.append(Case(f"{self.binding.name}.{v.suite}", v.id, "failed", reason, detail, seconds))

    def skip(self, cell: Cell, v: Vector, why: str) -> None:
        cell.unsupported += 1
        self.result.cases.append(Case(f"{self.binding.name}.{v.suite}", v.id, "skipped", why))

    def vector(self, cell: Cell, v: Vector, kinds: Sequence[str] | None) -> None:
        binding = self.binding
        if (kinds is not None and v.kind not in kinds) or v.kind in LATER_KINDS:
            self.skip(cell, v, f"{binding.name} does not list the kind {v.kind}")
            return
        line = request(v)
        if v.unknown_options:
            unknown = ", ".join(v.unknown_options)
            self.fail(cell, v, f"option {unknown} unknown to this harness for {v.kind}", line=line)
            return
        known = OPTIONS if binding.options is None else binding.options
        missing = [o for o, value in v.options.items() if value and o not in known]
        if missing:
            self.skip(cell, v, f"{binding.name} does not list the option {', '.join(missing)}")
            return
        if self.crashes >= MAX_CONSECUTIVE_CRASHES:
            self.fail(cell, v, "not run: the runner keeps failing", line=line)
            return
        if self.runner is None:
            self.runner = Runner(self.command, self.root)
        start = time.monotonic()
        try:
            answer_line = self.runner.ask(line, self.timeout)
            self.crashes = 0
        except RunnerGoneError as gone:
            self.runner.close()
            self.runner = None
            self.crashes += 1
            self.fail(cell, v, str(gone), line=line, seconds=time.monotonic() - start)
            return
        seconds = time.monotonic() - start
        answer = parse_answer(answer_line)
        if answer.status == "unsupported" and kinds is None:
            self.skip(cell, v, f"{binding.name} answered unsupported")
            return
        if answer.status == "unsupported":
            reason: str | None = f"answered unsupported, but {binding.name} lists {v.kind}"
        elif answer.status == "invalid":
            reason = "not an answer of the runner protocol"
        else:
            reason = compare(v, answer)
        if reason is None:
            cell.passed += 1
            self.result.cases.append(Case(f"{binding.name}.{v.suite}", v.id, "passed", seconds=seconds))
        else:
            self.fail(cell, v, reason, line=line, answer=answer_line, seconds=seconds)

    def close(self) -> None:
        if self.runner is not None:
            self.runner.close()
            self.runner = None


def run_binding(binding: Binding, suites: list[Suite], root: Path, timeout: float, result: Result) -> None:
    command = resolve_command(binding, root)
    if command is None:
        build = f"; build it with `{binding.build}` there" if binding.build else ""
        problem = f"{binding.name}: runner {binding.command[0]} not found in {root}{build}"
        result.problems.append(problem)
        for suite in suites:
            result.cells[(binding.name, suite.name)] = Cell(failed=len(suite.vectors))
            group = f"{binding.name}.{suite.name}"
            result.cases += [Case(group, v.id, "failed", problem) for v in suite.vectors]
        return
    run = _BindingRun(binding, command, root, timeout, result)
    try:
        for suite in suites:
            cell = result.cells.setdefault((binding.name, suite.name), Cell())
            for v in suite.vectors:
                run.vector(cell, v, binding.kinds)
    finally:
        run.close()


# --- reporting ------------------------------------------------------------------------------------


def _cut(text: str, limit: int) -> str:
    return text if len(text) <= limit else text[:limit] + f"... ({len(text)} chars)"


def cell_text(cell: Cell) -> str:
    parts = []
    if cell.passed or not (cell.failed or cell.unsupported):
        parts.append(f"{cell.passed} passed")
    if cell.failed:
        parts.append(f"{cell.failed} FAILED")
    if cell.unsupported:
        parts.append(f"{cell.unsupported} n/s")
    return ", ".join(parts)


def _table(result: Result, bindings: list[Binding], suites: list[Suite]) -> list[list[str]]:
    names = [b.name for b in bindings]
    rows = [["suite", *names]]
    totals = {n: Cell() for n in names}
    for suite in suites:
        row = [f"{suite.name} ({len(suite.vectors)})"]
        for n in names:
            cell = result.cells.get((n, suite.name), Cell())
            row.append(cell_text(cell))
            totals[n].passed += cell.passed
            totals[n].failed += cell.failed
            totals[n].unsupported += cell.unsupported
        rows.append(row)
    rows.append([f"total ({sum(len(s.vectors) for s in suites)})", *(cell_text(totals[n]) for n in names)])
    return rows


def report(result: Result, bindings: list[Binding], suites: list[Suite], max_failures: int, out: IO[str]) -> None:
    rows = _table(result, bindings, suites)
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    for line_no, row in enumerate(rows):
        out.write("  ".join(c.ljust(widths[i]) for i, c in enumerate(row)).rstrip() + "\n")
        if line_no in (0, len(rows) - 2):
            out.write("  ".join("-" * w for w in widths) + "\n")
    out.write("(n/s: a kind or vector option the binding does not list as supported)\n")
    for problem in result.problems:
        out.write(f"\nFAILED {problem}\n")
    for shown, failure in enumerate(result.failures):
        if shown == max_failures:
            out.write(f"\n... and {len(result.failures) - shown} more failures (--max-failures)\n")
            break
        v = failure.vector
        out.write(f"\nFAILED {failure.binding} {v.suite} {v.id}: {failure.reason}\n")
        if v.note:
            out.write(f"  note:     {_cut(v.note, 300)}\n")
        out.write(f"  request:  {_cut(failure.request, 300)}\n")
        out.write(f"  expected: {_cut(json.dumps(v.expect), 300)}\n")
        out.write(f"  actual:   {_cut(failure.answer, 300) if failure.answer else '(no answer)'}\n")


def json_report(result: Result, bindings: list[Binding], suites: list[Suite]) -> dict[str, Any]:
    return {
        "ok": result.ok,
        "problems": result.problems,
        "results": [
            {"binding": b.name, "suite": s.name, **vars(result.cells.get((b.name, s.name), Cell()))}
            for b in bindings
            for s in suites
        ],
        "failures": [
            {
                "binding": f.binding,
                "suite": f.vector.suite,
                "id": f.vector.id,
                "reason": f.reason,
                "request": f.request,
                "expected": f.vector.expect,
                "actual": f.answer,
            }
            for f in result.failures
        ],
    }


_XML_UNSAFE = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def _xml_text(text: str, limit: int = 4000) -> str:
    """Text XML 1.0 can carry (control characters as \\xNN), cut to `limit` characters."""
    return _XML_UNSAFE.sub(lambda m: f"\\x{ord(m.group()):02x}", _cut(text, limit))


def junit_xml(cases: Sequence[Case], name: str = "ilahrs conformance") -> str:
    """JUnit XML (the Ant/Jenkins form GitHub Actions, GitLab and Jenkins read): one <testsuite>
    per group (binding.suite, or the live flows), one <testcase> per case; a failure carries the
    reason as its message and the request, expectation and answer as its text."""
    groups: dict[str, list[Case]] = {}
    for case in cases:
        groups.setdefault(case.group, []).append(case)

    def counts(items: Sequence[Case]) -> dict[str, str]:
        return {
            "tests": str(len(items)),
            "failures": str(sum(c.status == "failed" for c in items)),
            "errors": "0",
            "skipped": str(sum(c.status == "skipped" for c in items)),
            "time": f"{sum(c.seconds for c in items):.3f}",
        }

    root = ElementTree.Element("testsuites", {"name": name, **counts(cases)})
    for group, items in groups.items():
        suite = ElementTree.SubElement(root, "testsuite", {"name": group, **counts(items)})
        for case in items:
            attrs = {"name": _xml_text(case.name, 500), "classname": group, "time": f"{case.seconds:.3f}"}
            element = ElementTree.SubElement(suite, "testcase", attrs)
            if case.status == "failed":
                failure = ElementTree.SubElement(element, "failure", {"message": _xml_text(case.message, 500)})
                failure.text = _xml_text(case.detail)
            elif case.status == "skipped":
                ElementTree.SubElement(element, "skipped", {"message": _xml_text(case.message, 500)})
    ElementTree.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ElementTree.tostring(root, encoding="unicode") + "\n"


# --- the command line -----------------------------------------------------------------------------


def _names(text: str) -> list[str]:
    return [n.strip() for n in text.split(",") if n.strip()]


def add_arguments(
    parser: argparse.ArgumentParser,
    *,
    vectors: Path = VECTORS_DIR,
    root: Path | None = None,
    bindings_dir: Path | None = None,
) -> None:
    """The options of `ilahrs conformance` (and of the repository's conformance/harness.py, with
    its own defaults)."""
    parser.add_argument(
        "--vectors", type=Path, default=vectors, help=f"directory of suites (*.json); default {vectors}"
    )
    parser.add_argument("--command", dest="runner_command", help="run this runner command line (shell-style quoting)")
    parser.add_argument("--name", default="runner", help="the name shown for --command (default runner)")
    parser.add_argument("--bindings", help="comma-separated binding names (default: every registered one)")
    parser.add_argument(
        "--bindings-dir",
        type=Path,
        default=bindings_dir,
        help="where NAME.json registrations are" + (f"; default {bindings_dir}" if bindings_dir else ""),
    )
    parser.add_argument(
        "--root",
        type=Path,
        default=root,
        help="where runner commands run (default: a registration's own root, see conformance/README.md; "
        "the current directory for --command)",
    )
    parser.add_argument("--suites", help="comma-separated suites to run (default: all)")
    parser.add_argument("--suite", action="append", help="one suite to run (repeatable)")
    parser.add_argument(
        "--kinds",
        help="comma-separated kinds to send; others count as not supported (n/s). With --command the runner "
        "is held to these kinds (an `unsupported` answer fails); without, its `unsupported` answers count n/s",
    )
    parser.add_argument(
        "--options",
        help=f"comma-separated vector options the runner knows ({', '.join(OPTIONS)}; default all, `-` for none); "
        "vectors with another option count as not supported (n/s)",
    )
    parser.add_argument("-k", dest="pattern", help="only vectors (or live flows) whose id contains this text")
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds to wait for one answer (default 20)")
    parser.add_argument("--max-failures", type=int, default=40, help="failures to print (default 40)")
    parser.add_argument("--json", type=Path, help="also write the results as JSON to this file")
    parser.add_argument("--junit", type=Path, help="also write the results as JUnit XML to this file")
    live = parser.add_argument_group("live device (see ilahrs.conformance.live)")
    live.add_argument("--device", metavar="PORT", help="run the session flows against a device on this port")
    live.add_argument("--baud", type=int, help="baud rate of --device (default: the AHRS line's)")
    live.add_argument(
        "--allow-calibration", action="store_true", help="also run flows that change the stored calibration"
    )
    live.add_argument("--quiet", type=float, default=0.25, help="seconds of silence that show nothing more comes")
    live.add_argument(
        "--alignment-time",
        type=int,
        default=2,
        help="alignment time loaded for the run, s (default 2; the commands flows send while the device "
        "aligns must fit in it)",
    )
    live.add_argument("--accumulation-time", type=int, default=2, help="accumulation time for the run, s (default 2)")


def _select(args: argparse.Namespace) -> list[Suite]:
    suites = load_suites(args.vectors)
    wanted = [*(args.suite or []), *(_names(args.suites) if args.suites else [])]
    if wanted:
        unknown = sorted(set(wanted) - {s.name for s in suites})
        if unknown:
            raise SuiteError(f"no suite named {', '.join(unknown)} in {args.vectors}")
        suites = [s for s in suites if s.name in wanted]
    if args.pattern:
        suites = [Suite(s.name, s.path, [v for v in s.vectors if args.pattern in v.id]) for s in suites]
        suites = [s for s in suites if s.vectors]
    for suite in suites:  # translate everything once up front: a bad vector is a suite error
        for v in suite.vectors:
            if v.kind not in LATER_KINDS:
                request(v)
    return suites


def _bindings(args: argparse.Namespace) -> list[Binding]:
    kinds = _names(args.kinds) if args.kinds else None
    unknown = [k for k in kinds or [] if k not in KINDS]
    if unknown:
        raise BindingError(f"unknown kinds {', '.join(unknown)} (kinds: {', '.join(KINDS)})")
    options = None if args.options is None else [o for o in _names(args.options) if o != "-"]
    wrong = [o for o in options or [] if o not in OPTIONS]
    if wrong:
        raise BindingError(f"unknown options {', '.join(wrong)} (options: {', '.join(OPTIONS)})")
    if args.runner_command:
        return [Binding(args.name, shlex.split(args.runner_command), kinds, None, options)]
    if args.bindings_dir is None:
        raise BindingError("give the runner with --command (or registrations with --bindings-dir)")
    bindings = load_bindings(args.bindings_dir, _names(args.bindings) if args.bindings else None)
    if not bindings:
        raise BindingError(f"no bindings registered in {args.bindings_dir}")
    for binding in bindings:
        if kinds is not None:
            binding.kinds = [k for k in binding.kinds or KINDS if k in kinds]
        if options is not None:
            binding.options = [o for o in binding.options or OPTIONS if o in options]
    return bindings


def run(args: argparse.Namespace, out: IO[str] = sys.stdout) -> int:
    """`ilahrs conformance` with parsed arguments (add_arguments)."""
    if args.device:
        from .live import run_live

        return run_live(args, out)
    try:
        suites = _select(args)
        bindings = _bindings(args)
    except (SuiteError, BindingError) as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    root = args.root if args.root is not None else Path.cwd()
    result = Result()
    vector_count = sum(len(s.vectors) for s in suites)
    out.write(
        f"conformance: {vector_count} vectors in {len(suites)} suites from {args.vectors}; "
        f"bindings: {', '.join(b.name for b in bindings)}\n\n"
    )
    try:
        for binding in bindings:
            base = root if args.root is not None or binding.root is None else binding.root
            run_binding(binding, suites, base, args.timeout, result)
    except SuiteError as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    report(result, bindings, suites, args.max_failures, out)
    if args.json:
        args.json.write_text(json.dumps(json_report(result, bindings, suites), indent=1) + "\n", encoding="utf-8")
    if args.junit:
        args.junit.write_text(junit_xml(result.cases), encoding="utf-8")
    out.write(f"\n{'PASSED' if result.ok else 'FAILED'}\n")
    return 0 if result.ok else 1


def main(argv: Sequence[str] | None = None, out: IO[str] = sys.stdout, **defaults: Any) -> int:
    """The suite as a program of its own; `defaults` as add_arguments takes them."""
    parser = argparse.ArgumentParser(description="Run the conformance vectors against runners or a device.")
    add_arguments(parser, **defaults)
    return run(parser.parse_args(argv), out)
