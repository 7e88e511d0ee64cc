# Copied from generator/targets/python/runtime/conformance/report.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Reports: the table of results, JSON and JUnit XML."""

from __future__ import annotations

import json
import re
from collections.abc import Sequence
from typing import IO, Any
from xml.etree import ElementTree

from .runner import Binding, Case, Cell, Result
from .vectors import Suite, suite_version

__all__ = ["cell_text", "json_report", "junit_xml", "report", "summary_line", "version_text"]


def _cut(text: str, limit: int) -> str:
    return text if len(text) <= limit else text[:limit] + f"... ({len(text)} chars)"


_SHORT = (
    ("failed", "FAILED"),
    ("unexpected_passes", "XPASS"),
    ("expected_failures", "xfail"),
    ("unsupported", "n/s"),
    ("not_applicable", "n/a"),
    ("skipped", "skipped"),
)


def cell_text(cell: Cell) -> str:
    parts = []
    others = [getattr(cell, name) for name, _ in _SHORT]
    if cell.passed or not any(others):
        parts.append(f"{cell.passed} passed")
    parts += [f"{getattr(cell, name)} {word}" for name, word in _SHORT if getattr(cell, name)]
    return ", ".join(parts)


def summary_line(cell: Cell) -> str:
    """The counts of a run, as protobuf's conformance runner gives them."""
    return (
        f"{cell.passed} passed, {cell.failed} failed, {cell.expected_failures} expected failures, "
        f"{cell.unexpected_passes} unexpected passes, {cell.not_applicable} not applicable, "
        f"{cell.skipped} skipped, {cell.unsupported} not supported"
    )


def version_text(suites: list[Suite]) -> str:
    """The suites' version as the reports show it: `suites 1.0.0 (ICD rev 1.7)`."""
    found = suite_version(suites)
    return f"suites {found['version'] or 'unversioned'} (ICD rev {found['icd_revision'] or 'unknown'})"


def _table(result: Result, bindings: list[Binding], suites: list[Suite]) -> list[list[str]]:
    names = [b.name for b in bindings]
    rows = [["suite", *names]]
    totals = {n: Cell() for n in names}
    for suite in suites:
        row = [f"{suite.name} ({len(suite.vectors)})"]
        for n in names:
            cell = result.cells.get((n, suite.name), Cell())
            row.append(cell_text(cell))
            for name, value in vars(cell).items():
                setattr(totals[n], name, getattr(totals[n], name) + value)
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
    out.write(
        "(n/s: a kind or vector option the binding does not list as supported; n/a: not applicable by its "
        "declaration; xfail: an expected failure; XPASS: listed as an expected failure but passed; skipped: "
        "above --level or not chosen by -k)\n"
    )
    for problem in result.problems:
        out.write(f"\nFAILED {problem}\n")
    for shown, failure in enumerate(result.failures):
        if shown == max_failures:
            out.write(f"\n... and {len(result.failures) - shown} more failures (--max-failures)\n")
            break
        v = failure.vector
        out.write(f"\nFAILED {failure.binding} {v.suite} {v.id}: {failure.reason}\n")
        out.write(f"  level:    {v.level}{' ' + v.erratum if v.erratum else ''}\n")
        if v.note:
            out.write(f"  note:     {_cut(v.note, 300)}\n")
        out.write(f"  request:  {_cut(failure.request, 300)}\n")
        out.write(f"  expected: {_cut(json.dumps(v.expect), 300)}\n")
        out.write(f"  actual:   {_cut(failure.answer, 300) if failure.answer else '(no answer)'}\n")


def _implementation(result: Result, binding: Binding) -> dict[str, Any]:
    plan = result.plans.get(binding.name)
    declaration = plan.declaration if plan is not None else None
    return {
        "name": binding.name,
        "declaration": declaration.doc if declaration is not None else None,
        "declaration_file": str(declaration.path) if declaration is not None and declaration.path else None,
        "expected_failures": dict(plan.expected) if plan is not None else {},
        "expected_failures_file": str(binding.expected_failures) if binding.expected_failures else None,
    }


def json_report(result: Result, bindings: list[Binding], suites: list[Suite]) -> dict[str, Any]:
    return {
        "ok": result.ok,
        "suite": suite_version(suites),
        "implementations": [_implementation(result, b) for b in bindings],
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
                "level": f.vector.level,
                "erratum": f.vector.erratum,
            }
            for f in result.failures
        ],
        "cases": [
            {
                "binding": o.binding,
                "suite": o.vector.suite,
                "id": o.vector.id,
                "level": o.vector.level,
                "erratum": o.vector.erratum,
                "outcome": o.outcome,
            }
            for o in result.outcomes
        ],
    }


_XML_UNSAFE = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def _xml_text(text: str, limit: int = 4000) -> str:
    """Text XML 1.0 can carry (control characters as \\xNN), cut to `limit` characters."""
    return _XML_UNSAFE.sub(lambda m: f"\\x{ord(m.group()):02x}", _cut(text, limit))


def junit_xml(
    cases: Sequence[Case], name: str = "ilahrs conformance", properties: dict[str, str | None] | None = None
) -> str:
    """JUnit XML (the Ant/Jenkins form GitHub Actions, GitLab and Jenkins read): one <testsuite>
    per group (binding.suite, or the live flows), one <testcase> per case; a failure carries the
    reason as its message and the request, expectation and answer as its text. `properties` (the
    suites' version and ICD revision) go into every <testsuite>'s <properties>."""
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
        if properties:
            props = ElementTree.SubElement(suite, "properties")
            for key, value in properties.items():
                ElementTree.SubElement(props, "property", {"name": key, "value": value or ""})
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
