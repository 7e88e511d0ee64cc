"""The state diagram (generated/docs/state-machine.dot, drawn to .svg; `ilahrs diagram` in Mermaid):
readable at a screen's width, with the transitions every state of a mode has drawn once."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys

import pytest

from generator import ROOT
from ilahrs import diagram
from ilahrs.statemachine import mermaid

DOT = ROOT / "generated" / "docs" / "state-machine.dot"
SVG = ROOT / "generated" / "docs" / "state-machine.svg"
SCREEN_PT = 1200
"""The widest drawing that fits a 1920-pixel screen at 100 % (1 pt = 4/3 px) with room to spare."""


def _arrows(text: str) -> list[tuple[str, str, str]]:
    return re.findall(r"^  (\w+) -> (\w+) \[label=\"([^\"]*)\"", text, re.MULTILINE)


def test_mode_wide_transitions_are_one_arrow() -> None:
    rows: list[diagram.Row] = [
        ("a1", "Stop", "idle", (), False, None),
        ("a2", "Stop", "idle", (), False, None),
        ("a2", "Go", "a1", (), False, None),
        ("b1", "Stop", "idle", (), False, None),
        ("b2", "Stop", "idle", (), True, None),  # a wildcard row: not folded
        ("idle", "Stop", "idle", (), False, None),
    ]
    modes = {"a1": "a", "a2": "a", "b1": "b", "b2": "b", "idle": "idle"}
    edges = diagram.fold(rows, modes=modes)
    assert [(e.state, e.to, e.whole_mode) for e in edges] == [
        ("a", "idle", True),
        ("a2", "a1", False),
        ("b1", "idle", False),
        ("b2", "idle", False),
        ("idle", "idle", False),
    ]
    assert [(e.state, e.to) for e in diagram.fold(rows)] == [(r[0], r[2]) for r in rows]


def test_few_arrows_into_idle_and_no_self_loop_labels() -> None:
    arrows = _arrows(DOT.read_text(encoding="utf-8"))
    into_idle = [a for a in arrows if a[1] == "idle"]
    assert len(into_idle) <= 9, into_idle
    assert ("mode_calibration", "idle", "ExitClb / ack") in arrows
    assert not [a for a in arrows if a[0] == a[1]], "a self-loop is written in its state's box"
    assert "stays on: ReadAHRSPar / ahrs_parameters_read" in DOT.read_text(encoding="utf-8")


def test_the_drawing_fits_a_screen() -> None:
    width = float(re.search(r'<svg width="([\d.]+)pt"', SVG.read_text(encoding="utf-8")).group(1))  # type: ignore[union-attr]
    assert width <= SCREEN_PT
    if shutil.which("dot") is None:
        pytest.skip("Graphviz dot is not installed")
    drawn = subprocess.run(["dot", "-Tsvg", str(DOT)], capture_output=True, text=True, check=True).stdout
    width = float(re.search(r'<svg width="([\d.]+)pt"', drawn).group(1))  # type: ignore[union-attr]
    assert width <= SCREEN_PT


def test_mermaid_draws_the_same_arrows() -> None:
    text = mermaid()
    assert 'state "any state of mode calibration" as mode_calibration' in text
    assert "    mode_calibration --> idle: ExitClb / ack\n" in text
    assert "    mode_continuous --> idle: Stop\n" in text
    assert "calibration_aligning --> idle" not in text
    dot = {(a, b) for a, b, _ in _arrows(DOT.read_text(encoding="utf-8"))}
    drawn = set(re.findall(r"^    (\w+) --> (\w+):", text, re.MULTILINE))
    assert dot == {(a, b) for a, b in drawn if a != b}
    result = subprocess.run([sys.executable, "-m", "ilahrs", "diagram"], capture_output=True, text=True, check=True)
    assert result.stdout == text
