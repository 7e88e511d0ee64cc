"""`ilahrs.Device` behind a real pseudo-terminal, served by a thread the way `ilahrs simulate` serves
it (`ilahrs.edge.simulate.Line`, the line configured by `_configure_pty`, the device's clock advanced with
the wall clock): the peer of the stateful client test and of the command-line matrix."""

from __future__ import annotations

import fcntl
import os
import select
import struct
import termios
import threading
import time

from ilahrs.edge.simulate import Line, _configure_pty
from ilahrs.roles import ParameterBlock
from ilahrs.session.device import Device, default_parameters
from ilahrs.statemachine import STATES, TIMER_FIELDS, TIMER_IS_RATE

DRAIN = 5.0
"""Generous time for a message the device sent to reach the client (it takes milliseconds)."""
SHORT_TIMER = 1
"""Seconds of alignment and accumulation the device starts with (the bottom of their ranges)."""
TICK = 0.02
"""Longest the serving thread waits for input before stepping the device."""


class _RecordingLine(Line):
    """The simulator's line, which keeps every message it writes, and writes nothing (and hears
    nothing) while unplugged."""

    def __init__(self, device: Device) -> None:
        super().__init__(device)
        self.connected = True
        self.written: list[bytes] = []

    def step(self, incoming: bytes, now: float) -> bytes:
        return super().step(incoming if self.connected else b"", now)

    def emit(self, message: bytes) -> bytes:
        if not self.connected:
            return b""
        self.written.append(message)
        return super().emit(message)


_SKIPPED_TIMERS = {timer for timer, rate in TIMER_IS_RATE.items() if not rate}
"""The timers `PtyDevice.skip` may end early: alignment and accumulation, never the output rate."""


def _device(seed: int, alignment: int = SHORT_TIMER) -> Device:
    raw = default_parameters().raw()
    raw[TIMER_FIELDS["alignment"][1]] = alignment
    return Device(seed=seed, parameters=ParameterBlock.from_raw(raw))


class PtyDevice:
    """`ilahrs.Device` served on a pseudo-terminal by a thread, as `ilahrs simulate` serves it
    (run_pty / _serve): the device's clock follows the wall clock."""

    def __init__(self, seed: int) -> None:
        self.lock = threading.Lock()
        self.line = _RecordingLine(_device(seed))
        self._seed = seed
        self._master, self._slave = os.openpty()
        _configure_pty(self._slave)
        os.set_blocking(self._master, False)
        self.path = os.ttyname(self._slave)
        self._stopped = False
        self.offset = 0.0
        """Seconds added to the wall clock: `skip()` moves the device's clock past a timer at once."""
        self.fast_after_input = False
        """Set: once bytes come from the host, every alignment and accumulation ends at once."""
        self._fast = False
        self._loops = 0
        self.failure: BaseException | None = None
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        pending = bytearray()
        try:
            while not self._stopped:
                with self.lock:
                    wait = self.line.device.next_event_in
                timeout = TICK if wait is None else max(0.0005, min(TICK, wait))
                readable, _, _ = select.select([self._master], [], [], timeout)
                incoming = b""
                if readable:
                    try:
                        incoming = os.read(self._master, 4096)
                    except (BlockingIOError, OSError):
                        incoming = b""
                with self.lock:
                    self._fast = self._fast or (self.fast_after_input and bool(incoming))
                    if self._fast and STATES[self.line.device.state].timer in _SKIPPED_TIMERS:
                        self._skip()
                    pending += self.line.step(incoming, time.monotonic() + self.offset)
                if pending:
                    try:
                        written = os.write(self._master, bytes(pending))
                    except BlockingIOError:
                        written = 0
                    del pending[:written]
                self._loops += 1
        except BaseException as exc:  # reported by the test, never swallowed
            self.failure = exc

    def snapshot(self) -> tuple[str, int]:
        """The device's state and how many messages it has written, at one instant."""
        with self.lock:
            return self.line.device.state, len(self.line.written)

    @property
    def written(self) -> list[bytes]:
        with self.lock:
            return list(self.line.written)

    def connect(self, connected: bool) -> None:
        with self.lock:
            self.line.connected = connected

    def _unread(self) -> int:
        """Bytes the host wrote that the device has not read yet."""
        return struct.unpack("i", fcntl.ioctl(self._master, termios.FIONREAD, b"\0\0\0\0"))[0]  # type: ignore[no-any-return]

    def power_cycle(self, alignment: int = SHORT_TIMER) -> None:
        """A new device in its power-up state (with `alignment` seconds of alignment), on the same
        line, once the old one has read what the host sent it."""
        end = time.monotonic() + DRAIN
        while self._unread() and time.monotonic() < end:
            time.sleep(0.005)
        loops = self._loops
        while self._loops < loops + 2 and time.monotonic() < end:  # what was read has been stepped
            time.sleep(0.005)
        self._seed += 1
        with self.lock:
            self.line.device = _device(self._seed, alignment)
            self.fast_after_input = self._fast = False

    def _skip(self) -> None:
        wait = self.line.device.next_event_in
        if wait is not None:
            self.offset += wait

    def skip(self) -> None:
        """End the timer running in the device's state now (the alignment, the accumulation)."""
        with self.lock:
            self._skip()

    def close(self) -> None:
        self._stopped = True
        self._thread.join(10)
        os.close(self._master)
        os.close(self._slave)
