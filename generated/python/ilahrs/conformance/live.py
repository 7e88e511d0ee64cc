# Copied from generator/targets/python/runtime/conformance/live.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Live conformance: drive a device through the session flows in real time and check each answer
(`ilahrs conformance --device PORT`).

Every `flow/...` vector of the `sessions` suite is a list of events a host can cause: a command
(any code, also unknown ones), a data message (the parameter block of the state when its size is
the one the state expects, else a message of that size) or a timer (waited for in real time: the
alignment and accumulation times, one output period, the parameter block timeout; a timer the
state does not run is a pause in which nothing may come). The expectation of each step comes from
the state machine of this package (`ilahrs.statemachine`) on the firmware the device reports, not
from the vector, so a device on older firmware is held to the rows of its own version. Checked:

- an acknowledgement carries the checksum of the message it acknowledges (E12);
- a data block is of the table the model expects and decodes (range checks included);
- output is of the format started, and continuous output comes at the configured rate: within
  RATE_TOLERANCE (relative) plus RATE_SLACK blocks over each stretch of continuous output;
- nothing comes where the model sends nothing (a pause of `--quiet` seconds after each step;
  output already on the line when a command leaves continuous mode is allowed for LATE_S).

The run first reads the device's parameters (Table 6.10) and loads them back with the alignment
time `--alignment-time`, the time the model waits for too (also when the device was set to align
faster: the commands a flow sends during an alignment must fit in it, and a run whose
`--alignment-time` is too short for them is refused); calibration runs use `--accumulation-time`. At the end, also
after a failure, Ctrl-C or SIGTERM, it loads the original parameters and reads them back, so a run
changes nothing on the unit. Flows that would change the stored calibration (AcceptClb after a
result, ClearClb) are skipped unless `--allow-calibration`. pyserial is needed (the `serial` extra).
"""

from __future__ import annotations

import argparse
import importlib
import json
import re
import sys
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import IO, Any, Final

from ..commands import COMMAND_SET, COMMANDS
from ..edge.signals import sigterm_as_interrupt
from ..errors import IlahrsError
from ..frame import Frame, MessageType
from ..nmea import NMEA_MAX_RATE_HZ, PahrSentence
from ..payloads import PAYLOADS, Payload
from ..roles import FIRMWARE, LOAD_PARAMETERS, LOW_POWER_OFF, READ_PARAMETERS, STOP
from ..session.host import Output
from ..spec import SERIAL_LINE
from ..statemachine import (
    ACK,
    BLOCK_TIMEOUT,
    COMMAND_EFFECTS,
    DEFAULT_FIRMWARE,
    INITIAL,
    OTHER_MESSAGE,
    OUTPUT,
    OUTPUT_FORMATS,
    OUTPUT_PREFIX,
    PARAMETER_BLOCK,
    PARAMETER_BLOCK_TIMEOUT_S,
    STATES,
    TIMER_EVENTS,
    TIMER_FIELDS,
    UNKNOWN,
    command_event,
    lookup,
)
from ..stream import StreamDecoder, StreamEvent
from .declaration import DeclarationError, load_declaration
from .report import junit_xml
from .runner import Case
from .runner import Plan as Selection
from .vectors import CommandEvent, DataEvent, SessionEvent, SuiteError, TimerEvent, Vector, load_suites, session

__all__ = ["RATE_SLACK", "RATE_TOLERANCE", "Plan", "alignment_needed", "plan_flow", "run_live"]

RATE_TOLERANCE: Final = 0.10
"""Continuous output: the count of blocks may differ from rate x time by this fraction ..."""
RATE_SLACK: Final = 2
"""... plus this many blocks (one period at each end of the stretch)."""
MIN_RATE_BLOCKS: Final = 10
"""A stretch shorter than this many periods is too short to measure the rate."""
REPLY_S: Final = 1.0
"""How long an answer may take (covers the 0.5 s of a calibration result, E38)."""
LATE_S: Final = 0.1
"""Output already on the line when a command leaves continuous mode."""
BLOCK_TIMEOUT_MARGIN_S: Final = 0.3
_POLL: Final = 0.01
_VERSION = re.compile(r"[0-9]+(?:\.[0-9]+)+")
_EFFECTS: Final = frozenset(COMMAND_EFFECTS)
_LOAD_TABLE: Final = COMMANDS[LOAD_PARAMETERS].parameter_block or ""
_READ_TABLE: Final = COMMANDS[READ_PARAMETERS].response_payloads[0]
_FIRMWARE_TABLE: Final = COMMANDS[FIRMWARE].response_payloads[0]


class MismatchError(Exception):
    """The device did not do what the model says."""


class UsageError(Exception):
    """The run's options cannot work (exit status 2)."""


# --- the plan: a flow's steps on the model -------------------------------------------------------


@dataclass(frozen=True)
class Step:
    """One event of a flow on the model: `cause` as the vector gives it, the event the table names,
    the states before and after, and what the device sends."""

    cause: SessionEvent
    event: str
    before: str
    after: str
    send: tuple[str, ...]
    output: str | None
    """The output format in effect after the step."""
    wait: str | None = None
    """A timer event the device fires in `before`: alignment, accumulation, output or block_timeout."""
    changes_calibration: bool = False


@dataclass(frozen=True)
class Plan:
    id: str
    steps: tuple[Step, ...]

    @property
    def changes_calibration(self) -> bool:
        return any(s.changes_calibration for s in self.steps)


def _resolve(cause: SessionEvent, state: str) -> str:
    """The event of the state machine's table that `cause` is in `state`."""
    if isinstance(cause, CommandEvent):
        return command_event(cause.code, state) or UNKNOWN
    if isinstance(cause, DataEvent):
        expects = STATES[state].expects
        return PARAMETER_BLOCK if expects is not None and cause.size == PAYLOADS[expects].SIZE else OTHER_MESSAGE
    return cause.name


def _timer_of(state: str, event: str) -> str | None:
    info = STATES[state]
    if event == BLOCK_TIMEOUT and info.expects is not None:
        return BLOCK_TIMEOUT
    if info.timer is not None and TIMER_EVENTS[info.timer] == event:
        return info.timer
    return None


def plan_flow(v: Vector, firmware: str | None) -> Plan:
    """The steps of a session vector on the model of `firmware` (None: current)."""
    state, output = INITIAL, None
    steps = []
    for cause in session(v.input, v.where).events:
        event = _resolve(cause, state)
        transition = lookup(state, event, firmware)
        wait = _timer_of(state, event) if isinstance(cause, TimerEvent) and transition is not None else None
        if transition is None:
            steps.append(Step(cause, event, state, state, (), output))
            continue
        info = COMMANDS.get(event)
        if info is not None and info.starts_output is not None:
            output = info.starts_output
        changes = event in _EFFECTS
        steps.append(Step(cause, event, state, transition.to, transition.send, output, wait, changes))
        state = transition.to
    return Plan(v.id, tuple(steps))


# --- the line ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Received:
    t: float
    message: StreamEvent


class Link:
    """The serial line: frames out, timestamped messages in."""

    def __init__(self, port: str, baud: int) -> None:
        try:
            serial = importlib.import_module("serial")
        except ImportError as exc:  # pragma: no cover - depends on the environment
            raise ImportError("the live mode needs pyserial: pip install 'pyserial>=3.5'") from exc
        parity = {"none": "N", "even": "E", "odd": "O"}[str(SERIAL_LINE["parity"])]
        self._port = serial.serial_for_url(
            port,
            baudrate=baud,
            bytesize=SERIAL_LINE["data_bits"],
            parity=parity,
            stopbits=SERIAL_LINE["stop_bits"],
            timeout=_POLL,
            write_timeout=5.0,
        )
        self._decoder = StreamDecoder()
        self._heard = time.monotonic()

    def close(self) -> None:
        self._port.close()

    def write(self, data: bytes) -> float:
        self._port.write(data)
        self._port.flush()
        return time.monotonic()

    def read(self) -> list[Received]:
        """What arrives within one poll interval (and what an idle line releases, E41)."""
        data: bytes = self._port.read(max(1, self._port.in_waiting))
        now = time.monotonic()
        if data:
            self._heard = now
            return [Received(now, m) for m in self._decoder.feed(data)]
        return [Received(now, m) for m in self._decoder.idle(now - self._heard)] if self._decoder.pending else []

    def drain(self, quiet: float, limit: float) -> int:
        """Read until nothing came for `quiet` seconds (at most `limit`); the count of messages."""
        count = 0
        end = time.monotonic() + limit
        last = time.monotonic()
        while time.monotonic() < end and time.monotonic() - last < quiet:
            got = self.read()
            if got:
                count += len(got)
                last = time.monotonic()
        return count


def _frame(kind: int, payload: bytes) -> bytes:
    return Frame(kind, payload).build()


def _command(name: str) -> bytes:
    return _frame(MessageType.COMMAND, bytes([COMMANDS[name].code]))


def _describe(m: StreamEvent) -> str:
    if m.sentence is not None:
        return "a $PAHR sentence"
    assert m.frame is not None
    kind = "command" if m.frame.message_type == MessageType.COMMAND else "data"
    return f"a {kind} frame with a {len(m.frame.payload)}-byte payload ({m.raw[:16].hex(' ')}...)"


def _data_block(m: StreamEvent, table: str) -> Payload | None:
    """The message as a block of `table` (None: not its size); MismatchError if it does not decode."""
    frame = m.frame
    cls = PAYLOADS[table]
    if frame is None or frame.message_type != MessageType.DATA or len(frame.payload) != cls.SIZE:
        return None
    try:
        block = cls.parse(frame.payload)
        block.check()
    except IlahrsError as exc:
        raise MismatchError(f"the {table} block does not decode: {exc}") from None
    return block


def _first_int(block: Payload) -> int:
    """The value of a block's first field (the checksum of an acknowledgement)."""
    value = next(iter(block.raw().values()))
    return value if isinstance(value, int) else -1


def _output(m: StreamEvent, fmt: str | None, mode: str | None) -> Output | None:
    """The message as an output block of format `fmt` (and USW mode `mode`, if given), or None."""
    if fmt is None:
        return None
    table = OUTPUT_FORMATS.get(fmt)
    data: Payload | PahrSentence | None = m.sentence if table is None else _data_block(m, table)
    if data is None:
        return None
    out = Output(data)
    return out if mode is None or out.usw.mode == mode else None


# --- running a flow -------------------------------------------------------------------------------


@dataclass
class Settings:
    quiet: float
    firmware: str | None
    rate: float
    durations: dict[str, float]
    blocks: dict[str, bytes]
    """Host-to-device table -> the payload the run sends for it."""


@dataclass
class FlowRun:
    """One flow against the device: the trace, the output timestamps, the stretches of output."""

    link: Link
    settings: Settings
    start: float = field(default_factory=time.monotonic)
    trace: list[str] = field(default_factory=list)
    outputs: list[float] = field(default_factory=list)
    streaming_since: float | None = None
    streaming: str | None = None
    """The output format of the stretch."""

    def note(self, t: float, text: str) -> None:
        self.trace.append(f"{t - self.start:+8.3f} s  {text}")

    def payload(self, cause: CommandEvent | DataEvent) -> bytes:
        if isinstance(cause, CommandEvent):
            return _frame(MessageType.COMMAND, bytes([cause.code]))
        for block in self.settings.blocks.values():
            if len(block) == cause.size:
                return _frame(MessageType.DATA, block)
        return _frame(MessageType.DATA, bytes(cause.size))

    def run(self, plan: Plan) -> None:
        for n, step in enumerate(plan.steps):
            try:
                self.step(step)
            except MismatchError as exc:
                raise MismatchError(f"step {n} ({step.cause.token} = {step.event} in {step.before}): {exc}") from None
        if self.streaming_since is not None:
            self.check_rate(self.streaming_since, time.monotonic())

    def step(self, step: Step) -> None:
        sent: int | None = None
        if isinstance(step.cause, TimerEvent):
            t0 = time.monotonic()
            self.note(t0, f"wait for {step.event}" + ("" if step.wait else " (no timer of it runs: a pause)"))
        else:
            data = self.payload(step.cause)
            sent = Frame.parse(data).checksum
            t0 = self.link.write(data)
            self.note(t0, f"sent {step.cause.token} ({step.event}): {data.hex(' ')}")
        leaving = STATES[step.before].timer == "output" and STATES[step.after].timer != "output"
        if leaving and self.streaming_since is not None:
            self.check_rate(self.streaming_since, t0)
            self.streaming_since = None
        owed = list(step.send)
        wait = 0.0 if step.wait is None else self.settings.durations[step.wait]
        deadline = t0 + wait + REPLY_S
        settle = t0 + (wait + BLOCK_TIMEOUT_MARGIN_S if step.wait == BLOCK_TIMEOUT else 0.0)
        quiet_until = max(settle, t0 + self.settings.quiet)
        ignored = 0
        while owed or time.monotonic() < quiet_until:
            if owed and time.monotonic() > deadline:
                got = f" (meanwhile {ignored} output blocks)" if ignored else ""
                raise MismatchError(f"no {owed[0]} within {deadline - t0:.1f} s{got}")
            for r in self.link.read():
                if owed and self.match(owed[0], step, r, sent):
                    owed.pop(0)
                    quiet_until = max(settle, r.t + self.settings.quiet)
                    if not owed and STATES[step.after].timer == "output" and step.before != step.after:
                        self.streaming_since, self.streaming = r.t, step.output
                elif self.allowed(step, r, t0, bool(owed)):
                    ignored += 1
                else:
                    expected = f"while waiting for {owed[0]}" if owed else "where the model sends nothing"
                    self.note(r.t, f"got {_describe(r.message)}")
                    raise MismatchError(f"{_describe(r.message)} at {r.t - self.start:+.3f} s {expected}")

    def match(self, item: str, step: Step, r: Received, sent: int | None) -> bool:
        """Whether `r` is the owed `item`; MismatchError if it is of its kind but wrong."""
        if item == ACK:
            block = _data_block(r.message, COMMAND_SET.acknowledgement.NAME)
            if block is None:
                return False
            value = _first_int(block)
            if value != sent:
                self.note(r.t, f"got an acknowledgement carrying {value:#06x}")
                raise MismatchError(f"the acknowledgement carries {value:#06x}, the message sent has {sent:#06x} (E12)")
            self.note(r.t, f"got ack {value:#06x}")
            return True
        if item == OUTPUT or item.startswith(OUTPUT_PREFIX):
            mode = None if item == OUTPUT else item.removeprefix(OUTPUT_PREFIX)
            if _output(r.message, step.output, mode) is None:
                return False
            self.outputs.append(r.t)
            self.note(r.t, f"got {item} ({step.output})")
            return True
        if _data_block(r.message, item) is None:
            return False
        self.note(r.t, f"got {item}")
        return True

    def allowed(self, step: Step, r: Received, t0: float, owing: bool) -> bool:
        """Output that may come besides the step's answers: the output of a state that streams."""
        streams_after = STATES[step.after].timer == "output"
        streams_before = STATES[step.before].timer == "output" and (owing or r.t - t0 <= LATE_S)
        if (streams_after or streams_before) and _output(r.message, step.output, None) is not None:
            if streams_after and (step.before == step.after or not owing):
                self.outputs.append(r.t)
            return True
        return False

    def check_rate(self, since: float, until: float) -> None:
        fmt_rate = self.settings.rate
        if OUTPUT_FORMATS.get(self.streaming or "") is None:
            fmt_rate = min(fmt_rate, NMEA_MAX_RATE_HZ)  # E22
        periods = (until - since) * fmt_rate
        if periods < MIN_RATE_BLOCKS:
            self.note(until, f"output for {until - since:.3f} s: too short to measure the rate")
            return
        count = sum(since < t <= until for t in self.outputs)
        allowed = RATE_TOLERANCE * periods + RATE_SLACK
        self.note(until, f"{count} output blocks in {until - since:.3f} s, {periods:.1f} expected at {fmt_rate:g} Hz")
        if abs(count - periods) > allowed:
            raise MismatchError(
                f"{count} output blocks in {until - since:.3f} s: {count / (until - since):.1f} Hz, "
                f"configured {fmt_rate:g} Hz (tolerance {RATE_TOLERANCE:.0%} + {RATE_SLACK} blocks)"
            )


# --- the run: parameters, flows, restore ----------------------------------------------------------


def _reset(link: Link, quiet: float) -> None:
    """Back to idle from any state: LowPowerOff (wakes a sleeping device, leaves a block wait),
    then the 0xFE code (Stop, or ExitClb in calibration), then a quiet line."""
    link.write(_command(LOW_POWER_OFF) + _command(STOP))
    link.drain(max(quiet, 0.2), 3.0)


def _ask(link: Link, data: bytes, want: str, quiet: float, ack_of: bytes = b"") -> tuple[Payload | None, list[str]]:
    """Send `data` from idle; the answer block of table `want` and any problems (an acknowledgement
    is checked against the checksum of `ack_of`)."""
    _reset(link, quiet)
    t0 = link.write(data)
    problems: list[str] = []
    while time.monotonic() < t0 + REPLY_S:
        for r in link.read():
            try:
                block = _data_block(r.message, want)
            except MismatchError as exc:
                problems.append(str(exc))
                continue
            if block is None:
                problems.append(f"unexpected {_describe(r.message)}")
                continue
            value = _first_int(block)
            if ack_of and value != Frame.parse(ack_of).checksum:
                problems.append(f"the acknowledgement carries {value:#06x}, not the checksum of the block (E12)")
            return block, problems
    return None, [*problems, f"no {want} within {REPLY_S} s"]


def _load_fields(block: Payload) -> dict[str, object]:
    names = {f.name for f in PAYLOADS[_LOAD_TABLE].FIELDS if f.type != "reserved"}
    return {k: v for k, v in block.raw().items() if k in names}


class Parameters:
    """The device's parameters around the run."""

    def __init__(self, link: Link, quiet: float) -> None:
        self.link = link
        self.quiet = quiet
        self.original: dict[str, object] | None = None

    def read(self) -> dict[str, object]:
        block, problems = _ask(self.link, _command(READ_PARAMETERS), _READ_TABLE, self.quiet)
        if block is None:
            raise MismatchError(f"{READ_PARAMETERS}: {'; '.join(problems)}")
        return _load_fields(block)

    def firmware(self) -> str:
        block, problems = _ask(self.link, _command(FIRMWARE), _FIRMWARE_TABLE, self.quiet)
        if block is None:
            raise MismatchError(f"{FIRMWARE}: {'; '.join(problems)}")
        return str(next(iter(block.raw().values())))

    def load(self, values: Mapping[str, object]) -> list[str]:
        block = PAYLOADS[_LOAD_TABLE].from_raw(values).build()
        frame = _frame(MessageType.DATA, block)
        ack = COMMAND_SET.acknowledgement.NAME
        _ack, problems = _ask(self.link, _command(LOAD_PARAMETERS) + frame, ack, self.quiet, frame)
        return problems

    def restore(self) -> str | None:
        """Load the original parameters and read them back; None when they are back, else why not."""
        if self.original is None:
            return None
        why = "not tried"
        for _attempt in range(3):
            try:
                problems = self.load(self.original)
                if self.read() == self.original:
                    return None
                why = "read back differs" + (f" ({'; '.join(problems)})" if problems else "")
            except MismatchError as exc:
                why = str(exc)
        return why


def _flows(args: argparse.Namespace) -> tuple[list[Vector], list[tuple[Vector, str, str]]]:
    """The flows to run, and those --level or --declaration exclude: (flow, outcome, why)."""
    suites = {s.name: s for s in load_suites(args.vectors)}
    if "sessions" not in suites:
        raise SuiteError(f"no sessions suite in {args.vectors}")
    flows = [v for v in suites["sessions"].vectors if v.id.startswith("flow/")]
    flows = [v for v in flows if not args.pattern or args.pattern in v.id]
    declaration = load_declaration(args.declaration) if args.declaration is not None else None
    plan = Selection(args.level, None, declaration)
    run: list[Vector] = []
    excluded: list[tuple[Vector, str, str]] = []
    for v in flows:
        why = plan.excluded(v)
        if why is None:
            run.append(v)
        else:
            excluded.append((v, *why))
    return run, excluded


def _version(text: str) -> str | None:
    found = _VERSION.search(text)
    return found.group() if found else None


def _number(value: object) -> float:
    assert isinstance(value, (int, float))
    return float(value)


def _settings(args: argparse.Namespace, run_values: Mapping[str, object], firmware: str | None) -> Settings:
    """The run's timing: what the device was loaded with (`run_values`), so the model waits as
    long as the device does."""
    rate = _number(run_values[TIMER_FIELDS["output"][1]])
    blocks: dict[str, bytes] = {}
    for name, cls in PAYLOADS.items():
        if cls.DIRECTION == "host_to_device" and name != COMMAND_SET.acknowledgement.NAME:
            values: dict[str, object] = dict(run_values) if name == _LOAD_TABLE else {}
            table, accumulation = TIMER_FIELDS["accumulation"]
            if name == table:
                values[accumulation] = args.accumulation_time
            names = {f.name for f in cls.FIELDS}
            blocks[name] = cls.from_raw({k: v for k, v in values.items() if k in names}).build()
    durations = {
        "alignment": float(_number(run_values[TIMER_FIELDS["alignment"][1]])),
        "accumulation": float(args.accumulation_time),
        "output": 1.0 / rate,
        BLOCK_TIMEOUT: PARAMETER_BLOCK_TIMEOUT_S,
    }
    return Settings(args.quiet, firmware, float(rate), durations, blocks)


ALIGNMENT_MARGIN_S: Final = 0.5
"""Time an alignment needs besides the quiet pauses of the commands sent during it."""


def alignment_needed(plans: list[Plan], quiet: float) -> tuple[float, str]:
    """The shortest alignment time (s) in which every plan's commands during an alignment fit (each
    is followed by `quiet` seconds in which nothing may come), and the plan that needs it."""
    needed, worst = 0.0, ""
    for plan in plans:
        during = 0
        for step in plan.steps:
            if STATES[step.before].timer == "alignment" and step.wait is None:
                during += 1
                seconds = during * quiet + ALIGNMENT_MARGIN_S
                if seconds > needed:
                    needed, worst = seconds, plan.id
            elif STATES[step.after].timer != "alignment":
                during = 0
    return needed, worst


def _flow_case(link: Link, settings: Settings, plan: Plan) -> Case:
    flow = FlowRun(link, settings)
    _reset(link, settings.quiet)
    flow.start = time.monotonic()
    try:
        flow.run(plan)
    except MismatchError as exc:
        detail = "\n".join(flow.trace[-40:])
        return Case("live.sessions", plan.id, "failed", str(exc), detail, time.monotonic() - flow.start)
    return Case("live.sessions", plan.id, "passed", seconds=time.monotonic() - flow.start)


@dataclass
class LiveReport:
    port: str
    firmware_text: str = ""
    firmware: str | None = None
    cases: list[Case] = field(default_factory=list)
    plans: dict[str, Plan] = field(default_factory=dict)
    flows: dict[str, Vector] = field(default_factory=dict)
    """Every flow of the run, by id (its level)."""
    outcomes: dict[str, str] = field(default_factory=dict)
    """A flow that did not run -> not_applicable or skipped."""
    restored: str | None = "not started"
    interrupted: bool = False
    error: str | None = None
    """Why the run stopped before its flows ended (the device, the suites or the options)."""
    touched: bool = False
    """Whether the run read the parameters (and so may have changed them)."""
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return (
            not self.interrupted
            and self.error is None
            and self.restored is None
            and all(c.status != "failed" for c in self.cases)
        )

    def as_json(self) -> dict[str, Any]:
        return {
            "ok": self.ok,
            "device": self.port,
            "firmware": self.firmware_text,
            "model_firmware": self.firmware or DEFAULT_FIRMWARE,
            "seconds": round(self.seconds, 3),
            "interrupted": self.interrupted,
            "restored": self.restored is None,
            "restore_problem": self.restored,
            "error": self.error,
            "flows": [
                {
                    "id": c.name,
                    "status": c.status,
                    "outcome": self.outcomes.get(c.name, c.status),
                    "level": self.flows[c.name].level if c.name in self.flows else None,
                    "erratum": self.flows[c.name].erratum if c.name in self.flows else None,
                    "message": c.message,
                    "seconds": round(c.seconds, 3),
                    "steps": [
                        {"event": s.event, "state": s.after, "send": list(s.send)}
                        for s in (self.plans[c.name].steps if c.name in self.plans else ())
                    ],
                }
                for c in self.cases
            ],
        }


def _run_flows(args: argparse.Namespace, device: Parameters, report: LiveReport, out: IO[str]) -> None:
    flows, excluded = _flows(args)
    for v, outcome, why in excluded:
        report.flows[v.id] = v
        report.outcomes[v.id] = outcome
        report.cases.append(Case("live.sessions", v.id, "skipped", f"{outcome.replace('_', ' ')}: {why}"))
    device.original = None
    original = device.read()
    report.firmware_text = device.firmware()
    report.firmware = _version(report.firmware_text)
    plans = [plan_flow(v, report.firmware) for v in flows]
    needed, worst = alignment_needed(plans, args.quiet)
    if args.alignment_time < needed:
        raise UsageError(
            f"--alignment-time {args.alignment_time} is too short: {worst} sends its commands during an "
            f"alignment of at least {needed:g} s at --quiet {args.quiet:g}"
        )
    device.original = original
    report.touched = True
    run_values = dict(original)
    run_values[TIMER_FIELDS["alignment"][1]] = args.alignment_time
    if run_values != original:
        problems = device.load(run_values)
        if device.read() != run_values:
            raise MismatchError(f"could not load the run's parameters: {'; '.join(problems) or 'read back differs'}")
    settings = _settings(args, run_values, report.firmware)
    out.write(
        f"live: {len(flows)} flows on {args.device} (firmware {report.firmware_text!r}: the model of "
        f"{report.firmware or DEFAULT_FIRMWARE}); update rate {settings.rate:g} Hz, alignment "
        f"{settings.durations['alignment']:g} s, accumulation {settings.durations['accumulation']:g} s\n"
    )
    out.flush()
    for v, plan in zip(flows, plans, strict=True):
        report.plans[v.id] = plan
        report.flows[v.id] = v
        if plan.changes_calibration and not args.allow_calibration:
            case = Case("live.sessions", v.id, "skipped", "changes the stored calibration (--allow-calibration)")
        else:
            case = _flow_case(device.link, settings, plan)
        report.cases.append(case)
        word = {"passed": "PASS", "failed": "FAIL", "skipped": "SKIP"}[case.status]
        out.write(f"{word} {v.id} ({case.seconds:.2f} s){': ' + case.message if case.message else ''}\n")
        out.flush()


def _summary(report: LiveReport, out: IO[str]) -> None:
    counts = {s: sum(c.status == s for c in report.cases) for s in ("passed", "failed", "skipped")}
    inapplicable = sum(o == "not_applicable" for o in report.outcomes.values())
    counts["skipped"] -= inapplicable
    for case in report.cases:
        if case.status == "failed":
            out.write(f"\nFAILED {case.name}: {case.message}\n")
            out.write("".join(f"  {line}\n" for line in case.detail.splitlines()))
    restored = "parameters restored" if report.restored is None else f"PARAMETERS NOT RESTORED: {report.restored}"
    if not report.touched:
        restored = "parameters not changed"
    out.write(
        f"\nlive: {len(report.cases)} flows: {counts['passed']} passed, {counts['failed']} failed, "
        f"{counts['skipped']} skipped, {inapplicable} not applicable in {report.seconds:.1f} s; {restored}\n"
    )
    out.write(f"{'PASSED' if report.ok else 'INTERRUPTED' if report.interrupted else 'FAILED'}\n")


def run_live(args: argparse.Namespace, out: IO[str] = sys.stdout) -> int:
    """`ilahrs conformance --device PORT`: 0 when every flow run passed and the parameters are back,
    1 on a failure, 2 when the device cannot be opened or the suites read, 130 when interrupted."""
    baud = args.baud or int(SERIAL_LINE["baud_rate"])
    try:
        link = Link(args.device, baud)
    except (ImportError, OSError, ValueError) as exc:
        print(f"ilahrs conformance: cannot open {args.device}: {exc}", file=sys.stderr)
        return 2
    report = LiveReport(args.device)
    device = Parameters(link, args.quiet)
    start = time.monotonic()
    status: int | None = None
    try:
        with sigterm_as_interrupt():
            try:
                _run_flows(args, device, report, out)
            except KeyboardInterrupt:
                report.interrupted = True
                print("ilahrs conformance: interrupted; restoring the parameters", file=sys.stderr)
            except (SuiteError, DeclarationError, MismatchError, UsageError) as exc:
                print(f"ilahrs conformance: {exc}", file=sys.stderr)
                report.error = str(exc)
                status = 1 if isinstance(exc, MismatchError) else 2
            finally:
                report.restored = device.restore()
    finally:
        link.close()
    report.seconds = time.monotonic() - start
    _write_reports(args, report)
    _summary(report, out)
    if status is not None:
        return status
    return 130 if report.interrupted else 0 if report.ok else 1


def _write_reports(args: argparse.Namespace, report: LiveReport) -> None:
    if args.json:
        args.json.write_text(json.dumps(report.as_json(), indent=1) + "\n", encoding="utf-8")
    if args.junit:
        cases = list(report.cases)
        if report.restored is not None:
            cases.append(Case("live.parameters", "restore", "failed", report.restored))
        args.junit.write_text(junit_xml(cases, "ilahrs live conformance"), encoding="utf-8")
