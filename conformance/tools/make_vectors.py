"""Write the conformance suites, conformance/vectors/*.json, from the oracle in oracle.py.

    python3 conformance/tools/make_vectors.py            # rewrite conformance/vectors/
    python3 conformance/tools/make_vectors.py --check    # exit 1 if the committed files differ

Each suite is a module of suites/ (suites/payloads.py writes payloads.json) with its cases as data
in suites/cases/<suite>.json: every vector has a note saying where its bytes come from (an ICD
table, an erratum of spec/ilahrs.yaml, a rule of spec/README.md, or how it was computed). Expected
answers are computed by the oracles (oracle.py, device_oracle.py), never by the generator or a
binding. The output is deterministic (fixed seeds, sorted nothing that depends on hashing), so the
committed JSON is exactly what this script writes: edit the cases, never the JSON.

The suites carry their version (suites.VERSION, semver): --check also compares what the script
writes with the suites of the last release (--since, by default the last tag reachable from HEAD,
read with git; skipped, and said so, when there is no tag yet: before the first release the
version holds no one to anything) and fails when an expectation changed or a vector went without
a major bump, or a vector was added or its level changed without at least a minor one.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from suites import build_all

VECTORS_DIR = Path(__file__).resolve().parent.parent / "vectors"

__all__ = ["build_all", "main", "version_problems"]

_EXPECTATION = ("kind", "input", "expect", "options")
_OBLIGATION = ("level", "erratum", "requires")


def _semver(text: object) -> tuple[int, int, int]:
    parts = str(text).split(".")
    return (int(parts[0]), int(parts[1]), int(parts[2])) if len(parts) == 3 else (0, 0, 0)


def version_problems(old: dict[str, Any], new: dict[str, Any]) -> list[str]:
    """Why suite `new` (a parsed suite file) needs a higher version than `old` (the same suite as
    committed before), or nothing: see suites.VERSION for the rule."""
    before, after = _semver(old.get("version", "0.0.0")), _semver(new.get("version"))
    olds = {v["id"]: v for v in old.get("vectors", [])}
    news = {v["id"]: v for v in new.get("vectors", [])}
    changed = sorted(i for i in olds if i not in news or any(olds[i].get(k) != news[i].get(k) for k in _EXPECTATION))
    added = sorted(set(news) - set(olds))
    moved = sorted(i for i in set(olds) & set(news) if any(olds[i].get(k) != news[i].get(k) for k in _OBLIGATION))
    suite, shown = new.get("suite"), f"{'.'.join(map(str, after))} (was {'.'.join(map(str, before))})"
    if changed and after[0] <= before[0]:
        return [
            f"{suite}: expectations of {len(changed)} vectors changed or removed ({changed[0]}, ...): "
            f"a major version bump is needed in suites/__init__.py, version {shown}"
        ]
    if (added or moved) and after <= before:
        first = (added or moved)[0]
        return [
            f"{suite}: {len(added)} vectors added, {len(moved)} levels changed ({first}, ...): "
            f"a minor version bump is needed in suites/__init__.py, version {shown}"
        ]
    return []


def _committed(since: str, path: Path) -> dict[str, Any] | None:
    """The suite file as committed at `since`, or None (not in git, or not there)."""
    try:
        top = subprocess.run(
            ["git", "rev-parse", "--show-toplevel"], cwd=path.parent, capture_output=True, text=True, check=True
        ).stdout.strip()
        rel = path.resolve().relative_to(Path(top).resolve()).as_posix()
        text = subprocess.run(
            ["git", "show", f"{since}:{rel}"], cwd=top, capture_output=True, text=True, check=True
        ).stdout
        doc: dict[str, Any] = json.loads(text)
    except (OSError, ValueError, subprocess.CalledProcessError):
        return None
    return doc


def last_release(where: Path) -> str | None:
    """The last tag reachable from HEAD (the last release), or None (no tag, or not in git)."""
    try:
        found = subprocess.run(
            ["git", "describe", "--tags", "--abbrev=0"], cwd=where, capture_output=True, text=True, check=True
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    return found or None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=VECTORS_DIR, help="where to write (default: conformance/vectors)")
    parser.add_argument("--check", action="store_true", help="compare with the files in --out instead of writing")
    parser.add_argument(
        "--since",
        default=None,
        help="the commit --check compares versions with (default: the last release tag; none yet: not compared)",
    )
    args = parser.parse_args(argv)
    files = build_all()
    if args.check:
        stale = [
            name
            for name, text in files.items()
            if not (args.out / name).is_file() or (args.out / name).read_text(encoding="utf-8") != text
        ]
        extra = sorted(p.name for p in args.out.glob("*.json") if p.name not in files)
        for name in stale:
            print(f"{args.out / name}: differs from what {Path(__file__).name} writes", file=sys.stderr)
        for name in extra:
            print(f"{args.out / name}: not written by {Path(__file__).name}", file=sys.stderr)
        bumps = []
        since = args.since if args.since is not None else last_release(args.out)
        if since is None:
            print(f"{Path(__file__).name}: no release tag yet, suite versions not compared", file=sys.stderr)
        for name, text in files.items():
            old = _committed(since, args.out / name) if since is not None else None
            if old is not None:
                bumps += version_problems(old, json.loads(text))
        for problem in bumps:
            print(f"{args.out}: {problem}", file=sys.stderr)
        return 1 if stale or extra or bumps else 0
    args.out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (args.out / name).write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
