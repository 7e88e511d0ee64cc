"""What each vector holds an implementation to: its level of obligation and the features it needs.

Levels (written as "level", with "erratum" for the erratum level), in this order:
  erratum      the vector's expected answer rests on one side of an erratum of spec/ilahrs.yaml that
               has an `alternative` (another reading an implementation may take). Which erratum a
               vector tests is set by the code that writes it ("tests", from the case files or
               computed), never read from its note; an erratum without an alternative (a
               correction) leaves the vector required. A session vector's comes from the spec's
               transitions (state_machine.transitions) instead: the first erratum with an
               alternative among the transitions its inputs take (for a step, step/<state>/<input>,
               the last input's first), E33 where no transition takes an input (it is ignored); a
               flow that passes only through transitions without such an erratum is required
  recommended  robustness beyond the ICD: a stream vector that discards bytes (recovering after
               garbage, damaged frames, false starts), which no ICD section asks a decoder to do
  required     everything else: what the ICD states, or the only reading of it

Features (written as "requires", only the non-empty ones), what a declaration must list for the
vector to apply: "commands" (Table C.1 names the vector sends, encodes or decodes), "outputs" (the
output formats the commands of a session start), "payloads" (payload tables), "variants", "nmea" ($PAHR:
nmea vectors and stream vectors with a sentence among their events) and "firmware" (a modelled
firmware behaviour: legacy_stop_clb, a session on firmware before the spec's firmware_before).
"""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path
from typing import Any

import oracle as o
import yaml

SPEC_FILE = Path(__file__).resolve().parents[3] / "spec" / "ilahrs.yaml"

LEGACY_STOP_CLB = "legacy_stop_clb"
_ERRATUM = re.compile(r"\bE\d+\b")


@cache
def spec() -> dict[str, Any]:
    with SPEC_FILE.open(encoding="utf-8") as file:
        doc: dict[str, Any] = yaml.safe_load(file)
    return doc


def icd_revision() -> str:
    return str(spec()["spec"]["icd"]["revision"])


@cache
def _errata() -> frozenset[str]:
    return frozenset(e["id"] for e in spec()["errata"])


@cache
def alternatives() -> dict[str, str]:
    """Each erratum of the spec with another reading an implementation may take -> that reading."""
    return {e["id"]: str(e["alternative"]) for e in spec()["errata"] if "alternative" in e}


def _choice(erratum: str | None) -> str | None:
    """The erratum if an implementation may take its other side, else None (none, or a correction)."""
    return erratum if erratum is not None and erratum in alternatives() else None


def variant_erratum(variant: str) -> str | None:
    """The erratum a device variant of the spec rests on (its scales assumed), if any."""
    (found,) = [v for v in spec()["variants"]["list"] if v["name"] == variant]
    erratum = found.get("erratum")
    return None if erratum is None else str(erratum)


def _commands() -> dict[str, dict[str, Any]]:
    return {c["name"]: c for c in spec()["commands"]}


def _firmware_before() -> str:
    (before,) = {t["firmware_before"] for t in spec()["state_machine"]["transitions"] if "firmware_before" in t}
    return str(before)


def _version(text: str) -> tuple[int, ...]:
    return tuple(int(part) for part in text.split("."))


def _tested(vector: dict[str, Any]) -> str | None:
    """The erratum the code that wrote the vector says it tests (checked against its note)."""
    note = vector.get("note", "")
    for erratum in _ERRATUM.findall(note):
        assert erratum in _errata(), f"{vector['id']}: its note cites {erratum}, which spec/ilahrs.yaml does not have"
    tested = vector.get("tests")
    if tested is None:
        return None
    assert tested in _errata(), f"{vector['id']} tests {tested}, which spec/ilahrs.yaml does not have"
    assert tested in _ERRATUM.findall(note), f"{vector['id']} tests {tested}: its note must say so"
    return str(tested)


def _transition_erratum(before: str, event: str, firmware: str | None) -> str | None:
    """The erratum of the spec's transition `event` takes in state `before` (E33: none takes it)."""
    commands = _commands()
    legacy = firmware is not None and _version(firmware) < _version(_firmware_before())
    for exact in (True, False):
        for t in spec()["state_machine"]["transitions"]:
            if before not in t["from"] or ("firmware_before" in t and not legacy):
                continue
            if (event in t["when"]) if exact else ("*" in t["when"] and event in commands):
                return _choice(t.get("erratum"))
    return _choice("E33")


def _session_erratum(vector: dict[str, Any]) -> str | None:
    """The first erratum with an alternative among the transitions a session vector's inputs take
    (for a step, its last input's first): its expected steps rest on that erratum's side."""
    steps = vector["expect"]["steps"]
    firmware = vector["input"].get("firmware")
    states = [spec()["state_machine"]["initial"], *(s["state"] for s in steps)]
    found = [_transition_erratum(states[i], step["event"], firmware) for i, step in enumerate(steps)]
    if vector["id"].startswith("step/"):
        found = [found[-1], *found[:-1]]
    return next((e for e in found if e is not None), None)


def level(vector: dict[str, Any]) -> tuple[str, str | None]:
    """(level, erratum) of a vector as make_vectors writes it (see the module's note)."""
    tested = _tested(vector)
    erratum = _session_erratum(vector) if vector["kind"] == "session" else _choice(tested)
    if erratum is not None:
        return "erratum", erratum
    if vector["kind"] == "stream" and vector["expect"]["discarded"] > 0:
        return "recommended", None
    return "required", None


def _frame_command(data: bytes) -> list[str]:
    """The Table C.1 names of a one-byte command frame's code ([] for anything else)."""
    if len(data) == 9 and data[:2] == b"\xaa\x55" and data[2] == o.COMMAND:
        return list(o.command_names(data[6]))
    return []


def requires(vector: dict[str, Any]) -> dict[str, Any]:
    """The features a declaration must list for the vector to apply (see the module's note)."""
    kind, input_, expect = vector["kind"], vector["input"], vector["expect"]
    refused = isinstance(expect, dict) and "error" in expect
    commands: list[str] = []
    if kind == "command_encode":
        commands = [input_["command"]]
    elif kind == "command_decode" and not refused:
        commands = list(expect["names"])
    elif kind == "ack" and not refused:
        commands = _frame_command(bytes.fromhex(input_.replace(" ", "")))
    elif kind == "session":
        known = _commands()
        commands = sorted({s["event"] for s in expect["steps"] if s["event"] in known})
    commands = [c for c in commands if c in _commands()]
    out: dict[str, Any] = {}
    if commands:
        out["commands"] = sorted(set(commands))
        starts = {_commands()[c].get("starts", {}).get("output") for c in commands} - {None}
        if starts and kind == "session":  # only a session makes the output flow
            out["outputs"] = sorted(starts)
    if kind in ("payload_decode", "payload_encode"):
        out["payloads"] = [input_["type"]]
        if "variant" in input_:
            out["variants"] = [input_["variant"]]
    if kind in ("nmea_decode", "nmea_encode") or (
        kind == "stream" and any("nmea" in event for event in expect["events"])
    ):
        out["nmea"] = True
    firmware = input_.get("firmware") if kind == "session" else None
    if firmware is not None and _version(firmware) < _version(_firmware_before()):
        out["firmware"] = [LEGACY_STOP_CLB]
    return out


def annotate(vector: dict[str, Any]) -> dict[str, Any]:
    """The vector with its level (and erratum) and requirements, after "note"."""
    lvl, erratum = level(vector)
    out = {k: v for k, v in vector.items() if k != "tests"}
    out["level"] = lvl
    if erratum is not None:
        out["erratum"] = erratum
    needs = requires(vector)
    if needs:
        out["requires"] = needs
    return out
