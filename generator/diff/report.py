"""What the comparison reports: the text a person reads, the JUnit XML a CI reads, and the version
bump the changes require (major for a breaking change, minor for an additive one, patch for
documentation; before 1.0.0 a breaking change needs a minor bump).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Sequence
from pathlib import Path

from ..model import Spec
from .fingerprint import wire_fingerprint
from .rules import ADDITIVE, API, BUMPS, CLASSES, DOCS, RULES, WIRE, Change

# The required bump and the version check.


def _version(text: str) -> tuple[int, int, int]:
    parts = text.split("-", maxsplit=1)[0].split("+", maxsplit=1)[0].split(".")
    return int(parts[0]), int(parts[1]) if len(parts) > 1 else 0, int(parts[2]) if len(parts) > 2 else 0


def required_bump(changes: Sequence[Change], old_version: str) -> str | None:
    """major, minor or patch (None: no change). Before 1.0.0 a breaking change needs a minor bump."""
    classes = {c.cls for c in changes}
    if not classes:
        return None
    if classes & {WIRE, API}:
        return "major" if _version(old_version)[0] > 0 else "minor"
    if ADDITIVE in classes:
        return "minor" if _version(old_version)[0] > 0 else "patch"
    return "patch"


def actual_bump(old_version: str, new_version: str) -> str | None:
    a, b = _version(old_version), _version(new_version)
    if b <= a:
        return None
    if b[0] > a[0]:
        return "major"
    if b[1] > a[1]:
        return "minor"
    return "patch"


def bump_is_enough(required: str | None, actual: str | None) -> bool:
    if required is None:
        return True
    return actual is not None and BUMPS.index(actual) <= BUMPS.index(required)


# The report.


def print_text(changes: Sequence[Change], old: Spec, new: Spec, required: str | None, actual: str | None) -> None:
    """Each change on a line, then the counts by class, the wire fingerprints and the bump."""
    enough = bump_is_enough(required, actual)
    for c in changes:
        print(c.line())
    counts = ", ".join(f"{sum(c.cls == k for c in changes)} {k}" for k in CLASSES)
    print(f"{len(changes)} changes ({counts})")
    fp_old, fp_new = wire_fingerprint(old), wire_fingerprint(new)
    print(f"wire fingerprint {fp_old:#018x} -> {fp_new:#018x}" + (" (same)" if fp_old == fp_new else ""))
    print(
        f"required bump: {required or 'none'}; version {old.version} -> {new.version} ({actual or 'no bump'})"
        + ("" if enough else ": NOT ENOUGH")
    )


def write_junit(path: Path, changes: Sequence[Change], required: str | None, enough: bool, checked: bool) -> None:
    suite = ET.Element("testsuite", name="spec-compatibility", tests=str(len(changes) + 1))
    failures = 0
    for c in changes:
        case = ET.SubElement(suite, "testcase", classname=f"spec.{c.cls}", name=f"{c.rule} {c.where}")
        breaking = (
            checked
            and not enough
            and c.cls != DOCS
            and BUMPS.index(_bump_of(c.cls)) <= BUMPS.index(required or "patch")
        )
        if breaking:
            failures += 1
            ET.SubElement(case, "failure", message=RULES[c.rule][1], type=c.rule).text = c.line()
        else:
            ET.SubElement(case, "system-out").text = c.line()
    case = ET.SubElement(suite, "testcase", classname="spec.version", name="version bump")
    if checked and not enough:
        failures += 1
        ET.SubElement(case, "failure", message=f"a {required} version bump is required", type="VERSION_BUMP")
    suite.set("failures", str(failures))
    tree = ET.ElementTree(suite)
    ET.indent(tree)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tree.write(tmp, encoding="utf-8", xml_declaration=True)
    tmp.replace(path)


def _bump_of(cls: str) -> str:
    return {WIRE: "major", API: "major", ADDITIVE: "minor", DOCS: "patch"}[cls]
