"""`ilahrs monitor` as a user runs it: under tmux against `ilahrs simulate` on a pty and on
loopback TCP. On-request formats are polled with GetDataReq, the rate is counted from receive
times, NMEA's 50 Hz cap is shown, units are the spec's symbols with the digits of each field's
resolution, and a lost device ends the view with one line, exit status 2 and the terminal back."""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from simulators import ILAHRS
from test_cli import simulator

from ilahrs.cli import monitor as cli_monitor
from ilahrs.cli.common import variant_named
from ilahrs.commands import COMMANDS
from ilahrs.nmea import NMEA_MAX_RATE_HZ
from ilahrs.payloads import PAYLOADS
from ilahrs.session.host import HostEvent, Output
from ilahrs.statemachine import OUTPUT_FORMATS

_ON_REQUEST = [n for n, i in COMMANDS.items() if i.starts_mode is not None and i.starts_mode != "continuous"]
ON_REQUEST = [
    next(n for n in _ON_REQUEST if OUTPUT_FORMATS[COMMANDS[n].starts_output or ""] is not None),  # binary
    next(n for n in _ON_REQUEST if OUTPUT_FORMATS[COMMANDS[n].starts_output or ""] is None),  # NMEA
]
NMEA_CONTINUOUS = next(
    n for n, i in COMMANDS.items() if i.starts_mode == "continuous" and OUTPUT_FORMATS[i.starts_output or ""] is None
)


class Pane:
    """A command in a detached tmux session; its exit status, stderr and `stty -a` afterwards."""

    def __init__(self, tmux: str, session: str, tmp_path: Path) -> None:
        self.tmux, self.session = tmux, session
        self.status, self.stderr, self.stty = tmp_path / "status", tmp_path / "stderr", tmp_path / "stty"

    def screen(self) -> str:
        run = [self.tmux, "capture-pane", "-p", "-t", self.session]
        return subprocess.run(run, check=False, capture_output=True, text=True).stdout

    def wait_screen(self, ready: Callable[[str], bool], timeout: float = 30.0) -> str:
        deadline = time.monotonic() + timeout
        screen = self.screen()
        while time.monotonic() < deadline and not ready(screen):
            time.sleep(0.3)
            screen = self.screen()
        assert ready(screen), screen
        return screen

    def wait_exit(self, timeout: float = 30.0) -> int:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not (self.stty.exists() and self.stty.read_text()):
            time.sleep(0.2)
        return int(self.status.read_text())


@contextmanager
def monitor(tmp_path: Path, *args: str) -> Iterator[Pane]:
    tmux = shutil.which("tmux")
    if tmux is None:
        pytest.fail("tmux is missing: `make test-python` installs it")
    session = f"ilahrs-monitor-{os.getpid()}-{time.monotonic_ns()}"
    pane = Pane(tmux, session, tmp_path)
    shell = (
        f"{' '.join(ILAHRS)} monitor {' '.join(args)} 2> {pane.stderr}; echo $? > {pane.status}; stty -a > {pane.stty}"
    )
    subprocess.run([tmux, "new-session", "-d", "-s", session, "-x", "110", "-y", "40", shell], check=True)
    try:
        yield pane
    finally:
        subprocess.run([tmux, "kill-session", "-t", session], capture_output=True, check=False)


def rate_shown(screen: str) -> float:
    found = re.search(r"rate +([0-9.]+) Hz", screen)
    assert found, screen
    return float(found.group(1))


# --- the rate, from receive times -------------------------------------------------------------------


def test_rate_of_a_100_hz_stream_read_in_batches_is_100_hz(monkeypatch: pytest.MonkeyPatch) -> None:
    """Blocks every 10 ms, read 50 ms at a time (each read stamps its blocks with its own time):
    the rate is counted from the receive times, not biased by one read's worth of blocks."""
    block = PAYLOADS["orientation_sensors"]()
    view = cli_monitor._View(None, "AHRScont3", variant_named(None))  # type: ignore[arg-type]
    clock = [100.0]
    monkeypatch.setattr(time, "monotonic", lambda: clock[0])
    sent = 0
    for read in range(1, 201):  # 10 s of reads
        clock[0] = 100.0 + read * 0.05
        arrived: list[HostEvent] = [Output(block, at=clock[0]) for _ in range(int(read * 0.05 * 100) - sent)]
        sent += len(arrived)
        view.take(arrived)
    assert abs(view.rate() - 100.0) <= 1.0, view.rate()


# --- on-request formats ------------------------------------------------------------------------------


@pytest.mark.parametrize("command", ON_REQUEST)
def test_on_request_formats_are_polled_with_getdatareq(tmp_path: Path, command: str) -> None:
    with simulator(tmp_path) as sim, monitor(tmp_path, sim.port, "--output-format", command) as pane:
        screen = pane.wait_screen(
            lambda s: "state on_request" in s and re.search(r"messages [1-9][0-9]{2}", s) is not None
        )
        assert "waiting for output" not in screen
        configured = 100 if OUTPUT_FORMATS[COMMANDS[command].starts_output or ""] else NMEA_MAX_RATE_HZ
        assert f"polling GetDataReq at {configured:g} Hz" in screen, screen
        subprocess.run([pane.tmux, "send-keys", "-t", pane.session, "q"], check=True)
        assert pane.wait_exit() == 0
    polls = [e for e in sim.entries() if e.get("state") == "on_request" and e["kind"] != "lost"]
    assert len(polls) > 100


# --- what the screen shows ---------------------------------------------------------------------------


def test_units_are_symbols_with_the_digits_of_each_resolution(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim, monitor(tmp_path, sim.port, "--output-format", "AHRScont3") as pane:
        screen = pane.wait_screen(lambda s: "mag_x" in s and "state continuous" in s)
        subprocess.run([pane.tmux, "send-keys", "-t", pane.session, "q"], check=True)
        assert pane.wait_exit() == 0
    assert "deg_per_s" not in screen and re.search(r"gyro_x +-?[0-9]+\.[0-9]{2} deg/s\n", screen), screen
    assert re.search(r"mag_x +-?[0-9]+ nT\n", screen), screen  # 10 nT steps: no decimals
    assert re.search(r"heading +[0-9]+\.[0-9]{2} deg\n", screen), screen
    assert re.search(r"acc_x +-?[0-9]+\.[0-9]{4} g\n", screen), screen  # KA 10000: 0.0001 g


def test_quaternion_components_carry_no_unit(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim, monitor(tmp_path, sim.port, "--output-format", "AHRScont2") as pane:
        screen = pane.wait_screen(lambda s: "lk0" in s)
        subprocess.run([pane.tmux, "send-keys", "-t", pane.session, "q"], check=True)
        assert pane.wait_exit() == 0
    assert re.search(r"lk0 +-?[01]\.[0-9]{4}\n", screen), screen
    assert " one" not in screen


def test_nmea_cap_is_shown_and_the_rate_agrees(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim, monitor(tmp_path, sim.port, "--output-format", NMEA_CONTINUOUS) as pane:
        screen = pane.wait_screen(lambda s: re.search(r"messages [0-9]{3}", s) is not None)
        subprocess.run([pane.tmux, "send-keys", "-t", pane.session, "q"], check=True)
        assert pane.wait_exit() == 0
    assert f"configured 100 Hz; NMEA output capped at {NMEA_MAX_RATE_HZ:g} Hz" in screen, screen
    assert 0.8 * NMEA_MAX_RATE_HZ < rate_shown(screen) < 1.2 * NMEA_MAX_RATE_HZ


# --- losing the device -------------------------------------------------------------------------------


@pytest.mark.parametrize("line", ["pty", "tcp"])
def test_losing_the_device_is_one_line_and_status_2(tmp_path: Path, line: str) -> None:
    args = ("--tcp", "127.0.0.1:0") if line == "tcp" else ()
    with simulator(tmp_path, *args) as sim:
        assert sim.port.startswith("socket://") == (line == "tcp")
        with monitor(tmp_path, sim.port) as pane:
            pane.wait_screen(lambda s: "state continuous" in s and "heading" in s)
            sim.process.send_signal(signal.SIGKILL)
            sim.process.wait(10)
            status = pane.wait_exit()
            err = pane.stderr.read_text()
            stty = pane.stty.read_text()
    assert status == 2, err
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert err.startswith(f"ilahrs monitor: {sim.port}: lost the device"), err
    assert re.search(r"(^|\s)icanon\b", stty) and re.search(r"(^|\s)echo\b", stty), stty  # the terminal is back
