# Copied from generator/targets/python/runtime/edge/serial.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""A serial client for a real or virtual AHRS: the host session (`ilahrs.session.host`) over pyserial.

pyserial is the optional dependency (the `serial` extra, or `pip install 'pyserial>=3.5'`) and is imported only when a
client is opened, so the rest of the package stays standard-library only. `port` is anything
`serial.serial_for_url` opens: a device path (/dev/ttyUSB0, the pty `ilahrs simulate` prints) or
`socket://127.0.0.1:PORT` for `ilahrs simulate --tcp`.

    with AhrsClient("/dev/ttyUSB0") as ahrs:
        ahrs.stop()
        params = ahrs.read_parameters()
        ahrs.load_parameters(params.raw() | {"update_rate": 50})
        ahrs.start("AHRScont3")
        for block in ahrs.output():            # or ahrs.frames(100): a list
            print(block.heading_deg)

Every method waits for exactly the answers the protocol defines and raises ClientError if they do
not come (or come wrong). Flows that start from idle are retried after a Stop (`retries`), so a
line that loses a message now and then still completes them. The last `history` events the
host saw are in `events` (each stamped with its time.monotonic() receive time, `at`); protocol
errors in `errors`; the count of bytes that belonged to no message in `discarded`. History is
bounded, so a client can stream for days.

A message never spans an idle line (E41): bytes the host holds (the start of a frame whose rest
never came) are given up once reads have returned nothing for IDLE_TIMEOUT. The quiet time counts
until a read finds bytes, never past them: an answer that begins after a pause of any length, the
caller's included, is read whole (`Host.receive(data, within=...)`).
`strict`: refuse data frames whose reserved byte is not the AHRS's (E42; they count as discarded).

A device path is opened for this client alone (POSIX: pyserial's `exclusive`, an flock on the
port): while it is open, opening the same port again, from this process or another, raises
`serial.SerialException` with errno EAGAIN. A socket:// URL is not locked.
"""

from __future__ import annotations

import dataclasses
import importlib
import os
import time
from collections import deque
from collections.abc import Callable, Iterator, Mapping
from types import TracebackType
from typing import Any, Final, TypeVar

from ..commands import COMMAND_SET, COMMANDS, build_command
from ..encodings import CalibrationType
from ..errors import ErrorKind, IlahrsError, brief, require_int, require_seconds, suggest
from ..nmea import PahrSentence
from ..payloads import PAYLOADS, Payload
from ..roles import (
    ACCEPT,
    BUILT_IN_TEST,
    CALIBRATION_RESULTS,
    CLEAR_CALIBRATION,
    FINISH,
    FIRMWARE,
    GET_DATA,
    LOAD_PARAMETERS,
    LOW_POWER_OFF,
    LOW_POWER_ON,
    READ_PARAMETERS,
    START_RUN,
    START_RUNS,
    STOP,
    STOP_RUN,
    ParameterBlock,
)
from ..session.anystate import AnyStateRequest, Reply
from ..session.host import Acknowledged, DataBlock, Discarded, Host, HostEvent, Output, ProtocolError
from ..spec import SERIAL_LINE
from ..statemachine import CALIBRATION_TYPES, INITIAL, TIMER_EVENTS, command_event, lookup

__all__ = ["LINE", "AhrsClient", "ClientError"]

_PARITY: Final = {"none": "N", "even": "E", "odd": "O"}
LINE: Final[Mapping[str, object]] = {
    "baudrate": SERIAL_LINE["baud_rate"],
    "bytesize": SERIAL_LINE["data_bits"],
    "parity": _PARITY[str(SERIAL_LINE["parity"])],
    "stopbits": SERIAL_LINE["stop_bits"],
}
"""pyserial settings of the AHRS line (section 6)."""
_POLL: Final = 0.01
DEFAULT_HISTORY: Final = 1000
"""Events (and received messages, and protocol errors) a client keeps by default."""
_QUEUE_LIMIT: Final = 4096
"""Answers and output blocks held for a caller that does not take them; the oldest go first."""


_T = TypeVar("_T")


class History(list[_T]):
    """A list that keeps only its last `limit` items (the oldest are dropped as new ones come)."""

    def __init__(self, limit: int) -> None:
        super().__init__()
        self.limit = limit

    def append(self, item: _T) -> None:
        super().append(item)
        if len(self) > self.limit:
            del self[: len(self) - self.limit]


class ClientError(IlahrsError):
    """A flow did not complete: the device did not answer as the protocol says."""


def _pyserial() -> Any:
    try:
        return importlib.import_module("serial")
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("ilahrs.serial needs pyserial: pip install 'pyserial>=3.5'") from exc


def _as_block(table: str | None, block: Payload | Mapping[str, object]) -> Payload:
    """A parameter block from a payload object or raw field values of `table`."""
    if not isinstance(block, Mapping):
        return block
    if table is None:
        raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, "the command takes no parameter block")
    return PAYLOADS[table].from_raw(block)


_C = TypeVar("_C", bound="AhrsClient")


class AhrsClient:
    """One AHRS on one serial port, driven through a Host session."""

    def __init__(
        self,
        port: str,
        *,
        timeout: float = 1.0,
        firmware: str | None = None,
        retries: int = 3,
        quiet: float = 0.25,
        clock: Callable[[], float] = time.monotonic,
        baud: int | None = None,
        history: int = DEFAULT_HISTORY,
        strict: bool = False,
        tap: Callable[[bytes, bool], None] | None = None,
    ) -> None:
        self.host = Host(firmware=firmware, reply_timeout=timeout, strict=strict)
        self.retries = retries
        self.quiet = quiet
        keep = require_int(history, "history", 0, 2**31)
        self.events: History[HostEvent] = History(keep)
        """The last `history` events the host reported, in order, each with its receive time `at`."""
        self.errors: History[ProtocolError] = History(keep)
        """The last `history` protocol errors outside the quiet period after a Stop."""
        self.received: History[bytes] = History(keep)
        """The last `history` valid messages received, as received."""
        self.tap = tap
        """Called with every chunk as it crosses the line, and whether it went out (True) or came in:
        one call per write and one per read, for a capture of the session."""
        self._discarded = 0
        self._queue: deque[HostEvent] = deque(maxlen=_QUEUE_LIMIT)
        self._clock = clock
        self._last = clock()
        self._draining = False
        line = dict(LINE)
        if baud is not None:
            line["baudrate"] = require_int(baud, "baud", 1, 10_000_000)
        self.baud = int(str(line["baudrate"]))
        """The line's baud rate (default: the spec's)."""
        if os.name == "posix" and "://" not in port:
            line["exclusive"] = True  # flock: a second process is refused the port, not given half its bytes
        self._port = _pyserial().serial_for_url(port, timeout=_POLL, write_timeout=5.0, **line)

    # --- Lifetime ----------------------------------------------------------------------------

    def close(self) -> None:
        self._port.close()

    def __enter__(self: _C) -> _C:
        return self

    def __exit__(
        self, kind: type[BaseException] | None, value: BaseException | None, traceback: TracebackType | None
    ) -> None:
        self.close()

    @property
    def discarded(self) -> int:
        """Bytes received that belonged to no valid message."""
        return self._discarded

    # --- The line ----------------------------------------------------------------------------

    def poll(self, seconds: float = _POLL) -> list[HostEvent]:
        """Read for up to `seconds` (at least one read); return the new events."""
        end = self._clock() + require_seconds(seconds)
        new: list[HostEvent] = []
        while True:
            new += self._read(wait=True)
            if self._clock() >= end:
                return new

    def _read(self, *, wait: bool) -> list[HostEvent]:
        """One read (see `_read_line`) through the host; the new events, stamped and recorded."""
        quiet, data, within = self._read_line(wait=wait)
        events = self.host.advance(quiet) + self.host.receive(data, within=within)
        now = self._last
        stamped = [dataclasses.replace(event, at=now) for event in events]
        for event in stamped:
            self._record(event)
        return stamped

    def _read_line(self, *, wait: bool) -> tuple[float, bytes, float]:
        """One read of the line: `(quiet, data, within)`. When nothing had come since the last
        read, the line was quiet until now: `quiet` seconds, which can end a message held from
        before (E41), never the bytes that come after it; then (`wait`) the first bytes within one
        poll interval, with the rest that came with them. `data` came at some moment of the
        `within` seconds after that (answers among them count before a deadline in that time,
        and the idle rule counts from its end: `Host.receive(data, within=...)`)."""
        quiet = 0.0
        data = b""
        if self._port.in_waiting:
            data = self._port.read(self._port.in_waiting)
        else:
            start = self._clock()
            quiet = max(0.0, start - self._last)
            self._last = max(self._last, start)
            if wait:
                data = self._port.read(1)
                if data and self._port.in_waiting:
                    data += self._port.read(self._port.in_waiting)
        now = self._clock()
        within = max(0.0, now - self._last)
        self._last = max(self._last, now)
        if data and self.tap is not None:
            self.tap(data, False)
        return quiet, data, within

    def _record(self, event: HostEvent) -> None:
        self.events.append(event)
        if isinstance(event, Discarded):
            self._discarded += event.count
        raw = getattr(event, "raw", None)
        if raw:
            self.received.append(raw)
        if isinstance(event, ProtocolError) and not self._draining:
            self.errors.append(event)
        if not self._draining and not isinstance(event, Discarded):
            self._queue.append(event)

    def _write(self, data: bytes) -> None:
        self._port.write(data)
        self._port.flush()
        if self.tap is not None:
            self.tap(data, True)

    # --- Requests ----------------------------------------------------------------------------

    def stop(self) -> None:
        """Send Stop (0xFE: ExitClb in calibration), wait until the line is quiet, and take the
        device to be idle (6.3.5: send Stop before any other command)."""
        self._draining = True
        try:
            self._write(build_command(STOP))
            deadline = self._clock() + max(2.0, 4 * self.quiet)
            quiet_since = self._clock()
            while self._clock() < deadline:
                if self.poll(_POLL):
                    quiet_since = self._clock()
                elif self._clock() - quiet_since >= self.quiet:
                    break
        finally:
            self._draining = False
        self._queue.clear()
        self.host.resync(INITIAL)

    def request(self, command: str, block: Payload | Mapping[str, object] | None = None) -> list[HostEvent]:
        """Send `command` (and its parameter block: a payload object or raw field values) and
        wait for every answer the table lists (acknowledgements included); return them. Retried
        after a Stop when the command is one that starts from idle. Nothing is sent for an unknown
        command or a block with a field its table does not have."""
        result: list[HostEvent] = self._retry(command, lambda: self._request(command, block))
        return result

    def send(self, command: str, block: Payload | Mapping[str, object] | None = None) -> None:
        """Send `command` (and its parameter block) without waiting: its answers come as events from
        `poll()` (an answer that does not come, as a ProtocolError). Refused (IlahrsError, nothing
        sent) while answers to the last command are owed or when the device ignores the command in
        its state (Host.send). For a steady request rate, as `ilahrs monitor` polls GET_DATA."""
        self._write(self.host.send(command, block))

    def _request(self, command: str, block: Payload | Mapping[str, object] | None) -> list[HostEvent]:
        info = COMMANDS.get(command) if isinstance(command, str) else None
        if info is None:
            raise COMMAND_SET.unknown(command)
        if block is not None:
            block = COMMAND_SET.parameter_block(command, block)
        self._read(wait=False)  # what came before the command, and the host's clock brought up to now
        self._queue.clear()
        self._write(self.host.send(command, block))
        answers: list[HostEvent] = []
        sources = {command, *(name for name in COMMANDS if COMMANDS[name].code == info.code)}
        if block is not None:
            sources.add(block.NAME)
        while self.host.owed:
            self.poll(_POLL)
            answers += self._take(sources)
        answers += self._take(sources)
        failures = [e for e in answers if isinstance(e, ProtocolError)]
        if failures:
            raise ClientError(failures[0].kind, None, None, f"{command}: {failures[0].detail}")
        return answers

    def _take(self, sources: set[str]) -> list[HostEvent]:
        """Remove and return the queued answers to the command (or its block)."""
        taken: list[HostEvent] = []
        for event in list(self._queue):
            source = event.message if isinstance(event, Acknowledged) else getattr(event, "source", None)
            if source in sources or (isinstance(event, ProtocolError) and event.problem != "unexpected"):
                self._queue.remove(event)
                taken.append(event)
        return taken

    def _retry(self, command: str, attempt: Callable[[], Any]) -> Any:
        """Run `attempt`; after a failure, Stop and try again if `command` starts from idle."""
        retry = lookup(INITIAL, command) is not None
        for remaining in range(self.retries, -1, -1):
            try:
                return attempt()
            except ClientError:
                if not retry or remaining == 0:
                    raise
                self.stop()
        raise AssertionError("unreachable")

    def request_any_state(
        self, command: str, block: Payload | Mapping[str, object] | None = None, *, output: str | None = None
    ) -> Reply:
        """Send `command` (and its parameter block) to a device whose state the client does not
        know, and wait until its answers show the state it was in (`ilahrs.session.anystate`): the
        decoded answers, or no answer after the reply timeout. Nothing is retried and no Stop
        is sent, so the device stays in its state. The client then follows the device from the
        state the answers show (unchanged when none fits). `output`: the output format the device
        uses, or the command that started it (default: the one this client started, if any)."""
        host = self.host
        output = output if output is not None else host.output_format
        request = AnyStateRequest(
            command, block, firmware=host.firmware, reply_timeout=host.reply_timeout, output=output
        )
        self._read(wait=False)  # what came before the command, and the host's clock brought up to now
        self._queue.clear()
        self._write(request.data)
        while not request.done:
            quiet, data, within = self._read_line(wait=True)
            request.advance(quiet)
            request.receive(data, within=within)
        reply = request.reply()
        answers = tuple(dataclasses.replace(event, at=self._last) for event in reply.answers)
        reply = dataclasses.replace(reply, answers=answers)
        for event in answers:
            self.events.append(event)
            raw = getattr(event, "raw", None)
            if raw:
                self.received.append(raw)
        if reply.host is not None:
            self.host = reply.host
        return reply

    def wait_for(self, predicate: Callable[[HostEvent], bool], timeout: float) -> HostEvent:
        """The first queued or new event that satisfies `predicate`; ClientError after `timeout`
        seconds (TIMEOUT; `timeout` may be infinite) or a protocol error about a missing answer."""
        end = self._clock() + require_seconds(timeout, "timeout", infinite=True)
        while True:
            while self._queue:
                event = self._queue.popleft()
                if predicate(event):
                    return event
                if isinstance(event, ProtocolError) and event.problem == "missing":
                    raise ClientError(event.kind, None, None, event.detail)
            if self._clock() >= end:
                raise ClientError(ErrorKind.TIMEOUT, None, None, f"nothing came within {timeout:.3g} s")
            self.poll(_POLL)

    def _block(self, answers: list[HostEvent]) -> Payload:
        for event in answers:
            if isinstance(event, DataBlock):
                return event.payload
        raise ClientError(ErrorKind.UNEXPECTED_MESSAGE, None, None, "no data block in the answer")

    # --- Flows -------------------------------------------------------------------------------

    def read_parameters(self) -> Payload:
        """READ_PARAMETERS: the parameter block (Table 6.10 form)."""
        return self._block(self.request(READ_PARAMETERS))

    def load_parameters(self, block: Payload | Mapping[str, object]) -> None:
        """LOAD_PARAMETERS and the block (Table 6.9, a payload object or raw values; values
        the load table does not have, such as a read block's device id, are left out)."""
        if isinstance(block, Mapping):
            table = PAYLOADS[COMMANDS[LOAD_PARAMETERS].parameter_block or ""]
            names = {f.name for f in table.FIELDS if f.type != "reserved"}
            known = names | {f.name for f in ParameterBlock.FIELDS}
            for key in block:
                if key not in known:
                    detail = f"{table.NAME} has no field {brief(key)}{suggest(key, known)}; nothing was sent"
                    raise IlahrsError(ErrorKind.MALFORMED, None, key if isinstance(key, str) else None, detail)
            block = table.from_raw({k: v for k, v in block.items() if k in names})
        self.request(LOAD_PARAMETERS, block)

    def firmware_version(self) -> str:
        """FIRMWARE: the firmware version text."""
        block = self._block(self.request(FIRMWARE))
        return str(next(iter(block.raw().values())))

    def built_in_test(self) -> Payload:
        """BUILT_IN_TEST: temperature and Unit Status Word."""
        return self._block(self.request(BUILT_IN_TEST))

    def start(self, command: str) -> Payload:
        """Start output (a command that starts continuous or on-request mode): wait for the
        acknowledgement and the initial alignment block, and return the block."""
        info = COMMANDS.get(command) if isinstance(command, str) else None
        if info is None:
            raise COMMAND_SET.unknown(command)
        if info.starts_mode is None:
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, f"{command} starts no output")

        def attempt() -> Payload:
            self._request(command, None)
            event = self.wait_for(
                lambda e: isinstance(e, DataBlock) and e.source == TIMER_EVENTS["alignment"],
                self.host.setting("alignment") + 2 * self.host.reply_timeout,
            )
            assert isinstance(event, DataBlock)
            return event.payload

        result: Payload = self._retry(command, attempt)
        return result

    def frames(self, count: int, timeout: float | None = None) -> list[Payload | PahrSentence]:
        """The next `count` output blocks (payload objects or $PAHR sentences); `output()`
        iterates without a count."""
        require_int(count, "count", 0, 2**31)
        if timeout is None:
            timeout = 2 * count / self.host.setting("output") + 2 * self.host.reply_timeout
        end = self._clock() + require_seconds(timeout, "timeout", infinite=True)
        blocks: list[Payload | PahrSentence] = []
        while len(blocks) < count:
            remaining = end - self._clock()
            event = self.wait_for(lambda e: isinstance(e, Output) and not e.late, max(0.0, remaining))
            assert isinstance(event, Output)
            blocks.append(event.data)
        return blocks

    def output(self, timeout: float | None = None) -> Iterator[Payload | PahrSentence]:
        """Output blocks (payload objects or $PAHR sentences) as they arrive, for as long as the
        caller iterates: `for block in client.output(): ...` after `start()`. ClientError
        (TIMEOUT) when none comes within `timeout` seconds (default: two output periods and
        twice the reply timeout)."""
        while True:
            wait = timeout
            if wait is None:
                wait = 2 / self.host.setting("output") + 2 * self.host.reply_timeout
            event = self.wait_for(lambda e: isinstance(e, Output) and not e.late, wait)
            assert isinstance(event, Output)
            yield event.data

    def get_data(self) -> Payload | PahrSentence:
        """GET_DATA: one output block in on-request mode."""
        for event in self.request(GET_DATA):
            if isinstance(event, Output):
                return event.data
        raise ClientError(ErrorKind.UNEXPECTED_MESSAGE, None, None, "no output block in the answer")

    def low_power(self, on: bool) -> Payload | PahrSentence | None:
        """LOW_POWER_ON or LOW_POWER_OFF. Going to sleep from continuous output returns the last
        block, which carries the sleep mode bits (E35)."""
        command = LOW_POWER_ON if on else LOW_POWER_OFF
        for event in self.request(command):
            if isinstance(event, Output):
                return event.data
        return None

    def get_calibration_results(self) -> Payload:
        """CALIBRATION_RESULTS: the results of the last calibration (Table 6.17)."""
        return self._block(self.request(CALIBRATION_RESULTS))

    def clear_calibration(self) -> None:
        """CLEAR_CALIBRATION: clear the hard/soft-iron calibration."""
        self.request(CLEAR_CALIBRATION)

    def calibrate_2d2t(
        self,
        parameters: Payload | Mapping[str, object],
        runs: int = 2,
        *,
        accept: bool = True,
        stop_after: Mapping[int, float] | None = None,
    ) -> tuple[list[Payload], Payload]:
        """A 2D-2T calibration (6.4.5 - 6.4.7): START_RUNS with `parameters` (Table 6.13), `runs`
        runs (START_RUN; run number -> seconds of accumulation after which STOP_RUN ends it early,
        in `stop_after`), FINISH, then ACCEPT (or the STOP code, which leaves calibration, if not `accept`). Returns the
        run results (Table 6.15) and the calibration result (Table 6.14)."""
        start = START_RUNS
        run_table = PAYLOADS[COMMANDS[START_RUN].parameter_block or ""]
        block = _as_block(COMMANDS[start].parameter_block, parameters)
        early = stop_after or {}

        def attempt() -> tuple[list[Payload], Payload]:
            self._request(start, block)
            results: list[Payload] = []
            for run in range(1, runs + 1):
                self._request(START_RUN, run_table())
                self.wait_for(
                    lambda e: isinstance(e, DataBlock) and e.source == TIMER_EVENTS["alignment"],
                    self.host.setting("alignment") + 2 * self.host.reply_timeout,
                )
                if run in early:
                    self.poll(early[run])
                    results.append(self._block(self._request(STOP_RUN, None)))
                else:
                    event = self.wait_for(
                        lambda e: isinstance(e, DataBlock) and e.source == TIMER_EVENTS["accumulation"],
                        self.host.setting("accumulation") + 2 * self.host.reply_timeout,
                    )
                    assert isinstance(event, DataBlock)
                    results.append(event.payload)
            final = self._block(self._request(FINISH, None))
            leave = command_event(COMMANDS[STOP].code, self.host.state) or STOP
            self._request(ACCEPT if accept else leave, None)
            return results, final

        result: tuple[list[Payload], Payload] = self._retry(start, attempt)
        return result

    def calibrate(
        self,
        command: str,
        parameters: Payload | Mapping[str, object],
        *,
        accept: bool = True,
        stop_after: float | None = None,
    ) -> Payload:
        """A single-run calibration (6.4.1 2D, 6.4.8 3D): `command` with `parameters` (Table 6.13,
        a payload object or raw values), the initial alignment, the accumulation (ended early by
        STOP_RUN after `stop_after` seconds, if given), then ACCEPT (or the STOP code, which leaves
        calibration, if not `accept`). Waits for every answer; returns the result (Table 6.14)."""
        info = COMMANDS.get(command) if isinstance(command, str) else None
        if info is None:
            raise COMMAND_SET.unknown(command)
        if command not in CALIBRATION_TYPES or command == START_RUNS:
            single = [name for name in CALIBRATION_TYPES if name != START_RUNS]
            detail = f"{command} is not a single-run calibration ({', '.join(single)})"
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, detail)
        block = COMMAND_SET.parameter_block(command, parameters)
        early = None if stop_after is None else require_seconds(stop_after, "stop_after")

        def attempt() -> Payload:
            self._request(command, block)
            self.wait_for(
                lambda e: isinstance(e, DataBlock) and e.source == TIMER_EVENTS["alignment"],
                self.host.setting("alignment") + 2 * self.host.reply_timeout,
            )
            if early is not None:
                self.poll(early)
                final = self._block(self._request(STOP_RUN, None))
            else:
                event = self.wait_for(
                    lambda e: isinstance(e, DataBlock) and e.source == TIMER_EVENTS["accumulation"],
                    self.host.setting("accumulation") + 2 * self.host.reply_timeout,
                )
                assert isinstance(event, DataBlock)
                final = event.payload
            leave = command_event(COMMANDS[STOP].code, self.host.state) or STOP
            self._request(ACCEPT if accept else leave, None)
            return final

        result: Payload = self._retry(command, attempt)
        return result

    def calibrate_2d(self, parameters: Payload | Mapping[str, object], *, accept: bool = True) -> Payload:
        """A 2D calibration (6.4.1): `calibrate` with the command whose result reports type 2D."""
        return self.calibrate(_calibration_command(CalibrationType.TWO_D), parameters, accept=accept)

    def calibrate_3d(self, parameters: Payload | Mapping[str, object], *, accept: bool = True) -> Payload:
        """A 3D calibration (6.4.8): `calibrate` with the command whose result reports type 3D."""
        return self.calibrate(_calibration_command(CalibrationType.THREE_D), parameters, accept=accept)


def _calibration_command(kind: int) -> str:
    return next(name for name, value in CALIBRATION_TYPES.items() if value == kind)
