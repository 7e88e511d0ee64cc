"""The `$PAHR` lines of prove/drivers, run by Frama-C on a copy of the C with one bug put in: each
line fails and names the bug. The callers' lines take pahr_body() by its contract, so what they
prove rests on EVA checking each call against it, which EVA does not count among its alarms;
prove/run.sh has to. (The analyses of the C as it is run in `make test-prove`.)"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.skipif(shutil.which("frama-c") is None, reason="Frama-C is not installed (make setup-prove)")


def run_with(tmp_path: Path, old: str, new: str, *lines: str) -> subprocess.CompletedProcess[str]:
    """prove/run.sh over a copy of generated/c/ilahrs.c in which OLD, found once, is NEW."""
    (tmp_path / "generated").mkdir()
    shutil.copytree(ROOT / "generated" / "c", tmp_path / "generated" / "c")
    shutil.copytree(ROOT / "prove", tmp_path / "prove", ignore=shutil.ignore_patterns("wp-cache"))
    source = tmp_path / "generated" / "c" / "ilahrs.c"
    text = source.read_text()
    assert text.count(old) == 1, old
    source.write_text(text.replace(old, new))
    return subprocess.run(
        [str(tmp_path / "prove" / "run.sh"), str(tmp_path / "out"), *lines],
        check=False,
        capture_output=True,
        text=True,
        timeout=600,
    )


def results(run: subprocess.CompletedProcess[str]) -> dict[str, str]:
    """Each line's result line, by name."""
    return {line.split()[0]: line for line in run.stdout.splitlines() if not line.startswith((" ", "prove:"))}


def test_a_call_that_breaks_pahr_body_s_contract_fails_its_caller_s_line(tmp_path: Path) -> None:
    """One byte more than the sentence: EVA marks the precondition invalid and still reports 0
    alarms; the line fails with the precondition named."""
    run = run_with(
        tmp_path,
        "answer = pahr_body(p, end, out);",
        "answer = pahr_body(p, end + 1, out);",
        "pahr_parse",
        "pahr_parse-speed",
    )
    assert run.returncode != 0, run.stdout
    found = results(run)
    assert "1 alarms" in found["pahr_parse"] and "1 alarms" in found["pahr_parse-speed"]
    assert "function pahr_body: precondition \\valid_read(p + (0 .. end - 1)) got status invalid" in run.stdout


def test_a_read_past_the_sentence_fails_the_pahr_body_lines(tmp_path: Path) -> None:
    """The CR looked for one byte past the LF, on both paths."""
    run = run_with(
        tmp_path, "star[PAHR_TAIL - 2u] != PAHR_CR", "star[PAHR_TAIL] != PAHR_CR", "pahr_body", "pahr_body-speed"
    )
    assert run.returncode != 0, run.stdout
    found = results(run)
    assert " 0 alarms" not in found["pahr_body"] and " 0 alarms" not in found["pahr_body-speed"]
    assert run.stdout.count("out of bounds read. assert \\valid_read(star + 5u)") == 2
