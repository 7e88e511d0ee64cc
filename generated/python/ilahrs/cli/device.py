# Copied from generator/targets/python/runtime/cli/device.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The subcommands that talk to an AHRS: `record`, `send`, `params` and `calibrate`, on top of the
serial client (`ilahrs.serial`). Each opens the port, leaves the device stopped when it ends (also
after Ctrl-C) and turns every failure into one line (CliError)."""

from __future__ import annotations

import math
import os
import shlex
import signal
import sys
import tempfile
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager, suppress
from typing import TYPE_CHECKING, Any, BinaryIO, Final, TextIO

from ..codec import Payload, date_from_text, field_text
from ..commands import COMMANDS
from ..encodings import Variant, calibration_accuracy_deg, calibration_succeeded
from ..errors import IlahrsError
from ..nmea import PahrSentence
from ..payloads import PAYLOADS
from ..pcapng import Direction, PcapngWriter
from ..roles import ACCEPT, FINISH, LOAD_PARAMETERS, START_RUN, START_RUNS, STOP
from ..session.anystate import states_hearing
from ..session.host import Acknowledged, DataBlock, HostEvent, Output, ProtocolError
from ..spec import SERIAL_LINE
from ..statemachine import CALIBRATION_TYPES, INITIAL, TIMER_EVENTS, TIMER_FIELDS, command_event
from ..statemachine import lookup as transition
from .capture import Chunk
from .capture_decoder import CaptureDecoder
from .common import SENTENCE_KIND, CliError, fields_of, lookup, open_client, parse_assignments

if TYPE_CHECKING:
    from ..edge.serial import AhrsClient

__all__ = ["CALIBRATIONS", "calibrate", "params", "record", "send"]

CALIBRATIONS: Final = {name.removeprefix("Start").removesuffix("Clb").lower(): name for name in CALIBRATION_TYPES}
"""The calibration words of `ilahrs calibrate` (2d, 2d2t, 3d) -> the command that starts each."""
_SLICE: Final = 0.25


def _now_us() -> int:
    return time.time_ns() // 1000


def _failure(port: str, what: str, exc: IlahrsError) -> CliError:
    detail = (exc.detail or str(exc)).removeprefix(f"{what}: ")  # the client's errors name the command
    return CliError(f"{port}: {what}: {detail}")


@contextmanager
def _session(port: str, baud: int, *, stop: bool = True) -> Iterator[AhrsClient]:
    """A client on `port` that sends Stop when the block ends, however it ends (with `stop`
    False: only when it ends by Ctrl-C)."""
    client = open_client(port, baud)
    interrupted = False
    try:
        yield client
    except KeyboardInterrupt:
        interrupted = True
        raise
    finally:
        try:
            if stop or interrupted:
                client.stop()
        except (OSError, IlahrsError):
            pass
        client.close()


def _probe(client: AhrsClient, port: str) -> None:
    """Stop, then check that the device answers (the firmware version)."""
    try:
        client.stop()
        client.firmware_version()
    except IlahrsError as exc:
        detail = f"{exc.detail or exc}; check the port and --baud"
        raise CliError(f"{port}: no answer from the AHRS at {client.baud} baud ({detail})") from exc
    except OSError as exc:
        raise CliError(f"{port}: {exc}") from exc


def _describe(kind: str, data: Payload | PahrSentence | None, variant: Variant) -> str:
    if data is None:
        return kind
    fields = fields_of(data, variant)
    if not isinstance(data, PahrSentence):  # a float32 as its shortest text, a date as YYYY-MM-DD
        raw = data.raw()
        for info in data.FIELDS:
            if info.name in fields and info.type == "f32" and info.multiplier == 1 and info.divisor == 1:
                fields[info.name] = field_text(info, raw[info.name])
    return f"{kind} " + " ".join(f"{k}={v}" for k, v in fields.items())


def _event_line(event: HostEvent, variant: Variant) -> str:
    if isinstance(event, Acknowledged):
        return f"acknowledged {event.message} (checksum {event.checksum:#06x})"
    if isinstance(event, DataBlock):
        return _describe(event.payload.NAME, event.payload, variant)
    if isinstance(event, Output):
        kind = SENTENCE_KIND if isinstance(event.data, PahrSentence) else event.data.NAME
        return _describe(kind, event.data, variant)
    return str(event)


# --- record ----------------------------------------------------------------------------------------


class _Terminated(BaseException):
    """SIGTERM during a recording: it ends as Ctrl-C ends it (Stop sent, the capture kept)."""


class _Signals:
    """Ctrl-C (SIGINT) and SIGTERM during a recording. The first one ends it: while `live`, it
    raises (KeyboardInterrupt, _Terminated), never in the middle of a chunk being written to the
    capture (then right after it); later ones, and any after `live` is cleared (the final Stop is
    draining), are only noted, so the device is always left stopped and the capture whole."""

    def __init__(self) -> None:
        self.caught: int | None = None
        self.live = True
        self.busy = False
        self._raised = False
        self._previous: dict[int, Any] = {}

    def __enter__(self) -> _Signals:
        try:
            for number in (signal.SIGINT, signal.SIGTERM):
                self._previous[number] = signal.signal(number, self._handler)
        except ValueError:  # not the main thread: the signals stay as they are
            pass
        return self

    def __exit__(self, *exc: object) -> None:
        for number, previous in self._previous.items():
            signal.signal(number, previous)

    def _handler(self, number: int, frame: object) -> None:
        if self.caught is None:
            self.caught = number
        if not self.busy:
            self.check()

    def check(self) -> None:
        """Raise for the first signal caught, once, while live."""
        if self.caught is not None and self.live and not self._raised:
            self._raised = True
            raise _Terminated if self.caught == signal.SIGTERM else KeyboardInterrupt


class _Capture:
    """A pcapng capture written to a temporary file beside `path`: `keep()` renames it onto `path`,
    `discard()` removes it, so a file already at `path` is untouched until the recording has data
    to replace it with. Every chunk is also decoded as `ilahrs decode` decodes the file
    (CaptureDecoder), so the summary counts what the capture holds."""

    def __init__(self, path: str, port: str, baud: int, signals: _Signals) -> None:
        self.path = path
        self.decoder = CaptureDecoder(context=True)
        self._signals = signals
        if os.path.isdir(path):
            raise CliError(f"{path}: is a directory")
        folder = os.path.dirname(os.path.abspath(path))
        try:
            handle, self._temporary = tempfile.mkstemp(prefix=f".{os.path.basename(path)}.", suffix=".part", dir=folder)
        except OSError as exc:
            raise CliError(f"{path}: cannot write there: {exc.strerror or exc}") from exc
        self._stream: BinaryIO = os.fdopen(handle, "wb")
        self.writer = PcapngWriter(
            self._stream,
            port=port,
            baud=baud,
            data_bits=int(SERIAL_LINE["data_bits"]),
            parity=str(SERIAL_LINE["parity"]),
            stop_bits=int(SERIAL_LINE["stop_bits"]),
        )

    def write(self, data: bytes, direction: Direction) -> None:
        """One chunk, stamped now, to the file and the decoder (a signal waits until both have it)."""
        stamp = time.time_ns() // 1000
        self._signals.busy = True
        try:
            self.writer.write(data, stamp, direction)
            self.decoder.feed(Chunk(stamp / 1_000_000, direction, bytes(data)))
        finally:
            self._signals.busy = False
        self._signals.check()

    def tap(self, data: bytes, outbound: bool) -> None:
        """AhrsClient's tap: each chunk as it crossed the line."""
        self.write(data, Direction.OUTBOUND if outbound else Direction.INBOUND)

    def keep(self) -> tuple[int, int, int]:
        """Rename the capture onto `path` (with the mode a new file gets); its messages, discarded
        bytes and decode errors, as `ilahrs decode` counts them."""
        self.decoder.finish()
        self._stream.close()
        mask = os.umask(0)
        os.umask(mask)
        try:
            os.chmod(self._temporary, 0o666 & ~mask)
            os.replace(self._temporary, self.path)
        except OSError as exc:
            raise CliError(f"{self.path}: {exc.strerror or exc}; the capture is in {self._temporary}") from exc
        return sum(self.decoder.counts.values()), self.decoder.discarded, len(self.decoder.errors)

    def discard(self) -> None:
        self._stream.close()
        with suppress(OSError):
            os.remove(self._temporary)


def _planned(text: str) -> tuple[str, dict[str, object]]:
    """A --send argument ("COMMAND key=value ...") -> the command and its raw field values,
    checked before the port is opened."""
    try:
        words = shlex.split(text)
    except ValueError as exc:
        raise CliError(f"--send {text!r}: {exc}") from exc
    if not words:
        raise CliError("--send needs a command name")
    name = lookup("command", words[0], COMMANDS)
    table_name = COMMANDS[name].parameter_block
    if table_name is None:
        if words[1:]:
            raise CliError(f"{name} takes no parameter block, so no key=value")
        return name, {}
    table = PAYLOADS[table_name]
    values = parse_assignments(table, words[1:])
    if name != LOAD_PARAMETERS:  # the parameters are checked once merged with the device's
        try:
            table.from_raw(values)
        except IlahrsError as exc:
            raise CliError(f"{exc.field or table_name}: {exc.detail or exc}") from exc
    return name, values


def _converse(client: AhrsClient, port: str, plan: Sequence[tuple[str, dict[str, object]]], start: str | None) -> None:
    """Send each planned command in order and wait for its answers (a command that starts an
    output: also its initial alignment); then start `start`."""
    for name, values in plan:
        try:
            if name == LOAD_PARAMETERS:  # fields not given keep the device's values
                client.load_parameters(client.read_parameters().raw() | values)
            elif COMMANDS[name].starts_mode is not None:
                client.start(name)
            else:
                table_name = COMMANDS[name].parameter_block
                client.request(name, None if table_name is None else PAYLOADS[table_name].from_raw(values))
        except IlahrsError as exc:
            raise _failure(port, name, exc) from exc
    if start is not None:
        try:
            client.start(start)
        except IlahrsError as exc:
            raise _failure(port, start, exc) from exc


def _listen(client: AhrsClient, duration: float | None, count: int | None) -> None:
    """Record until `duration` seconds have passed or `count` output messages have come."""
    end = None if duration is None else time.monotonic() + duration
    outputs = 0
    while (end is None or time.monotonic() < end) and (count is None or outputs < count):
        outputs += sum(1 for e in client.poll(0.05) if isinstance(e, Output) and not e.late)


def _plan(
    start: str | None, duration: float | None, count: int | None, sends: Sequence[str]
) -> tuple[str | None, list[tuple[str, dict[str, object]]]]:
    """The output command and the --send commands of a recording, every argument checked."""
    command = None
    if start is not None:
        starting = [n for n, info in COMMANDS.items() if info.starts_output is not None]
        command = lookup("output command", start, starting)
    if duration is not None and not (math.isfinite(duration) and duration > 0):
        raise CliError(f"--duration {duration}: not a positive number of seconds")
    if count is not None and count <= 0:
        raise CliError(f"--count {count}: not a positive number of messages")
    return command, [_planned(text) for text in sends]


def _recording(
    capture: _Capture, signals: _Signals, port: str, baud: int, talk: Callable[[AhrsClient], None]
) -> CliError | None:
    """Open the port, probe the device, then `talk`; Stop and close, however it ends. Returns the
    error that ended a recording that has data (a lost device, a failed command); raises it when
    the device never answered (the capture then discarded)."""
    answered = False
    try:
        try:
            with _session(port, baud) as client:
                client.tap = capture.tap  # every chunk read or written goes to the capture
                try:
                    _probe(client, port)
                    answered = True
                    talk(client)
                finally:
                    signals.live = False  # the final Stop drains whatever comes, whatever comes next
        except (KeyboardInterrupt, _Terminated) as exc:
            signals.caught = signals.caught or (signal.SIGTERM if isinstance(exc, _Terminated) else signal.SIGINT)
            if not answered:
                raise
        except CliError as exc:
            if not answered:
                raise
            return exc
        except OSError as exc:
            if not answered:
                raise CliError(f"{port}: {exc.strerror or exc}") from exc
            return CliError(f"{port}: the device was lost ({exc.strerror or exc})")
    except BaseException:
        if answered:
            capture.keep()
        else:
            capture.discard()
        if signals.caught == signal.SIGTERM:
            raise CliError("terminated before the device answered") from None
        raise
    return None


def record(
    port: str,
    baud: int,
    output: str,
    *,
    start: str | None,
    duration: float | None,
    count: int | None,
    sends: Sequence[str] = (),
    out: TextIO = sys.stderr,
) -> int:
    """Stop, check the device answers, send each of `sends` ("COMMAND key=value ...") and wait for
    its answers, optionally start an output, and record both directions until the duration
    (counted from then), the count, Ctrl-C, SIGTERM or the loss of the device; Stop on exit; print
    a one-line summary (what `ilahrs decode` finds in the capture) to `out`.

    The capture is written beside `output` and renamed onto it when the recording ends, kept
    whenever the device has answered; a recording that fails before (a wrong port, a silent
    device) leaves no file and `output` as it was. Returns 0, or 2 after SIGTERM; the loss of the
    device, or a command that fails, is a CliError after the summary."""
    command, plan = _plan(start, duration, count, sends)

    def talk(client: AhrsClient) -> None:
        _converse(client, port, plan, command)
        _listen(client, duration, count)

    with _Signals() as signals:
        capture = _Capture(output, port, baud, signals)
        failure = _recording(capture, signals, port, baud, talk)
        messages, discarded, errors = capture.keep()
    endings = {int(signal.SIGINT): " (interrupted)", int(signal.SIGTERM): " (terminated)"}
    ending = endings.get(signals.caught or 0, "")
    print(
        f"ilahrs record: {messages} messages, {discarded} bytes discarded, {errors} errors -> {output}{ending}",
        file=out,
    )
    if failure is not None:
        raise failure
    return 2 if signals.caught == signal.SIGTERM else 0


# --- send --------------------------------------------------------------------------------------------


def _block(command: str, assignments: Sequence[str], *, defaults: bool = True) -> Payload | None:
    """The parameter block `command` takes, from key=value words (the other fields take the
    table's defaults). The block of LOAD_PARAMETERS replaces every stored parameter: without
    `defaults`, one that leaves fields to their defaults is refused."""
    table_name = COMMANDS[command].parameter_block
    if table_name is None:
        if assignments:
            raise CliError(f"{command} takes no parameter block, so no key=value")
        return None
    table = PAYLOADS[table_name]
    values = parse_assignments(table, assignments)
    if command == LOAD_PARAMETERS and not defaults:
        left = [f.name for f in table.FIELDS if f.type != "reserved" and f.name not in values]
        if left:
            changed = " ".join(assignments) or "key=value"
            raise CliError(
                f"{command} replaces every parameter: {', '.join(left)} would be sent as defaults; "
                f"to change only some, run `ilahrs params PORT set {changed}` (or add --defaults)"
            )
    try:
        return table.from_raw(values)
    except IlahrsError as exc:
        raise CliError(f"{exc.field or table_name}: {exc.detail or exc}") from exc


def _answering(command: str) -> list[str]:
    """The states in which the device answers `command`."""
    code = COMMANDS[command].code
    return [s for s in states_hearing(command) if (t := transition(s, command_event(code, s) or command)) and t.send]


def send(
    port: str,
    baud: int,
    command: str,
    assignments: Sequence[str],
    *,
    variant: Variant,
    out: TextIO,
    defaults: bool = False,
    output: str | None = None,
    err: TextIO = sys.stderr,
) -> int:
    """Send one command (and its parameter block) to the device in whatever state it is, and print
    the decoded answers (AhrsClient.request_any_state). A command the device ignored is one line
    and status 2; a command heard in idle is then sent again after a Stop (as the client retries).
    `output`: the command that started the device's output (its blocks of every format have the
    same size; without it an output block whose format does not show prints raw, E7)."""
    name = lookup("command", command, COMMANDS)
    block = _block(name, assignments, defaults=defaults)
    with _session(port, baud, stop=False) as client:
        try:
            reply = client.request_any_state(name, block, output=output)
            answers = list(reply.answers)
            if reply.state is None and reply.received and INITIAL in states_hearing(name):
                print(f"ilahrs send: the device ignored {name} in its state; sent Stop and {name} again", file=err)
                client.stop()
                answers = [e for e in client.request(name, block) if not isinstance(e, ProtocolError)]
            elif reply.state is None:
                raise CliError(_ignored(port, name, reply.received))
        except IlahrsError as exc:
            raise _failure(port, name, exc) from exc
        except OSError as exc:
            raise CliError(f"{port}: {exc}") from exc
        if not answers:
            print(_silent(name, reply.silent), file=out)
        ambiguous = len(reply.formats) > 1
        for event in answers:
            line = _event_line(event, variant)
            if ambiguous and isinstance(event, Output):
                line = f"output raw={event.raw.hex()}"
            print(line, file=out)
        if ambiguous:
            starters = ", ".join(n for n, i in COMMANDS.items() if i.starts_output in reply.formats)
            formats = ", ".join(reply.formats)
            print(f"ilahrs send: the output block fits {formats}: --output-format ({starters}) decodes it", file=err)
    return 0


def _ignored(port: str, command: str, received: int) -> str:
    states = ", ".join(states_hearing(command))
    line = f"{port}: no answer: the device ignores {command} in its state (it acts on it in {states})"
    if not received:
        line += "; or nothing is there: check PORT and --baud"
    return line


def _silent(command: str, states: Sequence[str]) -> str:
    """The line of a command that owes no answer in the states that fit (a state that ignores it
    looks the same)."""
    tail = "; any other state ignores it" if not _answering(command) else ""
    return f"{command}: sent; no answer came (none is due in {', '.join(states)}{tail})"


# --- params ----------------------------------------------------------------------------------------


def params(port: str, baud: int, assignments: Sequence[str], *, variant: Variant, out: TextIO) -> int:
    """Print the parameters; with assignments, read-modify-write them (6.3.6) and read back. A
    value counts as taken when the device reads back what the table encodes (a float32: 3.3 is
    3.299999952316284 on the wire); floats print as the shortest text of their float32, dates as
    YYYY-MM-DD."""
    load = PAYLOADS[COMMANDS[LOAD_PARAMETERS].parameter_block or ""]
    changes = parse_assignments(load, assignments) if assignments else {}
    wanted: dict[str, object] = {}
    with _session(port, baud) as client:
        _probe(client, port)
        try:
            current = client.read_parameters()
            if changes:
                names = {f.name for f in load.FIELDS if f.type != "reserved"}
                try:
                    block = load.from_raw({k: v for k, v in (current.raw() | changes).items() if k in names})
                except IlahrsError as exc:
                    raise CliError(f"{exc.field or load.NAME}: {exc.detail or exc}") from exc
                wanted = dict(load.parse(block.build()).raw())  # the values as the table encodes them
                client.load_parameters(block)
                current = client.read_parameters()
        except IlahrsError as exc:
            raise _failure(port, "parameters", exc) from exc
    now = current.raw()
    infos = {f.name: f for f in current.FIELDS}
    for key, value in fields_of(current, variant).items():
        text = field_text(infos[key], now[key]) if infos[key].type == "f32" else value
        print(f"{key} = {text}", file=out)
    kept = [k for k in changes if now.get(k) != wanted[k]]
    if kept:
        asked = ", ".join(f"{k}={field_text(infos[k], wanted[k])}" for k in kept)
        raise CliError(f"the device did not take {asked}")
    return 0


# --- calibrate ---------------------------------------------------------------------------------------

_STEPS: Final = {
    "alignment": "Keep the object still while the AHRS aligns",
    "2d": "Turn the object slowly through at least one full circle, keeping it level",
    "3d": "Turn the object slowly through as many orientations as you can",
    "2d2t": "Turn the object slowly in heading through at least one full circle, keeping the pitch and roll "
    "of this run's tilt",
    "2d2t_first": "Tilt the object to the first pitch angle of the calibration, usually the lowest pitch it "
    "works at (6.4.5)",
    "2d2t_next": "Tilt the object to the next pitch angle, clearly different from the pitch of the runs before "
    "(two runs at essentially different pitch angles must succeed, 6.4.5)",
    "ready": "Press Enter when the object is there: ",
}
DEFAULT_ACCUMULATION_S: Final = 60
"""The default accumulation time of `ilahrs calibrate`, s: time for a slow full turn."""


class _Wait:
    """Waits for a data block sent on a timer event, showing progress on `out`."""

    def __init__(self, client: AhrsClient, port: str, out: TextIO) -> None:
        self._client = client
        self._port = port
        self._out = out

    def __call__(self, timer: str, label: str) -> Payload:
        client = self._client
        seconds = client.host.setting(timer)
        source = TIMER_EVENTS[timer]
        begin = time.monotonic()
        end = begin + seconds + 4 * client.host.reply_timeout
        while True:
            slice_end = time.monotonic() + _SLICE
            try:
                event = client.wait_for(lambda e: isinstance(e, DataBlock) and e.source == source, _SLICE)
            except IlahrsError as exc:
                if time.monotonic() < slice_end - 0.01 or time.monotonic() > end:
                    self._out.write("\n")
                    raise _failure(self._port, label, exc) from exc
                if self._out.isatty():
                    elapsed = min(seconds, time.monotonic() - begin)
                    self._out.write(f"\r  {label}: {elapsed:4.0f} / {seconds:.0f} s")
                    self._out.flush()
                continue
            assert isinstance(event, DataBlock)
            self._out.write(f"\r  {label}: done{' ' * 16}\n" if self._out.isatty() else f"  {label}: done\n")
            return event.payload


def _show(title: str, block: Payload, variant: Variant, out: TextIO) -> None:
    print(f"{title} ({block.ICD}):", file=out)
    infos = {f.name: f for f in block.FIELDS}
    for key, value in fields_of(block, variant, raw=True).items():
        print(f"  {key} = {field_text(infos[key], value)}", file=out)
    success = getattr(block, "success", None)
    if isinstance(success, int):
        accuracy = calibration_accuracy_deg(success)
        verdict = "succeeded" if calibration_succeeded(success) else "failed"
        if calibration_succeeded(success) and accuracy is not None:
            verdict += f", predicted heading accuracy {accuracy:g} deg"
        print(f"  -> {verdict}", file=out)


def _decide(answer: bool | None, ask: Callable[[str], str], out: TextIO) -> bool:
    if answer is not None:
        return answer
    try:
        reply = ask("Accept this calibration? [y/N] ")
    except EOFError:
        print("", file=out)
        return False
    return reply.strip().lower() in ("y", "yes")


def _calibration_block(
    start: str, accumulation: int, place: Mapping[str, object], stored: Mapping[str, object]
) -> Payload:
    """The parameter block of `start`: the accumulation time, the position and date stored in the
    device (`stored`, a parameter block's raw values) under those given (`place`)."""
    table = PAYLOADS[COMMANDS[start].parameter_block or ""]
    names = {f.name for f in table.FIELDS if f.type != "reserved"}
    values = {k: v for k, v in stored.items() if k in names} | dict(place)
    values[TIMER_FIELDS["accumulation"][1]] = accumulation
    try:
        return table.from_raw(values)
    except IlahrsError as exc:
        raise CliError(f"{exc.field or table.NAME}: {exc.detail or exc}") from exc


def calibration_place(
    latitude: float | None, longitude: float | None, altitude: float | None, date: str | None
) -> dict[str, object]:
    """The raw values of the options of `ilahrs calibrate` that were given (date: YYYY-MM-DD)."""
    place: dict[str, object] = {"latitude": latitude, "longitude": longitude, "altitude": altitude}
    if date is not None:
        try:
            place["date"] = date_from_text(date)
        except IlahrsError as exc:
            raise CliError(f"--date {date}: {exc.detail or exc}") from exc
    return {k: v for k, v in place.items() if v is not None}


def calibrate(
    port: str,
    baud: int,
    kind: str,
    *,
    accumulation: int = DEFAULT_ACCUMULATION_S,
    runs: int,
    answer: bool | None,
    variant: Variant,
    out: TextIO,
    place: Mapping[str, object] | None = None,
    ask: Callable[[str], str] = input,
) -> int:
    """A guided calibration: what to do at each step, progress, each run's result, the final
    result, then AcceptClb or ExitClb. The calibration block carries the position and date stored
    in the device, or those in `place` (latitude, longitude, altitude, date: raw values). A
    failed calibration is never accepted: ExitClb, then CliError (status 2)."""
    start = CALIBRATIONS[lookup("calibration", kind, CALIBRATIONS)]
    table = PAYLOADS[COMMANDS[start].parameter_block or ""]
    given = dict(place or {})
    _calibration_block(start, accumulation, given, {})  # refuse bad values before opening the port
    word = next(w for w, c in CALIBRATIONS.items() if c == start)
    interactive = answer is None and sys.stdin.isatty()
    with _session(port, baud) as client:
        _probe(client, port)
        wait = _Wait(client, port, out)
        try:
            stored = client.read_parameters()  # the position and date, and the alignment time
            block = _calibration_block(start, accumulation, given, stored.raw())
            shown = " ".join(
                f"{f.name}={field_text(f, block.raw()[f.name])}" for f in table.FIELDS if f.type != "reserved"
            )
            print(f"{start}: {table.TITLE}: {shown}", file=out)
            client.request(start, block)
            results: list[Payload] = []
            if start == START_RUNS:
                run_table = PAYLOADS[COMMANDS[START_RUN].parameter_block or ""]
                for run in range(1, runs + 1):
                    tilt = _STEPS["2d2t_first" if run == 1 else "2d2t_next"]
                    print(f"Run {run} of {runs}. {tilt}.", file=out)
                    if interactive:
                        _ready(ask, out)
                    print(f"{_STEPS['alignment']}.", file=out)
                    client.request(START_RUN, run_table())
                    wait("alignment", "alignment")
                    print(f"{_STEPS[word]}.", file=out)
                    results.append(wait("accumulation", "accumulation"))
                    _show(f"Run {run} result", results[-1], variant, out)
                final = next(e.payload for e in client.request(FINISH) if isinstance(e, DataBlock))
            else:
                print(f"{_STEPS['alignment']}.", file=out)
                wait("alignment", "alignment")
                print(f"{_STEPS[word]}.", file=out)
                final = wait("accumulation", "accumulation")
            _show("Calibration result", final, variant, out)
            success = getattr(final, "success", None)
            failed = isinstance(success, int) and not calibration_succeeded(success)
            accept = not failed and _decide(answer, ask, out)
            leave = command_event(COMMANDS[STOP].code, client.host.state) or STOP
            client.request(ACCEPT if accept else leave)
            print("accepted: saved in the AHRS" if accept else "discarded: the AHRS keeps its calibration", file=out)
        except IlahrsError as exc:
            raise _failure(port, start, exc) from exc
    if failed:
        raise CliError(f"{port}: {start}: the calibration failed (calibration success {success})")
    return 0


def _ready(ask: Callable[[str], str], out: TextIO) -> None:
    try:
        ask(_STEPS["ready"])
    except EOFError:
        print("", file=out)
