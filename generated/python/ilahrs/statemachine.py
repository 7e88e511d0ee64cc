# Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
# Do not edit: change the spec or the generator and run `make generate`.
"""The device's behaviour (6.1, 6.3, 6.4) as data: state x event -> next state and what the AHRS sends.

Events are the commands of Table C.1 by ICD name (a code shared by several names is the name valid
in the current mode: `command_event`, E14) and the events in EVENTS. A (state, event) pair with no
entry is ignored: no answer, no change of state (E33). The device model (`ilahrs.device`) and the
host session (`ilahrs.host`) both interpret this table; neither holds a transition of its own.

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
from dataclasses import dataclass
from types import MappingProxyType
from typing import Final

from .commands import CODES

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

INITIAL: Final = 'idle'
"""The state after power-up (6.3)."""
PARAMETER_BLOCK_TIMEOUT_S: Final = 1.0
"""How long the AHRS waits for the parameter block that must follow its command (E34)."""
DEFAULT_ALIGNMENT_TIME_S: Final = 30.0
"""Initial alignment time when no parameter block says otherwise (6.3.1)."""
DEFAULT_UPDATE_RATE_HZ: Final = 100.0
"""Update rate when no parameter block says otherwise (6.3.1)."""
RESULT_DELAY_S: Final = 0.0
"""Delay of a calibration result after accumulation ends in the model; hosts allow 0.5 s (E38)."""

PARAMETER_BLOCK: Final = 'parameter_block'
"""A data message whose payload has the size of the table the current state expects."""
OTHER_MESSAGE: Final = 'other_message'
"""A data message of any other size."""
UNKNOWN: Final = 'unknown'
"""A command frame whose code no command of Table C.1 has."""
BLOCK_TIMEOUT: Final = 'block_timeout'
"""No parameter block within parameter_block_timeout_s of the command (E34)."""
ALIGNMENT_DONE: Final = 'alignment_done'
"""The initial alignment time (Table 6.9, 30 s by default) has elapsed."""
ACCUMULATION_DONE: Final = 'accumulation_done'
"""The accumulation time of the calibration run (Table 6.13) has elapsed."""
OUTPUT_DUE: Final = 'output_due'
"""One output period has elapsed: 1 / update rate, at most 50 Hz for NMEA (E22)."""
EVENTS: Final[Mapping[str, str]] = MappingProxyType(
    {
        PARAMETER_BLOCK: 'A data message whose payload has the size of the table the current state expects.',
        OTHER_MESSAGE: 'A data message of any other size.',
        UNKNOWN: 'A command frame whose code no command of Table C.1 has.',
        BLOCK_TIMEOUT: 'No parameter block within parameter_block_timeout_s of the command (E34).',
        ALIGNMENT_DONE: 'The initial alignment time (Table 6.9, 30 s by default) has elapsed.',
        ACCUMULATION_DONE: 'The accumulation time of the calibration run (Table 6.13) has elapsed.',
        OUTPUT_DUE: 'One output period has elapsed: 1 / update rate, at most 50 Hz for NMEA (E22).',
    }
)
"""The events besides commands, with what they mean."""
TIMER_EVENTS: Final[Mapping[str, str]] = MappingProxyType({
    'accumulation': 'accumulation_done',
    'alignment': 'alignment_done',
    'output': 'output_due',
})
"""A state's timer -> the event it fires."""
TIMER_FIELDS: Final[Mapping[str, tuple[str, str]]] = MappingProxyType({
    'accumulation': ('calibration_parameters', 'accumulation_time'),
    'alignment': ('ahrs_parameters_load', 'alignment_time'),
    'output': ('ahrs_parameters_load', 'update_rate'),
})
"""A timer -> (parameter block, field) that sets its duration (seconds, or a rate in Hz for output)."""

ACK: Final = "ack"
OUTPUT: Final = "output"
OUTPUT_PREFIX: Final = "output_"

OUTPUT_FORMATS: Final[Mapping[str, str | None]] = MappingProxyType({
    'full_output': 'full_output',
    'quaternion': 'quaternion',
    'orientation_sensors': 'orientation_sensors',
    'nmea': None,
})
"""Output format started by a command -> its payload table, or None for $PAHR sentences."""
CALIBRATION_TYPES: Final[Mapping[str, int]] = MappingProxyType({'Start2DClb': 1, 'Start2D2TClb': 2, 'Start3DClb': 3})
"""Start command -> the calibration type (enum calibration_type) its result reports."""
COMMAND_EFFECTS: Final[Mapping[str, str]] = MappingProxyType({
    'ClearClb': 'clear_calibration',
    'AcceptClb': 'save_calibration',
})
"""Commands that change the calibration in non-volatile memory (6.4.3, 6.4.9)."""
MIN_SUCCESSFUL_RUNS: Final = 2
"""A 2D-2T calibration needs this many successful runs (6.4.5, E37)."""
DEFAULT_FIRMWARE: Final = '4.9.9.0'
"""The firmware version the device model runs unless told otherwise (every current behaviour)."""


@dataclass(frozen=True, slots=True)
class StateInfo:
    """A state of the device: its operating mode, the parameter block it waits for, its timer."""

    name: str
    mode: str
    expects: str | None
    """The payload table of the parameter block this state waits for (E34), if any."""
    timer: str | None
    """alignment, accumulation or output: the timer running in this state, if any."""
    doc: str


@dataclass(frozen=True, slots=True)
class Transition:
    """One cell of the table: go to `to` and send `send`."""

    to: str
    send: tuple[str, ...]
    wildcard: bool = False
    """From a `*` row: any command without a row of its own."""
    erratum: str | None = None


STATES: Final[Mapping[str, StateInfo]] = MappingProxyType(
    {
        'idle': StateInfo(
            name='idle',
            mode='idle',
            expects=None,
            timer=None,
            doc='Waiting for a command (6.1).',
        ),
        'awaiting_parameters': StateInfo(
            name='awaiting_parameters',
            mode='idle',
            expects='ahrs_parameters_load',
            timer=None,
            doc='LoadAHRSPar received; the parameter block must follow without pause (6.3.6).',
        ),
        'aligning_continuous': StateInfo(
            name='aligning_continuous',
            mode='continuous',
            expects=None,
            timer='alignment',
            doc='Initial alignment before continuous output (6.3.1, 6.3.3).',
        ),
        'continuous': StateInfo(
            name='continuous',
            mode='continuous',
            expects=None,
            timer='output',
            doc='Output of the chosen format at the update rate (6.3.1).',
        ),
        'aligning_on_request': StateInfo(
            name='aligning_on_request',
            mode='on_request',
            expects=None,
            timer='alignment',
            doc='Initial alignment before on-request output (6.3.2, 6.3.3).',
        ),
        'on_request': StateInfo(
            name='on_request',
            mode='on_request',
            expects=None,
            timer=None,
            doc='One block of the chosen format per GetDataReq (6.3.2, 6.3.4).',
        ),
        'sleep': StateInfo(
            name='sleep',
            mode='sleep',
            expects=None,
            timer=None,
            doc='Low-power mode; only LowPowerOff is heard (6.3.8).',
        ),
        'calibration_awaiting_parameters': StateInfo(
            name='calibration_awaiting_parameters',
            mode='calibration',
            expects='calibration_parameters',
            timer=None,
            doc='Start2DClb or Start3DClb received; the calibration parameter block must follow (6.4.1, 6.4.8).',
        ),
        'calibration_aligning': StateInfo(
            name='calibration_aligning',
            mode='calibration',
            expects=None,
            timer='alignment',
            doc='Initial alignment before the single calibration run (6.4.1, 6.4.8).',
        ),
        'calibration_accumulating': StateInfo(
            name='calibration_accumulating',
            mode='calibration',
            expects=None,
            timer='accumulation',
            doc='Accumulating data while the object turns (6.4.1, 6.4.8).',
        ),
        'calibration_deciding': StateInfo(
            name='calibration_deciding',
            mode='calibration',
            expects=None,
            timer=None,
            doc='Result sent; waiting for AcceptClb or ExitClb (6.4.1, 6.4.7).',
        ),
        'runs_awaiting_parameters': StateInfo(
            name='runs_awaiting_parameters',
            mode='calibration',
            expects='calibration_parameters',
            timer=None,
            doc='Start2D2TClb received; the calibration parameter block must follow (6.4.5).',
        ),
        'runs_ready': StateInfo(
            name='runs_ready',
            mode='calibration',
            expects=None,
            timer=None,
            doc='2D-2T calibration between runs: waiting for StartClbRun, FinishClb or ExitClb (6.4.5).',
        ),
        'run_awaiting_parameters': StateInfo(
            name='run_awaiting_parameters',
            mode='calibration',
            expects='calibration_run_parameters',
            timer=None,
            doc='StartClbRun received; the run parameter block must follow (6.4.6).',
        ),
        'run_aligning': StateInfo(
            name='run_aligning',
            mode='calibration',
            expects=None,
            timer='alignment',
            doc='Initial alignment before a 2D-2T run (6.4.5).',
        ),
        'run_accumulating': StateInfo(
            name='run_accumulating',
            mode='calibration',
            expects=None,
            timer='accumulation',
            doc='Accumulating data during a 2D-2T run (6.4.5).',
        ),
    }
)
"""Every state by name, in spec order."""

TRANSITIONS: Final[Mapping[tuple[str, str], Transition]] = MappingProxyType(
    {
        ('idle', 'AHRScont1'):
            Transition('aligning_continuous', ('ack',)),
        ('idle', 'AHRScont2'):
            Transition('aligning_continuous', ('ack',)),
        ('idle', 'AHRScont3'):
            Transition('aligning_continuous', ('ack',)),
        ('idle', 'NMEAcont'):
            Transition('aligning_continuous', ('ack',)),
        ('idle', 'AHRSreq1'):
            Transition('aligning_on_request', ('ack',)),
        ('idle', 'AHRSreq2'):
            Transition('aligning_on_request', ('ack',)),
        ('idle', 'AHRSreq3'):
            Transition('aligning_on_request', ('ack',)),
        ('idle', 'NMEAreq'):
            Transition('aligning_on_request', ('ack',)),
        ('idle', 'LoadAHRSPar'):
            Transition('awaiting_parameters', (), erratum='E13'),
        ('idle', 'ReadAHRSPar'):
            Transition('idle', ('ahrs_parameters_read',)),
        ('idle', 'GetVerFirmware'):
            Transition('idle', ('firmware_version',)),
        ('idle', 'GetBIT'):
            Transition('idle', ('bit_result',)),
        ('on_request', 'GetBIT'):
            Transition('on_request', ('bit_result',)),
        ('idle', 'LowPowerOn'):
            Transition('sleep', ()),
        ('idle', 'Start2DClb'):
            Transition('calibration_awaiting_parameters', (), erratum='E13'),
        ('idle', 'Start3DClb'):
            Transition('calibration_awaiting_parameters', (), erratum='E13'),
        ('idle', 'Start2D2TClb'):
            Transition('runs_awaiting_parameters', (), erratum='E13'),
        ('idle', 'ClearClb'):
            Transition('idle', ('ack',)),
        ('idle', 'GetClbRes'):
            Transition('idle', ('calibration_status',)),
        ('idle', 'Stop'):
            Transition('idle', (), erratum='E14'),
        ('awaiting_parameters', 'parameter_block'):
            Transition('idle', ('ack',)),
        ('awaiting_parameters', 'unknown'):
            Transition('idle', (), erratum='E34'),
        ('awaiting_parameters', 'other_message'):
            Transition('idle', (), erratum='E34'),
        ('awaiting_parameters', 'block_timeout'):
            Transition('idle', (), erratum='E34'),
        ('calibration_awaiting_parameters', 'unknown'):
            Transition('idle', (), erratum='E34'),
        ('calibration_awaiting_parameters', 'other_message'):
            Transition('idle', (), erratum='E34'),
        ('calibration_awaiting_parameters', 'block_timeout'):
            Transition('idle', (), erratum='E34'),
        ('runs_awaiting_parameters', 'unknown'):
            Transition('idle', (), erratum='E34'),
        ('runs_awaiting_parameters', 'other_message'):
            Transition('idle', (), erratum='E34'),
        ('runs_awaiting_parameters', 'block_timeout'):
            Transition('idle', (), erratum='E34'),
        ('calibration_awaiting_parameters', 'ExitClb'):
            Transition('idle', ('ack',)),
        ('runs_awaiting_parameters', 'ExitClb'):
            Transition('idle', ('ack',)),
        ('run_awaiting_parameters', 'ExitClb'):
            Transition('idle', ('ack',)),
        ('run_awaiting_parameters', 'unknown'):
            Transition('runs_ready', (), erratum='E34'),
        ('run_awaiting_parameters', 'other_message'):
            Transition('runs_ready', (), erratum='E34'),
        ('run_awaiting_parameters', 'block_timeout'):
            Transition('runs_ready', (), erratum='E34'),
        ('aligning_continuous', 'alignment_done'):
            Transition('continuous', ('initial_alignment',)),
        ('aligning_on_request', 'alignment_done'):
            Transition('on_request', ('initial_alignment',)),
        ('continuous', 'output_due'):
            Transition('continuous', ('output',)),
        ('on_request', 'GetDataReq'):
            Transition('on_request', ('output',), erratum='E39'),
        ('aligning_continuous', 'Stop'):
            Transition('idle', (), erratum='E14'),
        ('continuous', 'Stop'):
            Transition('idle', (), erratum='E14'),
        ('aligning_on_request', 'Stop'):
            Transition('idle', (), erratum='E14'),
        ('on_request', 'Stop'):
            Transition('idle', (), erratum='E14'),
        ('continuous', 'LowPowerOn'):
            Transition('sleep', ('output_sleep',), erratum='E35'),
        ('on_request', 'LowPowerOn'):
            Transition('sleep', (), erratum='E35'),
        ('sleep', 'LowPowerOff'):
            Transition('idle', ()),
        ('calibration_awaiting_parameters', 'parameter_block'):
            Transition('calibration_aligning', ('ack',)),
        ('calibration_aligning', 'alignment_done'):
            Transition('calibration_accumulating', ('initial_alignment',)),
        ('calibration_accumulating', 'accumulation_done'):
            Transition('calibration_deciding', ('calibration_result',), erratum='E38'),
        ('calibration_accumulating', 'StopClbRun'):
            Transition('calibration_deciding', ('calibration_result',), erratum='E38'),
        ('calibration_deciding', 'AcceptClb'):
            Transition('idle', ('ack',)),
        ('calibration_aligning', 'ExitClb'):
            Transition('idle', ('ack',), erratum='E14'),
        ('calibration_accumulating', 'ExitClb'):
            Transition('idle', ('ack',), erratum='E14'),
        ('calibration_deciding', 'ExitClb'):
            Transition('idle', ('ack',), erratum='E14'),
        ('runs_ready', 'ExitClb'):
            Transition('idle', ('ack',), erratum='E14'),
        ('run_aligning', 'ExitClb'):
            Transition('idle', ('ack',), erratum='E14'),
        ('run_accumulating', 'ExitClb'):
            Transition('idle', ('ack',), erratum='E14'),
        ('runs_awaiting_parameters', 'parameter_block'):
            Transition('runs_ready', ('ack',), erratum='E36'),
        ('runs_ready', 'StartClbRun'):
            Transition('run_awaiting_parameters', (), erratum='E13'),
        ('run_awaiting_parameters', 'parameter_block'):
            Transition('run_aligning', ('ack',)),
        ('run_aligning', 'alignment_done'):
            Transition('run_accumulating', ('initial_alignment',)),
        ('run_accumulating', 'accumulation_done'):
            Transition('runs_ready', ('calibration_run_result',)),
        ('run_accumulating', 'StopClbRun'):
            Transition('runs_ready', ('calibration_run_result',)),
        ('runs_ready', 'FinishClb'):
            Transition('calibration_deciding', ('calibration_result',), erratum='E37'),
        ('awaiting_parameters', 'AHRScont1'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'AHRScont2'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'AHRScont3'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'AHRSreq1'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'AHRSreq2'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'AHRSreq3'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'NMEAcont'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'NMEAreq'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'GetDataReq'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'Stop'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'LoadAHRSPar'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'ReadAHRSPar'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'LowPowerOn'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'LowPowerOff'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'GetVerFirmware'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'GetBIT'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'Start2DClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'Start2D2TClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'Start3DClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'StartClbRun'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'StopClbRun'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'FinishClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'AcceptClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'ExitClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'ClearClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('awaiting_parameters', 'GetClbRes'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AHRScont1'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AHRScont2'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AHRScont3'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AHRSreq1'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AHRSreq2'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AHRSreq3'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'NMEAcont'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'NMEAreq'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'GetDataReq'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'Stop'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'LoadAHRSPar'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'ReadAHRSPar'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'LowPowerOn'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'LowPowerOff'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'GetVerFirmware'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'GetBIT'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'Start2DClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'Start2D2TClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'Start3DClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'StartClbRun'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'StopClbRun'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'FinishClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'AcceptClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'ClearClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('calibration_awaiting_parameters', 'GetClbRes'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AHRScont1'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AHRScont2'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AHRScont3'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AHRSreq1'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AHRSreq2'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AHRSreq3'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'NMEAcont'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'NMEAreq'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'GetDataReq'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'Stop'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'LoadAHRSPar'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'ReadAHRSPar'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'LowPowerOn'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'LowPowerOff'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'GetVerFirmware'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'GetBIT'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'Start2DClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'Start2D2TClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'Start3DClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'StartClbRun'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'StopClbRun'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'FinishClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'AcceptClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'ClearClb'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('runs_awaiting_parameters', 'GetClbRes'):
            Transition('idle', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AHRScont1'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AHRScont2'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AHRScont3'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AHRSreq1'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AHRSreq2'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AHRSreq3'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'NMEAcont'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'NMEAreq'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'GetDataReq'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'Stop'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'LoadAHRSPar'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'ReadAHRSPar'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'LowPowerOn'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'LowPowerOff'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'GetVerFirmware'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'GetBIT'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'Start2DClb'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'Start2D2TClb'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'Start3DClb'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'StartClbRun'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'StopClbRun'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'FinishClb'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'AcceptClb'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'ClearClb'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
        ('run_awaiting_parameters', 'GetClbRes'):
            Transition('runs_ready', (), wildcard=True, erratum='E34'),
    }
)
"""(state, event) -> transition, for the current firmware."""

LEGACY_TRANSITIONS: Final[Mapping[tuple[str, str], tuple[str, Transition]]] = MappingProxyType(
    {
        ('runs_ready', 'StopClbRun'):
            ('4.9.9.0', Transition('calibration_deciding', ('calibration_result',), erratum='E29')),
    }
)
"""(state, event) -> (firmware version, transition): rows that replace the current ones on
firmware older than that version."""

_SHARED_CODES: Final[Mapping[tuple[int, str], str]] = MappingProxyType(
    {
        (0xFE, 'idle'): 'Stop',
        (0xFE, 'continuous'): 'Stop',
        (0xFE, 'on_request'): 'Stop',
        (0xFE, 'calibration'): 'ExitClb',
        (0xFE, 'sleep'): 'Stop',
    }
)


def firmware_version(text: str) -> tuple[int, ...]:
    """"4.9.9.0" -> (4, 9, 9, 0); non-numeric parts count as 0."""
    return tuple(int(part) if part.isdigit() else 0 for part in text.strip().split("."))


def lookup(state: str, event: str, firmware: str | None = None) -> Transition | None:
    """The transition for `event` in `state` on the given firmware version (default: current), or
    None: the device ignores the event (E33)."""
    if firmware is not None:
        legacy = LEGACY_TRANSITIONS.get((state, event))
        if legacy is not None and firmware_version(firmware) < firmware_version(legacy[0]):
            return legacy[1]
    return TRANSITIONS.get((state, event))


def command_event(code: int, state: str) -> str | None:
    """The command a code means in `state`: of the names sharing a code, the one valid in the
    state's mode, else the code's default name (0xFE is ExitClb in calibration, Stop elsewhere,
    E14); None for a code no command has."""
    names = CODES.get(code)
    if names is None:
        return None
    if len(names) == 1:
        return names[0]
    return _SHARED_CODES.get((code, STATES[state].mode))


def timer_transition(state: str) -> tuple[str, Transition] | None:
    """(event, transition) of the timer running in `state`, if any."""
    timer = STATES[state].timer
    if timer is None:
        return None
    event = TIMER_EVENTS[timer]
    transition = TRANSITIONS.get((state, event))
    return None if transition is None else (event, transition)


def mermaid() -> str:
    """The table as a Mermaid state diagram (`*` rows folded into one `*` label per edge)."""
    return "\n".join(_MERMAID) + "\n"


_MERMAID: Final = (
    'stateDiagram-v2',
    '    [*] --> idle',
    '    idle --> aligning_continuous: AHRScont1 / ack, AHRScont2 / ack, AHRScont3 / ack, NMEAcont / ack',
    '    idle --> aligning_on_request: AHRSreq1 / ack, AHRSreq2 / ack, AHRSreq3 / ack, NMEAreq / ack',
    '    idle --> awaiting_parameters: LoadAHRSPar',
    (
        '    idle --> idle: ReadAHRSPar / ahrs_parameters_read, GetVerFirmware / firmware_version, GetBIT / '
        'bit_result, ClearClb / ack, GetClbRes / calibration_status, Stop'
    ),
    '    on_request --> on_request: GetBIT / bit_result, GetDataReq / output',
    '    idle --> sleep: LowPowerOn',
    '    idle --> calibration_awaiting_parameters: Start2DClb, Start3DClb',
    '    idle --> runs_awaiting_parameters: Start2D2TClb',
    '    awaiting_parameters --> idle: parameter_block / ack, unknown, other_message, block_timeout, *',
    '    calibration_awaiting_parameters --> idle: unknown, other_message, block_timeout, ExitClb / ack, *',
    '    runs_awaiting_parameters --> idle: unknown, other_message, block_timeout, ExitClb / ack, *',
    '    run_awaiting_parameters --> idle: ExitClb / ack',
    '    run_awaiting_parameters --> runs_ready: unknown, other_message, block_timeout, *',
    '    aligning_continuous --> continuous: alignment_done / initial_alignment',
    '    aligning_on_request --> on_request: alignment_done / initial_alignment',
    '    continuous --> continuous: output_due / output',
    '    aligning_continuous --> idle: Stop',
    '    continuous --> idle: Stop',
    '    aligning_on_request --> idle: Stop',
    '    on_request --> idle: Stop',
    '    continuous --> sleep: LowPowerOn / output_sleep',
    '    on_request --> sleep: LowPowerOn',
    '    sleep --> idle: LowPowerOff',
    '    calibration_awaiting_parameters --> calibration_aligning: parameter_block / ack',
    '    calibration_aligning --> calibration_accumulating: alignment_done / initial_alignment',
    (
        '    calibration_accumulating --> calibration_deciding: accumulation_done / calibration_result, StopClbRun '
        '/ calibration_result'
    ),
    '    calibration_deciding --> idle: AcceptClb / ack, ExitClb / ack',
    '    calibration_aligning --> idle: ExitClb / ack',
    '    calibration_accumulating --> idle: ExitClb / ack',
    '    runs_ready --> idle: ExitClb / ack',
    '    run_aligning --> idle: ExitClb / ack',
    '    run_accumulating --> idle: ExitClb / ack',
    '    runs_awaiting_parameters --> runs_ready: parameter_block / ack',
    '    runs_ready --> run_awaiting_parameters: StartClbRun',
    '    run_awaiting_parameters --> run_aligning: parameter_block / ack',
    '    run_aligning --> run_accumulating: alignment_done / initial_alignment',
    (
        '    run_accumulating --> runs_ready: accumulation_done / calibration_run_result, StopClbRun / '
        'calibration_run_result'
    ),
    (
        '    runs_ready --> calibration_deciding: FinishClb / calibration_result, StopClbRun (firmware before '
        '4.9.9.0) / calibration_result'
    ),
)
