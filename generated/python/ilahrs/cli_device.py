# Copied from generator/targets/python/runtime/cli_device.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""The subcommands that talk to an AHRS: `record`, `send`, `params` and `calibrate`, on top of the
serial client (`ilahrs.serial`). Each opens the port, leaves the device stopped when it ends (also
after Ctrl-C) and turns every failure into one line (CliError)."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, BinaryIO, Final, TextIO

from .cli_common import SENTENCE_KIND, CliError, fields_of, lookup, open_client, parse_assignments
from .codec import Payload
from .commands import COMMANDS
from .encodings import Variant, calibration_accuracy_deg, calibration_succeeded
from .errors import IlahrsError
from .host import Acknowledged, DataBlock, HostEvent, Output, ProtocolError
from .nmea import PahrSentence
from .payloads import PAYLOADS
from .pcapng import Direction, PcapngWriter
from .roles import ACCEPT, FINISH, LOAD_PARAMETERS, START_RUN, START_RUNS, STOP
from .spec import SERIAL_LINE
from .statemachine import CALIBRATION_TYPES, STATES, TIMER_EVENTS, command_event
from .statemachine import lookup as transition

if TYPE_CHECKING:
    from .serial import AhrsClient

__all__ = ["CALIBRATIONS", "calibrate", "params", "record", "send"]

CALIBRATIONS: Final = {name.removeprefix("Start").removesuffix("Clb").lower(): name for name in CALIBRATION_TYPES}
"""The calibration words of `ilahrs calibrate` (2d, 2d2t, 3d) -> the command that starts each."""
_SLICE: Final = 0.25


def _now_us() -> int:
    return time.time_ns() // 1000


class _Tap:
    """The client's port, with every chunk read or written also written to a pcapng file."""

    def __init__(self, port: Any, writer: PcapngWriter) -> None:
        self._port = port
        self._writer = writer

    def read(self, size: int = 1) -> bytes:
        data: bytes = self._port.read(size)
        if data:
            self._writer.write(data, _now_us(), Direction.INBOUND)
        return data

    def write(self, data: bytes) -> int | None:
        written: int | None = self._port.write(data)
        self._writer.write(data, _now_us(), Direction.OUTBOUND)
        return written

    def __getattr__(self, name: str) -> Any:
        return getattr(self._port, name)


def _failure(port: str, what: str, exc: IlahrsError) -> CliError:
    detail = exc.detail or str(exc)
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
        raise CliError(f"{port}: no answer from the AHRS ({exc.detail or exc})") from exc
    except OSError as exc:
        raise CliError(f"{port}: {exc}") from exc


def _describe(kind: str, data: Payload | PahrSentence | None, variant: Variant) -> str:
    if data is None:
        return kind
    fields = fields_of(data, variant)
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


def record(
    port: str,
    baud: int,
    output: str,
    *,
    start: str | None,
    duration: float | None,
    count: int | None,
    out: TextIO = sys.stderr,
) -> int:
    """Stop, optionally start an output, and record both directions until the duration, the count
    or Ctrl-C; Stop on exit; print a one-line summary."""
    command = None
    if start is not None:
        starting = [n for n, info in COMMANDS.items() if info.starts_output is not None]
        command = lookup("output command", start, starting)
    try:
        stream: BinaryIO = open(output, "wb")  # noqa: SIM115 - closed below
    except OSError as exc:
        raise CliError(f"{output}: {exc.strerror or exc}") from exc
    outputs = 0
    interrupted = False
    with stream:
        writer = PcapngWriter(
            stream,
            port=port,
            baud=baud,
            data_bits=int(SERIAL_LINE["data_bits"]),
            parity=str(SERIAL_LINE["parity"]),
            stop_bits=int(SERIAL_LINE["stop_bits"]),
        )
        with _session(port, baud) as client:
            client._port = _Tap(client._port, writer)  # every chunk goes to the capture
            try:
                _probe(client, port)
                if command is not None:
                    try:
                        client.start(command)
                    except IlahrsError as exc:
                        raise _failure(port, command, exc) from exc
                end = None if duration is None else time.monotonic() + duration
                while (end is None or time.monotonic() < end) and (count is None or outputs < count):
                    outputs += sum(1 for e in client.poll(0.05) if isinstance(e, Output) and not e.late)
            except KeyboardInterrupt:
                interrupted = True
            finally:
                summary = (len(client.received), client.discarded, len(client.errors))
    messages, discarded, errors = summary
    stopped = " (interrupted)" if interrupted else ""
    print(
        f"ilahrs record: {messages} messages, {discarded} bytes discarded, {errors} errors -> {output}{stopped}",
        file=out,
    )
    return 0


# --- send --------------------------------------------------------------------------------------------


def _block(command: str, assignments: Sequence[str]) -> Payload | None:
    table_name = COMMANDS[command].parameter_block
    if table_name is None:
        if assignments:
            raise CliError(f"{command} takes no parameter block, so no key=value")
        return None
    table = PAYLOADS[table_name]
    values = parse_assignments(table, assignments)
    try:
        return table.from_raw(values)
    except IlahrsError as exc:
        raise CliError(f"{exc.field or table_name}: {exc.detail or exc}") from exc


def _believe_valid(client: AhrsClient, command: str) -> None:
    """A new client believes the device idle: for a command that idle ignores, believe the device
    is in a state that hears it (the user knows the device's state)."""
    host = client.host
    event = command_event(COMMANDS[command].code, host.state) or command
    if transition(host.state, event) is not None:
        return
    for state in STATES:
        named = command_event(COMMANDS[command].code, state) or command
        if named == command and transition(state, command) is not None:
            host.resync(state)
            return


def send(port: str, baud: int, command: str, assignments: Sequence[str], *, variant: Variant, out: TextIO) -> int:
    """Send one command (and its parameter block); print the decoded answers."""
    name = lookup("command", command, COMMANDS)
    block = _block(name, assignments)
    with _session(port, baud, stop=False) as client:
        _believe_valid(client, name)
        try:
            answers = client.request(name, block)
        except IlahrsError as exc:
            raise _failure(port, name, exc) from exc
        if not answers:
            print(f"{name}: sent (the command has no answer)", file=out)
        for event in answers:
            if not isinstance(event, ProtocolError):
                print(_event_line(event, variant), file=out)
    return 0


# --- params ----------------------------------------------------------------------------------------


def params(port: str, baud: int, assignments: Sequence[str], *, variant: Variant, out: TextIO) -> int:
    """Print the parameters; with assignments, read-modify-write them (6.3.6) and read back."""
    load = PAYLOADS[COMMANDS[LOAD_PARAMETERS].parameter_block or ""]
    changes = parse_assignments(load, assignments) if assignments else {}
    with _session(port, baud) as client:
        _probe(client, port)
        try:
            current = client.read_parameters()
            if changes:
                merged = current.raw() | changes
                names = {f.name for f in load.FIELDS if f.type != "reserved"}
                try:
                    load.from_raw({k: v for k, v in merged.items() if k in names})
                except IlahrsError as exc:
                    raise CliError(f"{exc.field or load.NAME}: {exc.detail or exc}") from exc
                client.load_parameters(merged)
                current = client.read_parameters()
        except IlahrsError as exc:
            raise _failure(port, "parameters", exc) from exc
    now = current.raw()
    kept = [k for k, v in changes.items() if now.get(k) != v]
    for key, value in fields_of(current, variant).items():
        print(f"{key} = {value}", file=out)
    if kept:
        raise CliError(f"the device did not take {', '.join(f'{k}={changes[k]}' for k in kept)}")
    return 0


# --- calibrate ---------------------------------------------------------------------------------------

_STEPS: Final = {
    "alignment": "Keep the object still while the AHRS aligns",
    "2d": "Turn the object slowly through at least one full circle, keeping it level",
    "3d": "Turn the object slowly through as many orientations as you can",
    "2d2t": "Turn the object slowly through a full circle, tilted as for this run",
}


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
    for key, value in fields_of(block, variant, raw=True).items():
        print(f"  {key} = {value}", file=out)
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


def calibrate(
    port: str,
    baud: int,
    kind: str,
    *,
    accumulation: int | None,
    runs: int,
    answer: bool | None,
    variant: Variant,
    out: TextIO,
    ask: Callable[[str], str] = input,
) -> int:
    """A guided calibration: what to do at each step, progress, each run's result, the final
    result, then AcceptClb or ExitClb."""
    start = CALIBRATIONS[lookup("calibration", kind, CALIBRATIONS)]
    table = PAYLOADS[COMMANDS[start].parameter_block or ""]
    block = _block(start, [f"accumulation_time={accumulation}"] if accumulation is not None else [])
    assert block is not None
    word = next(w for w, c in CALIBRATIONS.items() if c == start)
    with _session(port, baud) as client:
        _probe(client, port)
        wait = _Wait(client, port, out)
        try:
            client.read_parameters()  # the alignment time, for the progress
            print(f"{start}: {table.TITLE} accumulation {block.raw().get('accumulation_time')!s} s", file=out)
            client.request(start, block)
            results: list[Payload] = []
            if start == START_RUNS:
                run_table = PAYLOADS[COMMANDS[START_RUN].parameter_block or ""]
                for run in range(1, runs + 1):
                    print(f"Run {run} of {runs}. {_STEPS['alignment']}.", file=out)
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
            accept = _decide(answer, ask, out)
            leave = command_event(COMMANDS[STOP].code, client.host.state) or STOP
            client.request(ACCEPT if accept else leave)
            print("accepted: saved in the AHRS" if accept else "discarded: the AHRS keeps its calibration", file=out)
        except IlahrsError as exc:
            raise _failure(port, start, exc) from exc
    return 0
