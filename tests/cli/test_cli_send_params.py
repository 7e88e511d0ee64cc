"""`ilahrs send`, `params` and `calibrate` as a user runs them, against `ilahrs simulate` on a
pseudo-terminal driven into each state first: the answer of every command in every state that
answers it, the device's state never assumed; parameters compared and printed as the table
encodes them (float32, the date encoding); parameter blocks never silently defaulted; failed
calibrations, --baud, a closed pipe and --help. The sans-I/O part (`ilahrs.session.anystate`) against
the device model."""

from __future__ import annotations

import doctest
import os
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from device_support import Pair
from simulators import ILAHRS, Simulator, ilahrs
from test_cli import decoded, simulator

import ilahrs as package
from ilahrs.cli.decode import kinds
from ilahrs.codec import date_from_text, field_text, float32_text
from ilahrs.edge.serial import AhrsClient
from ilahrs.errors import IlahrsError
from ilahrs.payloads import PAYLOADS
from ilahrs.roles import LOAD_PARAMETERS
from ilahrs.session import anystate
from ilahrs.session.anystate import AnyStateRequest, Reply
from ilahrs.session.host import Acknowledged, DataBlock, Output
from ilahrs.statemachine import TIMER_FIELDS

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys are POSIX")

LOAD = PAYLOADS[package.COMMANDS[LOAD_PARAMETERS].parameter_block or ""]
RUN_OF_TWO = {"accumulation_time": 60}  # long enough for a StopClbRun to come while accumulating


def one_line(result: subprocess.CompletedProcess[str], *words: str, status: int = 2) -> str:
    assert result.returncode == status, (result.stdout, result.stderr)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    for word in words:
        assert word in lines[0], lines[0]
    return lines[0]


def answer(result: subprocess.CompletedProcess[str]) -> str:
    assert result.returncode == 0, (result.stdout, result.stderr)
    assert "Traceback" not in result.stderr
    return result.stdout.strip()


def wait_for_state(sim: Simulator, state: str, timeout: float = 20.0) -> None:
    """Until the simulator's log shows it sending in `state` (the alignment block of a run)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if any(e.get("state") == state for e in sim.entries()):
            return
        time.sleep(0.05)
    pytest.fail(f"the simulator never reached {state}")


def with_client(sim: Simulator, action: Callable[[AhrsClient], object]) -> None:
    """Drive the device with the serial client, then let it go (no Stop)."""
    client = AhrsClient(sim.port)
    try:
        client.stop()
        action(client)
    finally:
        client.close()


# --- send: the answer of each command not valid in idle, from the state where it is answered ---------


def test_get_data_is_answered_in_on_request_mode(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        with_client(sim, lambda c: c.start("NMEAreq"))
        assert answer(ilahrs("send", sim.port, "GetDataReq")).startswith("PAHR roll=")
        with_client(sim, lambda c: c.start("AHRSreq2"))
        decoded_block = answer(ilahrs("send", sim.port, "GetDataReq", "--output-format", "AHRSreq2"))
        assert decoded_block.startswith("quaternion heading=")
        # Without the format, the block (the size of every binary format) prints raw, never guessed (E7).
        guessed = ilahrs("send", sim.port, "GetDataReq")
        assert answer(guessed).startswith("output raw=aa55")
        assert "--output-format" in guessed.stderr


def test_a_2d2t_calibration_by_send(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        with_client(sim, lambda c: c.request("Start2D2TClb", RUN_OF_TWO))
        assert answer(ilahrs("send", sim.port, "StartClbRun")).startswith("acknowledged calibration_run_parameters")
        wait_for_state(sim, "run_accumulating")
        stopped = answer(ilahrs("send", sim.port, "StopClbRun"))
        assert stopped.startswith("calibration_run_result calibration_type=2 run=1")
        finished = answer(ilahrs("send", sim.port, "FinishClb"))
        assert finished.startswith("calibration_result calibration_type=2")
        assert answer(ilahrs("send", sim.port, "AcceptClb")).startswith("acknowledged AcceptClb")
        assert "bit_result" in answer(ilahrs("send", sim.port, "GetBIT"))  # idle again


def test_stop_run_in_a_single_run_calibration(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        with_client(sim, lambda c: c.request("Start3DClb", RUN_OF_TWO))
        wait_for_state(sim, "calibration_accumulating")
        assert answer(ilahrs("send", sim.port, "StopClbRun")).startswith("calibration_result calibration_type=3")
        assert answer(ilahrs("send", sim.port, "ExitClb")).startswith("acknowledged ExitClb")


def test_low_power_off_wakes_the_device(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        with_client(sim, lambda c: c.low_power(True))
        one_line(ilahrs("send", sim.port, "GetBIT"), "ignores GetBIT in its state")  # asleep
        woke = answer(ilahrs("send", sim.port, "LowPowerOff"))
        assert woke == "LowPowerOff: sent; no answer came (none is due in sleep; any other state ignores it)"
        assert "bit_result" in answer(ilahrs("send", sim.port, "GetBIT"))


@pytest.mark.parametrize("command", ["GetDataReq", "StartClbRun", "StopClbRun", "FinishClb", "AcceptClb"])
def test_a_command_idle_ignores_is_one_line_and_status_2(tmp_path: Path, command: str) -> None:
    with simulator(tmp_path) as sim:
        line = one_line(ilahrs("send", sim.port, command), f"no answer: the device ignores {command} in its state")
        assert "(the command has no answer)" not in line
        assert "bit_result" in answer(ilahrs("send", sim.port, "GetBIT"))  # still idle, still there


def test_low_power_off_in_idle_says_what_it_cannot_know(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        said = answer(ilahrs("send", sim.port, "LowPowerOff"))
        assert "none is due in sleep" in said and "ignores" in said


def test_a_command_of_idle_while_streaming_is_sent_again_after_stop(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        with_client(sim, lambda c: c.start("AHRScont3"))
        result = ilahrs("send", sim.port, "GetBIT")
        assert answer(result).startswith("bit_result")
        assert "sent Stop and GetBIT again" in result.stderr


def test_a_silent_device_gets_one_line_without_a_repeated_prefix(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        with_client(sim, lambda c: c.low_power(True))
        line = one_line(ilahrs("send", sim.port, "GetBIT"), "GetBIT", "--baud")
        assert "GetBIT: GetBIT" not in line


def test_the_probe_failure_points_at_the_baud_rate() -> None:
    master, slave = os.openpty()
    try:
        one_line(ilahrs("params", os.ttyname(slave)), "no answer", "--baud")
    finally:
        os.close(master)
        os.close(slave)


# --- send: parameter blocks are never silently defaulted -------------------------------------------


def test_a_partial_parameter_block_is_refused(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        line = one_line(ilahrs("send", sim.port, "LoadAHRSPar", "update_rate=20"), "alignment_time", "--defaults")
        assert "ilahrs params PORT set update_rate=20" in line
        assert "alignment_time = 1" in answer(ilahrs("params", sim.port))  # nothing was sent
        whole = ilahrs("params", sim.port).stdout.replace(" = ", "=").split("\n")
        fields = [kv for kv in whole if kv.split("=")[0] in {f.name for f in LOAD.FIELDS}]
        fields = [kv.replace("update_rate=100", "update_rate=20") for kv in fields]
        assert answer(ilahrs("send", sim.port, "LoadAHRSPar", *fields)).startswith("acknowledged ahrs_parameters_load")
        shown = answer(ilahrs("params", sim.port))
        assert "update_rate = 20" in shown and "alignment_time = 1" in shown
        defaults = ilahrs("send", sim.port, "LoadAHRSPar", "update_rate=50", "--defaults")
        assert answer(defaults).startswith("acknowledged ahrs_parameters_load")
        assert "alignment_time = 30" in answer(ilahrs("params", sim.port))


# --- params: values as the table encodes them ---------------------------------------------------------


def test_params_takes_float32_values_and_dates(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        result = ilahrs("params", sim.port, "set", "declination=3.3", "longitude=-73.6", "date=2024-06-15")
        shown = answer(result)
        for line in ("declination = 3.3", "longitude = -73.6", "date = 2024-06-15"):
            assert line in shown.splitlines(), shown
        assert "date = 2024-06-15" in answer(ilahrs("params", sim.port))
        raw = str(date_from_text("2020-01-01"))
        assert "date = 2020-01-01" in answer(ilahrs("params", sim.port, "set", f"date={raw}"))
        one_line(ilahrs("params", sim.port, "set", "date=2024-13-01"), "date")


def test_float32_and_date_text() -> None:
    date = next(f for f in LOAD.FIELDS if f.encoding == "date")
    near = LOAD.parse(LOAD.from_raw({"declination": 3.3}).build()).raw()["declination"]
    assert isinstance(near, float)
    assert near != 3.3 and float32_text(near) == "3.3"
    assert float32_text(50.0) == "50.0" and float32_text(1e-5) == "1e-05"
    assert field_text(date, 2014.19677734375) == "2014-03-11"
    wire = LOAD.parse(LOAD.from_raw({"date": date_from_text("2024-06-15")}).build()).raw()["date"]
    assert field_text(date, wire) == "2024-06-15"
    with pytest.raises(IlahrsError):
        date_from_text("15/06/2024")


# --- calibrate ------------------------------------------------------------------------------------


def test_calibrate_uses_the_stored_place_and_the_options(tmp_path: Path) -> None:
    capture = tmp_path / "calibration.pcapng"
    with simulator(tmp_path, "--record", str(capture)) as sim:
        answer(ilahrs("params", sim.port, "set", "latitude=45.5", "altitude=120", "date=2024-06-15"))
        result = ilahrs("calibrate", sim.port, "2d", "--accumulation", "2", "--yes", "--longitude", "-73.6")
        assert "accepted" in answer(result)
        dated = ilahrs("calibrate", sim.port, "2d", "--accumulation", "2", "--no", "--date", "2025-01-31")
        assert "discarded" in answer(dated)
    sent = [r["fields"] for r in decoded(capture) if r["kind"] == "calibration_parameters"]
    assert len(sent) == 2
    first, second = sent
    assert isinstance(first, dict) and isinstance(second, dict)
    assert (first["latitude"], first["longitude"], first["altitude"]) == (45.5, pytest.approx(-73.6), 120.0)
    assert first["accumulation_time"] == 2
    date = next(f for f in LOAD.FIELDS if f.encoding == "date")
    assert field_text(date, first["date"]) == "2024-06-15"
    assert field_text(date, second["date"]) == "2025-01-31" and second["longitude"] == 0.0


def test_a_failed_calibration_is_status_2_after_the_result(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        result = ilahrs("calibrate", sim.port, "2d2t", "--runs", "1", "--accumulation", "1", "--yes")
        one_line(result, "calibration failed")
        assert "-> failed" in result.stdout and "discarded" in result.stdout and "accepted" not in result.stdout
        status = answer(ilahrs("send", sim.port, "GetClbRes"))
        assert "calibration_type=0" in status  # nothing was saved


def test_2d2t_says_which_tilt(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        result = ilahrs("calibrate", sim.port, "2d2t", "--accumulation", "2", "--yes")
        shown = answer(result)
    assert "first pitch angle" in shown and "next pitch angle" in shown and "tilted as for this run" not in shown


def test_calibrate_options_are_checked_before_the_port() -> None:
    one_line(ilahrs("calibrate", "/dev/ilahrs-no-such-port", "2d", "--latitude", "91"), "latitude: 91.0 outside")
    one_line(ilahrs("calibrate", "/dev/ilahrs-no-such-port", "2d", "--date", "2024-02-30"), "--date")
    one_line(ilahrs("calibrate", "/dev/ilahrs-no-such-port", "2d", "--accumulation", "0"), "accumulation_time")


# --- every subcommand: --baud, a closed pipe, --help ---------------------------------------------------


@pytest.mark.parametrize("subcommand", ["record", "send", "params", "monitor", "calibrate"])
@pytest.mark.parametrize("baud", ["-5", "0", "fast"])
def test_baud_must_be_a_positive_integer(tmp_path: Path, subcommand: str, baud: str) -> None:
    extra = {"record": ["-o", str(tmp_path / "x.pcapng")], "send": ["GetBIT"], "calibrate": ["2d"]}.get(subcommand, [])
    one_line(ilahrs(subcommand, "/dev/ilahrs-no-such-port", *extra, "--baud", baud), "--baud", "positive integer")


def test_a_closed_pipe_is_one_line_not_a_traceback(tmp_path: Path) -> None:
    with simulator(tmp_path) as sim:
        shell = subprocess.run(
            ["bash", "-c", 'set -o pipefail; "$@" | head -1', "-", *ILAHRS, "params", sim.port],
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )
        assert shell.stdout.startswith("update_rate = ") and len(shell.stdout.splitlines()) == 1
        assert "Traceback" not in shell.stderr and "Exception" not in shell.stderr, shell.stderr
        read, write = os.pipe()
        os.close(read)  # the reader is gone before the first byte: every write fails
        try:
            closed = subprocess.run(
                [*ILAHRS, "params", sim.port], stdout=write, stderr=subprocess.PIPE, text=True, timeout=60, check=False
            )
        finally:
            os.close(write)
    assert closed.returncode == 2, closed.stderr
    lines = closed.stderr.strip().splitlines()
    assert len(lines) == 1 and "standard output closed" in lines[0], closed.stderr


def _help(*args: str) -> str:
    result = ilahrs(*args, "--help")
    assert result.returncode == 0, result.stderr
    return " ".join(result.stdout.split())


def test_help_lists_the_names_and_defaults() -> None:
    send = _help("send")
    assert all(f"{name}," in send or f"{name}." in send for name in package.COMMANDS)
    assert f"{LOAD_PARAMETERS}: update_rate" in send and "--defaults" in send
    params = _help("params")
    assert all(f.name in params for f in LOAD.FIELDS if f.type != "reserved")
    decode = _help("decode")
    assert all(kind in decode for kind in kinds())
    calibrate = _help("calibrate")
    table, name = TIMER_FIELDS["accumulation"]
    span = next(f for f in PAYLOADS[table].FIELDS if f.name == name)
    assert f"{span.low:g}..{span.high:g}" in calibrate and "(default 60)" in calibrate
    assert "--latitude" in calibrate and "--date YYYY-MM-DD" in calibrate and "(default 2)" in calibrate
    variant = next(iter(package.VARIANTS))
    for text in (send, params, calibrate):
        assert "(default 115200)" in text and f"default {variant})" in text


# --- the sans-I/O part -----------------------------------------------------------------------------------


def _ask(pair: Pair, command: str, block: object = None, output: str | None = None) -> Reply:
    request = AnyStateRequest(command, block, output=output)  # type: ignore[arg-type]
    request.receive(pair.device.receive(request.data))
    for _ in range(300):
        if request.done:
            break
        request.advance(0.01)
        request.receive(pair.device.advance(0.01))
    assert request.done
    return request.reply()


def test_anystate_doctest() -> None:
    assert doctest.testmod(anystate).failed == 0


def test_anystate_finds_the_state_from_the_answers() -> None:
    pair = Pair()
    assert _ask(pair, "GetDataReq").state is None
    pair.send("NMEAreq")
    pair.wait(1.5)
    reply = _ask(pair, "GetDataReq")
    assert reply.state == "on_request" and isinstance(reply.answers[0], Output)
    reply = _ask(pair, "GetBIT")
    assert reply.state == "idle" and isinstance(reply.answers[0], DataBlock)  # idle first: both fit
    pair = Pair()
    assert _ask(pair, "FinishClb").state is None and _ask(pair, "StartClbRun", {}).state is None
    pair.send("Start2D2TClb", PAYLOADS["calibration_parameters"].from_raw(RUN_OF_TWO))
    reply = _ask(pair, "StartClbRun", {})
    assert reply.state == "runs_ready" and isinstance(reply.answers[0], Acknowledged)
    assert reply.host is not None and reply.host.state == "run_aligning"
    pair.wait(1.5)
    assert _ask(pair, "StopClbRun").state == "run_accumulating"
    reply = _ask(pair, "FinishClb")
    assert reply.state == "runs_ready" and isinstance(reply.answers[0], DataBlock)
    assert _ask(pair, "AcceptClb").state == "calibration_deciding"
    silent = _ask(pair, "LowPowerOff")
    assert silent.state == "sleep" and silent.answers == () and silent.silent == ("sleep",)


def test_every_subcommand_shows_a_value_the_same_way() -> None:
    """One rule for each kind of value, whichever subcommand prints it: a clear status word reads
    OK (never an empty cell), a date its calendar date, in `send`/`params`/`monitor` rows as in
    `decode` rows."""
    from ilahrs.cli.common import USW_CLEAR, fields_of, variant_named
    from ilahrs.cli.decode import row_fields

    variant = variant_named(None)
    bit = package.BitResult(usw=0)
    assert fields_of(bit, variant)["usw"] == row_fields(bit, variant)["usw"] == USW_CLEAR == "OK"
    read = PAYLOADS["ahrs_parameters_read"].from_raw({"date": date_from_text("2024-06-15")})
    date = next(info for info in read.FIELDS if info.name == "date")
    assert row_fields(read, variant)["date"] == field_text(date, read.raw()["date"]) == "2024-06-15"


@pytest.mark.parametrize("to", ["text", "csv"])
def test_decode_into_a_closed_pipe_is_the_same_one_line(tmp_path: Path, to: str) -> None:
    """decode (message by message and columnar) ends a closed pipe as every subcommand does."""
    capture = tmp_path / "s.pcapng"
    with simulator(tmp_path) as sim:
        recorded = ilahrs("record", sim.port, "-o", str(capture), "--start", "AHRScont3", "--count", "300")
        assert recorded.returncode == 0, recorded.stderr
    read, write = os.pipe()
    os.close(read)
    try:
        closed = subprocess.run(
            [*ILAHRS, "decode", str(capture), "--to", to],
            stdout=write,
            stderr=subprocess.PIPE,
            text=True,
            timeout=60,
            check=False,
        )
    finally:
        os.close(write)
    assert closed.returncode == 2, closed.stderr
    assert closed.stderr.strip().splitlines() == ["ilahrs: decode: standard output closed"]
