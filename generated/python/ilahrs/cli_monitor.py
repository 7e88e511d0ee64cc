# Copied from generator/targets/python/runtime/cli_monitor.py for spec/ilahrs.yaml,
# spec hash 78b1daeba1b7bf7f76f1a5c04fb54e25a73744c609525a6a8c577ce8f2cf2b4a.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs monitor`: a live full-screen view (curses) of an AHRS's output.

Stop, start the chosen output, then show every field of the latest block in engineering units
with its unit, the Unit Status Word's flags by name (highlighted when set), the measured frame
rate against the configured rate, and the counts of discarded bytes and protocol errors. `q`
quits; the device is sent Stop on the way out, also after Ctrl-C.
"""

from __future__ import annotations

import contextlib
import curses
import time
from collections import deque
from typing import TYPE_CHECKING, Any, Final

from .cli_common import SENTENCE_KIND, CliError, fields_of, lookup, open_client
from .commands import COMMANDS
from .encodings import Variant
from .errors import IlahrsError
from .host import Output
from .nmea import PahrSentence
from .status import UnitStatusWord, UswFlag

if TYPE_CHECKING:
    from .serial import AhrsClient

__all__ = ["monitor"]

_QUIT: Final = (ord("q"), ord("Q"))
_WINDOW: Final = 2.0
"""Seconds over which the frame rate is measured."""


def _units(data: Any) -> dict[str, str]:
    if isinstance(data, PahrSentence):
        return {name: unit for name, *_rest, unit in data._SPEC}
    return {f.name: f.unit or "" for f in data.FIELDS}


class _View:
    def __init__(self, client: AhrsClient, command: str, variant: Variant) -> None:
        self.client = client
        self.command = command
        self.variant = variant
        self.latest: Any = None
        self.times: deque[float] = deque()
        self.count = 0

    def take(self, events: list[Any]) -> None:
        now = time.monotonic()
        for event in events:
            if isinstance(event, Output) and not event.late:
                self.latest = event.data
                self.count += 1
                self.times.append(now)
        while self.times and now - self.times[0] > _WINDOW:
            self.times.popleft()

    def rate(self) -> float:
        if len(self.times) < 2:
            return 0.0
        span = self.times[-1] - self.times[0]
        return (len(self.times) - 1) / span if span > 0 else 0.0

    def draw(self, screen: Any) -> None:
        screen.erase()
        height, width = screen.getmaxyx()

        def put(row: int, col: int, text: str, attr: int = 0) -> None:
            if 0 <= row < height - 1 and col < width - 1:
                screen.addnstr(row, col, text, width - 1 - col, attr)

        configured = self.client.host.setting("output")
        put(0, 0, f"ilahrs monitor  {self.command}  state {self.client.host.state}   q: quit", curses.A_BOLD)
        put(1, 0, f"rate {self.rate():6.1f} Hz (configured {configured:g} Hz)   messages {self.count}")
        put(2, 0, f"discarded {self.client.discarded} bytes   errors {len(self.client.errors)}")
        data = self.latest
        if data is None:
            put(4, 0, "waiting for output (initial alignment) ...")
            screen.refresh()
            return
        kind = SENTENCE_KIND if isinstance(data, PahrSentence) else data.NAME
        put(4, 0, kind, curses.A_UNDERLINE)
        units = _units(data)
        row = 5
        for name, value in fields_of(data, self.variant).items():
            if name == "usw":
                continue
            shown = f"{value:12.4f}" if isinstance(value, float) else f"{value!s:>12}"
            put(row, 2, f"{name:<14}{shown} {units.get(name, '')}")
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
    curses.curs_set(0)
    screen.nodelay(True)
    while True:
        view.take(view.client.poll(0.05))
        view.draw(screen)
        if screen.getch() in _QUIT:
            return


def monitor(port: str, baud: int, command: str, variant: Variant, *, strict: bool = False) -> int:
    """Run the live view until `q`; Stop on exit. `strict`: refuse data frames whose reserved byte
    is not the AHRS's (E42)."""
    name = lookup("output command", command, [n for n, i in COMMANDS.items() if i.starts_output is not None])
    client = open_client(port, baud, strict=strict)
    try:
        try:
            client.stop()
            client.read_parameters()  # the configured rate
            client.request(name)
        except IlahrsError as exc:
            raise CliError(f"{port}: no answer from the AHRS ({exc.detail or exc})") from exc
        view = _View(client, name, variant)
        with contextlib.suppress(KeyboardInterrupt):
            curses.wrapper(_loop, view)
    finally:
        try:
            client.stop()
        finally:
            client.close()
    return 0
