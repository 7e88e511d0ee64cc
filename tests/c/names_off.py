"""The C binding built with -DILAHRS_NAMES=0 against the default build (make test-c).

Compiled with ILAHRS_NAMES=0 (header and ilahrs.c), the library holds no name strings: the name
functions (REMOVED below) are neither declared nor defined, every error's `field` is NULL, and
everything else answers exactly as in the default build. This checks:

- the driver tests/c/names_off.c, built by default (REFERENCE) and with ILAHRS_NAMES=0 and the
  same compiler and flags otherwise (NAMES-OFF), prints the same text for the same inputs (the
  driver's first line, ILAHRS_NAMES=1 or =0, tells the builds apart): every byte string of the
  conformance vectors (inputs and expected bytes) and the chunks of damaged captures
  (tests/c/differential.py); the NAMES=0 driver itself stops if an error's field is not NULL;
- the comparison is not vacuous: enough payload parses, frames, sentences and errors happened;
- a call to a removed function does not compile with -DILAHRS_NAMES=0 (gcc -std=c99 -Werror) and
  compiles by default;
- ilahrs.c compiled with -DILAHRS_NAMES=0 defines none of the removed functions and its read-only
  data holds none of the command, payload, field, variant, state and event names that the
  default build's holds.

    python tests/c/names_off.py CAPTURE-TOOL REFERENCE NAMES-OFF [REFERENCE NAMES-OFF ...]

CAPTURE-TOOL is build/c/capture; each REFERENCE and NAMES-OFF pair are names_off.c builds, as command
lines. A pair must share everything but ILAHRS_NAMES: builds optimized for speed and for size may
hand a stream message out after consuming a different number of bytes, which the driver prints.
"""

from __future__ import annotations

import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import differential

import ilahrs
from ilahrs import statemachine

ROOT = Path(__file__).resolve().parent.parent.parent
C_DIR = ROOT / "generated" / "c"
CC = "gcc"
# The warning flags of mk/c.mk when run by make (C_STD in the environment).
C_STD = shlex.split(os.environ.get("C_STD", "-std=c99 -Wall -Werror"))

REMOVED = ("ilahrs_mode_name", "ilahrs_command_name", "ilahrs_command_by_name", "ilahrs_variant_name",
           "ilahrs_variant_by_name", "ilahrs_payload_name", "ilahrs_payload_by_name", "ilahrs_field_name",
           "ilahrs_usw_flag_name", "ilahrs_pahr_field_name", "ilahrs_state_name", "ilahrs_state_by_name",
           "ilahrs_event_name", "ilahrs_event_by_name", "ilahrs_answer_name")
KEPT = ("ilahrs_error_kind_name", "ilahrs_variant_part_number")

CAPTURE_SEEDS = (2, 3, 5, 7)
# At least this many of each in the compared output, or the comparison proves little.
MINIMUM = {"inputs": 1000, "payload parses": 300, "frames": 1000, "sentences": 200, "errors": 5000,
           "transitions": 1000}


def vector_bytes(kind: str, value: Any, side: str) -> list[bytes]:
    """The byte strings in a vector's input or expectation (`side`)."""
    if isinstance(value, dict) and "error" in value:
        return []
    hex_inputs = {"checksum", "frame_decode", "command_decode", "ack"}
    hex_expects = {"ack", "command_encode", "frame_encode", "payload_encode"}
    if side == "input":
        if kind in hex_inputs:
            return [bytes.fromhex(value)]
        if kind == "payload_decode":
            return [bytes.fromhex(value["hex"])]
        if kind == "frame_encode":
            return [bytes.fromhex(value["payload"])]
        if kind == "nmea_decode":
            return [value.encode("latin-1")]
        if kind == "stream":
            return [bytes.fromhex("".join(value["chunks"]))]
        return []
    if kind in hex_expects and isinstance(value, str):
        return [bytes.fromhex(value)]
    if kind == "nmea_encode" and isinstance(value, str):
        return [value.encode("latin-1")]
    if kind == "stream":
        return [bytes.fromhex(e["frame"]) if "frame" in e else e["nmea"].encode("latin-1") for e in value["events"]]
    return []


def collect_inputs(tool: str, directory: Path) -> list[bytes]:
    """Every byte string of the vectors, then the chunks of damaged captures; no repeats."""
    found: dict[bytes, None] = {}
    for path in sorted((ROOT / "conformance" / "vectors").glob("*.json")):
        for vector in json.loads(path.read_text(encoding="utf-8"))["vectors"]:
            for side in ("input", "expect"):
                for data in vector_bytes(vector["kind"], vector[side], side):
                    found.setdefault(data)
    vectors = len(found)
    for seed in CAPTURE_SEEDS:
        for chunk in differential.damaged_capture(tool, seed, directory)[1]:
            found.setdefault(chunk)
    print(f"{len(found)} inputs: {vectors} byte strings of the vectors, {len(found) - vectors} chunks of "
          f"{len(CAPTURE_SEEDS)} damaged captures")
    return list(found)


def run_driver(driver: str, inputs: Path) -> tuple[int, list[str]]:
    result = subprocess.run([*shlex.split(driver), str(inputs)], capture_output=True, text=True, check=False)
    lines = result.stdout.splitlines()
    if result.stderr:
        lines += ["stderr: " + line for line in result.stderr.splitlines()]
    return result.returncode, lines


def first_difference(want: list[str], got: list[str]) -> str:
    at = next((i for i, (a, b) in enumerate(zip(want, got, strict=False)) if a != b), min(len(want), len(got)))
    block = next((want[i] for i in range(min(at, len(want) - 1), -1, -1) if re.match(r"input \d+ len=", want[i])), "")
    shown = [f"  first difference at line {at + 2} ({block or 'before the first input'}):"]
    for name, lines in (("reference", want), ("names off", got)):
        for line in lines[at : at + 3] or ["(end of output)"]:
            shown.append(f"  {name}: {line[:400]}")
    return "\n".join(shown)


def counts(lines: list[str]) -> dict[str, int]:
    return {
        "inputs": sum(bool(re.match(r"input \d+ len=", line)) for line in lines),
        "payload parses": sum(bool(re.match(r"P\d+ ok ", line)) for line in lines),
        "frames": sum(line.startswith("  F ") for line in lines),
        "sentences": sum(line.startswith(("  S ", "pahr_parse ok")) for line in lines),
        "errors": sum(line.count(" err=") for line in lines),
        "transitions": sum(len(re.findall(r" [a-z]+:\d+:\d+>1/", line)) for line in lines
                           if line.startswith(("states", "walk"))),
    }


def compare(reference: str, names_off: str, inputs: Path) -> tuple[list[str], list[str]]:
    """Run both drivers over the inputs: the failures and the reference's output."""
    failures = []
    outputs = []
    for driver, first in ((reference, "ILAHRS_NAMES=1"), (names_off, "ILAHRS_NAMES=0")):
        status, lines = run_driver(driver, inputs)
        outputs.append(lines)
        if not lines or lines[0] != first:
            failures.append(f"{driver}: first line {lines[:1]}, want {first}")
        if status != 0:
            fails = [line for line in lines if line.startswith(("FAIL", "stderr:"))] or lines[-2:]
            failures.append(f"{driver}: exit status {status}\n" + "\n".join("  " + line[:400] for line in fails[:5]))
    want, got = outputs
    if failures:
        return failures, want
    found = counts(want)
    print(f"{reference}: " + ", ".join(f"{n} {name}" for name, n in found.items()) + f", {len(want)} lines")
    failures += [f"{reference}: only {found[name]} {name} (want at least {n}): the comparison proves little"
                 for name, n in MINIMUM.items() if found[name] < n]
    failures += [f"{reference}: {line[:400]}" for line in want if "MISMATCH" in line][:3]
    if got[1:] != want[1:]:
        failures.append(f"{names_off}: output differs from {reference}\n{first_difference(want[1:], got[1:])}")
    else:
        print(f"{names_off}: the same {len(got) - 1} lines")
    return failures, want


def compiles(source: str, names: int | None, directory: Path) -> tuple[bool, str]:
    path = directory / "snippet.c"
    path.write_text(source, encoding="ascii")
    define = [] if names is None else [f"-DILAHRS_NAMES={names}"]
    result = subprocess.run([CC, *C_STD, *define, f"-I{C_DIR}", "-fsyntax-only", str(path)],
                            capture_output=True, text=True, check=False)
    return result.returncode == 0, result.stderr


def compile_checks(directory: Path) -> list[str]:
    """A call to ilahrs_command_name, and a mention of every removed function, compile by default
    and not with ILAHRS_NAMES=0; the functions that stay compile in both."""
    call = ('#include "ilahrs.h"\n#include <stddef.h>\n'
            "int main(void) { return ilahrs_command_name(ILAHRS_COMMAND_STOP) != NULL; }\n")
    snippets = [("a call to ilahrs_command_name", call, False)]
    snippets += [(name, f'#include "ilahrs.h"\nint main(void) {{ (void){name}; return 0; }}\n', False)
                 for name in REMOVED]
    snippets += [(name, f'#include "ilahrs.h"\nint main(void) {{ (void){name}; return 0; }}\n', True) for name in KEPT]
    failures = []
    for what, source, kept in snippets:
        for names in (None, 1):
            ok, errors = compiles(source, names, directory)
            if not ok:
                flag = "default build" if names is None else "-DILAHRS_NAMES=1"
                failures.append(f"{what} does not compile ({flag}):\n  " + errors.strip()[:600])
        ok, errors = compiles(source, 0, directory)
        if ok != kept:
            failures.append(f"{what} {'does not compile' if kept else 'compiles'} with -DILAHRS_NAMES=0"
                            + (":\n  " + errors.strip()[:600] if errors else ""))
    print(f"compile checks: {len(snippets)} snippets, each by default, with -DILAHRS_NAMES=1 and =0")
    return failures


def library_names() -> set[str]:
    """Names the library may hold: commands, payload tables and their fields, variants, states, events."""
    names = set(ilahrs.COMMANDS) | set(ilahrs.VARIANTS) | set(statemachine.STATES) | set(statemachine.EVENTS)
    for name, payload in ilahrs.PAYLOADS.items():
        names.add(name)
        names.update(field.name for field in payload.FIELDS)
    return names


def object_strings(names: int, directory: Path) -> tuple[set[str], set[str]]:
    """ilahrs.c compiled with ILAHRS_NAMES=`names`: its defined functions and its read-only strings."""
    obj = directory / f"ilahrs-names{names}.o"
    data = directory / f"ilahrs-names{names}.rodata"
    subprocess.run([CC, *C_STD, "-O2", f"-DILAHRS_NAMES={names}", "-c", str(C_DIR / "ilahrs.c"), "-o", str(obj)],
                   check=True)
    symbols = subprocess.run(["nm", "--defined-only", str(obj)], capture_output=True, text=True, check=True).stdout
    subprocess.run(["objcopy", "-O", "binary", "-j", ".rodata*", str(obj), str(data)], check=True)
    defined = {line.split()[-1] for line in symbols.splitlines() if line.strip()}
    return defined, set(data.read_bytes().decode("latin-1").split("\0"))


def object_checks(directory: Path, error_kinds: set[str]) -> list[str]:
    failures = []
    defined_on, strings_on = object_strings(1, directory)
    defined_off, strings_off = object_strings(0, directory)
    failures += [f"ilahrs.c with ILAHRS_NAMES=1 does not define {name}" for name in REMOVED + KEPT
                 if name not in defined_on]
    failures += [f"ilahrs.c with ILAHRS_NAMES=0 defines {name}" for name in REMOVED if name in defined_off]
    failures += [f"ilahrs.c with ILAHRS_NAMES=0 does not define {name}" for name in KEPT if name not in defined_off]
    # Error kind names stay (ilahrs_error_kind_name), and "unknown" is one of them.
    held = (library_names() & strings_on) - error_kinds
    if len(held) < 50:
        failures.append(f"only {len(held)} names found in the default build's read-only data: is the check blind?")
    left = sorted(held & strings_off)
    if left:
        failures.append(f"ilahrs.c with ILAHRS_NAMES=0 still holds {len(left)} names: {', '.join(left[:12])}")
    print(f"object checks: {len(REMOVED)} functions gone, {len(held)} names of the default build looked for")
    return failures


def main(argv: list[str]) -> int:
    if len(argv) < 4 or len(argv) % 2 != 0:
        print(__doc__, file=sys.stderr)
        return 2
    tool, drivers = argv[1], argv[2:]
    with tempfile.TemporaryDirectory() as tmp:
        directory = Path(tmp)
        failures = compile_checks(directory)
        inputs = directory / "inputs.txt"
        inputs.write_text("".join(data.hex() + "\n" for data in collect_inputs(tool, directory)), encoding="ascii")
        error_kinds: set[str] = set()
        for reference, names_off in zip(drivers[::2], drivers[1::2], strict=True):
            differ, want = compare(reference, names_off, inputs)
            failures += differ
            error_kinds |= {line.split()[2] for line in want if line.startswith("error_kind ")}
        failures += object_checks(directory, error_kinds)
    for failure in failures:
        print("FAILED " + failure)
    print(f"names off: {'FAILED' if failures else 'passed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
