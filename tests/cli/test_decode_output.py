"""Where `ilahrs decode` writes: `--to FORMAT [PATH]`, files written whole and renamed into place,
directories that are not replaced without --force, and the formats of `to_*` modules."""

from __future__ import annotations

import argparse
import io
import os
from pathlib import Path
from types import ModuleType

import pytest

import ilahrs
from ilahrs.__main__ import main
from ilahrs.cli import decode as decode_module
from ilahrs.cli.common import CliError
from ilahrs.cli.exports import Export, replacing
from ilahrs.pcapng import Direction, PcapngWriter
from ilahrs.statemachine import DEFAULT_ALIGNMENT_TIME_S

START_US = 1_700_000_000_000_000


def capture() -> bytes:
    """A pcapng capture: Stop, AHRScont1, its acknowledgement, the alignment block and a second of
    output, as a device model answers."""
    device = ilahrs.Device(seed=1)
    out = io.BytesIO()
    writer = PcapngWriter(out, port="/dev/ttyUSB0", baud=115200)
    now = START_US
    for name in ("Stop", "AHRScont1"):
        command = ilahrs.build_command(name)
        writer.write(command, now, Direction.OUTBOUND)
        now += 4_500
        writer.write(device.receive(command), now, Direction.INBOUND)
    for _ in range(int(DEFAULT_ALIGNMENT_TIME_S) + 1):
        now += 1_000_000
        writer.write(device.advance(1.0), now, Direction.INBOUND)
    return out.getvalue()


def run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    try:
        code = main(["decode", *args])
    except SystemExit as exc:  # argparse's own errors
        code = int(exc.code or 0)
    found = capsys.readouterr()
    return code, found.out, found.err


@pytest.fixture
def pcapng(tmp_path: Path) -> Path:
    path = tmp_path / "two.pcapng"
    path.write_bytes(capture())
    return path


def leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


def test_a_file_gets_what_standard_output_gets(capsys: pytest.CaptureFixture[str], pcapng: Path) -> None:
    for form in ("csv", "jsonl", "text"):
        code, shown, _ = run(capsys, str(pcapng), "--to", form)
        assert code == 0
        out = pcapng.parent / f"rows.{form}"
        out.write_text("what was there before\n")
        code, printed, err = run(capsys, str(pcapng), "--to", form, str(out))
        assert code == 0, err
        assert printed == ""
        assert out.read_text() == shown and shown.count("\n") > 50
        assert "decode errors" in err
    assert leftovers(pcapng.parent) == []


def test_a_capture_cut_short_keeps_its_rows_in_the_file(capsys: pytest.CaptureFixture[str], pcapng: Path) -> None:
    cut = pcapng.parent / "cut.pcapng"
    cut.write_bytes(pcapng.read_bytes()[:-7])
    out = pcapng.parent / "rows.csv"
    code, shown, _ = run(capsys, str(cut), "--to", "csv")
    assert code == 2 and shown.count("\n") > 3
    code, _, err = run(capsys, str(cut), "--to", "csv", str(out))
    assert code == 2
    assert err.count("\n") == 1 and "file ends inside the block" in err
    assert out.read_text() == shown
    assert leftovers(pcapng.parent) == []


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--to", "cvs"], "unknown output format 'cvs'; did you mean csv?"),
        (["--to", "csv", "a", "b"], "--to takes a format and at most one path, not 'csv a b'"),
        (["--to", "csv", "/no/such/folder/rows.csv"], "/no/such/folder/rows.csv: no such directory /no/such/folder"),
        (["--follow", "--to", "csv", "rows.csv"], "--follow writes to standard output"),
    ],
)
def test_what_cannot_be_done_is_one_line(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, pcapng: Path, args: list[str], message: str
) -> None:
    monkeypatch.chdir(pcapng.parent)
    code, printed, err = run(capsys, str(pcapng), *args)
    assert code == 2 and printed == ""
    assert err.startswith(f"ilahrs decode: {message}") and err.count("\n") == 1, err


def test_a_directory_is_not_a_file(capsys: pytest.CaptureFixture[str], pcapng: Path) -> None:
    code, _, err = run(capsys, str(pcapng), "--to", "csv", str(pcapng.parent))
    assert code == 2 and err == f"ilahrs decode: {pcapng.parent}: is a directory\n"


def test_several_captures_need_a_format_that_takes_many(capsys: pytest.CaptureFixture[str], pcapng: Path) -> None:
    code, _, err = run(capsys, str(pcapng), str(pcapng), "--to", "csv")
    assert code == 2 and err.startswith("ilahrs decode: --to csv decodes one capture, not 2")


def _fake(written: list[tuple[list[str], str]]) -> ModuleType:
    def write(args: argparse.Namespace, path: str) -> int:
        os.mkdir(path)
        (Path(path) / "part").write_text(",".join(args.files))
        written.append((list(args.files), args.selected[0]))
        return 0

    module = ModuleType("to_fake")
    module.EXPORTS = {"fake": Export("directory", "fake", "a test dataset", write, many=True)}  # type: ignore[attr-defined]
    return module


def test_a_format_of_a_to_module(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, pcapng: Path
) -> None:
    written: list[tuple[list[str], str]] = []
    module = _fake(written)
    monkeypatch.setattr(decode_module, "exports", lambda: dict(module.EXPORTS))
    out = pcapng.parent / "dataset"
    code, _, err = run(capsys, str(pcapng), str(pcapng), "--to", "fake")
    assert code == 2 and err == "ilahrs decode: --to fake needs the directory to write: --to fake PATH\n"
    code, _, err = run(capsys, str(pcapng), str(pcapng), "--to", "fake", str(out))
    assert (code, err) == (0, "")
    assert (out / "part").read_text() == f"{pcapng},{pcapng}"
    code, _, err = run(capsys, str(pcapng), "--to", "fake", str(out))
    assert code == 2 and err == f"ilahrs decode: {out}: exists and is not empty (--force replaces it)\n"
    code, _, err = run(capsys, str(pcapng), "--to", "fake", str(out), "--force")
    assert (code, err) == (0, "")
    assert (out / "part").read_text() == str(pcapng)
    assert leftovers(pcapng.parent) == []


def test_a_failed_write_leaves_what_was_there(tmp_path: Path) -> None:
    target = tmp_path / "dataset"
    target.mkdir()
    (target / "old").write_text("kept")
    with pytest.raises(CliError, match="broken"), replacing(str(target), directory=True, force=True) as temporary:
        os.mkdir(temporary)
        raise CliError("broken")
    assert (target / "old").read_text() == "kept"
    with pytest.raises(CliError, match="nothing was written"), replacing(str(tmp_path / "file.csv"), directory=False):
        pass
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dataset"]
