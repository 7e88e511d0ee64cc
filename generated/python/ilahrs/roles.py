# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""The part each command plays in the flows of the serial client (`ilahrs.serial`) and the device
model (`ilahrs.session.device`), found from the spec's structure by the generator, not by name: what a
command answers in the initial state, the block it takes and where that leads, the effects of its
transitions, the timers (generator/targets/python/roles.py)."""

from __future__ import annotations

from typing import Final

from .payloads import AhrsParametersRead

__all__ = [
    "ACCEPT",
    "BUILT_IN_TEST",
    "CALIBRATION_RESULTS",
    "CLEAR_CALIBRATION",
    "FINISH",
    "FIRMWARE",
    "GET_DATA",
    "LOAD_PARAMETERS",
    "LOW_POWER_OFF",
    "LOW_POWER_ON",
    "READ_PARAMETERS",
    "START_RUN",
    "START_RUNS",
    "STOP",
    "STOP_RUN",
    "ParameterBlock",
]

STOP: Final = "Stop"
"""Back to the initial state from every output state (its code also leaves calibration)."""
READ_PARAMETERS: Final = "ReadAHRSPar"
"""Read the parameter memory: the block with every value the load block carries."""
LOAD_PARAMETERS: Final = "LoadAHRSPar"
"""Load the parameter block that the device stores."""
FIRMWARE: Final = "GetVerFirmware"
"""Read the firmware version text."""
BUILT_IN_TEST: Final = "GetBIT"
"""Read the built-in test and USW."""
CALIBRATION_RESULTS: Final = "GetClbRes"
"""Read the results of the last calibration."""
GET_DATA: Final = "GetDataReq"
"""Ask for one output block (on-request mode)."""
LOW_POWER_ON: Final = "LowPowerOn"
"""Enter the low-power state."""
LOW_POWER_OFF: Final = "LowPowerOff"
"""Leave the low-power state."""
START_RUNS: Final = "Start2D2TClb"
"""Start a multi-run (2D-2T) calibration."""
START_RUN: Final = "StartClbRun"
"""Start one run of a multi-run calibration."""
STOP_RUN: Final = "StopClbRun"
"""End a run's data accumulation early."""
FINISH: Final = "FinishClb"
"""Finish a multi-run calibration and compute its result."""
ACCEPT: Final = "AcceptClb"
"""Accept and save the calibration result (effect save_calibration)."""
CLEAR_CALIBRATION: Final = "ClearClb"
"""Clear the saved calibration (effect clear_calibration)."""

ParameterBlock = AhrsParametersRead
"""The parameter memory, as READ_PARAMETERS answers it (Table 6.10)."""
