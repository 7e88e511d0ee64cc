# Copied from generator/targets/python/runtime/conformance/vectors.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The suites: vectors as the format (conformance/vectors.schema.json) gives them, checked, with a
session vector's events as typed values."""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

__all__ = [
    "KINDS",
    "LEVELS",
    "OPTIONS",
    "REQUIRES",
    "SPECIAL_FLOATS",
    "VECTORS_DIR",
    "CommandEvent",
    "DataEvent",
    "Session",
    "SessionEvent",
    "Suite",
    "SuiteError",
    "TimerEvent",
    "Vector",
    "int_value",
    "latin1",
    "load_suites",
    "name_token",
    "parse_hex",
    "session",
    "session_event",
    "suite_version",
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
LEVELS = ("required", "recommended", "erratum")
"""A vector's level of obligation, in order (conformance/README.md, Levels): `--level required`
runs the first, `recommended` the first two, `all` every one."""
REQUIRES = ("commands", "outputs", "payloads", "variants", "nmea", "firmware")
"""What a vector's "requires" may name: the features of a declaration it needs (lists of names, and
nmea a boolean)."""
OPTIONS: dict[str, tuple[str, ...]] = {"strict": ("frame_decode", "stream")}
"""The vector options this harness sends (`"options"` of a vector), and the kinds each applies to.
A vector with an option not listed here fails: it is never sent without it."""
SPECIAL_FLOATS = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}
_HEX_RE = re.compile(r"(?:[0-9A-Fa-f]{2})*")
_NAME_RE = re.compile(r"[^\s=,%]+")
_VERSION_RE = re.compile(r"[0-9]+(?:\.[0-9]+)*")
_SEMVER_RE = re.compile(r"[0-9]+\.[0-9]+\.[0-9]+")
_ERRATUM_RE = re.compile(r"E[0-9]+")


class SuiteError(Exception):
    """A suite file that does not follow the vector format."""


def parse_hex(text: object, where: str) -> bytes:
    """Vector hex: two hex digits per byte, either case, spaces allowed."""
    if not isinstance(text, str) or not _HEX_RE.fullmatch(text.replace(" ", "")):
        raise SuiteError(f"{where}: not a hex string: {text!r}")
    return bytes.fromhex(text.replace(" ", ""))


def latin1(text: str, where: str) -> bytes:
    try:
        return text.encode("latin-1")
    except UnicodeEncodeError:
        raise SuiteError(f"{where}: text must be Latin-1 (one byte per character): {text!r}") from None


def name_token(value: object, where: str) -> str:
    if not isinstance(value, str) or not _NAME_RE.fullmatch(value):
        raise SuiteError(f"{where}: not a name: {value!r}")
    return value


def int_value(value: object, where: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise SuiteError(f"{where}: not an integer: {value!r}")
    return value


@dataclass
class Vector:
    suite: str
    id: str
    kind: str
    input: Any
    expect: Any
    note: str | None
    options: dict[str, Any] = field(default_factory=dict)
    level: str = "required"
    erratum: str | None = None
    requires: dict[str, Any] = field(default_factory=dict)

    @property
    def where(self) -> str:
        return f"{self.suite}:{self.id}"

    @property
    def key(self) -> str:
        """The vector's name in the whole set, as expected-failure files write it: <suite>/<id>."""
        return f"{self.suite}/{self.id}"

    @property
    def unknown_options(self) -> list[str]:
        """Options this harness cannot send (not in OPTIONS, or not for this kind)."""
        return [k for k in self.options if self.kind not in OPTIONS.get(k, ())]


@dataclass(frozen=True)
class CommandEvent:
    """A session event: the host sends a command frame with this code (any byte, also codes no
    command has)."""

    code: int

    @property
    def token(self) -> str:
        """The event as the runner protocol writes it: C:HH."""
        return f"C:{self.code:02X}"


@dataclass(frozen=True)
class DataEvent:
    """A session event: the host sends a data message with a payload of this size."""

    size: int

    @property
    def token(self) -> str:
        """The event as the runner protocol writes it: D:N."""
        return f"D:{self.size}"


@dataclass(frozen=True)
class TimerEvent:
    """A session event the host causes by waiting: the state machine's event of this name (a timer)."""

    name: str

    @property
    def token(self) -> str:
        """The event as the runner protocol writes it: E:NAME."""
        return f"E:{self.name}"


SessionEvent = CommandEvent | DataEvent | TimerEvent
"""One event of a session vector."""


@dataclass(frozen=True)
class Session:
    """The input of a session vector: the firmware of the model (None: the current one) and the
    events, in order."""

    firmware: str | None
    events: tuple[SessionEvent, ...]


def session_event(event: object, w: str) -> SessionEvent:
    if not isinstance(event, dict) or len(event) != 1:
        raise SuiteError(f'{w}: an event is {{"command": code}}, {{"data": size}} or {{"event": name}}')
    ((key, value),) = event.items()
    if key == "command":
        code = int(value, 16) if isinstance(value, str) else int_value(value, w)
        if not 0 <= code <= 0xFF:
            raise SuiteError(f"{w}: a command code is a byte")
        return CommandEvent(code)
    if key == "data":
        return DataEvent(int_value(value, w))
    if key == "event":
        return TimerEvent(name_token(value, w))
    raise SuiteError(f"{w}: unknown session event {key!r}")


def session(i: object, w: str) -> Session:
    """The input of a session vector, checked."""
    if not isinstance(i, dict):
        raise SuiteError(f"{w}: input must be an object")
    firmware = i.get("firmware", "-")
    if firmware != "-" and not (isinstance(firmware, str) and _VERSION_RE.fullmatch(firmware)):
        raise SuiteError(f"{w}: firmware is a version like 4.9.8.0")
    events = i.get("events")
    if not isinstance(events, list) or not events:
        raise SuiteError(f"{w}: events must be a non-empty list")
    return Session(None if firmware == "-" else firmware, tuple(session_event(event, w) for event in events))


@dataclass
class Suite:
    name: str
    path: Path
    vectors: list[Vector]
    version: str | None = None
    """The suites' semver (a changed expectation is a major bump, a new vector a minor one)."""
    icd_revision: str | None = None


def _obligation(path: Path, raw: dict[str, Any]) -> tuple[str, str | None, dict[str, Any]]:
    """A vector's level, erratum and requires, checked (absent: required, nothing)."""
    where = f"{path}: {raw['id']}"
    level = raw.get("level", "required")
    if level not in LEVELS:
        raise SuiteError(f"{where}: level must be one of {', '.join(LEVELS)}")
    erratum = raw.get("erratum")
    if (level == "erratum") != (erratum is not None):
        raise SuiteError(f"{where}: an erratum-level vector names its erratum, and only it does")
    if erratum is not None and not (isinstance(erratum, str) and _ERRATUM_RE.fullmatch(erratum)):
        raise SuiteError(f"{where}: erratum is an id like E12")
    requires = raw.get("requires", {})
    if not isinstance(requires, dict) or any(k not in REQUIRES for k in requires):
        raise SuiteError(f"{where}: requires is an object of {', '.join(REQUIRES)}")
    for key, value in requires.items():
        good = (
            isinstance(value, bool)
            if key == "nmea"
            else isinstance(value, list) and all(isinstance(v, str) for v in value)
        )
        if not good:
            what = "true or false" if key == "nmea" else "a list of names"
            raise SuiteError(f"{where}: requires.{key} must be {what}")
    return level, erratum, requires


def _suite_vectors(path: Path, name: str, raws: list[object]) -> list[Vector]:
    vectors: list[Vector] = []
    seen: set[str] = set()
    for n, raw in enumerate(raws):
        if not isinstance(raw, dict) or not all(k in raw for k in ("id", "kind", "input", "expect")):
            raise SuiteError(f"{path}: vector {n} needs id, kind, input and expect")
        if not isinstance(raw["id"], str) or raw["id"] in seen:
            raise SuiteError(f"{path}: vector {n}: id missing or repeated: {raw['id']!r}")
        if raw["kind"] not in KINDS:
            raise SuiteError(f"{path}: {raw['id']}: unknown kind {raw['kind']!r}")
        options = raw.get("options", {})
        if not isinstance(options, dict):
            raise SuiteError(f"{path}: {raw['id']}: options must be an object")
        seen.add(raw["id"])
        level, erratum, requires = _obligation(path, raw)
        vector = Vector(name, raw["id"], raw["kind"], raw["input"], raw["expect"], raw.get("note"), options)
        vector.level, vector.erratum, vector.requires = level, erratum, requires
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
        version, icd = doc.get("version"), doc.get("icd_revision")
        if version is not None and not (isinstance(version, str) and _SEMVER_RE.fullmatch(version)):
            raise SuiteError(f"{path}: version must be a semver like 1.0.0")
        if icd is not None and not isinstance(icd, str):
            raise SuiteError(f"{path}: icd_revision must be a string like 1.7")
        vectors = _suite_vectors(path, doc["suite"], doc["vectors"])
        suites.append(Suite(doc["suite"], path, vectors, version, icd))
    return suites


def suite_version(suites: list[Suite]) -> dict[str, str | None]:
    """The version and ICD revision of a set of suites, as every report shows them ("a, b" when the
    files disagree; None when none says)."""

    def joined(values: list[str | None]) -> str | None:
        found = sorted({v for v in values if v is not None})
        return ", ".join(found) if found else None

    return {
        "version": joined([s.version for s in suites]),
        "icd_revision": joined([s.icd_revision for s in suites]),
    }
