"""A recorded session with the virtual AHRS, for the dissector's differential test.

The Python package's sans-I/O `Device` and `Host` talk back to back on one simulated clock; every
chunk either side writes goes into a pcapng capture (`ilahrs.pcapng`) with its time and direction,
as `ilahrs record` writes them. The device's bytes are cut into chunks the way serial reads cut
them (a message split across packets, several messages in one packet); garbage is put between
messages; an acknowledgement, an alignment block, an output frame and a $PAHR sentence get a wrong
checksum (so an answer goes missing and an alignment block never comes), and one output block is
written after the Stop that ended its output (late output).

The session sends every command of the spec, brings every payload table on the line, runs a 2D, a
3D and a 2D-2T calibration and both $PAHR outputs. `Recording.covered()` says which commands and
tables it used, so the test can require all of them.

    python tests/wireshark/session.py OUT.pcapng [--variant NAME] [--seed N]
"""

from __future__ import annotations

import argparse
import random
import sys
from dataclasses import dataclass, field
from pathlib import Path

import ilahrs
from ilahrs.pcapng import Direction, PcapngWriter
from ilahrs.session.device import Device
from ilahrs.session.host import Acknowledged, DataBlock, HostEvent, Output

EPOCH_US = 1_700_000_000_000_000
"""The capture's first timestamp (microseconds since 1970)."""
BYTE_US = 87
"""Time one byte takes on a 115200 baud 8N1 line (10 bits), rounded."""
PORT = "/dev/ttyVIRT0"

# Garbage the line may carry: noise, a false header, an absurd length, a foreign sentence, a
# $PAHR sentence cut short. None of it holds a frame or $PAHR sentence that only its checksum spoils.
GARBAGE = (
    bytes.fromhex("00 13 7f 80 fe"),
    bytes.fromhex("aa 55 07"),
    bytes.fromhex("aa 55 01 00 ff 00 11 22"),
    b"$GPGGA,1,2*00\r\n",
    b"$PAHR,0001.00\x00",
    bytes.fromhex("55 aa 55"),
)


@dataclass
class Packet:
    timestamp_us: int
    direction: Direction
    data: bytes


@dataclass
class Recording:
    packets: list[Packet] = field(default_factory=list)
    damaged: list[bytes] = field(default_factory=list)
    """Frames and sentences written with a wrong checksum, as written."""
    commands: set[str] = field(default_factory=set)
    tables: set[str] = field(default_factory=set)
    late: int = 0

    def covered(self) -> tuple[set[str], set[str]]:
        """(commands never sent, payload tables never on the line)."""
        return set(ilahrs.COMMANDS) - self.commands, set(ilahrs.PAYLOADS) - self.tables


class Session:
    def __init__(self, variant: str, seed: int) -> None:
        self.rng = random.Random(seed)
        self.device = Device(seed=seed, variant=variant)
        self.host = ilahrs.Host()
        self.now_us = 0
        self.recording = Recording()
        self.damage_frame = False
        self.damage_sentence = False

    # --- the line --------------------------------------------------------------------------------

    def write(self, data: bytes, direction: Direction) -> None:
        self.recording.packets.append(Packet(EPOCH_US + self.now_us, direction, data))
        self.now_us += len(data) * BYTE_US

    def idle(self, seconds: float) -> None:
        """Time passes with nothing on the line (the host's clock too)."""
        step = round(seconds * 1_000_000)
        self.now_us += step
        self.events(self.host.advance(step / 1_000_000))

    def events(self, events: list[HostEvent]) -> None:
        for event in events:
            if isinstance(event, Acknowledged):
                self.recording.tables.add(ilahrs.PAYLOADS["acknowledgement"].NAME)
            elif isinstance(event, DataBlock):
                self.recording.tables.add(event.payload.NAME)
            elif isinstance(event, Output):
                self.recording.late += event.late
                if isinstance(event.data, ilahrs.PahrSentence):
                    continue
                self.recording.tables.add(event.data.NAME)

    def from_device(self, data: bytes) -> None:
        """The device's bytes as serial reads return them: mostly small chunks, sometimes several
        messages at once; now and then garbage before them."""
        data = self.damage(data)
        if self.rng.random() < 0.15:
            data = self.rng.choice(GARBAGE) + data
        pos = 0
        while pos < len(data):
            size = self.rng.randint(1, 24) if self.rng.random() < 0.7 else self.rng.randint(40, 160)
            chunk = data[pos : pos + size]
            before = self.now_us
            self.write(chunk, Direction.INBOUND)
            self.events(self.host.advance((self.now_us - before) / 1_000_000))
            self.events(self.host.receive(chunk))
            pos += size

    def damage(self, data: bytes) -> bytes:
        """Spoil the checksum of the first frame or sentence in `data` when asked to."""
        if self.damage_sentence and data.startswith(b"$"):
            end = data.index(b"\n") + 1
            digit = b"0" if data[end - 4 : end - 3] != b"0" else b"1"
            spoiled = data[: end - 4] + digit + data[end - 3 : end]
            self.damage_sentence = False
            self.recording.damaged.append(spoiled)
            return spoiled + data[end:]
        if self.damage_frame and data.startswith(ilahrs.frame.HEADER):
            size = ilahrs.frame.HEADER_SIZE + int.from_bytes(data[4:6], "little")
            spoiled = data[: size - 3] + bytes([data[size - 3] ^ 0x01]) + data[size - 2 : size]
            self.damage_frame = False
            self.recording.damaged.append(spoiled)
            return spoiled + data[size:]
        return data

    # --- the protocol ----------------------------------------------------------------------------

    def send(self, command: str, block: ilahrs.Payload | None = None, *, together: bool = False) -> None:
        """The host writes a command (and its parameter block, in a packet of its own unless
        `together`); the device answers 2 ms later."""
        data = self.host.send(command, block)
        self.recording.commands.add(command)
        if block is not None:
            self.recording.tables.add(block.NAME)
        cut = len(data) if together or block is None else len(ilahrs.build_command(command))
        self.write(data[:cut], Direction.OUTBOUND)
        if cut < len(data):
            self.now_us += 1000
            self.write(data[cut:], Direction.OUTBOUND)
        answer = self.device.receive(data)
        self.run(0.002)
        if answer:
            self.from_device(answer)

    def run(self, seconds: float, step: float = 0.01) -> None:
        """Let time pass: what the device sends meanwhile goes on the line, at most `step` apart."""
        remaining = round(seconds * 1_000_000)
        while remaining > 0:
            micro = min(remaining, round(step * 1_000_000))
            out = self.device.advance(micro / 1_000_000)
            self.idle(micro / 1_000_000)
            remaining -= micro
            if out:
                self.from_device(out)

    def stop_with_output_in_flight(self) -> None:
        """Stop while an output block is on its way: the block arrives after the Stop went out."""
        wait = self.device.next_event_in
        assert wait is not None
        in_flight = self.device.advance(wait)
        self.idle(wait)
        data = self.host.send("Stop")
        self.recording.commands.add("Stop")
        self.write(data, Direction.OUTBOUND)
        assert self.device.receive(data) == b""
        self.from_device(in_flight)


def configure(s: Session) -> None:
    """Read what the device is, load short alignment and a 20 Hz rate, clear the calibration."""
    s.send("GetVerFirmware")
    s.send("ReadAHRSPar")
    s.send("GetBIT")
    load = ilahrs.AhrsParametersLoad.from_raw(
        {
            "update_rate": 20,
            "alignment_time": 1,
            "latitude": 45.5,
            "longitude": -73.5,
            "altitude": 30.0,
            "date": ilahrs.encode_date(2024, 5, 17),
        }
    )
    s.send("LoadAHRSPar", load)
    s.send("ReadAHRSPar")
    s.damage_frame = True  # the acknowledgement never arrives: missing after the host's timeout
    s.send("ClearClb")
    s.idle(1.2)
    s.send("ClearClb")
    s.send("GetClbRes")


def outputs(s: Session) -> None:
    """Continuous output in each binary format (a damaged frame, a lost alignment block, a block in
    flight at Stop, the last block before sleep); on request in each format, GetBIT in between."""
    s.send("AHRScont1")
    s.run(1.3)
    s.damage_frame = True
    s.run(0.3, step=0.12)
    s.stop_with_output_in_flight()
    s.idle(1.5)
    s.send("AHRScont2")
    s.damage_frame = True  # the alignment block is lost: output arrives instead
    s.run(1.2)
    s.send("Stop")
    s.idle(0.3)
    s.send("AHRScont3")
    s.run(1.3, step=0.07)
    s.send("LowPowerOn")
    s.idle(0.2)
    s.send("LowPowerOff")
    for start in ("AHRSreq1", "AHRSreq2", "AHRSreq3"):
        s.send(start)
        s.run(1.1)
        s.send("GetDataReq")
        s.send("GetBIT")
        s.send("GetDataReq")
        s.send("Stop")


def sentences(s: Session) -> None:
    """$PAHR sentences, continuous (one damaged) and on request; sleep from idle."""
    s.send("NMEAcont")
    s.run(1.2)
    s.damage_sentence = True
    s.run(0.2)
    s.send("Stop")
    s.idle(0.5)
    s.send("NMEAreq")
    s.run(1.1)
    s.send("GetDataReq")
    s.send("Stop")
    s.send("LowPowerOn")
    s.send("LowPowerOff")


def calibrations(s: Session) -> None:
    """3D accepted; 2D stopped early and left; 2D-2T with two full runs and one stopped early."""
    block = ilahrs.CalibrationParameters.from_raw(
        {
            "accumulation_time": 2,
            "latitude": 45.5,
            "longitude": -73.5,
            "altitude": 30.0,
            "date": ilahrs.encode_date(2024, 5, 17),
        }
    )
    s.send("Start3DClb", block)
    s.run(3.2)
    s.send("AcceptClb")
    s.send("Start2DClb", block, together=True)
    s.run(1.5)
    s.send("StopClbRun")
    s.send("ExitClb")
    s.send("Start2D2TClb", block)
    for _ in range(2):
        s.send("StartClbRun", ilahrs.CalibrationRunParameters())
        s.run(3.2)
    s.send("StartClbRun", ilahrs.CalibrationRunParameters(), together=True)
    s.run(1.5)
    s.send("StopClbRun")
    s.send("FinishClb")
    s.send("AcceptClb")
    s.send("GetClbRes")


def scenario(session: Session) -> None:
    """Every command, every payload table, three calibrations, $PAHR output."""
    configure(session)
    outputs(session)
    sentences(session)
    calibrations(session)
    session.idle(0.1)


def save(path: Path, recording: Recording) -> None:
    with path.open("wb") as out:
        writer = PcapngWriter(out, port=PORT, baud=115200)
        for packet in recording.packets:
            writer.write(packet.data, packet.timestamp_us, packet.direction)


def record(path: Path, *, variant: str = "g300_a2_tmga", seed: int = 20140311) -> Recording:
    session = Session(variant, seed)
    scenario(session)
    save(path, session.recording)
    return session.recording


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--variant", default="g300_a2_tmga")
    parser.add_argument("--seed", type=int, default=20140311)
    args = parser.parse_args(argv)
    recording = record(args.out, variant=args.variant, seed=args.seed)
    print(f"{args.out}: {len(recording.packets)} packets, {len(recording.damaged)} damaged messages")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
