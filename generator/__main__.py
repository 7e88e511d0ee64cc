"""Command line: `python -m generator [--check] [--target NAME ...]`; `python -m generator diff --help`.

Writes generated/ from spec/ilahrs.yaml; with --check, writes nothing and exits 1 if
generated/ differs from what the spec produces (a changed, missing or stale file).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import DEFAULT_SPEC, ROOT, build_spec
from .formatting import FormatterError
from .load import SpecError
from .render import derived_files, render, target_names, writers

# Build products that may sit inside generated/ without being generated.
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


def _on_disk(out: Path, targets: list[str]) -> set[str]:
    found: set[str] = set()
    for target in targets:
        base = out / target
        if not base.is_dir():
            continue
        for path in base.rglob("*"):
            rel = path.relative_to(out)
            generated = not IGNORED_PARTS.intersection(rel.parts) and not any(
                part.endswith(".egg-info") for part in rel.parts
            )
            if path.is_file() and generated:
                found.add(rel.as_posix())
    return found


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["diff"]:
        from .diff import main as diff_main

        return diff_main(argv[1:])
    parser = argparse.ArgumentParser(prog="python -m generator", description=__doc__)
    parser.add_argument("--spec", type=Path, default=DEFAULT_SPEC, help="spec file (default spec/ilahrs.yaml)")
    parser.add_argument("--out", type=Path, default=ROOT / "generated", help="output folder (default generated/)")
    parser.add_argument("--target", action="append", choices=target_names(), help="only this target (repeatable)")
    parser.add_argument("--check", action="store_true", help="compare instead of writing; exit 1 on any difference")
    parser.add_argument("--validate-only", action="store_true", help="check the spec and stop")
    args = parser.parse_args(argv)

    try:
        spec = build_spec(args.spec)
    except SpecError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.validate_only:
        print(f"{spec.file}: valid (spec hash {spec.sha256})")
        return 0
    targets = args.target or target_names()
    try:
        files = render(spec, targets)
    except FormatterError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    # A target's outputs live under generated/<target-folder>/; a target may write more than one folder,
    # and a folder may hold the outputs of several targets (docs/): a file is stale only in a folder
    # whose every writer ran.
    folders = sorted(
        folder for folder in {path.split("/", 1)[0] for path in files} if writers(spec)[folder] <= set(targets)
    )
    existing = _on_disk(args.out, folders)
    changed = [
        p
        for p, text in sorted(files.items())
        if not (args.out / p).is_file() or (args.out / p).read_text(encoding="utf-8") != text
    ]
    stale = sorted(existing - set(files) - derived_files(targets))
    if args.check:
        for path in changed:
            print(f"differs: generated/{path}", file=sys.stderr)
        for path in stale:
            print(f"stale (not produced by the spec): generated/{path}", file=sys.stderr)
        if changed or stale:
            print("generated/ is out of date: run `make generate` and commit the result", file=sys.stderr)
            return 1
        print(f"generated/ matches {spec.file} ({len(files)} files)")
        return 0
    for path in changed:
        dest = args.out / path
        dest.parent.mkdir(parents=True, exist_ok=True)
        dest.write_text(files[path], encoding="utf-8", newline="\n")
    for path in stale:
        (args.out / path).unlink()
    print(f"generated {len(files)} files from {spec.file} ({len(changed)} changed, {len(stale)} removed)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
