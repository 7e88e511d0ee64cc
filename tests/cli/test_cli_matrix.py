"""Every subcommand that talks to a device, from every state the device can be in: `send` with every
command name, `record` with every start command (and none), `calibrate` with every kind, `params`,
and `monitor` (a real subprocess on a terminal, briefly). Each ends in a decoded answer or in one
clear line on stderr with exit status 2, never a traceback; `send` prints the decoded answer of
every command in every state where the device answers it (the table in `ilahrs.statemachine`).

The device is `ilahrs.Device` on a pseudo-terminal, served by a thread (tests/session/test_client_stateful.py,
PtyDevice); before each case it is power-cycled and driven into the state with the serial client,
along the shortest path the table gives (a command alone, without its parameter block, leaves it
waiting for the block). Alignment and accumulation are ended at once on the way (the device's clock
is moved past them), so the matrix is quick; the CLI then runs in-process (`ilahrs.__main__.main`),
the cases several at a time, each thread with its own device and its own stdout and stderr.
"""

from __future__ import annotations

import io
import os
import pty
import select
import subprocess
import sys
import threading
import time
import traceback
from collections import deque
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Final, TextIO

import pytest
from pty_device import PtyDevice

from ilahrs import build_command
from ilahrs.__main__ import main
from ilahrs.cli.device import CALIBRATIONS
from ilahrs.commands import COMMANDS
from ilahrs.edge.serial import AhrsClient
from ilahrs.payloads import PAYLOADS, Payload
from ilahrs.pcapng import Direction, read
from ilahrs.session.device import default_parameters
from ilahrs.statemachine import (
    ACK,
    INITIAL,
    OUTPUT,
    OUTPUT_FORMATS,
    OUTPUT_PREFIX,
    PARAMETER_BLOCK,
    STATES,
    command_event,
    lookup,
    timer_transition,
)

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

ALIGNMENT: Final = 3
"""Seconds of alignment the device starts with: an aligning state lasts through one CLI run."""
ACCUMULATION: Final = 30
"""Seconds of accumulation of the calibrations the driver starts (ended at once when passed through)."""
WORKERS: Final = int(os.environ.get("ILAHRS_MATRIX_WORKERS", "8"))
"""Cases run at once (each waits on its device most of the time)."""
STARTS: Final = tuple(name for name, info in COMMANDS.items() if info.starts_output is not None)
OUTPUT_TABLES: Final = {table for table in OUTPUT_FORMATS.values() if table is not None}
SENTENCE_KIND: Final = "PAHR"

# --- Driving the device into a state ---------------------------------------------------------------


@dataclass(frozen=True)
class Step:
    command: str | None  # None: the state's timer ends
    block: bool = True  # False: the command alone, so that the device waits for its block


def _edges(state: str) -> Iterator[tuple[Step, str]]:
    for name in COMMANDS:
        if (command_event(COMMANDS[name].code, state) or name) != name:
            continue  # 0xFE is Stop or ExitClb by mode (E14)
        transition = lookup(state, name)
        if transition is None:
            continue
        if STATES[transition.to].expects is not None:
            after = lookup(transition.to, PARAMETER_BLOCK)
            assert after is not None
            yield Step(name), after.to
            yield Step(name, block=False), transition.to
        else:
            yield Step(name), transition.to
    timed = timer_transition(state)
    if timed is not None and timed[1].to != state:
        yield Step(None), timed[1].to


def _paths() -> dict[str, tuple[Step, ...]]:
    """The shortest way from power-up to every state (breadth first over the table)."""
    paths: dict[str, tuple[Step, ...]] = {INITIAL: ()}
    queue = deque([INITIAL])
    while queue:
        state = queue.popleft()
        for step, to in _edges(state):
            if to not in paths:
                paths[to] = (*paths[state], step)
                queue.append(to)
    return paths


PATHS: Final = _paths()


def _block_values(table: str) -> dict[str, object]:
    """Values a user would give: the device's own parameters; a long accumulation."""
    names = {f.name for f in PAYLOADS[table].FIELDS if f.type != "reserved"}
    values: dict[str, object] = {k: v for k, v in default_parameters().raw().items() if k in names}
    values["alignment_time"] = ALIGNMENT
    if "accumulation_time" in names:
        values["accumulation_time"] = ACCUMULATION
    return {k: v for k, v in values.items() if k in names}


def _block(command: str) -> Payload | None:
    table = COMMANDS[command].parameter_block
    return None if table is None else PAYLOADS[table].from_raw(_block_values(table))


def drive(device: PtyDevice, state: str) -> None:
    """Power-cycle the device and drive it into `state` with the serial client."""
    device.power_cycle(ALIGNMENT)
    with AhrsClient(device.path) as client:
        client.poll(0.05)  # what the device sent before its power cycle
        client.host.resync(INITIAL)
        for step in PATHS[state]:
            before = device.snapshot()[0]
            if step.command is None:
                device.skip()
            elif step.block:
                client.request(step.command, _block(step.command))
            else:
                client._write(build_command(step.command))
            end = time.monotonic() + 10
            while device.snapshot()[0] == before and time.monotonic() < end:
                client.poll(0.01)
    reached = device.snapshot()[0]
    assert reached == state, f"driving the device into {state} left it in {reached}"


# --- Running the CLI in-process, several at once ----------------------------------------------------


class _PerThread(io.TextIOBase):
    """sys.stdout / sys.stderr for threads that each capture their own."""

    def __init__(self, fallback: TextIO) -> None:
        self._local = threading.local()
        self._fallback = fallback

    def capture(self) -> io.StringIO:
        self._local.buffer = io.StringIO()
        return self._local.buffer  # type: ignore[no-any-return]

    def write(self, text: str) -> int:
        buffer: TextIO = getattr(self._local, "buffer", None) or self._fallback
        return buffer.write(text)

    def isatty(self) -> bool:
        return False


@dataclass(frozen=True)
class Result:
    status: int
    stdout: str
    stderr: str
    state: str  # the state the device was in when the CLI started
    output: Path | None = None  # the capture `record` wrote


def _run(argv: list[str], stdout: _PerThread, stderr: _PerThread) -> tuple[int, str, str]:
    out = stdout.capture()
    err = stderr.capture()
    try:
        status = main(argv)
    except SystemExit as exc:
        status = exc.code if isinstance(exc.code, int) else 1
    except BaseException:  # what a user would see: the traceback
        err.write(traceback.format_exc())
        status = 1
    return status, out.getvalue(), err.getvalue()


Case = tuple[str, str, str]  # (subcommand, state, argument: command name, kind, "-")


def _argv(case: Case, port: str, folder: Path) -> list[str]:
    sub, state, arg = case
    if sub == "send":
        table = COMMANDS[arg].parameter_block
        values = [] if table is None else [f"{k}={v}" for k, v in _block_values(table).items()]
        started = [step.command for step in PATHS[state] if step.command in STARTS]
        output = ["--output-format", started[-1]] if started else []  # the user knows what they started
        return ["send", port, arg, *values, *output]
    if sub == "params":
        return ["params", port]
    if sub == "record":
        start = [] if arg == "-" else ["--start", arg]
        return ["record", port, "-o", str(folder / f"{state}-{arg}.pcapng"), *start, "--duration", "0.2"]
    assert sub == "calibrate"
    return ["calibrate", port, arg, "--accumulation", "1", "--runs", "2", "--yes"]


def _cases() -> list[Case]:
    cases: list[Case] = [("send", s, c) for s in STATES for c in COMMANDS]
    cases += [("params", s, "-") for s in STATES]
    cases += [("record", s, c) for s in STATES for c in ("-", *STARTS)]
    cases += [("calibrate", s, k) for s in STATES for k in CALIBRATIONS]
    return cases


CASES: Final = _cases()


@pytest.fixture(scope="module")
def results(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[Case, Result]]:
    folder = tmp_path_factory.mktemp("matrix")
    local = threading.local()
    devices: list[PtyDevice] = []
    lock = threading.Lock()

    def one(case: Case) -> tuple[Case, Result]:
        device = getattr(local, "device", None)
        if device is None:
            device = local.device = PtyDevice(seed=len(devices) + 1)
            with lock:
                devices.append(device)
        sub, state, _arg = case
        try:
            drive(device, state)
        except Exception as exc:
            raise AssertionError(f"{case}: {exc}") from exc
        # send hears the state as it is; the other subcommands run whole flows: their alignments
        # and accumulations end at once, from the first byte they send
        device.fast_after_input = sub in ("record", "calibrate")
        status, out, err = _run(_argv(case, device.path, folder), routed[0], routed[1])
        output = folder / f"{state}-{_arg}.pcapng" if sub == "record" else None
        return case, Result(status, out, err, state, output)

    saved = sys.stdout, sys.stderr
    routed = _PerThread(saved[0]), _PerThread(saved[1])
    sys.stdout, sys.stderr = routed
    started = time.monotonic()
    try:
        with ThreadPoolExecutor(WORKERS) as pool:
            found = dict(pool.map(one, CASES))
    finally:
        sys.stdout, sys.stderr = saved
        for device in devices:
            device.close()
    print(f"\nCLI matrix: {len(found)} cases in {time.monotonic() - started:.0f} s")
    yield found


# --- What each case must give ------------------------------------------------------------------------


def _answer(state: str, command: str) -> tuple[str, ...]:
    """What the device sends for `command` in `state` (with its parameter block): () when nothing."""
    event = command_event(COMMANDS[command].code, state) or command
    if event != command:
        return ()
    transition = lookup(state, command)
    if transition is None:
        return ()
    sent = transition.send
    if STATES[transition.to].expects is not None:
        after = lookup(transition.to, PARAMETER_BLOCK)
        sent += after.send if after is not None else ()
    return sent


def _answer_lines(items: tuple[str, ...], stdout: str) -> list[str]:
    """The items of the answer that stdout does not show decoded."""
    lines = stdout.splitlines()
    missing = []
    for item in items:
        if item == ACK:
            kinds: set[str] = {"acknowledged"}
        elif item == OUTPUT or item.startswith(OUTPUT_PREFIX):
            kinds = OUTPUT_TABLES | {SENTENCE_KIND}
        else:
            kinds = {item}
        if not any(line.split(" ", 1)[0] in kinds for line in lines):
            missing.append(item)
    return missing


def _one_clear_outcome(result: Result) -> None:
    assert "Traceback" not in result.stderr, result.stderr
    assert result.status in (0, 2), (result.status, result.stderr)
    if result.status == 2:
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1, result.stderr


@pytest.mark.parametrize(("state", "command"), [(s, c) for s in STATES for c in COMMANDS])
def test_send(results: dict[Case, Result], state: str, command: str) -> None:
    result = results[("send", state, command)]
    _one_clear_outcome(result)
    expected = _answer(state, command)
    if expected:
        assert result.status == 0, result.stderr
        missing = _answer_lines(expected, result.stdout)
        assert not missing, f"the answer's {missing} not shown: {result.stdout!r}"


@pytest.mark.parametrize("state", list(STATES))
def test_params(results: dict[Case, Result], state: str) -> None:
    """The parameters, or one line (a sleeping device hears nothing but LowPowerOff, 6.3.8)."""
    result = results[("params", state, "-")]
    _one_clear_outcome(result)
    assert result.status == 2 or "update_rate = " in result.stdout, result.stdout


@pytest.mark.parametrize(("state", "start"), [(s, c) for s in STATES for c in ("-", *STARTS)])
def test_record(results: dict[Case, Result], state: str, start: str) -> None:
    """A capture with the device's answers in it, or one line. (The summary line goes to the
    sys.stderr of when ilahrs.cli.device was imported, so the capture is checked instead.)"""
    result = results[("record", state, start)]
    _one_clear_outcome(result)
    if result.status == 0:
        capture = result.output
        assert capture is not None and capture.exists()
        with capture.open("rb") as stream:
            inbound = [p for p in read(stream).packets if p.direction == Direction.INBOUND]
        assert inbound, f"{capture}: nothing from the device"


@pytest.mark.parametrize(("state", "kind"), [(s, k) for s in STATES for k in CALIBRATIONS])
def test_calibrate(results: dict[Case, Result], state: str, kind: str) -> None:
    result = results[("calibrate", state, kind)]
    _one_clear_outcome(result)
    assert "Calibration result" in result.stdout or result.status == 2, result.stdout


# --- monitor: a real terminal, a few real processes ----------------------------------------------


def _monitor(device: PtyDevice, seconds: float) -> tuple[int, str]:
    """`ilahrs monitor` on a terminal of its own for `seconds`, then q; (status, all it wrote)."""
    leader, follower = pty.openpty()
    env = {**os.environ, "TERM": "xterm", "LINES": "40", "COLUMNS": "120"}
    process = subprocess.Popen(
        [sys.executable, "-m", "ilahrs", "monitor", device.path],
        stdin=follower,
        stdout=follower,
        stderr=follower,
        env=env,
        close_fds=True,
    )
    os.close(follower)
    screen = bytearray()
    end = time.monotonic() + seconds
    quit_sent = False
    try:
        while process.poll() is None or select.select([leader], [], [], 0)[0]:
            if time.monotonic() > end and not quit_sent:
                os.write(leader, b"q")
                quit_sent = True
                end += 20  # then it must end
            elif time.monotonic() > end:
                process.kill()
                break
            if select.select([leader], [], [], 0.05)[0]:
                try:
                    screen += os.read(leader, 65536)
                except OSError:
                    break
        status = process.wait(20)
    finally:
        os.close(leader)
    return status, screen.decode("utf-8", "replace")


MONITOR_STATES: Final = [s for s in STATES if STATES[s].expects is None]
"""Monitor starts with a Stop; the states that wait for a block (1 s) cannot outlast its start-up."""


@pytest.mark.parametrize("state", MONITOR_STATES)
def test_monitor_briefly(state: str) -> None:
    device = PtyDevice(seed=7)
    try:
        drive(device, state)
        device.fast_after_input = True
        status, screen = _monitor(device, 1.5)
    finally:
        device.close()
    assert "Traceback" not in screen, screen
    assert status in (0, 2), screen[-2000:]
