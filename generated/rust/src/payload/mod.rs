// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
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

use crate::error::{Error, ErrorKind, Result};
use crate::variant::{Variant, VariantParameter};
use crate::wire::{self, Field};

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

pub use acknowledgement::{Acknowledgement, AcknowledgementRepr};
pub use ahrs_parameters_load::{AhrsParametersLoad, AhrsParametersLoadRepr};
pub use ahrs_parameters_read::{AhrsParametersRead, AhrsParametersReadRepr};
pub use bit_result::{BitResult, BitResultRepr};
pub use calibration_parameters::{CalibrationParameters, CalibrationParametersRepr};
pub use calibration_result::{CalibrationResult, CalibrationResultRepr};
pub use calibration_run_parameters::{CalibrationRunParameters, CalibrationRunParametersRepr};
pub use calibration_run_result::{CalibrationRunResult, CalibrationRunResultRepr};
pub use calibration_status::{CalibrationStatus, CalibrationStatusRepr};
pub use firmware_version::{FirmwareVersion, FirmwareVersionRepr};
pub use full_output::{FullOutput, FullOutputRepr};
pub use initial_alignment::{InitialAlignment, InitialAlignmentRepr};
pub use orientation_sensors::{OrientationSensors, OrientationSensorsRepr};
pub use quaternion::{Quaternion, QuaternionRepr};

/// The greatest finite float32, as a double.
pub const F32_MAX: f64 = f32::MAX as f64;

/// The most fields any table has.
pub const MAX_FIELDS: usize = 16;

/// How a field's bytes are read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FieldKind {
    /// An unsigned integer, little-endian.
    Unsigned,
    /// A two's complement signed integer, little-endian.
    Signed,
    /// An IEEE 754 float32, little-endian.
    Float,
    /// Text: Latin-1 bytes padded with NULs.
    Char,
    /// Bytes with no meaning, kept verbatim.
    Reserved,
}

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

/// The divisor of a scale: a number, or a parameter of the device variant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Divisor {
    /// A fixed divisor.
    Fixed(i32),
    /// A divisor that depends on the device variant.
    Parameter(VariantParameter),
}

/// Engineering value = raw x `multiplier` / `divisor`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Scale {
    /// The multiplier.
    pub multiplier: i32,
    /// The divisor.
    pub divisor: Divisor,
}

impl Scale {
    /// The divisor for `variant`, or `None` when it depends on the variant and none is given.
    pub const fn divisor(&self, variant: Option<Variant>) -> Option<i32> {
        match (self.divisor, variant) {
            (Divisor::Fixed(divisor), _) => Some(divisor),
            (Divisor::Parameter(parameter), Some(variant)) => Some(variant.parameter(parameter)),
            (Divisor::Parameter(_), None) => None,
        }
    }

    /// The engineering value of `raw` (in the field's unit), or `None` when the divisor needs a
    /// variant and none is given.
    pub fn engineering(&self, raw: f64, variant: Option<Variant>) -> Option<f64> {
        let divisor = self.divisor(variant)?;
        Some(raw * f64::from(self.multiplier) / f64::from(divisor))
    }

    /// The raw value for the engineering value `value`, before rounding, or `None` when the
    /// divisor needs a variant and none is given.
    pub fn raw(&self, value: f64, variant: Option<Variant>) -> Option<f64> {
        let divisor = self.divisor(variant)?;
        Some(value * f64::from(divisor) / f64::from(self.multiplier))
    }
}

/// A raw field value of any type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value<'a> {
    /// An integer field's value.
    Int(i64),
    /// A float field's value (builders take any double and refuse what float32 cannot hold).
    Float(f64),
    /// A char field's bytes (Latin-1, trailing NULs removed) or a reserved field's bytes.
    Bytes(&'a [u8]),
}

/// What a field is: name, position, type, what a builder accepts and how to scale it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldInfo {
    /// The spec's name of the field.
    pub name: &'static str,
    /// The ICD's name of the field.
    pub icd_name: &'static str,
    /// Where the field starts in its payload (bytes).
    pub offset: usize,
    /// The field's size (bytes).
    pub size: usize,
    /// How the field's bytes are read.
    pub kind: FieldKind,
    /// The least raw value a builder accepts (numeric fields).
    pub min: f64,
    /// The greatest raw value a builder accepts (numeric fields).
    pub max: f64,
    /// The value a builder uses when none is given.
    pub default: Value<'static>,
    /// How to turn the raw value into an engineering value, if the field has a scale.
    pub scale: Option<Scale>,
    /// The unit of the engineering value (or of the raw value when there is no scale).
    pub unit: Option<Unit>,
    /// A value encoding the field follows, if any.
    pub encoding: Option<Encoding>,
    /// What the field means.
    pub doc: &'static str,
}

impl FieldInfo {
    /// The field's position in its payload (byte offsets).
    pub const fn position(&self) -> Field {
        self.offset..self.offset + self.size
    }

    /// The error a builder gives for a bad value of this field.
    pub const fn refuse(&self) -> Error {
        Error::at(ErrorKind::OutOfRange, self.offset).with_field(self.name)
    }

    /// The field's raw value in `payload` (a whole payload of the field's table).
    pub fn read<'a>(&self, payload: &'a [u8]) -> Value<'a> {
        let at = self.position();
        match (self.kind, self.size) {
            (FieldKind::Unsigned, 1) => Value::Int(i64::from(wire::get_u8(payload, at))),
            (FieldKind::Unsigned, 2) => Value::Int(i64::from(wire::get_u16(payload, at))),
            (FieldKind::Signed, 2) => Value::Int(i64::from(wire::get_i16(payload, at))),
            (FieldKind::Unsigned, 4) => Value::Int(i64::from(wire::get_u32(payload, at))),
            (FieldKind::Float, 4) => Value::Float(f64::from(wire::get_f32(payload, at))),
            (FieldKind::Char, _) => Value::Bytes(wire::trim_nul(wire::bytes(payload, at))),
            _ => Value::Bytes(wire::bytes(payload, at)),
        }
    }

    /// Checks `value` the way a builder does: an integer inside the field's range, a finite
    /// float inside its range (and float32), text no longer than the field, reserved bytes of
    /// exactly its size, plus the rules of the field's encoding. Error: `out_of_range` at the
    /// field's offset, naming the field.
    pub fn check(&self, value: Value<'_>) -> Result<()> {
        let ok = match (self.kind, value) {
            (FieldKind::Unsigned | FieldKind::Signed, Value::Int(raw)) => {
                (self.min..=self.max).contains(&(raw as f64))
            }
            (FieldKind::Float, Value::Float(raw)) => {
                let inside = (self.min..=self.max).contains(&raw);
                raw.is_finite() && inside && self.encoding_accepts(raw)
            }
            (FieldKind::Float, Value::Int(raw)) => return self.check(Value::Float(raw as f64)),
            (FieldKind::Char, Value::Bytes(text)) => text.len() <= self.size,
            (FieldKind::Reserved, Value::Bytes(bytes)) => bytes.len() == self.size,
            _ => false,
        };
        if ok {
            Ok(())
        } else {
            Err(self.refuse())
        }
    }

    /// True unless the field's encoding refuses the float `raw`.
    fn encoding_accepts(&self, raw: f64) -> bool {
        match self.encoding {
            Some(Encoding::Declination) => crate::encoding::Declination::accepts(raw),
            _ => {
                let _ = raw;
                true
            }
        }
    }

    /// Checks `value` (see [`FieldInfo::check`]) and writes it into `payload`.
    pub fn write(&self, payload: &mut [u8], value: Value<'_>) -> Result<()> {
        self.check(value)?;
        let at = self.position();
        match (self.kind, value) {
            (FieldKind::Unsigned, Value::Int(raw)) if self.size == 1 => {
                wire::set_u8(payload, at, self.int::<u8>(Value::Int(raw))?)
            }
            (FieldKind::Unsigned, Value::Int(raw)) if self.size == 2 => {
                wire::set_u16(payload, at, self.int::<u16>(Value::Int(raw))?)
            }
            (FieldKind::Signed, Value::Int(raw)) if self.size == 2 => {
                wire::set_i16(payload, at, self.int::<i16>(Value::Int(raw))?)
            }
            (FieldKind::Unsigned, Value::Int(raw)) if self.size == 4 => {
                wire::set_u32(payload, at, self.int::<u32>(Value::Int(raw))?)
            }
            (FieldKind::Float, Value::Float(raw)) => wire::set_f32(payload, at, raw as f32),
            (FieldKind::Float, Value::Int(raw)) => wire::set_f32(payload, at, raw as f32),
            (FieldKind::Char, Value::Bytes(text)) => wire::set_padded(payload, at, text),
            (FieldKind::Reserved, Value::Bytes(bytes)) => wire::put(payload, at, bytes),
            _ => return Err(self.refuse()),
        }
        Ok(())
    }

    /// `value` checked and converted to the field's integer type.
    pub fn int<T: TryFrom<i64>>(&self, value: Value<'_>) -> Result<T> {
        self.check(value)?;
        match value {
            Value::Int(raw) => T::try_from(raw).map_err(|_| self.refuse()),
            _ => Err(self.refuse()),
        }
    }

    /// `value` checked and converted to float32.
    pub fn float(&self, value: Value<'_>) -> Result<f32> {
        self.check(value)?;
        match value {
            Value::Float(raw) => Ok(raw as f32),
            Value::Int(raw) => Ok(raw as f32),
            Value::Bytes(_) => Err(self.refuse()),
        }
    }

    /// `value` checked and copied into the field's bytes (text padded with NULs).
    pub fn array<const N: usize>(&self, value: Value<'_>) -> Result<[u8; N]> {
        self.check(value)?;
        match value {
            Value::Bytes(bytes) if bytes.len() <= N => {
                let mut out = [0; N];
                wire::put(&mut out, 0..bytes.len(), bytes);
                Ok(out)
            }
            _ => Err(self.refuse()),
        }
    }

    /// The raw value for the engineering value `value`: scaled, rounded half away from zero for
    /// integer fields, and checked. Errors: `out_of_range` for a value the field cannot hold
    /// (or a variant-dependent scale without a variant).
    pub fn raw_from(&self, value: f64, variant: Option<Variant>) -> Result<Value<'static>> {
        let raw = match self.scale {
            Some(scale) => scale.raw(value, variant).ok_or(self.refuse())?,
            None => value,
        };
        let raw = match self.kind {
            FieldKind::Unsigned | FieldKind::Signed => {
                Value::Int(wire::round_half_away(raw).ok_or(self.refuse())?)
            }
            _ => Value::Float(raw),
        };
        self.check(raw)?;
        Ok(raw)
    }

    /// The engineering value of `value` (in the field's unit), or `None` for a field without a
    /// scale, a non-numeric value, or a variant-dependent scale without a variant.
    pub fn engineering(&self, value: Value<'_>, variant: Option<Variant>) -> Option<f64> {
        let raw = match value {
            Value::Int(raw) => raw as f64,
            Value::Float(raw) => raw,
            Value::Bytes(_) => return None,
        };
        self.scale?.engineering(raw, variant)
    }
}

/// Checks that a payload of `len` bytes has exactly `size` bytes: `truncated` at `len` when
/// shorter, `trailing_data` at `size` when longer.
pub const fn check_size(len: usize, size: usize) -> Result<()> {
    if len < size {
        Err(Error::at(ErrorKind::Truncated, len))
    } else if len > size {
        Err(Error::at(ErrorKind::TrailingData, size))
    } else {
        Ok(())
    }
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
        match name {
            "full_output" => Some(PayloadKind::FullOutput),
            "quaternion" => Some(PayloadKind::Quaternion),
            "orientation_sensors" => Some(PayloadKind::OrientationSensors),
            "initial_alignment" => Some(PayloadKind::InitialAlignment),
            "ahrs_parameters_load" => Some(PayloadKind::AhrsParametersLoad),
            "ahrs_parameters_read" => Some(PayloadKind::AhrsParametersRead),
            "firmware_version" => Some(PayloadKind::FirmwareVersion),
            "bit_result" => Some(PayloadKind::BitResult),
            "calibration_parameters" => Some(PayloadKind::CalibrationParameters),
            "calibration_result" => Some(PayloadKind::CalibrationResult),
            "calibration_run_result" => Some(PayloadKind::CalibrationRunResult),
            "calibration_run_parameters" => Some(PayloadKind::CalibrationRunParameters),
            "calibration_status" => Some(PayloadKind::CalibrationStatus),
            "acknowledgement" => Some(PayloadKind::Acknowledgement),
            _ => None,
        }
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

    /// The index of the field named `name`, if the table has one.
    pub fn field_index(self, name: &str) -> Option<usize> {
        self.fields().iter().position(|info| info.name == name)
    }

    /// True if an engineering value of some field needs the device variant.
    pub fn variant_dependent(self) -> bool {
        self.fields().iter().any(|info| match info.scale {
            Some(scale) => matches_parameter(scale.divisor),
            None => false,
        })
    }
}

/// True for a divisor that depends on the variant.
const fn matches_parameter(divisor: Divisor) -> bool {
    match divisor {
        Divisor::Parameter(_) => true,
        Divisor::Fixed(_) => false,
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
        Ok(match kind {
            PayloadKind::FullOutput => AnyPayload::FullOutput(FullOutputRepr::parse(data)?),
            PayloadKind::Quaternion => AnyPayload::Quaternion(QuaternionRepr::parse(data)?),
            PayloadKind::OrientationSensors => {
                AnyPayload::OrientationSensors(OrientationSensorsRepr::parse(data)?)
            }
            PayloadKind::InitialAlignment => {
                AnyPayload::InitialAlignment(InitialAlignmentRepr::parse(data)?)
            }
            PayloadKind::AhrsParametersLoad => {
                AnyPayload::AhrsParametersLoad(AhrsParametersLoadRepr::parse(data)?)
            }
            PayloadKind::AhrsParametersRead => {
                AnyPayload::AhrsParametersRead(AhrsParametersReadRepr::parse(data)?)
            }
            PayloadKind::FirmwareVersion => {
                AnyPayload::FirmwareVersion(FirmwareVersionRepr::parse(data)?)
            }
            PayloadKind::BitResult => AnyPayload::BitResult(BitResultRepr::parse(data)?),
            PayloadKind::CalibrationParameters => {
                AnyPayload::CalibrationParameters(CalibrationParametersRepr::parse(data)?)
            }
            PayloadKind::CalibrationResult => {
                AnyPayload::CalibrationResult(CalibrationResultRepr::parse(data)?)
            }
            PayloadKind::CalibrationRunResult => {
                AnyPayload::CalibrationRunResult(CalibrationRunResultRepr::parse(data)?)
            }
            PayloadKind::CalibrationRunParameters => {
                AnyPayload::CalibrationRunParameters(CalibrationRunParametersRepr::parse(data)?)
            }
            PayloadKind::CalibrationStatus => {
                AnyPayload::CalibrationStatus(CalibrationStatusRepr::parse(data)?)
            }
            PayloadKind::Acknowledgement => {
                AnyPayload::Acknowledgement(AcknowledgementRepr::parse(data)?)
            }
        })
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

    /// The size of the payload [`AnyPayload::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        self.kind().size()
    }

    /// Checks every field in table order (see the table's `Repr::validate`).
    pub fn validate(&self) -> Result<()> {
        match self {
            AnyPayload::FullOutput(repr) => repr.validate(),
            AnyPayload::Quaternion(repr) => repr.validate(),
            AnyPayload::OrientationSensors(repr) => repr.validate(),
            AnyPayload::InitialAlignment(repr) => repr.validate(),
            AnyPayload::AhrsParametersLoad(repr) => repr.validate(),
            AnyPayload::AhrsParametersRead(repr) => repr.validate(),
            AnyPayload::FirmwareVersion(repr) => repr.validate(),
            AnyPayload::BitResult(repr) => repr.validate(),
            AnyPayload::CalibrationParameters(repr) => repr.validate(),
            AnyPayload::CalibrationResult(repr) => repr.validate(),
            AnyPayload::CalibrationRunResult(repr) => repr.validate(),
            AnyPayload::CalibrationRunParameters(repr) => repr.validate(),
            AnyPayload::CalibrationStatus(repr) => repr.validate(),
            AnyPayload::Acknowledgement(repr) => repr.validate(),
        }
    }

    /// Writes the payload into `buf` (see the table's `Repr::build`); returns its size (bytes).
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        match self {
            AnyPayload::FullOutput(repr) => repr.build(buf),
            AnyPayload::Quaternion(repr) => repr.build(buf),
            AnyPayload::OrientationSensors(repr) => repr.build(buf),
            AnyPayload::InitialAlignment(repr) => repr.build(buf),
            AnyPayload::AhrsParametersLoad(repr) => repr.build(buf),
            AnyPayload::AhrsParametersRead(repr) => repr.build(buf),
            AnyPayload::FirmwareVersion(repr) => repr.build(buf),
            AnyPayload::BitResult(repr) => repr.build(buf),
            AnyPayload::CalibrationParameters(repr) => repr.build(buf),
            AnyPayload::CalibrationResult(repr) => repr.build(buf),
            AnyPayload::CalibrationRunResult(repr) => repr.build(buf),
            AnyPayload::CalibrationRunParameters(repr) => repr.build(buf),
            AnyPayload::CalibrationStatus(repr) => repr.build(buf),
            AnyPayload::Acknowledgement(repr) => repr.build(buf),
        }
    }

    /// Writes a data frame carrying the payload into `buf`; returns its size (bytes).
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        match self {
            AnyPayload::FullOutput(repr) => repr.build_frame(buf),
            AnyPayload::Quaternion(repr) => repr.build_frame(buf),
            AnyPayload::OrientationSensors(repr) => repr.build_frame(buf),
            AnyPayload::InitialAlignment(repr) => repr.build_frame(buf),
            AnyPayload::AhrsParametersLoad(repr) => repr.build_frame(buf),
            AnyPayload::AhrsParametersRead(repr) => repr.build_frame(buf),
            AnyPayload::FirmwareVersion(repr) => repr.build_frame(buf),
            AnyPayload::BitResult(repr) => repr.build_frame(buf),
            AnyPayload::CalibrationParameters(repr) => repr.build_frame(buf),
            AnyPayload::CalibrationResult(repr) => repr.build_frame(buf),
            AnyPayload::CalibrationRunResult(repr) => repr.build_frame(buf),
            AnyPayload::CalibrationRunParameters(repr) => repr.build_frame(buf),
            AnyPayload::CalibrationStatus(repr) => repr.build_frame(buf),
            AnyPayload::Acknowledgement(repr) => repr.build_frame(buf),
        }
    }

    /// The raw value of field `index` (table order), or `None` past the last field.
    pub fn value(&self, index: usize) -> Option<Value<'_>> {
        match self {
            AnyPayload::FullOutput(repr) => repr.value(index),
            AnyPayload::Quaternion(repr) => repr.value(index),
            AnyPayload::OrientationSensors(repr) => repr.value(index),
            AnyPayload::InitialAlignment(repr) => repr.value(index),
            AnyPayload::AhrsParametersLoad(repr) => repr.value(index),
            AnyPayload::AhrsParametersRead(repr) => repr.value(index),
            AnyPayload::FirmwareVersion(repr) => repr.value(index),
            AnyPayload::BitResult(repr) => repr.value(index),
            AnyPayload::CalibrationParameters(repr) => repr.value(index),
            AnyPayload::CalibrationResult(repr) => repr.value(index),
            AnyPayload::CalibrationRunResult(repr) => repr.value(index),
            AnyPayload::CalibrationRunParameters(repr) => repr.value(index),
            AnyPayload::CalibrationStatus(repr) => repr.value(index),
            AnyPayload::Acknowledgement(repr) => repr.value(index),
        }
    }

    /// Every raw value, in table order (`Value::Int(0)` past the table's last field).
    pub fn values(&self) -> [Value<'_>; MAX_FIELDS] {
        let mut out = [Value::Int(0); MAX_FIELDS];
        for (index, slot) in out.iter_mut().enumerate() {
            if let Some(value) = self.value(index) {
                *slot = value;
            }
        }
        out
    }

    /// Sets field `index` (table order) after checking `value` (see [`FieldInfo::check`]).
    /// Errors: `out_of_range` naming the field, or with no field for an index past the last.
    pub fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        match self {
            AnyPayload::FullOutput(repr) => repr.set_value(index, value),
            AnyPayload::Quaternion(repr) => repr.set_value(index, value),
            AnyPayload::OrientationSensors(repr) => repr.set_value(index, value),
            AnyPayload::InitialAlignment(repr) => repr.set_value(index, value),
            AnyPayload::AhrsParametersLoad(repr) => repr.set_value(index, value),
            AnyPayload::AhrsParametersRead(repr) => repr.set_value(index, value),
            AnyPayload::FirmwareVersion(repr) => repr.set_value(index, value),
            AnyPayload::BitResult(repr) => repr.set_value(index, value),
            AnyPayload::CalibrationParameters(repr) => repr.set_value(index, value),
            AnyPayload::CalibrationResult(repr) => repr.set_value(index, value),
            AnyPayload::CalibrationRunResult(repr) => repr.set_value(index, value),
            AnyPayload::CalibrationRunParameters(repr) => repr.set_value(index, value),
            AnyPayload::CalibrationStatus(repr) => repr.set_value(index, value),
            AnyPayload::Acknowledgement(repr) => repr.set_value(index, value),
        }
    }

    /// The engineering value of field `index` (see [`FieldInfo::engineering`]).
    pub fn engineering(&self, index: usize, variant: Option<Variant>) -> Option<f64> {
        let info = self.kind().fields().get(index)?;
        info.engineering(self.value(index)?, variant)
    }
}
