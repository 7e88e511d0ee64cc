"""The layers of the Python package: the `ilahrs` subcommands are the modules of ilahrs.cli, a
session vector's events are typed values that make the runner protocol's request line, a runner
that exits is reported with the last lines of its stderr, and the module paths the READMEs named
before the layers still import."""

from __future__ import annotations

import importlib
import io
import json
import subprocess
import sys
from pathlib import Path

import pytest

import ilahrs
from ilahrs.cli import parser, subcommands
from ilahrs.conformance import CommandEvent, DataEvent, TimerEvent, Vector, load_suites, main, request
from ilahrs.conformance.live import plan_flow
from ilahrs.conformance.vectors import session

ROOT = Path(__file__).resolve().parents[2]
SUBCOMMANDS = {
    "calibrate",
    "conformance",
    "decode",
    "diagram",
    "monitor",
    "params",
    "plot",
    "record",
    "send",
    "simulate",
}


def test_subcommands_are_the_modules_of_ilahrs_cli() -> None:
    """One registry: each subcommand is a module with add_parser and run, and the parser has
    exactly those, in the modules' order."""
    found = subcommands()
    assert set(found) == SUBCOMMANDS
    assert list(found) == sorted(found)
    for name, module in found.items():
        assert module.__name__ == f"ilahrs.cli.{name}"
    actions = [a for a in parser()._actions if a.dest == "command"]
    assert len(actions) == 1
    assert list(actions[0].choices or ()) == list(found)


def _session_vectors() -> list[Vector]:
    return [v for s in load_suites(ROOT / "conformance" / "vectors") for v in s.vectors if v.kind == "session"]


def _token(event: dict[str, object]) -> str:
    """The runner protocol's form of one vector event, written out from the format's definition."""
    ((key, value),) = event.items()
    if key == "command":
        code = int(value, 16) if isinstance(value, str) else value
        assert isinstance(code, int)
        return f"C:{code:02X}"
    return f"D:{value}" if key == "data" else f"E:{value}"


def test_session_events_are_typed_and_make_the_request_line() -> None:
    vectors = _session_vectors()
    assert vectors
    kinds: set[type] = set()
    for v in vectors:
        events = session(v.input, v.where).events
        kinds |= {type(e) for e in events}
        assert all(isinstance(e, (CommandEvent, DataEvent, TimerEvent)) for e in events)
        assert [e.token for e in events] == [_token(e) for e in v.input["events"]]
        firmware = v.input.get("firmware", "-")
        tokens = ",".join(_token(e) for e in v.input["events"])
        assert request(v).startswith(f"session {firmware} {tokens}")
    assert kinds == {CommandEvent, DataEvent, TimerEvent}


def test_a_flow_plan_carries_the_typed_events() -> None:
    flows = [v for v in _session_vectors() if v.id.startswith("flow/")]
    assert flows
    for v in flows:
        plan = plan_flow(v, None)
        assert [step.cause for step in plan.steps] == list(session(v.input, v.where).events)


def test_a_runner_that_exits_is_reported_with_its_last_stderr(tmp_path: Path) -> None:
    """The reason names the runner's last stderr lines, also those written after it exited by a
    process that still holds its stderr: the harness reads stderr to its end, not for a while."""
    runner = tmp_path / "runner.sh"
    runner.write_text("#!/bin/sh\nexec 1>&-\n(sleep 0.5; echo written late >&2) &\nexit 3\n")
    runner.chmod(0o755)
    vectors = tmp_path / "vectors"
    vectors.mkdir()
    suite = {"suite": "t", "source": "test", "vectors": [{"id": "c", "kind": "checksum", "input": "00", "expect": 0}]}
    (vectors / "t.json").write_text(json.dumps(suite))
    out = io.StringIO()
    status = main(["--command", str(runner), "--vectors", str(vectors), "--timeout", "30"], out)
    assert status == 1
    failure = next(line for line in out.getvalue().splitlines() if line.startswith("FAILED"))
    assert "exit status 3" in failure
    assert "stderr: written late" in failure


@pytest.mark.parametrize("name", ["serial", "simulate", "anystate", "cli_plot", "pcapng", "columnar", "statemachine"])
def test_documented_module_paths_import(name: str) -> None:
    module = importlib.import_module(f"ilahrs.{name}")
    assert all(hasattr(module, n) for n in getattr(module, "__all__", []))


def test_every_exported_name_and_python_m() -> None:
    assert all(hasattr(ilahrs, name) for name in ilahrs.__all__)
    for module in ("ilahrs", "ilahrs.__main__"):
        command = [sys.executable, "-m", module, "--version"]
        done = subprocess.run(command, check=False, capture_output=True, text=True, timeout=60)
        assert done.returncode == 0, done.stderr
        assert done.stdout.startswith(f"ilahrs {ilahrs.__version__}")
