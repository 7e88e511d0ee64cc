"""`ilahrs simulate` checks every option at start-up: a value that would make it fail later (on
the first GetVerFirmware, at StopClbRun, when the log is written) is refused at once with one
line on stderr and exit status 2."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest


def _simulate(*args: str) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "ilahrs", "simulate", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=30, check=False)


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (("--firmware", "banana"), "firmware"),
        (("--firmware", "4.²"), "firmware"),
        (("--firmware", ""), "firmware"),
        (("--firmware-text", "€"), "firmware_text"),
        (("--log", "/"), "log"),
        (("--log", "/nonexistent-folder/simulator.jsonl"), "log"),
    ],
)
def test_bad_options_are_refused_at_start_up(args: tuple[str, ...], says: str, tmp_path: Path) -> None:
    del tmp_path
    result = _simulate(*args)
    assert result.returncode == 2, result.stderr
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("ilahrs simulate: ") and says in lines[0], result.stderr
