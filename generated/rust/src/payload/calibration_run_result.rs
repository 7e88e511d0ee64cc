// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.15, 2D-2T calibration run result (30 bytes).
//!
//! Sent after each run of a 2D-2T calibration (6.4.5).

use crate::encoding::CalibrationSuccess;
use crate::encoding::CalibrationType;
use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Unit, Value};
use crate::status::StatusWord;
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 30;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Type of calibration, `u8`.
    pub const CALIBRATION_TYPE: Field = 0..1;
    /// Calibration run, `u8`.
    pub const RUN: Field = 1..2;
    /// Percent of used data points, `u8`, percent.
    pub const DATA_USED: Field = 2..3;
    /// Calibration success, `u8`.
    pub const SUCCESS: Field = 3..4;
    /// Reserved, `reserved[4]`.
    pub const RESERVED_1: Field = 4..8;
    /// Average pitch, deg, `f32`, degrees.
    pub const AVERAGE_PITCH: Field = 8..12;
    /// Average roll, deg, `f32`, degrees.
    pub const AVERAGE_ROLL: Field = 12..16;
    /// Reserved, `reserved[12]`.
    pub const RESERVED_2: Field = 16..28;
    /// USW, `u16`.
    pub const USW: Field = 28..30;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Type of calibration, `u8`.
    pub const CALIBRATION_TYPE: FieldInfo = FieldInfo {
        icd_name: "Type of calibration",
        min: 2.0,
        max: 2.0,
        default: Value::Int(2),
        doc: "2 for 2D-2T calibration.",
        ..FieldInfo::new(
            "calibration_type",
            field::CALIBRATION_TYPE,
            FieldKind::Unsigned,
        )
    };

    /// Calibration run, `u8`.
    pub const RUN: FieldInfo = FieldInfo {
        icd_name: "Calibration run",
        min: 1.0,
        max: 255.0,
        default: Value::Int(1),
        doc: "Number of this run (1, 2, ...).",
        ..FieldInfo::new("run", field::RUN, FieldKind::Unsigned)
    };

    /// Percent of used data points, `u8`, percent.
    pub const DATA_USED: FieldInfo = FieldInfo {
        icd_name: "Percent of used data points",
        min: 0.0,
        max: 100.0,
        unit: Some(Unit::Percent),
        doc: "Percent of data points used.",
        ..FieldInfo::new("data_used", field::DATA_USED, FieldKind::Unsigned)
    };

    /// Calibration success, `u8`.
    pub const SUCCESS: FieldInfo = FieldInfo {
        icd_name: "Calibration success",
        encoding: Some(Encoding::CalibrationSuccess),
        doc: "0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255: successful without an estimate.",
        ..FieldInfo::new("success", field::SUCCESS, FieldKind::Unsigned)
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED_1: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 4]),
        ..FieldInfo::new("reserved_1", field::RESERVED_1, FieldKind::Reserved)
    };

    /// Average pitch, deg, `f32`, degrees.
    pub const AVERAGE_PITCH: FieldInfo = FieldInfo {
        icd_name: "Average pitch, deg",
        min: -90.0,
        max: 90.0,
        unit: Some(Unit::Deg),
        doc: "Average pitch during the run.",
        ..FieldInfo::new("average_pitch", field::AVERAGE_PITCH, FieldKind::Float)
    };

    /// Average roll, deg, `f32`, degrees.
    pub const AVERAGE_ROLL: FieldInfo = FieldInfo {
        icd_name: "Average roll, deg",
        min: -180.0,
        max: 180.0,
        unit: Some(Unit::Deg),
        doc: "Average roll during the run.",
        ..FieldInfo::new("average_roll", field::AVERAGE_ROLL, FieldKind::Float)
    };

    /// Reserved, `reserved[12]`.
    pub const RESERVED_2: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 12]),
        ..FieldInfo::new("reserved_2", field::RESERVED_2, FieldKind::Reserved)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = crate::payload::full_output::info::USW;
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 9] = [
    info::CALIBRATION_TYPE,
    info::RUN,
    info::DATA_USED,
    info::SUCCESS,
    info::RESERVED_1,
    info::AVERAGE_PITCH,
    info::AVERAGE_ROLL,
    info::RESERVED_2,
    info::USW,
];

/// Table 6.15, 2D-2T calibration run result: a zero-copy view over a payload.
///
/// [`CalibrationRunResult::new_checked`] checks the size once; the accessors never panic,
/// even on a view made by [`CalibrationRunResult::new_unchecked`] over a short buffer
/// (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationRunResult<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationRunResult<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationRunResult<T> {
        CalibrationRunResult { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<CalibrationRunResult<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(CalibrationRunResult { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Type of calibration, `u8`: 2 for 2D-2T calibration.
    pub fn calibration_type(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::CALIBRATION_TYPE)
    }

    /// Calibration run, `u8`: Number of this run (1, 2, ...).
    pub fn run(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::RUN)
    }

    /// Percent of used data points, `u8`, percent: Percent of data points used.
    pub fn data_used(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::DATA_USED)
    }

    /// Calibration success, `u8`: 0: run not successful (excluded); 1..254: predicted
    /// heading error in deg*10; 255: successful without an estimate.
    pub fn success(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::SUCCESS)
    }

    /// Reserved, `reserved[4]`.
    pub fn reserved_1(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED_1)
    }

    /// Average pitch, deg, `f32`, degrees: Average pitch during the run.
    pub fn average_pitch(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_PITCH)
    }

    /// Average roll, deg, `f32`, degrees: Average roll during the run.
    pub fn average_roll(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_ROLL)
    }

    /// Reserved, `reserved[12]`.
    pub fn reserved_2(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED_2)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::USW)
    }

    /// Type of calibration as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationType> {
        CalibrationType::from_raw(self.calibration_type())
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationRunResult<T> {
    /// Sets [`Self::calibration_type`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_calibration_type(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::CALIBRATION_TYPE, value);
    }

    /// Sets [`Self::run`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_run(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::RUN, value);
    }

    /// Sets [`Self::data_used`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_data_used(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::DATA_USED, value);
    }

    /// Sets [`Self::success`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_success(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::SUCCESS, value);
    }

    /// Sets [`Self::reserved_1`] (bytes kept verbatim).
    pub fn set_reserved_1(&mut self, value: &[u8; 4]) {
        wire::put(self.buffer.as_mut(), field::RESERVED_1, value);
    }

    /// Sets [`Self::average_pitch`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_average_pitch(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_PITCH, value);
    }

    /// Sets [`Self::average_roll`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_average_roll(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_ROLL, value);
    }

    /// Sets [`Self::reserved_2`] (bytes kept verbatim).
    pub fn set_reserved_2(&mut self, value: &[u8; 12]) {
        wire::put(self.buffer.as_mut(), field::RESERVED_2, value);
    }

    /// Sets [`Self::usw`] (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::USW, value);
    }
}

/// Table 6.15, 2D-2T calibration run result: the payload as a value, with raw field values.
///
/// [`CalibrationRunResultRepr::parse`] and [`CalibrationRunResultRepr::build`] are exact
/// inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same bytes
/// when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationRunResultRepr {
    /// Type of calibration, `u8`: 2 for 2D-2T calibration.
    pub calibration_type: u8,
    /// Calibration run, `u8`: Number of this run (1, 2, ...).
    pub run: u8,
    /// Percent of used data points, `u8`, percent: Percent of data points used.
    pub data_used: u8,
    /// Calibration success, `u8`: 0: run not successful (excluded); 1..254: predicted
    /// heading error in deg*10; 255: successful without an estimate.
    pub success: u8,
    /// Reserved, `reserved[4]`.
    pub reserved_1: [u8; 4],
    /// Average pitch, deg, `f32`, degrees: Average pitch during the run.
    pub average_pitch: f32,
    /// Average roll, deg, `f32`, degrees: Average roll during the run.
    pub average_roll: f32,
    /// Reserved, `reserved[12]`.
    pub reserved_2: [u8; 12],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
}

impl CalibrationRunResultRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<CalibrationRunResultRepr> {
        let view = CalibrationRunResult::new_checked(data)?;
        Ok(CalibrationRunResultRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &CalibrationRunResult<T>) -> CalibrationRunResultRepr {
        CalibrationRunResultRepr {
            calibration_type: view.calibration_type(),
            run: view.run(),
            data_used: view.data_used(),
            success: view.success(),
            reserved_1: wire::array(view.as_bytes(), field::RESERVED_1),
            average_pitch: view.average_pitch(),
            average_roll: view.average_roll(),
            reserved_2: wire::array(view.as_bytes(), field::RESERVED_2),
            usw: view.usw(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`CalibrationRunResultRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationRunResultRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut CalibrationRunResult::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut CalibrationRunResult<T>) {
        view.set_calibration_type(self.calibration_type);
        view.set_run(self.run);
        view.set_data_used(self.data_used);
        view.set_success(self.success);
        wire::put(view.buffer.as_mut(), field::RESERVED_1, &self.reserved_1);
        view.set_average_pitch(self.average_pitch);
        view.set_average_roll(self.average_roll);
        wire::put(view.buffer.as_mut(), field::RESERVED_2, &self.reserved_2);
        view.set_usw(self.usw);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`CalibrationRunResultRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 9] {
        [
            Raw::value(self.calibration_type),
            Raw::value(self.run),
            Raw::value(self.data_used),
            Raw::value(self.success),
            Value::Bytes(&self.reserved_1),
            Raw::value(self.average_pitch),
            Raw::value(self.average_roll),
            Value::Bytes(&self.reserved_2),
            Raw::value(self.usw),
        ]
    }

    /// The raw value of field `index` (table order), or `None` past the last field.
    pub fn value(&self, index: usize) -> Option<Value<'_>> {
        self.values().get(index).copied()
    }

    /// Sets field `index` (table order) after checking `value` as a builder does.
    /// Errors: `out_of_range` naming the field, or with no field for an index past the
    /// last.
    pub fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        match index {
            0 => self.calibration_type = Raw::from_value(&info::CALIBRATION_TYPE, value)?,
            1 => self.run = Raw::from_value(&info::RUN, value)?,
            2 => self.data_used = Raw::from_value(&info::DATA_USED, value)?,
            3 => self.success = Raw::from_value(&info::SUCCESS, value)?,
            4 => self.reserved_1 = info::RESERVED_1.array(value)?,
            5 => self.average_pitch = Raw::from_value(&info::AVERAGE_PITCH, value)?,
            6 => self.average_roll = Raw::from_value(&info::AVERAGE_ROLL, value)?,
            7 => self.reserved_2 = info::RESERVED_2.array(value)?,
            8 => self.usw = Raw::from_value(&info::USW, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Type of calibration as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationType> {
        CalibrationType::from_raw(self.calibration_type)
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success)
    }

    /// Sets Calibration success.
    pub fn set_success_decoded(&mut self, value: CalibrationSuccess) {
        self.success = value.encode();
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}

impl Table for CalibrationRunResultRepr {
    fn validate(&self) -> Result<()> {
        CalibrationRunResultRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationRunResultRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationRunResultRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        CalibrationRunResultRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        CalibrationRunResultRepr::set_value(self, index, value)
    }
}

impl Default for CalibrationRunResultRepr {
    /// Every field at its default: calibration_type 2, run 1, otherwise zero.
    fn default() -> CalibrationRunResultRepr {
        CalibrationRunResultRepr {
            calibration_type: 2,
            run: 1,
            data_used: 0,
            success: 0,
            reserved_1: [0; 4],
            average_pitch: 0.0,
            average_roll: 0.0,
            reserved_2: [0; 12],
            usw: 0,
        }
    }
}
