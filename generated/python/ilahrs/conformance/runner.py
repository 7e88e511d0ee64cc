# Copied from generator/targets/python/runtime/conformance/runner.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Runners: the registrations of bindings, a runner process fed one request line at a time, and a
binding run against the suites."""

from __future__ import annotations

import contextlib
import json
import queue
import shutil
import subprocess
import sys
import threading
import time
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO

from .compare import compare
from .declaration import Declaration
from .protocol import parse_answer, request
from .vectors import KINDS, LEVELS, OPTIONS, Suite, Vector

__all__ = [
    "MAX_CONSECUTIVE_CRASHES",
    "OUTCOMES",
    "Binding",
    "BindingError",
    "Case",
    "Cell",
    "Failure",
    "Outcome",
    "Plan",
    "Result",
    "Runner",
    "RunnerGoneError",
    "load_bindings",
    "resolve_command",
    "run_binding",
]


class BindingError(Exception):
    """A binding registration that cannot be used."""


@dataclass
class Binding:
    name: str
    command: list[str]
    kinds: list[str] | None  # None: an ad-hoc runner, its own `unsupported` answers decide
    build: str | None
    options: list[str] | None = None  # the vector options it knows; None: every one (OPTIONS)
    root: Path | None = None
    """Where its command runs and relative paths in it resolve: a registration's "root", relative to
    the registration's folder (that folder when absent); None (an ad-hoc runner): --root or the
    current directory."""
    declaration: Path | None = None
    """Its declaration (conformance/declaration.schema.json): a registration's "declaration",
    relative to the registration's folder; None: everything applies."""
    expected_failures: Path | None = None
    """Its expected-failure file: a registration's "expected_failures", relative to its folder."""


def _binding(path: Path) -> Binding:
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        raise BindingError(f"{path}: {err}") from None
    command = doc.get("command") if isinstance(doc, dict) else None
    if (
        not isinstance(doc, dict)
        or not isinstance(doc.get("name"), str)
        or not isinstance(command, list)
        or not command
        or not all(isinstance(c, str) for c in command)
        or not isinstance(doc.get("kinds"), list)
    ):
        raise BindingError(f'{path}: a binding is {{"name": str, "command": [str, ...], "kinds": [...], "build": str}}')
    unknown = [k for k in doc["kinds"] if k not in KINDS]
    if unknown:
        raise BindingError(f"{path}: unknown kinds {unknown}")
    options = doc.get("options")
    if options is not None and (not isinstance(options, list) or any(o not in OPTIONS for o in options)):
        raise BindingError(f"{path}: options must be a list of {', '.join(OPTIONS)}")
    root = doc.get("root", ".")
    if not isinstance(root, str):
        raise BindingError(f"{path}: root must be a directory relative to the registration, such as ../..")
    base = (path.parent / root).resolve()
    files: list[Path | None] = []
    for key in ("declaration", "expected_failures"):
        value = doc.get(key)
        if value is not None and not isinstance(value, str):
            raise BindingError(f"{path}: {key} must be a file name relative to the registration")
        files.append(None if value is None else (path.parent / value).resolve())
    return Binding(doc["name"], command, list(doc["kinds"]), doc.get("build"), options, base, *files)


def load_bindings(directory: Path, only: list[str] | None) -> list[Binding]:
    found: dict[str, Binding] = {}
    for path in sorted(directory.glob("*.json")):
        binding = _binding(path)
        found[binding.name] = binding
    if only is None:
        return list(found.values())
    missing = [n for n in only if n not in found]
    if missing:
        raise BindingError(
            f"no registration for {', '.join(missing)} in {directory} (registered: {', '.join(found) or 'none'})"
        )
    return [found[n] for n in only]


class RunnerGoneError(Exception):
    pass


class Runner:
    """One runner process: a line in, a line out, with a time limit per answer."""

    def __init__(self, command: list[str], cwd: Path) -> None:
        self.proc = subprocess.Popen(
            command, cwd=cwd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        self.lines: queue.Queue[bytes | None] = queue.Queue()
        self.stderr: deque[str] = deque(maxlen=20)
        assert self.proc.stdout is not None and self.proc.stderr is not None
        threading.Thread(target=self._pump, args=(self.proc.stdout,), daemon=True).start()
        self._stderr_reader = threading.Thread(target=self._drain, args=(self.proc.stderr,), daemon=True)
        self._stderr_reader.start()

    def _pump(self, stream: IO[bytes]) -> None:
        for line in stream:
            self.lines.put(line)
        self.lines.put(None)

    def _drain(self, stream: IO[bytes]) -> None:
        for line in stream:
            self.stderr.append(line.decode("utf-8", "replace").rstrip())

    def ask(self, line: str, timeout: float) -> str:
        """Send one request and wait for its answer, both within `timeout` seconds."""
        stdin = self.proc.stdin
        assert stdin is not None
        deadline = time.monotonic() + timeout
        failed: list[OSError] = []

        def write() -> None:  # in a thread: a runner that stops reading must not block the harness
            try:
                stdin.write(line.encode("ascii") + b"\n")
                stdin.flush()
            except OSError as err:
                failed.append(err)

        writer = threading.Thread(target=write, daemon=True)
        writer.start()
        writer.join(timeout)
        if writer.is_alive():
            self.kill()
            raise RunnerGoneError(f"did not read its request within {timeout:g} s")
        if failed:
            raise RunnerGoneError(self._why("closed its input"))
        try:
            answer = self.lines.get(timeout=max(0.0, deadline - time.monotonic()))
        except queue.Empty:
            self.kill()
            raise RunnerGoneError(f"no answer within {timeout:g} s") from None
        if answer is None:
            raise RunnerGoneError(self._why("exited"))
        return answer.decode("latin-1").rstrip("\r\n")

    def kill(self) -> None:
        self.proc.kill()
        self.proc.wait()

    def _why(self, what: str) -> str:
        try:
            code = self.proc.wait(timeout=2)
        except subprocess.TimeoutExpired:
            code = None
        self._stderr_reader.join(timeout=2)  # its last lines: read until the runner's stderr closes
        tail = " | ".join(list(self.stderr)[-5:])
        return f"runner {what} (exit status {code})" + (f"; stderr: {tail}" if tail else "")

    def close(self) -> None:
        if self.proc.stdin is not None:
            with contextlib.suppress(OSError):
                self.proc.stdin.close()
        try:
            self.proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


def resolve_command(binding: Binding, root: Path) -> list[str] | None:
    """The command with {python} replaced by this interpreter and a program path relative to
    `root` made absolute; None when its program does not exist."""
    command = [sys.executable if part == "{python}" else part for part in binding.command]
    program = command[0]
    if "/" in program:
        path = Path(program) if Path(program).is_absolute() else root / program
        return [str(path), *command[1:]] if path.exists() else None
    return command if shutil.which(program) else None


@dataclass
class Failure:
    binding: str
    vector: Vector
    reason: str
    request: str
    answer: str


@dataclass
class Cell:
    """The counts of one binding on one suite (the names the JSON report writes)."""

    passed: int = 0
    failed: int = 0
    unsupported: int = 0
    expected_failures: int = 0
    unexpected_passes: int = 0
    not_applicable: int = 0
    skipped: int = 0


OUTCOMES = ("passed", "failed", "expected_failure", "unexpected_pass", "unsupported", "not_applicable", "skipped")
_COUNTER = {
    "passed": "passed",
    "failed": "failed",
    "expected_failure": "expected_failures",
    "unexpected_pass": "unexpected_passes",
    "unsupported": "unsupported",
    "not_applicable": "not_applicable",
    "skipped": "skipped",
}


@dataclass
class Outcome:
    """A vector run against a binding: `outcome` one of OUTCOMES, `reason` why (a failure's reason,
    what excluded it)."""

    binding: str
    vector: Vector
    outcome: str
    reason: str = ""


@dataclass
class Plan:
    """What a binding is held to: the level (a vector above it is skipped), the vectors -k chose
    (None: all), its declaration (None: everything applies), its expected failures."""

    level: str = "all"
    chosen: set[str] | None = None
    declaration: Declaration | None = None
    expected: dict[str, str] = field(default_factory=dict)

    def excluded(self, v: Vector) -> tuple[str, str] | None:
        """(outcome, reason) when the vector is not run: skipped, or not_applicable."""
        if self.chosen is not None and v.key not in self.chosen:
            return "skipped", "not chosen by -k"
        if self.level != "all" and LEVELS.index(v.level) > LEVELS.index(self.level):
            return "skipped", f"level {v.level} is above --level {self.level}"
        why = self.declaration.why_not(v) if self.declaration is not None else None
        return ("not_applicable", why) if why is not None else None


@dataclass
class Case:
    """One test case of a report: a vector run against a binding, or a flow run against a device.
    `status`: passed, failed or skipped; `detail`: what was sent, expected and received."""

    group: str
    name: str
    status: str
    message: str = ""
    detail: str = ""
    seconds: float = 0.0


@dataclass
class Result:
    cells: dict[tuple[str, str], Cell] = field(default_factory=dict)
    failures: list[Failure] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)  # a binding that could not run at all
    cases: list[Case] = field(default_factory=list)
    outcomes: list[Outcome] = field(default_factory=list)
    plans: dict[str, Plan] = field(default_factory=dict)
    """Each binding's plan (its declaration and expected failures), for the reports."""

    @property
    def ok(self) -> bool:
        return (
            not self.failures
            and not self.problems
            and not any(c.failed or c.unexpected_passes for c in self.cells.values())
        )

    def totals(self) -> Cell:
        total = Cell()
        for cell in self.cells.values():
            for name, value in vars(cell).items():
                setattr(total, name, getattr(total, name) + value)
        return total


MAX_CONSECUTIVE_CRASHES = 5


def _failure_detail(v: Vector, line: str, answer: str) -> str:
    lines = [f"note:     {v.note}"] if v.note else []
    lines += [f"request:  {line}", f"expected: {json.dumps(v.expect)}", f"actual:   {answer or '(no answer)'}"]
    return "\n".join(lines)


class _BindingRun:
    """One binding against the suites: the runner process, restarted after a crash."""

    def __init__(
        self, binding: Binding, command: list[str], root: Path, timeout: float, result: Result, *, plan: Plan
    ) -> None:
        self.binding = binding
        self.plan = plan
        self.command = command
        self.root = root
        self.timeout = timeout
        self.result = result
        self.runner: Runner | None = None
        self.crashes = 0

    def record(self, cell: Cell, v: Vector, outcome: str, reason: str = "") -> None:
        counter = _COUNTER[outcome]
        setattr(cell, counter, getattr(cell, counter) + 1)
        self.result.outcomes.append(Outcome(self.binding.name, v, outcome, reason))

    def fail(self, cell: Cell, v: Vector, reason: str, *, line: str, answer: str = "", seconds: float = 0.0) -> None:
        group = f"{self.binding.name}.{v.suite}"
        listed = self.plan.expected.get(v.key)
        if listed is not None:
            self.record(cell, v, "expected_failure", reason)
            message = f"expected failure ({listed}): {reason}"
            self.result.cases.append(Case(group, v.id, "skipped", message, seconds=seconds))
            return
        self.record(cell, v, "failed", reason)
        self.result.failures.append(Failure(self.binding.name, v, reason, line, answer))
        detail = _failure_detail(v, line, answer)
        self.result.cases.append(Case(group, v.id, "failed", reason, detail, seconds))

    def passed(self, cell: Cell, v: Vector, *, line: str, answer: str, seconds: float) -> None:
        group = f"{self.binding.name}.{v.suite}"
        listed = self.plan.expected.get(v.key)
        if listed is None:
            self.record(cell, v, "passed")
            self.result.cases.append(Case(group, v.id, "passed", seconds=seconds))
            return
        reason = f"unexpected pass: listed as an expected failure ({listed})"
        self.record(cell, v, "unexpected_pass", reason)
        self.result.failures.append(Failure(self.binding.name, v, reason, line, answer))
        self.result.cases.append(Case(group, v.id, "failed", reason, _failure_detail(v, line, answer), seconds))

    def skip(self, cell: Cell, v: Vector, why: str, outcome: str = "unsupported") -> None:
        self.record(cell, v, outcome, why)
        message = why if outcome == "unsupported" else f"{outcome.replace('_', ' ')}: {why}"
        self.result.cases.append(Case(f"{self.binding.name}.{v.suite}", v.id, "skipped", message))

    def not_sent(self, v: Vector, kinds: Sequence[str] | None) -> tuple[str, str] | None:
        """(outcome, reason) of a vector not sent to the runner: skipped, not applicable, not
        supported, or failed (an option this harness does not know)."""
        binding = self.binding
        excluded = self.plan.excluded(v)
        if excluded is not None:
            return excluded
        if kinds is not None and v.kind not in kinds:
            return "unsupported", f"{binding.name} does not list the kind {v.kind}"
        if v.unknown_options:
            return "failed", f"option {', '.join(v.unknown_options)} unknown to this harness for {v.kind}"
        known = OPTIONS if binding.options is None else binding.options
        missing = [o for o, value in v.options.items() if value and o not in known]
        if missing:
            return "unsupported", f"{binding.name} does not list the option {', '.join(missing)}"
        return None

    def vector(self, cell: Cell, v: Vector, kinds: Sequence[str] | None) -> None:
        binding = self.binding
        line = request(v)
        not_sent = self.not_sent(v, kinds)
        if not_sent is not None and not_sent[0] == "failed":
            self.fail(cell, v, not_sent[1], line=line)
            return
        if not_sent is not None:
            self.skip(cell, v, not_sent[1], not_sent[0])
            return
        if self.crashes >= MAX_CONSECUTIVE_CRASHES:
            self.fail(cell, v, "not run: the runner keeps failing", line=line)
            return
        if self.runner is None:
            self.runner = Runner(self.command, self.root)
        start = time.monotonic()
        try:
            answer_line = self.runner.ask(line, self.timeout)
            self.crashes = 0
        except RunnerGoneError as gone:
            self.runner.close()
            self.runner = None
            self.crashes += 1
            self.fail(cell, v, str(gone), line=line, seconds=time.monotonic() - start)
            return
        seconds = time.monotonic() - start
        answer = parse_answer(answer_line)
        if answer.status == "unsupported" and kinds is None:
            self.skip(cell, v, f"{binding.name} answered unsupported")
            return
        if answer.status == "unsupported":
            reason: str | None = f"answered unsupported, but {binding.name} lists {v.kind}"
        elif answer.status == "invalid":
            reason = "not an answer of the runner protocol"
        else:
            reason = compare(v, answer)
        if reason is None:
            self.passed(cell, v, line=line, answer=answer_line, seconds=seconds)
        else:
            self.fail(cell, v, reason, line=line, answer=answer_line, seconds=seconds)

    def close(self) -> None:
        if self.runner is not None:
            self.runner.close()
            self.runner = None


def run_binding(
    binding: Binding, suites: list[Suite], root: Path, timeout: float, result: Result, *, plan: Plan | None = None
) -> None:
    plan = plan if plan is not None else Plan()
    result.plans[binding.name] = plan
    command = resolve_command(binding, root)
    if command is None:
        build = f"; build it with `{binding.build}` there" if binding.build else ""
        problem = f"{binding.name}: runner {binding.command[0]} not found in {root}{build}"
        result.problems.append(problem)
        for suite in suites:
            result.cells[(binding.name, suite.name)] = Cell(failed=len(suite.vectors))
            group = f"{binding.name}.{suite.name}"
            result.cases += [Case(group, v.id, "failed", problem) for v in suite.vectors]
            result.outcomes += [Outcome(binding.name, v, "failed", problem) for v in suite.vectors]
        return
    run = _BindingRun(binding, command, root, timeout, result, plan=plan)
    try:
        for suite in suites:
            cell = result.cells.setdefault((binding.name, suite.name), Cell())
            for v in suite.vectors:
                run.vector(cell, v, binding.kinds)
    finally:
        run.close()
