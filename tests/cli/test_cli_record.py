"""`ilahrs record` as a user runs it: against `ilahrs simulate` on a pseudo-terminal (and on
loopback TCP), ended by --count, --duration, Ctrl-C, SIGTERM and the loss of the device, with a
file already at the output path, several commands sent, and a second process on the same port."""

from __future__ import annotations

import os
import pty
import re
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from simulators import ILAHRS, Simulator, ilahrs
from test_cli import assert_stopped, decoded, simulator, written_intact

from ilahrs import PAYLOADS, StreamDecoder
from ilahrs.commands import COMMANDS
from ilahrs.roles import LOAD_PARAMETERS, READ_PARAMETERS

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

OLD = b"an earlier capture the user wants to keep\n" * 100
_SUMMARY = re.compile(r"^ilahrs record: (\d+) messages, (\d+) bytes discarded, (\d+) errors -> (.*)$")
_WAIT = 30.0


def wait_until(condition: Callable[[], bool], what: str, timeout: float = _WAIT) -> None:
    end = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < end, f"timed out waiting for {what}"
        time.sleep(0.05)


def outputs_sent(sim: Simulator, table: str = "AHRScont3") -> int:
    """Output blocks of `table` the simulator has written so far."""
    size = PAYLOADS[COMMANDS[table].starts_output or ""].SIZE
    return sum(1 for e in sim.entries() if e.get("kind") == "frame" and len(str(e["message"])) // 2 == size + 8)


def start_recording(port: str, capture: Path, *args: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [*ILAHRS, "record", port, "-o", str(capture), *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def summary_of(line: str) -> tuple[int, int, int]:
    match = _SUMMARY.match(line)
    assert match, line
    return int(match[1]), int(match[2]), int(match[3])


def decode_counts(capture: Path) -> tuple[int, int, int]:
    """Messages, discarded bytes and errors as `ilahrs decode` reports them."""
    summary = ilahrs("decode", str(capture)).stderr
    messages = int(re.search(r"(\d+) messages", summary)[1])  # type: ignore[index]
    discarded = int(re.search(r"(\d+) bytes discarded", summary)[1])  # type: ignore[index]
    errors = int(re.search(r"(\d+) decode errors", summary)[1])  # type: ignore[index]
    return messages, discarded, errors


def leftovers(folder: Path, *keep: str) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name not in keep and not p.name.startswith("simulator"))


def one_line(result: subprocess.CompletedProcess[str], *words: str) -> str:
    assert result.returncode == 2, (result.stdout, result.stderr)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    for word in words:
        assert word in lines[0], lines[0]
    return lines[0]


# --- Never destroy what the user has ----------------------------------------------------------------


def test_a_failed_recording_leaves_the_existing_file_and_no_other(tmp_path: Path) -> None:
    keep = tmp_path / "keep.pcapng"
    keep.write_bytes(OLD)
    one_line(ilahrs("record", "/dev/ilahrs-no-such-port", "-o", str(keep)), "cannot open")
    assert keep.read_bytes() == OLD
    assert leftovers(tmp_path, "keep.pcapng") == []
    # A port that is there but silent (a pty nobody answers on): the line suggests --baud.
    controller, terminal = pty.openpty()
    try:
        result = ilahrs("record", os.ttyname(terminal), "-o", str(keep))
    finally:
        os.close(controller)
        os.close(terminal)
    one_line(result, "no answer", "--baud")
    assert keep.read_bytes() == OLD
    assert leftovers(tmp_path, "keep.pcapng") == []
    # A new file is not created either.
    one_line(ilahrs("record", "/dev/ilahrs-no-such-port", "-o", str(tmp_path / "new.pcapng")), "cannot open")
    assert leftovers(tmp_path, "keep.pcapng") == []


def test_the_file_is_replaced_only_when_the_recording_ends(tmp_path: Path) -> None:
    keep = tmp_path / "keep.pcapng"
    keep.write_bytes(OLD)
    with simulator(tmp_path) as sim:
        process = start_recording(sim.port, keep, "--start", "AHRScont3")
        wait_until(lambda: outputs_sent(sim) >= 20, "output")
        assert keep.read_bytes() == OLD  # the recording goes elsewhere meanwhile
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=_WAIT)
        assert process.returncode == 0, err
        assert "Traceback" not in err and "(interrupted)" in err
        sim.stop()
        entries = sim.entries()
    rows = decoded(keep)
    assert [r["raw"] for r in rows if r["direction"] == "in"] == written_intact(entries)
    assert leftovers(tmp_path, "keep.pcapng") == []
    assert (keep.stat().st_mode & 0o777) == 0o666 & ~_umask()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


# --- Losing the device, SIGTERM ------------------------------------------------------------------------


@pytest.mark.parametrize("line", ["pty", "tcp"])
def test_losing_the_device_keeps_the_capture_and_says_so(tmp_path: Path, line: str) -> None:
    capture = tmp_path / "lost.pcapng"
    capture.write_bytes(OLD)
    with simulator(tmp_path, *(["--tcp", "127.0.0.1:0"] if line == "tcp" else [])) as sim:
        port = sim.port if line == "pty" or sim.port.startswith("socket://") else f"socket://{sim.port}"
        process = start_recording(port, capture, "--start", "AHRScont3")
        wait_until(lambda: outputs_sent(sim) >= 20, "output")
        sim.process.kill()
        sim.process.wait(_WAIT)
        _, err = process.communicate(timeout=_WAIT)
        entries = sim.entries()
    assert process.returncode == 2, err
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 2, err
    assert summary_of(lines[0]) == decode_counts(capture)
    assert "the device was lost" in lines[1] and port in lines[1]
    rows = decoded(capture)
    inbound = [r["raw"] for r in rows if r["direction"] == "in"]
    assert len(inbound) >= 20 and inbound == written_intact(entries)[: len(inbound)]
    assert leftovers(tmp_path, "lost.pcapng") == []


def test_sigterm_stops_the_device_keeps_the_capture_and_counts_it(tmp_path: Path) -> None:
    capture = tmp_path / "terminated.pcapng"
    with simulator(tmp_path) as sim:
        process = start_recording(sim.port, capture, "--start", "AHRScont3")
        wait_until(lambda: outputs_sent(sim) >= 20, "output")
        process.send_signal(signal.SIGTERM)
        _, err = process.communicate(timeout=_WAIT)
        assert process.returncode == 2, err
        assert "Traceback" not in err
        lines = err.strip().splitlines()
        assert len(lines) == 1 and lines[0].endswith("(terminated)"), err
        assert_stopped(sim)
        sim.stop()
        entries = sim.entries()
    rows = decoded(capture)
    assert [r["kind"] for r in rows if r["direction"] == "out"][-1] == "Stop"
    assert [r["raw"] for r in rows if r["direction"] == "in"] == written_intact(entries)
    assert summary_of(lines[0]) == decode_counts(capture)


def test_the_summary_counts_every_message_of_a_long_recording(tmp_path: Path) -> None:
    capture = tmp_path / "long.pcapng"
    with simulator(tmp_path, "--update-rate", "100") as sim:
        result = ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--count", "1100")
        sim.stop()
        entries = sim.entries()
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    messages, discarded, errors = summary_of(result.stderr.strip())
    assert messages > 1100
    assert (messages, discarded, errors) == decode_counts(capture)
    assert [r["raw"] for r in decoded(capture) if r["direction"] == "in"] == written_intact(entries)


# --- Several commands, one process on a port --------------------------------------------------------


def test_send_records_a_conversation_and_a_second_process_is_refused(tmp_path: Path) -> None:
    capture = tmp_path / "session.pcapng"
    with simulator(tmp_path) as sim:
        process = start_recording(
            sim.port, capture, "--send", "GetBIT", "--send", "LoadAHRSPar update_rate=20", "--start", "AHRScont3"
        )
        wait_until(lambda: outputs_sent(sim) >= 10, "output")
        intruder = ilahrs("send", sim.port, "GetBIT")
        line = one_line(intruder, "in use by another process")
        assert line == f"ilahrs send: {sim.port} is in use by another process"
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=_WAIT)
        assert process.returncode == 0, err
        sim.stop()
        entries = sim.entries()
    rows = decoded(capture)
    assert [r["raw"] for r in rows if r["direction"] == "in"] == written_intact(entries)  # nothing taken away
    kinds = [str(r["kind"]) for r in rows]
    (read_table,) = COMMANDS[READ_PARAMETERS].response_payloads
    load_table = str(COMMANDS[LOAD_PARAMETERS].parameter_block)
    # Stop and the probe, then each --send in order (LoadAHRSPar after reading what it keeps), then --start.
    expected = ["Stop", "GetVerFirmware", "firmware_version", "GetBIT", "bit_result", READ_PARAMETERS, read_table]
    assert kinds[: len(expected)] == expected
    assert kinds[len(expected) : len(expected) + 3] == [LOAD_PARAMETERS, load_table, "acknowledgement"]
    assert kinds[len(expected) + 3 : len(expected) + 6] == ["AHRScont3", "acknowledgement", "initial_alignment"]
    read = next(r["fields"] for r in rows if r["kind"] == read_table)
    load = next(r["fields"] for r in rows if r["kind"] == load_table)
    assert isinstance(read, dict) and isinstance(load, dict)
    assert load["update_rate"] == 20
    assert {k: v for k, v in load.items() if k != "update_rate"} == {k: read[k] for k in load if k != "update_rate"}
    assert read["alignment_time"] == 1  # the simulator's, not the table's default: kept from the device
    assert summary_of(err.strip()) == decode_counts(capture)


def test_send_arguments_are_checked_before_the_port_is_opened(tmp_path: Path) -> None:
    keep = tmp_path / "keep.pcapng"
    keep.write_bytes(OLD)
    port = "/dev/ilahrs-no-such-port"
    one_line(ilahrs("record", port, "-o", str(keep), "--send", "GetBTI"), "did you mean GetBIT")
    one_line(ilahrs("record", port, "-o", str(keep), "--send", "GetBIT x=1"), "no parameter block")
    one_line(ilahrs("record", port, "-o", str(keep), "--send", "LoadAHRSPar update_rat=20"), "update_rate")
    assert keep.read_bytes() == OLD
    help_text = ilahrs("record", "--help").stdout
    assert '--send "LoadAHRSPar update_rate=' in help_text and "--send GetBIT" in help_text


# --- --duration and --count ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("option", "value"),
    [("--duration", v) for v in ("-3", "0", "nan", "inf", "x")]
    + [
        ("--count", "0"),
        ("--count", "-1"),
    ],
)
def test_non_positive_duration_and_count_are_refused(tmp_path: Path, option: str, value: str) -> None:
    keep = tmp_path / "keep.pcapng"
    keep.write_bytes(OLD)
    one_line(ilahrs("record", "/dev/ilahrs-no-such-port", "-o", str(keep), option, value), option)
    assert keep.read_bytes() == OLD


def test_duration_counts_from_the_end_of_the_initial_alignment(tmp_path: Path) -> None:
    help_text = " ".join(ilahrs("record", "--help").stdout.split())
    assert "record S seconds after the --send commands and the --start output's initial alignment" in help_text
    capture = tmp_path / "timed.pcapng"
    with simulator(tmp_path, "--alignment-time", "2") as sim:
        result = ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--duration", "1.5")
    assert result.returncode == 0, result.stderr
    rows = decoded(capture)
    aligned = next(float(str(r["time"])) for r in rows if r["kind"] == "initial_alignment")
    started = next(float(str(r["time"])) for r in rows if r["kind"] == "AHRScont3")
    last = max(float(str(r["time"])) for r in rows if r["kind"] == "orientation_sensors")
    assert aligned - started >= 1.9  # the alignment is not counted ...
    assert last - aligned >= 1.4  # ... the 1.5 s come after it (less one output period)


def test_each_packet_is_a_chunk_as_it_crossed_the_line(tmp_path: Path) -> None:
    """A packet per read, never the first byte of a message in a packet of its own: with the
    simulator writing each message whole, every inbound packet holds whole messages."""
    from ilahrs.pcapng import Direction, read

    capture = tmp_path / "s.pcapng"
    with simulator(tmp_path) as sim:
        result = ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--count", "50")
        assert result.returncode == 0, result.stderr
    with capture.open("rb") as stream:
        inbound = [p.data for p in read(stream).packets if p.direction == Direction.INBOUND]
    assert len(inbound) >= 50 and min(len(p) for p in inbound) > 1
    decoder = StreamDecoder()
    for packet in inbound:
        messages = decoder.feed(packet)
        assert messages and decoder.pending == 0, packet.hex()
