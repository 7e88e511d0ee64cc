"""The `ilahrs` command end to end, as a user runs it: every subcommand as a subprocess against
`ilahrs simulate` on a pseudo-terminal (monitor under tmux), captures checked against the
simulator's log, and bad input answered with one line on stderr and exit status 2."""

from __future__ import annotations

import csv
import io
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
import simulators
from simulators import ILAHRS, Simulator, ilahrs

from ilahrs import Frame, build_command
from ilahrs.cli.common import field_columns
from ilahrs.cli.decode import BASE_COLUMNS
from ilahrs.pcapng import Direction, read

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

@contextmanager
def simulator(tmp_path: Path, *args: str) -> Iterator[Simulator]:
    """The simulator the command-line tests drive: seeded, with a one-second alignment."""
    with simulators.simulator(tmp_path, "--seed", "1", "--alignment-time", "1", *args) as sim:
        yield sim


def decoded(path: Path, *options: str) -> list[dict[str, object]]:
    result = ilahrs("decode", str(path), "--to", "jsonl", *options)
    assert result.returncode == 0, result.stderr
    assert "messages" in result.stderr.splitlines()[0]
    return [json.loads(line) for line in result.stdout.splitlines()]


def assert_stopped(sim: Simulator) -> None:
    """The device sends nothing more: its output was stopped."""
    time.sleep(0.5)
    before = len(sim.entries())
    time.sleep(1.0)
    assert len(sim.entries()) == before, "the device still sends"


def written_intact(entries: list[dict[str, object]]) -> list[str]:
    return [str(e["message"]) for e in entries if e.get("intact") is True]


def test_record_then_decode_gives_what_the_simulator_sent(tmp_path: Path) -> None:
    capture, kept = tmp_path / "session.pcapng", tmp_path / "simulated.pcapng"
    with simulator(tmp_path, "--record", str(kept)) as sim:
        result = ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--count", "40")
        assert result.returncode == 0, result.stderr
        assert result.stderr.startswith("ilahrs record: ") and "0 errors" in result.stderr
        sim.stop()
        entries = sim.entries()
    rows = decoded(capture)
    inbound = [r for r in rows if r["direction"] == "in"]
    assert [r["raw"] for r in inbound] == written_intact(entries)
    kinds = [r["kind"] for r in rows]
    assert kinds[0] == "Stop" and "AHRScont3" in kinds and "initial_alignment" in kinds
    assert kinds.count("orientation_sensors") >= 40
    assert kinds[-1] == "Stop" or "Stop" in kinds[-5:]
    output = next(r for r in rows if r["kind"] == "orientation_sensors")
    fields = output["fields"]
    assert isinstance(fields, dict) and {"heading", "gyro_x", "acc_z", "mag_x", "utermo", "usw"} <= set(fields)
    assert isinstance(fields["gyro_x"], float) and fields["usw"] == "OK"
    # simulate --record keeps the same session from the device's end: the same messages.
    simulated = decoded(kept)
    assert [r["raw"] for r in simulated if r["direction"] == "in"] == written_intact(entries)
    assert [r["kind"] for r in simulated if r["direction"] == "out"] == [
        r["kind"] for r in rows if r["direction"] == "out"
    ]
    # The file is pcapng for an independent reader as well.
    tshark = shutil.which("tshark")
    if tshark is not None:
        listing = subprocess.run(
            [tshark, "-r", str(capture), "-T", "fields", "-e", "frame.len"], capture_output=True, text=True, check=True
        )
        assert [int(n) for n in listing.stdout.split()] == [len(p.data) for p in read(capture.open("rb")).packets]


def test_decode_with_faults_keeps_every_intact_message(tmp_path: Path) -> None:
    capture = tmp_path / "faulty.pcapng"
    faults = ("--corrupt-rate", "0.001", "--drop-rate", "0.001", "--garbage-rate", "0.2")
    with simulator(tmp_path, *faults) as sim:
        result = ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--duration", "2.5")
        assert result.returncode == 0, result.stderr
        sim.stop()
        entries = sim.entries()
    assert any(e.get("intact") is False for e in entries), "the faults never struck"
    rows = decoded(capture)
    assert [r["raw"] for r in rows if r["direction"] == "in" and r["kind"] != "damaged"] == written_intact(entries)
    assert any(r["kind"] == "damaged" and r["reason"] for r in rows)
    summary = ilahrs("decode", str(capture), "--to", "csv").stderr
    assert "bytes discarded in" in summary and "in offset" in summary


def test_decode_csv_and_raw_dump(tmp_path: Path) -> None:
    capture = tmp_path / "session.pcapng"
    with simulator(tmp_path, "--record", str(capture)) as sim:
        assert ilahrs("send", sim.port, "NMEAcont").returncode == 0
        time.sleep(1.5)
        assert ilahrs("send", sim.port, "Stop").returncode == 0
    result = ilahrs("decode", str(capture), "--to", "csv", "--types", "PAHR,acknowledgement")
    assert result.returncode == 0, result.stderr
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    header = result.stdout.splitlines()[0].split(",")
    assert header == [*BASE_COLUMNS, *field_columns(["acknowledgement", "PAHR"])]  # no calibration: no accuracy
    sentences = [r for r in rows if r["kind"] == "PAHR"]
    assert len(sentences) >= 20 and all(r["direction"] == "in" for r in rows)
    assert all(0 <= float(r["heading"]) < 360 and float(r["time"]) > 0 for r in sentences)
    # The inbound bytes alone, as a terminal program saves them: the same sentences, no times.
    dump = tmp_path / "dump.bin"
    dump.write_bytes(b"".join(p.data for p in read(capture.open("rb")).packets if p.direction == Direction.INBOUND))
    raw = ilahrs("decode", str(dump), "--to", "csv", "--types", "PAHR")
    again = list(csv.DictReader(io.StringIO(raw.stdout)))
    assert [r["heading"] for r in again] == [r["heading"] for r in sentences]
    assert all(r["time"] == "" for r in again)


def test_send_params_and_calibrate_change_the_device(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        result = ilahrs("params", sim.port, "set", "update_rate=50", "latitude=38.5")
        assert result.returncode == 0, result.stderr
        assert "update_rate = 50" in result.stdout
        shown = ilahrs("params", sim.port).stdout
        assert "update_rate = 50" in shown and "latitude = 38.5" in shown
        result = ilahrs("calibrate", sim.port, "2d", "--accumulation", "2", "--yes")
        assert result.returncode == 0, result.stderr
        assert "Calibration result (Table 6.14)" in result.stdout and "accepted" in result.stdout
        status = ilahrs("send", sim.port, "GetClbRes")
        assert status.returncode == 0 and "calibration_status calibration_type=1 runs_used=1" in status.stdout
        assert "bit_result" in ilahrs("send", sim.port, "GetBIT").stdout
        sent = Frame.parse(build_command("AHRScont3"))
        acknowledged = ilahrs("send", sim.port, "AHRScont3").stdout.strip()
        assert acknowledged == f"acknowledged AHRScont3 (checksum {sent.checksum:#06x})"
        time.sleep(1.5)
        sim.stop()
        last = sim.entries()[-1]
    assert last["state"] == "continuous"


def test_monitor_under_tmux(tmp_path: Path) -> None:
    tmux = shutil.which("tmux")
    if tmux is None:
        pytest.fail("tmux is missing: `make test-python` installs it")
    session = f"ilahrs-monitor-{os.getpid()}"
    done = tmp_path / "status"
    with simulator(tmp_path) as sim:
        shell = f"{' '.join(ILAHRS)} monitor {sim.port}; echo $? > {done}"
        subprocess.run([tmux, "new-session", "-d", "-s", session, "-x", "100", "-y", "40", shell], check=True)
        try:
            screen = ""
            deadline = time.monotonic() + 20
            while time.monotonic() < deadline and "state continuous" not in screen:
                time.sleep(0.5)
                screen = subprocess.run(
                    [tmux, "capture-pane", "-p", "-t", session], check=False, capture_output=True, text=True
                ).stdout
            assert "state continuous" in screen, screen
            assert "heading" in screen and " deg" in screen and "MAGNETOMETER_FAILURE" in screen
            assert "Hz (configured 100 Hz)" in screen
            subprocess.run([tmux, "send-keys", "-t", session, "q"], check=True)
            deadline = time.monotonic() + 10
            while time.monotonic() < deadline and not done.exists():
                time.sleep(0.2)
            assert done.exists() and done.read_text().strip() == "0"
        finally:
            subprocess.run([tmux, "kill-session", "-t", session], capture_output=True, check=False)
        assert_stopped(sim)


def test_plot_writes_a_png(tmp_path: Path) -> None:
    image_module = pytest.importorskip("PIL.Image")
    capture, png = tmp_path / "session.pcapng", tmp_path / "plot.png"
    with simulator(tmp_path) as sim:
        assert ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--count", "50").returncode == 0
    result = ilahrs("plot", str(capture), "-o", str(png), "--fields", "heading,pitch,roll,gyro_z", "--size", "640x480")
    assert result.returncode == 0, result.stderr
    with image_module.open(png) as image:
        assert image.size == (640, 480)
        low, high = image.convert("L").getextrema()
        assert high - low > 100


def test_ctrl_c_leaves_the_device_stopped_and_the_capture_valid(tmp_path: Path) -> None:
    capture = tmp_path / "interrupted.pcapng"
    with simulator(tmp_path) as sim:
        process = subprocess.Popen(
            [*ILAHRS, "record", sim.port, "-o", str(capture), "--start", "AHRScont3"], stderr=subprocess.PIPE, text=True
        )
        time.sleep(3.0)
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=20)
        assert "Traceback" not in err and "interrupted" in err
        assert_stopped(sim)
        sim.stop()
        entries = sim.entries()
    rows = decoded(capture)
    assert rows[-1]["kind"] == "Stop" or any(r["kind"] == "Stop" for r in rows[-5:])
    assert [r["raw"] for r in rows if r["direction"] == "in" and r["kind"] != "damaged"] == written_intact(entries)


def _one_line_error(result: subprocess.CompletedProcess[str], *words: str) -> None:
    assert result.returncode == 2, (result.stdout, result.stderr)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    for word in words:
        assert word in lines[0], lines[0]


def test_bad_input_is_one_line_and_status_2(tmp_path: Path) -> None:
    text = tmp_path / "notes.txt"
    text.write_text("hello, not a capture\n" * 10)
    _one_line_error(ilahrs("decode", str(tmp_path / "missing.pcapng")), "no such file")
    _one_line_error(ilahrs("decode", str(text)), "neither pcapng nor")
    _one_line_error(ilahrs("frobnicate"), "unknown command")
    _one_line_error(ilahrs("decod", "x"), "did you mean decode")
    _one_line_error(ilahrs("decode", str(text), "--variant", "g300_a2_tgx"), "did you mean g300_a2_tga")
    _one_line_error(ilahrs("send", "/dev/ilahrs-no-such-port", "GetBIT"), "cannot open")
    _one_line_error(ilahrs("send", "/dev/ilahrs-no-such-port", "GetBTI"), "did you mean GetBIT")
    _one_line_error(ilahrs("send", "/dev/ilahrs-no-such-port", "LoadAHRSPar", "update_rate=500"), "update_rate")
    capture = tmp_path / "cut.pcapng"
    with simulator(tmp_path, "--record", str(capture)) as sim:
        _one_line_error(ilahrs("params", sim.port, "set", "update_rate=0"), "update_rate", "outside")
        _one_line_error(ilahrs("params", sim.port, "set", "update_rat=5"), "did you mean update_rate")
    data = capture.read_bytes()
    (tmp_path / "cut.pcapng").write_bytes(data[: len(data) - 7])
    result = ilahrs("decode", str(capture))
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert result.stderr.strip().splitlines()[-1].endswith(")") and "file ends inside the block" in result.stderr


def test_a_port_that_does_not_answer(tmp_path: Path) -> None:
    master, slave = os.openpty()
    try:
        _one_line_error(ilahrs("params", os.ttyname(slave), timeout=60), "no answer")
    finally:
        os.close(master)
        os.close(slave)


def test_version() -> None:
    import ilahrs as package

    result = ilahrs("--version")
    expected = f"ilahrs {package.__version__} (wire fingerprint {package.WIRE_FINGERPRINT:016x})"
    assert result.returncode == 0 and result.stdout.strip() == expected
