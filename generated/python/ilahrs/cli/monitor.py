# Copied from generator/targets/python/runtime/cli/monitor.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs monitor`: a live full-screen view (curses) of an AHRS's output.

Stop, start the chosen output, then show every field of the latest block in engineering units
with its unit symbol (the spec's UNIT_SYMBOLS) and the digits its resolution gives (its scale in
the spec: heading to 0.01 deg, a magnetic field to 10 nT), the Unit Status Word's flags by name
(highlighted when set), the measured frame rate against the configured rate, and the counts of
discarded bytes and protocol errors. In an on-request mode (where the state machine answers
GET_DATA with an output block) the monitor sends GET_DATA at the configured update rate; NMEA
output runs at most at NMEA_MAX_RATE_HZ (E22), which the screen says when the configured rate
is above it. The rate is counted from the blocks' receive times over the last RATE_WINDOW
seconds. `q` quits; the device is sent Stop on the way out, also after Ctrl-C or SIGTERM. A lost
device (unplugged, the simulator killed) ends the view with one line and exit status 2.
"""

from __future__ import annotations

import argparse
import contextlib
import curses
import math
import time
from collections import deque
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any, Final

from ..codec import FieldInfo, Payload
from ..commands import COMMANDS
from ..edge.signals import sigterm_as_interrupt
from ..encodings import Variant
from ..errors import IlahrsError
from ..nmea import NMEA_MAX_RATE_HZ, PahrSentence
from ..roles import GET_DATA
from ..session.host import HostEvent, Output
from ..spec import UNIT_SYMBOLS
from ..statemachine import OUTPUT, OUTPUT_FORMATS
from ..statemachine import lookup as transition
from ..status import UnitStatusWord, UswFlag
from .arguments import (
    PORT_EPILOG,
    OneLineParser,
    output_format_argument,
    port_arguments,
    strict_argument,
    variant_argument,
)
from .common import SENTENCE_KIND, CliError, fields_of, lookup, open_client, variant_named
from .decode import output_table

if TYPE_CHECKING:
    from ..edge.serial import AhrsClient

__all__ = ["RATE_WINDOW", "RateMeter", "field_formats", "format_value", "monitor", "polled", "polling_rate"]

_QUIT: Final = (ord("q"), ord("Q"))
RATE_WINDOW: Final = 4.0
"""Seconds of receive times over which the frame rate is measured."""
_DRAW: Final = 0.05
"""Seconds between two updates of the screen (and looks at the keyboard)."""
_F32_DIGITS: Final = 7
"""Significant digits of a float32 field (no scale: its resolution is its own)."""


class RateMeter:
    """The rate of events from their receive times: the events after the first in the window,
    divided by the time from the first to the last. Events read together share a receive time, so
    counting the first time's events too would bias the rate up by a read's worth of events."""

    def __init__(self, window: float = RATE_WINDOW) -> None:
        self.window = window
        self._times: deque[float] = deque()

    def add(self, times: Iterable[float]) -> None:
        """Receive times (seconds, any monotonic clock), in order."""
        self._times.extend(times)
        if self._times:
            newest = self._times[-1]
            while newest - self._times[0] > self.window:
                self._times.popleft()

    def rate(self) -> float:
        """Events per second; 0 before two receive times are known."""
        if not self._times:
            return 0.0
        first = self._times[0]
        span = self._times[-1] - first
        if span <= 0:
            return 0.0
        return sum(1 for t in self._times if t > first) / span


def polled(state: str) -> bool:
    """Whether the device answers GET_DATA with an output block in `state` (an on-request mode)."""
    found = transition(state, GET_DATA)
    return found is not None and not found.wildcard and OUTPUT in found.send


def polling_rate(client: AhrsClient) -> float:
    """The rate output comes (or is asked for) at: the configured update rate, at most
    NMEA_MAX_RATE_HZ for NMEA output (E22)."""
    rate = client.host.setting("output")
    fmt = client.host.output_format
    if fmt is not None and OUTPUT_FORMATS.get(fmt) is None:
        rate = min(rate, NMEA_MAX_RATE_HZ)
    return rate


def _decimals(info: FieldInfo, variant: Variant) -> int | None:
    if info.type == "f32":
        return None
    divisor = info.divisor
    scale = getattr(variant, divisor.lower()) if isinstance(divisor, str) else divisor
    resolution = info.multiplier / scale
    return max(0, math.ceil(-math.log10(resolution) - 1e-9))


def field_formats(data: Payload | PahrSentence, variant: Variant) -> dict[str, tuple[int | None, str]]:
    """Each field of a decoded message -> (decimals its resolution gives, None for a float32 field;
    its unit's symbol, "" for none)."""
    if isinstance(data, PahrSentence):
        return {name: (decimals, UNIT_SYMBOLS.get(unit, unit)) for name, _k, _w, decimals, *_r, unit in data._SPEC}
    return {
        f.name: (_decimals(f, variant), UNIT_SYMBOLS.get(f.unit, f.unit) if f.unit else "")
        for f in data.FIELDS
        if f.type != "reserved"
    }


def format_value(value: object, decimals: int | None, width: int = 12) -> str:
    """A value with the digits of its field's resolution (general form, 7 digits, for a float32)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return f"{value!s:>{width}}"
    if decimals is None:
        return f"{value:>{width}.{_F32_DIGITS}g}"
    return f"{value:>{width}.{decimals}f}"


class _View:
    def __init__(self, client: AhrsClient, command: str, variant: Variant) -> None:
        self.client = client
        self.command = command
        self.variant = variant
        self.latest: Any = None
        self.meter = RateMeter()
        self.count = 0
        self.next_request = 0.0

    def take(self, events: list[HostEvent]) -> None:
        times = []
        for event in events:
            if isinstance(event, Output) and not event.late:
                self.latest = event.data
                self.count += 1
                times.append(event.at)
        self.meter.add(times)

    def rate(self) -> float:
        return self.meter.rate()

    def step(self) -> None:
        """Read for a while; in an on-request mode, send GET_DATA when the next one is due (on a
        fixed schedule, so the requests keep the configured rate on average)."""
        client = self.client
        if not polled(client.host.state):
            self.take(client.poll(_DRAW))
            return
        now = time.monotonic()
        if not client.host.owed and now >= self.next_request:
            client.send(GET_DATA)
            self.next_request = max(self.next_request + 1.0 / polling_rate(client), now)
        if client.host.owed:
            self.take(client.poll(0))
        else:
            time.sleep(max(0.0, min(self.next_request - time.monotonic(), _DRAW)))

    def rate_note(self) -> str:
        configured = self.client.host.setting("output")
        note = f"configured {configured:g} Hz"
        if polling_rate(self.client) < configured:
            note += f"; NMEA output capped at {NMEA_MAX_RATE_HZ:g} Hz"
        return note

    def counts(self) -> str:
        client = self.client
        text = f"messages {self.count}   discarded {client.discarded} bytes   errors {len(client.errors)}"
        if polled(client.host.state):
            text += f"   polling {GET_DATA} at {polling_rate(client):g} Hz"
        return text

    def draw(self, screen: Any) -> None:
        screen.erase()
        height, width = screen.getmaxyx()

        def put(row: int, col: int, text: str, attr: int = 0) -> None:
            if 0 <= row < height - 1 and col < width - 1:
                screen.addnstr(row, col, text, width - 1 - col, attr)

        put(0, 0, f"ilahrs monitor  {self.command}  state {self.client.host.state}   q: quit", curses.A_BOLD)
        put(1, 0, f"rate {self.rate():6.1f} Hz ({self.rate_note()})")
        put(2, 0, self.counts())
        data = self.latest
        if data is None:
            put(4, 0, "waiting for output (initial alignment) ...")
            screen.refresh()
            return
        kind = SENTENCE_KIND if isinstance(data, PahrSentence) else data.NAME
        put(4, 0, kind, curses.A_UNDERLINE)
        formats = field_formats(data, self.variant)
        row = 5
        for name, value in fields_of(data, self.variant).items():
            if name == "usw":
                continue
            decimals, symbol = formats.get(name, (None, ""))
            put(row, 2, f"{name:<14}{format_value(value, decimals)} {symbol}".rstrip())
            row += 1
        word = UnitStatusWord(int(data.usw))
        put(row + 1, 0, f"USW {word.raw:#06x}  mode {word.mode.value}", curses.A_BOLD)
        col, row = 0, row + 2
        for flag in UswFlag:
            label = f" {flag.name} "
            if col + len(label) >= width - 1:
                col, row = 0, row + 1
            put(row, col, label, curses.A_REVERSE | curses.A_BOLD if flag in word.flags else curses.A_DIM)
            col += len(label) + 1
        screen.refresh()


def _loop(screen: Any, view: _View) -> None:
    with contextlib.suppress(curses.error):  # a terminal that cannot hide the cursor
        curses.curs_set(0)
    screen.nodelay(True)
    next_draw = 0.0
    while True:
        view.step()
        if time.monotonic() >= next_draw:
            view.draw(screen)
            next_draw = time.monotonic() + _DRAW
            if screen.getch() in _QUIT:
                return


def _lost(port: str, exc: OSError) -> CliError:
    detail = exc.strerror or str(exc) or type(exc).__name__
    return CliError(f"{port}: lost the device ({detail})")


def monitor(port: str, baud: int, command: str, variant: Variant, *, strict: bool = False) -> int:
    """Run the live view until `q`, Ctrl-C or SIGTERM; Stop on exit. `strict`: refuse data frames
    whose reserved byte is not the AHRS's (E42). CliError (one line) when the device does not
    answer or is lost."""
    name = lookup("output command", command, [n for n, i in COMMANDS.items() if i.starts_output is not None])
    client = open_client(port, baud, strict=strict)
    alive = True
    try:
        with sigterm_as_interrupt():
            try:
                client.stop()
                client.read_parameters()  # the configured rate
                client.request(name)
            except IlahrsError as exc:
                raise CliError(f"{port}: no answer from the AHRS ({exc.detail or exc})") from exc
            except OSError as exc:
                alive = False
                raise _lost(port, exc) from None
            view = _View(client, name, variant)
            try:
                curses.wrapper(_loop, view)
            except KeyboardInterrupt:
                pass
            except OSError as exc:  # curses.wrapper has restored the terminal
                alive = False
                raise _lost(port, exc) from None
    finally:
        if alive:
            with contextlib.suppress(OSError, IlahrsError):
                client.stop()
        with contextlib.suppress(OSError):
            client.close()
    return 0


# --- the subcommand -------------------------------------------------------------------------------


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    sub = commands.add_parser("monitor", help="live full-screen view of the output (q quits)", epilog=PORT_EPILOG)
    port_arguments(sub)
    output_format_argument(sub, "AHRScont3")
    variant_argument(sub)
    strict_argument(sub)
    return sub


def run(args: argparse.Namespace) -> int:
    """`ilahrs monitor`."""
    output_table(args.output_format)  # refuse an unknown command before opening the port
    return monitor(args.port, args.baud, args.output_format, variant_named(args.variant), strict=args.strict)
