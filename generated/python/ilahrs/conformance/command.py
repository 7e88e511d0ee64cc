# Copied from generator/targets/python/runtime/conformance/command.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
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

from . import html
from .declaration import (
    DeclarationError,
    everything,
    load_declaration,
    load_expected_failures,
    write_expected_failures,
    write_new,
)
from .live import run_live
from .protocol import request
from .report import json_report, junit_xml, report, summary_line, version_text
from .runner import Binding, BindingError, Plan, Result, load_bindings, run_binding
from .vectors import KINDS, LEVELS, OPTIONS, VECTORS_DIR, Suite, SuiteError, load_suites, suite_version

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
    parser.add_argument(
        "--command",
        dest="runner_command",
        metavar="CMD",
        action="append",
        help="run this runner command line (shell-style quoting); repeatable, each with its --name",
    )
    parser.add_argument(
        "--name",
        action="append",
        help="the name shown for --command, one per --command in the same order (default runner)",
    )
    parser.add_argument(
        "--bindings",
        help="comma-separated registered binding names, or `all` (default: every registered one without "
        "--command, none with it; with --command the runners run beside them, e.g. --bindings all)",
    )
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
        help="comma-separated kinds to send; others count as not supported (n/s). With --command the runners "
        "are held to these kinds (an `unsupported` answer fails; registered bindings keep their own); "
        "without, the registered bindings are limited to them; without --kinds a --command runner's "
        "`unsupported` answers count n/s",
    )
    parser.add_argument(
        "--options",
        help=f"comma-separated vector options the runner knows ({', '.join(OPTIONS)}; default all, `-` for none); "
        "vectors with another option count as not supported (n/s); like --kinds, for the --command runners "
        "when there are any",
    )
    parser.add_argument(
        "-k", dest="pattern", help="only vectors (or live flows) whose id contains this text; the others are skipped"
    )
    parser.add_argument(
        "--level",
        choices=(*LEVELS[:-1], "all"),
        default="all",
        help="the obligation to hold the implementation to: required (what the ICD states), recommended (also "
        "robustness beyond it) or all (also each erratum's side); vectors above it are skipped (default all)",
    )
    parser.add_argument(
        "--declaration",
        type=Path,
        metavar="FILE",
        help="what the implementation supports (conformance/declaration.schema.json): vectors and live flows it "
        "does not declare are not applicable. For the --command runners when there are any, else for every "
        'registered binding. Default: a registration\'s own "declaration", else everything',
    )
    parser.add_argument(
        "--init-declaration",
        type=Path,
        metavar="FILE",
        help="write a declaration with everything enabled (the spec's side of every erratum) to FILE and stop",
    )
    parser.add_argument("--force", action="store_true", help="let --init-declaration replace an existing file")
    parser.add_argument(
        "--expected-failures",
        type=Path,
        metavar="FILE",
        help='vectors known to fail, {"<suite>/<id>": "reason"}: reported as expected, not failing the run; one '
        "that passes fails it. Like --declaration, for the --command runners when there are any. Default: a "
        'registration\'s own "expected_failures", else none',
    )
    parser.add_argument(
        "--update-expected-failures",
        action="store_true",
        help="rewrite the expected-failure file(s) from this run (sorted; reasons kept; entries of vectors not "
        "run kept; unexpected passes dropped)",
    )
    parser.add_argument("--timeout", type=float, default=20.0, help="seconds to wait for one answer (default 20)")
    parser.add_argument("--max-failures", type=int, default=40, help="failures to print (default 40)")
    parser.add_argument("--json", type=Path, help="also write the results as JSON to this file")
    parser.add_argument("--junit", type=Path, help="also write the results as JUnit XML to this file")
    parser.add_argument(
        "--report",
        type=Path,
        metavar="FILE.html",
        help="also write the results as one self-contained HTML page (ilahrs.conformance.html)",
    )
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
    if args.pattern:  # suites with no chosen vector leave the run; the others' unchosen vectors are skipped
        suites = [s for s in suites if any(args.pattern in v.id for v in s.vectors)]
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
    commands = _commands(args, kinds, options)
    for command in commands:
        command.declaration, command.expected_failures = args.declaration, args.expected_failures
    if commands and not args.bindings:
        return _one_file(args, commands)
    if args.bindings_dir is None:
        raise BindingError("give the runner with --command (or registrations with --bindings-dir)")
    only = None if args.bindings in (None, "all") else _names(args.bindings)
    bindings = load_bindings(args.bindings_dir, only)
    if not bindings:
        raise BindingError(f"no bindings registered in {args.bindings_dir}")
    clash = sorted({b.name for b in bindings} & {c.name for c in commands})
    if clash:
        raise BindingError(f"--name {', '.join(clash)} is a registered binding's name too; choose another")
    for binding in bindings:
        if kinds is not None and not commands:
            binding.kinds = [k for k in binding.kinds or KINDS if k in kinds]
        if options is not None and not commands:
            binding.options = [o for o in binding.options or OPTIONS if o in options]
        if args.declaration is not None and not commands:
            binding.declaration = args.declaration
        if args.expected_failures is not None and not commands:
            binding.expected_failures = args.expected_failures
    return _one_file(args, [*bindings, *commands])


def _one_file(args: argparse.Namespace, bindings: list[Binding]) -> list[Binding]:
    """The bindings, unless --update-expected-failures would rewrite one --expected-failures file
    from several runs."""
    shared = [
        b for b in bindings if args.expected_failures is not None and b.expected_failures == args.expected_failures
    ]
    if args.update_expected_failures and len(shared) > 1:
        raise BindingError("--update-expected-failures with --expected-failures rewrites one file: choose one binding")
    return bindings


def _commands(args: argparse.Namespace, kinds: list[str] | None, options: list[str] | None) -> list[Binding]:
    """The --command runners, each named by its --name."""
    commands: list[str] = args.runner_command or []
    names: list[str] = args.name or []
    if len(names) > len(commands) or (len(commands) > 1 and len(names) != len(commands)):
        raise BindingError(f"{len(commands)} --command and {len(names)} --name: give one --name per --command")
    names = names or ["runner"] * len(commands)
    if len(set(names)) != len(names):
        raise BindingError(f"--name {', '.join(sorted({n for n in names if names.count(n) > 1}))} given twice")
    pairs = zip(names, commands, strict=True)
    return [Binding(name, shlex.split(command), kinds, None, options) for name, command in pairs]


def _plans(args: argparse.Namespace, bindings: list[Binding], suites: list[Suite]) -> dict[str, Plan]:
    """Each binding's plan: --level, -k, its declaration and its expected failures (checked against
    every suite of --vectors, so a filtered run does not call a listed id unknown)."""
    everything_loaded = load_suites(args.vectors)
    chosen = {v.key for s in suites for v in s.vectors if args.pattern in v.id} if args.pattern else None
    plans = {}
    for binding in bindings:
        declaration = load_declaration(binding.declaration) if binding.declaration is not None else None
        expected: dict[str, str] = {}
        if binding.expected_failures is not None:
            expected = load_expected_failures(
                binding.expected_failures, everything_loaded, missing_ok=args.update_expected_failures
            )
        elif args.update_expected_failures:
            raise DeclarationError(
                f"--update-expected-failures: {binding.name} has no expected-failure file "
                "(give --expected-failures FILE)"
            )
        plans[binding.name] = Plan(args.level, chosen, declaration, expected)
    return plans


def _update_expected(result: Result, bindings: list[Binding], out: IO[str]) -> None:
    """Each binding's expected-failure file from the run: its failures (a listed one keeps its
    reason, a new one gets its failure's), and the listed vectors this run did not run."""
    for binding in bindings:
        path = binding.expected_failures
        assert path is not None
        old = result.plans[binding.name].expected
        ran = {o.vector.key: o for o in result.outcomes if o.binding == binding.name}
        new = {k: reason for k, reason in old.items() if k not in ran or ran[k].outcome not in _RUN}
        for key, o in ran.items():
            if o.outcome in ("failed", "expected_failure"):
                new[key] = old.get(key, o.reason)
        write_expected_failures(path, new)
        out.write(f"updated {path}: {len(new)} expected failures (was {len(old)})\n")


_RUN = ("passed", "failed", "expected_failure", "unexpected_pass")


def _init_declaration(args: argparse.Namespace) -> int:
    try:
        write_new(args.init_declaration, everything(load_suites(args.vectors)), args.force)
    except (SuiteError, DeclarationError) as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    print(f"wrote {args.init_declaration}: everything enabled; edit it to what the implementation supports")
    return 0


def _describe(binding: Binding, plan: Plan) -> str:
    parts = []
    if plan.declaration is not None:
        parts.append(f"declaration {binding.declaration}")
    if binding.expected_failures is not None:
        parts.append(f"{len(plan.expected)} expected failures in {binding.expected_failures}")
    return f"  {binding.name}: {'; '.join(parts)}\n" if parts else ""


def _write_reports(
    args: argparse.Namespace, result: Result, bindings: list[Binding], suites: list[Suite], out: IO[str]
) -> bool:
    """--json, --junit, --update-expected-failures and --report; False (said on stderr) when one
    cannot be written."""
    doc = json_report(result, bindings, suites)
    try:
        if args.json:
            args.json.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
        if args.junit:
            properties = {f"suite_{k}": v for k, v in suite_version(suites).items()}
            args.junit.write_text(junit_xml(result.cases, properties=properties), encoding="utf-8")
        if args.update_expected_failures:
            _update_expected(result, bindings, out)
    except (OSError, DeclarationError) as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return False
    if args.report:
        try:
            html.write(args.report, doc)
        except OSError as err:
            print(f"ilahrs conformance: cannot write the report {args.report}: {err.strerror or err}", file=sys.stderr)
            return False
    return True


def run(args: argparse.Namespace, out: IO[str] = sys.stdout) -> int:
    """`ilahrs conformance` with parsed arguments (add_arguments)."""
    if args.init_declaration is not None:
        return _init_declaration(args)
    if args.report and args.device:
        print("ilahrs conformance: --report is for runs against runners; with --device use --json", file=sys.stderr)
        return 2
    if args.report and not args.report.parent.is_dir():
        print(f"ilahrs conformance: cannot write {args.report}: no folder {args.report.parent}", file=sys.stderr)
        return 2
    if args.device:
        return run_live(args, out)
    try:
        suites = _select(args)
        bindings = _bindings(args)
        plans = _plans(args, bindings, suites)
    except (SuiteError, BindingError, DeclarationError) as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    root = args.root if args.root is not None else Path.cwd()
    result = Result()
    vector_count = sum(len(s.vectors) for s in suites)
    out.write(
        f"conformance: {vector_count} vectors in {len(suites)} suites from {args.vectors}, {version_text(suites)}; "
        f"level {args.level}; bindings: {', '.join(b.name for b in bindings)}\n"
    )
    out.write("".join(_describe(b, plans[b.name]) for b in bindings) + "\n")
    try:
        for binding in bindings:
            base = root if args.root is not None or binding.root is None else binding.root
            run_binding(binding, suites, base, args.timeout, result, plan=plans[binding.name])
    except SuiteError as err:
        print(f"ilahrs conformance: {err}", file=sys.stderr)
        return 2
    report(result, bindings, suites, args.max_failures, out)
    if not _write_reports(args, result, bindings, suites, out):
        return 2
    out.write(f"\n{version_text(suites)}: {summary_line(result.totals())}\n")
    out.write(f"{'PASSED' if result.ok else 'FAILED'}\n")
    return 0 if result.ok else 1


def main(argv: Sequence[str] | None = None, out: IO[str] = sys.stdout, **defaults: Any) -> int:
    """The suite as a program of its own; `defaults` as add_arguments takes them."""
    parser = argparse.ArgumentParser(description="Run the conformance vectors against runners or a device.")
    add_arguments(parser, **defaults)
    return run(parser.parse_args(argv), out)
