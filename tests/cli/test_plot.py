"""`ilahrs plot` on a hand-made capture, checked through the matplotlib objects it draws: no line
across a time without output, no vertical stroke where heading wraps, one panel per quantity (heading
0-360 apart from a few degrees of pitch and roll) sharing the time axis, legends outside the data,
multiplexed fields one line per turn, and a field the capture lacks refused in one line."""

from __future__ import annotations

import math
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from ilahrs import Frame, FullOutput, InitialAlignment, MessageType, ack_for, build_command
from ilahrs.cli.common import variant_named
from ilahrs.pcapng import Direction, PcapngWriter

pyplot = pytest.importorskip("matplotlib.pyplot")

ILAHRS = [sys.executable, "-m", "ilahrs"]
START_US = 1_700_000_000_000_000
PERIOD = 0.01
"""100 Hz output."""
STRETCHES = ((1.0, 4.0), (61.0, 64.0))
"""Two stretches of output with 57 s of silence between them."""
GAP = (STRETCHES[0][1], STRETCHES[1][0])
VDD_LEVELS = (12.0, 5.0)
"""Vdd of Table 6.4 in turn: the input voltage, the stabilised sensor supply (E19)."""
UTERMO_LEVELS = tuple(1000 + 250 * k for k in range(7))
ANGLE_AMPLITUDE = 5.0


def heading_at(t: float) -> float:
    """Rising through 360 in the first stretch (340 + 15 deg/s), falling through 0 in the second."""
    if t < GAP[1]:
        return (340.0 + 15.0 * (t - STRETCHES[0][0])) % 360.0
    return (10.0 - 15.0 * (t - STRETCHES[1][0])) % 360.0


def output_frames() -> Iterator[tuple[float, bytes]]:
    frame_number = 0
    for number, (start, end) in enumerate(STRETCHES):
        # the second stretch begins one turn later: the frames carry no index, the plot must tell
        frame_number += number
        for i in range(round((end - start) / PERIOD) + 1):
            t = start + i * PERIOD
            raw = {
                "heading": round(heading_at(t) * 100) % 36000,
                "pitch": round(ANGLE_AMPLITUDE * 100 * math.sin(2 * math.pi * t / 3)),
                "roll": round(-ANGLE_AMPLITUDE * 100 * math.cos(2 * math.pi * t / 3)),
                "ugyro_x": round(300 * math.sin(t)),
                "vdd": round(VDD_LEVELS[frame_number % 2] * 1000) + i % 3,
                "utermo": UTERMO_LEVELS[frame_number % 7] + i % 2,
            }
            frame_number += 1
            yield t, Frame(MessageType.DATA, FullOutput.from_raw(raw).build()).build()


def write_capture(path: Path) -> None:
    with path.open("wb") as stream:
        writer = PcapngWriter(stream, port="/dev/ttyUSB0", baud=115200)
        start = build_command("AHRScont1")
        writer.write(start, START_US, Direction.OUTBOUND)
        writer.write(ack_for(start), START_US + 5_000, Direction.INBOUND)
        alignment = Frame(MessageType.DATA, InitialAlignment.from_raw({}).build()).build()
        writer.write(alignment, START_US + 500_000, Direction.INBOUND)
        for t, frame in output_frames():
            writer.write(frame, START_US + round(t * 1e6), Direction.INBOUND)


@pytest.fixture
def capture(tmp_path: Path) -> Path:
    path = tmp_path / "gap-and-wrap.pcapng"
    write_capture(path)
    return path


def drawn(capture: Path, png: Path, fields: str, monkeypatch: pytest.MonkeyPatch) -> Any:
    """Run `ilahrs plot` in this process and keep the Figure it drew (it closes it otherwise)."""
    from ilahrs.cli.plot import plot

    pyplot.close("all")
    monkeypatch.setattr(pyplot, "close", lambda *args: None)
    variant = variant_named(None)
    status = plot(str(capture), str(png), fields_text=fields, size_text="1200x900", variant=variant, output_format=None)
    assert status == 0 and png.stat().st_size > 0
    figures = [pyplot.figure(n) for n in pyplot.get_fignums()]
    assert len(figures) == 1
    return figures[0]


def lines_of(figure: Any) -> dict[str, Any]:
    return {line.get_label(): line for axis in figure.axes for line in axis.get_lines()}


def finite_steps(line: Any) -> list[tuple[float, float, float, float]]:
    """(x0, y0, x1, y1) of each stroke the line draws: both ends finite."""
    x, y = line.get_xdata(), line.get_ydata()
    return [
        (x[i], y[i], x[i + 1], y[i + 1])
        for i in range(len(x) - 1)
        if all(math.isfinite(v) for v in (x[i], y[i], x[i + 1], y[i + 1]))
    ]


def test_lines_break_at_a_gap_in_the_output(capture: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    figure = drawn(capture, tmp_path / "gap.png", "heading,pitch,roll,ugyro_x", monkeypatch)
    lines = lines_of(figure)
    assert set(lines) == {"heading", "pitch", "roll", "ugyro_x"}
    for label, line in lines.items():
        x, y = line.get_xdata(), line.get_ydata()
        assert any(GAP[0] < x[i] < GAP[1] and math.isnan(y[i]) for i in range(len(x))), f"{label}: no break"
        widest = max(x1 - x0 for x0, _, x1, _ in finite_steps(line))
        assert widest < 10 * PERIOD, f"{label}: a {widest:.1f} s stroke through a time without data"


def test_heading_wraps_without_a_vertical_stroke(
    capture: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    figure = drawn(capture, tmp_path / "wrap.png", "heading", monkeypatch)
    (heading,) = lines_of(figure).values()
    steps = finite_steps(heading)
    assert max(abs(y1 - y0) for _, y0, _, y1 in steps) < 5.0, "a stroke across the panel where heading wraps"
    x, y = heading.get_xdata(), heading.get_ydata()
    breaks = [x[i] for i in range(len(x)) if math.isnan(y[i]) and not GAP[0] < x[i] < GAP[1]]
    rising = STRETCHES[0][0] + 20.0 / 15.0  # 340 + 15 deg/s reaches 360
    falling = STRETCHES[1][0] + 10.0 / 15.0  # 10 - 15 deg/s reaches 0
    assert [round(b, 2) for b in breaks] == [round(rising, 2), round(falling, 2)]
    # the line runs to the panel's edges at the wrap, and the panel is the compass
    assert {360.0, 0.0} <= {float(v) for v in y if math.isfinite(v)}
    assert figure.axes[0].get_ylim() == (0.0, 360.0)


def test_one_panel_per_quantity_sharing_time(capture: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    figure = drawn(capture, tmp_path / "panels.png", "heading,pitch,roll,vdd,utermo,ugyro_x", monkeypatch)
    axes = figure.axes
    panels = [sorted(line.get_label().split(" ")[0] for line in axis.get_lines()) for axis in axes]
    assert [sorted(set(p)) for p in panels] == [["heading"], ["pitch", "roll"], ["vdd"], ["ugyro_x", "utermo"]]
    assert axes[0].get_ylim() == (0.0, 360.0)
    low, high = axes[1].get_ylim()
    assert -2 * ANGLE_AMPLITUDE < low < -ANGLE_AMPLITUDE * 0.9 and ANGLE_AMPLITUDE * 0.9 < high < 2 * ANGLE_AMPLITUDE
    for axis in axes[1:]:
        assert axis.get_shared_x_axes().joined(axes[0], axis)
    assert "V" in axes[2].get_ylabel() and "deg" in axes[0].get_ylabel() and "deg" in axes[1].get_ylabel()


def test_legends_are_outside_the_data(capture: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    figure = drawn(capture, tmp_path / "legend.png", "heading,pitch,roll,vdd", monkeypatch)
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    whole = figure.bbox
    for axis in figure.axes:
        legend = axis.get_legend()
        assert legend is not None
        box = legend.get_window_extent(renderer)
        for other in figure.axes:
            assert not box.overlaps(other.get_window_extent(renderer)), "a legend over the data"
        assert whole.x0 <= box.x0 and box.x1 <= whole.x1 and whole.y0 <= box.y0 and box.y1 <= whole.y1


def test_multiplexed_fields_are_drawn_per_turn(capture: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    figure = drawn(capture, tmp_path / "turns.png", "vdd,utermo", monkeypatch)
    lines = lines_of(figure)
    vdd = [line for label, line in lines.items() if label.startswith("vdd")]
    utermo = [line for label, line in lines.items() if label.startswith("utermo")]
    assert len(vdd) == 2 and len(utermo) == 7
    for group, spread in ((vdd, 0.01), (utermo, 2)):
        levels = []
        for line in group:
            values = [float(v) for v in line.get_ydata() if math.isfinite(v)]
            assert max(values) - min(values) < spread, f"{line.get_label()} mixes quantities: a sawtooth"
            levels.append(round(min(values), 1))
        assert len(set(levels)) == len(group)


def one_line_error(*args: str) -> str:
    result = subprocess.run([*ILAHRS, "plot", *args], capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode == 2 and result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    return lines[0]


def test_a_field_the_capture_lacks_or_no_table_has_is_an_error(capture: Path, tmp_path: Path) -> None:
    png = tmp_path / "never.png"
    line = one_line_error(str(capture), "-o", str(png), "--fields", "heading,gyro_z")
    assert "gyro_z" in line and "orientation_sensors" in line and "full_output" in line
    line = one_line_error(str(capture), "-o", str(png), "--fields", "heading,pich")
    assert "'pich'" in line and "did you mean pitch?" in line
    assert not png.exists()
