// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.15, 2D-2T calibration run result (30 bytes).
//!
//! Sent after each run of a 2D-2T calibration (6.4.5).

use crate::encoding::CalibrationSuccess;
use crate::encoding::CalibrationType;
use crate::error::{Error, ErrorKind, Result};
use crate::frame::{FrameRepr, MessageType};
use crate::payload::{check_size, Value};
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
    use super::field;
    use crate::payload::{FieldInfo, FieldKind, Value};

    /// Type of calibration, `u8`.
    pub const CALIBRATION_TYPE: FieldInfo = FieldInfo {
        name: "calibration_type",
        icd_name: "Type of calibration",
        offset: field::CALIBRATION_TYPE.start,
        size: 1,
        kind: FieldKind::Unsigned,
        min: 2.0,
        max: 2.0,
        default: Value::Int(2),
        scale: None,
        unit: None,
        encoding: None,
        doc: "2 for 2D-2T calibration.",
    };

    /// Calibration run, `u8`.
    pub const RUN: FieldInfo = FieldInfo {
        name: "run",
        icd_name: "Calibration run",
        offset: field::RUN.start,
        size: 1,
        kind: FieldKind::Unsigned,
        min: 1.0,
        max: 255.0,
        default: Value::Int(1),
        scale: None,
        unit: None,
        encoding: None,
        doc: "Number of this run (1, 2, ...).",
    };

    /// Percent of used data points, `u8`, percent.
    pub const DATA_USED: FieldInfo = FieldInfo {
        name: "data_used",
        icd_name: "Percent of used data points",
        offset: field::DATA_USED.start,
        size: 1,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 100.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Percent),
        encoding: None,
        doc: "Percent of data points used.",
    };

    /// Calibration success, `u8`.
    pub const SUCCESS: FieldInfo = FieldInfo {
        name: "success",
        icd_name: "Calibration success",
        offset: field::SUCCESS.start,
        size: 1,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 255.0,
        default: Value::Int(0),
        scale: None,
        unit: None,
        encoding: Some(crate::payload::Encoding::CalibrationSuccess),
        doc:
            "0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255: successful without an estimate.",
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED_1: FieldInfo = FieldInfo {
        name: "reserved_1",
        icd_name: "Reserved",
        offset: field::RESERVED_1.start,
        size: 4,
        kind: FieldKind::Reserved,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(&[0; 4]),
        scale: None,
        unit: None,
        encoding: None,
        doc: "",
    };

    /// Average pitch, deg, `f32`, degrees.
    pub const AVERAGE_PITCH: FieldInfo = FieldInfo {
        name: "average_pitch",
        icd_name: "Average pitch, deg",
        offset: field::AVERAGE_PITCH.start,
        size: 4,
        kind: FieldKind::Float,
        min: -90.0,
        max: 90.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Average pitch during the run.",
    };

    /// Average roll, deg, `f32`, degrees.
    pub const AVERAGE_ROLL: FieldInfo = FieldInfo {
        name: "average_roll",
        icd_name: "Average roll, deg",
        offset: field::AVERAGE_ROLL.start,
        size: 4,
        kind: FieldKind::Float,
        min: -180.0,
        max: 180.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Average roll during the run.",
    };

    /// Reserved, `reserved[12]`.
    pub const RESERVED_2: FieldInfo = FieldInfo {
        name: "reserved_2",
        icd_name: "Reserved",
        offset: field::RESERVED_2.start,
        size: 12,
        kind: FieldKind::Reserved,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(&[0; 12]),
        scale: None,
        unit: None,
        encoding: None,
        doc: "",
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        name: "usw",
        icd_name: "USW",
        offset: field::USW.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 65535.0,
        default: Value::Int(0),
        scale: None,
        unit: None,
        encoding: Some(crate::payload::Encoding::Usw),
        doc: "Unit Status Word (section 6.5).",
    };
}

/// Every field, in wire order.
pub static FIELDS: [crate::payload::FieldInfo; 9] = [
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
/// [`CalibrationRunResult::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`CalibrationRunResult::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationRunResult<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationRunResult<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationRunResult<T> {
        CalibrationRunResult { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
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
        wire::get_u8(self.buffer.as_ref(), field::CALIBRATION_TYPE)
    }

    /// Type of calibration as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationType> {
        CalibrationType::from_raw(self.calibration_type())
    }

    /// Calibration run, `u8`: Number of this run (1, 2, ...).
    pub fn run(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::RUN)
    }

    /// Percent of used data points, `u8`, percent: Percent of data points used.
    pub fn data_used(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::DATA_USED)
    }

    /// Calibration success, `u8`: 0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255: successful without an estimate.
    pub fn success(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::SUCCESS)
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }

    /// Reserved, `reserved\[4\]`:
    pub fn reserved_1(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED_1)
    }

    /// Average pitch, deg, `f32`, degrees: Average pitch during the run.
    pub fn average_pitch(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::AVERAGE_PITCH)
    }

    /// Average roll, deg, `f32`, degrees: Average roll during the run.
    pub fn average_roll(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::AVERAGE_ROLL)
    }

    /// Reserved, `reserved\[12\]`:
    pub fn reserved_2(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED_2)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::USW)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationRunResult<T> {
    /// Sets Type of calibration (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_calibration_type(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::CALIBRATION_TYPE, value);
    }

    /// Sets Calibration run (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_run(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::RUN, value);
    }

    /// Sets Percent of used data points (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_data_used(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::DATA_USED, value);
    }

    /// Sets Calibration success (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_success(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::SUCCESS, value);
    }

    /// Sets Reserved (4 bytes, kept verbatim).
    pub fn set_reserved_1(&mut self, value: &[u8; 4]) {
        wire::put(self.buffer.as_mut(), field::RESERVED_1, value);
    }

    /// Sets Average pitch, deg (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_average_pitch(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::AVERAGE_PITCH, value);
    }

    /// Sets Average roll, deg (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_average_roll(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::AVERAGE_ROLL, value);
    }

    /// Sets Reserved (12 bytes, kept verbatim).
    pub fn set_reserved_2(&mut self, value: &[u8; 12]) {
        wire::put(self.buffer.as_mut(), field::RESERVED_2, value);
    }

    /// Sets USW (raw, unchecked: [`CalibrationRunResultRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::USW, value);
    }
}

/// Table 6.15, 2D-2T calibration run result: the payload as a value, with raw field values.
///
/// [`CalibrationRunResultRepr::parse`] and [`CalibrationRunResultRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationRunResultRepr {
    /// Type of calibration, `u8`: 2 for 2D-2T calibration.
    pub calibration_type: u8,
    /// Calibration run, `u8`: Number of this run (1, 2, ...).
    pub run: u8,
    /// Percent of used data points, `u8`, percent: Percent of data points used.
    pub data_used: u8,
    /// Calibration success, `u8`: 0: run not successful (excluded); 1..254: predicted heading error in deg*10; 255: successful without an estimate.
    pub success: u8,
    /// Reserved, `reserved\[4\]`:
    pub reserved_1: [u8; 4],
    /// Average pitch, deg, `f32`, degrees: Average pitch during the run.
    pub average_pitch: f32,
    /// Average roll, deg, `f32`, degrees: Average roll during the run.
    pub average_roll: f32,
    /// Reserved, `reserved\[12\]`:
    pub reserved_2: [u8; 12],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
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

impl CalibrationRunResultRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
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

    /// Checks every field in table order, as a builder does; the first bad one is the error:
    /// `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        for (info, value) in FIELDS.iter().zip(self.values()) {
            info.check(value)?;
        }
        Ok(())
    }

    /// The size of the payload [`CalibrationRunResultRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationRunResultRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
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

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`CalibrationRunResultRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        FrameRepr::new(MessageType::Data, &payload).build(buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 9] {
        [
            Value::Int(i64::from(self.calibration_type)),
            Value::Int(i64::from(self.run)),
            Value::Int(i64::from(self.data_used)),
            Value::Int(i64::from(self.success)),
            Value::Bytes(&self.reserved_1),
            Value::Float(f64::from(self.average_pitch)),
            Value::Float(f64::from(self.average_roll)),
            Value::Bytes(&self.reserved_2),
            Value::Int(i64::from(self.usw)),
        ]
    }

    /// The raw value of field `index` (table order), or `None` past the last field.
    pub fn value(&self, index: usize) -> Option<Value<'_>> {
        self.values().get(index).copied()
    }

    /// Sets field `index` (table order) after checking `value` as a builder does. Errors:
    /// `out_of_range` naming the field, or with no field for an index past the last.
    pub fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        match index {
            0 => self.calibration_type = info::CALIBRATION_TYPE.int(value)?,
            1 => self.run = info::RUN.int(value)?,
            2 => self.data_used = info::DATA_USED.int(value)?,
            3 => self.success = info::SUCCESS.int(value)?,
            4 => self.reserved_1 = info::RESERVED_1.array(value)?,
            5 => self.average_pitch = info::AVERAGE_PITCH.float(value)?,
            6 => self.average_roll = info::AVERAGE_ROLL.float(value)?,
            7 => self.reserved_2 = info::RESERVED_2.array(value)?,
            8 => self.usw = info::USW.int(value)?,
            _ => return Err(Error::new(ErrorKind::OutOfRange)),
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
