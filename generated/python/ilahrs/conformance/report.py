# Copied from generator/targets/python/runtime/conformance/report.py for spec/ilahrs.yaml,
# spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the runtime source and run `make generate`.
"""Reports: the table of results, JSON and JUnit XML."""

from __future__ import annotations

import json
import re
from collections.abc import Sequence
from typing import IO, Any
from xml.etree import ElementTree

from .runner import Binding, Case, Cell, Result
from .vectors import Suite

__all__ = ["cell_text", "json_report", "junit_xml", "report"]


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
