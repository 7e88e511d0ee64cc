#!/usr/bin/env python3
"""Run conformance vectors against one or more bindings' runners and compare the answers.

    python3 conformance/harness.py                               # every registered binding, every suite
    python3 conformance/harness.py --bindings python,c           # some bindings
    python3 conformance/harness.py --vectors DIR                 # any directory of suites
    python3 conformance/harness.py --command ./my_runner         # an unregistered runner, no JSON needed
    python3 conformance/harness.py --suite nmea -k bad-checksum  # a subset, for debugging

The harness owns the vectors (conformance/vectors/*.json) and all test logic; a runner only turns
request lines into answer lines (conformance/README.md, "The runner protocol"). Each runner is
started once and fed every vector. Standard library only, Python 3.10 or later.
Exit status: 0 when nothing failed, 1 when something failed, 2 when the suites or the
bindings cannot be read.
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
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

ROOT = Path(__file__).resolve().parent.parent
KINDS = (
    "checksum", "frame_decode", "frame_encode", "command_encode", "command_decode", "ack",
    "payload_decode", "payload_encode", "nmea_decode", "nmea_encode", "stream", "session",
)
LATER_KINDS: tuple[str, ...] = ()  # kinds of the format this harness does not translate yet
_VERSION_RE = re.compile(r"[0-9]+(?:\.[0-9]+)*")
SPECIAL_FLOATS = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}
REL_TOL = 1e-9  # engineering values and NMEA numbers
ABS_TOL = 1e-12
_HEX_RE = re.compile(r"(?:[0-9A-Fa-f]{2})*")
_NAME_RE = re.compile(r"[^\s=,%]+")


class SuiteError(Exception):
    """A suite file that does not follow the vector format."""


class BindingError(Exception):
    """A binding registration that cannot be used."""


# --- the token forms of the runner protocol -------------------------------------------------------


def parse_hex(text: str, where: str) -> bytes:
    """Vector hex: two hex digits per byte, either case, spaces allowed."""
    compact = text.replace(" ", "")
    if not isinstance(text, str) or not _HEX_RE.fullmatch(compact):
        raise SuiteError(f"{where}: not a hex string: {text!r}")
    return bytes.fromhex(compact)


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
            pair = token[i + 1:i + 3]
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

    @property
    def where(self) -> str:
        return f"{self.suite}:{self.id}"


def request(v: Vector) -> str:
    """The request line for a vector (conformance/README.md, requests)."""
    i, w = v.input, v.where
    if v.kind in ("checksum", "frame_decode", "command_decode", "ack"):
        return f"{v.kind} {hex_token(parse_hex(i, w))}"
    if not isinstance(i, dict) and v.kind not in ("nmea_decode",):
        raise SuiteError(f"{w}: input must be an object")
    if v.kind == "frame_encode":
        line = f"frame_encode {int_value(i.get('message_type'), w)} {hex_token(parse_hex(i.get('payload', ''), w))}"
        return line + (f" {int_value(i['reserved'], w)}" if "reserved" in i else "")
    if v.kind == "command_encode":
        return f"command_encode {name_token(i.get('command'), w)}"
    if v.kind == "payload_decode":
        line = f"payload_decode {name_token(i.get('type'), w)} {hex_token(parse_hex(i.get('hex', ''), w))}"
        return line + (f" {name_token(i['variant'], w)}" if "variant" in i else "")
    if v.kind == "payload_encode":
        fields = i.get("fields", {})
        if not isinstance(fields, dict):
            raise SuiteError(f"{w}: fields must be an object")
        parts = [f"{name_token(k, w)}={value_token(x, w)}" for k, x in fields.items()]
        variant = name_token(i["variant"], w) if "variant" in i else "-"
        return " ".join(["payload_encode", name_token(i.get("type"), w), variant, *parts])
    if v.kind == "nmea_decode":
        if not isinstance(i, str):
            raise SuiteError(f"{w}: input must be the sentence as a string")
        return f"nmea_decode {text_token(latin1(i, w))}"
    if v.kind == "nmea_encode":
        parts = [f"{name_token(k, w)}={num_token(x, w)}" for k, x in i.items()]
        return " ".join(["nmea_encode", *parts])
    if v.kind == "stream":
        chunks = i.get("chunks")
        if not isinstance(chunks, list) or not chunks:
            raise SuiteError(f"{w}: chunks must be a non-empty list of hex strings")
        return "stream " + ",".join(hex_token(parse_hex(c, w)) for c in chunks)
    if v.kind == "session":
        return _session_request(i, w)
    raise SuiteError(f"{w}: unknown kind {v.kind!r}")


def _session_request(i: dict[str, Any], w: str) -> str:
    firmware = i.get("firmware", "-")
    if firmware != "-" and not (isinstance(firmware, str) and _VERSION_RE.fullmatch(firmware)):
        raise SuiteError(f"{w}: firmware is a version like 4.9.8.0")
    events = i.get("events")
    if not isinstance(events, list) or not events:
        raise SuiteError(f"{w}: events must be a non-empty list")
    tokens = []
    for event in events:
        if not isinstance(event, dict) or len(event) != 1:
            raise SuiteError(f"{w}: an event is {{\"command\": code}}, {{\"data\": size}} or {{\"event\": name}}")
        (key, value), = event.items()
        if key == "command":
            code = int(value, 16) if isinstance(value, str) else int_value(value, w)
            if not 0 <= code <= 0xFF:
                raise SuiteError(f"{w}: a command code is a byte")
            tokens.append(f"C:{code:02X}")
        elif key == "data":
            tokens.append(f"D:{int_value(value, w)}")
        elif key == "event":
            tokens.append(f"E:{name_token(value, w)}")
        else:
            raise SuiteError(f"{w}: unknown session event {key!r}")
    return f"session {firmware} " + ",".join(tokens)


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
    out = {}
    for token in tokens:
        key, sep, value = token.partition("=")
        if not sep or key in out:
            return None
        out[key] = value
    return out


def as_int(token: str | None) -> int | None:
    if token is None or not re.fullmatch(r"-?[0-9]+", token):
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
        text = read_text_token(token)
        if text is not None and text == latin1(expected, where):
            return True
        compact = expected.replace(" ", "")
        actual_hex = read_hex_token(token)
        return bool(compact) and actual_hex is not None and _HEX_RE.fullmatch(compact) is not None and \
            actual_hex == bytes.fromhex(compact)
    raise SuiteError(f"{where}: unsupported field value {expected!r}")


def compare(v: Vector, answer: Answer) -> str | None:
    """None when the answer meets the expectation, else why not."""
    exp, w = v.expect, v.where
    if isinstance(exp, dict) and "error" in exp:
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
    if answer.status != "ok":
        return f"expected a result, got {answer.status}"
    toks = answer.tokens
    if v.kind in ("frame_encode", "command_encode", "ack", "payload_encode"):
        return None if len(toks) == 1 and same_hex(exp, toks[0], w) else "bytes differ"
    if v.kind == "checksum":
        return None if len(toks) == 1 and as_int(toks[0]) == int_value(exp, w) else "checksum differs"
    if v.kind == "nmea_encode":
        if not isinstance(exp, str):
            raise SuiteError(f"{w}: expected the sentence as a string")
        text = read_text_token(toks[0]) if len(toks) == 1 else None
        return None if text == latin1(exp, w) else "sentence differs"
    got = keyed(toks)
    if got is None:
        return "answer is not KEY=VALUE tokens"
    if not isinstance(exp, dict):
        raise SuiteError(f"{w}: expected an object")
    if v.kind == "frame_decode":
        for key in ("message_type", "reserved"):
            if key in exp and as_int(got.get(key)) != int_value(exp[key], w):
                return f"{key} differs"
        if "payload" in exp and not same_hex(exp["payload"], got.get("payload"), w):
            return "payload differs"
        return None
    if v.kind == "command_decode":
        if "code" in exp and as_int(got.get("code")) != int_value(exp["code"], w):
            return "code differs"
        if "names" in exp and (got.get("names") or "-").split(",") != (exp["names"] or ["-"]):
            return "names differ"
        return None
    if v.kind == "payload_decode":
        return _compare_payload(exp, got, w)
    if v.kind == "nmea_decode":
        for key, want in exp.items():
            same = as_int(got.get(key)) == want if key == "usw" else same_number(want, got.get(key), w)
            if not same:
                return f"{key} differs"
        return None
    if v.kind == "stream":
        return _compare_stream(exp, got, w)
    if v.kind == "session":
        return _compare_session(exp, got, w)
    raise SuiteError(f"{w}: unknown kind {v.kind!r}")


def _compare_session(exp: dict[str, Any], got: dict[str, str], w: str) -> str | None:
    tokens = got.get("steps")
    if tokens is None:
        return "steps missing"
    steps = []
    for token in tokens.split(","):
        parts = token.split(">")
        if len(parts) != 3:
            return f"step {token!r} is not EVENT>STATE>SENDS"
        steps.append({"event": parts[0], "state": parts[1], "send": [] if parts[2] == "-" else parts[2].split("+")})
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
        if "frame" in want:
            same = token.startswith("F:") and same_hex(want["frame"], token[2:], w)
        elif "nmea" in want:
            same = token.startswith("N:") and read_text_token(token[2:]) == latin1(want["nmea"], w)
        else:
            raise SuiteError(f"{w}: an event is {{\"frame\": hex}} or {{\"nmea\": sentence}}")
        if not same:
            return f"event {n} differs: expected {json.dumps(want)}, got {token[:120]}"
    if len(actual) != len(exp["events"]):
        return f"{len(actual)} events, expected {len(exp['events'])}"
    return None


# --- suites ---------------------------------------------------------------------------------------


@dataclass
class Suite:
    name: str
    path: Path
    vectors: list[Vector]


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
        if not isinstance(doc, dict) or not isinstance(doc.get("suite"), str) or not isinstance(
                doc.get("vectors"), list):
            raise SuiteError(f"{path}: a suite is {{\"suite\": str, \"source\": str, \"vectors\": [...]}}")
        name = doc["suite"]
        vectors: list[Vector] = []
        seen: set[str] = set()
        for n, raw in enumerate(doc["vectors"]):
            if not isinstance(raw, dict) or not all(k in raw for k in ("id", "kind", "input", "expect")):
                raise SuiteError(f"{path}: vector {n} needs id, kind, input and expect")
            if not isinstance(raw["id"], str) or raw["id"] in seen:
                raise SuiteError(f"{path}: vector {n}: id missing or repeated: {raw['id']!r}")
            if raw["kind"] not in KINDS + LATER_KINDS:
                raise SuiteError(f"{path}: {raw['id']}: unknown kind {raw['kind']!r}")
            seen.add(raw["id"])
            vectors.append(Vector(name, raw["id"], raw["kind"], raw["input"], raw["expect"], raw.get("note")))
        suites.append(Suite(name, path, vectors))
    return suites


# --- bindings and runners -------------------------------------------------------------------------


@dataclass
class Binding:
    name: str
    command: list[str]
    kinds: list[str] | None  # None: an ad-hoc runner, its own `unsupported` answers decide
    build: str | None


def load_bindings(directory: Path, only: list[str] | None) -> list[Binding]:
    found: dict[str, Binding] = {}
    for path in sorted(directory.glob("*.json")):
        try:
            doc = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as err:
            raise BindingError(f"{path}: {err}") from None
        if not isinstance(doc, dict) or not isinstance(doc.get("name"), str) or not isinstance(
                doc.get("command"), list) or not all(isinstance(c, str) for c in doc["command"]) or not doc[
                "command"] or not isinstance(doc.get("kinds"), list):
            raise BindingError(f"{path}: a binding is {{\"name\": str, \"command\": [str, ...], \"kinds\": [...], "
                               "\"build\": str}}")
        unknown = [k for k in doc["kinds"] if k not in KINDS + LATER_KINDS]
        if unknown:
            raise BindingError(f"{path}: unknown kinds {unknown}")
        found[doc["name"]] = Binding(doc["name"], doc["command"], list(doc["kinds"]), doc.get("build"))
    if only is None:
        return list(found.values())
    missing = [n for n in only if n not in found]
    if missing:
        raise BindingError(f"no registration for {', '.join(missing)} in {directory} "
                           f"(registered: {', '.join(found) or 'none'})")
    return [found[n] for n in only]


class RunnerGoneError(Exception):
    pass


class Runner:
    """One runner process: a line in, a line out, with a time limit per answer."""

    def __init__(self, command: list[str], cwd: Path) -> None:
        self.proc = subprocess.Popen(command, cwd=cwd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE)
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
    """The command with {python} replaced by this interpreter; None when its program does not exist."""
    command = [sys.executable if part == "{python}" else part for part in binding.command]
    program = command[0]
    if "/" in program:
        path = Path(program) if Path(program).is_absolute() else root / program
        return command if path.exists() else None
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
class Result:
    cells: dict[tuple[str, str], Cell] = field(default_factory=dict)
    failures: list[Failure] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)  # a binding that could not run at all

    @property
    def ok(self) -> bool:
        return not self.failures and not self.problems and not any(c.failed for c in self.cells.values())


MAX_CONSECUTIVE_CRASHES = 5


def run_binding(binding: Binding, suites: list[Suite], root: Path, timeout: float, result: Result) -> None:
    command = resolve_command(binding, root)
    if command is None:
        build = f"; build it with `{binding.build}`" if binding.build else ""
        result.problems.append(f"{binding.name}: runner {binding.command[0]} not found{build}")
        for suite in suites:
            result.cells[(binding.name, suite.name)] = Cell(failed=len(suite.vectors))
        return
    runner: Runner | None = None
    crashes = 0
    try:
        for suite in suites:
            cell = result.cells.setdefault((binding.name, suite.name), Cell())
            for v in suite.vectors:
                listed = binding.kinds is None or v.kind in binding.kinds
                if not listed or v.kind in LATER_KINDS:
                    cell.unsupported += 1
                    continue
                line = request(v)
                if crashes >= MAX_CONSECUTIVE_CRASHES:
                    cell.failed += 1
                    result.failures.append(Failure(binding.name, v, "not run: the runner keeps failing", line, ""))
                    continue
                if runner is None:
                    runner = Runner(command, root)
                try:
                    answer_line = runner.ask(line, timeout)
                    crashes = 0
                except RunnerGoneError as gone:
                    runner.close()
                    runner = None
                    crashes += 1
                    cell.failed += 1
                    result.failures.append(Failure(binding.name, v, str(gone), line, ""))
                    continue
                answer = parse_answer(answer_line)
                if answer.status == "unsupported" and binding.kinds is None:
                    cell.unsupported += 1
                    continue
                if answer.status == "unsupported":
                    reason: str | None = f"answered unsupported, but {binding.name} lists {v.kind}"
                elif answer.status == "invalid":
                    reason = "not an answer of the runner protocol"
                else:
                    reason = compare(v, answer)
                if reason is None:
                    cell.passed += 1
                else:
                    cell.failed += 1
                    result.failures.append(Failure(binding.name, v, reason, line, answer_line))
    finally:
        if runner is not None:
            runner.close()


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


def report(result: Result, bindings: list[Binding], suites: list[Suite], max_failures: int,
           out: IO[str]) -> None:
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
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    for line_no, row in enumerate(rows):
        out.write("  ".join(c.ljust(widths[i]) for i, c in enumerate(row)).rstrip() + "\n")
        if line_no in (0, len(rows) - 2):
            out.write("  ".join("-" * w for w in widths) + "\n")
    out.write("(n/s: a kind the binding does not list as supported)\n")
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
        "results": [{"binding": b.name, "suite": s.name, **vars(result.cells.get((b.name, s.name), Cell()))}
                    for b in bindings for s in suites],
        "failures": [{"binding": f.binding, "suite": f.vector.suite, "id": f.vector.id, "reason": f.reason,
                      "request": f.request, "expected": f.vector.expect, "actual": f.answer}
                     for f in result.failures],
    }


def main(argv: list[str] | None = None, out: IO[str] = sys.stdout) -> int:
    parser = argparse.ArgumentParser(description="Run the conformance vectors against binding runners.")
    parser.add_argument("--vectors", type=Path, default=ROOT / "conformance" / "vectors",
                        help="directory of suites (*.json); default conformance/vectors")
    parser.add_argument("--bindings", help="comma-separated binding names (default: every registered one)")
    parser.add_argument("--bindings-dir", type=Path, default=ROOT / "conformance" / "bindings",
                        help="where the NAME.json registrations are; default conformance/bindings")
    parser.add_argument("--command", help="run this runner command line (shell-style quoting) instead of the "
                        "registered bindings; kinds it answers `unsupported` count as not supported")
    parser.add_argument("--name", default="runner", help="the name shown for --command")
    parser.add_argument("--root", type=Path, default=ROOT, help="where runner commands run; default the repository")
    parser.add_argument("--suite", action="append", help="only this suite (repeatable)")
    parser.add_argument("-k", dest="pattern", help="only vectors whose id contains this text")
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds to wait for one answer (default 20)")
    parser.add_argument("--max-failures", type=int, default=40, help="failures to print (default 40)")
    parser.add_argument("--json", type=Path, help="also write the results as JSON to this file")
    args = parser.parse_args(argv)
    try:
        suites = load_suites(args.vectors)
        if args.suite:
            unknown = sorted(set(args.suite) - {s.name for s in suites})
            if unknown:
                raise SuiteError(f"no suite named {', '.join(unknown)} in {args.vectors}")
            suites = [s for s in suites if s.name in args.suite]
        if args.pattern:
            suites = [Suite(s.name, s.path, [v for v in s.vectors if args.pattern in v.id]) for s in suites]
            suites = [s for s in suites if s.vectors]
        for suite in suites:  # translate everything once up front: a bad vector is a suite error
            for v in suite.vectors:
                if v.kind not in LATER_KINDS:
                    request(v)
        if args.command:
            bindings = [Binding(args.name, shlex.split(args.command), None, None)]
        else:
            only = [n.strip() for n in args.bindings.split(",") if n.strip()] if args.bindings else None
            bindings = load_bindings(args.bindings_dir, only)
            if not bindings:
                raise BindingError(f"no bindings registered in {args.bindings_dir}")
    except (SuiteError, BindingError) as err:
        print(f"harness: {err}", file=sys.stderr)
        return 2
    result = Result()
    vector_count = sum(len(s.vectors) for s in suites)
    out.write(f"conformance: {vector_count} vectors in {len(suites)} suites from {args.vectors}; "
              f"bindings: {', '.join(b.name for b in bindings)}\n\n")
    try:
        for binding in bindings:
            run_binding(binding, suites, args.root, args.timeout, result)
    except SuiteError as err:
        print(f"harness: {err}", file=sys.stderr)
        return 2
    report(result, bindings, suites, args.max_failures, out)
    if args.json:
        args.json.write_text(json.dumps(json_report(result, bindings, suites), indent=1) + "\n", encoding="utf-8")
    out.write(f"\n{'PASSED' if result.ok else 'FAILED'}\n")
    return 0 if result.ok else 1


if __name__ == "__main__":
    sys.exit(main())
