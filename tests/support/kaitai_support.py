"""The Kaitai-compiled parsers of generated/kaitai/ilahrs.ksy, read the way the ilahrs binding reads.

`make build-kaitai` compiles the .ksy with the official compiler (ksc 0.11) into a Kaitai Python
parser (build/kaitai/python/ilahrs.py, runtime `kaitaistruct`) and a `construct` definition
(build/kaitai/construct/ilahrs.py). Both modules are called `ilahrs`, like the binding, so they
are loaded from their files under other names. Everything here takes names and shapes from the
spec model or from the .ksy itself; nothing about the protocol is written down twice.
"""

from __future__ import annotations

import functools
import importlib.util
import io
import math
import random
import struct
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

import yaml
from kaitaistruct import EndOfStreamError, KaitaiStream, ValidationFailedError

from generator import build_spec
from generator.model import Field, Payload, Spec, Variant
from generator.naming import pascal
from generator.targets.kaitai.filters import (
    constant_scaled,
    engineering_id,
    scaled_type_id,
    variant_parameters,
    variant_scaled,
)

ROOT = Path(__file__).resolve().parents[2]
KSY = ROOT / "generated" / "kaitai" / "ilahrs.ksy"
KAITAI_BUILD = ROOT / "build" / "kaitai"

Raw = dict[str, int | float | str | bytes]

# Bytes a Kaitai primitive type reads (the .ksy uses meta/endian, so no suffix).
KSY_TYPE_SIZES = {"u1": 1, "s1": 1, "u2": 2, "s2": 2, "u4": 4, "s4": 4, "f4": 4, "f8": 8}


class KaitaiBuildMissingError(RuntimeError):
    """The compiled parsers are absent or older than the .ksy."""


@functools.cache
def spec() -> Spec:
    return build_spec()


@functools.cache
def ksy() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(KSY.read_text(encoding="utf-8"))
    return data


def _load(kind: str) -> ModuleType:
    path = KAITAI_BUILD / kind / f"{spec().name}.py"
    if not path.is_file():
        raise KaitaiBuildMissingError(f"{path.relative_to(ROOT)} is missing: run `make build-kaitai`")
    if path.stat().st_mtime < KSY.stat().st_mtime:
        stale = f"{path.relative_to(ROOT)} is older than {KSY.relative_to(ROOT)}"
        raise KaitaiBuildMissingError(f"{stale}: run `make build-kaitai`")
    module_spec = importlib.util.spec_from_file_location(f"{spec().name}_{kind}", path)
    assert module_spec is not None and module_spec.loader is not None
    module = importlib.util.module_from_spec(module_spec)
    module_spec.loader.exec_module(module)
    return module


@functools.cache
def kaitai_module() -> ModuleType:
    """The Kaitai Python parser (ksc `python` target)."""
    return _load("python")


@functools.cache
def construct_module() -> ModuleType:
    """The `construct` definition (ksc `construct` target)."""
    return _load("construct")


def kaitai_root() -> Any:
    """The top-level Kaitai class: one frame."""
    return getattr(kaitai_module(), pascal(spec().name))


def kaitai_type(name: str) -> Any:
    """The Kaitai class of a .ksy type, e.g. `full_output` -> Ilahrs.FullOutput."""
    return getattr(kaitai_root(), pascal(name))


def construct_type(name: str | None = None) -> Any:
    """The construct of a .ksy type (`None`: the frame)."""
    top = spec().name
    return getattr(construct_module(), top if name is None else f"{top}__{name}")


def stream(data: bytes) -> KaitaiStream:
    return KaitaiStream(io.BytesIO(data))


# --- errors ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Refusal:
    """An input refused as the spec says: kind, byte offset, field (None where none applies)."""

    kind: str
    offset: int | None
    field: str | None


class KaitaiRefusedError(Exception):
    """The Kaitai parser refused the input; `refusal` is the spec's error for it."""

    def __init__(self, refusal: Refusal) -> None:
        super().__init__(f"{refusal.kind} at {refusal.offset} ({refusal.field})")
        self.refusal = refusal


def _attribute(src_path: str) -> dict[str, Any]:
    """The .ksy attribute a Kaitai `src_path` ("/seq/4", "/types/x/seq/0") points at."""
    node: Any = ksy()
    for part in src_path.strip("/").split("/"):
        node = node[int(part)] if isinstance(node, list) else node[part]
    assert isinstance(node, dict)
    return node


def _attribute_size(attr: dict[str, Any]) -> int:
    if "contents" in attr:
        return len(attr["contents"])
    return KSY_TYPE_SIZES[attr["type"]]


def refusal(exc: Exception, data: bytes) -> Refusal:
    """The spec's error for a Kaitai exception raised while parsing `data` from its start.

    A failed `valid` or `contents` check names its error kind in the attribute's
    `-ilahrs-error` key; it is at the attribute's first byte (the stream has just read it).
    Running out of input is `truncated` at the input length.
    """
    if isinstance(exc, ValidationFailedError) and exc.src_path is not None:
        attr = _attribute(exc.src_path)
        error = attr["-ilahrs-error"]
        return Refusal(error["kind"], exc.io.pos() - _attribute_size(attr), error["field"])
    if isinstance(exc, EndOfStreamError):
        return Refusal("truncated", len(data), None)
    raise exc


def decode_frame(data: bytes) -> Any:
    """Parse exactly one frame with the Kaitai parser; Refusal-carrying KaitaiRefusedError otherwise."""
    io_ = stream(data)
    try:
        frame = kaitai_root()(io_)
    except (ValidationFailedError, EndOfStreamError) as exc:
        raise KaitaiRefusedError(refusal(exc, data)) from exc
    if not io_.is_eof():
        raise KaitaiRefusedError(Refusal("trailing_data", io_.pos(), None))
    return frame


def decode_payload(name: str, data: bytes) -> Any:
    """Parse exactly one payload of table `name` with the Kaitai parser."""
    io_ = stream(data)
    try:
        payload = kaitai_type(name)(io_)
    except (ValidationFailedError, EndOfStreamError) as exc:
        raise KaitaiRefusedError(refusal(exc, data)) from exc
    if not io_.is_eof():
        raise KaitaiRefusedError(Refusal("trailing_data", io_.pos(), None))
    return payload


# --- payload values -------------------------------------------------------------------


def _raw_value(field: Field, value: Any) -> int | float | str | bytes:
    if field.encoding == "usw":
        value = value.value
    if field.is_integer:
        return int(value)  # enum members are IntEnum (Kaitai) or EnumIntegerString (construct)
    if field.is_float:
        return float(value)
    if field.kind == "char":
        return str(value)
    return bytes(value)


def kaitai_raw(payload: Payload, obj: Any) -> Raw:
    """A Kaitai-parsed payload as the binding's `raw()` dict (table order)."""
    return {f.name: _raw_value(f, getattr(obj, f.name)) for f in payload.fields}


def construct_raw(payload: Payload, container: Any) -> Raw:
    """A construct-parsed payload as the binding's `raw()` dict (table order)."""
    result: Raw = {}
    for f in payload.fields:
        value = container[f.name]
        if f.enum is not None and hasattr(value, "int"):
            value = value.int  # construct's EnumIntegerString
        result[f.name] = _raw_value(f, value)
    return result


def construct_input(payload: Payload, raw: Raw) -> dict[str, Any]:
    """The binding's raw dict as what construct builds from (a status word is a struct)."""
    return {f.name: {"value": raw[f.name]} if f.encoding == "usw" else raw[f.name] for f in payload.fields}


def kaitai_values(payload: Payload, obj: Any, variant: Variant | None = None) -> dict[str, float]:
    """Engineering values from the .ksy's value instances; variant-dependent ones need `variant`.

    Those live in the parametric type `<payload>_scaled(payload, <variant parameters>)`.
    """
    result = {f.name: float(getattr(obj, engineering_id(f))) for f in constant_scaled(payload)}
    if variant is not None and variant_scaled(payload):
        parameters = [float(variant.value(p)) for p in variant_parameters(payload)]
        scaled = kaitai_type(scaled_type_id(payload))(obj, *parameters, stream(b""))
        result.update({f.name: float(getattr(scaled, engineering_id(f))) for f in variant_scaled(payload)})
    return {f.name: result[f.name] for f in payload.scaled_fields if f.name in result}


def same_raw(a: Raw, b: Raw) -> bool:
    """Equal field by field; floats compared by their bits (NaN equals the same NaN)."""
    if list(a) != list(b):
        return False
    for key, x in a.items():
        y = b[key]
        if isinstance(x, float) and isinstance(y, float):
            if struct.pack("<d", x) != struct.pack("<d", y):
                return False
        elif type(x) is not type(y) or x != y:
            return False
    return True


# --- deterministic inputs -------------------------------------------------------------


def f32(value: float) -> float:
    """`value` rounded to float32, as the wire carries it."""
    result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    return result


def valid_raw(payload: Payload, rng: random.Random) -> Raw:
    """Raw values a builder accepts, drawn from the model's bounds and encodings."""
    model = spec()
    raw: Raw = {}
    for f in payload.fields:
        raw[f.name] = _valid_value(f, model, rng)
    return raw


def _valid_value(f: Field, model: Spec, rng: random.Random) -> int | float | str | bytes:
    if f.kind == "reserved":
        return rng.randbytes(f.size)
    if f.kind == "char":
        # Any Latin-1 text that fits, NULs inside but not at the end (decoders strip those).
        return "".join(chr(rng.randrange(256)) for _ in range(rng.randrange(f.size + 1))).rstrip("\x00")
    if f.encoding == "date" and model.date is not None:
        return f32(rng.uniform(model.date.year_min, model.date.year_max + 1))
    if f.encoding == "declination" and model.declination is not None:
        d = model.declination
        return f32(rng.choice([rng.uniform(d.min, d.max), float(d.compute_value)]))
    bounds = f.bounds
    assert bounds is not None, f.name
    low, high = bounds
    if f.is_integer:
        return rng.choice([int(low), int(high), rng.randint(int(low), int(high))])
    if f.range is None:
        # No range: any finite float32, drawn by its bits so every magnitude appears.
        while True:
            value: float = struct.unpack("<f", rng.randbytes(4))[0]
            if math.isfinite(value):
                return value
    return f32(rng.choice([low, high, rng.uniform(low, high)]))


def output_tables() -> list[Payload]:
    """The tables a command starts as continuous or on-request output (Tables 6.4-6.6)."""
    names = {c.starts_output for c in spec().commands if c.starts_output is not None}
    return [p for p in spec().payloads if p.name in names]


def random_frame_payloads(rng: random.Random, count: int) -> list[tuple[Payload, bytes]]:
    """`count` (table, payload bytes) pairs: every table in turn, the output tables thrice as often."""
    outputs = output_tables()
    tables: list[Payload] = []
    for p in spec().payloads:
        tables.extend([p] * (3 if p in outputs else 1))
    return [(table, rng.randbytes(table.size)) for table in (tables[i % len(tables)] for i in range(count))]
