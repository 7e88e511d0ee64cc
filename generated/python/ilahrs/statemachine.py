# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""The device's behaviour (6.1, 6.3, 6.4) as data: state x event -> next state and what the AHRS sends.

Events are the commands of Table C.1 by ICD name (a code shared by several names is the name valid
in the current mode: `command_event`, E14) and the events in EVENTS. A (state, event) pair with no
entry is ignored: no answer, no change of state (E33). The device model (`ilahrs.session.device`) and the
host session (`ilahrs.session.host`) both interpret this table (through `ilahrs.machine`); neither holds a
transition of its own.

What a transition sends: ACK (the acknowledgement of the message received), OUTPUT (one block of
the current output format), OUTPUT_PREFIX + a USW mode name (the same block with that mode's USW
bits, E35), or a payload name (one data block of that table).

>>> lookup("idle", "AHRScont3")
Transition(to='aligning_continuous', send=('ack',), wildcard=False, erratum=None)
>>> command_event(0xFE, "calibration_deciding")
'ExitClb'
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Final

from .commands import CODES
from .machine import Machine, StateInfo, Transition, firmware_version

__all__ = [
    "ACCUMULATION_DONE",
    "ACK",
    "ALIGNMENT_DONE",
    "BLOCK_TIMEOUT",
    "CALIBRATION_TYPES",
    "COMMAND_EFFECTS",
    "DEFAULT_ALIGNMENT_TIME_S",
    "DEFAULT_FIRMWARE",
    "DEFAULT_UPDATE_RATE_HZ",
    "EVENTS",
    "INITIAL",
    "LEGACY_TRANSITIONS",
    "MIN_SUCCESSFUL_RUNS",
    "OTHER_MESSAGE",
    "OUTPUT",
    "OUTPUT_DUE",
    "OUTPUT_FORMATS",
    "OUTPUT_PREFIX",
    "PARAMETER_BLOCK",
    "PARAMETER_BLOCK_TIMEOUT_S",
    "RESULT_DELAY_S",
    "STATES",
    "TIMER_EVENTS",
    "TIMER_FIELDS",
    "TIMER_IS_RATE",
    "TRANSITIONS",
    "UNKNOWN",
    "StateInfo",
    "Transition",
    "command_event",
    "firmware_version",
    "lookup",
    "mermaid",
    "timer_transition",
]

INITIAL: Final = "idle"
"""The state after power-up (6.3)."""
PARAMETER_BLOCK_TIMEOUT_S: Final = 1.0
"""How long the AHRS waits for the parameter block that must follow its command (E34)."""
DEFAULT_ALIGNMENT_TIME_S: Final = 30.0
"""Initial alignment time when no parameter block says otherwise (6.3.1)."""
DEFAULT_UPDATE_RATE_HZ: Final = 100.0
"""Update rate when no parameter block says otherwise (6.3.1)."""
RESULT_DELAY_S: Final = 0.0
"""Delay of a calibration result after accumulation ends in the model; hosts allow 0.5 s (E38)."""

PARAMETER_BLOCK: Final = "parameter_block"
"""A data message whose payload has the size of the table the current state expects."""
OTHER_MESSAGE: Final = "other_message"
"""A data message of any other size."""
UNKNOWN: Final = "unknown"
"""A command frame whose code no command of Table C.1 has."""
BLOCK_TIMEOUT: Final = "block_timeout"
"""No parameter block within parameter_block_timeout_s of the command (E34)."""
ALIGNMENT_DONE: Final = "alignment_done"
"""The initial alignment time (Table 6.9, 30 s by default) has elapsed."""
ACCUMULATION_DONE: Final = "accumulation_done"
"""The accumulation time of the calibration run (Table 6.13) has elapsed."""
OUTPUT_DUE: Final = "output_due"
"""One output period has elapsed: 1 / update rate, at most 50 Hz for NMEA (E22)."""
EVENTS: Final[Mapping[str, str]] = MappingProxyType(
    {
        PARAMETER_BLOCK: "A data message whose payload has the size of the table the current state expects.",
        OTHER_MESSAGE: "A data message of any other size.",
        UNKNOWN: "A command frame whose code no command of Table C.1 has.",
        BLOCK_TIMEOUT: "No parameter block within parameter_block_timeout_s of the command (E34).",
        ALIGNMENT_DONE: "The initial alignment time (Table 6.9, 30 s by default) has elapsed.",
        ACCUMULATION_DONE: "The accumulation time of the calibration run (Table 6.13) has elapsed.",
        OUTPUT_DUE: "One output period has elapsed: 1 / update rate, at most 50 Hz for NMEA (E22).",
    }
)
"""The events besides commands, with what they mean."""
TIMER_EVENTS: Final[Mapping[str, str]] = MappingProxyType(
    {"accumulation": "accumulation_done", "alignment": "alignment_done", "output": "output_due"}
)
"""A state's timer -> the event it fires."""
TIMER_FIELDS: Final[Mapping[str, tuple[str, str]]] = MappingProxyType(
    {
        "accumulation": ("calibration_parameters", "accumulation_time"),
        "alignment": ("ahrs_parameters_load", "alignment_time"),
        "output": ("ahrs_parameters_load", "update_rate"),
    }
)
"""A timer -> (parameter block, field) that sets its duration (seconds, or a rate in Hz for output)."""
TIMER_IS_RATE: Final[Mapping[str, bool]] = MappingProxyType({"accumulation": False, "alignment": False, "output": True})
"""A timer -> whether its field is a rate (Hz) rather than a duration (s)."""

ACK: Final = "ack"
OUTPUT: Final = "output"
OUTPUT_PREFIX: Final = "output_"

OUTPUT_FORMATS: Final[Mapping[str, str | None]] = MappingProxyType(
    {
        "full_output": "full_output",
        "quaternion": "quaternion",
        "orientation_sensors": "orientation_sensors",
        "nmea": None,
    }
)
"""Output format started by a command -> its payload table, or None for $PAHR sentences."""
CALIBRATION_TYPES: Final[Mapping[str, int]] = MappingProxyType({"Start2DClb": 1, "Start2D2TClb": 2, "Start3DClb": 3})
"""Start command -> the calibration type (enum calibration_type) its result reports."""
COMMAND_EFFECTS: Final[Mapping[str, str]] = MappingProxyType(
    {"ClearClb": "clear_calibration", "AcceptClb": "save_calibration"}
)
"""Commands that change the calibration in non-volatile memory (6.4.3, 6.4.9)."""
MIN_SUCCESSFUL_RUNS: Final = 2
"""A 2D-2T calibration needs this many successful runs (6.4.5, E37)."""
DEFAULT_FIRMWARE: Final = "4.9.9.0"
"""The firmware version the device model runs unless told otherwise (every current behaviour)."""

STATES: Final[Mapping[str, StateInfo]] = MappingProxyType(
    {
        "idle": StateInfo("idle", "idle", None, None, "Waiting for a command (6.1)."),
        "awaiting_parameters": StateInfo(
            "awaiting_parameters",
            "idle",
            "ahrs_parameters_load",
            None,
            "LoadAHRSPar received; the parameter block must follow without pause (6.3.6).",
        ),
        "aligning_continuous": StateInfo(
            "aligning_continuous",
            "continuous",
            None,
            "alignment",
            "Initial alignment before continuous output (6.3.1, 6.3.3).",
        ),
        "continuous": StateInfo(
            "continuous", "continuous", None, "output", "Output of the chosen format at the update rate (6.3.1)."
        ),
        "aligning_on_request": StateInfo(
            "aligning_on_request",
            "on_request",
            None,
            "alignment",
            "Initial alignment before on-request output (6.3.2, 6.3.3).",
        ),
        "on_request": StateInfo(
            "on_request", "on_request", None, None, "One block of the chosen format per GetDataReq (6.3.2, 6.3.4)."
        ),
        "sleep": StateInfo("sleep", "sleep", None, None, "Low-power mode; only LowPowerOff is heard (6.3.8)."),
        "calibration_awaiting_parameters": StateInfo(
            "calibration_awaiting_parameters",
            "calibration",
            "calibration_parameters",
            None,
            "Start2DClb or Start3DClb received; the calibration parameter block must follow (6.4.1, 6.4.8).",
        ),
        "calibration_aligning": StateInfo(
            "calibration_aligning",
            "calibration",
            None,
            "alignment",
            "Initial alignment before the single calibration run (6.4.1, 6.4.8).",
        ),
        "calibration_accumulating": StateInfo(
            "calibration_accumulating",
            "calibration",
            None,
            "accumulation",
            "Accumulating data while the object turns (6.4.1, 6.4.8).",
        ),
        "calibration_deciding": StateInfo(
            "calibration_deciding",
            "calibration",
            None,
            None,
            "Result sent; waiting for AcceptClb or ExitClb (6.4.1, 6.4.7).",
        ),
        "runs_awaiting_parameters": StateInfo(
            "runs_awaiting_parameters",
            "calibration",
            "calibration_parameters",
            None,
            "Start2D2TClb received; the calibration parameter block must follow (6.4.5).",
        ),
        "runs_ready": StateInfo(
            "runs_ready",
            "calibration",
            None,
            None,
            "2D-2T calibration between runs: waiting for StartClbRun, FinishClb or ExitClb (6.4.5).",
        ),
        "run_awaiting_parameters": StateInfo(
            "run_awaiting_parameters",
            "calibration",
            "calibration_run_parameters",
            None,
            "StartClbRun received; the run parameter block must follow (6.4.6).",
        ),
        "run_aligning": StateInfo(
            "run_aligning", "calibration", None, "alignment", "Initial alignment before a 2D-2T run (6.4.5)."
        ),
        "run_accumulating": StateInfo(
            "run_accumulating", "calibration", None, "accumulation", "Accumulating data during a 2D-2T run (6.4.5)."
        ),
    }
)
"""Every state by name, in spec order."""

TRANSITIONS: Final[Mapping[tuple[str, str], Transition]] = MappingProxyType(
    {
        ("idle", "AHRScont1"): Transition("aligning_continuous", ("ack",)),
        ("idle", "AHRScont2"): Transition("aligning_continuous", ("ack",)),
        ("idle", "AHRScont3"): Transition("aligning_continuous", ("ack",)),
        ("idle", "NMEAcont"): Transition("aligning_continuous", ("ack",)),
        ("idle", "AHRSreq1"): Transition("aligning_on_request", ("ack",)),
        ("idle", "AHRSreq2"): Transition("aligning_on_request", ("ack",)),
        ("idle", "AHRSreq3"): Transition("aligning_on_request", ("ack",)),
        ("idle", "NMEAreq"): Transition("aligning_on_request", ("ack",)),
        ("idle", "LoadAHRSPar"): Transition("awaiting_parameters", (), erratum="E13"),
        ("idle", "ReadAHRSPar"): Transition("idle", ("ahrs_parameters_read",)),
        ("idle", "GetVerFirmware"): Transition("idle", ("firmware_version",)),
        ("idle", "GetBIT"): Transition("idle", ("bit_result",)),
        ("on_request", "GetBIT"): Transition("on_request", ("bit_result",)),
        ("idle", "LowPowerOn"): Transition("sleep", ()),
        ("idle", "Start2DClb"): Transition("calibration_awaiting_parameters", (), erratum="E13"),
        ("idle", "Start3DClb"): Transition("calibration_awaiting_parameters", (), erratum="E13"),
        ("idle", "Start2D2TClb"): Transition("runs_awaiting_parameters", (), erratum="E13"),
        ("idle", "ClearClb"): Transition("idle", ("ack",)),
        ("idle", "GetClbRes"): Transition("idle", ("calibration_status",)),
        ("idle", "Stop"): Transition("idle", (), erratum="E14"),
        ("awaiting_parameters", "parameter_block"): Transition("idle", ("ack",)),
        ("awaiting_parameters", "unknown"): Transition("idle", (), erratum="E34"),
        ("awaiting_parameters", "other_message"): Transition("idle", (), erratum="E34"),
        ("awaiting_parameters", "block_timeout"): Transition("idle", (), erratum="E34"),
        ("calibration_awaiting_parameters", "unknown"): Transition("idle", (), erratum="E34"),
        ("calibration_awaiting_parameters", "other_message"): Transition("idle", (), erratum="E34"),
        ("calibration_awaiting_parameters", "block_timeout"): Transition("idle", (), erratum="E34"),
        ("runs_awaiting_parameters", "unknown"): Transition("idle", (), erratum="E34"),
        ("runs_awaiting_parameters", "other_message"): Transition("idle", (), erratum="E34"),
        ("runs_awaiting_parameters", "block_timeout"): Transition("idle", (), erratum="E34"),
        ("calibration_awaiting_parameters", "ExitClb"): Transition("idle", ("ack",)),
        ("runs_awaiting_parameters", "ExitClb"): Transition("idle", ("ack",)),
        ("run_awaiting_parameters", "ExitClb"): Transition("idle", ("ack",)),
        ("run_awaiting_parameters", "unknown"): Transition("runs_ready", (), erratum="E34"),
        ("run_awaiting_parameters", "other_message"): Transition("runs_ready", (), erratum="E34"),
        ("run_awaiting_parameters", "block_timeout"): Transition("runs_ready", (), erratum="E34"),
        ("aligning_continuous", "alignment_done"): Transition("continuous", ("initial_alignment",)),
        ("aligning_on_request", "alignment_done"): Transition("on_request", ("initial_alignment",)),
        ("continuous", "output_due"): Transition("continuous", ("output",)),
        ("on_request", "GetDataReq"): Transition("on_request", ("output",), erratum="E39"),
        ("aligning_continuous", "Stop"): Transition("idle", (), erratum="E14"),
        ("continuous", "Stop"): Transition("idle", (), erratum="E14"),
        ("aligning_on_request", "Stop"): Transition("idle", (), erratum="E14"),
        ("on_request", "Stop"): Transition("idle", (), erratum="E14"),
        ("continuous", "LowPowerOn"): Transition("sleep", ("output_sleep",), erratum="E35"),
        ("on_request", "LowPowerOn"): Transition("sleep", (), erratum="E35"),
        ("sleep", "LowPowerOff"): Transition("idle", ()),
        ("calibration_awaiting_parameters", "parameter_block"): Transition("calibration_aligning", ("ack",)),
        ("calibration_aligning", "alignment_done"): Transition("calibration_accumulating", ("initial_alignment",)),
        ("calibration_accumulating", "accumulation_done"): Transition(
            "calibration_deciding", ("calibration_result",), erratum="E38"
        ),
        ("calibration_accumulating", "StopClbRun"): Transition(
            "calibration_deciding", ("calibration_result",), erratum="E38"
        ),
        ("calibration_deciding", "AcceptClb"): Transition("idle", ("ack",)),
        ("calibration_aligning", "ExitClb"): Transition("idle", ("ack",), erratum="E14"),
        ("calibration_accumulating", "ExitClb"): Transition("idle", ("ack",), erratum="E14"),
        ("calibration_deciding", "ExitClb"): Transition("idle", ("ack",), erratum="E14"),
        ("runs_ready", "ExitClb"): Transition("idle", ("ack",), erratum="E14"),
        ("run_aligning", "ExitClb"): Transition("idle", ("ack",), erratum="E14"),
        ("run_accumulating", "ExitClb"): Transition("idle", ("ack",), erratum="E14"),
        ("runs_awaiting_parameters", "parameter_block"): Transition("runs_ready", ("ack",), erratum="E36"),
        ("runs_ready", "StartClbRun"): Transition("run_awaiting_parameters", (), erratum="E13"),
        ("run_awaiting_parameters", "parameter_block"): Transition("run_aligning", ("ack",)),
        ("run_aligning", "alignment_done"): Transition("run_accumulating", ("initial_alignment",)),
        ("run_accumulating", "accumulation_done"): Transition("runs_ready", ("calibration_run_result",)),
        ("run_accumulating", "StopClbRun"): Transition("runs_ready", ("calibration_run_result",)),
        ("runs_ready", "FinishClb"): Transition("calibration_deciding", ("calibration_result",), erratum="E37"),
        ("awaiting_parameters", "AHRScont1"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "AHRScont2"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "AHRScont3"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "AHRSreq1"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "AHRSreq2"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "AHRSreq3"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "NMEAcont"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "NMEAreq"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "GetDataReq"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "Stop"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "LoadAHRSPar"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "ReadAHRSPar"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "LowPowerOn"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "LowPowerOff"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "GetVerFirmware"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "GetBIT"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "Start2DClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "Start2D2TClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "Start3DClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "StartClbRun"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "StopClbRun"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "FinishClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "AcceptClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "ExitClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "ClearClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("awaiting_parameters", "GetClbRes"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AHRScont1"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AHRScont2"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AHRScont3"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AHRSreq1"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AHRSreq2"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AHRSreq3"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "NMEAcont"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "NMEAreq"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "GetDataReq"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "Stop"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "LoadAHRSPar"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "ReadAHRSPar"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "LowPowerOn"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "LowPowerOff"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "GetVerFirmware"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "GetBIT"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "Start2DClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "Start2D2TClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "Start3DClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "StartClbRun"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "StopClbRun"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "FinishClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "AcceptClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "ClearClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("calibration_awaiting_parameters", "GetClbRes"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AHRScont1"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AHRScont2"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AHRScont3"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AHRSreq1"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AHRSreq2"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AHRSreq3"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "NMEAcont"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "NMEAreq"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "GetDataReq"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "Stop"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "LoadAHRSPar"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "ReadAHRSPar"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "LowPowerOn"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "LowPowerOff"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "GetVerFirmware"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "GetBIT"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "Start2DClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "Start2D2TClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "Start3DClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "StartClbRun"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "StopClbRun"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "FinishClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "AcceptClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "ClearClb"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("runs_awaiting_parameters", "GetClbRes"): Transition("idle", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AHRScont1"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AHRScont2"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AHRScont3"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AHRSreq1"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AHRSreq2"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AHRSreq3"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "NMEAcont"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "NMEAreq"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "GetDataReq"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "Stop"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "LoadAHRSPar"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "ReadAHRSPar"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "LowPowerOn"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "LowPowerOff"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "GetVerFirmware"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "GetBIT"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "Start2DClb"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "Start2D2TClb"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "Start3DClb"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "StartClbRun"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "StopClbRun"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "FinishClb"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "AcceptClb"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "ClearClb"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
        ("run_awaiting_parameters", "GetClbRes"): Transition("runs_ready", (), wildcard=True, erratum="E34"),
    }
)
"""(state, event) -> transition, for the current firmware."""

LEGACY_TRANSITIONS: Final[Mapping[tuple[str, str], tuple[str, Transition]]] = MappingProxyType(
    {
        ("runs_ready", "StopClbRun"): (
            "4.9.9.0",
            Transition("calibration_deciding", ("calibration_result",), erratum="E29"),
        ),
    }
)
"""(state, event) -> (firmware version, transition): rows that replace the current ones on
firmware older than that version."""

_SHARED_CODES: Final[Mapping[tuple[int, str], str]] = MappingProxyType(
    {
        (0xFE, "idle"): "Stop",
        (0xFE, "continuous"): "Stop",
        (0xFE, "on_request"): "Stop",
        (0xFE, "calibration"): "ExitClb",
        (0xFE, "sleep"): "Stop",
    }
)
"""(shared command code, operating mode) -> the command the code means there (E14)."""

MACHINE: Final = Machine(INITIAL, STATES, TRANSITIONS, LEGACY_TRANSITIONS, CODES, _SHARED_CODES, TIMER_EVENTS)
"""The table, with the lookups of `ilahrs.machine`."""
lookup: Final = MACHINE.lookup
command_event: Final = MACHINE.command_event
timer_transition: Final = MACHINE.timer_transition
mermaid: Final = MACHINE.mermaid
