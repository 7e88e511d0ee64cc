"""What changed between two specs, and what it means for a user who vendors the bindings.

`python -m generator diff --against REV_OR_FILE` compares the model of the spec (loaded,
validated and laid out: offsets and sizes, not YAML text) with the model of another version of
it: a spec file, or a git revision (the spec's path at that revision). Every change is reported
with the named rule that classifies it, in one of four classes:

    wire-breaking  an old device and a new host (or the reverse) disagree about bytes
    api-breaking   code written against the old bindings stops compiling or means something else
    additive       something new; what existed is unchanged
    docs           documentation only: no byte and no identifier changes

The required version bump follows (major for a breaking change, minor for an additive one,
patch for documentation; before 1.0.0 a breaking change needs a minor bump), and
`--check-version` fails when the spec's `version` does not bump at least that much.

The same wire-relevant view of the model (`wire_facts`: command codes, payload layouts, frame,
state-machine answers; never names or docs) gives the wire fingerprint every binding exports.

Here: the command line. The rules and their classes are in rules.py, the comparison in
compare.py, the wire facts and fingerprint in fingerprint.py, the text and JUnit report and the
version bump in report.py.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

from ..load import SpecError
from ..model import Spec
from .compare import compare
from .fingerprint import wire_facts, wire_fingerprint
from .report import actual_bump, bump_is_enough, print_text, required_bump, write_junit
from .rules import ADDITIVE, API, BUMPS, CLASSES, DOCS, RULES, WIRE, Change

__all__ = [
    "ADDITIVE",
    "API",
    "BUMPS",
    "CLASSES",
    "DOCS",
    "RULES",
    "WIRE",
    "Change",
    "actual_bump",
    "bump_is_enough",
    "compare",
    "main",
    "required_bump",
    "wire_facts",
    "wire_fingerprint",
    "write_junit",
]


def _spec_at(against: str, spec_path: Path, tmp: Path) -> Path:
    """A file: itself. Otherwise a git revision: the spec's path at that revision."""
    candidate = Path(against)
    if candidate.is_file():
        return candidate
    spec_path = spec_path.resolve()
    try:
        top = subprocess.run(
            ["git", "-C", str(spec_path.parent), "rev-parse", "--show-toplevel"],
            capture_output=True, text=True, check=True,
        ).stdout.strip()  # fmt: skip
    except (OSError, subprocess.CalledProcessError) as exc:
        raise SpecError(against, None, (), f"neither a file nor a git revision (no git repository: {exc})") from exc
    rel = spec_path.relative_to(Path(top).resolve()).as_posix()
    shown = subprocess.run(["git", "-C", top, "show", f"{against}:{rel}"], capture_output=True, check=False)
    if shown.returncode != 0:
        message = shown.stderr.decode("utf-8", "replace").strip().splitlines()
        raise SpecError(
            against, None, (), f"neither a file nor a git revision holding {rel}: {message[-1] if message else ''}"
        )
    out = tmp / f"{against.replace('/', '_')}.yaml"
    out.write_bytes(shown.stdout)
    return out


def main(argv: list[str] | None = None, build: Callable[[Path], Spec] | None = None) -> int:
    from .. import DEFAULT_SPEC, build_spec

    build = build or build_spec
    parser = argparse.ArgumentParser(
        prog="python -m generator diff",
        description="Every change between two specs, classified by named rules (wire-breaking, api-breaking,"
        " additive, docs), and the version bump it requires.",
        epilog="example: python -m generator diff --against v1.0.0 --check-version --junit build/spec-diff.xml",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter,
    )
    parser.add_argument("--against", metavar="REV_OR_FILE", help="the older spec: a spec file or a git revision")
    parser.add_argument("--spec", type=Path, default=DEFAULT_SPEC, help="the newer spec file")
    parser.add_argument(
        "--check-version", action="store_true", help="exit 1 if the spec's version does not bump enough"
    )
    parser.add_argument("--junit", type=Path, metavar="FILE", help="also write the result as JUnit XML")
    parser.add_argument("--rules", action="store_true", help="list the rules and stop")
    args = parser.parse_args(argv)
    if args.rules:
        for name, (cls, what) in RULES.items():
            print(f"{cls:<13}  {name:<28}  {what}")
        return 0
    if args.against is None:
        parser.error("--against REV_OR_FILE is required")
    try:
        with tempfile.TemporaryDirectory(prefix="ilahrs-diff-") as tmp:
            old = build(_spec_at(args.against, args.spec, Path(tmp)))
        new = build(args.spec)
    except SpecError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    changes = compare(old, new)
    required = required_bump(changes, old.version)
    actual = actual_bump(old.version, new.version)
    enough = bump_is_enough(required, actual)
    print_text(changes, old, new, required, actual)
    if args.junit is not None:
        try:
            write_junit(args.junit, changes, required, enough, args.check_version)
        except OSError as exc:
            print(f"error: cannot write {args.junit}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    if args.check_version and not enough:
        print(
            f"error: spec version {new.version} must be at least a {required} bump over {old.version}", file=sys.stderr
        )
        return 1
    return 0
