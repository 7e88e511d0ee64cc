# Copied from generator/targets/python/runtime/edge/simulate.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The virtual AHRS on a serial line: the device model behind a pseudo-terminal or a loopback
socket, in real time.

`run_pty()` opens a pty whose device end is set to the AHRS line (BAUDRATE, 8N1, raw), prints
its path as the first line of output, and serves the device model there; any serial client
(pyserial, `screen`) can talk to it. `run_tcp()` serves a loopback address instead (never another
address) and prints the URL a client opens, `socket://HOST:PORT`, first; it serves one connection
at a time, one after another, until stopped. The device carries on between connections, as a
real AHRS does when a program closes its port: its state, parameters and calibration stay, its
clock runs, and what it sends while no client is connected is lost (counted in `Line.lost`).
Output is paced by the device model's own clock, advanced with the wall clock. A `Faults` object
corrupts and drops bytes and puts garbage between messages at given rates (seeded), and the log
(JSON lines) says what was meant and what was written for every message, so a test can check that
each intact message arrived.

This module is the edge of the package: it uses os, select, socket and termios (POSIX).
"""

from __future__ import annotations

import ipaddress
import json
import os
import random
import select
import signal
import socket
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from types import FrameType
from typing import BinaryIO, Final, TextIO

from ..pcapng import Direction, PcapngWriter
from ..session.device import Device
from ..spec import SERIAL_LINE
from ..stream import StreamDecoder

__all__ = ["BAUDRATE", "Faults", "Line", "loopback_address", "recorder", "run_pty", "run_tcp", "socket_url"]

BAUDRATE: Final = int(SERIAL_LINE["baud_rate"])
"""The baud rate of the AHRS serial line (section 6; 8 data bits, no parity, 1 stop bit: `ilahrs.spec`)."""
_BUFFER_LIMIT: Final = 65536
"""Bytes the line holds for a reader that does not read; beyond them output is lost, as on a UART."""
_TICK: Final = 0.02
"""Longest wait between two looks at the device's clock, seconds."""


@dataclass(frozen=True, slots=True)
class Faults:
    """Damage done to what the device sends: each byte is corrupted (replaced by another value)
    with probability `corrupt_rate` or dropped with probability `drop_rate`; before each message,
    1 to 16 random bytes are inserted with probability `garbage_rate`."""

    corrupt_rate: float = 0.0
    drop_rate: float = 0.0
    garbage_rate: float = 0.0
    seed: int = 0

    @property
    def active(self) -> bool:
        return self.corrupt_rate > 0 or self.drop_rate > 0 or self.garbage_rate > 0


class Line:
    """The device end of the line, sans-I/O: bytes from the host and wall-clock time in, bytes to
    write out, with faults applied and every message logged."""

    def __init__(self, device: Device, faults: Faults | None = None, log: TextIO | None = None) -> None:
        self.device = device
        self.faults = faults or Faults()
        self._rng = random.Random(self.faults.seed)
        self._log = log
        self._splitter = StreamDecoder()
        self._time: float | None = None
        self.sent = 0
        """Messages the device sent."""
        self.intact = 0
        """Messages written unchanged."""
        self.lost = 0
        """Messages lost because nobody read the line."""
        self.recorder: Callable[[bytes, bool], None] | None = None
        """Called with each chunk the host sent (True: host to device) and each chunk written."""

    def step(self, incoming: bytes, now: float) -> bytes:
        """Advance the device to `now` (seconds, any monotonic clock), hand it `incoming`; return
        what to write to the line."""
        elapsed = 0.0 if self._time is None else max(0.0, now - self._time)
        self._time = now
        out = self.device.advance(elapsed)
        if incoming:
            if self.recorder is not None:
                self.recorder(incoming, True)
            out += self.device.receive(incoming)
        if not out:
            return b""
        written = bytearray()
        for message in self._splitter.feed(out):
            written += self.emit(message.raw)
        if written and self.recorder is not None:
            self.recorder(bytes(written), False)
        return bytes(written)

    def lose(self, data: bytes) -> None:
        """Count messages that could not be written (the reader's buffer is full)."""
        self.lost += 1
        self._record({"kind": "lost", "written": data.hex()})

    def emit(self, message: bytes) -> bytes:
        """What the line writes for one message the device sends: the message with the faults
        applied (and garbage before it), counted and logged."""
        faults = self.faults
        rng = self._rng
        garbage = b""
        if faults.garbage_rate > 0 and rng.random() < faults.garbage_rate:
            garbage = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
            self._record({"kind": "garbage", "written": garbage.hex()})
        damaged = bytearray()
        for byte in message:
            if faults.drop_rate > 0 and rng.random() < faults.drop_rate:
                continue
            corrupt = faults.corrupt_rate > 0 and rng.random() < faults.corrupt_rate
            damaged.append(byte ^ rng.randint(1, 255) if corrupt else byte)
        intact = bytes(damaged) == message
        self.sent += 1
        self.intact += intact
        kind = "sentence" if message[:1] == b"$" else "frame"
        self._record({"kind": kind, "message": message.hex(), "written": damaged.hex(), "intact": intact})
        return garbage + bytes(damaged)

    def _record(self, entry: dict[str, object]) -> None:
        if self._log is not None:
            entry = {"t": round(self.device.now, 6), "state": self.device.state, **entry}
            self._log.write(json.dumps(entry, sort_keys=True) + "\n")
            self._log.flush()


def recorder(stream: BinaryIO, port: str) -> Callable[[bytes, bool], None]:
    """A Line.recorder that writes each chunk to `stream` as pcapng (ilahrs.pcapng), as the host
    sees the line: what the host sent is outbound, what the device wrote inbound."""
    writer = PcapngWriter(stream, port=port, baud=BAUDRATE, application="ilahrs simulate")

    def write(data: bytes, from_host: bool) -> None:
        direction = Direction.OUTBOUND if from_host else Direction.INBOUND
        writer.write(data, time.time_ns() // 1000, direction)

    return write


def loopback_address(text: str) -> tuple[str, int]:
    """HOST:PORT -> (host, port), refusing any host that is not a loopback address."""
    host, sep, port = text.rpartition(":")
    host = host.strip("[]")
    if not sep or not port.isdigit() or not 0 <= int(port) <= 65535:
        raise ValueError(f"{text!r} is not HOST:PORT")
    if host == "localhost":
        host = "127.0.0.1"
    try:
        address = ipaddress.ip_address(host)
    except ValueError as exc:
        raise ValueError(f"{host!r} is not an IP address (only loopback addresses are served)") from exc
    if not address.is_loopback:
        raise ValueError(f"{host} is not a loopback address; the virtual device serves loopback only")
    return host, int(port)


def socket_url(host: str, port: int) -> str:
    """The pyserial URL of a TCP port: socket://HOST:PORT (an IPv6 host in brackets)."""
    return f"socket://[{host}]:{port}" if ":" in host else f"socket://{host}:{port}"


class _Stop:
    """Set by SIGINT / SIGTERM."""

    def __init__(self) -> None:
        self.requested = False
        signal.signal(signal.SIGINT, self._handle)
        signal.signal(signal.SIGTERM, self._handle)

    def _handle(self, signum: int, frame: FrameType | None) -> None:
        del signum, frame
        self.requested = True


def _serve(
    line: Line,
    fd: int,
    stop: _Stop,
    reader: Callable[[], bytes | None],
    writer: Callable[[bytes], int],
    *,
    clock: Callable[[], float] = time.monotonic,
) -> None:
    """Pump bytes between the line and a file descriptor until stopped or the peer closes."""
    pending = bytearray()
    while not stop.requested:
        wait = line.device.next_event_in
        timeout = _TICK if wait is None else max(0.0005, min(_TICK, wait))
        readable, _, _ = select.select([fd], [], [], timeout)
        incoming = b""
        if readable:
            data = reader()
            if data is None:
                break
            incoming = data
        out = line.step(incoming, clock())
        if out:
            if len(pending) + len(out) > _BUFFER_LIMIT:
                line.lose(out)
            else:
                pending += out
        if pending:
            try:
                written = writer(bytes(pending))
            except BlockingIOError:
                written = 0
            except OSError:
                break  # the peer is gone
            del pending[:written]


def _configure_pty(fd: int) -> None:
    """Raw mode on the AHRS line (SERIAL_LINE: baud rate, data bits, parity, stop bits), no flow control."""
    import termios
    import tty

    tty.setraw(fd)
    attrs = termios.tcgetattr(fd)
    attrs[2] &= ~(termios.PARENB | termios.CSTOPB | termios.CSIZE | termios.CRTSCTS)
    attrs[2] |= getattr(termios, f"CS{SERIAL_LINE['data_bits']}") | termios.CLOCAL | termios.CREAD
    if SERIAL_LINE["parity"] != "none":
        attrs[2] |= termios.PARENB | (termios.PARODD if SERIAL_LINE["parity"] == "odd" else 0)
    if SERIAL_LINE["stop_bits"] == 2:
        attrs[2] |= termios.CSTOPB
    attrs[4] = attrs[5] = getattr(termios, f"B{BAUDRATE}")
    termios.tcsetattr(fd, termios.TCSANOW, attrs)


def run_pty(line: Line, out: TextIO = sys.stdout) -> int:
    """Serve `line` on a new pseudo-terminal; print its path first. Returns an exit status."""
    stop = _Stop()  # before the path is printed: a client may signal as soon as it reads it
    master, slave = os.openpty()
    try:
        _configure_pty(slave)
        os.set_blocking(master, False)
        print(os.ttyname(slave), file=out, flush=True)

        def read() -> bytes:
            try:
                return os.read(master, 4096)
            except (BlockingIOError, OSError):
                return b""  # EIO while no client has the device open: nothing to read

        _serve(line, master, stop, read, lambda data: os.write(master, data))
    finally:
        os.close(master)
        os.close(slave)
    return 0


def run_tcp(line: Line, address: str, out: TextIO = sys.stdout) -> int:
    """Serve `line` on a loopback address (port 0: any free port); print socket://HOST:PORT first.
    One connection at a time, one after another, until SIGINT / SIGTERM; between connections the
    device carries on and what it sends is lost. Returns an exit status."""
    host, port = loopback_address(address)
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    stop = _Stop()
    with socket.socket(family, socket.SOCK_STREAM) as server:
        server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        server.bind((host, port))
        server.listen(1)
        server.setblocking(False)
        print(socket_url(host, server.getsockname()[1]), file=out, flush=True)
        while not stop.requested:
            connection = _accept(line, server, stop)
            if connection is not None:
                _serve_connection(line, connection, stop)
    return 0


def _accept(line: Line, server: socket.socket, stop: _Stop) -> socket.socket | None:
    """Wait for the next client while the device runs on (its output lost, and not recorded: no
    host saw it); None when stopped."""
    recording, line.recorder = line.recorder, None
    try:
        while not stop.requested:
            wait = line.device.next_event_in
            timeout = _TICK if wait is None else max(0.0005, min(_TICK, wait))
            ready, _, _ = select.select([server], [], [], timeout)
            out = line.step(b"", time.monotonic())
            if out:
                line.lose(out)
            if ready:
                try:
                    connection, _peer = server.accept()
                except (BlockingIOError, ConnectionAbortedError):
                    continue
                return connection
        return None
    finally:
        line.recorder = recording


def _serve_connection(line: Line, connection: socket.socket, stop: _Stop) -> None:
    with connection:
        connection.setblocking(False)
        connection.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

        def read() -> bytes | None:
            try:
                data = connection.recv(4096)
            except BlockingIOError:
                return b""
            except OSError:
                return None
            return data or None  # b"": the peer closed

        _serve(line, connection.fileno(), stop, read, connection.send)
