"""The serial client against the device model, driven by Hypothesis as a user might drive it: every
command of Table C.1 from whatever state the device is in, after pauses around the idle timeout
(E41) and the output period, read in chunks of every size, with the device unplugged, power-cycled
and the port closed and reopened in between.

The device is `ilahrs.Device` behind a real pseudo-terminal, served by a thread the way
`ilahrs simulate` serves it (`ilahrs.edge.simulate.Line`, the line configured by `_configure_pty`, the
device's clock advanced with the wall clock), so pauses are real pauses. After every step:

- every message the device wrote to the line reaches the client, in order: none lost, none invented
  (the device's log against `client.received`), and no byte is discarded (the line has no faults);
- the client's idea of the device's state (`client.host.state`) is the device's;
- nothing but IlahrsError (ClientError included) ever comes out of the client.

Derandomized and bounded for `make test`; ILAHRS_STATEFUL_EXAMPLES and ILAHRS_STATEFUL_STEPS make
the run longer, ILAHRS_STATEFUL_RANDOM=1 draws new examples each run (`make fuzz-stateful`) and
ILAHRS_STATEFUL_SHRINK=1 shrinks a failing example (slow: every step takes real time).
The (state, command, pause) combinations explored are counted, printed at the end (pytest -s) and
written to build/stateful/client.txt.
"""

from __future__ import annotations

import os
import sys
import time
from collections import Counter
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

# The Python-versions run (tools/test-python-versions) installs pytest and pyserial only.
pytest.importorskip("hypothesis")

from hypothesis import HealthCheck, Phase, event, settings
from hypothesis import strategies as st
from hypothesis.stateful import (
    RuleBasedStateMachine,
    invariant,
    precondition,
    rule,
    run_state_machine_as_test,
)
from pty_device import DRAIN, SHORT_TIMER, TICK, PtyDevice

from ilahrs import IDLE_TIMEOUT, IlahrsError
from ilahrs.commands import COMMANDS
from ilahrs.edge.serial import AhrsClient
from ilahrs.encodings import DECLINATION_COMPUTE, DECLINATION_MAX, DECLINATION_MIN
from ilahrs.payloads import PAYLOADS, Payload
from ilahrs.statemachine import (
    DEFAULT_UPDATE_RATE_HZ,
    STATES,
    TIMER_FIELDS,
    TIMER_IS_RATE,
    command_event,
    lookup,
)

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

ROOT = Path(__file__).resolve().parents[2]
REPORT = ROOT / "build" / "stateful" / "client.txt"

EXAMPLES = int(os.environ.get("ILAHRS_STATEFUL_EXAMPLES", "8"))
STEPS = int(os.environ.get("ILAHRS_STATEFUL_STEPS", "25"))
RANDOM = os.environ.get("ILAHRS_STATEFUL_RANDOM") == "1"
SHRINK = RANDOM or os.environ.get("ILAHRS_STATEFUL_SHRINK") == "1"

PAUSES = sorted(
    {
        0.0,
        1.0 / DEFAULT_UPDATE_RATE_HZ,  # one output period
        IDLE_TIMEOUT / 2,
        IDLE_TIMEOUT - 0.001,  # just inside the idle timeout ...
        IDLE_TIMEOUT + 0.001,  # ... and just past it
        IDLE_TIMEOUT * 1.5,
        IDLE_TIMEOUT * 5,
        IDLE_TIMEOUT * 20,
    }
)
"""Seconds a caller waits, without reading, before its next command (0, 10, 50, 99, 101, 150, 500 ms, 2 s)."""
CHUNKS = (1, 2, 7, 64, 4096)
"""Most bytes one read of the port returns."""
LOSSES = ("unplugged", "power_cycle", "reopened")
"""How the device is lost and brought back: the line cut both ways while the device runs on; the
line cut and the device restarted (idle, as after power-up); the client's port closed and reopened."""
MAX_LOSSES = 2
"""Losses of the device in one example (each costs a reply timeout)."""
HISTORY = 10**7
"""Big enough that the client keeps every event of a run."""

EXPLORED: Counter[tuple[str, str, int]] = Counter()
"""(device state, command, pause in ms) -> times sent."""
OUTCOMES: Counter[str] = Counter()


def _ms(seconds: float) -> int:
    return round(seconds * 1000)


class _Chunked:
    """The client's port, returning at most `size` bytes a read."""

    def __init__(self, port: Any, size: int) -> None:
        self._port = port
        self.size = size

    def read(self, size: int = 1) -> bytes:
        data: bytes = self._port.read(min(size, self.size))
        return data

    def __getattr__(self, name: str) -> Any:
        return getattr(self._port, name)


# --- Parameter blocks drawn within the table's ranges ---------------------------------------------

_SHORT_FIELDS = {name for timer, (_table, name) in TIMER_FIELDS.items() if not TIMER_IS_RATE[timer]}
"""Alignment and accumulation times: kept short so that runs are quick."""


def _field_values(table: str) -> st.SearchStrategy[dict[str, object]]:
    fields: dict[str, st.SearchStrategy[object]] = {}
    for info in PAYLOADS[table].FIELDS:
        if info.type == "reserved" or info.low is None or info.high is None:
            continue
        if info.type.startswith(("u", "i")):
            low, high = int(info.low), int(info.high)
            if info.name in _SHORT_FIELDS:
                high = min(high, low + SHORT_TIMER)
            fields[info.name] = st.integers(low, high)
        elif info.encoding == "declination":  # a declination, or the request to compute it
            fields[info.name] = st.one_of(
                st.floats(DECLINATION_MIN, DECLINATION_MAX, width=32), st.just(DECLINATION_COMPUTE)
            )
        elif info.type == "f32":
            fields[info.name] = st.floats(info.low, info.high, width=32, allow_nan=False, allow_infinity=False)
    return st.fixed_dictionaries(fields)


BLOCKS = {name: _field_values(name) for name in {i.parameter_block for i in COMMANDS.values()} if name is not None}


def _heard(state: str, command: str) -> bool:
    """Whether the device answers or acts on `command` in `state` (the table has a transition)."""
    event = command_event(COMMANDS[command].code, state) or command
    return event == command and lookup(state, event) is not None


# --- The machine ----------------------------------------------------------------------------------


class ClientAgainstDevice(RuleBasedStateMachine):
    def __init__(self) -> None:
        super().__init__()
        self.device = PtyDevice(seed=1)
        self.client = self._open()
        self.earlier: list[bytes] = []
        """Messages earlier clients (before a reopen) received."""
        self.losses = 0

    def _open(self) -> AhrsClient:
        return AhrsClient(self.device.path, history=HISTORY)

    def teardown(self) -> None:
        self.client.close()
        self.device.close()

    def received(self) -> list[bytes]:
        return self.earlier + list(self.client.received)

    def _call(self, action: str, *args: Any) -> str:
        """Run a client method; the outcome ("answered", "refused" ...). Anything but an
        IlahrsError escapes and fails the test."""
        try:
            getattr(self.client, action)(*args)
        except IlahrsError as exc:
            return f"{type(exc).__name__} {exc.kind.name}"
        return "answered"

    def _drain(self) -> None:
        """Read until the client has received every message the device has written so far."""
        _state, count = self.device.snapshot()
        end = time.monotonic() + DRAIN
        while len(self.received()) < count and time.monotonic() < end:
            self.client.poll(TICK)

    # --- Rules ------------------------------------------------------------------------------------

    def _send(self, command: str | None, pause: float, chunk: int, data: st.DataObject) -> None:
        """Read in chunks of at most `chunk` bytes from now on; wait `pause` without reading; send
        `command` (None: one the device hears in its state) with its parameter block."""
        port = self.client._port
        self.client._port = _Chunked(port._port if isinstance(port, _Chunked) else port, chunk)
        time.sleep(pause)
        state, _count = self.device.snapshot()
        if command is None:
            command = data.draw(st.sampled_from([name for name in sorted(COMMANDS) if _heard(state, name)]))
        table = COMMANDS[command].parameter_block
        block: Payload | None = None
        if table is not None:
            block = PAYLOADS[table].from_raw(data.draw(BLOCKS[table], label=table))
        EXPLORED[(state, command, _ms(pause))] += 1
        event(f"{state} {command}")
        outcome = self._call("request", command, block)
        OUTCOMES[outcome] += 1
        event(outcome)

    @rule(
        command=st.sampled_from(sorted(COMMANDS)),
        pause=st.sampled_from(PAUSES),
        chunk=st.sampled_from(CHUNKS),
        data=st.data(),
    )
    def send_any(self, command: str, pause: float, chunk: int, data: st.DataObject) -> None:
        """Any command, whether or not the device hears it in its state."""
        self._send(command, pause, chunk, data)

    @rule(pause=st.sampled_from(PAUSES), chunk=st.sampled_from(CHUNKS), data=st.data())
    def send_heard(self, pause: float, chunk: int, data: st.DataObject) -> None:
        """A command the device hears in its state (every state hears one), so that runs go deep
        into calibration."""
        self._send(None, pause, chunk, data)

    @rule(seconds=st.sampled_from(PAUSES))
    def read(self, seconds: float) -> None:
        """Read for a while (the output, the timers' blocks)."""
        self.client.poll(seconds)

    @precondition(lambda self: self.losses < MAX_LOSSES)
    @rule(
        how=st.sampled_from(LOSSES),
        command=st.sampled_from(sorted(COMMANDS)),
        pause=st.sampled_from(PAUSES),
        data=st.data(),
    )
    def lose(self, how: str, command: str, pause: float, data: st.DataObject) -> None:
        """Lose the device, try a command while it is gone, bring it back, and Stop (6.3.5) as a
        user does before anything else."""
        self.losses += 1
        self.device.connect(False)
        self._drain()  # what was on the line before the cut still arrives
        if how == "reopened":
            self.client.close()
            self.earlier += list(self.client.received)
            self.client = self._open()
        else:
            table = COMMANDS[command].parameter_block
            block = None if table is None else PAYLOADS[table].from_raw(data.draw(BLOCKS[table], label=table))
            retries, self.client.retries = self.client.retries, 0
            OUTCOMES[f"while lost: {self._call('request', command, block)}"] += 1
            self.client.retries = retries
        time.sleep(pause)
        if how == "power_cycle":
            self.device.power_cycle()
        self.device.connect(True)
        outcome = self._call("stop")
        assert outcome == "answered", f"Stop after the device came back: {outcome}"

    # --- Invariants -------------------------------------------------------------------------------

    @invariant()
    def nothing_lost_or_invented(self) -> None:
        assert self.device.failure is None, self.device.failure
        _state, count = self.device.snapshot()
        self._drain()
        received = self.received()
        written = self.device.written
        rest = iter(written)
        invented = [m.hex(" ") for m in received if not any(m == w for w in rest)]
        assert not invented, f"the client received messages the device never wrote: {invented}"
        lost = [(i, m.hex(" ")[:29]) for i, m in enumerate(written[: len(received)]) if m != received[i]][:1]
        assert len(received) >= count and not lost, (
            f"{count - len(received)} of {count} messages the device wrote never reached the client "
            f"(the first at {lost}); last events: {list(self.client.events)[-4:]}"
        )
        assert self.client.discarded == 0, f"{self.client.discarded} bytes discarded on a clean line"

    @invariant()
    def the_client_knows_the_state(self) -> None:
        """The host's state is the device's once the bytes in flight have arrived (a command with
        no answer changes the host's state when it is written, the device's when it is read)."""
        end = time.monotonic() + DRAIN
        while True:
            state, _count = self.device.snapshot()
            if self.client.host.state == state or time.monotonic() > end:
                break
            self.client.poll(TICK)
        assert self.client.host.state == state, (
            f"the client believes {self.client.host.state}, the device is in {state}"
        )


def _report() -> str:
    states = {s for s, _c, _p in EXPLORED}
    commands = {c for _s, c, _p in EXPLORED}
    pauses = {p for _s, _c, p in EXPLORED}
    heard = {(s, c, p) for s, c, p in EXPLORED if _heard(s, c)}
    lines = [
        f"stateful client test: {EXAMPLES} examples x {STEPS} steps" + (" (random)" if RANDOM else " (derandomized)"),
        f"explored {len(EXPLORED)} (state, command, pause) combinations of "
        f"{len(STATES)} x {len(COMMANDS)} x {len(PAUSES)} = {len(STATES) * len(COMMANDS) * len(PAUSES)}: "
        f"{len(states)} states x {len(commands)} commands x {len(pauses)} pauses seen; "
        f"{len(heard)} of them commands the device hears in that state; {sum(EXPLORED.values())} commands sent",
        "states: " + ", ".join(sorted(states)),
        "outcomes: " + ", ".join(f"{k} {v}" for k, v in sorted(OUTCOMES.items())),
    ]
    return "\n".join(lines)


SETTINGS = settings(
    max_examples=EXAMPLES,
    stateful_step_count=STEPS,
    derandomize=not RANDOM,
    database=None,
    deadline=None,
    print_blob=True,
    phases=(Phase.explicit, Phase.generate, Phase.shrink) if SHRINK else (Phase.explicit, Phase.generate),
    suppress_health_check=list(HealthCheck),
)


@pytest.fixture
def report() -> Iterator[None]:
    EXPLORED.clear()
    OUTCOMES.clear()
    try:
        yield
    finally:
        text = _report()
        REPORT.parent.mkdir(parents=True, exist_ok=True)
        REPORT.write_text(text + "\n")
        print("\n" + text)


def test_the_client_keeps_every_answer_and_the_state_whatever_the_user_does(report: None) -> None:
    run_state_machine_as_test(ClientAgainstDevice, settings=SETTINGS)
