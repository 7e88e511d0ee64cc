# Copied from generator/targets/python/runtime/codec.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""What every payload class is made of: its field table (FieldInfo), the Payload protocol, and the
code that decodes, checks and encodes a payload by walking the table (PayloadBase).

A payload class (`ilahrs.payloads`) declares NAME, SIZE, FIELDS and the `struct` layout of its
fields, and its fields as dataclass fields in wire order; everything else is here.
"""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar, Final, Protocol, TypeVar

from .encodings import VARIANTS, Variant, declination_is_valid, decode_date, encode_date
from .errors import ErrorKind, IlahrsError, brief, require_bytes, suggest
from .valuecodec import FLOAT32_MAX

__all__ = [
    "FLOAT32_MAX",
    "Buffer",
    "FieldInfo",
    "JsonValue",
    "Payload",
    "PayloadBase",
    "date_from_text",
    "date_text",
    "field_kind",
    "field_text",
    "float32_text",
    "maker",
    "required_variant",
    "variant_of",
]

Buffer = bytes | bytearray | memoryview
JsonValue = int | float | str | None
"""A value `json.dumps` writes as standard JSON."""


def variant_of(variant: Variant | str | None) -> Variant | None:
    """A device variant from a Variant or its name (a key of ilahrs.VARIANTS); None stays None.
    IlahrsError(OUT_OF_RANGE) for anything else."""
    if variant is None or isinstance(variant, Variant):
        return variant
    if isinstance(variant, str) and variant in VARIANTS:
        return VARIANTS[variant]
    detail = f"{brief(variant)} is not a variant: one of {', '.join(VARIANTS)} or a Variant{suggest(variant, VARIANTS)}"
    raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "variant", detail)


def required_variant(variant: Variant | str) -> Variant:
    """`variant_of` for an accessor that needs a variant: None is refused too."""
    found = variant_of(variant)
    if found is None:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "variant", "this value needs the device variant (KG, KA)")
    return found


_P = TypeVar("_P")
"""The class a classmethod is called on (typing.Self, which needs Python 3.11)."""
_B = TypeVar("_B", bound="PayloadBase")


@dataclass(frozen=True, slots=True)
class FieldInfo:
    """Where and what a field is: name, ICD spelling, offset, size, wire type, unit and scale;
    `low`..`high`, the raw values a builder accepts (None for text and reserved bytes); the value
    `encoding` it follows (usw, date, declination, calibration_success), if any; and how many
    quantities it carries in turn in successive frames (`multiplexed`, 0 for one)."""

    name: str
    icd_name: str
    offset: int
    size: int
    type: str
    unit: str | None
    multiplier: int
    divisor: int | str
    low: float | None = None
    high: float | None = None
    encoding: str | None = None
    multiplexed: int = 0


def field_kind(info: FieldInfo) -> str:
    """What a field's wire type holds: "integer", "float", "char" (text) or "reserved" (bytes)."""
    if info.type in ("char", "reserved"):
        return info.type
    return "float" if info.type == "f32" else "integer"


_FLOAT32: Final = struct.Struct("<f")
_ISO_DATE: Final = re.compile(r"([0-9]{4})-([0-9]{2})-([0-9]{2})")


def float32_text(value: float) -> str:
    """The shortest decimal text that reads back as the same float32 as `value` (3.3 for the
    float32 nearest 3.3, 3.299999952316284 as a float64)."""
    if not math.isfinite(value) or abs(value) > FLOAT32_MAX:
        return repr(float(value))
    wire = _FLOAT32.pack(value)
    for digits in range(1, 10):
        text = f"{value:.{digits}g}"
        if _FLOAT32.pack(float(text)) == wire:
            return repr(float(text))
    return repr(float(value))  # pragma: no cover - 9 digits always round-trip a float32


def field_text(info: FieldInfo, value: object) -> str:
    """A raw field value as a user reads and writes it: a field in the date encoding as its
    calendar date (YYYY-MM-DD, the raw number if it is no date), a float32 as its shortest text
    (float32_text), anything else as str()."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    if info.encoding == "date":
        date = date_text(value)
        return float32_text(value) if date is None else date
    if info.type == "f32":
        return float32_text(value)
    return str(value)


def date_text(value: float) -> str | None:
    """The calendar date of a float in the date encoding, YYYY-MM-DD (the nearest valid date,
    E15); None when no date encodes near it."""
    try:
        year, month, day = decode_date(value)
    except IlahrsError:
        return None
    return f"{year:04d}-{month:02d}-{day:02d}"


def date_from_text(text: str) -> float:
    """The date float (the ICD's date encoding) of a calendar date written YYYY-MM-DD;
    IlahrsError(OUT_OF_RANGE) for other text or an invalid date."""
    match = _ISO_DATE.fullmatch(text.strip()) if isinstance(text, str) else None
    if match is None:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "date", f"{brief(text)} is not a date YYYY-MM-DD")
    year, month, day = (int(part) for part in match.groups())
    return encode_date(year, month, day)


class Payload(Protocol):
    """What every payload class offers."""

    NAME: ClassVar[str]
    ICD: ClassVar[str]
    TITLE: ClassVar[str]
    SIZE: ClassVar[int]
    DIRECTION: ClassVar[str]
    """host_to_device or device_to_host."""
    FIELDS: ClassVar[tuple[FieldInfo, ...]]

    @classmethod
    def parse(cls: type[_P], data: Buffer) -> _P: ...

    @classmethod
    def from_raw(cls: type[_P], values: Mapping[str, object]) -> _P: ...

    def build(self) -> bytes: ...

    def check(self) -> None: ...

    def raw(self) -> dict[str, int | float | str | bytes]: ...

    def values(self, variant: Variant | str | None = None) -> dict[str, float]: ...

    def json(self) -> dict[str, JsonValue]: ...


def _size_error(size: int, expected: int) -> IlahrsError:
    if size < expected:
        return IlahrsError(ErrorKind.TRUNCATED, size, None, f"payload of {size} bytes, expected {expected}")
    return IlahrsError(ErrorKind.TRAILING_DATA, expected, None, f"payload of {size} bytes, expected {expected}")


def _text(raw: bytes) -> str:
    return raw.rstrip(b"\x00").decode("latin-1")


def _check_int(value: object, low: int, high: int, name: str, offset: int) -> None:
    if isinstance(value, bool) or not isinstance(value, int):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{brief(value)} is not an integer")
    if not low <= value <= high:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{value} outside {low}..{high}")


def _check_float(value: object, low: float, high: float, name: str, offset: int) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{brief(value)} is not a number")
    if isinstance(value, int) and abs(value) > FLOAT32_MAX:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{brief(value)} outside {low!r}..{high!r}")
    if not math.isfinite(value) or not low <= value <= high:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{brief(value)} outside {low!r}..{high!r}")


def _check_declination(value: object, name: str, offset: int) -> None:
    _check_float(value, -FLOAT32_MAX, FLOAT32_MAX, name, offset)
    assert isinstance(value, (int, float))
    if not declination_is_valid(value):
        detail = f"{brief(value)} is neither a declination nor the compute request"
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, detail)


def _check_text(value: object, size: int, name: str, offset: int) -> None:
    if not isinstance(value, str):
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{brief(value)} is not text")
    try:
        encoded = value.encode("latin-1")
    except UnicodeEncodeError as exc:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, "text must be Latin-1") from exc
    if len(encoded) > size:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"{len(encoded)} bytes do not fit {size}")


def _check_bytes(value: object, size: int, name: str, offset: int) -> None:
    if not isinstance(value, (bytes, bytearray)) or len(value) != size:
        raise IlahrsError(ErrorKind.OUT_OF_RANGE, offset, name, f"needs exactly {size} bytes")


def _check_field(info: FieldInfo, value: object) -> None:
    """Raise IlahrsError(OUT_OF_RANGE) if a builder must refuse `value` for the field."""
    kind = field_kind(info)
    if info.encoding == "declination":
        _check_declination(value, info.name, info.offset)
    elif kind in ("char", "reserved"):
        check = _check_text if kind == "char" else _check_bytes
        check(value, info.size, info.name, info.offset)
    else:
        assert info.low is not None and info.high is not None
        if kind == "float":
            _check_float(value, info.low, info.high, info.name, info.offset)
        else:
            _check_int(value, int(info.low), int(info.high), info.name, info.offset)


_MAKERS: dict[type, Callable[..., Any]] = {}


def maker(cls: type[_B]) -> Callable[..., _B]:
    """A function building `cls(*values)` from a payload class's field values in wire order,
    several times faster. A frozen dataclass sets each field through object.__setattr__; this sets
    them on an unfrozen twin class with the same slots and then gives the object its class, so the
    result is the same immutable object (equal, same type, same hash). No field is checked, as
    in `cls(*values)`. A class the twin cannot stand in for (no matching slots, a __post_init__)
    gets `cls` itself."""
    found = _MAKERS.get(cls)
    if found is None:
        found = _MAKERS[cls] = _twin_maker(cls)
    return found


def _twin_maker(cls: type[_B]) -> Callable[..., _B]:
    names = tuple(info.name for info in cls.FIELDS)
    if cls.__dict__.get("__slots__") != names or hasattr(cls, "__post_init__"):
        return cls
    try:
        twin = type(f"_{cls.__name__}Fields", cls.__bases__, {"__slots__": names, "FIELDS": cls.FIELDS})
        params = ", ".join(f"v{index}" for index in range(len(names)))
        lines = [f"def make({params}):", "    o = _new(_twin)"]
        lines += [f"    o.{name} = v{index}" for index, name in enumerate(names)]
        lines += ["    o.__class__ = _cls", "    return o"]
        scope: dict[str, Any] = {"_new": object.__new__, "_twin": twin, "_cls": cls}
        exec("\n".join(lines), scope)  # the source is built from field names only
        make: Callable[..., _B] = scope["make"]
        sample = cls._STRUCT.unpack(bytes(cls.SIZE))
        if make(*sample) != cls(*sample):
            return cls
    except (TypeError, AttributeError):
        return cls
    return make


class PayloadBase:
    """The code of every payload class: exact-inverse `parse` and `build`, `from_raw`, `check`
    and `raw`, all read from the class's FIELDS and _STRUCT."""

    __slots__ = ()

    NAME: ClassVar[str]
    SIZE: ClassVar[int]
    FIELDS: ClassVar[tuple[FieldInfo, ...]]
    _STRUCT: ClassVar[struct.Struct]
    _TEXT: ClassVar[tuple[int, ...]] = ()
    """The indices of the text fields: bytes on the wire, str in the class."""

    if TYPE_CHECKING:

        def __init__(self, *values: Any, **named: Any) -> None: ...

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls._TEXT = tuple(index for index, info in enumerate(cls.FIELDS) if info.type == "char")

    @classmethod
    def parse(cls: type[_B], data: Buffer) -> _B:
        """Decode exactly SIZE bytes (truncated / trailing_data otherwise; MALFORMED for a value that
        is not a byte string)."""
        data = require_bytes(data, "data")
        if len(data) != cls.SIZE:
            raise _size_error(len(data), cls.SIZE)
        make: Callable[..., _B] = _MAKERS.get(cls) or maker(cls)
        if not cls._TEXT:
            return make(*cls._STRUCT.unpack(data))
        values: list[Any] = list(cls._STRUCT.unpack(data))
        for index in cls._TEXT:
            values[index] = _text(values[index])
        return make(*values)

    @classmethod
    def from_raw(cls: type[_B], values: Mapping[str, object]) -> _B:
        """Build from raw field values (missing fields take their defaults); checked like `build()`."""
        if not isinstance(values, Mapping):
            raise IlahrsError(ErrorKind.MALFORMED, None, None, f"{brief(values)} is not a mapping of field values")
        known = {info.name for info in cls.FIELDS}
        for key in values:
            if key not in known:
                detail = f"{cls.NAME} has no field {brief(key)}{suggest(key, known)}"
                raise IlahrsError(ErrorKind.MALFORMED, None, key if isinstance(key, str) else None, detail)
        result = cls(**values)
        result.check()
        return result

    def check(self) -> None:
        """Raise IlahrsError(OUT_OF_RANGE) for the first field a builder must refuse."""
        for info in self.FIELDS:
            _check_field(info, getattr(self, info.name))

    def build(self) -> bytes:
        """Encode the SIZE-byte payload; refuse out-of-range values."""
        self.check()
        values = [getattr(self, info.name) for info in self.FIELDS]
        for index in self._TEXT:
            values[index] = values[index].encode("latin-1")
        return self._STRUCT.pack(*values)

    def raw(self) -> dict[str, int | float | str | bytes]:
        """Every field's raw value, in table order."""
        return {info.name: getattr(self, info.name) for info in self.FIELDS}

    def json(self) -> dict[str, JsonValue]:
        """Every field's raw value, ready for `json.dumps` (standard JSON): reserved bytes as hex
        text, a float field's NaN or infinity as None."""
        result: dict[str, JsonValue] = {}
        for name, value in self.raw().items():
            if isinstance(value, bytes):
                result[name] = value.hex()
            elif isinstance(value, float) and not math.isfinite(value):
                result[name] = None
            else:
                result[name] = value
        return result
