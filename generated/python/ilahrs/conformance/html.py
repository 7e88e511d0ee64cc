# Copied from generator/targets/python/runtime/conformance/html.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The results of a run as one self-contained HTML page: the suite x implementation matrix, each
implementation's declaration and expected failures, and every failure with its request, expectation
and answer.

`render` takes the dict `json_report` makes (what `--json` writes) and returns the page: inline CSS,
no script, no fonts, images or links to fetch, so it opens from a file, a CI artifact or an e-mail
as it is. The keys of a run with levels, declarations and expected failures ("suite",
"implementations", "cases", the extra counts of "results" and "level" of "failures") are shown
when present; a report without them renders too. The same dict gives the same page, byte for
byte (no date, no machine name): a report can be committed or compared.
"""

from __future__ import annotations

import html
import json
import os
import re
import tempfile
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

__all__ = ["COUNTS", "render", "write"]

COUNTS: tuple[tuple[str, str, str], ...] = (
    # (key in a "results" entry, label, CSS class of the label)
    ("passed", "passed", "pass"),
    ("failed", "failed", "fail"),
    ("unexpected_passes", "unexpected pass", "fail"),
    ("expected_failures", "expected failure", "xfail"),
    ("unsupported", "not supported", "muted"),
    ("not_applicable", "not applicable", "muted"),
    ("skipped", "skipped", "muted"),
)
"""The counts of one cell of the matrix, in the order shown. "skipped" is counted from "cases"
where the "results" entries do not carry it."""

_OUTCOMES = {  # a case's outcome (in "cases") -> its label, as COUNTS names it
    "passed": "passed",
    "failed": "failed",
    "unexpected_pass": "unexpected pass",
    "expected_failure": "expected failure",
    "unsupported": "not supported",
    "not_applicable": "not applicable",
    "skipped": "skipped",
}
_LEVELS = ("required", "recommended", "erratum")

_STYLE = """
body { font: 14px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; color: #1d232b; background: #fff;
  margin: 0 auto; padding: 1.5em 2em 3em; max-width: 80em; }
h1 { font-size: 1.6em; margin: 0 0 .2em; }
h2 { font-size: 1.25em; margin: 1.8em 0 .6em; border-bottom: 1px solid #d5dae0; padding-bottom: .2em; }
h3 { font-size: 1.05em; margin: 1.2em 0 .4em; }
.meta { color: #4a5462; margin: 0 0 1em; }
.verdict { display: inline-block; font-weight: 700; padding: .25em .8em; border-radius: .3em; }
.verdict.pass { background: #d8f0dc; color: #14532d; }
.verdict.fail { background: #f9d6d5; color: #7f1d1d; }
table { border-collapse: collapse; margin: .4em 0 1em; }
th, td { border: 1px solid #d5dae0; padding: .35em .6em; text-align: left; vertical-align: top; }
thead th { background: #eef1f4; }
tbody th { font-weight: 600; white-space: nowrap; }
td.cell { min-width: 9em; }
td.pass { background: #e3f4e6; }
td.fail { background: #fbe0df; }
td.xfail { background: #fdf1d6; }
td.empty { background: #f3f4f6; color: #6b7280; }
tr.total th, tr.total td { border-top: 2px solid #9aa3ad; }
.count { display: block; white-space: nowrap; }
.count b { font-variant-numeric: tabular-nums; }
.count.fail { color: #991b1b; font-weight: 600; }
.count.fail a { color: inherit; }
.count.xfail { color: #8a5a00; }
.count.muted { color: #5b6572; }
.legend span { display: inline-block; margin-right: 1.2em; }
.swatch { display: inline-block; width: .9em; height: .9em; border: 1px solid #9aa3ad; vertical-align: -.1em;
  margin-right: .3em; }
details { border: 1px solid #d5dae0; border-radius: .3em; margin: .35em 0; padding: .3em .7em; }
details[open] { background: #fafbfc; }
summary { cursor: pointer; }
summary .id { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-weight: 600; }
.tag { display: inline-block; font-size: .8em; padding: 0 .45em; border-radius: .25em; margin-left: .3em;
  background: #e5e7eb; color: #374151; }
.tag.required { background: #dbe7fb; color: #1e3a8a; }
.tag.recommended { background: #e7e1f7; color: #4c1d95; }
.tag.erratum { background: #fdeccc; color: #7c4a03; }
.tag.unexpected { background: #f9d6d5; color: #7f1d1d; }
dl.failure { display: grid; grid-template-columns: max-content 1fr; gap: .25em .8em; margin: .5em 0 .2em; }
dl.failure dt { font-weight: 600; }
dl.failure dd { margin: 0; min-width: 0; }
pre { font: 12.5px/1.4 ui-monospace, "DejaVu Sans Mono", monospace; margin: 0; padding: .3em .5em;
  background: #f3f4f6; border-radius: .25em; white-space: pre-wrap; overflow-wrap: anywhere; }
.none { color: #6b7280; font-style: italic; }
ul.problems li { color: #7f1d1d; }
@media print { details { break-inside: avoid; } }
"""

_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\ud800-\udfff\ufdd0-\ufdef\ufffe\uffff]")


def _visible(match: re.Match[str]) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def _e(value: object) -> str:
    """Text for HTML: escaped, and the characters a page cannot show (control characters, lone
    surrogates, noncharacters) written as \\xNN or \\uNNNN, so that what a runner sent stays visible."""
    return html.escape(_UNSAFE.sub(_visible, str(value)), quote=True)


def _json(value: object) -> str:
    return json.dumps(value, ensure_ascii=False, indent=None if not isinstance(value, (dict, list)) else 1)


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def _count(value: object) -> int:
    return value if isinstance(value, int) and not isinstance(value, bool) else 0


def _dicts(value: object) -> list[Mapping[str, Any]]:
    return [v for v in value if isinstance(v, Mapping)] if isinstance(value, list) else []


def _unique(names: Iterable[object]) -> list[str]:
    return list(dict.fromkeys(str(n) for n in names if n is not None))


class _Report:
    """The report dict read once, tolerating absent keys (a report from before levels) and values
    of the wrong type (shown as far as they go, never an exception)."""

    def __init__(self, doc: Mapping[str, Any]) -> None:
        self.doc = doc
        suite = doc.get("suite")
        self.suite: Mapping[str, Any] = suite if isinstance(suite, Mapping) else {}
        self.results = _dicts(doc.get("results"))
        self.failures = _dicts(doc.get("failures"))
        self.cases = _dicts(doc.get("cases")) if "cases" in doc else None
        self.implementations = {str(i.get("name")): i for i in _dicts(doc.get("implementations"))}
        problems = doc.get("problems")
        self.problems = [str(p) for p in problems] if isinstance(problems, list) else []
        self.bindings = _unique(
            [
                *self.implementations,
                *(r.get("binding") for r in self.results),
                *(f.get("binding") for f in self.failures),
            ]
        )
        self.suites = _unique([*(r.get("suite") for r in self.results), *(f.get("suite") for f in self.failures)])
        self.cells: dict[tuple[str, str], dict[str, int]] = {}
        for r in self.results:
            cell = self.cell(str(r.get("binding")), str(r.get("suite")))
            for key, _, _ in COUNTS:
                cell[key] += _count(r.get(key))
        counted = any("skipped" in r for r in self.results)
        for c in [] if counted else self.cases or []:
            if c.get("outcome") == "skipped":
                self.cell(str(c.get("binding")), str(c.get("suite")))["skipped"] += 1

    def cell(self, binding: str, suite: str) -> dict[str, int]:
        return self.cells.setdefault((binding, suite), {key: 0 for key, _, _ in COUNTS})

    @property
    def ok(self) -> bool:
        ok = self.doc.get("ok")
        return ok if isinstance(ok, bool) else not (self.failures or self.problems)

    def version_text(self) -> str:
        version, icd = self.suite.get("version"), self.suite.get("icd_revision")
        parts = [f"suite version {version}" if version else "suite version not recorded"]
        if icd:
            parts.append(f"ICD revision {icd}")
        return ", ".join(parts)


def _cell_class(counts: Mapping[str, int]) -> str:
    if counts["failed"] or counts["unexpected_passes"]:
        return "fail"
    if counts["expected_failures"]:
        return "xfail"
    return "pass" if counts["passed"] else "empty"


def _cell_html(counts: Mapping[str, int], failures: str | None) -> str:
    """The counts of a cell; a failure count links to the binding's failures (`failures`: their
    anchor, None when it has none listed)."""
    shown = []
    for key, label, css in COUNTS:
        if counts[key]:
            text = f"<b>{counts[key]}</b> {label}"
            if css == "fail" and failures:
                text = f'<a href="#{failures}">{text}</a>'
            shown.append(f'<span class="count {css}" data-count="{key}">{text}</span>')
    return "".join(shown) or '<span class="count muted">nothing run</span>'


def _anchor(r: _Report, binding: str) -> str | None:
    """The id of a binding's failures heading (by position: a name may hold any character)."""
    listed = any(str(f.get("binding")) == binding for f in r.failures)
    return f"failures-{r.bindings.index(binding) + 1}" if listed else None


def _matrix(r: _Report) -> list[str]:
    out = ['<h2 id="matrix">Suites &times; implementations</h2>']
    if not r.bindings or not r.suites:
        return [*out, '<p class="none">No results in this report.</p>']
    out.append('<table class="matrix"><thead><tr><th scope="col">suite</th>')
    out += [f'<th scope="col" data-binding="{_e(b)}">{_e(b)}</th>' for b in r.bindings]
    out.append("</tr></thead><tbody>")
    totals = {b: {key: 0 for key, _, _ in COUNTS} for b in r.bindings}
    for suite in r.suites:
        out.append(f'<tr data-suite="{_e(suite)}"><th scope="row">{_e(suite)}</th>')
        for b in r.bindings:
            counts = r.cells.get((b, suite)) or {key: 0 for key, _, _ in COUNTS}
            for key in counts:
                totals[b][key] += counts[key]
            out.append(
                f'<td class="cell {_cell_class(counts)}" data-binding="{_e(b)}" data-suite="{_e(suite)}">'
                f"{_cell_html(counts, _anchor(r, b))}</td>"
            )
        out.append("</tr>")
    out.append('<tr class="total"><th scope="row">total</th>')
    out += [
        f'<td class="cell {_cell_class(totals[b])}" data-binding="{_e(b)}" data-suite="">'
        f"{_cell_html(totals[b], _anchor(r, b))}</td>"
        for b in r.bindings
    ]
    out.append("</tr></tbody></table>")
    out.append(
        '<p class="legend">'
        '<span><span class="swatch" style="background:#e3f4e6"></span>all run passed</span>'
        '<span><span class="swatch" style="background:#fbe0df"></span>a failure or an unexpected pass</span>'
        '<span><span class="swatch" style="background:#fdf1d6"></span>expected failures only</span>'
        '<span><span class="swatch" style="background:#f3f4f6"></span>nothing run</span></p>'
        '<p class="meta">not supported: a kind or vector option the implementation does not list; '
        "not applicable: left out by its declaration; skipped: left out by the level or -k chosen.</p>"
    )
    return out


def _levels(r: _Report) -> list[str]:
    """Outcomes by level of obligation and implementation (only with "cases")."""
    if not r.cases:
        return []
    table: dict[tuple[str, str], dict[str, int]] = {}
    levels: list[str] = [*_LEVELS]
    for c in r.cases:
        level = str(c.get("level") or "unstated")
        if level not in levels:
            levels.append(level)
        outcome = str(c.get("outcome"))
        counts = table.setdefault((level, str(c.get("binding"))), {})
        counts[outcome] = counts.get(outcome, 0) + 1
    used = [level for level in levels if any(key[0] == level for key in table)]
    out = ['<h2 id="levels">By level of obligation</h2><table class="levels"><thead><tr><th scope="col">level</th>']
    out += [f'<th scope="col">{_e(b)}</th>' for b in r.bindings]
    out.append("</tr></thead><tbody>")
    for level in used:
        tag = f'<span class="tag {_e(level)}">{_e(level)}</span>'
        out.append(f'<tr data-level="{_e(level)}"><th scope="row">{tag}</th>')
        for b in r.bindings:
            counts = table.get((level, b), {})
            outcomes = [*_OUTCOMES, *sorted(set(counts) - set(_OUTCOMES))]
            text = ", ".join(f"{counts[o]} {_OUTCOMES.get(o, o)}" for o in outcomes if counts.get(o))
            out.append(f'<td data-binding="{_e(b)}">{_e(text) or "&ndash;"}</td>')
        out.append("</tr>")
    out.append("</tbody></table>")
    return out


def _implementations(r: _Report) -> list[str]:
    if not r.implementations:
        return []
    out = ['<h2 id="implementations">Implementations</h2>']
    for name in r.bindings:
        impl = r.implementations.get(name)
        if impl is None:
            continue
        out.append(f'<section class="implementation" data-binding="{_e(name)}"><h3>{_e(name)}</h3>')
        declaration, declaration_file = impl.get("declaration"), impl.get("declaration_file")
        if declaration is None:
            out.append('<p class="none">No declaration: every vector applies.</p>')
        else:
            source = f" ({_e(declaration_file)})" if declaration_file else ""
            out.append(
                f'<details class="declaration"><summary>Declaration{source}</summary>'
                f"<pre>{_e(_json(declaration))}</pre></details>"
            )
        expected = impl.get("expected_failures")
        expected_file = impl.get("expected_failures_file")
        source = f" ({_e(expected_file)})" if expected_file else ""
        if isinstance(expected, Mapping) and expected:
            out.append(
                f'<details class="expected-failures"><summary>{_plural(len(expected), "expected failure")}'
                f"{source}</summary>"
                '<table><thead><tr><th scope="col">vector</th><th scope="col">reason</th></tr></thead><tbody>'
            )
            out += [
                f'<tr><td class="id">{_e(vector)}</td><td>{_e(reason)}</td></tr>' for vector, reason in expected.items()
            ]
            out.append("</tbody></table></details>")
        else:
            out.append(f'<p class="none">No expected failures{source}.</p>')
        out.append("</section>")
    return out


def _failure(f: Mapping[str, Any]) -> str:
    level, erratum = f.get("level"), f.get("erratum")
    reason = str(f.get("reason", ""))
    tags = ""
    if level:
        tags += f'<span class="tag {_e(level)}" data-level="{_e(level)}">{_e(level)}</span>'
    if erratum:
        tags += f'<span class="tag erratum">{_e(erratum)}</span>'
    if reason.startswith("unexpected pass"):
        tags += '<span class="tag unexpected">unexpected pass</span>'
    actual = f.get("actual")
    fields = [
        ("request", f"<pre>{_e(f.get('request', ''))}</pre>"),
        ("expected", f"<pre>{_e(_json(f.get('expected')))}</pre>"),
        ("actual", f"<pre>{_e(actual)}</pre>" if actual else '<span class="none">(no answer)</span>'),
    ]
    if level:
        fields.append(("level", _e(level) + (f" ({_e(erratum)})" if erratum else "")))
    body = "".join(f"<dt>{name}</dt><dd>{value}</dd>" for name, value in fields)
    return (
        f'<details class="failure" data-binding="{_e(f.get("binding"))}" data-suite="{_e(f.get("suite"))}" '
        f'data-id="{_e(f.get("id"))}"><summary><span class="id">{_e(f.get("suite"))}/{_e(f.get("id"))}</span>'
        f"{tags} &mdash; {_e(reason)}</summary>"
        f'<dl class="failure">{body}</dl></details>'
    )


def _failures(r: _Report) -> list[str]:
    out = [f'<h2 id="failures">Failures ({len(r.failures)})</h2>']
    if r.problems:
        out.append('<ul class="problems">' + "".join(f"<li>{_e(p)}</li>" for p in r.problems) + "</ul>")
    if not r.failures:
        return [*out, '<p class="none">No failures.</p>']
    for name in r.bindings:
        mine = [f for f in r.failures if str(f.get("binding")) == name]
        if mine:
            anchor = _anchor(r, name)
            out.append(f'<h3 id="{anchor}" data-binding="{_e(name)}">{_e(name)} ({len(mine)})</h3>')
            out += [_failure(f) for f in mine]
    return out


def render(report: Mapping[str, Any]) -> str:
    """The page for a report dict (json_report's): a str of HTML, the same for the same dict."""
    r = _Report(report)
    verdict = '<span class="verdict pass">PASSED</span>' if r.ok else '<span class="verdict fail">FAILED</span>'
    title = f"ilahrs conformance: {r.version_text()}"
    counts = {key: sum(c[key] for c in r.cells.values()) for key, _, _ in COUNTS}
    summary = ", ".join(f"{counts[key]} {label}" for key, label, _ in COUNTS if counts[key]) or "nothing run"
    parts: Sequence[str] = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{_e(title)}</title><style>{_STYLE}</style></head><body>",
        "<h1>ilahrs conformance report</h1>",
        f'<p class="meta" id="suite-version">{_e(r.version_text())}</p>',
        f'<p>{verdict} <span class="meta">{_plural(len(r.bindings), "implementation")}, '
        f"{_plural(len(r.suites), 'suite')}: {_e(summary)}</span></p>",
        *_matrix(r),
        *_levels(r),
        *_implementations(r),
        *_failures(r),
        "</body></html>",
        "",
    ]
    return "\n".join(parts)


def write(path: Path, report: Mapping[str, Any]) -> None:
    """The page written to `path` through a temporary file in its folder, renamed over it once
    whole: a failed write leaves what was there. OSError when it cannot be written."""
    text = render(report)
    folder = path.parent
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=folder)
    try:
        with os.fdopen(handle, "w", encoding="utf-8", newline="\n") as stream:
            stream.write(text)
        umask = os.umask(0o022)  # mkstemp makes the file private; a report is an ordinary file
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
