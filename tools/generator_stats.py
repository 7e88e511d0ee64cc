"""How big the generator is: templates, generator modules, runtime files and generated lines.

    python tools/generator_stats.py           a table
    python tools/generator_stats.py --json    the same numbers for a program

It measures the repository it lives in (or --root):

- templates: every file under generator/targets/*/templates/, its lines and how many of them
  carry Jinja (`{{`, `{%` or `{#`);
- generator modules: the Python files under generator/, templates and runtime folders excepted;
- runtime files: every file under generator/targets/*/runtime/ (copied into generated/ as is);
- generated lines: every file under each folder of generated/ (one folder per binding), build
  products excepted.

A line is what `wc -l` counts, plus an unterminated last line. The limits the project keeps are
shown beside the numbers; the tool reports, it does not enforce them. Standard library only.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Iterator
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent

TEMPLATE_TOTAL_LIMIT = 5000
TEMPLATE_LIMIT = 300
MODULE_LIMIT = 400

JINJA_MARKS = ("{{", "{%", "{#")

# The order bindings are listed in; any other folder of generated/ follows, by name.
BINDINGS = ("python", "c", "rust", "rust-conformance", "kaitai", "docs")

# Build products that may sit in these folders without being sources (as generator/__main__.py
# skips them when it compares generated/).
IGNORED_PARTS = {
    "target",
    "__pycache__",
    ".mypy_cache",
    ".ruff_cache",
    ".pytest_cache",
    "node_modules",
    "build",
    "Cargo.lock",
}


@dataclass(frozen=True)
class FileLines:
    path: str  # relative to the repository root
    lines: int


@dataclass(frozen=True)
class Template:
    path: str
    lines: int
    jinja_lines: int

    @property
    def jinja_share(self) -> float:
        return self.jinja_lines / self.lines if self.lines else 0.0


@dataclass(frozen=True)
class Group:
    """A set of files: how many, their lines, the largest one."""

    count: int
    total_lines: int
    largest: FileLines | None


@dataclass(frozen=True)
class Binding:
    name: str
    files: int
    lines: int


@dataclass(frozen=True)
class Stats:
    templates: list[Template]
    modules: Group
    runtime: Group
    bindings: list[Binding]

    @property
    def template_lines(self) -> int:
        return sum(t.lines for t in self.templates)

    @property
    def largest_template(self) -> Template | None:
        return max(self.templates, key=lambda t: (t.lines, t.path), default=None)


def line_list(text: str) -> list[str]:
    """The lines of `text`: split at newlines, an unterminated last line included."""
    lines = text.split("\n")
    if lines[-1] == "":
        lines.pop()
    return lines


def _read(path: Path) -> str:
    return path.read_text(encoding="utf-8", errors="replace")


def _files(folder: Path) -> Iterator[Path]:
    """The files under `folder` (none if it does not exist), build products skipped, sorted."""
    if not folder.is_dir():
        return
    for path in sorted(folder.rglob("*")):
        parts = path.relative_to(folder).parts
        skipped = IGNORED_PARTS.intersection(parts) or any(part.endswith(".egg-info") for part in parts)
        if path.is_file() and not skipped:
            yield path


def _group(root: Path, paths: list[Path]) -> Group:
    sizes = [FileLines(p.relative_to(root).as_posix(), len(line_list(_read(p)))) for p in paths]
    largest = max(sizes, key=lambda f: (f.lines, f.path), default=None)
    return Group(count=len(sizes), total_lines=sum(f.lines for f in sizes), largest=largest)


def templates(root: Path) -> list[Template]:
    found: list[Template] = []
    for target in sorted((root / "generator" / "targets").glob("*/")):
        for path in _files(target / "templates"):
            lines = line_list(_read(path))
            jinja = sum(1 for line in lines if any(mark in line for mark in JINJA_MARKS))
            found.append(Template(path.relative_to(root).as_posix(), len(lines), jinja))
    return sorted(found, key=lambda t: (-t.lines, t.path))


def modules(root: Path) -> Group:
    paths = [
        p
        for p in _files(root / "generator")
        if p.suffix == ".py" and not {"templates", "runtime"}.intersection(p.relative_to(root).parts)
    ]
    return _group(root, paths)


def runtime(root: Path) -> Group:
    paths = [p for target in sorted((root / "generator" / "targets").glob("*/")) for p in _files(target / "runtime")]
    return _group(root, paths)


def bindings(root: Path) -> list[Binding]:
    out = root / "generated"
    folders = [p.name for p in out.iterdir() if p.is_dir()] if out.is_dir() else []
    order = [name for name in BINDINGS if name in folders] + sorted(set(folders) - set(BINDINGS))
    result: list[Binding] = []
    for name in order:
        files = list(_files(out / name))
        result.append(Binding(name, len(files), sum(len(line_list(_read(p))) for p in files)))
    return result


def measure(root: Path) -> Stats:
    return Stats(templates(root), modules(root), runtime(root), bindings(root))


def as_json(stats: Stats) -> dict[str, Any]:
    largest = stats.largest_template
    return {
        "limits": {
            "template_total_lines": TEMPLATE_TOTAL_LIMIT,
            "template_lines": TEMPLATE_LIMIT,
            "module_lines": MODULE_LIMIT,
        },
        "templates": {
            "count": len(stats.templates),
            "total_lines": stats.template_lines,
            "largest": {"path": largest.path, "lines": largest.lines} if largest else None,
            "files": [{**asdict(t), "jinja_share": round(t.jinja_share, 4)} for t in stats.templates],
        },
        "generator_modules": asdict(stats.modules),
        "runtime_files": asdict(stats.runtime),
        "generated": {
            "total_lines": sum(b.lines for b in stats.bindings),
            "bindings": {b.name: {"files": b.files, "lines": b.lines} for b in stats.bindings},
        },
    }


# A row of the table: what, lines, lines with Jinja, their share, a note.
Row = tuple[str, str, str, str, str]


def _row(what: str, lines: int | None, note: str = "", jinja: int | None = None) -> Row:
    count = "-" if lines is None else f"{lines:,}"
    if jinja is None:
        return (what, count, "", "", note)
    share = f"{jinja / lines:.0%}" if lines else ""
    return (what, count, f"{jinja:,}", share, note)


def _limit(lines: int, limit: int) -> str:
    return f"over the limit of {limit:,}" if lines > limit else ""


def _largest(group: Group, limit: int | None) -> Row:
    if group.largest is None:
        return _row("  largest: none", None)
    note = _limit(group.largest.lines, limit) if limit is not None else ""
    return _row(f"  largest: {group.largest.path}", group.largest.lines, note)


def table(stats: Stats) -> str:
    total = stats.template_lines
    jinja = sum(t.jinja_lines for t in stats.templates)
    note = _limit(total, TEMPLATE_TOTAL_LIMIT) or f"limit {TEMPLATE_TOTAL_LIMIT:,} in all, {TEMPLATE_LIMIT:,} each"
    rows = [_row(f"templates: {len(stats.templates)} files", total, note, jinja)]
    largest = stats.largest_template
    if largest is not None:
        rows.append(_row(f"  largest: {largest.path}", largest.lines))
    for t in stats.templates:
        short = t.path.removeprefix("generator/targets/").replace("/templates/", "/", 1)
        rows.append(_row(f"  {short}", t.lines, _limit(t.lines, TEMPLATE_LIMIT), t.jinja_lines))
    modules = stats.modules
    rows.append(_row(f"generator modules: {modules.count} files", modules.total_lines, f"limit {MODULE_LIMIT:,} each"))
    rows.append(_largest(modules, MODULE_LIMIT))
    rows.append(_row(f"runtime files: {stats.runtime.count} files", stats.runtime.total_lines))
    rows.append(_largest(stats.runtime, None))
    files = sum(b.files for b in stats.bindings)
    rows.append(_row(f"generated: {files} files", sum(b.lines for b in stats.bindings)))
    rows.extend(_row(f"  {b.name}: {b.files} files", b.lines) for b in stats.bindings)
    header: Row = ("", "lines", "jinja", "share", "")
    widths = [max(len(row[i]) for row in [header, *rows]) for i in range(len(header))]

    def line(row: Row) -> str:
        cells = [row[0].ljust(widths[0]), *(row[i].rjust(widths[i]) for i in (1, 2, 3)), row[4]]
        return "  ".join(cells).rstrip()

    return "\n".join(line(row) for row in [header, *rows]) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="generator_stats.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument("--root", type=Path, default=ROOT, help="the repository to measure (default: this one)")
    args = parser.parse_args(argv)
    stats = measure(args.root.resolve())
    sys.stdout.write(json.dumps(as_json(stats), indent=2) + "\n" if args.json else table(stats))
    return 0


if __name__ == "__main__":
    sys.exit(main())
