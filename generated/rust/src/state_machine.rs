// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! The device state machine (6.1, 6.3, 6.4): in each state, what the AHRS does on each command and
//! event, as a table generated from the spec's `state_machine`.
//!
//! [`transition`] looks a (state, event) pair up in [`TRANSITIONS`] (and, for firmware older than
//! a row's version, in [`OLDER_FIRMWARE`] first); `None` means the device ignores the event: no
//! answer, no change of state. [`Event::for_code`] and [`Event::for_data`] turn what arrives on
//! the wire into events: a command code names the command valid in the state's mode, a data
//! message is a parameter block when the state expects one of its size. [`Device`] holds a state
//! and applies events to it. No allocation, no I/O.
//!
//! ```
//! use ilahrs::state_machine::{transition, Answer, Device, Event, State};
//!
//! let step = transition(State::Idle, Event::AhrsCont1, None);
//! assert_eq!(step.map(|t| t.next), Some(State::AligningContinuous));
//!
//! let mut device = Device::new(None);
//! let (event, step) = device.handle_data(0);
//! assert_eq!(event, Event::OtherMessage);
//! assert_eq!(step.map(|t| t.sends), None);
//! ```

mod device;

pub use device::{transition, Device, Firmware, Row, Transition};

use crate::command::{Command, Mode};
use crate::payload::PayloadKind;
use crate::status::UswMode;
use device::row;

/// A state of the device.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum State {
    /// `idle` (idle mode): Waiting for a command (6.1).
    Idle,
    /// `awaiting_parameters` (idle mode, expects ahrs_parameters_load): LoadAHRSPar received; the parameter block must follow without pause (6.3.6).
    AwaitingParameters,
    /// `aligning_continuous` (continuous mode, alignment timer): Initial alignment before continuous output (6.3.1, 6.3.3).
    AligningContinuous,
    /// `continuous` (continuous mode, output timer): Output of the chosen format at the update rate (6.3.1).
    Continuous,
    /// `aligning_on_request` (on_request mode, alignment timer): Initial alignment before on-request output (6.3.2, 6.3.3).
    AligningOnRequest,
    /// `on_request` (on_request mode): One block of the chosen format per GetDataReq (6.3.2, 6.3.4).
    OnRequest,
    /// `sleep` (sleep mode): Low-power mode; only LowPowerOff is heard (6.3.8).
    Sleep,
    /// `calibration_awaiting_parameters` (calibration mode, expects calibration_parameters): Start2DClb or Start3DClb received; the calibration parameter block must follow (6.4.1, 6.4.8).
    CalibrationAwaitingParameters,
    /// `calibration_aligning` (calibration mode, alignment timer): Initial alignment before the single calibration run (6.4.1, 6.4.8).
    CalibrationAligning,
    /// `calibration_accumulating` (calibration mode, accumulation timer): Accumulating data while the object turns (6.4.1, 6.4.8).
    CalibrationAccumulating,
    /// `calibration_deciding` (calibration mode): Result sent; waiting for AcceptClb or ExitClb (6.4.1, 6.4.7).
    CalibrationDeciding,
    /// `runs_awaiting_parameters` (calibration mode, expects calibration_parameters): Start2D2TClb received; the calibration parameter block must follow (6.4.5).
    RunsAwaitingParameters,
    /// `runs_ready` (calibration mode): 2D-2T calibration between runs: waiting for StartClbRun, FinishClb or ExitClb (6.4.5). (E36)
    RunsReady,
    /// `run_awaiting_parameters` (calibration mode, expects calibration_run_parameters): StartClbRun received; the run parameter block must follow (6.4.6).
    RunAwaitingParameters,
    /// `run_aligning` (calibration mode, alignment timer): Initial alignment before a 2D-2T run (6.4.5).
    RunAligning,
    /// `run_accumulating` (calibration mode, accumulation timer): Accumulating data during a 2D-2T run (6.4.5).
    RunAccumulating,
}

impl State {
    /// The state after power-up.
    pub const INITIAL: State = State::Idle;

    /// Every state, in the spec's order.
    pub const ALL: [State; 16] = [
        State::Idle,
        State::AwaitingParameters,
        State::AligningContinuous,
        State::Continuous,
        State::AligningOnRequest,
        State::OnRequest,
        State::Sleep,
        State::CalibrationAwaitingParameters,
        State::CalibrationAligning,
        State::CalibrationAccumulating,
        State::CalibrationDeciding,
        State::RunsAwaitingParameters,
        State::RunsReady,
        State::RunAwaitingParameters,
        State::RunAligning,
        State::RunAccumulating,
    ];

    /// The state's name in the spec.
    pub const fn name(self) -> &'static str {
        match self {
            State::Idle => "idle",
            State::AwaitingParameters => "awaiting_parameters",
            State::AligningContinuous => "aligning_continuous",
            State::Continuous => "continuous",
            State::AligningOnRequest => "aligning_on_request",
            State::OnRequest => "on_request",
            State::Sleep => "sleep",
            State::CalibrationAwaitingParameters => "calibration_awaiting_parameters",
            State::CalibrationAligning => "calibration_aligning",
            State::CalibrationAccumulating => "calibration_accumulating",
            State::CalibrationDeciding => "calibration_deciding",
            State::RunsAwaitingParameters => "runs_awaiting_parameters",
            State::RunsReady => "runs_ready",
            State::RunAwaitingParameters => "run_awaiting_parameters",
            State::RunAligning => "run_aligning",
            State::RunAccumulating => "run_accumulating",
        }
    }

    /// The operating mode the device is in.
    pub const fn mode(self) -> Mode {
        match self {
            State::Idle => Mode::Idle,
            State::AwaitingParameters => Mode::Idle,
            State::AligningContinuous => Mode::Continuous,
            State::Continuous => Mode::Continuous,
            State::AligningOnRequest => Mode::OnRequest,
            State::OnRequest => Mode::OnRequest,
            State::Sleep => Mode::Sleep,
            State::CalibrationAwaitingParameters => Mode::Calibration,
            State::CalibrationAligning => Mode::Calibration,
            State::CalibrationAccumulating => Mode::Calibration,
            State::CalibrationDeciding => Mode::Calibration,
            State::RunsAwaitingParameters => Mode::Calibration,
            State::RunsReady => Mode::Calibration,
            State::RunAwaitingParameters => Mode::Calibration,
            State::RunAligning => Mode::Calibration,
            State::RunAccumulating => Mode::Calibration,
        }
    }

    /// The parameter block the state waits for, if any.
    pub const fn expects(self) -> Option<PayloadKind> {
        match self {
            State::AwaitingParameters => Some(PayloadKind::AhrsParametersLoad),
            State::CalibrationAwaitingParameters => Some(PayloadKind::CalibrationParameters),
            State::RunsAwaitingParameters => Some(PayloadKind::CalibrationParameters),
            State::RunAwaitingParameters => Some(PayloadKind::CalibrationRunParameters),
            _ => None,
        }
    }

    /// The event the state's timer fires, if a timer runs in it.
    pub const fn timer(self) -> Option<Event> {
        match self {
            State::AligningContinuous => Some(Event::AlignmentDone),
            State::Continuous => Some(Event::OutputDue),
            State::AligningOnRequest => Some(Event::AlignmentDone),
            State::CalibrationAligning => Some(Event::AlignmentDone),
            State::CalibrationAccumulating => Some(Event::AccumulationDone),
            State::RunAligning => Some(Event::AlignmentDone),
            State::RunAccumulating => Some(Event::AccumulationDone),
            _ => None,
        }
    }
}

/// What happens to the device: a command (by the name valid in the current mode) or another event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Event {
    /// The command `AHRScont1` (0x80, 6.3.1).
    AhrsCont1,
    /// The command `AHRScont2` (0x82, 6.3.1).
    AhrsCont2,
    /// The command `AHRScont3` (0x83, 6.3.1).
    AhrsCont3,
    /// The command `AHRSreq1` (0x84, 6.3.2).
    AhrsReq1,
    /// The command `AHRSreq2` (0x86, 6.3.2).
    AhrsReq2,
    /// The command `AHRSreq3` (0x87, 6.3.2).
    AhrsReq3,
    /// The command `NMEAcont` (0x88, 6.3.3).
    NmeaCont,
    /// The command `NMEAreq` (0x89, 6.3.3).
    NmeaReq,
    /// The command `GetDataReq` (0xCA, 6.3.4).
    GetDataReq,
    /// The command `Stop` (0xFE, 6.3.5).
    Stop,
    /// The command `LoadAHRSPar` (0x40, 6.3.6).
    LoadAhrsPar,
    /// The command `ReadAHRSPar` (0x41, 6.3.7).
    ReadAhrsPar,
    /// The command `LowPowerOn` (0xB0, 6.3.8).
    LowPowerOn,
    /// The command `LowPowerOff` (0xBA, 6.3.9).
    LowPowerOff,
    /// The command `GetVerFirmware` (0x1F, 6.3.10).
    GetVerFirmware,
    /// The command `GetBIT` (0x1A, 6.3.11).
    GetBit,
    /// The command `Start2DClb` (0x21, 6.4.8).
    Start2dClb,
    /// The command `Start2D2TClb` (0x22, 6.4.5).
    Start2d2tClb,
    /// The command `Start3DClb` (0x23, 6.4.1).
    Start3dClb,
    /// The command `StartClbRun` (0x2B, 6.4.6).
    StartClbRun,
    /// The command `StopClbRun` (0x20, 6.4.2).
    StopClbRun,
    /// The command `FinishClb` (0x2C, 6.4.7).
    FinishClb,
    /// The command `AcceptClb` (0x2E, 6.4.3).
    AcceptClb,
    /// The command `ExitClb` (0xFE, 6.4.4).
    ExitClb,
    /// The command `ClearClb` (0x2F, 6.4.9).
    ClearClb,
    /// The command `GetClbRes` (0x2A, 6.4.10).
    GetClbRes,
    /// A data message whose payload has the size of the table the current state expects.
    ParameterBlock,
    /// A data message of any other size.
    OtherMessage,
    /// A command frame whose code no command of Table C.1 has.
    Unknown,
    /// No parameter block within parameter_block_timeout_s of the command (E34).
    BlockTimeout,
    /// The initial alignment time (Table 6.9, 30 s by default) has elapsed.
    AlignmentDone,
    /// The accumulation time of the calibration run (Table 6.13) has elapsed.
    AccumulationDone,
    /// One output period has elapsed: 1 / update rate, at most 50 Hz for NMEA (E22).
    OutputDue,
}

impl Event {
    /// Every event: the commands, then the other events.
    pub const ALL: [Event; 33] = [
        Event::AhrsCont1,
        Event::AhrsCont2,
        Event::AhrsCont3,
        Event::AhrsReq1,
        Event::AhrsReq2,
        Event::AhrsReq3,
        Event::NmeaCont,
        Event::NmeaReq,
        Event::GetDataReq,
        Event::Stop,
        Event::LoadAhrsPar,
        Event::ReadAhrsPar,
        Event::LowPowerOn,
        Event::LowPowerOff,
        Event::GetVerFirmware,
        Event::GetBit,
        Event::Start2dClb,
        Event::Start2d2tClb,
        Event::Start3dClb,
        Event::StartClbRun,
        Event::StopClbRun,
        Event::FinishClb,
        Event::AcceptClb,
        Event::ExitClb,
        Event::ClearClb,
        Event::GetClbRes,
        Event::ParameterBlock,
        Event::OtherMessage,
        Event::Unknown,
        Event::BlockTimeout,
        Event::AlignmentDone,
        Event::AccumulationDone,
        Event::OutputDue,
    ];

    /// The event's name in the spec's table (a command's ICD name).
    pub const fn name(self) -> &'static str {
        match self {
            Event::AhrsCont1 => "AHRScont1",
            Event::AhrsCont2 => "AHRScont2",
            Event::AhrsCont3 => "AHRScont3",
            Event::AhrsReq1 => "AHRSreq1",
            Event::AhrsReq2 => "AHRSreq2",
            Event::AhrsReq3 => "AHRSreq3",
            Event::NmeaCont => "NMEAcont",
            Event::NmeaReq => "NMEAreq",
            Event::GetDataReq => "GetDataReq",
            Event::Stop => "Stop",
            Event::LoadAhrsPar => "LoadAHRSPar",
            Event::ReadAhrsPar => "ReadAHRSPar",
            Event::LowPowerOn => "LowPowerOn",
            Event::LowPowerOff => "LowPowerOff",
            Event::GetVerFirmware => "GetVerFirmware",
            Event::GetBit => "GetBIT",
            Event::Start2dClb => "Start2DClb",
            Event::Start2d2tClb => "Start2D2TClb",
            Event::Start3dClb => "Start3DClb",
            Event::StartClbRun => "StartClbRun",
            Event::StopClbRun => "StopClbRun",
            Event::FinishClb => "FinishClb",
            Event::AcceptClb => "AcceptClb",
            Event::ExitClb => "ExitClb",
            Event::ClearClb => "ClearClb",
            Event::GetClbRes => "GetClbRes",
            Event::ParameterBlock => "parameter_block",
            Event::OtherMessage => "other_message",
            Event::Unknown => "unknown",
            Event::BlockTimeout => "block_timeout",
            Event::AlignmentDone => "alignment_done",
            Event::AccumulationDone => "accumulation_done",
            Event::OutputDue => "output_due",
        }
    }

    /// The command, if the event is one.
    pub const fn command(self) -> Option<Command> {
        match self {
            Event::AhrsCont1 => Some(Command::AhrsCont1),
            Event::AhrsCont2 => Some(Command::AhrsCont2),
            Event::AhrsCont3 => Some(Command::AhrsCont3),
            Event::AhrsReq1 => Some(Command::AhrsReq1),
            Event::AhrsReq2 => Some(Command::AhrsReq2),
            Event::AhrsReq3 => Some(Command::AhrsReq3),
            Event::NmeaCont => Some(Command::NmeaCont),
            Event::NmeaReq => Some(Command::NmeaReq),
            Event::GetDataReq => Some(Command::GetDataReq),
            Event::Stop => Some(Command::Stop),
            Event::LoadAhrsPar => Some(Command::LoadAhrsPar),
            Event::ReadAhrsPar => Some(Command::ReadAhrsPar),
            Event::LowPowerOn => Some(Command::LowPowerOn),
            Event::LowPowerOff => Some(Command::LowPowerOff),
            Event::GetVerFirmware => Some(Command::GetVerFirmware),
            Event::GetBit => Some(Command::GetBit),
            Event::Start2dClb => Some(Command::Start2dClb),
            Event::Start2d2tClb => Some(Command::Start2d2tClb),
            Event::Start3dClb => Some(Command::Start3dClb),
            Event::StartClbRun => Some(Command::StartClbRun),
            Event::StopClbRun => Some(Command::StopClbRun),
            Event::FinishClb => Some(Command::FinishClb),
            Event::AcceptClb => Some(Command::AcceptClb),
            Event::ExitClb => Some(Command::ExitClb),
            Event::ClearClb => Some(Command::ClearClb),
            Event::GetClbRes => Some(Command::GetClbRes),
            _ => None,
        }
    }

    /// The event of receiving `command`.
    pub const fn from_command(command: Command) -> Event {
        match command {
            Command::AhrsCont1 => Event::AhrsCont1,
            Command::AhrsCont2 => Event::AhrsCont2,
            Command::AhrsCont3 => Event::AhrsCont3,
            Command::AhrsReq1 => Event::AhrsReq1,
            Command::AhrsReq2 => Event::AhrsReq2,
            Command::AhrsReq3 => Event::AhrsReq3,
            Command::NmeaCont => Event::NmeaCont,
            Command::NmeaReq => Event::NmeaReq,
            Command::GetDataReq => Event::GetDataReq,
            Command::Stop => Event::Stop,
            Command::LoadAhrsPar => Event::LoadAhrsPar,
            Command::ReadAhrsPar => Event::ReadAhrsPar,
            Command::LowPowerOn => Event::LowPowerOn,
            Command::LowPowerOff => Event::LowPowerOff,
            Command::GetVerFirmware => Event::GetVerFirmware,
            Command::GetBit => Event::GetBit,
            Command::Start2dClb => Event::Start2dClb,
            Command::Start2d2tClb => Event::Start2d2tClb,
            Command::Start3dClb => Event::Start3dClb,
            Command::StartClbRun => Event::StartClbRun,
            Command::StopClbRun => Event::StopClbRun,
            Command::FinishClb => Event::FinishClb,
            Command::AcceptClb => Event::AcceptClb,
            Command::ExitClb => Event::ExitClb,
            Command::ClearClb => Event::ClearClb,
            Command::GetClbRes => Event::GetClbRes,
        }
    }

    /// The event of receiving a command frame with `code` in `state`: of the commands sharing a
    /// code, the one valid in the state's mode; `unknown` for a code no command has.
    pub const fn for_code(code: u8, state: State) -> Event {
        match code {
            0x1A => Event::GetBit,
            0x1F => Event::GetVerFirmware,
            0x20 => Event::StopClbRun,
            0x21 => Event::Start2dClb,
            0x22 => Event::Start2d2tClb,
            0x23 => Event::Start3dClb,
            0x2A => Event::GetClbRes,
            0x2B => Event::StartClbRun,
            0x2C => Event::FinishClb,
            0x2E => Event::AcceptClb,
            0x2F => Event::ClearClb,
            0x40 => Event::LoadAhrsPar,
            0x41 => Event::ReadAhrsPar,
            0x80 => Event::AhrsCont1,
            0x82 => Event::AhrsCont2,
            0x83 => Event::AhrsCont3,
            0x84 => Event::AhrsReq1,
            0x86 => Event::AhrsReq2,
            0x87 => Event::AhrsReq3,
            0x88 => Event::NmeaCont,
            0x89 => Event::NmeaReq,
            0xB0 => Event::LowPowerOn,
            0xBA => Event::LowPowerOff,
            0xCA => Event::GetDataReq,
            0xFE => match state.mode() {
                Mode::Idle | Mode::Continuous | Mode::OnRequest | Mode::Sleep => Event::Stop,
                Mode::Calibration => Event::ExitClb,
            },
            _ => Event::Unknown,
        }
    }
}

/// What the device sends when it takes a transition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Answer {
    /// `ack`: The acknowledgement of the message just received.
    Ack,
    /// `ahrs_parameters_read`: One ahrs_parameters_read block (Table 6.10, Parameters read).
    AhrsParametersRead,
    /// `firmware_version`: One firmware_version block (Table 6.11, Firmware version).
    FirmwareVersion,
    /// `bit_result`: One bit_result block (Table 6.12, Built-in test answer).
    BitResult,
    /// `calibration_status`: One calibration_status block (Table 6.17, Calibration results read back).
    CalibrationStatus,
    /// `initial_alignment`: One initial_alignment block (Table 6.8, Initial alignment data).
    InitialAlignment,
    /// `output`: One block of the output format chosen by the start command.
    Output,
    /// `output_sleep`: One output block whose USW reports mode sleep (E35).
    OutputSleep,
    /// `calibration_result`: One calibration_result block (Table 6.14, Calibration result).
    CalibrationResult,
    /// `calibration_run_result`: One calibration_run_result block (Table 6.15, 2D-2T calibration run result).
    CalibrationRunResult,
}

impl Answer {
    /// The answer's name in the spec's table.
    pub const fn name(self) -> &'static str {
        match self {
            Answer::Ack => "ack",
            Answer::AhrsParametersRead => "ahrs_parameters_read",
            Answer::FirmwareVersion => "firmware_version",
            Answer::BitResult => "bit_result",
            Answer::CalibrationStatus => "calibration_status",
            Answer::InitialAlignment => "initial_alignment",
            Answer::Output => "output",
            Answer::OutputSleep => "output_sleep",
            Answer::CalibrationResult => "calibration_result",
            Answer::CalibrationRunResult => "calibration_run_result",
        }
    }

    /// The payload table of the block sent, when the answer names one.
    pub const fn payload(self) -> Option<PayloadKind> {
        match self {
            Answer::AhrsParametersRead => Some(PayloadKind::AhrsParametersRead),
            Answer::FirmwareVersion => Some(PayloadKind::FirmwareVersion),
            Answer::BitResult => Some(PayloadKind::BitResult),
            Answer::CalibrationStatus => Some(PayloadKind::CalibrationStatus),
            Answer::InitialAlignment => Some(PayloadKind::InitialAlignment),
            Answer::CalibrationResult => Some(PayloadKind::CalibrationResult),
            Answer::CalibrationRunResult => Some(PayloadKind::CalibrationRunResult),
            _ => None,
        }
    }

    /// The USW mode the output block carries, when the answer sets one.
    pub const fn usw_mode(self) -> Option<UswMode> {
        match self {
            Answer::OutputSleep => Some(UswMode::Sleep),
            _ => None,
        }
    }
}

/// Every (state, event) pair the device acts on, sorted by state, then event (declaration
/// order); a pair without a row is ignored.
#[rustfmt::skip]
pub const TRANSITIONS: [Row; 166] = [
    // idle
    row(State::Idle,                          Event::AhrsCont1,        State::AligningContinuous,            &[Answer::Ack]),
    row(State::Idle,                          Event::AhrsCont2,        State::AligningContinuous,            &[Answer::Ack]),
    row(State::Idle,                          Event::AhrsCont3,        State::AligningContinuous,            &[Answer::Ack]),
    row(State::Idle,                          Event::AhrsReq1,         State::AligningOnRequest,             &[Answer::Ack]),
    row(State::Idle,                          Event::AhrsReq2,         State::AligningOnRequest,             &[Answer::Ack]),
    row(State::Idle,                          Event::AhrsReq3,         State::AligningOnRequest,             &[Answer::Ack]),
    row(State::Idle,                          Event::NmeaCont,         State::AligningContinuous,            &[Answer::Ack]),
    row(State::Idle,                          Event::NmeaReq,          State::AligningOnRequest,             &[Answer::Ack]),
    row(State::Idle,                          Event::Stop,             State::Idle,                          &[]), // E14
    row(State::Idle,                          Event::LoadAhrsPar,      State::AwaitingParameters,            &[]), // E13
    row(State::Idle,                          Event::ReadAhrsPar,      State::Idle,                          &[Answer::AhrsParametersRead]),
    row(State::Idle,                          Event::LowPowerOn,       State::Sleep,                         &[]),
    row(State::Idle,                          Event::GetVerFirmware,   State::Idle,                          &[Answer::FirmwareVersion]),
    row(State::Idle,                          Event::GetBit,           State::Idle,                          &[Answer::BitResult]),
    row(State::Idle,                          Event::Start2dClb,       State::CalibrationAwaitingParameters, &[]), // E13
    row(State::Idle,                          Event::Start2d2tClb,     State::RunsAwaitingParameters,        &[]), // E13
    row(State::Idle,                          Event::Start3dClb,       State::CalibrationAwaitingParameters, &[]), // E13
    row(State::Idle,                          Event::ClearClb,         State::Idle,                          &[Answer::Ack]),
    row(State::Idle,                          Event::GetClbRes,        State::Idle,                          &[Answer::CalibrationStatus]),
    // awaiting_parameters
    row(State::AwaitingParameters,            Event::AhrsCont1,        State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::AhrsCont2,        State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::AhrsCont3,        State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::AhrsReq1,         State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::AhrsReq2,         State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::AhrsReq3,         State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::NmeaCont,         State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::NmeaReq,          State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::GetDataReq,       State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::Stop,             State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::LoadAhrsPar,      State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::ReadAhrsPar,      State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::LowPowerOn,       State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::LowPowerOff,      State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::GetVerFirmware,   State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::GetBit,           State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::Start2dClb,       State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::Start2d2tClb,     State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::Start3dClb,       State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::StartClbRun,      State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::StopClbRun,       State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::FinishClb,        State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::AcceptClb,        State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::ExitClb,          State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::ClearClb,         State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::GetClbRes,        State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::ParameterBlock,   State::Idle,                          &[Answer::Ack]),
    row(State::AwaitingParameters,            Event::OtherMessage,     State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::Unknown,          State::Idle,                          &[]), // E34
    row(State::AwaitingParameters,            Event::BlockTimeout,     State::Idle,                          &[]), // E34
    // aligning_continuous
    row(State::AligningContinuous,            Event::Stop,             State::Idle,                          &[]), // E14
    row(State::AligningContinuous,            Event::AlignmentDone,    State::Continuous,                    &[Answer::InitialAlignment]),
    // continuous
    row(State::Continuous,                    Event::Stop,             State::Idle,                          &[]), // E14
    row(State::Continuous,                    Event::LowPowerOn,       State::Sleep,                         &[Answer::OutputSleep]), // E35
    row(State::Continuous,                    Event::OutputDue,        State::Continuous,                    &[Answer::Output]),
    // aligning_on_request
    row(State::AligningOnRequest,             Event::Stop,             State::Idle,                          &[]), // E14
    row(State::AligningOnRequest,             Event::AlignmentDone,    State::OnRequest,                     &[Answer::InitialAlignment]),
    // on_request
    row(State::OnRequest,                     Event::GetDataReq,       State::OnRequest,                     &[Answer::Output]), // E39
    row(State::OnRequest,                     Event::Stop,             State::Idle,                          &[]), // E14
    row(State::OnRequest,                     Event::LowPowerOn,       State::Sleep,                         &[]), // E35
    row(State::OnRequest,                     Event::GetBit,           State::OnRequest,                     &[Answer::BitResult]),
    // sleep
    row(State::Sleep,                         Event::LowPowerOff,      State::Idle,                          &[]),
    // calibration_awaiting_parameters
    row(State::CalibrationAwaitingParameters, Event::AhrsCont1,        State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::AhrsCont2,        State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::AhrsCont3,        State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::AhrsReq1,         State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::AhrsReq2,         State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::AhrsReq3,         State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::NmeaCont,         State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::NmeaReq,          State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::GetDataReq,       State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::Stop,             State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::LoadAhrsPar,      State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::ReadAhrsPar,      State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::LowPowerOn,       State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::LowPowerOff,      State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::GetVerFirmware,   State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::GetBit,           State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::Start2dClb,       State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::Start2d2tClb,     State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::Start3dClb,       State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::StartClbRun,      State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::StopClbRun,       State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::FinishClb,        State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::AcceptClb,        State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::ExitClb,          State::Idle,                          &[Answer::Ack]),
    row(State::CalibrationAwaitingParameters, Event::ClearClb,         State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::GetClbRes,        State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::ParameterBlock,   State::CalibrationAligning,           &[Answer::Ack]),
    row(State::CalibrationAwaitingParameters, Event::OtherMessage,     State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::Unknown,          State::Idle,                          &[]), // E34
    row(State::CalibrationAwaitingParameters, Event::BlockTimeout,     State::Idle,                          &[]), // E34
    // calibration_aligning
    row(State::CalibrationAligning,           Event::ExitClb,          State::Idle,                          &[Answer::Ack]), // E14
    row(State::CalibrationAligning,           Event::AlignmentDone,    State::CalibrationAccumulating,       &[Answer::InitialAlignment]),
    // calibration_accumulating
    row(State::CalibrationAccumulating,       Event::StopClbRun,       State::CalibrationDeciding,           &[Answer::CalibrationResult]), // E38
    row(State::CalibrationAccumulating,       Event::ExitClb,          State::Idle,                          &[Answer::Ack]), // E14
    row(State::CalibrationAccumulating,       Event::AccumulationDone, State::CalibrationDeciding,           &[Answer::CalibrationResult]), // E38
    // calibration_deciding
    row(State::CalibrationDeciding,           Event::AcceptClb,        State::Idle,                          &[Answer::Ack]),
    row(State::CalibrationDeciding,           Event::ExitClb,          State::Idle,                          &[Answer::Ack]), // E14
    // runs_awaiting_parameters
    row(State::RunsAwaitingParameters,        Event::AhrsCont1,        State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::AhrsCont2,        State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::AhrsCont3,        State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::AhrsReq1,         State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::AhrsReq2,         State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::AhrsReq3,         State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::NmeaCont,         State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::NmeaReq,          State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::GetDataReq,       State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::Stop,             State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::LoadAhrsPar,      State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::ReadAhrsPar,      State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::LowPowerOn,       State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::LowPowerOff,      State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::GetVerFirmware,   State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::GetBit,           State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::Start2dClb,       State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::Start2d2tClb,     State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::Start3dClb,       State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::StartClbRun,      State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::StopClbRun,       State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::FinishClb,        State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::AcceptClb,        State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::ExitClb,          State::Idle,                          &[Answer::Ack]),
    row(State::RunsAwaitingParameters,        Event::ClearClb,         State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::GetClbRes,        State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::ParameterBlock,   State::RunsReady,                     &[Answer::Ack]), // E36
    row(State::RunsAwaitingParameters,        Event::OtherMessage,     State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::Unknown,          State::Idle,                          &[]), // E34
    row(State::RunsAwaitingParameters,        Event::BlockTimeout,     State::Idle,                          &[]), // E34
    // runs_ready
    row(State::RunsReady,                     Event::StartClbRun,      State::RunAwaitingParameters,         &[]), // E13
    row(State::RunsReady,                     Event::FinishClb,        State::CalibrationDeciding,           &[Answer::CalibrationResult]), // E37
    row(State::RunsReady,                     Event::ExitClb,          State::Idle,                          &[Answer::Ack]), // E14
    // run_awaiting_parameters
    row(State::RunAwaitingParameters,         Event::AhrsCont1,        State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::AhrsCont2,        State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::AhrsCont3,        State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::AhrsReq1,         State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::AhrsReq2,         State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::AhrsReq3,         State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::NmeaCont,         State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::NmeaReq,          State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::GetDataReq,       State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::Stop,             State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::LoadAhrsPar,      State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::ReadAhrsPar,      State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::LowPowerOn,       State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::LowPowerOff,      State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::GetVerFirmware,   State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::GetBit,           State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::Start2dClb,       State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::Start2d2tClb,     State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::Start3dClb,       State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::StartClbRun,      State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::StopClbRun,       State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::FinishClb,        State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::AcceptClb,        State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::ExitClb,          State::Idle,                          &[Answer::Ack]),
    row(State::RunAwaitingParameters,         Event::ClearClb,         State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::GetClbRes,        State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::ParameterBlock,   State::RunAligning,                   &[Answer::Ack]),
    row(State::RunAwaitingParameters,         Event::OtherMessage,     State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::Unknown,          State::RunsReady,                     &[]), // E34
    row(State::RunAwaitingParameters,         Event::BlockTimeout,     State::RunsReady,                     &[]), // E34
    // run_aligning
    row(State::RunAligning,                   Event::ExitClb,          State::Idle,                          &[Answer::Ack]), // E14
    row(State::RunAligning,                   Event::AlignmentDone,    State::RunAccumulating,               &[Answer::InitialAlignment]),
    // run_accumulating
    row(State::RunAccumulating,               Event::StopClbRun,       State::RunsReady,                     &[Answer::CalibrationRunResult]),
    row(State::RunAccumulating,               Event::ExitClb,          State::Idle,                          &[Answer::Ack]), // E14
    row(State::RunAccumulating,               Event::AccumulationDone, State::RunsReady,                     &[Answer::CalibrationRunResult]),
];

/// Rows that apply only to firmware older than their version (its numeric parts), and there
/// take precedence over [`TRANSITIONS`].
#[rustfmt::skip]
pub const OLDER_FIRMWARE: [(&[u32], Row); 1] = [
    (&[4, 9, 9, 0], row(State::RunsReady, Event::StopClbRun, State::CalibrationDeciding, &[Answer::CalibrationResult])), // E29
];

/// The most numeric parts a [`Firmware`] version holds.
pub const MAX_FIRMWARE_PARTS: usize = 8;
