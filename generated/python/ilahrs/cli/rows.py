# Copied from generator/targets/python/runtime/cli/rows.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The rows of `ilahrs decode`: the kinds a row can have, its columns, its fields as text
(`row_fields`), the Message a row is made of, and `RowWriter`, which writes Messages as text, CSV
or JSON lines."""

from __future__ import annotations

import csv
import json
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Final, TextIO

from ..codec import Payload, date_text
from ..commands import COMMANDS, decode_command
from ..encodings import Variant, calibration_accuracy_deg, calibration_succeeded
from ..errors import IlahrsError
from ..nmea import PahrSentence
from ..payloads import PAYLOADS
from ..pcapng import Direction
from ..statemachine import command_event
from .common import SENTENCE_KIND, field_columns, fields_of, usw_text

__all__ = [
    "ACCURACY",
    "BASE_COLUMNS",
    "DAMAGED",
    "DIRECTIONS",
    "FAILED",
    "FORMATS",
    "SUCCEEDED",
    "UNDETERMINED",
    "Message",
    "RowWriter",
    "accuracy_value",
    "command_name",
    "csv_text",
    "decode_columns",
    "kinds",
    "outcome_value",
    "row_fields",
    "usw_value",
]


UNDETERMINED: Final = "frame"
"""The kind of a frame whose table the context does not tell."""
DAMAGED: Final = "damaged"
"""The kind of a row that reports damage: bytes that are no message, or an answer that never came."""
FORMATS: Final = ("text", "csv", "jsonl")
BASE_COLUMNS: Final = ("time", "direction", "kind", "offset", "packet", "length", "reason", "detail")
"""The first columns of every CSV row; the fields of the selected kinds follow (`decode_columns`)."""
ACCURACY: Final = "accuracy"
"""The column beside a calibration's success: its predicted accuracy in degrees (3 sigma)."""
SUCCEEDED: Final = "succeeded"
FAILED: Final = "failed"
DIRECTIONS: Final = {Direction.INBOUND: "in", Direction.OUTBOUND: "out"}


def kinds() -> list[str]:
    """Every message kind a row can have."""
    return [*PAYLOADS, SENTENCE_KIND, *COMMANDS, UNDETERMINED, DAMAGED]


def decode_columns(kinds: Iterable[str]) -> list[str]:
    """The field columns of `decode` rows of these kinds: `field_columns`, with `accuracy` after
    each calibration success."""
    result: list[str] = []
    for name in field_columns(kinds):
        result.append(name)
        if name in _CALIBRATION_FIELDS:
            result.append(ACCURACY)
    return result


_CALIBRATION_FIELDS: Final = frozenset(
    info.name for table in PAYLOADS.values() for info in table.FIELDS if info.encoding == "calibration_success"
)


def usw_value(raw: int) -> str:
    return usw_text(raw)


def outcome_value(raw: int) -> str:
    return SUCCEEDED if calibration_succeeded(raw) else FAILED


def accuracy_value(raw: int) -> float | None:
    return calibration_accuracy_deg(raw) if calibration_succeeded(raw) else None


def _date(value: float) -> object:
    text = date_text(value)
    return value if text is None else text  # not a date the encoding can give: the number as sent


def row_fields(data: Payload | PahrSentence, variant: Variant, *, raw: bool = False) -> dict[str, object]:
    """The fields of a `decode` row: `fields_of`, where in engineering units the Unit Status Word
    with no flag reads OK, a date reads YYYY-MM-DD (the nearest calendar date, E15) and a
    calibration's success reads succeeded or failed, its accuracy in degrees in `accuracy` (None
    when there is none). `raw`: every field as sent (`accuracy` None)."""
    fields = fields_of(data, variant, raw=raw)
    if isinstance(data, PahrSentence):
        if not raw:
            fields["usw"] = usw_value(data.usw)
        return fields
    result: dict[str, object] = {}
    for info in data.FIELDS:
        if info.type == "reserved":
            continue
        value = fields[info.name]
        sent = getattr(data, info.name)
        if info.encoding == "calibration_success":
            result[info.name] = value if raw else outcome_value(sent)
            result[ACCURACY] = None if raw else accuracy_value(sent)
            continue
        if not raw and info.encoding == "usw":
            value = usw_value(sent)
        elif not raw and info.encoding == "date":
            value = _date(sent)
        result[info.name] = value
    return result


@dataclass(frozen=True, slots=True)
class Message:
    """One row: when (seconds since the capture's first chunk, its last byte), which way, what,
    where (offset in its direction's bytes; the pcapng packet of its last byte), its bytes and its
    decoded payload or sentence. A damaged row has kind DAMAGED, a `reason` and a `detail`."""

    time: float | None
    direction: Direction
    kind: str
    offset: int
    raw: bytes
    data: Payload | PahrSentence | None = None
    packet: int | None = None
    reason: str | None = None
    detail: str | None = None


def command_name(raw: bytes, state: str) -> str:
    try:
        code, names = decode_command(raw)
    except IlahrsError:
        return UNDETERMINED
    return command_event(code, state) or names[0]


class RowWriter:
    """Writes Messages as text, CSV or JSON lines."""

    def __init__(self, out: TextIO, form: str, selected: Iterable[str], variant: Variant, *, raw: bool) -> None:
        self._out = out
        self._form = form
        self._variant = variant
        self._raw = raw
        self._columns = [*BASE_COLUMNS, *decode_columns(selected)]
        self._csv = csv.DictWriter(out, self._columns, extrasaction="ignore", lineterminator="\n")
        if form == "csv":
            self._csv.writeheader()

    def write(self, message: Message) -> None:
        fields = {} if message.data is None else row_fields(message.data, self._variant, raw=self._raw)
        stamp = None if message.time is None else round(message.time, 6)
        direction = DIRECTIONS[message.direction]
        base: dict[str, object] = {"direction": direction, "kind": message.kind, "offset": message.offset}
        base.update(packet=message.packet, length=len(message.raw), reason=message.reason, detail=message.detail)
        if self._form == "csv":
            row: dict[str, object] = {"time": "" if stamp is None else f"{stamp:.6f}", **base, **fields}
            self._csv.writerow(row)
        elif self._form == "jsonl":
            entry: dict[str, object] = {"time": stamp, **base, "raw": message.raw.hex(), "fields": fields}
            self._out.write(json.dumps(entry) + "\n")
        else:
            head = "-" if stamp is None else f"{stamp:.6f}"
            body = " ".join(f"{k}={_text(v)}" for k, v in fields.items())
            if message.kind == DAMAGED:
                where = f"offset={message.offset} length={len(message.raw)}"
                where += "" if message.packet is None else f" packet={message.packet}"
                body = f"{message.reason} {where}: {message.detail}"
            elif message.data is None and message.kind == UNDETERMINED:
                body = message.raw.hex(" ")
            self._out.write(f"{head:>12} {direction:<3} {message.kind} {body}".rstrip() + "\n")


def _text(value: object) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, str):
        return value if value and " " not in value else json.dumps(value)
    return str(value)


def csv_text(value: object) -> str:
    """One field as csv.writer (QUOTE_MINIMAL, lineterminator \\n) writes it."""
    if value is None:
        return ""
    text = str(value)
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text
