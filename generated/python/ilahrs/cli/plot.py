# Copied from generator/targets/python/runtime/cli/plot.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs plot`: time series of chosen fields of a capture as a PNG. Needs matplotlib (the `plot`
extra, or `pip install 'matplotlib>=3.8'`); nothing else in the package does.

What the figure shows, and why:

- One panel per quantity, all sharing the time axis. The panels come from the spec's field units
  (`ilahrs.spec.UNITS`), not from a list of names: rates, accelerations, magnetic field,
  temperature, voltage, ADC codes ... each get their own. Angles are split by their range: an
  angle whose range is 0..360 (heading) is a compass direction, drawn on a fixed 0-360 panel; a
  signed angle (pitch, roll) gets a panel scaled to its data, so a few degrees stay readable.
- No line across a time without data: wherever two successive messages of a table are more than
  GAP_PERIODS output periods apart (the period is the median interval between that table's
  messages in the capture), the line breaks.
- No vertical stroke where a heading wraps (359 deg to 0 deg): the line runs to the panel's edge
  at the time the wrap happens (interpolated), breaks, and comes back from the other edge. The
  heading is not unwrapped, so the panel always reads as a compass direction.
- A multiplexed field (one that carries several quantities in turn in successive frames, such as
  Vdd and Utermo of Table 6.4, E19) is drawn as one line per turn: "vdd (turn 1/2)" is the
  quantity of the 1st, 3rd, 5th ... frame. The frame does not say which quantity it carries, so
  the turns are numbered from the first frame of the capture; after a gap, the turns are matched
  to the ones before it by the nearest values (a lost frame inside a stretch of output shifts the
  turns: the frame carries no index to notice it by).
- The legends are outside the panels, on the right.
- A raw dump has no times: x is the message number, and a gap cannot be seen (no break).
- A field name that no table has is refused with the closest valid name; a field this capture's
  messages do not carry is refused with the tables that do carry it.

`figure()` builds the matplotlib Figure (for a script or a test); `plot()` writes it as a PNG.
"""

from __future__ import annotations

import argparse
import importlib
import itertools
import math
import os
import re
import statistics
import tempfile
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, Final

from ..encodings import Variant
from ..nmea import PahrSentence
from ..payloads import PAYLOADS
from ..pcapng import Direction
from ..spec import UNITS
from .arguments import OneLineParser, output_format_argument, variant_argument
from .capture import open_source
from .capture_decoder import CaptureDecoder
from .common import SENTENCE_KIND, CliError, fields_of, lookup, variant_named
from .decode import output_table
from .rows import Message

__all__ = ["GAP_PERIODS", "Quantity", "figure", "plot", "plottable"]

GAP_PERIODS: Final = 5.0
"""A line breaks where two successive messages of its table are more than this many output periods
apart."""
_DPI: Final = 100
_MAX_PIXELS: Final = 10000
_CIRCLE: Final = 360.0
"""A full turn in degrees: an angle field whose range is 0..360 wraps around."""
_ANGLE_UNIT: Final = "deg"
_NO_UNIT: Final = "value"


@dataclass(frozen=True, slots=True)
class Quantity:
    """What one field of one table carries: its unit (None: a count or code), whether it is a
    compass direction that wraps at 360 degrees, and how many quantities it carries in turn."""

    unit: str | None
    circular: bool = False
    multiplexed: int = 0

    @property
    def group(self) -> tuple[str, bool]:
        """The panel the field goes to: by unit, compass directions apart from signed angles."""
        return (self.unit or _NO_UNIT, self.circular)


def _circular(unit: str | None, low: float | None, high: float | None) -> bool:
    return unit == _ANGLE_UNIT and low is not None and high is not None and low >= 0 and high <= _CIRCLE


def _scaled(raw: float | None, multiplier: int, divisor: int | str) -> float | None:
    if raw is None or isinstance(divisor, str):
        return None
    return raw * multiplier / divisor


def plottable() -> dict[str, dict[str, Quantity]]:
    """Message kind (a device-to-host payload table, PAHR) -> its fields that hold a number in
    engineering units -> what they carry."""
    found: dict[str, dict[str, Quantity]] = {}
    for name, table in PAYLOADS.items():
        if table.DIRECTION != "device_to_host":
            continue
        fields = {
            info.name: Quantity(
                info.unit,
                _circular(
                    info.unit,
                    _scaled(info.low, info.multiplier, info.divisor),
                    _scaled(info.high, info.multiplier, info.divisor),
                ),
                info.multiplexed,
            )
            for info in table.FIELDS
            if info.type not in ("reserved", "char") and info.encoding is None
        }
        if fields:
            found[name] = fields
    found[SENTENCE_KIND] = {
        name: Quantity(unit, _circular(unit, low / 10**decimals, high / 10**decimals))
        for name, kind, _width, decimals, low, high, unit in PahrSentence._SPEC
        if kind == "decimal"
    }
    return found


_PLOTTABLE: Final = plottable()


@dataclass(slots=True)
class _Series:
    """One field of one table, as read from the capture."""

    name: str
    kind: str
    quantity: Quantity
    times: list[float] = field(default_factory=list)
    values: list[float] = field(default_factory=list)


@dataclass(frozen=True, slots=True)
class _Line:
    label: str
    x: list[float]
    y: list[float]


def _size(text: str) -> tuple[int, int]:
    match = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", text)
    if not match or not all(0 < int(v) <= _MAX_PIXELS for v in match.groups()):
        raise CliError(f"--size {text!r}: expected WIDTHxHEIGHT in pixels, e.g. 1200x800")
    return int(match.group(1)), int(match.group(2))


def _pyplot() -> Any:
    try:
        matplotlib = importlib.import_module("matplotlib")
    except ImportError as exc:
        raise CliError("plotting needs matplotlib: pip install 'matplotlib>=3.8'") from exc
    matplotlib.use("Agg")
    return importlib.import_module("matplotlib.pyplot")


def _fields(text: str) -> list[str]:
    """The names of `--fields`, each checked (CliError with the closest valid name) and once."""
    valid = {name: None for fields in _PLOTTABLE.values() for name in fields}
    names: dict[str, None] = {}
    for item in text.split(","):
        if item.strip():
            names[lookup("field", item.strip(), valid)] = None
    if not names:
        raise CliError("--fields names no field")
    return list(names)


class _Collector:
    """The series of the requested fields, per field and table, from decoded messages."""

    def __init__(self, fields: Sequence[str], variant: Variant) -> None:
        self.fields = fields
        self.variant = variant
        self.series: dict[tuple[str, str], _Series] = {}
        self.kinds: dict[str, None] = {}
        """The kinds of the device-to-host messages seen, in order."""
        self.count = 0

    def take(self, message: Message) -> None:
        if message.direction != Direction.INBOUND or message.data is None:
            return
        self.count += 1
        self.kinds[message.kind] = None
        carried = _PLOTTABLE.get(message.kind, {})
        values = fields_of(message.data, self.variant)
        x = message.time if message.time is not None else float(self.count)
        for name in self.fields:
            value = values.get(name)
            if name in carried and isinstance(value, (int, float)) and not isinstance(value, bool):
                key = (name, message.kind)
                if key not in self.series:
                    self.series[key] = _Series(name, message.kind, carried[name])
                self.series[key].times.append(x)
                self.series[key].values.append(float(value))


def _read(path: str, fields: Sequence[str], variant: Variant, output: str | None) -> tuple[list[_Series], bool]:
    """The series of `fields` in the capture at `path`, per field and table, and whether the
    capture has times (pcapng) or only an order (a raw dump: x is the message's number)."""
    source = open_source(path)
    timed = source.kind == "pcapng"
    decoder = CaptureDecoder(context=timed, output=output, output_known=output is not None)
    collector = _Collector(fields, variant)
    try:
        for chunk in source.chunks():
            for message in decoder.feed(chunk):
                collector.take(message)
        for message in decoder.finish():
            collector.take(message)
    finally:
        source.close()
    series = collector.series
    missing = [name for name in fields if not any(s.name == name for s in series.values())]
    if missing:
        raise CliError(_missing(path, missing, list(collector.kinds), not timed and output is None))
    return [series[key] for name in fields for key in series if key[0] == name], timed


def _missing(path: str, missing: Sequence[str], kinds: Sequence[str], guessing: bool) -> str:
    """One line: which requested fields the capture lacks, what it has, which tables carry them
    (`guessing`: a raw dump read without --output-format, whose output frames go undecoded)."""
    by_tables: dict[str, list[str]] = {}
    for name in missing:
        by_tables.setdefault(", ".join(k for k, f in _PLOTTABLE.items() if name in f), []).append(name)
    where = "; ".join(
        f"{', '.join(names)} {'is' if len(names) == 1 else 'are'} in {t}" for t, names in by_tables.items()
    )
    hint = " (a raw dump: name the command that started its output with --output-format)" if guessing else ""
    has = f"whose messages are {', '.join(kinds)}" if kinds else "which has no decoded device-to-host message"
    return f"{path}: no {', '.join(missing)} in this capture, {has}{hint}; {where}"


# --- Lines ------------------------------------------------------------------------------------------


def _segments(times: Sequence[float], timed: bool) -> list[int]:
    """The stretch of output each sample belongs to: a new one after every gap longer than
    GAP_PERIODS periods (the median interval between samples)."""
    steps = [b - a for a, b in itertools.pairwise(times)]
    positive = [s for s in steps if s > 0]
    if not timed or not positive:
        return [0] * len(times)
    limit = GAP_PERIODS * statistics.median(positive)
    segment = [0]
    for step in steps:
        segment.append(segment[-1] + (step > limit))
    return segment


def _turns(values: Sequence[float], segments: Sequence[int], count: int) -> list[int]:
    """The turn (0 .. count-1) of each frame of a multiplexed field: frames in turn within a
    stretch of output; after a gap, the rotation that best continues the last value of each turn."""
    turns: list[int] = []
    last: dict[int, float] = {}
    start = 0
    while start < len(values):
        end = start
        while end < len(values) and segments[end] == segments[start]:
            end += 1
        head = values[start : min(end, start + count)]
        shift = (turns[-1] + 1) % count if turns else 0
        if last and turns:
            candidates = [(shift + r) % count for r in range(count)]
            shift = min(candidates, key=lambda s: _mismatch(head, last, s, count))
        for i in range(start, end):
            turn = (shift + i - start) % count
            turns.append(turn)
            last[turn] = values[i]
        start = end
    return turns


def _mismatch(head: Sequence[float], last: dict[int, float], shift: int, count: int) -> float:
    pairs = [(v, last.get((shift + i) % count)) for i, v in enumerate(head)]
    return sum(abs(v - w) for v, w in pairs if w is not None)


def _polyline(
    times: Sequence[float], values: Sequence[float], segments: Sequence[int], circular: bool
) -> tuple[list[float], list[float]]:
    """x and y with NaN breaks: between stretches of output, and where a compass direction wraps
    (the line then runs to the edge of 0..360 at the interpolated time of the wrap)."""
    x: list[float] = []
    y: list[float] = []
    for i, (t, v) in enumerate(zip(times, values, strict=True)):
        if i:
            t0, v0 = times[i - 1], values[i - 1]
            if segments[i] != segments[i - 1]:
                x.append((t0 + t) / 2)
                y.append(math.nan)
            elif circular and abs(v - v0) > _CIRCLE / 2:
                up = v < v0  # 359 -> 1: the direction grew past 360
                unwrapped = v + _CIRCLE if up else v - _CIRCLE
                edge, other = (_CIRCLE, 0.0) if up else (0.0, _CIRCLE)
                when = t0 + (t - t0) * (edge - v0) / (unwrapped - v0)
                x += [when, when, when]
                y += [edge, math.nan, other]
        x.append(t)
        y.append(v)
    return x, y


def _lines(series: _Series, timed: bool, label: str) -> list[_Line]:
    segments = _segments(series.times, timed)
    count = series.quantity.multiplexed
    if count < 2:
        return [_Line(label, *_polyline(series.times, series.values, segments, series.quantity.circular))]
    turns = _turns(series.values, segments, count)
    lines = []
    for turn in range(count):
        chosen = [i for i, t in enumerate(turns) if t == turn]
        if chosen:
            x, y = _polyline(
                [series.times[i] for i in chosen],
                [series.values[i] for i in chosen],
                [segments[i] for i in chosen],
                series.quantity.circular,
            )
            lines.append(_Line(f"{label} (turn {turn + 1}/{count})", x, y))
    return lines


def _unit_label(group: tuple[str, bool]) -> str:
    unit, circular = group
    meaning = UNITS.get(unit, "")
    meaning = re.split(r" \(|, ", meaning)[0]
    text = f"{meaning} ({unit})" if meaning and meaning != unit else unit
    return f"{text}, 0-360" if circular else text


def _labels(series: Iterable[_Series]) -> dict[tuple[str, str], str]:
    """A field's name as its label; with its table beside it when several tables carry it."""
    listed = list(series)
    names = [s.name for s in listed]
    return {(s.name, s.kind): s.name if names.count(s.name) == 1 else f"{s.name} ({s.kind})" for s in listed}


# --- The figure -------------------------------------------------------------------------------------


def figure(
    path: str,
    fields_text: str,
    *,
    size_text: str = "1200x800",
    variant: Variant,
    output_format: str | None = None,
) -> Any:
    """The matplotlib Figure of `fields_text` (comma-separated field names) in the capture at
    `path`; CliError for an unknown field, a field the capture lacks, or no matplotlib."""
    fields = _fields(fields_text)
    width, height = _size(size_text)
    output = output_table(output_format) if output_format else None
    pyplot = _pyplot()
    series, timed = _read(path, fields, variant, output)
    panels: dict[tuple[str, bool], list[_Series]] = {}
    for one in series:
        panels.setdefault(one.quantity.group, []).append(one)
    labels = _labels(series)
    figure_, axes = pyplot.subplots(
        len(panels),
        1,
        sharex=True,
        squeeze=False,
        figsize=(width / _DPI, height / _DPI),
        dpi=_DPI,
        layout="constrained",
    )
    for axis, (group, members) in zip(axes[:, 0], panels.items(), strict=True):
        for one in members:
            for line in _lines(one, timed, labels[(one.name, one.kind)]):
                axis.plot(line.x, line.y, label=line.label, linewidth=1)
        axis.set_ylabel(_unit_label(group))
        if group[1]:
            axis.set_ylim(0.0, _CIRCLE)
            axis.set_yticks([0.0, 90.0, 180.0, 270.0, 360.0])
        axis.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize="small")
        axis.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time since the capture's first packet (s)" if timed else "message number")
    figure_.suptitle(path)
    return figure_


def plot(path: str, out: str, *, fields_text: str, size_text: str, variant: Variant, output_format: str | None) -> int:
    """Write the PNG (to a temporary file renamed to `out`: an existing `out` is replaced whole or
    left as it was); CliError for an unknown field, a capture without it, or no matplotlib."""
    built = figure(path, fields_text, size_text=size_text, variant=variant, output_format=output_format)
    pyplot = _pyplot()
    temporary = None
    try:
        handle, temporary = tempfile.mkstemp(suffix=".png", prefix=".ilahrs-plot-", dir=os.path.dirname(out) or ".")
        with os.fdopen(handle, "wb") as stream:
            built.savefig(stream, format="png", dpi=_DPI)
        os.replace(temporary, out)
        temporary = None
    except OSError as exc:
        raise CliError(f"{out}: {exc.strerror or exc}") from exc
    finally:
        pyplot.close(built)
        if temporary is not None:
            os.unlink(temporary)
    return 0


# --- the subcommand -------------------------------------------------------------------------------


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    fields = ", ".join({name: None for table in plottable().values() for name in table})
    sub = commands.add_parser(
        "plot",
        help="plot fields of a capture to a PNG (needs matplotlib)",
        description="One panel per quantity (by the fields' units; heading 0-360 apart from signed angles), "
        "sharing the time axis; lines break at gaps in the output and where heading wraps; multiplexed fields "
        "(Vdd, Utermo of Table 6.4) are drawn one line per turn.",
        epilog=f"FIELD: {fields}. Example: ilahrs plot s.pcapng -o s.png --fields heading,pitch,roll,gyro_z",
    )
    sub.add_argument("file", metavar="FILE", help="pcapng file or raw byte dump")
    sub.add_argument("-o", "--output", required=True, metavar="OUT.png", help="the PNG to write")
    sub.add_argument(
        "--fields",
        default="heading,pitch,roll",
        metavar="FIELD,...",
        help="fields to plot (default heading,pitch,roll)",
    )
    sub.add_argument("--size", default="1200x800", metavar="WxH", help="image size in pixels (default 1200x800)")
    variant_argument(sub)
    output_format_argument(sub, None)
    return sub


def run(args: argparse.Namespace) -> int:
    """`ilahrs plot`."""
    return plot(
        args.file,
        args.output,
        fields_text=args.fields,
        size_text=args.size,
        variant=variant_named(args.variant),
        output_format=args.output_format,
    )
