// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.17, Calibration results read back (52 bytes, E2).
//!
//! The AHRS answer to GetClbRes (6.4.10).

use crate::encoding::CalibrationStatusType;
use crate::encoding::CalibrationSuccess;
use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Value};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 52;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Type of calibration performed, `u8`.
    pub const CALIBRATION_TYPE: Field = 0..1;
    /// Number of used calibration runs, `u8`.
    pub const RUNS_USED: Field = 1..2;
    /// Reserved, `reserved[1]`.
    pub const RESERVED: Field = 2..3;
    /// Calibration success, `u8`.
    pub const SUCCESS: Field = 3..4;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_11: Field = 4..8;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_12: Field = 8..12;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_13: Field = 12..16;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_21: Field = 16..20;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_22: Field = 20..24;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_23: Field = 24..28;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_31: Field = 28..32;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_32: Field = 32..36;
    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_33: Field = 36..40;
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_X: Field = 40..44;
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Y: Field = 44..48;
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Z: Field = 48..52;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Type of calibration performed, `u8`.
    pub const CALIBRATION_TYPE: FieldInfo = FieldInfo {
        icd_name: "Type of calibration performed",
        doc: "0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D; above 0x80: parameters loaded by other software.",
        ..FieldInfo::new("calibration_type", field::CALIBRATION_TYPE, FieldKind::Unsigned)
    };

    /// Number of used calibration runs, `u8`.
    pub const RUNS_USED: FieldInfo = crate::payload::calibration_result::info::RUNS_USED;

    /// Reserved, `reserved[1]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 1]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };

    /// Calibration success, `u8`.
    pub const SUCCESS: FieldInfo = FieldInfo {
        icd_name: "Calibration success",
        encoding: Some(Encoding::CalibrationSuccess),
        doc: "0: not successful; 1..254: predicted heading error in deg*10; 255: successful without an estimate.",
        ..FieldInfo::new("success", field::SUCCESS, FieldKind::Unsigned)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_11: FieldInfo = crate::payload::calibration_result::info::TM_C_11;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_12: FieldInfo = crate::payload::calibration_result::info::TM_C_12;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_13: FieldInfo = crate::payload::calibration_result::info::TM_C_13;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_21: FieldInfo = crate::payload::calibration_result::info::TM_C_21;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_22: FieldInfo = crate::payload::calibration_result::info::TM_C_22;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_23: FieldInfo = crate::payload::calibration_result::info::TM_C_23;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_31: FieldInfo = crate::payload::calibration_result::info::TM_C_31;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_32: FieldInfo = crate::payload::calibration_result::info::TM_C_32;

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_33: FieldInfo = crate::payload::calibration_result::info::TM_C_33;

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_X: FieldInfo = crate::payload::calibration_result::info::HM_0_X;

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Y: FieldInfo = crate::payload::calibration_result::info::HM_0_Y;

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Z: FieldInfo = crate::payload::calibration_result::info::HM_0_Z;
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 16] = [
    info::CALIBRATION_TYPE,
    info::RUNS_USED,
    info::RESERVED,
    info::SUCCESS,
    info::TM_C_11,
    info::TM_C_12,
    info::TM_C_13,
    info::TM_C_21,
    info::TM_C_22,
    info::TM_C_23,
    info::TM_C_31,
    info::TM_C_32,
    info::TM_C_33,
    info::HM_0_X,
    info::HM_0_Y,
    info::HM_0_Z,
];

/// Table 6.17, Calibration results read back: a zero-copy view over a payload.
///
/// [`CalibrationStatus::new_checked`] checks the size once; the accessors never panic, even
/// on a view made by [`CalibrationStatus::new_unchecked`] over a short buffer (missing
/// bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationStatus<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationStatus<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationStatus<T> {
        CalibrationStatus { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<CalibrationStatus<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(CalibrationStatus { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Type of calibration performed, `u8`: 0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D;
    /// above 0x80: parameters loaded by other software.
    pub fn calibration_type(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::CALIBRATION_TYPE)
    }

    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    pub fn runs_used(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::RUNS_USED)
    }

    /// Reserved, `reserved[1]`.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }

    /// Calibration success, `u8`: 0: not successful; 1..254: predicted heading error in
    /// deg*10; 255: successful without an estimate.
    pub fn success(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::SUCCESS)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 1.
    pub fn tm_c_11(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_11)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 2.
    pub fn tm_c_12(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_12)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 3.
    pub fn tm_c_13(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_13)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 1.
    pub fn tm_c_21(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_21)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 2.
    pub fn tm_c_22(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_22)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 3.
    pub fn tm_c_23(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_23)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 1.
    pub fn tm_c_31(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_31)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 2.
    pub fn tm_c_32(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_32)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 3.
    pub fn tm_c_33(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::TM_C_33)
    }

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 1.
    pub fn hm_0_x(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::HM_0_X)
    }

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 2.
    pub fn hm_0_y(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::HM_0_Y)
    }

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 3.
    pub fn hm_0_z(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::HM_0_Z)
    }

    /// Type of calibration performed as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationStatusType> {
        CalibrationStatusType::from_raw(self.calibration_type())
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationStatus<T> {
    /// Sets [`Self::calibration_type`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_calibration_type(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::CALIBRATION_TYPE, value);
    }

    /// Sets [`Self::runs_used`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_runs_used(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::RUNS_USED, value);
    }

    /// Sets [`Self::reserved`] (bytes kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 1]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets [`Self::success`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_success(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::SUCCESS, value);
    }

    /// Sets [`Self::tm_c_11`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_11(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_11, value);
    }

    /// Sets [`Self::tm_c_12`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_12(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_12, value);
    }

    /// Sets [`Self::tm_c_13`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_13(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_13, value);
    }

    /// Sets [`Self::tm_c_21`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_21(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_21, value);
    }

    /// Sets [`Self::tm_c_22`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_22(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_22, value);
    }

    /// Sets [`Self::tm_c_23`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_23(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_23, value);
    }

    /// Sets [`Self::tm_c_31`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_31(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_31, value);
    }

    /// Sets [`Self::tm_c_32`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_32(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_32, value);
    }

    /// Sets [`Self::tm_c_33`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_tm_c_33(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_33, value);
    }

    /// Sets [`Self::hm_0_x`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_hm_0_x(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::HM_0_X, value);
    }

    /// Sets [`Self::hm_0_y`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_hm_0_y(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::HM_0_Y, value);
    }

    /// Sets [`Self::hm_0_z`] (raw, unchecked: [`CalibrationStatusRepr::build`] checks ranges).
    pub fn set_hm_0_z(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::HM_0_Z, value);
    }
}

/// Table 6.17, Calibration results read back: the payload as a value, with raw field
/// values.
///
/// [`CalibrationStatusRepr::parse`] and [`CalibrationStatusRepr::build`] are exact
/// inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same bytes
/// when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CalibrationStatusRepr {
    /// Type of calibration performed, `u8`: 0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D;
    /// above 0x80: parameters loaded by other software.
    pub calibration_type: u8,
    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    pub runs_used: u8,
    /// Reserved, `reserved[1]`.
    pub reserved: [u8; 1],
    /// Calibration success, `u8`: 0: not successful; 1..254: predicted heading error in
    /// deg*10; 255: successful without an estimate.
    pub success: u8,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 1.
    pub tm_c_11: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 2.
    pub tm_c_12: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 3.
    pub tm_c_13: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 1.
    pub tm_c_21: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 2.
    pub tm_c_22: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 3.
    pub tm_c_23: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 1.
    pub tm_c_31: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 2.
    pub tm_c_32: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 3.
    pub tm_c_33: f32,
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 1.
    pub hm_0_x: f32,
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 2.
    pub hm_0_y: f32,
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 3.
    pub hm_0_z: f32,
}

impl CalibrationStatusRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<CalibrationStatusRepr> {
        let view = CalibrationStatus::new_checked(data)?;
        Ok(CalibrationStatusRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &CalibrationStatus<T>) -> CalibrationStatusRepr {
        CalibrationStatusRepr {
            calibration_type: view.calibration_type(),
            runs_used: view.runs_used(),
            reserved: wire::array(view.as_bytes(), field::RESERVED),
            success: view.success(),
            tm_c_11: view.tm_c_11(),
            tm_c_12: view.tm_c_12(),
            tm_c_13: view.tm_c_13(),
            tm_c_21: view.tm_c_21(),
            tm_c_22: view.tm_c_22(),
            tm_c_23: view.tm_c_23(),
            tm_c_31: view.tm_c_31(),
            tm_c_32: view.tm_c_32(),
            tm_c_33: view.tm_c_33(),
            hm_0_x: view.hm_0_x(),
            hm_0_y: view.hm_0_y(),
            hm_0_z: view.hm_0_z(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`CalibrationStatusRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationStatusRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut CalibrationStatus::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut CalibrationStatus<T>) {
        view.set_calibration_type(self.calibration_type);
        view.set_runs_used(self.runs_used);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
        view.set_success(self.success);
        view.set_tm_c_11(self.tm_c_11);
        view.set_tm_c_12(self.tm_c_12);
        view.set_tm_c_13(self.tm_c_13);
        view.set_tm_c_21(self.tm_c_21);
        view.set_tm_c_22(self.tm_c_22);
        view.set_tm_c_23(self.tm_c_23);
        view.set_tm_c_31(self.tm_c_31);
        view.set_tm_c_32(self.tm_c_32);
        view.set_tm_c_33(self.tm_c_33);
        view.set_hm_0_x(self.hm_0_x);
        view.set_hm_0_y(self.hm_0_y);
        view.set_hm_0_z(self.hm_0_z);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`CalibrationStatusRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 16] {
        [
            Raw::value(self.calibration_type),
            Raw::value(self.runs_used),
            Value::Bytes(&self.reserved),
            Raw::value(self.success),
            Raw::value(self.tm_c_11),
            Raw::value(self.tm_c_12),
            Raw::value(self.tm_c_13),
            Raw::value(self.tm_c_21),
            Raw::value(self.tm_c_22),
            Raw::value(self.tm_c_23),
            Raw::value(self.tm_c_31),
            Raw::value(self.tm_c_32),
            Raw::value(self.tm_c_33),
            Raw::value(self.hm_0_x),
            Raw::value(self.hm_0_y),
            Raw::value(self.hm_0_z),
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
            1 => self.runs_used = Raw::from_value(&info::RUNS_USED, value)?,
            2 => self.reserved = info::RESERVED.array(value)?,
            3 => self.success = Raw::from_value(&info::SUCCESS, value)?,
            4 => self.tm_c_11 = Raw::from_value(&info::TM_C_11, value)?,
            5 => self.tm_c_12 = Raw::from_value(&info::TM_C_12, value)?,
            6 => self.tm_c_13 = Raw::from_value(&info::TM_C_13, value)?,
            7 => self.tm_c_21 = Raw::from_value(&info::TM_C_21, value)?,
            8 => self.tm_c_22 = Raw::from_value(&info::TM_C_22, value)?,
            9 => self.tm_c_23 = Raw::from_value(&info::TM_C_23, value)?,
            10 => self.tm_c_31 = Raw::from_value(&info::TM_C_31, value)?,
            11 => self.tm_c_32 = Raw::from_value(&info::TM_C_32, value)?,
            12 => self.tm_c_33 = Raw::from_value(&info::TM_C_33, value)?,
            13 => self.hm_0_x = Raw::from_value(&info::HM_0_X, value)?,
            14 => self.hm_0_y = Raw::from_value(&info::HM_0_Y, value)?,
            15 => self.hm_0_z = Raw::from_value(&info::HM_0_Z, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Type of calibration performed as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationStatusType> {
        CalibrationStatusType::from_raw(self.calibration_type)
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success)
    }

    /// Sets Calibration success.
    pub fn set_success_decoded(&mut self, value: CalibrationSuccess) {
        self.success = value.encode();
    }
}

impl Table for CalibrationStatusRepr {
    fn validate(&self) -> Result<()> {
        CalibrationStatusRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationStatusRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationStatusRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        CalibrationStatusRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        CalibrationStatusRepr::set_value(self, index, value)
    }
}
