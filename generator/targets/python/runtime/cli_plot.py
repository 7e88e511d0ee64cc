"""`ilahrs plot`: time series of chosen fields of a capture as a PNG, one panel per unit, with
axis labels and units. Needs matplotlib (the `plot` extra, or `pip install 'matplotlib>=3.8'`);
nothing else in the package does."""

from __future__ import annotations

import importlib
import re
from typing import Any, Final

from .cli_capture import open_source
from .cli_common import CliError, fields_of, lookup
from .cli_decode import CaptureDecoder, output_table
from .encodings import Variant
from .nmea import PahrSentence
from .payloads import PAYLOADS
from .pcapng import Direction

__all__ = ["plot"]

_DPI: Final = 100
_MAX_PIXELS: Final = 10000


def _units() -> dict[str, str]:
    """Field name -> its unit, from the device-to-host tables and the sentence."""
    units: dict[str, str] = {}
    for table in PAYLOADS.values():
        if table.DIRECTION == "device_to_host":
            for info in table.FIELDS:
                if info.type not in ("reserved", "char") and info.encoding is None:
                    units.setdefault(info.name, info.unit or "")
    for name, *_rest, unit in PahrSentence._SPEC:
        if name != "usw":
            units.setdefault(name, unit)
    return units


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


def _series(path: str, fields: list[str], variant: Variant, output: str | None) -> tuple[dict[str, Any], bool]:
    source = open_source(path)
    decoder = CaptureDecoder(context=source.kind == "pcapng", output=output, output_known=output is not None)
    series: dict[str, tuple[list[float], list[float]]] = {name: ([], []) for name in fields}
    index = 0
    try:
        for chunk in source.chunks():
            for message in decoder.feed(chunk):
                if message.direction != Direction.INBOUND or message.data is None:
                    continue
                index += 1
                values = fields_of(message.data, variant)
                x = message.time if message.time is not None else float(index)
                for name in fields:
                    value = values.get(name)
                    if isinstance(value, (int, float)):
                        series[name][0].append(x)
                        series[name][1].append(float(value))
    finally:
        source.close()
    return series, source.kind == "pcapng"


def plot(path: str, out: str, *, fields_text: str, size_text: str, variant: Variant, output_format: str | None) -> int:
    """Write the PNG; CliError for an unknown field, a capture without it, or no matplotlib."""
    units = _units()
    fields = [lookup("field", f.strip(), units) for f in fields_text.split(",") if f.strip()]
    if not fields:
        raise CliError("--fields names no field")
    width, height = _size(size_text)
    output = output_table(output_format) if output_format else None
    pyplot = _pyplot()
    series, timed = _series(path, fields, variant, output)
    empty = [name for name in fields if not series[name][0]]
    if len(empty) == len(fields):
        raise CliError(f"{path}: no message carries {', '.join(fields)} (for a raw dump, try --output-format)")
    panels: dict[str, list[str]] = {}
    for name in fields:
        if series[name][0]:
            panels.setdefault(units[name], []).append(name)
    figure, axes = pyplot.subplots(len(panels), 1, sharex=True, squeeze=False, figsize=(width / _DPI, height / _DPI))
    for axis, (unit, names) in zip(axes[:, 0], panels.items(), strict=True):
        for name in names:
            axis.plot(*series[name], label=name, linewidth=1)
        axis.set_ylabel(unit or "value")
        axis.legend(loc="upper right")
        axis.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time (s)" if timed else "message")
    figure.suptitle(path)
    try:
        figure.savefig(out, dpi=_DPI)
    except OSError as exc:
        raise CliError(f"{out}: {exc.strerror or exc}") from exc
    finally:
        pyplot.close(figure)
    return 0
