"""`ilahrs decode CAPTURE.pcapng --to csv` decodes the device's continuous output as columns
(ColumnarCapture): the rows and the summary must be those of the message-by-message path
(CaptureDecoder + RowWriter), byte for byte, on clean and damaged two-direction captures."""

from __future__ import annotations

import io
import random
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from test_decode_captures import ANSWER_US, Line, flipped, on_request

import ilahrs
from ilahrs.cli import columnar_capture
from ilahrs.cli.capture import Chunk, open_source
from ilahrs.cli.decode import CaptureDecoder, ColumnarCapture, ColumnarCsv, RowWriter, kinds, summary
from ilahrs.pcapng import Direction
from ilahrs.statemachine import DEFAULT_ALIGNMENT_TIME_S

pytest.importorskip("numpy")
VARIANT = ilahrs.VARIANTS["AHRS-10"] if "AHRS-10" in ilahrs.VARIANTS else next(iter(ilahrs.VARIANTS.values()))


def message_csv(path: Path, selected: list[str], *, raw: bool = False, **options: object) -> tuple[str, list[str]]:
    out = io.StringIO()
    decoder = CaptureDecoder(context=True, **options)  # type: ignore[arg-type]
    writer = RowWriter(out, "csv", selected, VARIANT, raw=raw)
    wanted = set(selected)
    for chunk in open_source(str(path)).chunks():
        for m in decoder.feed(chunk):
            if m.kind in wanted:
                writer.write(m)
    for m in decoder.finish():
        if m.kind in wanted:
            writer.write(m)
    return out.getvalue(), summary(decoder, "ilahrs decode")


def columnar_csv(
    path: Path, selected: list[str], *, packets: bool = False, raw: bool = False, **options: object
) -> tuple[str, list[str]]:
    """The rows and summary of ColumnarCapture fed the capture's chunks (`feed`), or its packets as
    arrays (`Source.packets`, `feed_packets`: what `ilahrs decode CAPTURE.pcapng` does)."""
    out = io.StringIO()
    decoder = ColumnarCapture(out, selected, VARIANT, raw=raw, **options)  # type: ignore[arg-type]
    source = open_source(str(path))
    if packets:
        for found in source.packets():
            decoder.feed_packets(found)
    else:
        for chunk in source.chunks():
            decoder.feed(chunk)
    decoder.finish()
    return out.getvalue(), summary(decoder, "ilahrs decode")


def stream(line: Line, seconds: float, damage: Callable[[int, bytes], bytes] | None = None) -> None:
    """Record the device's output for `seconds`, a packet every 10 ms (split across two packets
    now and then), each changed by `damage(i, data)`."""
    rng = random.Random(7)
    for i in range(round(seconds / 0.01)):
        data = line.wait(0.01)
        if damage is not None:
            data = damage(i, data)
        if data and rng.random() < 0.1:
            cut = rng.randrange(len(data))
            line.inbound(data[:cut], after=0)
            line.inbound(data[cut:], after=0.001)
        else:
            line.inbound(data, after=0)


def continuous(damage: Callable[[int, bytes], bytes] | None = None, command: str = "AHRScont1") -> Line:
    line = Line()
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.inbound(line.send(ilahrs.build_command(command)))
    stream(line, DEFAULT_ALIGNMENT_TIME_S + 3, damage)
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.inbound(line.send(ilahrs.build_command("ReadAHRSPar")))
    line.inbound(line.send(ilahrs.build_command(command)))
    stream(line, DEFAULT_ALIGNMENT_TIME_S + 2, damage)
    line.inbound(line.send(ilahrs.build_command("Stop")))
    return line


def bad_checksum(i: int, data: bytes) -> bytes:
    return flipped(data) if i % 97 == 5 and len(data) > 12 else data


def truncated(i: int, data: bytes) -> bytes:
    return data[:20] if i % 89 == 7 else data


def garbage(i: int, data: bytes) -> bytes:
    return b"\x01\xaa\x55\x02" + data if i % 83 == 3 else data


def lost(i: int, data: bytes) -> bytes:
    return b"" if 3000 < i < 3200 else data  # 2 s without output: a missing output block


def all_damage(i: int, data: bytes) -> bytes:
    return lost(i, garbage(i, truncated(i, bad_checksum(i, data))))


CAPTURES: dict[str, Callable[[], Line]] = {
    "clean": continuous,
    "sentences": lambda: continuous(command="NMEAcont"),
    "bad_checksum": lambda: continuous(bad_checksum),
    "truncated": lambda: continuous(truncated),
    "garbage": lambda: continuous(garbage),
    "lost": lambda: continuous(lost),
    "all_damage": lambda: continuous(all_damage),
}


def retry() -> Line:
    line = Line()
    on_request(line)
    answer = line.send(ilahrs.build_command("GetDataReq"))
    line.inbound(flipped(answer))
    line.wait(1.0 - ANSWER_US / 1e6)
    line.inbound(line.send(ilahrs.build_command("GetDataReq")))
    line.inbound(line.send(ilahrs.build_command("AHRScont1")))
    stream(line, DEFAULT_ALIGNMENT_TIME_S + 2)
    return line


CAPTURES["retry"] = retry


@pytest.mark.parametrize("packets", [False, True], ids=["chunks", "packets"])
@pytest.mark.parametrize("strict", [False, True], ids=["lenient", "strict"])
@pytest.mark.parametrize("stretch", [1 << 20, 700], ids=["1MiB", "700B"])
@pytest.mark.parametrize("name", list(CAPTURES))
def test_columns_give_the_rows_and_summary_of_the_messages(
    name: str, stretch: int, strict: bool, *, packets: bool, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(columnar_capture, "_STRETCH", stretch)
    path = CAPTURES[name]().save(tmp_path / f"{name}.pcapng")
    for selected in (kinds(), ["full_output", "damaged", "Stop"]):
        expected = message_csv(path, selected, strict=strict)
        got = columnar_csv(path, selected, strict=strict, packets=packets)
        assert got[0].count("\n") > (10 if selected == kinds() else 2)
        assert got == expected


def test_a_capture_begun_mid_stream_with_output_format(tmp_path: Path) -> None:
    line = Line()
    line.device.receive(ilahrs.build_command("AHRScont1"))
    line.wait(DEFAULT_ALIGNMENT_TIME_S + 0.5)
    stream(line, 3.0, all_damage)
    line.inbound(line.send(ilahrs.build_command("Stop")))
    path = line.save(tmp_path / "mid.pcapng")
    options: dict[str, Any] = {"output": "full_output", "output_known": True, "start": "AHRScont1"}
    expected = message_csv(path, kinds(), **options)
    assert expected[0].count("full_output") > 200
    assert columnar_csv(path, kinds(), **options) == expected
    result = subprocess.run(
        [sys.executable, "-m", "ilahrs", "decode", str(path), "--to", "csv", "--output-format", "AHRScont1"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert (result.stdout, result.stderr.splitlines()) == expected


def test_continuous_output_goes_the_columnar_way(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = continuous().save(tmp_path / "clean.pcapng")
    calls: list[int] = []
    original = ColumnarCapture._rows

    def counted(self: ColumnarCapture, *args: object, **options: object) -> None:
        calls.append(1)
        original(self, *args, **options)  # type: ignore[arg-type]

    monkeypatch.setattr(ColumnarCapture, "_rows", counted)
    text, _ = columnar_csv(path, kinds())
    assert calls and text.count("full_output") >= 500


@pytest.mark.parametrize("command", ["AHRScont2", "AHRScont3"])
def test_the_other_output_tables_raw_or_not(command: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Quaternion and orientation_sensors output (whose rates and accelerations are scaled by the
    variant), in engineering units and with --raw (every field as sent, those too), damaged."""
    monkeypatch.setattr(columnar_capture, "_STRETCH", 700)
    line = Line()
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.inbound(line.send(ilahrs.build_command(command)))
    stream(line, DEFAULT_ALIGNMENT_TIME_S + 4, all_damage)  # 2 s lost, then 2 s of output
    line.inbound(line.send(ilahrs.build_command("Stop")))
    path = line.save(tmp_path / "other.pcapng")
    table = ilahrs.COMMANDS[command].starts_output
    for raw in (False, True):
        expected = message_csv(path, kinds(), raw=raw)
        assert expected[0].count(f",{table},") > 150
        assert columnar_csv(path, kinds(), packets=True, raw=raw) == expected


def test_a_raw_dump_with_raw_values_as_columns() -> None:
    """A raw dump of orientation_sensors output to CSV with --raw (ColumnarCsv): the rates and
    accelerations as sent, as message by message."""
    device = ilahrs.Device(seed=1)
    device.receive(ilahrs.build_command("AHRScont3"))
    device.advance(DEFAULT_ALIGNMENT_TIME_S)
    data = b"".join(device.advance(0.01) for _ in range(300))
    rows = []
    for columns in (False, True):
        out = io.StringIO()
        if columns:
            decoder = ColumnarCsv(out, kinds(), VARIANT, raw=True, output="orientation_sensors")
            decoder.feed(data)
            decoder.finish()
        else:
            messages = CaptureDecoder(context=False, output="orientation_sensors", output_known=True)
            writer = RowWriter(out, "csv", kinds(), VARIANT, raw=True)
            for m in [*messages.feed(Chunk(None, Direction.INBOUND, data)), *messages.finish()]:
                writer.write(m)
        rows.append(out.getvalue())
    assert rows[0].count("orientation_sensors") == 300
    assert rows[1] == rows[0]


def test_times_as_columns_read_as_row_writer_writes_them() -> None:
    """`_stamps`, the time column of a stretch, gives RowWriter's f"{round(t, 6):.6f}" for halves
    of a millionth held exactly (round half to even), float steps near a millionth, and times too
    large for "%.6f" of the value alone."""
    numpy = pytest.importorskip("numpy")
    rng = random.Random(3)
    times = [0.0, 0.0078125, 0.0000005, 1.5e-6, 2.5e-6, 2.0**32 - 1e-6, 2.0**32, 3e9 + 0.4999995, 1e12 + 0.0000015]
    times += [rng.uniform(0, 1e5) for _ in range(200)] + [rng.randrange(10**12) / 1e6 for _ in range(200)]
    for values in (times, times[:1], times[:2]):
        expected = [f"{round(t, 6):.6f}" for t in values]
        assert columnar_capture._stamps(numpy, numpy.array(values)) == expected
