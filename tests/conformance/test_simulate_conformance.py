"""`ilahrs simulate`, `diagram` and `conformance` as a user meets them: the TCP simulator serves
one connection after another and prints the URL a client opens, a wrong variant is named as one,
`diagram` is described, the live conformance run passes against the simulator whatever its
alignment time, and registered bindings run from any directory."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from simulators import ILAHRS, ilahrs, simulator

from ilahrs.edge.serial import AhrsClient

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

REPOSITORY = Path(__file__).resolve().parents[2]


# --- simulate -----------------------------------------------------------------------------------------


def test_tcp_prints_the_url_and_serves_one_connection_after_another(tmp_path: Path) -> None:
    with simulator(tmp_path, "--tcp", "127.0.0.1:0", "--alignment-time", "1") as sim:
        assert sim.first_line.startswith("socket://127.0.0.1:"), sim.first_line
        with AhrsClient(sim.first_line) as client:
            client.stop()
            block = client.read_parameters().raw()
            client.load_parameters(block | {"update_rate": 20})
        for _ in range(2):  # the device carries on: what the first client loaded is still there
            with AhrsClient(sim.first_line) as client:
                client.stop()
                assert client.read_parameters().raw()["update_rate"] == 20
                client.start("AHRScont3")
                assert len(client.frames(5)) == 5
            assert sim.process.poll() is None, "the simulator exited when the client closed"
        assert sim.stop() == 0


def test_unknown_variant_is_named_as_a_variant() -> None:
    result = ilahrs("simulate", "--variant", "g300_a2_tmgaa")
    assert result.returncode == 2
    assert result.stderr.strip() == "ilahrs simulate: unknown variant 'g300_a2_tmgaa'; did you mean g300_a2_tmga?"
    assert "g300_a2_tmga" in ilahrs("simulate", "--help").stdout


def test_diagram_has_a_description() -> None:
    text = ilahrs("diagram", "--help").stdout
    assert "Mermaid" in text and "state machine" in text.replace("\n", " ")


# --- conformance --device -------------------------------------------------------------------------


def live(port: str, *args: str) -> subprocess.CompletedProcess[str]:
    command = [*ILAHRS, "conformance", "--device", port, *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=600, check=False)


@pytest.mark.parametrize("alignment", [["--alignment-time", "1"], []], ids=["alignment-1s", "default"])
def test_live_flows_pass_whatever_the_device_alignment_time(tmp_path: Path, alignment: list[str]) -> None:
    """The flows that send commands while the device aligns (the sleep flows), with the live run's
    default options, against a simulator that aligns in 1 s and one with the default 30 s."""
    with simulator(tmp_path, *alignment) as sim:
        result = live(sim.first_line, "-k", "flow/sleep/")
        assert result.returncode == 0, result.stdout + result.stderr
        assert " 0 failed" in result.stdout and "parameters restored" in result.stdout
        assert "PASS flow/sleep/during-alignment" in result.stdout
        with AhrsClient(sim.first_line) as client:
            client.stop()
            expected = int(alignment[1]) if alignment else 30
            assert client.read_parameters().raw()["alignment_time"] == expected


def test_live_refuses_an_alignment_time_too_short_for_the_flows(tmp_path: Path) -> None:
    with simulator(tmp_path, "--alignment-time", "1") as sim:
        result = live(sim.first_line, "--alignment-time", "1", "-k", "flow/sleep/during-alignment")
    assert result.returncode == 2
    (line,) = result.stderr.splitlines()
    assert "--alignment-time 1 is too short: flow/sleep/during-alignment" in line
    assert "PASSED" not in result.stdout and "parameters not changed" in result.stdout


# --- conformance --bindings-dir ---------------------------------------------------------------------


def test_registered_bindings_run_from_any_directory(tmp_path: Path) -> None:
    """The python registration (a runner path relative to the repository) from a temporary
    current directory."""
    report = tmp_path / "report.json"
    command = [
        *ILAHRS,
        "conformance",
        "--bindings-dir",
        str(REPOSITORY / "conformance" / "bindings"),
        "--bindings",
        "python",
        "--suite",
        "checksum",
        "--json",
        str(report),
    ]
    result = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "build it with" not in result.stdout and "PASSED" in result.stdout
    assert json.loads(report.read_text())["ok"] is True
