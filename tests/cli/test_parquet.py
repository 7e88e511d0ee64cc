"""`ilahrs decode CAPTURE... --to parquet DIR`: a Parquet dataset, a folder per message kind, of
two captures in two folders (a two-direction pcapng with damage and a raw dump with $PAHR
sentences and calibration blocks, both named run.*): read back with DuckDB and pandas, it holds
the rows of `decode --to csv` of each capture, value for value; its columns carry their unit and
ICD table; `--jobs 2` writes the same files as `--jobs 1`; folders are searched and what is no
capture is skipped; Ctrl-C leaves nothing behind."""

from __future__ import annotations

import argparse
import csv
import io
import math
import os
import struct
from collections.abc import Iterator
from contextlib import redirect_stderr
from pathlib import Path
from typing import Any

import pytest
from test_decode_captures import Line
from test_decode_columns_capture import bad_checksum, stream

import ilahrs
from ilahrs.cli import main, to_parquet
from ilahrs.cli.dataset import part_name
from ilahrs.statemachine import DEFAULT_ALIGNMENT_TIME_S

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")
duckdb = pytest.importorskip("duckdb")
pandas = pytest.importorskip("pandas")
pytest.importorskip("numpy")

START_US = 1_700_000_000_000_000
"""The first timestamp of the pcapng capture (test_decode_captures.Line's)."""


def two_way() -> bytes:
    """Stop, AHRScont1, the output through the alignment and a second more (a bad checksum now
    and then), Stop: commands, answers, output and damage."""
    line = Line()
    line.inbound(line.send(ilahrs.build_command("Stop")))
    line.inbound(line.send(ilahrs.build_command("AHRScont1")))
    stream(line, DEFAULT_ALIGNMENT_TIME_S + 1, bad_checksum)
    line.inbound(line.send(ilahrs.build_command("Stop")))
    return line.file.getvalue()


def raw_dump() -> bytes:
    """$PAHR sentences, calibration run results (text outcome and an accuracy column), bytes that
    start nothing, a full_output frame."""
    sentences = [ilahrs.PahrSentence(roll=r, pitch=-r, heading=3599 * r, usw=r).build().encode() for r in (1, 2, 3)]
    results = [
        ilahrs.CalibrationRunResult(success=s, average_pitch=p).build() for s, p in ((0, -1.5), (12, 0), (255, 2))
    ]
    at = next(f.offset for f in ilahrs.CalibrationRunResult.FIELDS if f.name == "average_pitch")
    results[1] = results[1][:at] + struct.pack("<f", math.nan) + results[1][at + 4 :]  # a builder refuses it
    frames = [ilahrs.Frame(ilahrs.MessageType.DATA, block).build() for block in results]
    full = ilahrs.Frame(ilahrs.MessageType.DATA, ilahrs.FullOutput(heading=12345, pitch=-77).build()).build()
    return b"".join(sentences) + b"".join(frames) + b"\x01\x02\x03" + full


@pytest.fixture(scope="module")
def captures(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """in/a/run.pcapng, in/b/run.bin, in/b/notes.txt (no capture), in/b/.hidden (left out)."""
    top = tmp_path_factory.mktemp("captures")
    (top / "in" / "a").mkdir(parents=True)
    (top / "in" / "b").mkdir()
    (top / "in" / "a" / "run.pcapng").write_bytes(two_way())
    (top / "in" / "b" / "run.bin").write_bytes(raw_dump())
    (top / "in" / "b" / "notes.txt").write_text("no capture here\n")
    (top / "in" / "b" / ".hidden").write_bytes(raw_dump())
    return top


def decode(*args: str) -> tuple[int, str]:
    """`ilahrs decode ARGS` in this process: the exit status and stderr."""
    err = io.StringIO()
    with redirect_stderr(err):
        status = main(["decode", *args])
    return status, err.getvalue()


@pytest.fixture(scope="module")
def dataset(captures: Path) -> tuple[Path, str]:
    out = captures / "set1"
    status, err = decode(str(captures / "in"), "--to", "parquet", str(out), "--jobs", "1")
    assert status == 0, err
    return out, err


def csv_rows(path: Path, *options: str) -> list[dict[str, str]]:
    target = path.parents[2] / f"{path.name}.csv"  # outside the folders of captures
    status, err = decode(str(path), "--to", "csv", str(target), *options)
    assert status == 0, err
    return list(csv.DictReader(io.StringIO(target.read_text())))


def same(text: str, value: Any) -> bool:
    """A CSV cell and the dataset's value of it."""
    if value is None:
        return text == ""
    if isinstance(value, float) and math.isnan(value):  # pandas has NaN for a null of a float column too
        return text in ("", "nan")
    if isinstance(value, float):
        return float(text) == value
    return text == str(value)


def relative(value: Any) -> str:
    """A `time` of the dataset as the CSV's: seconds since the capture's first timestamp."""
    if value is None or value is pandas.NaT:
        return ""
    micros = round(value.timestamp() * 1_000_000) - START_US
    return f"{micros / 1_000_000:.6f}"


def test_duckdb_reads_the_rows_of_the_csv(captures: Path, dataset: tuple[Path, str]) -> None:
    out, err = dataset
    assert "skipped " in err and "notes.txt" in err and ".hidden" not in err
    assert "2 captures" in err
    query = f"SELECT * FROM read_parquet('{out}/**/*.parquet', hive_partitioning=true, union_by_name=true)"
    found = duckdb.sql(query).fetchdf()
    for name in ("a/run.pcapng", "b/run.bin"):
        path = captures / "in" / name
        expected = csv_rows(path)
        mine = found[found["source"] == str(path)]
        assert len(mine) == len(expected)
        by_place = {(r["kind"], r["direction"], int(r["offset"])): r for r in mine.to_dict("records")}
        for row in expected:
            got = by_place[(row["kind"], row["direction"], int(row["offset"]))]
            assert relative(got["time"]) == row["time"] if row["time"] else pandas.isna(got["time"])
            for column, text in row.items():
                if column in ("time", "kind"):
                    continue
                value = got.get(column)
                assert same(text, None if value is pandas.NaT else value), (column, text, got)
    kinds = set(found["kind"])
    assert {"damaged", "full_output", "Stop", "AHRScont1", "PAHR", "calibration_run_result"} <= kinds


def test_pandas_reads_a_kind_with_its_types_and_metadata(captures: Path, dataset: tuple[Path, str]) -> None:
    out, _ = dataset
    table = pandas.read_parquet(out / "kind=full_output", engine="pyarrow")
    rows = [r for r in csv_rows(captures / "in" / "a" / "run.pcapng") if r["kind"] == "full_output"]
    mine = table[table["source"] == str(captures / "in" / "a" / "run.pcapng")].sort_values("offset")
    assert mine["offset"].tolist() == [int(r["offset"]) for r in rows]
    assert mine["heading"].tolist() == [float(r["heading"]) for r in rows]
    assert mine["usw"].tolist() == [r["usw"] for r in rows]
    assert str(mine["time"].dtype) == "datetime64[us, UTC]"
    names = {part_name(str(captures / "in" / name)) for name in ("a/run.pcapng", "b/run.bin")}
    assert len(names) == 2 and {p.name for p in out.rglob("*.parquet")} == names  # run.* apart
    files = sorted((out / "kind=full_output").iterdir())
    schema = pq.read_schema(files[0])
    heading = schema.field("heading")
    assert heading.type == pa.float64()
    meta = {k.decode(): v.decode() for k, v in heading.metadata.items()}
    cls = ilahrs.FullOutput
    info = next(f for f in cls.FIELDS if f.name == "heading")
    assert meta == {"unit": info.unit, "icd_table": cls.ICD, "icd_title": cls.TITLE, "icd_field": info.icd_name}
    assert schema.field("ugyro_x").type == pa.int64() and schema.field("usw").type == pa.string()
    assert "reason" not in schema.names and "kind" not in schema.names
    calibration = pq.read_table(next((out / "kind=calibration_run_result").iterdir()))
    assert calibration.schema.field("accuracy").metadata[b"unit"] == b"deg"
    pitch = calibration.column("average_pitch").to_pylist()  # a NaN is a float, not a missing value
    assert pitch[0] == -1.5 and math.isnan(pitch[1]) and pitch[2] == 2
    pahr = pq.read_schema(next((out / "kind=PAHR").iterdir()))
    assert pahr.field("heading").metadata[b"unit"] == b"deg" and pahr.field("heading").type == pa.float64()


def files(out: Path) -> dict[str, bytes]:
    return {str(p.relative_to(out)): p.read_bytes() for p in sorted(out.rglob("*.parquet"))}


def test_raw_values_and_two_jobs(captures: Path, dataset: tuple[Path, str]) -> None:
    out, _ = dataset
    two = captures / "set2"
    status, err = decode(str(captures / "in"), "--to", "parquet", str(two), "--jobs", "2")
    assert status == 0, err
    assert files(out) == files(two)  # the same files, byte for byte
    raw = captures / "raw"
    dump = captures / "in" / "b" / "run.bin"
    status, err = decode(str(dump), "--to", "parquet", str(raw), "--raw", "--types", "PAHR,calibration_run_result")
    assert status == 0, err
    assert sorted(p.name for p in raw.iterdir()) == ["kind=PAHR", "kind=calibration_run_result"]
    pahr = pq.read_table(next((raw / "kind=PAHR").iterdir()))
    expected = [r for r in csv_rows(dump, "--raw") if r["kind"] == "PAHR"]
    assert pahr.column("heading").to_pylist() == [int(r["heading"]) for r in expected]
    assert pahr.schema.field("heading").metadata[b"scale"] == b"1/100"


def test_a_capture_cut_short_and_what_is_refused(captures: Path, tmp_path: Path) -> None:
    whole = (captures / "in" / "a" / "run.pcapng").read_bytes()
    cut = tmp_path / "cut.pcapng"
    cut.write_bytes(whole[: len(whole) - 7])
    out = tmp_path / "out"
    status, err = decode(str(cut), str(captures / "in" / "b" / "run.bin"), "--to", "parquet", str(out), "--jobs", "1")
    assert status == 2 and f"{cut}: " in err.splitlines()[-1]
    assert (out / "kind=full_output" / part_name(str(cut))).exists()  # its rows before the damage
    status, err = decode(str(cut), "--to", "parquet", str(out))
    assert (status, err.strip()) == (2, f"ilahrs decode: {out}: exists and is not empty (--force replaces it)")
    status, err = decode(str(tmp_path / "none.bin"), "--to", "parquet", str(tmp_path / "x"))
    assert (status, err.count("\n")) == (2, 1) and "no such file" in err
    status, err = decode(str(captures / "in" / "b" / "notes.txt"), "--to", "parquet", str(tmp_path / "x"))
    assert (status, err.count("\n")) == (2, 1) and "neither pcapng nor a raw capture" in err
    assert not (tmp_path / "x").exists()


def test_without_pyarrow_one_line_names_the_extra(
    captures: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import importlib

    real = importlib.import_module

    def missing(name: str, package: str | None = None) -> Any:
        if name.startswith("pyarrow"):
            raise ImportError(name)
        return real(name, package)

    monkeypatch.setattr(importlib, "import_module", missing)
    status, err = decode(str(captures / "in"), "--to", "parquet", str(tmp_path / "out"))
    assert status == 2
    assert err == "ilahrs decode: --to parquet needs pyarrow, the parquet extra: pip install 'pyarrow>=14'\n"
    assert os.listdir(tmp_path) == []


def test_ctrl_c_stops_the_workers_and_leaves_nothing(
    captures: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pools: list[Any] = []

    def interrupted(futures: list[Any]) -> Iterator[Any]:
        pools.extend(futures)
        raise KeyboardInterrupt

    monkeypatch.setattr(to_parquet, "as_completed", interrupted)
    status, err = decode(str(captures / "in"), "--to", "parquet", str(tmp_path / "out"), "--jobs", "2")
    assert (status, err.splitlines()[-1]) == (130, "ilahrs decode: interrupted")
    assert os.listdir(tmp_path) == []
    assert pools and all(f.cancelled() or f.done() for f in pools)


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_a_line_per_capture_on_a_terminal_and_each_capture_once(captures: Path, tmp_path: Path) -> None:
    run = captures / "in" / "a" / "run.pcapng"
    args = argparse.Namespace(
        files=[str(run), str(captures / "in" / "a"), str(captures / "in" / "b" / "run.bin")],
        selected=["damaged"],
        variant=None,
        raw=False,
        output_format=None,
        strict=False,
        jobs=1,  # in order (in processes, the lines come as the captures are done)
    )
    err = Terminal()
    assert to_parquet.write(args, str(tmp_path / "out"), err) == 0
    lines = err.getvalue().splitlines()
    assert lines[:2] == [
        f"ilahrs decode: [1/2] {run}: 104 messages",
        f"ilahrs decode: [2/2] {captures / 'in' / 'b' / 'run.bin'}: 7 messages",
    ]
    assert lines[2].startswith("ilahrs decode: 2 captures, 111 messages, 2 damaged rows (damaged 2)")


def test_a_dataset_inside_the_folder_of_captures_is_not_read_back(captures: Path, tmp_path: Path) -> None:
    logs = tmp_path / "logs"
    logs.mkdir()
    (logs / "run.bin").write_bytes((captures / "in" / "b" / "run.bin").read_bytes())
    for options in ((), ("--force",)):
        status, err = decode(str(logs), "--to", "parquet", str(logs / "dataset"), *options)
        assert status == 0 and err.startswith("ilahrs decode: 1 capture, 7 messages"), err
