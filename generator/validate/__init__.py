"""Step 2 of the pipeline: reject a spec that is malformed or inconsistent.

First the structure, against spec/schema.json; then what a schema cannot say:
unknown types, names and codes used twice, references to things that do not exist,
scales on non-numeric fields, ranges outside what a type holds. Sizes and offsets are
checked by the layout step, which computes them. Every error names file, line and path.

The checks live in this package's modules, one per part of the spec, and run in the order
below (the first problem found is the one reported):

    sections.py  errata, error kinds, modes, variants, enums, frame, payloads,
                 acknowledgement, status word, $PAHR sentence
    fields.py    one field of the frame or a payload
    commands.py  the commands
    machine.py   the state machine
    common.py    unique names, and the names the parts refer to
    names.py     names a target cannot take (generator/targets/*/reserved.txt)
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import jsonschema

from ..load import LoadedSpec, PathKey
from ..model import FLOAT32_MAX, PRIMITIVES, TIMER_EVENTS, answer_kind
from .commands import check_commands
from .fields import ENCODING_TYPES
from .machine import check_state_machine
from .names import check_reserved
from .sections import (
    REQUIRED_FRAME_FIELDS,
    check_acknowledgement,
    check_frame,
    check_names,
    check_nmea,
    check_payloads,
    check_status_word,
)

__all__ = [
    "ENCODING_TYPES",
    "FLOAT32_MAX",
    "PRIMITIVES",
    "REQUIRED_FRAME_FIELDS",
    "SCHEMA_PATH",
    "TIMER_EVENTS",
    "answer_kind",
    "validate",
]

SCHEMA_PATH = Path(__file__).resolve().parents[2] / "spec" / "schema.json"


def _schema() -> dict[str, Any]:
    result: dict[str, Any] = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    return result


def _check_schema(spec: LoadedSpec, schema: dict[str, Any]) -> None:
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(spec.data), key=lambda e: (len(e.absolute_path), str(e.absolute_path)))
    if errors:
        # Report the most specific error first: the deepest path.
        error = max(errors, key=lambda e: len(e.absolute_path))
        path: PathKey = tuple(error.absolute_path)
        if error.validator == "additionalProperties" and isinstance(error.instance, dict):
            # Name the first key the schema does not know, at its own line.
            allowed = set(error.schema.get("properties", {}))
            patterns = list(error.schema.get("patternProperties", {}))
            extra = [k for k in error.instance if k not in allowed and not any(re.search(p, k) for p in patterns)]
            if extra:
                raise spec.key_error((*path, extra[0]), f"unknown key {extra[0]!r} ({error.message})")
        raise spec.error(path, error.message)


def validate(spec: LoadedSpec) -> None:
    """Raise SpecError for the first problem found; return quietly for a usable spec."""
    schema = _schema()
    _check_schema(spec, schema)
    d = spec.data
    names = check_names(spec)
    check_frame(spec, d["frame"], names)
    check_payloads(spec, d["payloads"], names)
    check_commands(spec, names)
    check_acknowledgement(spec, d.get("acknowledgement"), names)
    if d.get("status_word") is not None:
        check_status_word(spec, d["status_word"])
    if d.get("nmea") is not None:
        check_nmea(spec, d["nmea"])
    if d.get("state_machine") is not None:
        check_state_machine(spec, d["state_machine"], names)
    check_reserved(spec, schema)
