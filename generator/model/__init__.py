"""Step 3 of the pipeline: the validated spec as typed, immutable objects.

The model holds what the spec says, nothing computed about placement: offsets and sizes
derived from declaration order are the layout step's (generator/layout.py), which returns
the same objects with `offset` filled in. Templates read the laid-out model and never
change it.

This package is the model's one import point (`from generator.model import ...`); the objects
live in its modules, one per part of the spec:

    fields.py     wire types, units, scales, fields, payload tables
    frame.py      the frame and the commands
    encodings.py  enums, value encodings, the unit status word, the $PAHR sentence
    machine.py    the state machine and its protocol words (timer events, answers)
    spec.py       Spec, the root, and the small sections it holds directly
    build.py      the build: validated data into these objects (build_machine.py: the state
                  machine's rows expanded into its table; text.py: spec prose on one line)
"""

from __future__ import annotations

from ..load import LoadedSpec, PathKey
from .build import build
from .encodings import (
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
from .fields import FLOAT32_MAX, PRIMITIVES, Field, Payload, Primitive, Scale, Unit
from .frame import Command, FormerName, Frame, MessageType, Strict
from .machine import (
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
from .spec import Erratum, ErrorKind, Mode, SerialLine, Spec, Variant, VariantParameter

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
