"""`ilahrs conformance` as a user runs it: installed with pip into a fresh virtual environment and
run against each of the repository's runners (the same results as conformance/harness.py, which
`make conformance` runs); its JUnit XML read by an independent parser (junitparser); and the live
mode against `ilahrs simulate` on a pty: passing on the default device, failing on each
misbehaviour, following the firmware the device reports, and restoring the parameters after an
interrupted run."""

from __future__ import annotations

import json
import os
import select
import shutil
import signal
import subprocess
import sys
import time
import venv
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from junitparser import Failure, JUnitXml, Skipped

from ilahrs.edge.serial import AhrsClient

pytest.importorskip("serial")

ROOT = Path(__file__).resolve().parents[2]
BINDINGS = sorted((ROOT / "conformance" / "bindings").glob("*.json"))
# Live runs: short timers, a short pause after each step (the simulator answers within a tick).
FAST = ("--quiet", "0.1", "--alignment-time", "1", "--accumulation-time", "1")


# --- the package in a fresh virtual environment --------------------------------------------------


@pytest.fixture(scope="module")
def fresh_ilahrs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """generated/python built into a wheel (by this environment's pip, setuptools and wheel: no
    network) and installed with pip into a new virtual environment; the path of its `ilahrs`."""
    base = tmp_path_factory.mktemp("fresh")
    source = base / "src"
    shutil.copytree(ROOT / "generated" / "python", source, ignore=shutil.ignore_patterns("*.egg-info", "build"))
    quiet = ["--quiet", "--disable-pip-version-check", "--no-deps", "--no-index"]
    wheels = base / "wheels"
    build = [sys.executable, "-m", "pip", "wheel", *quiet, "--no-build-isolation", "-w", str(wheels), str(source)]
    subprocess.run(build, check=True)
    venv.create(base / "venv", with_pip=True)
    install = [str(base / "venv" / "bin" / "python"), "-m", "pip", "install", *quiet]
    subprocess.run([*install, *map(str, wheels.glob("ilahrs-*.whl"))], check=True)
    script = base / "venv" / "bin" / "ilahrs"
    assert script.exists()
    return script


def _results(report: Path) -> dict[str, Any]:
    doc = json.loads(report.read_text())
    return {"ok": doc["ok"], "results": doc["results"], "failures": doc["failures"], "problems": doc["problems"]}


@pytest.mark.parametrize("binding", BINDINGS, ids=[p.stem for p in BINDINGS])
def test_installed_suite_matches_make_conformance(binding: Path, fresh_ilahrs: Path, tmp_path: Path) -> None:
    registration = json.loads(binding.read_text())
    program = registration["command"][0]
    if program != "{python}" and not (ROOT / program).exists():
        pytest.skip(f"{program} is not built ({registration['build']})")
    repo = tmp_path / "repo.json"
    harness = [sys.executable, str(ROOT / "conformance" / "harness.py"), "--bindings", registration["name"]]
    subprocess.run([*harness, "--json", str(repo)], check=True, capture_output=True)
    installed = tmp_path / "installed.json"
    command = " ".join(registration["command"])
    options = ["--options", ",".join(registration["options"]) or "-"] if "options" in registration else []
    run = subprocess.run(
        [str(fresh_ilahrs), "conformance", "--command", command, "--name", registration["name"], *options,
         "--kinds", ",".join(registration["kinds"]), "--json", str(installed), "--junit", str(tmp_path / "j.xml")],
        cwd=ROOT, capture_output=True, text=True, check=False,
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr
    assert "vectors in 8 suites from" in run.stdout and "/venv/" in run.stdout  # the package's own suites
    assert _results(installed) == _results(repo)
    xml = JUnitXml.fromfile(str(tmp_path / "j.xml"))
    vectors = sum(r["passed"] + r["failed"] + r["unsupported"] for r in _results(repo)["results"])
    assert xml.tests == vectors and xml.failures == 0 and xml.errors == 0


def test_installed_vectors_are_the_repository_vectors(fresh_ilahrs: Path) -> None:
    site = next((fresh_ilahrs.parent.parent / "lib").glob("python*/site-packages/ilahrs/vectors"))
    shipped = {p.name: p.read_bytes() for p in site.glob("*.json")}
    assert shipped == {p.name: p.read_bytes() for p in (ROOT / "conformance" / "vectors").glob("*.json")}


# --- JUnit XML of failures, read by junitparser ----------------------------------------------------


def test_junit_failures_carry_request_expected_and_actual(tmp_path: Path) -> None:
    runner = tmp_path / "runner.py"
    runner.write_text(
        "import sys\n"
        "for line in sys.stdin:\n"
        "    kind, arg = line.split()[:2]\n"
        "    print('ok 7' if kind == 'checksum' and arg == '01' else 'unsupported', flush=True)\n"
    )
    junit = tmp_path / "report.xml"
    run = subprocess.run(
        [sys.executable, "-m", "ilahrs", "conformance", "--command", f"{sys.executable} {runner}", "--name", "mine",
         "--suites", "checksum,frames", "--kinds", "checksum", "--junit", str(junit)],
        capture_output=True, text=True, check=False,
    )
    assert run.returncode == 1, run.stderr
    xml = JUnitXml.fromfile(str(junit))
    suites = {suite.name: suite for suite in xml}
    assert set(suites) == {"mine.checksum", "mine.frames"}
    checksum = suites["mine.checksum"]
    assert checksum.tests == 10 and checksum.failures == 10
    frames = suites["mine.frames"]
    count = len(json.loads((ROOT / "conformance" / "vectors" / "frames.json").read_text())["vectors"])
    assert frames.tests == count and frames.skipped == count and frames.failures == 0
    case = next(iter(checksum))
    (failure,) = [r for r in case.result if isinstance(r, Failure)]
    assert failure.message and "request:  checksum " in failure.text and "expected: " in failure.text
    assert "actual:   unsupported" in failure.text or "actual:   ok 7" in failure.text
    assert all(isinstance(r, Skipped) for c in frames for r in c.result)


def test_bad_options_are_one_line_and_status_two(tmp_path: Path) -> None:
    bad: list[list[str]] = [
        ["--kinds", "teleport", "--command", "true"],
        [],
        ["--suites", "nope", "--command", "true"],
        ["--device", str(tmp_path / "no-such-port")],
    ]
    for args in bad:
        run = subprocess.run([sys.executable, "-m", "ilahrs", "conformance", *args], capture_output=True,
                             text=True, check=False)
        assert run.returncode == 2 and run.stderr.count("\n") == 1 and "Traceback" not in run.stderr, run.stderr


# --- the live mode against the simulator ----------------------------------------------------------


@contextmanager
def simulator(*args: str) -> Iterator[str]:
    process = subprocess.Popen([sys.executable, "-m", "ilahrs", "simulate", *args], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout is not None
        ready, _, _ = select.select([process.stdout], [], [], 20)
        assert ready, "the simulator printed nothing"
        yield process.stdout.readline().strip()
    finally:
        process.send_signal(signal.SIGTERM)
        try:
            process.wait(10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(10)
        for stream in (process.stdout, process.stderr):
            if stream is not None:
                stream.close()


def live(port: str, tmp_path: Path, *args: str) -> tuple[int, str, dict[str, Any]]:
    report = tmp_path / "live.json"
    run = subprocess.run(
        [sys.executable, "-m", "ilahrs", "conformance", "--device", port, *FAST, "--json", str(report), *args],
        capture_output=True, text=True, check=False, timeout=300,
    )
    return run.returncode, run.stdout + run.stderr, json.loads(report.read_text())


def test_live_passes_on_the_simulator_and_writes_junit(tmp_path: Path) -> None:
    junit = tmp_path / "live.xml"
    with simulator() as port:
        code, text, report = live(port, tmp_path, "-k", "flow/continuous/", "--junit", str(junit))
    assert code == 0, text
    assert [f["status"] for f in report["flows"]] == ["passed"] * 4 and report["restored"]
    assert "4 flows: 4 passed, 0 failed, 0 skipped" in text and "parameters restored" in text
    xml = JUnitXml.fromfile(str(junit))
    assert xml.tests == 4 and xml.failures == 0


def test_live_skips_flows_that_change_the_calibration(tmp_path: Path) -> None:
    with simulator() as port:
        code, text, report = live(port, tmp_path, "-k", "flow/unknown/calibration")
    assert code == 0, text
    (flow,) = report["flows"]
    assert flow["status"] == "skipped" and "--allow-calibration" in flow["message"]


@pytest.mark.parametrize(
    ("misbehave", "message"),
    [
        ("wrong-ack-checksum", "the acknowledgement carries 0x0088, the message sent has 0x0087 (E12)"),
        ("skip-alignment-block", "E:alignment_done = alignment_done in aligning_continuous): no initial_alignment"),
        ("wrong-rate", "Hz, configured 100 Hz (tolerance 10% + 2 blocks)"),
    ],
)
def test_live_fails_on_each_misbehaviour(misbehave: str, message: str, tmp_path: Path) -> None:
    with simulator("--misbehave", misbehave) as port:
        code, text, report = live(port, tmp_path, "-k", "flow/continuous/AHRScont1")
    assert code == 1, text
    (flow,) = report["flows"]
    assert flow["status"] == "failed" and message in flow["message"], flow["message"]
    assert f"FAILED flow/continuous/AHRScont1: {flow['message']}" in text
    assert " s  sent C:80" in text  # the trace, with timestamps


STOPCLB = "flow/stopclb/4.9.8.0-finishes-without-runs"


def _stopclb_step(report: dict[str, Any]) -> dict[str, Any]:
    (flow,) = report["flows"]
    assert flow["status"] == "passed", flow
    return next(s for s in flow["steps"] if s["event"] == "StopClbRun")


def test_live_follows_the_firmware_the_device_reports(tmp_path: Path) -> None:
    with simulator() as port:
        code, text, current = live(port, tmp_path, "-k", STOPCLB)
    assert code == 0, text
    assert _stopclb_step(current) == {"event": "StopClbRun", "state": "runs_ready", "send": []}
    with simulator("--firmware", "4.9.8.0") as port:
        code, text, legacy = live(port, tmp_path, "-k", STOPCLB)
    assert code == 0, text
    assert legacy["model_firmware"] == "4.9.8.0"
    assert _stopclb_step(legacy) == {"event": "StopClbRun", "state": "calibration_deciding",
                                     "send": ["calibration_result"]}
    # A device that behaves as 4.9.8.0 but reports the current version fails the flow.
    with simulator("--firmware", "4.9.8.0", "--firmware-text", "AHRS 4.9.9.0") as port:
        code, text, lying = live(port, tmp_path, "-k", STOPCLB)
    assert code == 1 and "where the model sends nothing" in lying["flows"][0]["message"], text


def test_parameters_are_restored_after_an_interrupted_run(tmp_path: Path) -> None:
    with simulator("--alignment-time", "7") as port:
        with AhrsClient(port) as client:
            client.stop()
            before = client.read_parameters().raw()
        assert before["alignment_time"] == 7
        process = subprocess.Popen(
            [sys.executable, "-m", "ilahrs", "conformance", "--device", port, *FAST, "-k", "flow/"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )
        assert process.stdout is not None
        header = process.stdout.readline()
        assert "alignment 1 s" in header
        first = process.stdout.readline()
        assert first.startswith("PASS "), first
        time.sleep(0.3)  # inside the next flow
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=60)
        assert process.returncode == 130, out + err
        assert "interrupted; restoring the parameters" in err and "parameters restored" in out
        with AhrsClient(port) as client:
            client.stop()
            assert client.read_parameters().raw() == before


@pytest.mark.skipif(os.environ.get("ILAHRS_LIVE_FULL") != "1", reason="the full live run takes minutes")
def test_full_live_run(tmp_path: Path) -> None:
    with simulator() as port:
        code, text, report = live(port, tmp_path, "--allow-calibration")
    assert code == 0, text
    assert all(f["status"] == "passed" for f in report["flows"])


def test_live_on_a_silent_line_says_so(tmp_path: Path) -> None:
    master, slave = os.openpty()
    try:
        run = subprocess.run(
            [sys.executable, "-m", "ilahrs", "conformance", "--device", os.ttyname(slave), *FAST],
            capture_output=True, text=True, check=False, timeout=60,
        )
    finally:
        os.close(master)
        os.close(slave)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "ReadAHRSPar: no ahrs_parameters_read within 1.0 s" in run.stderr
    assert "parameters not changed" in run.stdout and "Traceback" not in run.stderr
