# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""The commands of Table C.1, their parameter blocks and the acknowledgement.

Every command is a frame of message type 0 whose one-byte payload is the command code.
Stop and ExitClb share the code 0xFE (E14). A command followed by a parameter block
(ahrs_parameters_load, calibration_parameters, calibration_run_parameters) is sent as two
frames: the command, then the block as a data frame (E5). The functions are `ilahrs.commandset`'s.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Final

from .commandset import CommandInfo, CommandSet
from .payloads import PAYLOADS, Acknowledgement

__all__ = [
    "CODES",
    "COMMANDS",
    "CommandInfo",
    "ack_for",
    "build_command",
    "build_parameter_block",
    "command_names",
    "decode_command",
]

COMMANDS: Final[Mapping[str, CommandInfo]] = MappingProxyType(
    {
        "AHRScont1": CommandInfo(
            name="AHRScont1",
            id="ahrs_cont1",
            code=0x80,
            icd="6.3.1",
            group="control",
            purpose="Start continuous output in the Full Output Data format (Table 6.4).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="continuous",
            starts_output="full_output",
            shares_code_with=None,
            former_names=(),
        ),
        "AHRScont2": CommandInfo(
            name="AHRScont2",
            id="ahrs_cont2",
            code=0x82,
            icd="6.3.1",
            group="control",
            purpose="Start continuous output in the Quaternion of Orientation format (Table 6.5).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="continuous",
            starts_output="quaternion",
            shares_code_with=None,
            former_names=(),
        ),
        "AHRScont3": CommandInfo(
            name="AHRScont3",
            id="ahrs_cont3",
            code=0x83,
            icd="6.3.1",
            group="control",
            purpose="Start continuous output in the Orientation + Sensor Outputs format (Table 6.6).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="continuous",
            starts_output="orientation_sensors",
            shares_code_with=None,
            former_names=(),
        ),
        "AHRSreq1": CommandInfo(
            name="AHRSreq1",
            id="ahrs_req1",
            code=0x84,
            icd="6.3.2",
            group="control",
            purpose="Start on-request output in the Full Output Data format (Table 6.4).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="on_request",
            starts_output="full_output",
            shares_code_with=None,
            former_names=(),
        ),
        "AHRSreq2": CommandInfo(
            name="AHRSreq2",
            id="ahrs_req2",
            code=0x86,
            icd="6.3.2",
            group="control",
            purpose="Start on-request output in the Quaternion of Orientation format (Table 6.5).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="on_request",
            starts_output="quaternion",
            shares_code_with=None,
            former_names=(),
        ),
        "AHRSreq3": CommandInfo(
            name="AHRSreq3",
            id="ahrs_req3",
            code=0x87,
            icd="6.3.2",
            group="control",
            purpose="Start on-request output in the Orientation + Sensor Outputs format (Table 6.6).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="on_request",
            starts_output="orientation_sensors",
            shares_code_with=None,
            former_names=(),
        ),
        "NMEAcont": CommandInfo(
            name="NMEAcont",
            id="nmea_cont",
            code=0x88,
            icd="6.3.3",
            group="control",
            purpose="Start continuous output of $PAHR sentences (Table 6.7), at most 50 Hz.",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="continuous",
            starts_output="nmea",
            shares_code_with=None,
            former_names=(),
        ),
        "NMEAreq": CommandInfo(
            name="NMEAreq",
            id="nmea_req",
            code=0x89,
            icd="6.3.3",
            group="control",
            purpose="Start on-request output of $PAHR sentences (Table 6.7).",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode="on_request",
            starts_output="nmea",
            shares_code_with=None,
            former_names=(),
        ),
        "GetDataReq": CommandInfo(
            name="GetDataReq",
            id="get_data_req",
            code=0xCA,
            icd="6.3.4",
            group="control",
            purpose="Ask for one block of the current output format in the On Request mode.",
            valid_in=("on_request",),
            response="output",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "Stop": CommandInfo(
            name="Stop",
            id="stop",
            code=0xFE,
            icd="6.3.5",
            group="control",
            purpose="Stop the current operating mode and go to idle.",
            valid_in=("idle", "continuous", "on_request"),
            response="none",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with="ExitClb",
            former_names=(),
        ),
        "LoadAHRSPar": CommandInfo(
            name="LoadAHRSPar",
            id="load_ahrs_par",
            code=0x40,
            icd="6.3.6",
            group="control",
            purpose="Load the user parameter block (Table 6.9) into non-volatile memory.",
            valid_in=("idle",),
            response="none",
            response_payloads=(),
            parameter_block="ahrs_parameters_load",
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "ReadAHRSPar": CommandInfo(
            name="ReadAHRSPar",
            id="read_ahrs_par",
            code=0x41,
            icd="6.3.7",
            group="control",
            purpose="Read the parameter block (Table 6.10) from non-volatile memory.",
            valid_in=("idle",),
            response="data",
            response_payloads=("ahrs_parameters_read",),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "LowPowerOn": CommandInfo(
            name="LowPowerOn",
            id="low_power_on",
            code=0xB0,
            icd="6.3.8",
            group="control",
            purpose="Switch to the low-power Sleep mode.",
            valid_in=("idle", "continuous", "on_request"),
            response="none",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "LowPowerOff": CommandInfo(
            name="LowPowerOff",
            id="low_power_off",
            code=0xBA,
            icd="6.3.9",
            group="control",
            purpose="Wake from Sleep mode into idle.",
            valid_in=("sleep",),
            response="none",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "GetVerFirmware": CommandInfo(
            name="GetVerFirmware",
            id="get_ver_firmware",
            code=0x1F,
            icd="6.3.10",
            group="control",
            purpose="Read the firmware version string (Table 6.11).",
            valid_in=("idle",),
            response="data",
            response_payloads=("firmware_version",),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "GetBIT": CommandInfo(
            name="GetBIT",
            id="get_bit",
            code=0x1A,
            icd="6.3.11",
            group="control",
            purpose="Read the built-in-test answer, temperature and Unit Status Word (Table 6.12).",
            valid_in=("idle", "on_request"),
            response="data",
            response_payloads=("bit_result",),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "Start2DClb": CommandInfo(
            name="Start2DClb",
            id="start_2d_clb",
            code=0x21,
            icd="6.4.8",
            group="calibration",
            purpose="Start 2D hard/soft-iron calibration; the calibration parameter block (Table 6.13) follows.",
            valid_in=("idle",),
            response="none",
            response_payloads=(),
            parameter_block="calibration_parameters",
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "Start2D2TClb": CommandInfo(
            name="Start2D2TClb",
            id="start_2d2t_clb",
            code=0x22,
            icd="6.4.5",
            group="calibration",
            purpose="Start 2D-2T (multi-run) calibration; the calibration parameter block (Table 6.13) follows.",
            valid_in=("idle",),
            response="none",
            response_payloads=(),
            parameter_block="calibration_parameters",
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "Start3DClb": CommandInfo(
            name="Start3DClb",
            id="start_3d_clb",
            code=0x23,
            icd="6.4.1",
            group="calibration",
            purpose="Start 3D calibration; the calibration parameter block (Table 6.13) follows.",
            valid_in=("idle",),
            response="none",
            response_payloads=(),
            parameter_block="calibration_parameters",
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "StartClbRun": CommandInfo(
            name="StartClbRun",
            id="start_clb_run",
            code=0x2B,
            icd="6.4.6",
            group="calibration",
            purpose="Start one run of a multi-run (2D-2T) calibration; the run parameter block (Table 6.16) follows.",
            valid_in=("calibration",),
            response="none",
            response_payloads=(),
            parameter_block="calibration_run_parameters",
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "StopClbRun": CommandInfo(
            name="StopClbRun",
            id="stop_clb_run",
            code=0x20,
            icd="6.4.2",
            group="calibration",
            purpose="Stop data accumulation in the current calibration run before its set time.",
            valid_in=("calibration",),
            response="data",
            response_payloads=("calibration_result", "calibration_run_result"),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=("StopClb",),
        ),
        "FinishClb": CommandInfo(
            name="FinishClb",
            id="finish_clb",
            code=0x2C,
            icd="6.4.7",
            group="calibration",
            purpose="Finish a multi-run (2D-2T) calibration and compute its result (Table 6.14).",
            valid_in=("calibration",),
            response="data",
            response_payloads=("calibration_result",),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "AcceptClb": CommandInfo(
            name="AcceptClb",
            id="accept_clb",
            code=0x2E,
            icd="6.4.3",
            group="calibration",
            purpose="Accept the calibration result and save it to non-volatile memory; go to idle.",
            valid_in=("calibration",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "ExitClb": CommandInfo(
            name="ExitClb",
            id="exit_clb",
            code=0xFE,
            icd="6.4.4",
            group="calibration",
            purpose="Leave calibration without computing or saving anything; go to idle.",
            valid_in=("calibration",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with="Stop",
            former_names=(),
        ),
        "ClearClb": CommandInfo(
            name="ClearClb",
            id="clear_clb",
            code=0x2F,
            icd="6.4.9",
            group="calibration",
            purpose="Clear the hard/soft-iron calibration parameters from non-volatile memory.",
            valid_in=("idle",),
            response="ack",
            response_payloads=(),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
        "GetClbRes": CommandInfo(
            name="GetClbRes",
            id="get_clb_res",
            code=0x2A,
            icd="6.4.10",
            group="calibration",
            purpose="Read the results of the last calibration (Table 6.17).",
            valid_in=("idle",),
            response="data",
            response_payloads=("calibration_status",),
            parameter_block=None,
            starts_mode=None,
            starts_output=None,
            shares_code_with=None,
            former_names=(),
        ),
    }
)
"""Every command by ICD name."""

CODES: Final[Mapping[int, tuple[str, ...]]] = MappingProxyType(
    {
        0x1A: ("GetBIT",),
        0x1F: ("GetVerFirmware",),
        0x20: ("StopClbRun",),
        0x21: ("Start2DClb",),
        0x22: ("Start2D2TClb",),
        0x23: ("Start3DClb",),
        0x2A: ("GetClbRes",),
        0x2B: ("StartClbRun",),
        0x2C: ("FinishClb",),
        0x2E: ("AcceptClb",),
        0x2F: ("ClearClb",),
        0x40: ("LoadAHRSPar",),
        0x41: ("ReadAHRSPar",),
        0x80: ("AHRScont1",),
        0x82: ("AHRScont2",),
        0x83: ("AHRScont3",),
        0x84: ("AHRSreq1",),
        0x86: ("AHRSreq2",),
        0x87: ("AHRSreq3",),
        0x88: ("NMEAcont",),
        0x89: ("NMEAreq",),
        0xB0: ("LowPowerOn",),
        0xBA: ("LowPowerOff",),
        0xCA: ("GetDataReq",),
        0xFE: ("ExitClb", "Stop"),
    }
)
"""Every command code with its ICD name(s), sorted."""
AHRS_CONT1: Final = 0x80
"""AHRScont1 (6.3.1): Start continuous output in the Full Output Data format (Table 6.4)."""
AHRS_CONT2: Final = 0x82
"""AHRScont2 (6.3.1): Start continuous output in the Quaternion of Orientation format (Table 6.5)."""
AHRS_CONT3: Final = 0x83
"""AHRScont3 (6.3.1): Start continuous output in the Orientation + Sensor Outputs format (Table 6.6)."""
AHRS_REQ1: Final = 0x84
"""AHRSreq1 (6.3.2): Start on-request output in the Full Output Data format (Table 6.4)."""
AHRS_REQ2: Final = 0x86
"""AHRSreq2 (6.3.2): Start on-request output in the Quaternion of Orientation format (Table 6.5)."""
AHRS_REQ3: Final = 0x87
"""AHRSreq3 (6.3.2): Start on-request output in the Orientation + Sensor Outputs format (Table 6.6)."""
NMEA_CONT: Final = 0x88
"""NMEAcont (6.3.3): Start continuous output of $PAHR sentences (Table 6.7), at most 50 Hz."""
NMEA_REQ: Final = 0x89
"""NMEAreq (6.3.3): Start on-request output of $PAHR sentences (Table 6.7)."""
GET_DATA_REQ: Final = 0xCA
"""GetDataReq (6.3.4): Ask for one block of the current output format in the On Request mode."""
STOP: Final = 0xFE
"""Stop (6.3.5): Stop the current operating mode and go to idle."""
LOAD_AHRS_PAR: Final = 0x40
"""LoadAHRSPar (6.3.6): Load the user parameter block (Table 6.9) into non-volatile memory."""
READ_AHRS_PAR: Final = 0x41
"""ReadAHRSPar (6.3.7): Read the parameter block (Table 6.10) from non-volatile memory."""
LOW_POWER_ON: Final = 0xB0
"""LowPowerOn (6.3.8): Switch to the low-power Sleep mode."""
LOW_POWER_OFF: Final = 0xBA
"""LowPowerOff (6.3.9): Wake from Sleep mode into idle."""
GET_VER_FIRMWARE: Final = 0x1F
"""GetVerFirmware (6.3.10): Read the firmware version string (Table 6.11)."""
GET_BIT: Final = 0x1A
"""GetBIT (6.3.11): Read the built-in-test answer, temperature and Unit Status Word (Table 6.12)."""
START_2D_CLB: Final = 0x21
"""Start2DClb (6.4.8): Start 2D hard/soft-iron calibration; the calibration parameter block (Table 6.13)
follows."""
START_2D2T_CLB: Final = 0x22
"""Start2D2TClb (6.4.5): Start 2D-2T (multi-run) calibration; the calibration parameter block (Table 6.13)
follows."""
START_3D_CLB: Final = 0x23
"""Start3DClb (6.4.1): Start 3D calibration; the calibration parameter block (Table 6.13) follows."""
START_CLB_RUN: Final = 0x2B
"""StartClbRun (6.4.6): Start one run of a multi-run (2D-2T) calibration; the run parameter block (Table
6.16) follows."""
STOP_CLB_RUN: Final = 0x20
"""StopClbRun (6.4.2): Stop data accumulation in the current calibration run before its set time."""
FINISH_CLB: Final = 0x2C
"""FinishClb (6.4.7): Finish a multi-run (2D-2T) calibration and compute its result (Table 6.14)."""
ACCEPT_CLB: Final = 0x2E
"""AcceptClb (6.4.3): Accept the calibration result and save it to non-volatile memory; go to idle."""
EXIT_CLB: Final = 0xFE
"""ExitClb (6.4.4): Leave calibration without computing or saving anything; go to idle."""
CLEAR_CLB: Final = 0x2F
"""ClearClb (6.4.9): Clear the hard/soft-iron calibration parameters from non-volatile memory."""
GET_CLB_RES: Final = 0x2A
"""GetClbRes (6.4.10): Read the results of the last calibration (Table 6.17)."""

COMMAND_SET: Final = CommandSet(COMMANDS, CODES, Acknowledgement, PAYLOADS)
"""The table, with the functions of `ilahrs.commandset`; the acknowledgement is a acknowledgement block."""
command_names: Final = COMMAND_SET.command_names
build_command: Final = COMMAND_SET.build_command
build_parameter_block: Final = COMMAND_SET.build_parameter_block
decode_command: Final = COMMAND_SET.decode_command
ack_for: Final = COMMAND_SET.ack_for
