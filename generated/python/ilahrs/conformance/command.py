# Copied from generator/targets/python/runtime/conformance/command.py for spec/ilahrs.yaml,
# spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs conformance` (and the repository's conformance/harness.py): its options, and the run of
the suites against runners or, with --device, of the session flows against a device (live)."""

from __future__ import annotations

import argparse
import json
import shlex
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import IO, Any

from .live import run_live
from .protocol import request
from .report import json_report, junit_xml, report
from .runner import Binding, BindingError, Result, load_bindings, run_binding
from .vectors import KINDS, OPTIONS, VECTORS_DIR, Suite, SuiteError, load_suites

__all__ = ["add_arguments", "main", "run"]


def _names(text: str) -> list[str]:
    return [n.strip() for n in text.split(",") if n.strip()]


def add_arguments(
    parser: argparse.ArgumentParser,
    *,
    vectors: Path = VECTORS_DIR,
    root: Path | None = None,
    bindings_dir: Path | None = None,
) -> None:
    """The options of `ilahrs conformance` (and of the repository's conformance/harness.py, with
    its own defaults)."""
    parser.add_argument(
        "--vectors", type=Path, default=vectors, help=f"directory of suites (*.json); default {vectors}"
    )
    parser.add_argument("--command", dest="runner_command", help="run this runner command line (shell-style quoting)")
    parser.add_argument("--name", default="runner", help="the name shown for --command (default runner)")
    parser.add_argument("--bindings", help="comma-separated binding names (default: every registered one)")
    parser.add_argument(
        "--bindings-dir",
        type=Path,
        default=bindings_dir,
        help="where NAME.json registrations are" + (f"; default {bindings_dir}" if bindings_dir else ""),
    )
    parser.add_argument(
        "--root",
        type=Path,
        default=root,
        help="where runner commands run (default: a registration's own root, see conformance/README.md; "
        "the current directory for --command)",
    )
    parser.add_argument("--suites", help="comma-separated suites to run (default: all)")
    parser.add_argument("--suite", action="append", help="one suite to run (repeatable)")
    parser.add_argument(
        "--kinds",
        help="comma-separated kinds to send; others count as not supported (n/s). With --command the runner "
        "is held to these kinds (an `unsupported` answer fails); without, its `unsupported` answers count n/s",
    )
    parser.add_argument(
        "--options",
        help=f"comma-separated vector options the runner knows ({', '.join(OPTIONS)}; default all, `-` for none); "
        "vectors with another option count as not supported (n/s)",
    )
    parser.add_argument("-k", dest="pattern", help="only vectors (or live flows) whose id contains this text")
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds to wait for one answer (default 20)")
    parser.add_argument("--max-failures", type=int, default=40, help="failures to print (default 40)")
    parser.add_argument("--json", type=Path, help="also write the results as JSON to this file")
    parser.add_argument("--junit", type=Path, help="also write the results as JUnit XML to this file")
    live = parser.add_argument_group("live device (see ilahrs.conformance.live)")
    live.add_argument("--device", metavar="PORT", help="run the session flows against a device on this port")
    live.add_argument("--baud", type=int, help="baud rate of --device (default: the AHRS line's)")
    live.add_argument(
        "--allow-calibration", action="store_true", help="also run flows that change the stored calibration"
    )
    live.add_argument("--quiet", type=float, default=0.25, help="seconds of silence that show nothing more comes")
    live.add_argument(
        "--alignment-time",
        type=int,
        default=2,
        help="alignment time loaded for the run, s (default 2; the commands flows send while the device "
        "aligns must fit in it)",
    )
    live.add_argument("--accumulation-time", type=int, default=2, help="accumulation time for the run, s (default 2)")


def _select(args: argparse.Namespace) -> list[Suite]:
    suites = load_suites(args.vectors)
    wanted = [*(args.suite or []), *(_names(args.suites) if args.suites else [])]
    if wanted:
        unknown = sorted(set(wanted) - {s.name for s in suites})
        if unknown:
            raise SuiteError(f"no suite named {', '.join(unknown)} in {args.vectors}")
        suites = [s for s in suites if s.name in wanted]
    if args.pattern:
        suites = [Suite(s.name, s.path, [v for v in s.vectors if args.pattern in v.id]) for s in suites]
        suites = [s for s in suites if s.vectors]
    for suite in suites:  # translate everything once up front: a bad vector is a suite error
        for v in suite.vectors:
            request(v)
    return suites


def _bindings(args: argparse.Namespace) -> list[Binding]:
    kinds = _names(args.kinds) if args.kinds else None
    unknown = [k for k in kinds or [] if k not in KINDS]
    if unknown:
        raise BindingError(f"unknown kinds {', '.join(unknown)} (kinds: {', '.join(KINDS)})")
    options = None if args.options is None else [o for o in _names(args.options) if o != "-"]
    wrong = [o for o in options or [] if o not in OPTIONS]
    if wrong:
        raise BindingError(f"unknown options {', '.join(wrong)} (options: {', '.join(OPTIONS)})")
    if args.runner_command:
        return [Binding(args.name, shlex.split(args.runner_command), kinds, None, options)]
    if args.bindings_dir is None:
        raise BindingError("give the runner with --command (or registrations with --bindings-dir)")
    bindings = load_bindings(args.bindings_dir, _names(args.bindings) if args.bindings else None)
    if not bindings:
        raise BindingError(f"no bindings registered in {args.bindings_dir}")
    for binding in bindings:
        if kinds is not None:
            binding.kinds = [k for k in binding.kinds or KINDS if k in kinds]
        if options is not None:
            binding.options = [o for o in binding.options or OPTIONS if o in options]
    return bindings


def run(args: argparse.Namespace, out: IO[str] = sys.stdout) -> int:
    """`ilahrs conformance` with parsed arguments (add_arguments)."""
    if args.device:
        return run_live(args, out)
    try:
        suites = _select(args)
        bindings = _bindings(args)
    except (SuiteError, BindingError) as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    root = args.root if args.root is not None else Path.cwd()
    result = Result()
    vector_count = sum(len(s.vectors) for s in suites)
    out.write(
        f"conformance: {vector_count} vectors in {len(suites)} suites from {args.vectors}; "
        f"bindings: {', '.join(b.name for b in bindings)}\n\n"
    )
    try:
        for binding in bindings:
            base = root if args.root is not None or binding.root is None else binding.root
            run_binding(binding, suites, base, args.timeout, result)
    except SuiteError as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    report(result, bindings, suites, args.max_failures, out)
    if args.json:
        args.json.write_text(json.dumps(json_report(result, bindings, suites), indent=1) + "\n", encoding="utf-8")
    if args.junit:
        args.junit.write_text(junit_xml(result.cases), encoding="utf-8")
    out.write(f"\n{'PASSED' if result.ok else 'FAILED'}\n")
    return 0 if result.ok else 1


def main(argv: Sequence[str] | None = None, out: IO[str] = sys.stdout, **defaults: Any) -> int:
    """The suite as a program of its own; `defaults` as add_arguments takes them."""
    parser = argparse.ArgumentParser(description="Run the conformance vectors against runners or a device.")
    add_arguments(parser, **defaults)
    return run(parser.parse_args(argv), out)
