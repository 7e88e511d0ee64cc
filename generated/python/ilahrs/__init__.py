# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""ilahrs: the Inertial Labs AHRS protocol (Inertial Labs AHRS Interface Control Document, rev 1.7).

Frames, the commands of Table C.1, every payload table, the Unit Status Word, the $PAHR sentence
and a sans-I/O stream decoder, generated from spec/ilahrs.yaml (spec 1.0.0).
The device's behaviour is a table (`ilahrs.statemachine`) that a reference device model
(`Device`) and a host session (`Host`) interpret, both sans-I/O; `ilahrs.simulate` serves the
model as a virtual AHRS on a pty or loopback socket (`ilahrs simulate`), and `ilahrs.serial`
drives a real or virtual AHRS over pyserial (the optional `serial` extra).
Standard library only.

>>> import ilahrs
>>> ilahrs.build_command("AHRScont3").hex(" ")
'aa 55 00 00 07 00 83 8a 00'
>>> ilahrs.decode_command(bytes.fromhex("AA 55 00 00 07 00 FE 05 01"))
(254, ('ExitClb', 'Stop'))
"""

from __future__ import annotations

from .bulk import decode_output
from .columnar import columns, columns_by_kind
from .commands import (
    CODES,
    COMMANDS,
    CommandInfo,
    ack_for,
    build_command,
    build_parameter_block,
    command_names,
    decode_command,
)
from .encodings import (
    DECLINATION_COMPUTE,
    VARIANTS,
    CalibrationStatusType,
    CalibrationType,
    Variant,
    calibration_accuracy_deg,
    calibration_succeeded,
    declination_is_computed,
    decode_date,
    encode_date,
)
from .errors import ErrorKind, IlahrsError
from .frame import MAX_FRAME_SIZE, Frame, MessageType, checksum
from .nmea import PahrSentence
from .payloads import (
    PAYLOADS,
    Acknowledgement,
    AhrsParametersLoad,
    AhrsParametersRead,
    BitResult,
    CalibrationParameters,
    CalibrationResult,
    CalibrationRunParameters,
    CalibrationRunResult,
    CalibrationStatus,
    FieldInfo,
    FirmwareVersion,
    FullOutput,
    InitialAlignment,
    OrientationSensors,
    Payload,
    Quaternion,
)
from .session.device import Device
from .session.host import Acknowledged, DataBlock, Discarded, Host, HostEvent, Output, ProtocolError
from .spec import SPEC_SHA256, SPEC_VERSION, WIRE_FINGERPRINT
from .status import UnitStatusWord, UswFlag, UswMode
from .stream import IDLE_BYTE_TIMES, IDLE_TIMEOUT, MAX_MESSAGE_SIZE, StreamDecoder, StreamEvent

__all__ = [
    "CODES",
    "COMMANDS",
    "DECLINATION_COMPUTE",
    "IDLE_BYTE_TIMES",
    "IDLE_TIMEOUT",
    "MAX_FRAME_SIZE",
    "MAX_MESSAGE_SIZE",
    "PAYLOADS",
    "SPEC_SHA256",
    "SPEC_VERSION",
    "VARIANTS",
    "WIRE_FINGERPRINT",
    "Acknowledged",
    "Acknowledgement",
    "AhrsParametersLoad",
    "AhrsParametersRead",
    "BitResult",
    "CalibrationParameters",
    "CalibrationResult",
    "CalibrationRunParameters",
    "CalibrationRunResult",
    "CalibrationStatus",
    "CalibrationStatusType",
    "CalibrationType",
    "CommandInfo",
    "DataBlock",
    "Device",
    "Discarded",
    "ErrorKind",
    "FieldInfo",
    "FirmwareVersion",
    "Frame",
    "FullOutput",
    "Host",
    "HostEvent",
    "IlahrsError",
    "InitialAlignment",
    "MessageType",
    "OrientationSensors",
    "Output",
    "PahrSentence",
    "Payload",
    "ProtocolError",
    "Quaternion",
    "StreamDecoder",
    "StreamEvent",
    "UnitStatusWord",
    "UswFlag",
    "UswMode",
    "Variant",
    "ack_for",
    "build_command",
    "build_parameter_block",
    "calibration_accuracy_deg",
    "calibration_succeeded",
    "checksum",
    "columns",
    "columns_by_kind",
    "command_names",
    "declination_is_computed",
    "decode_command",
    "decode_date",
    "decode_output",
    "encode_date",
]

__version__ = SPEC_VERSION
"""The package's version: the spec's (spec/ilahrs.yaml `version`, as in pyproject.toml)."""
