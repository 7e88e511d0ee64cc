// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Payload tables: one module per table, each with field positions (`field`), field
//! descriptions (`info`), a zero-copy view and a value type (`...Repr`).
//!
//! This module adds what works on any table: [`PayloadKind`] (every table, by name),
//! [`FieldInfo`] (what a field is and what a builder accepts), [`Value`] (a raw field value of
//! any type) and [`AnyPayload`] (a value of any table).
//!
//! ```
//! use ilahrs::payload::{AnyPayload, PayloadKind, Value};
//!
//! let kind = PayloadKind::from_name("full_output").unwrap();
//! let bytes = [0u8; 34];
//! let payload = AnyPayload::parse(kind, &bytes)?;
//! for (info, value) in kind.fields().iter().zip(payload.values()) {
//!     let _ = (info.name, value);
//! }
//! # Ok::<(), ilahrs::Error>(())
//! ```

mod codec;

pub use acknowledgement::{Acknowledgement, AcknowledgementRepr};
pub use ahrs_parameters_load::{AhrsParametersLoad, AhrsParametersLoadRepr};
pub use ahrs_parameters_read::{AhrsParametersRead, AhrsParametersReadRepr};
pub use bit_result::{BitResult, BitResultRepr};
pub use calibration_parameters::{CalibrationParameters, CalibrationParametersRepr};
pub use calibration_result::{CalibrationResult, CalibrationResultRepr};
pub use calibration_run_parameters::{CalibrationRunParameters, CalibrationRunParametersRepr};
pub use calibration_run_result::{CalibrationRunResult, CalibrationRunResultRepr};
pub use calibration_status::{CalibrationStatus, CalibrationStatusRepr};
pub use codec::{check_size, Divisor, FieldInfo, FieldKind, Scale, Value, F32_MAX};
pub use firmware_version::{FirmwareVersion, FirmwareVersionRepr};
pub use full_output::{FullOutput, FullOutputRepr};
pub use initial_alignment::{InitialAlignment, InitialAlignmentRepr};
pub use orientation_sensors::{OrientationSensors, OrientationSensorsRepr};
pub use quaternion::{Quaternion, QuaternionRepr};

use crate::error::Result;
use codec::Table;
pub mod acknowledgement;
pub mod ahrs_parameters_load;
pub mod ahrs_parameters_read;
pub mod bit_result;
pub mod calibration_parameters;
pub mod calibration_result;
pub mod calibration_run_parameters;
pub mod calibration_run_result;
pub mod calibration_status;
pub mod firmware_version;
pub mod full_output;
pub mod initial_alignment;
pub mod orientation_sensors;
pub mod quaternion;

/// The most fields any table has.
pub const MAX_FIELDS: usize = 16;

/// A unit of measure (the spec's `units`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Unit {
    /// degrees
    Deg,
    /// degrees per second
    DegPerS,
    /// standard gravity
    G,
    /// nanotesla
    Nt,
    /// volts DC
    V,
    /// degrees Celsius
    Degc,
    /// dimensionless
    One,
    /// hertz
    Hz,
    /// seconds
    S,
    /// metres
    M,
    /// ADC codes (no physical scale given by the ICD)
    Adc,
    /// percent
    Percent,
    /// fractional year, see encoding `date`
    Year,
}

impl Unit {
    /// The suffix of engineering accessors in this unit (`heading_deg`).
    pub const fn suffix(self) -> &'static str {
        match self {
            Unit::Deg => "deg",
            Unit::DegPerS => "dps",
            Unit::G => "g",
            Unit::Nt => "nt",
            Unit::V => "v",
            Unit::Degc => "degc",
            Unit::One => "value",
            Unit::Hz => "hz",
            Unit::S => "s",
            Unit::M => "m",
            Unit::Adc => "adc",
            Unit::Percent => "percent",
            Unit::Year => "year",
        }
    }

    /// The unit's name in words.
    pub const fn doc(self) -> &'static str {
        match self {
            Unit::Deg => "degrees",
            Unit::DegPerS => "degrees per second",
            Unit::G => "standard gravity",
            Unit::Nt => "nanotesla",
            Unit::V => "volts DC",
            Unit::Degc => "degrees Celsius",
            Unit::One => "dimensionless",
            Unit::Hz => "hertz",
            Unit::S => "seconds",
            Unit::M => "metres",
            Unit::Adc => "ADC codes (no physical scale given by the ICD)",
            Unit::Percent => "percent",
            Unit::Year => "fractional year, see encoding `date`",
        }
    }
}

/// A value encoding the ICD defines for a field.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// The `usw` encoding.
    Usw,
    /// The `declination` encoding.
    Declination,
    /// The `date` encoding.
    Date,
    /// The `calibration_success` encoding.
    CalibrationSuccess,
}

/// Every payload table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PayloadKind {
    /// Table 6.4, Full Output Data (34 bytes).
    FullOutput,
    /// Table 6.5, Quaternion of Orientation (34 bytes).
    Quaternion,
    /// Table 6.6, Orientation + Sensor Outputs (34 bytes).
    OrientationSensors,
    /// Table 6.8, Initial alignment data (50 bytes).
    InitialAlignment,
    /// Table 6.9, Parameters to load (50 bytes).
    AhrsParametersLoad,
    /// Table 6.10, Parameters read (50 bytes).
    AhrsParametersRead,
    /// Table 6.11, Firmware version (50 bytes).
    FirmwareVersion,
    /// Table 6.12, Built-in test answer (4 bytes).
    BitResult,
    /// Table 6.13, Calibration parameters (22 bytes).
    CalibrationParameters,
    /// Table 6.14, Calibration result (52 bytes).
    CalibrationResult,
    /// Table 6.15, 2D-2T calibration run result (30 bytes).
    CalibrationRunResult,
    /// Table 6.16, Calibration run parameters (6 bytes).
    CalibrationRunParameters,
    /// Table 6.17, Calibration results read back (52 bytes).
    CalibrationStatus,
    /// 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement (2 bytes).
    Acknowledgement,
}

impl PayloadKind {
    /// Every table, in the spec's order.
    pub const ALL: [PayloadKind; 14] = [
        PayloadKind::FullOutput,
        PayloadKind::Quaternion,
        PayloadKind::OrientationSensors,
        PayloadKind::InitialAlignment,
        PayloadKind::AhrsParametersLoad,
        PayloadKind::AhrsParametersRead,
        PayloadKind::FirmwareVersion,
        PayloadKind::BitResult,
        PayloadKind::CalibrationParameters,
        PayloadKind::CalibrationResult,
        PayloadKind::CalibrationRunResult,
        PayloadKind::CalibrationRunParameters,
        PayloadKind::CalibrationStatus,
        PayloadKind::Acknowledgement,
    ];

    /// The table's name in the spec.
    pub const fn name(self) -> &'static str {
        match self {
            PayloadKind::FullOutput => "full_output",
            PayloadKind::Quaternion => "quaternion",
            PayloadKind::OrientationSensors => "orientation_sensors",
            PayloadKind::InitialAlignment => "initial_alignment",
            PayloadKind::AhrsParametersLoad => "ahrs_parameters_load",
            PayloadKind::AhrsParametersRead => "ahrs_parameters_read",
            PayloadKind::FirmwareVersion => "firmware_version",
            PayloadKind::BitResult => "bit_result",
            PayloadKind::CalibrationParameters => "calibration_parameters",
            PayloadKind::CalibrationResult => "calibration_result",
            PayloadKind::CalibrationRunResult => "calibration_run_result",
            PayloadKind::CalibrationRunParameters => "calibration_run_parameters",
            PayloadKind::CalibrationStatus => "calibration_status",
            PayloadKind::Acknowledgement => "acknowledgement",
        }
    }

    /// The table whose spec name is `name`, if any.
    pub fn from_name(name: &str) -> Option<PayloadKind> {
        PayloadKind::ALL
            .into_iter()
            .find(|kind| kind.name() == name)
    }

    /// The table's size (bytes).
    pub const fn size(self) -> usize {
        match self {
            PayloadKind::FullOutput => full_output::SIZE,
            PayloadKind::Quaternion => quaternion::SIZE,
            PayloadKind::OrientationSensors => orientation_sensors::SIZE,
            PayloadKind::InitialAlignment => initial_alignment::SIZE,
            PayloadKind::AhrsParametersLoad => ahrs_parameters_load::SIZE,
            PayloadKind::AhrsParametersRead => ahrs_parameters_read::SIZE,
            PayloadKind::FirmwareVersion => firmware_version::SIZE,
            PayloadKind::BitResult => bit_result::SIZE,
            PayloadKind::CalibrationParameters => calibration_parameters::SIZE,
            PayloadKind::CalibrationResult => calibration_result::SIZE,
            PayloadKind::CalibrationRunResult => calibration_run_result::SIZE,
            PayloadKind::CalibrationRunParameters => calibration_run_parameters::SIZE,
            PayloadKind::CalibrationStatus => calibration_status::SIZE,
            PayloadKind::Acknowledgement => acknowledgement::SIZE,
        }
    }

    /// The ICD table and title.
    pub const fn title(self) -> &'static str {
        match self {
            PayloadKind::FullOutput => "Table 6.4, Full Output Data",
            PayloadKind::Quaternion => "Table 6.5, Quaternion of Orientation",
            PayloadKind::OrientationSensors => "Table 6.6, Orientation + Sensor Outputs",
            PayloadKind::InitialAlignment => "Table 6.8, Initial alignment data",
            PayloadKind::AhrsParametersLoad => "Table 6.9, Parameters to load",
            PayloadKind::AhrsParametersRead => "Table 6.10, Parameters read",
            PayloadKind::FirmwareVersion => "Table 6.11, Firmware version",
            PayloadKind::BitResult => "Table 6.12, Built-in test answer",
            PayloadKind::CalibrationParameters => "Table 6.13, Calibration parameters",
            PayloadKind::CalibrationResult => "Table 6.14, Calibration result",
            PayloadKind::CalibrationRunResult => "Table 6.15, 2D-2T calibration run result",
            PayloadKind::CalibrationRunParameters => "Table 6.16, Calibration run parameters",
            PayloadKind::CalibrationStatus => "Table 6.17, Calibration results read back",
            PayloadKind::Acknowledgement => {
                "6.3.1 (Table 6.2 with a one-word payload), Acknowledgement"
            }
        }
    }

    /// The table's fields, in wire order.
    pub fn fields(self) -> &'static [FieldInfo] {
        match self {
            PayloadKind::FullOutput => &full_output::FIELDS,
            PayloadKind::Quaternion => &quaternion::FIELDS,
            PayloadKind::OrientationSensors => &orientation_sensors::FIELDS,
            PayloadKind::InitialAlignment => &initial_alignment::FIELDS,
            PayloadKind::AhrsParametersLoad => &ahrs_parameters_load::FIELDS,
            PayloadKind::AhrsParametersRead => &ahrs_parameters_read::FIELDS,
            PayloadKind::FirmwareVersion => &firmware_version::FIELDS,
            PayloadKind::BitResult => &bit_result::FIELDS,
            PayloadKind::CalibrationParameters => &calibration_parameters::FIELDS,
            PayloadKind::CalibrationResult => &calibration_result::FIELDS,
            PayloadKind::CalibrationRunResult => &calibration_run_result::FIELDS,
            PayloadKind::CalibrationRunParameters => &calibration_run_parameters::FIELDS,
            PayloadKind::CalibrationStatus => &calibration_status::FIELDS,
            PayloadKind::Acknowledgement => &acknowledgement::FIELDS,
        }
    }
}

/// A value of any payload table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AnyPayload {
    /// Table 6.4, Full Output Data.
    FullOutput(FullOutputRepr),
    /// Table 6.5, Quaternion of Orientation.
    Quaternion(QuaternionRepr),
    /// Table 6.6, Orientation + Sensor Outputs.
    OrientationSensors(OrientationSensorsRepr),
    /// Table 6.8, Initial alignment data.
    InitialAlignment(InitialAlignmentRepr),
    /// Table 6.9, Parameters to load.
    AhrsParametersLoad(AhrsParametersLoadRepr),
    /// Table 6.10, Parameters read.
    AhrsParametersRead(AhrsParametersReadRepr),
    /// Table 6.11, Firmware version.
    FirmwareVersion(FirmwareVersionRepr),
    /// Table 6.12, Built-in test answer.
    BitResult(BitResultRepr),
    /// Table 6.13, Calibration parameters.
    CalibrationParameters(CalibrationParametersRepr),
    /// Table 6.14, Calibration result.
    CalibrationResult(CalibrationResultRepr),
    /// Table 6.15, 2D-2T calibration run result.
    CalibrationRunResult(CalibrationRunResultRepr),
    /// Table 6.16, Calibration run parameters.
    CalibrationRunParameters(CalibrationRunParametersRepr),
    /// Table 6.17, Calibration results read back.
    CalibrationStatus(CalibrationStatusRepr),
    /// 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement.
    Acknowledgement(AcknowledgementRepr),
}

impl AnyPayload {
    /// The value of table `kind` whose fields all take their defaults.
    pub fn new(kind: PayloadKind) -> AnyPayload {
        match kind {
            PayloadKind::FullOutput => AnyPayload::FullOutput(Default::default()),
            PayloadKind::Quaternion => AnyPayload::Quaternion(Default::default()),
            PayloadKind::OrientationSensors => AnyPayload::OrientationSensors(Default::default()),
            PayloadKind::InitialAlignment => AnyPayload::InitialAlignment(Default::default()),
            PayloadKind::AhrsParametersLoad => AnyPayload::AhrsParametersLoad(Default::default()),
            PayloadKind::AhrsParametersRead => AnyPayload::AhrsParametersRead(Default::default()),
            PayloadKind::FirmwareVersion => AnyPayload::FirmwareVersion(Default::default()),
            PayloadKind::BitResult => AnyPayload::BitResult(Default::default()),
            PayloadKind::CalibrationParameters => {
                AnyPayload::CalibrationParameters(Default::default())
            }
            PayloadKind::CalibrationResult => AnyPayload::CalibrationResult(Default::default()),
            PayloadKind::CalibrationRunResult => {
                AnyPayload::CalibrationRunResult(Default::default())
            }
            PayloadKind::CalibrationRunParameters => {
                AnyPayload::CalibrationRunParameters(Default::default())
            }
            PayloadKind::CalibrationStatus => AnyPayload::CalibrationStatus(Default::default()),
            PayloadKind::Acknowledgement => AnyPayload::Acknowledgement(Default::default()),
        }
    }

    /// Decodes `data` as table `kind` (see the table's `Repr::parse`).
    pub fn parse(kind: PayloadKind, data: &[u8]) -> Result<AnyPayload> {
        match kind {
            PayloadKind::FullOutput => FullOutputRepr::parse(data).map(AnyPayload::FullOutput),
            PayloadKind::Quaternion => QuaternionRepr::parse(data).map(AnyPayload::Quaternion),
            PayloadKind::OrientationSensors => {
                OrientationSensorsRepr::parse(data).map(AnyPayload::OrientationSensors)
            }
            PayloadKind::InitialAlignment => {
                InitialAlignmentRepr::parse(data).map(AnyPayload::InitialAlignment)
            }
            PayloadKind::AhrsParametersLoad => {
                AhrsParametersLoadRepr::parse(data).map(AnyPayload::AhrsParametersLoad)
            }
            PayloadKind::AhrsParametersRead => {
                AhrsParametersReadRepr::parse(data).map(AnyPayload::AhrsParametersRead)
            }
            PayloadKind::FirmwareVersion => {
                FirmwareVersionRepr::parse(data).map(AnyPayload::FirmwareVersion)
            }
            PayloadKind::BitResult => BitResultRepr::parse(data).map(AnyPayload::BitResult),
            PayloadKind::CalibrationParameters => {
                CalibrationParametersRepr::parse(data).map(AnyPayload::CalibrationParameters)
            }
            PayloadKind::CalibrationResult => {
                CalibrationResultRepr::parse(data).map(AnyPayload::CalibrationResult)
            }
            PayloadKind::CalibrationRunResult => {
                CalibrationRunResultRepr::parse(data).map(AnyPayload::CalibrationRunResult)
            }
            PayloadKind::CalibrationRunParameters => {
                CalibrationRunParametersRepr::parse(data).map(AnyPayload::CalibrationRunParameters)
            }
            PayloadKind::CalibrationStatus => {
                CalibrationStatusRepr::parse(data).map(AnyPayload::CalibrationStatus)
            }
            PayloadKind::Acknowledgement => {
                AcknowledgementRepr::parse(data).map(AnyPayload::Acknowledgement)
            }
        }
    }

    /// The value's table.
    pub const fn kind(&self) -> PayloadKind {
        match self {
            AnyPayload::FullOutput(_) => PayloadKind::FullOutput,
            AnyPayload::Quaternion(_) => PayloadKind::Quaternion,
            AnyPayload::OrientationSensors(_) => PayloadKind::OrientationSensors,
            AnyPayload::InitialAlignment(_) => PayloadKind::InitialAlignment,
            AnyPayload::AhrsParametersLoad(_) => PayloadKind::AhrsParametersLoad,
            AnyPayload::AhrsParametersRead(_) => PayloadKind::AhrsParametersRead,
            AnyPayload::FirmwareVersion(_) => PayloadKind::FirmwareVersion,
            AnyPayload::BitResult(_) => PayloadKind::BitResult,
            AnyPayload::CalibrationParameters(_) => PayloadKind::CalibrationParameters,
            AnyPayload::CalibrationResult(_) => PayloadKind::CalibrationResult,
            AnyPayload::CalibrationRunResult(_) => PayloadKind::CalibrationRunResult,
            AnyPayload::CalibrationRunParameters(_) => PayloadKind::CalibrationRunParameters,
            AnyPayload::CalibrationStatus(_) => PayloadKind::CalibrationStatus,
            AnyPayload::Acknowledgement(_) => PayloadKind::Acknowledgement,
        }
    }

    /// The value as its table's type.
    fn table(&self) -> &dyn Table {
        match self {
            AnyPayload::FullOutput(repr) => repr,
            AnyPayload::Quaternion(repr) => repr,
            AnyPayload::OrientationSensors(repr) => repr,
            AnyPayload::InitialAlignment(repr) => repr,
            AnyPayload::AhrsParametersLoad(repr) => repr,
            AnyPayload::AhrsParametersRead(repr) => repr,
            AnyPayload::FirmwareVersion(repr) => repr,
            AnyPayload::BitResult(repr) => repr,
            AnyPayload::CalibrationParameters(repr) => repr,
            AnyPayload::CalibrationResult(repr) => repr,
            AnyPayload::CalibrationRunResult(repr) => repr,
            AnyPayload::CalibrationRunParameters(repr) => repr,
            AnyPayload::CalibrationStatus(repr) => repr,
            AnyPayload::Acknowledgement(repr) => repr,
        }
    }

    /// The value as its table's type, for writing.
    fn table_mut(&mut self) -> &mut dyn Table {
        match self {
            AnyPayload::FullOutput(repr) => repr,
            AnyPayload::Quaternion(repr) => repr,
            AnyPayload::OrientationSensors(repr) => repr,
            AnyPayload::InitialAlignment(repr) => repr,
            AnyPayload::AhrsParametersLoad(repr) => repr,
            AnyPayload::AhrsParametersRead(repr) => repr,
            AnyPayload::FirmwareVersion(repr) => repr,
            AnyPayload::BitResult(repr) => repr,
            AnyPayload::CalibrationParameters(repr) => repr,
            AnyPayload::CalibrationResult(repr) => repr,
            AnyPayload::CalibrationRunResult(repr) => repr,
            AnyPayload::CalibrationRunParameters(repr) => repr,
            AnyPayload::CalibrationStatus(repr) => repr,
            AnyPayload::Acknowledgement(repr) => repr,
        }
    }
}
