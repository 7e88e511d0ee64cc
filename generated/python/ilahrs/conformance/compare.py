# Copied from generator/targets/python/runtime/conformance/compare.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""An answer against a vector's expectation."""

from __future__ import annotations

import json
import math
import re
import struct
from collections.abc import Callable
from typing import Any

from .protocol import Answer, keyed, read_hex_token, read_text_token
from .vectors import SPECIAL_FLOATS, SuiteError, Vector, int_value, latin1, parse_hex

__all__ = ["ABS_TOL", "REL_TOL", "as_float", "as_int", "compare", "same_hex", "same_number", "same_raw"]

REL_TOL = 1e-9  # engineering values and NMEA numbers
ABS_TOL = 1e-12
_HEX_RE = re.compile(r"(?:[0-9A-Fa-f]{2})*")
_INT_RE = re.compile(r"-?[0-9]+")


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
