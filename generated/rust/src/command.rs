// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Commands (Appendix C, Table C.1): one-byte command frames, decoding a code back to the
//! command names, and the parameter blocks that follow some commands.
//!
//! ```
//! use ilahrs::command::{decode_command, Command};
//!
//! let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
//! let n = Command::AhrsCont1.build(&mut buf)?;
//! let (code, names) = decode_command(&buf[..n])?;
//! assert_eq!(code, 0x80);
//! assert_eq!(names, &[Command::AhrsCont1]);
//! assert_eq!(Command::from_name("AHRScont1"), Some(Command::AhrsCont1));
//! # Ok::<(), ilahrs::Error>(())
//! ```

mod frames;

pub use frames::{build_command, decode_command, Response};

use crate::error::Result;
use crate::payload::{self, PayloadKind};

/// The buffer a command and the parameter block that follows it need together, for the
/// largest block (bytes): a command frame (9 bytes, the frame around the one-byte code)
/// and the data frame of Table 6.9, Parameters to load (58 bytes), the block
/// after `LoadAHRSPar`.
///
/// [`crate::frame::MAX_FRAME_SIZE`] holds one frame: a buffer of this size holds what any
/// `build_...` function for a command with its block writes.
pub const MAX_COMMAND_WITH_BLOCK_SIZE: usize = 67;

/// An operating mode of the AHRS (section 6.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    /// All sensors powered; the AHRS waits for a command. Indicator red. The mode after power-up (6.3). (6.1 (1))
    Idle,
    /// Endless output of data blocks at the configured update rate. Indicator green. (6.1 (2))
    Continuous,
    /// One data block after each GetDataReq. Indicator green. (6.1 (3))
    OnRequest,
    /// Embedded hard- and soft-iron calibration procedure. (6.1 (4), 6.4)
    Calibration,
    /// Low-power mode; no output; the AHRS waits for LowPowerOff. Indicator off. (6.1 (5))
    Sleep,
}

impl Mode {
    /// Every mode, in the spec's order.
    pub const ALL: [Mode; 5] = [
        Mode::Idle,
        Mode::Continuous,
        Mode::OnRequest,
        Mode::Calibration,
        Mode::Sleep,
    ];

    /// The mode's name in the spec.
    pub const fn name(self) -> &'static str {
        match self {
            Mode::Idle => "idle",
            Mode::Continuous => "continuous",
            Mode::OnRequest => "on_request",
            Mode::Calibration => "calibration",
            Mode::Sleep => "sleep",
        }
    }
}

/// A command of Table C.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Command {
    /// `AHRScont1` (0x80, 6.3.1): Start continuous output in the Full Output Data format (Table 6.4).
    AhrsCont1,
    /// `AHRScont2` (0x82, 6.3.1): Start continuous output in the Quaternion of Orientation format (Table 6.5).
    AhrsCont2,
    /// `AHRScont3` (0x83, 6.3.1): Start continuous output in the Orientation + Sensor Outputs format (Table 6.6).
    AhrsCont3,
    /// `AHRSreq1` (0x84, 6.3.2): Start on-request output in the Full Output Data format (Table 6.4).
    AhrsReq1,
    /// `AHRSreq2` (0x86, 6.3.2): Start on-request output in the Quaternion of Orientation format (Table 6.5).
    AhrsReq2,
    /// `AHRSreq3` (0x87, 6.3.2): Start on-request output in the Orientation + Sensor Outputs format (Table 6.6).
    AhrsReq3,
    /// `NMEAcont` (0x88, 6.3.3): Start continuous output of $PAHR sentences (Table 6.7), at most 50 Hz.
    NmeaCont,
    /// `NMEAreq` (0x89, 6.3.3): Start on-request output of $PAHR sentences (Table 6.7).
    NmeaReq,
    /// `GetDataReq` (0xCA, 6.3.4): Ask for one block of the current output format in the On Request mode.
    GetDataReq,
    /// `Stop` (0xFE, 6.3.5): Stop the current operating mode and go to idle. (E14)
    Stop,
    /// `LoadAHRSPar` (0x40, 6.3.6): Load the user parameter block (Table 6.9) into non-volatile memory. (E13)
    LoadAhrsPar,
    /// `ReadAHRSPar` (0x41, 6.3.7): Read the parameter block (Table 6.10) from non-volatile memory.
    ReadAhrsPar,
    /// `LowPowerOn` (0xB0, 6.3.8): Switch to the low-power Sleep mode. (E35)
    LowPowerOn,
    /// `LowPowerOff` (0xBA, 6.3.9): Wake from Sleep mode into idle.
    LowPowerOff,
    /// `GetVerFirmware` (0x1F, 6.3.10): Read the firmware version string (Table 6.11).
    GetVerFirmware,
    /// `GetBIT` (0x1A, 6.3.11): Read the built-in-test answer, temperature and Unit Status Word (Table 6.12). (E25)
    GetBit,
    /// `Start2DClb` (0x21, 6.4.8): Start 2D hard/soft-iron calibration; the calibration parameter block (Table 6.13) follows. (E13)
    Start2dClb,
    /// `Start2D2TClb` (0x22, 6.4.5): Start 2D-2T (multi-run) calibration; the calibration parameter block (Table 6.13) follows. (E13)
    Start2d2tClb,
    /// `Start3DClb` (0x23, 6.4.1): Start 3D calibration; the calibration parameter block (Table 6.13) follows. (E13)
    Start3dClb,
    /// `StartClbRun` (0x2B, 6.4.6): Start one run of a multi-run (2D-2T) calibration; the run parameter block (Table 6.16) follows. (E13)
    StartClbRun,
    /// `StopClbRun` (0x20, 6.4.2): Stop data accumulation in the current calibration run before its set time.
    StopClbRun,
    /// `FinishClb` (0x2C, 6.4.7): Finish a multi-run (2D-2T) calibration and compute its result (Table 6.14).
    FinishClb,
    /// `AcceptClb` (0x2E, 6.4.3): Accept the calibration result and save it to non-volatile memory; go to idle.
    AcceptClb,
    /// `ExitClb` (0xFE, 6.4.4): Leave calibration without computing or saving anything; go to idle. (E14)
    ExitClb,
    /// `ClearClb` (0x2F, 6.4.9): Clear the hard/soft-iron calibration parameters from non-volatile memory.
    ClearClb,
    /// `GetClbRes` (0x2A, 6.4.10): Read the results of the last calibration (Table 6.17).
    GetClbRes,
}

impl Command {
    /// Every command, in the order of Table C.1.
    pub const ALL: [Command; 26] = [
        Command::AhrsCont1,
        Command::AhrsCont2,
        Command::AhrsCont3,
        Command::AhrsReq1,
        Command::AhrsReq2,
        Command::AhrsReq3,
        Command::NmeaCont,
        Command::NmeaReq,
        Command::GetDataReq,
        Command::Stop,
        Command::LoadAhrsPar,
        Command::ReadAhrsPar,
        Command::LowPowerOn,
        Command::LowPowerOff,
        Command::GetVerFirmware,
        Command::GetBit,
        Command::Start2dClb,
        Command::Start2d2tClb,
        Command::Start3dClb,
        Command::StartClbRun,
        Command::StopClbRun,
        Command::FinishClb,
        Command::AcceptClb,
        Command::ExitClb,
        Command::ClearClb,
        Command::GetClbRes,
    ];

    /// The command whose ICD name is `name`, if any.
    pub fn from_name(name: &str) -> Option<Command> {
        Command::ALL
            .into_iter()
            .find(|command| command.name() == name)
    }

    /// The ICD's name of the command (`AHRScont1`).
    pub const fn name(self) -> &'static str {
        match self {
            Command::AhrsCont1 => "AHRScont1",
            Command::AhrsCont2 => "AHRScont2",
            Command::AhrsCont3 => "AHRScont3",
            Command::AhrsReq1 => "AHRSreq1",
            Command::AhrsReq2 => "AHRSreq2",
            Command::AhrsReq3 => "AHRSreq3",
            Command::NmeaCont => "NMEAcont",
            Command::NmeaReq => "NMEAreq",
            Command::GetDataReq => "GetDataReq",
            Command::Stop => "Stop",
            Command::LoadAhrsPar => "LoadAHRSPar",
            Command::ReadAhrsPar => "ReadAHRSPar",
            Command::LowPowerOn => "LowPowerOn",
            Command::LowPowerOff => "LowPowerOff",
            Command::GetVerFirmware => "GetVerFirmware",
            Command::GetBit => "GetBIT",
            Command::Start2dClb => "Start2DClb",
            Command::Start2d2tClb => "Start2D2TClb",
            Command::Start3dClb => "Start3DClb",
            Command::StartClbRun => "StartClbRun",
            Command::StopClbRun => "StopClbRun",
            Command::FinishClb => "FinishClb",
            Command::AcceptClb => "AcceptClb",
            Command::ExitClb => "ExitClb",
            Command::ClearClb => "ClearClb",
            Command::GetClbRes => "GetClbRes",
        }
    }

    /// The command's code, the one-byte payload of its frame.
    pub const fn code(self) -> u8 {
        match self {
            Command::AhrsCont1 => 0x80,
            Command::AhrsCont2 => 0x82,
            Command::AhrsCont3 => 0x83,
            Command::AhrsReq1 => 0x84,
            Command::AhrsReq2 => 0x86,
            Command::AhrsReq3 => 0x87,
            Command::NmeaCont => 0x88,
            Command::NmeaReq => 0x89,
            Command::GetDataReq => 0xCA,
            Command::Stop => 0xFE,
            Command::LoadAhrsPar => 0x40,
            Command::ReadAhrsPar => 0x41,
            Command::LowPowerOn => 0xB0,
            Command::LowPowerOff => 0xBA,
            Command::GetVerFirmware => 0x1F,
            Command::GetBit => 0x1A,
            Command::Start2dClb => 0x21,
            Command::Start2d2tClb => 0x22,
            Command::Start3dClb => 0x23,
            Command::StartClbRun => 0x2B,
            Command::StopClbRun => 0x20,
            Command::FinishClb => 0x2C,
            Command::AcceptClb => 0x2E,
            Command::ExitClb => 0xFE,
            Command::ClearClb => 0x2F,
            Command::GetClbRes => 0x2A,
        }
    }

    /// Every command with code `code`, sorted by ICD name (empty for an unknown code).
    pub const fn with_code(code: u8) -> &'static [Command] {
        match code {
            0x1A => &[Command::GetBit],
            0x1F => &[Command::GetVerFirmware],
            0x20 => &[Command::StopClbRun],
            0x21 => &[Command::Start2dClb],
            0x22 => &[Command::Start2d2tClb],
            0x23 => &[Command::Start3dClb],
            0x2A => &[Command::GetClbRes],
            0x2B => &[Command::StartClbRun],
            0x2C => &[Command::FinishClb],
            0x2E => &[Command::AcceptClb],
            0x2F => &[Command::ClearClb],
            0x40 => &[Command::LoadAhrsPar],
            0x41 => &[Command::ReadAhrsPar],
            0x80 => &[Command::AhrsCont1],
            0x82 => &[Command::AhrsCont2],
            0x83 => &[Command::AhrsCont3],
            0x84 => &[Command::AhrsReq1],
            0x86 => &[Command::AhrsReq2],
            0x87 => &[Command::AhrsReq3],
            0x88 => &[Command::NmeaCont],
            0x89 => &[Command::NmeaReq],
            0xB0 => &[Command::LowPowerOn],
            0xBA => &[Command::LowPowerOff],
            0xCA => &[Command::GetDataReq],
            0xFE => &[Command::ExitClb, Command::Stop],
            _ => &[],
        }
    }

    /// The ICD section that describes the command.
    pub const fn icd(self) -> &'static str {
        match self {
            Command::AhrsCont1 => "6.3.1",
            Command::AhrsCont2 => "6.3.1",
            Command::AhrsCont3 => "6.3.1",
            Command::AhrsReq1 => "6.3.2",
            Command::AhrsReq2 => "6.3.2",
            Command::AhrsReq3 => "6.3.2",
            Command::NmeaCont => "6.3.3",
            Command::NmeaReq => "6.3.3",
            Command::GetDataReq => "6.3.4",
            Command::Stop => "6.3.5",
            Command::LoadAhrsPar => "6.3.6",
            Command::ReadAhrsPar => "6.3.7",
            Command::LowPowerOn => "6.3.8",
            Command::LowPowerOff => "6.3.9",
            Command::GetVerFirmware => "6.3.10",
            Command::GetBit => "6.3.11",
            Command::Start2dClb => "6.4.8",
            Command::Start2d2tClb => "6.4.5",
            Command::Start3dClb => "6.4.1",
            Command::StartClbRun => "6.4.6",
            Command::StopClbRun => "6.4.2",
            Command::FinishClb => "6.4.7",
            Command::AcceptClb => "6.4.3",
            Command::ExitClb => "6.4.4",
            Command::ClearClb => "6.4.9",
            Command::GetClbRes => "6.4.10",
        }
    }

    /// The modes in which the AHRS accepts the command.
    pub const fn valid_in(self) -> &'static [Mode] {
        match self {
            Command::AhrsCont1 => &[Mode::Idle],
            Command::AhrsCont2 => &[Mode::Idle],
            Command::AhrsCont3 => &[Mode::Idle],
            Command::AhrsReq1 => &[Mode::Idle],
            Command::AhrsReq2 => &[Mode::Idle],
            Command::AhrsReq3 => &[Mode::Idle],
            Command::NmeaCont => &[Mode::Idle],
            Command::NmeaReq => &[Mode::Idle],
            Command::GetDataReq => &[Mode::OnRequest],
            Command::Stop => &[Mode::Idle, Mode::Continuous, Mode::OnRequest],
            Command::LoadAhrsPar => &[Mode::Idle],
            Command::ReadAhrsPar => &[Mode::Idle],
            Command::LowPowerOn => &[Mode::Idle, Mode::Continuous, Mode::OnRequest],
            Command::LowPowerOff => &[Mode::Sleep],
            Command::GetVerFirmware => &[Mode::Idle],
            Command::GetBit => &[Mode::Idle, Mode::OnRequest],
            Command::Start2dClb => &[Mode::Idle],
            Command::Start2d2tClb => &[Mode::Idle],
            Command::Start3dClb => &[Mode::Idle],
            Command::StartClbRun => &[Mode::Calibration],
            Command::StopClbRun => &[Mode::Calibration],
            Command::FinishClb => &[Mode::Calibration],
            Command::AcceptClb => &[Mode::Calibration],
            Command::ExitClb => &[Mode::Calibration],
            Command::ClearClb => &[Mode::Idle],
            Command::GetClbRes => &[Mode::Idle],
        }
    }

    /// What the AHRS sends back to the command itself.
    pub const fn response(self) -> Response {
        match self {
            Command::AhrsCont1 => Response::Ack,
            Command::AhrsCont2 => Response::Ack,
            Command::AhrsCont3 => Response::Ack,
            Command::AhrsReq1 => Response::Ack,
            Command::AhrsReq2 => Response::Ack,
            Command::AhrsReq3 => Response::Ack,
            Command::NmeaCont => Response::Ack,
            Command::NmeaReq => Response::Ack,
            Command::GetDataReq => Response::Output,
            Command::Stop => Response::None,
            Command::LoadAhrsPar => Response::None,
            Command::ReadAhrsPar => Response::Data(&[PayloadKind::AhrsParametersRead]),
            Command::LowPowerOn => Response::None,
            Command::LowPowerOff => Response::None,
            Command::GetVerFirmware => Response::Data(&[PayloadKind::FirmwareVersion]),
            Command::GetBit => Response::Data(&[PayloadKind::BitResult]),
            Command::Start2dClb => Response::None,
            Command::Start2d2tClb => Response::None,
            Command::Start3dClb => Response::None,
            Command::StartClbRun => Response::None,
            Command::StopClbRun => Response::Data(&[
                PayloadKind::CalibrationResult,
                PayloadKind::CalibrationRunResult,
            ]),
            Command::FinishClb => Response::Data(&[PayloadKind::CalibrationResult]),
            Command::AcceptClb => Response::Ack,
            Command::ExitClb => Response::Ack,
            Command::ClearClb => Response::Ack,
            Command::GetClbRes => Response::Data(&[PayloadKind::CalibrationStatus]),
        }
    }

    /// The payload table of the data message the host sends right after the command, if any.
    pub const fn parameter_block(self) -> Option<PayloadKind> {
        match self {
            Command::LoadAhrsPar => Some(PayloadKind::AhrsParametersLoad),
            Command::Start2dClb => Some(PayloadKind::CalibrationParameters),
            Command::Start2d2tClb => Some(PayloadKind::CalibrationParameters),
            Command::Start3dClb => Some(PayloadKind::CalibrationParameters),
            Command::StartClbRun => Some(PayloadKind::CalibrationRunParameters),
            _ => None,
        }
    }

    /// The mode the command starts, if it starts one.
    pub const fn starts_mode(self) -> Option<Mode> {
        match self {
            Command::AhrsCont1 => Some(Mode::Continuous),
            Command::AhrsCont2 => Some(Mode::Continuous),
            Command::AhrsCont3 => Some(Mode::Continuous),
            Command::AhrsReq1 => Some(Mode::OnRequest),
            Command::AhrsReq2 => Some(Mode::OnRequest),
            Command::AhrsReq3 => Some(Mode::OnRequest),
            Command::NmeaCont => Some(Mode::Continuous),
            Command::NmeaReq => Some(Mode::OnRequest),
            _ => None,
        }
    }
}

/// Writes `LoadAHRSPar` and, right after it, its parameter block (Table 6.9) as a
/// data frame into `buf`; returns the size of both (bytes).
///
/// Errors: those of [`payload::AhrsParametersLoadRepr::build`], `buffer_too_small` (a buffer of
/// [`MAX_COMMAND_WITH_BLOCK_SIZE`] bytes holds both).
pub fn build_load_ahrs_par(
    parameters: &payload::AhrsParametersLoadRepr,
    buf: &mut [u8],
) -> Result<usize> {
    frames::build_with_block(
        Command::LoadAhrsPar,
        |rest| parameters.build_frame(rest),
        buf,
    )
}

/// Writes `Start2DClb` and, right after it, its parameter block (Table 6.13) as a
/// data frame into `buf`; returns the size of both (bytes).
///
/// Errors: those of [`payload::CalibrationParametersRepr::build`], `buffer_too_small` (a buffer of
/// [`MAX_COMMAND_WITH_BLOCK_SIZE`] bytes holds both).
pub fn build_start_2d_clb(
    parameters: &payload::CalibrationParametersRepr,
    buf: &mut [u8],
) -> Result<usize> {
    frames::build_with_block(
        Command::Start2dClb,
        |rest| parameters.build_frame(rest),
        buf,
    )
}

/// Writes `Start2D2TClb` and, right after it, its parameter block (Table 6.13) as a
/// data frame into `buf`; returns the size of both (bytes).
///
/// Errors: those of [`payload::CalibrationParametersRepr::build`], `buffer_too_small` (a buffer of
/// [`MAX_COMMAND_WITH_BLOCK_SIZE`] bytes holds both).
pub fn build_start_2d2t_clb(
    parameters: &payload::CalibrationParametersRepr,
    buf: &mut [u8],
) -> Result<usize> {
    frames::build_with_block(
        Command::Start2d2tClb,
        |rest| parameters.build_frame(rest),
        buf,
    )
}

/// Writes `Start3DClb` and, right after it, its parameter block (Table 6.13) as a
/// data frame into `buf`; returns the size of both (bytes).
///
/// Errors: those of [`payload::CalibrationParametersRepr::build`], `buffer_too_small` (a buffer of
/// [`MAX_COMMAND_WITH_BLOCK_SIZE`] bytes holds both).
pub fn build_start_3d_clb(
    parameters: &payload::CalibrationParametersRepr,
    buf: &mut [u8],
) -> Result<usize> {
    frames::build_with_block(
        Command::Start3dClb,
        |rest| parameters.build_frame(rest),
        buf,
    )
}

/// Writes `StartClbRun` and, right after it, its parameter block (Table 6.16) as a
/// data frame into `buf`; returns the size of both (bytes).
///
/// Errors: those of [`payload::CalibrationRunParametersRepr::build`], `buffer_too_small` (a buffer of
/// [`MAX_COMMAND_WITH_BLOCK_SIZE`] bytes holds both).
pub fn build_start_clb_run(
    parameters: &payload::CalibrationRunParametersRepr,
    buf: &mut [u8],
) -> Result<usize> {
    frames::build_with_block(
        Command::StartClbRun,
        |rest| parameters.build_frame(rest),
        buf,
    )
}
