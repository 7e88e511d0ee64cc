"""Step 3 of the pipeline: the validated spec as typed, immutable objects.

The model holds what the spec says, nothing computed about placement: offsets and sizes
derived from declaration order are the layout step's (generator/layout.py), which returns
the same objects with `offset` filled in. Templates read the laid-out model and never
change it.

This module is the model's one import point; the objects live beside it, one module per
part of the spec:

    model_fields.py     wire types, units, scales, fields, payload tables
    model_frame.py      the frame and the commands
    model_encodings.py  enums, value encodings, the unit status word, the $PAHR sentence
    model_machine.py    the state machine and its protocol words (timer events, answers)
    model_spec.py       Spec, the root, and the small sections it holds directly
    model_build.py      the build: validated data into these objects (model_build_machine.py:
                        the state machine's rows expanded into its table)
"""

from __future__ import annotations

from .load import LoadedSpec, PathKey
from .model_build import build
from .model_encodings import (
    CalibrationSuccessEncoding,
    DateEncoding,
    DateTerm,
    DeclinationEncoding,
    Enum,
    EnumValue,
    Nmea,
    NmeaField,
    StatusFlag,
    StatusMode,
    StatusWord,
)
from .model_fields import FLOAT32_MAX, PRIMITIVES, Field, Payload, Primitive, Scale, Unit
from .model_frame import Command, FormerName, Frame, MessageType, Strict
from .model_machine import (
    ANSWER_ACK,
    ANSWER_OUTPUT,
    OUTPUT_MODE_PREFIX,
    TIMER_EVENTS,
    Answer,
    SmEvent,
    SmState,
    SmTimer,
    StateMachine,
    Transition,
    answer_kind,
)
from .model_spec import Erratum, ErrorKind, Mode, SerialLine, Spec, Variant, VariantParameter

__all__ = [
    "ANSWER_ACK",
    "ANSWER_OUTPUT",
    "FLOAT32_MAX",
    "OUTPUT_MODE_PREFIX",
    "PRIMITIVES",
    "TIMER_EVENTS",
    "Answer",
    "CalibrationSuccessEncoding",
    "Command",
    "DateEncoding",
    "DateTerm",
    "DeclinationEncoding",
    "Enum",
    "EnumValue",
    "Erratum",
    "ErrorKind",
    "Field",
    "FormerName",
    "Frame",
    "LoadedSpec",
    "MessageType",
    "Mode",
    "Nmea",
    "NmeaField",
    "PathKey",
    "Payload",
    "Primitive",
    "Scale",
    "SerialLine",
    "SmEvent",
    "SmState",
    "SmTimer",
    "Spec",
    "StateMachine",
    "StatusFlag",
    "StatusMode",
    "StatusWord",
    "Strict",
    "Transition",
    "Unit",
    "Variant",
    "VariantParameter",
    "answer_kind",
    "build",
]
