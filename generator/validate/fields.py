"""Validation of one field of the frame or a payload (part of generator.validate): a known type
with the right size, references that exist, and a range and default the type can hold."""

from __future__ import annotations

import math
from typing import Any

from ..load import LoadedSpec, PathKey
from ..model.fields import FLOAT32_MAX, PRIMITIVES, Primitive
from .common import Names

# The field types each encoding may have.
ENCODING_TYPES = {"usw": ("u16",), "date": ("f32",), "declination": ("f32",), "calibration_success": ("u8",)}

NUMERIC_KINDS = ("unsigned", "signed", "float")


def check_field(spec: LoadedSpec, f: dict[str, Any], path: PathKey, names: Names) -> None:
    """Raise SpecError for the first problem with field `f` at `path`."""
    primitive = _check_type(spec, f, path)
    _check_references(spec, f, path, names)
    if "encoding" in f:
        _check_encoding(spec, f, path, names)
    if "range" in f:
        _check_range(spec, f, path, primitive)
    if "default" in f:
        _check_default(spec, f, path, primitive)
    if "erratum" in f and f["erratum"] not in names.errata:
        raise spec.error((*path, "erratum"), f"unknown erratum {f['erratum']!r}")


def _check_type(spec: LoadedSpec, f: dict[str, Any], path: PathKey) -> Primitive:
    """A known type; a length exactly when the type has no fixed size; no numeric key on text."""
    type_name = f["type"]
    if type_name not in PRIMITIVES:
        known = ", ".join(PRIMITIVES)
        raise spec.error((*path, "type"), f"unknown type {type_name!r} (known: {known})")
    primitive = PRIMITIVES[type_name]
    if primitive.size is None and "length" not in f:
        raise spec.error(path, f"a {type_name} field needs a length")
    if primitive.size is not None and "length" in f:
        raise spec.error((*path, "length"), f"a {type_name} field has a fixed size; length is not allowed")
    if primitive.kind not in NUMERIC_KINDS:
        for key in ("scale", "unit", "range", "enum", "encoding", "multiplexed"):
            if key in f:
                raise spec.error((*path, key), f"{key} on non-numeric field {f['name']!r} of type {type_name}")
    return primitive


def _check_references(spec: LoadedSpec, f: dict[str, Any], path: PathKey, names: Names) -> None:
    """The unit, the variant parameter a scale divides by and the enum exist; a scale has a unit."""
    if "unit" in f and f["unit"] not in names.units:
        raise spec.error((*path, "unit"), f"unknown unit {f['unit']!r}")
    if "scale" in f:
        divisor = f["scale"].get("divisor")
        if isinstance(divisor, str) and divisor not in names.variant_parameters:
            raise spec.error((*path, "scale", "divisor"), f"unknown variant parameter {divisor!r}")
        if "unit" not in f:
            raise spec.error((*path, "scale"), f"scaled field {f['name']!r} has no unit")
    if "enum" in f and f["enum"] not in names.enums:
        raise spec.error((*path, "enum"), f"unknown enum {f['enum']!r}")


def _check_encoding(spec: LoadedSpec, f: dict[str, Any], path: PathKey, names: Names) -> None:
    encoding = f["encoding"]
    if encoding != "usw" and encoding not in names.encodings:
        raise spec.error((*path, "encoding"), f"encoding {encoding!r} is not defined under `encodings`")
    if encoding == "usw" and names.status_word is None:
        raise spec.error((*path, "encoding"), "encoding 'usw' needs a `status_word` section")
    if f["type"] not in ENCODING_TYPES[encoding]:
        raise spec.error(
            (*path, "encoding"), f"encoding {encoding!r} needs type {ENCODING_TYPES[encoding][0]}, not {f['type']}"
        )


def _check_range(spec: LoadedSpec, f: dict[str, Any], path: PathKey, primitive: Primitive) -> None:
    """Low first; integers within the type for an integer field, finite float32 values for a float."""
    low, high = f["range"]
    if low > high:
        raise spec.error((*path, "range"), f"range [{low}, {high}] is empty")
    if primitive.kind in ("unsigned", "signed"):
        assert primitive.min is not None and primitive.max is not None
        if not (isinstance(low, int) and isinstance(high, int)):
            raise spec.error((*path, "range"), "the range of an integer field must be integers")
        if low < primitive.min or high > primitive.max:
            raise spec.error(
                (*path, "range"),
                f"range [{low}, {high}] does not fit type {f['type']} [{primitive.min}, {primitive.max}]",
            )
    elif primitive.kind == "float" and not all(math.isfinite(v) and abs(v) <= FLOAT32_MAX for v in (low, high)):
        raise spec.error((*path, "range"), "the range of a float field must be finite float32 values")


def _check_default(spec: LoadedSpec, f: dict[str, Any], path: PathKey, primitive: Primitive) -> None:
    """Text that fits a char field; a number within the range (or the type) for a numeric one."""
    default = f["default"]
    if primitive.kind == "char":
        if not isinstance(default, str) or len(default.encode("latin-1")) > f["length"]:
            raise spec.error((*path, "default"), "default does not fit the char field")
    elif primitive.kind in NUMERIC_KINDS:
        if not isinstance(default, (int, float)) or isinstance(default, bool):
            raise spec.error((*path, "default"), "default of a numeric field must be a number")
        bounds = f.get("range")
        if bounds is None and primitive.min is not None and primitive.max is not None:
            bounds = [primitive.min, primitive.max]
        if bounds is not None and not bounds[0] <= default <= bounds[1]:
            raise spec.error((*path, "default"), f"default {default} is outside [{bounds[0]}, {bounds[1]}]")
