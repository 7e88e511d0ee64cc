// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.14, Calibration result (52 bytes, E1).
//!
//! Sent when a calibration completes (after the accumulation time, StopClbRun, or FinishClb).

use crate::encoding::CalibrationSuccess;
use crate::encoding::CalibrationType;
use crate::error::{Error, ErrorKind, Result};
use crate::frame::{FrameRepr, MessageType};
use crate::payload::{check_size, Value};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 52;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Type of calibration, `u8`.
    pub const CALIBRATION_TYPE: Field = 0..1;

    /// Number of used calibration runs, `u8`.
    pub const RUNS_USED: Field = 1..2;

    /// Percent of used data points, `u8`, percent.
    pub const DATA_USED: Field = 2..3;

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
    use super::field;
    use crate::payload::{FieldInfo, FieldKind, Value};

    /// Type of calibration, `u8`.
    pub const CALIBRATION_TYPE: FieldInfo = FieldInfo {
        name: "calibration_type",
        icd_name: "Type of calibration",
        offset: field::CALIBRATION_TYPE.start,
        size: 1,
        kind: FieldKind::Unsigned,
        min: 1.0,
        max: 3.0,
        default: Value::Int(1),
        scale: None,
        unit: None,
        encoding: None,
        doc: "1 for 2D, 2 for 2D-2T, 3 for 3D calibration.",
    };

    /// Number of used calibration runs, `u8`.
    pub const RUNS_USED: FieldInfo = FieldInfo {
        name: "runs_used",
        icd_name: "Number of used calibration runs",
        offset: field::RUNS_USED.start,
        size: 1,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 255.0,
        default: Value::Int(0),
        scale: None,
        unit: None,
        encoding: None,
        doc: "Number of calibration runs used.",
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
        doc: "Percent of data points used (2D and 3D calibrations only).",
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
            "0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful without an estimate.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_11: FieldInfo = FieldInfo {
        name: "tm_c_11",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_11.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 1 column 1.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_12: FieldInfo = FieldInfo {
        name: "tm_c_12",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_12.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 1 column 2.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_13: FieldInfo = FieldInfo {
        name: "tm_c_13",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_13.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 1 column 3.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_21: FieldInfo = FieldInfo {
        name: "tm_c_21",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_21.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 2 column 1.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_22: FieldInfo = FieldInfo {
        name: "tm_c_22",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_22.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 2 column 2.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_23: FieldInfo = FieldInfo {
        name: "tm_c_23",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_23.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 2 column 3.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_31: FieldInfo = FieldInfo {
        name: "tm_c_31",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_31.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 3 column 1.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_32: FieldInfo = FieldInfo {
        name: "tm_c_32",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_32.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 3 column 2.",
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_33: FieldInfo = FieldInfo {
        name: "tm_c_33",
        icd_name: "Matrix for soft iron correction",
        offset: field::TM_C_33.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Soft-iron matrix Tm_c row 3 column 3.",
    };

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_X: FieldInfo = FieldInfo {
        name: "hm_0_x",
        icd_name: "Matrix for hard iron correction",
        offset: field::HM_0_X.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Hard-iron vector Hm_0 component 1.",
    };

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Y: FieldInfo = FieldInfo {
        name: "hm_0_y",
        icd_name: "Matrix for hard iron correction",
        offset: field::HM_0_Y.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Hard-iron vector Hm_0 component 2.",
    };

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Z: FieldInfo = FieldInfo {
        name: "hm_0_z",
        icd_name: "Matrix for hard iron correction",
        offset: field::HM_0_Z.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Hard-iron vector Hm_0 component 3.",
    };
}

/// Every field, in wire order.
pub static FIELDS: [crate::payload::FieldInfo; 16] = [
    info::CALIBRATION_TYPE,
    info::RUNS_USED,
    info::DATA_USED,
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

/// Table 6.14, Calibration result: a zero-copy view over a payload.
///
/// [`CalibrationResult::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`CalibrationResult::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationResult<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationResult<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationResult<T> {
        CalibrationResult { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<CalibrationResult<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(CalibrationResult { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Type of calibration, `u8`: 1 for 2D, 2 for 2D-2T, 3 for 3D calibration.
    pub fn calibration_type(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::CALIBRATION_TYPE)
    }

    /// Type of calibration as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationType> {
        CalibrationType::from_raw(self.calibration_type())
    }

    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    pub fn runs_used(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::RUNS_USED)
    }

    /// Percent of used data points, `u8`, percent: Percent of data points used (2D and 3D calibrations only).
    pub fn data_used(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::DATA_USED)
    }

    /// Calibration success, `u8`: 0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful without an estimate.
    pub fn success(&self) -> u8 {
        wire::get_u8(self.buffer.as_ref(), field::SUCCESS)
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1 column 1.
    pub fn tm_c_11(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_11)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1 column 2.
    pub fn tm_c_12(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_12)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1 column 3.
    pub fn tm_c_13(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_13)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2 column 1.
    pub fn tm_c_21(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_21)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2 column 2.
    pub fn tm_c_22(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_22)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2 column 3.
    pub fn tm_c_23(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_23)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3 column 1.
    pub fn tm_c_31(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_31)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3 column 2.
    pub fn tm_c_32(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_32)
    }

    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3 column 3.
    pub fn tm_c_33(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::TM_C_33)
    }

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD): Hard-iron vector Hm_0 component 1.
    pub fn hm_0_x(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::HM_0_X)
    }

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD): Hard-iron vector Hm_0 component 2.
    pub fn hm_0_y(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::HM_0_Y)
    }

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD): Hard-iron vector Hm_0 component 3.
    pub fn hm_0_z(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::HM_0_Z)
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationResult<T> {
    /// Sets Type of calibration (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_calibration_type(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::CALIBRATION_TYPE, value);
    }

    /// Sets Number of used calibration runs (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_runs_used(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::RUNS_USED, value);
    }

    /// Sets Percent of used data points (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_data_used(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::DATA_USED, value);
    }

    /// Sets Calibration success (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_success(&mut self, value: u8) {
        wire::set_u8(self.buffer.as_mut(), field::SUCCESS, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_11(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_11, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_12(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_12, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_13(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_13, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_21(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_21, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_22(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_22, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_23(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_23, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_31(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_31, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_32(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_32, value);
    }

    /// Sets Matrix for soft iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_33(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::TM_C_33, value);
    }

    /// Sets Matrix for hard iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_hm_0_x(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::HM_0_X, value);
    }

    /// Sets Matrix for hard iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_hm_0_y(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::HM_0_Y, value);
    }

    /// Sets Matrix for hard iron correction (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_hm_0_z(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::HM_0_Z, value);
    }
}

/// Table 6.14, Calibration result: the payload as a value, with raw field values.
///
/// [`CalibrationResultRepr::parse`] and [`CalibrationResultRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationResultRepr {
    /// Type of calibration, `u8`: 1 for 2D, 2 for 2D-2T, 3 for 3D calibration.
    pub calibration_type: u8,
    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    pub runs_used: u8,
    /// Percent of used data points, `u8`, percent: Percent of data points used (2D and 3D calibrations only).
    pub data_used: u8,
    /// Calibration success, `u8`: 0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful without an estimate.
    pub success: u8,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1 column 1.
    pub tm_c_11: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1 column 2.
    pub tm_c_12: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1 column 3.
    pub tm_c_13: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2 column 1.
    pub tm_c_21: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2 column 2.
    pub tm_c_22: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2 column 3.
    pub tm_c_23: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3 column 1.
    pub tm_c_31: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3 column 2.
    pub tm_c_32: f32,
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3 column 3.
    pub tm_c_33: f32,
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD): Hard-iron vector Hm_0 component 1.
    pub hm_0_x: f32,
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD): Hard-iron vector Hm_0 component 2.
    pub hm_0_y: f32,
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD): Hard-iron vector Hm_0 component 3.
    pub hm_0_z: f32,
}

impl Default for CalibrationResultRepr {
    /// Every field at its default: calibration_type 1, otherwise zero.
    fn default() -> CalibrationResultRepr {
        CalibrationResultRepr {
            calibration_type: 1,
            runs_used: 0,
            data_used: 0,
            success: 0,
            tm_c_11: 0.0,
            tm_c_12: 0.0,
            tm_c_13: 0.0,
            tm_c_21: 0.0,
            tm_c_22: 0.0,
            tm_c_23: 0.0,
            tm_c_31: 0.0,
            tm_c_32: 0.0,
            tm_c_33: 0.0,
            hm_0_x: 0.0,
            hm_0_y: 0.0,
            hm_0_z: 0.0,
        }
    }
}

impl CalibrationResultRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
    pub fn parse(data: &[u8]) -> Result<CalibrationResultRepr> {
        let view = CalibrationResult::new_checked(data)?;
        Ok(CalibrationResultRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &CalibrationResult<T>) -> CalibrationResultRepr {
        CalibrationResultRepr {
            calibration_type: view.calibration_type(),
            runs_used: view.runs_used(),
            data_used: view.data_used(),
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

    /// Checks every field in table order, as a builder does; the first bad one is the error:
    /// `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        for (info, value) in FIELDS.iter().zip(self.values()) {
            info.check(value)?;
        }
        Ok(())
    }

    /// The size of the payload [`CalibrationResultRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationResultRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
        self.emit(&mut CalibrationResult::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut CalibrationResult<T>) {
        view.set_calibration_type(self.calibration_type);
        view.set_runs_used(self.runs_used);
        view.set_data_used(self.data_used);
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

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`CalibrationResultRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        FrameRepr::new(MessageType::Data, &payload).build(buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 16] {
        [
            Value::Int(i64::from(self.calibration_type)),
            Value::Int(i64::from(self.runs_used)),
            Value::Int(i64::from(self.data_used)),
            Value::Int(i64::from(self.success)),
            Value::Float(f64::from(self.tm_c_11)),
            Value::Float(f64::from(self.tm_c_12)),
            Value::Float(f64::from(self.tm_c_13)),
            Value::Float(f64::from(self.tm_c_21)),
            Value::Float(f64::from(self.tm_c_22)),
            Value::Float(f64::from(self.tm_c_23)),
            Value::Float(f64::from(self.tm_c_31)),
            Value::Float(f64::from(self.tm_c_32)),
            Value::Float(f64::from(self.tm_c_33)),
            Value::Float(f64::from(self.hm_0_x)),
            Value::Float(f64::from(self.hm_0_y)),
            Value::Float(f64::from(self.hm_0_z)),
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
            1 => self.runs_used = info::RUNS_USED.int(value)?,
            2 => self.data_used = info::DATA_USED.int(value)?,
            3 => self.success = info::SUCCESS.int(value)?,
            4 => self.tm_c_11 = info::TM_C_11.float(value)?,
            5 => self.tm_c_12 = info::TM_C_12.float(value)?,
            6 => self.tm_c_13 = info::TM_C_13.float(value)?,
            7 => self.tm_c_21 = info::TM_C_21.float(value)?,
            8 => self.tm_c_22 = info::TM_C_22.float(value)?,
            9 => self.tm_c_23 = info::TM_C_23.float(value)?,
            10 => self.tm_c_31 = info::TM_C_31.float(value)?,
            11 => self.tm_c_32 = info::TM_C_32.float(value)?,
            12 => self.tm_c_33 = info::TM_C_33.float(value)?,
            13 => self.hm_0_x = info::HM_0_X.float(value)?,
            14 => self.hm_0_y = info::HM_0_Y.float(value)?,
            15 => self.hm_0_z = info::HM_0_Z.float(value)?,
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
}
