# Copied from generator/targets/python/runtime/cli/common.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""What the subcommands of `ilahrs` share: the one kind of error a user sees (CliError: one line,
exit status 2), name look-ups that suggest the closest valid name, key=value parsing, the rows of
decoded messages (every field in engineering units, or raw) and opening a port.

Standard library only; pyserial is imported by `ilahrs.serial` when a port is opened.
"""

from __future__ import annotations

import difflib
import errno
import math
from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Final

from ..codec import FieldInfo, Payload, date_from_text, field_kind
from ..encodings import VARIANTS, Variant, calibration_accuracy_deg, calibration_succeeded
from ..errors import IlahrsError
from ..nmea import PahrSentence
from ..payloads import PAYLOADS
from ..spec import SERIAL_LINE
from ..status import USW_FAILURE_FLAGS, USW_WARNING_FLAGS, UnitStatusWord, UswFlag

if TYPE_CHECKING:
    from ..edge.serial import AhrsClient

__all__ = [
    "BAUDRATE",
    "SENTENCE_KIND",
    "USW_CLEAR",
    "CliError",
    "field_columns",
    "fields_of",
    "lookup",
    "open_client",
    "parse_assignments",
    "usw_text",
    "variant_named",
]

BAUDRATE: Final = int(SERIAL_LINE["baud_rate"])
"""The AHRS line's baud rate (section 6): the default of every port argument."""
SENTENCE_KIND: Final = PahrSentence.IDENTIFIER
"""The message kind of a $PAHR sentence in decoded rows."""
_BUSY: Final = {errno.EAGAIN, errno.EWOULDBLOCK}
"""The errno of a port another client holds (AhrsClient locks device paths)."""
USW_CLEAR: Final = "OK"
"""The Unit Status Word with no flag set, in readiness mode."""
_USW_SEPARATOR: Final = "|"
_USW_FLAGS: Final = USW_FAILURE_FLAGS.value | USW_WARNING_FLAGS.value
_USW_NAMES: Final = [(flag.value, flag.name or "") for flag in UswFlag]
"""Each flag's value and name, in the order of `UswFlag` (that of the names in usw_text)."""


class CliError(Exception):
    """Bad input or an unreachable device: printed as one line on stderr, exit status 2."""


def lookup(kind: str, name: str, choices: Iterable[str]) -> str:
    """`name` if it is one of `choices` (exactly, else ignoring case); CliError suggesting the
    closest valid name otherwise."""
    names = list(choices)
    if name in names:
        return name
    folded = {n.lower(): n for n in names}
    if name.lower() in folded:
        return folded[name.lower()]
    close = difflib.get_close_matches(name, names, n=1, cutoff=0.5)
    close = close or difflib.get_close_matches(name.lower(), list(folded), n=1, cutoff=0.5)
    hint = f"; did you mean {folded.get(close[0], close[0])}?" if close else f" (one of {', '.join(names)})"
    raise CliError(f"unknown {kind} {name!r}{hint}")


def variant_named(name: str | None) -> Variant:
    """The variant called `name` (the first the spec lists when None)."""
    if name is None:
        return next(iter(VARIANTS.values()))
    return VARIANTS[lookup("variant", name, VARIANTS)]


def _number(text: str) -> int | float | str:
    try:
        return int(text, 0)
    except ValueError:
        pass
    try:
        value = float(text)
    except ValueError:
        return text
    return value if math.isfinite(value) else text


def parse_assignments(table: type[Payload], items: Iterable[str]) -> dict[str, object]:
    """key=value words -> raw field values of `table` (names checked, values checked by the
    caller's from_raw); a field in the date encoding also takes a calendar date YYYY-MM-DD."""
    names = [f.name for f in table.FIELDS if f.type != "reserved"]
    kinds = {f.name: field_kind(f) for f in table.FIELDS}
    dates = {f.name for f in table.FIELDS if f.encoding == "date"}
    values: dict[str, object] = {}
    for item in items:
        key, sep, text = item.partition("=")
        if not sep:
            raise CliError(f"{item!r} is not key=value (fields of {table.NAME}: {', '.join(names)})")
        key = lookup(f"field of {table.NAME}", key.strip(), names)
        value = text if kinds[key] == "char" else _number(text.strip())
        if isinstance(value, str) and key in dates:
            try:
                value = date_from_text(text)
            except IlahrsError as exc:
                raise CliError(f"{key}={text!r}: not a date YYYY-MM-DD nor a number") from exc
        if isinstance(value, str) and kinds[key] != "char":
            raise CliError(f"{key}={text!r}: not a number")
        if kinds[key] == "float" and isinstance(value, int):
            value = float(value)
        values[key] = value
    return values


def usw_text(raw: int) -> str:
    """A Unit Status Word as the names of its flags (and its mode when not readiness), joined by
    '|'; USW_CLEAR when no flag is set in readiness mode (never empty, which reads as missing)."""
    word = UnitStatusWord(raw)
    flags = raw & _USW_FLAGS
    names = [name for value, name in _USW_NAMES if flags & value == value]
    if word.mode.value != "readiness":
        names.append(str(word.mode.value).upper())
    return _USW_SEPARATOR.join(names) or USW_CLEAR


def _field_value(info: FieldInfo, raw: object, values: Mapping[str, float], *, as_raw: bool) -> object:
    if as_raw or isinstance(raw, (str, bytes)):
        return raw.hex() if isinstance(raw, bytes) else raw
    if info.encoding == "usw" and isinstance(raw, int):
        return usw_text(raw)
    if info.encoding == "calibration_success" and isinstance(raw, int):
        accuracy = calibration_accuracy_deg(raw)
        return accuracy if calibration_succeeded(raw) and accuracy is not None else raw
    return values.get(info.name, raw)


def fields_of(data: Payload | PahrSentence, variant: Variant, *, raw: bool = False) -> dict[str, object]:
    """Every field of a decoded message: engineering units (USW as named flags), or raw values."""
    if isinstance(data, PahrSentence):
        sentence = {name: getattr(data, name) for name in data.FIELDS}
        if raw:
            return dict(sentence)
        result: dict[str, object] = dict(data.values())
        result["usw"] = usw_text(data.usw)
        return result
    values = data.values(variant)
    return {
        info.name: _field_value(info, getattr(data, info.name), values, as_raw=raw)
        for info in data.FIELDS
        if info.type != "reserved"
    }


def field_columns(kinds: Iterable[str]) -> list[str]:
    """The field columns of the given message kinds (payload tables, the sentence), in spec order,
    each name once."""
    wanted = set(kinds)
    columns: dict[str, None] = {}
    for name, table in PAYLOADS.items():
        if name in wanted:
            columns.update((f.name, None) for f in table.FIELDS if f.type != "reserved")
    if SENTENCE_KIND in wanted:
        columns.update((name, None) for name in PahrSentence.FIELDS)
    return list(columns)


def open_client(port: str, baud: int = BAUDRATE, *, timeout: float = 1.0, strict: bool = False) -> AhrsClient:
    """An AhrsClient on `port` (a device path or socket://HOST:PORT) at `baud` (`strict`: see
    AhrsClient); CliError when the port cannot be opened, another process holds it, or pyserial
    is missing."""
    try:
        from ..edge.serial import AhrsClient
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise CliError(f"{exc}") from exc
    try:
        client = AhrsClient(port, timeout=timeout, strict=strict, baud=baud)
    except ImportError as exc:
        raise CliError(str(exc)) from exc
    except (OSError, ValueError) as exc:
        if getattr(exc, "errno", None) in _BUSY:  # the lock AhrsClient takes on a device path
            raise CliError(f"{port} is in use by another process") from exc
        raise CliError(f"cannot open {port}: {_reason(exc)}") from exc
    return client


def _reason(exc: BaseException) -> str:
    text = str(exc)
    if "] " in text:  # pyserial: "[Errno 2] could not open port X: [Errno 2] No such file..."
        text = text.rsplit("] ", 1)[-1]
    return text or type(exc).__name__
