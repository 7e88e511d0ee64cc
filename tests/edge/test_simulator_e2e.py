"""The virtual AHRS end to end: `python -m ilahrs simulate` as a subprocess on a pty (and on a
loopback socket), driven by the pyserial client through the host session, with and without
fault injection. Timing bounds are generous; the simulator is always stopped."""

from __future__ import annotations

import os
import select
import signal
import socket
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest
from simulators import simulator

import ilahrs
from ilahrs.edge.serial import AhrsClient
from ilahrs.session.host import Output

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

def count_outputs(client: AhrsClient, seconds: float) -> int:
    return sum(1 for e in client.poll(seconds) if isinstance(e, Output) and not e.late)


def full_flow(client: AhrsClient, rate: int = 50, *, faults: bool = False) -> None:
    """Stop; read, load and read back parameters; continuous output; 2D-2T calibration; NMEA;
    sleep and wake."""
    client.stop()
    params = client.read_parameters()
    assert isinstance(params, ilahrs.AhrsParametersRead)
    client.load_parameters(params.raw() | {"update_rate": rate, "alignment_time": 1})
    again = client.read_parameters()
    assert isinstance(again, ilahrs.AhrsParametersRead)
    assert (again.update_rate, again.alignment_time) == (rate, 1)
    assert again.device_id == params.device_id
    alignment = client.start("AHRScont3")
    assert isinstance(alignment, ilahrs.InitialAlignment) and alignment.usw == 0
    seconds = 2.0
    outputs = count_outputs(client, seconds)
    assert outputs >= 50
    assert 0.6 * rate * seconds <= outputs <= 1.3 * rate * seconds, outputs
    client.stop()
    runs, final = client.calibrate_2d2t({"accumulation_time": 2, "latitude": 38.9}, runs=2)
    assert [r.raw()["run"] for r in runs] == [1, 2]
    assert isinstance(final, ilahrs.CalibrationResult)
    assert final.calibration_type == 2 and final.runs_used == 2 and ilahrs.calibration_succeeded(final.success)
    status = client.get_calibration_results()
    assert isinstance(status, ilahrs.CalibrationStatus)
    assert (status.calibration_type, status.runs_used, status.success) == (2, 2, final.success)
    assert (status.tm_c_11, status.hm_0_z) == (final.tm_c_11, final.hm_0_z)
    client.start("NMEAcont")
    sentences = client.frames(20)
    assert all(isinstance(s, ilahrs.PahrSentence) for s in sentences)
    last = client.low_power(True)
    if not faults or last is not None:  # with faults the last block may be lost: then a retry sleeps from idle
        assert isinstance(last, ilahrs.PahrSentence) and ilahrs.UnitStatusWord(last.usw).mode == ilahrs.UswMode.SLEEP
    assert client.host.state == "sleep"
    client.poll(0.3)
    assert client.low_power(False) is None
    assert client.host.state == "idle"
    assert client.built_in_test().raw()["usw"] == 0


def test_pty_full_flow(tmp_path: Path) -> None:
    start = time.monotonic()
    with simulator(tmp_path, "--seed", "1") as sim:
        assert sim.first_line.startswith("/dev/")
        with AhrsClient(sim.first_line) as client:
            full_flow(client)
            assert client.errors == []
            assert client.discarded == 0
        assert sim.stop() == 0
    assert time.monotonic() - start < 60


def test_pty_full_flow_with_faults(tmp_path: Path) -> None:
    """Corrupted and dropped bytes and garbage: the flows still complete (retried after a Stop),
    every message the simulator wrote intact reaches the host, and every other byte is reported."""
    faults = ("--corrupt-rate", "0.0005", "--drop-rate", "0.0005", "--garbage-rate", "0.1", "--seed", "6")
    with simulator(tmp_path, *faults) as sim, AhrsClient(sim.first_line, retries=10) as client:
        full_flow(client, faults=True)
        client.stop()  # quiet line: everything written has been read
        received, discarded, pending = list(client.received), client.discarded, client.host.pending
        assert sim.stop() == 0
        entries = sim.entries()
    intact = [bytes.fromhex(str(e["message"])) for e in entries if e.get("intact") is True]
    damaged = [e for e in entries if e.get("intact") is False]
    garbage = [e for e in entries if e["kind"] == "garbage"]
    assert damaged and garbage, "the faults never struck: nothing was tested"
    assert received == intact
    written = sum(len(bytes.fromhex(str(e["written"]))) for e in entries if e["kind"] != "lost")
    assert written == sum(len(m) for m in received) + discarded + pending
    assert discarded > 0


def test_tcp_loopback(tmp_path: Path) -> None:
    with simulator(tmp_path, "--tcp", "127.0.0.1:0", "--update-rate", "50", "--alignment-time", "1") as sim:
        host, _, port = sim.first_line.rpartition(":")
        assert host == "socket://127.0.0.1" and port.isdigit() and int(port) > 0
        with AhrsClient(sim.first_line) as client:
            client.stop()
            assert client.read_parameters().raw()["update_rate"] == 50
            client.start("AHRScont2")
            blocks = client.frames(60)
            assert all(isinstance(b, ilahrs.Quaternion) for b in blocks)
            client.stop()
        assert sim.process.poll() is None  # serves the next client
        assert sim.stop() == 0


def test_tcp_answers_behind_a_stale_header(tmp_path: Path) -> None:
    """E41 over the simulator's TCP line: the start of a frame a host left (cut off mid-write),
    then Stop and ReadAHRSPar: the device gives the stale bytes up once the line has been idle for
    IDLE_TIMEOUT and answers (it answered nothing before, however long it waited)."""
    read = ilahrs.build_command("ReadAHRSPar")
    with simulator(tmp_path, "--tcp", "127.0.0.1:0") as sim:
        _, _, port = sim.first_line.rpartition(":")
        with socket.create_connection(("127.0.0.1", int(port)), timeout=10) as connection:
            connection.sendall(bytes.fromhex("AA 55 01 00 3A 00"))
            time.sleep(0.02)
            connection.sendall(ilahrs.build_command("Stop") + read)
            sent = time.monotonic()
            decoder = ilahrs.StreamDecoder()
            frames: list[ilahrs.Frame] = []
            while not frames and time.monotonic() - sent < 5.0:
                ready, _, _ = select.select([connection], [], [], 0.1)
                if ready:
                    frames += [e.frame for e in decoder.feed(connection.recv(4096)) if e.frame is not None]
            waited = time.monotonic() - sent
        assert frames, "no answer behind the stale header"
        assert len(frames[0].payload) == ilahrs.AhrsParametersRead.SIZE
        assert ilahrs.IDLE_TIMEOUT / 2 < waited < 3.0  # the answer waits for the idle line, then comes


@pytest.mark.parametrize("address", ["0.0.0.0:0", "192.0.2.1:5000", "example.com:80", "127.0.0.1"])
def test_tcp_refuses_non_loopback(address: str) -> None:
    command = [sys.executable, "-m", "ilahrs", "simulate", "--tcp", address]
    result = subprocess.run(command, capture_output=True, text=True, timeout=30, check=False)
    assert result.returncode == 2
    assert result.stdout == ""
    assert "loopback" in result.stderr or "HOST:PORT" in result.stderr


def test_pty_line_settings_and_sigint(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        fd = os.open(sim.first_line, os.O_RDWR | os.O_NOCTTY)
        try:
            attrs = termios.tcgetattr(fd)
        finally:
            os.close(fd)
        assert attrs[4] == attrs[5] == termios.B115200
        assert attrs[2] & termios.CSIZE == termios.CS8
        assert not attrs[2] & (termios.PARENB | termios.CSTOPB)
        assert not attrs[3] & (termios.ECHO | termios.ICANON)
        assert sim.stop(signal.SIGINT) == 0


def test_diagram_command() -> None:
    command = [sys.executable, "-m", "ilahrs", "diagram"]
    result = subprocess.run(command, capture_output=True, text=True, timeout=30, check=False)
    assert result.returncode == 0
    assert result.stdout.startswith("stateDiagram-v2\n")
    assert "idle --> aligning_continuous" in result.stdout


def test_core_does_not_import_pyserial() -> None:
    code = "import sys, ilahrs, ilahrs.serial; assert 'serial' not in sys.modules, sorted(sys.modules)"
    subprocess.run([sys.executable, "-c", code], check=True, timeout=30)
