// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.14, Calibration result (52 bytes, E1).
//!
//! Sent when a calibration completes (after the accumulation time, StopClbRun, or FinishClb).

use crate::encoding::CalibrationSuccess;
use crate::encoding::CalibrationType;
use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Unit, Value};
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
    use super::*;

    /// Type of calibration, `u8`.
    pub const CALIBRATION_TYPE: FieldInfo = FieldInfo {
        icd_name: "Type of calibration",
        min: 1.0,
        max: 3.0,
        default: Value::Int(1),
        doc: "1 for 2D, 2 for 2D-2T, 3 for 3D calibration.",
        ..FieldInfo::new(
            "calibration_type",
            field::CALIBRATION_TYPE,
            FieldKind::Unsigned,
        )
    };

    /// Number of used calibration runs, `u8`.
    pub const RUNS_USED: FieldInfo = FieldInfo {
        icd_name: "Number of used calibration runs",
        doc: "Number of calibration runs used.",
        ..FieldInfo::new("runs_used", field::RUNS_USED, FieldKind::Unsigned)
    };

    /// Percent of used data points, `u8`, percent.
    pub const DATA_USED: FieldInfo = FieldInfo {
        icd_name: "Percent of used data points",
        min: 0.0,
        max: 100.0,
        unit: Some(Unit::Percent),
        doc: "Percent of data points used (2D and 3D calibrations only).",
        ..FieldInfo::new("data_used", field::DATA_USED, FieldKind::Unsigned)
    };

    /// Calibration success, `u8`.
    pub const SUCCESS: FieldInfo = FieldInfo {
        icd_name: "Calibration success",
        encoding: Some(Encoding::CalibrationSuccess),
        doc: "0: not successful; 1..254: predicted 3-sigma heading error in deg*10; 255: successful without an estimate.",
        ..FieldInfo::new("success", field::SUCCESS, FieldKind::Unsigned)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_11: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 1 column 1.",
        ..FieldInfo::new("tm_c_11", field::TM_C_11, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_12: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 1 column 2.",
        ..FieldInfo::new("tm_c_12", field::TM_C_12, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_13: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 1 column 3.",
        ..FieldInfo::new("tm_c_13", field::TM_C_13, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_21: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 2 column 1.",
        ..FieldInfo::new("tm_c_21", field::TM_C_21, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_22: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 2 column 2.",
        ..FieldInfo::new("tm_c_22", field::TM_C_22, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_23: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 2 column 3.",
        ..FieldInfo::new("tm_c_23", field::TM_C_23, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_31: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 3 column 1.",
        ..FieldInfo::new("tm_c_31", field::TM_C_31, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_32: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 3 column 2.",
        ..FieldInfo::new("tm_c_32", field::TM_C_32, FieldKind::Float)
    };

    /// Matrix for soft iron correction, `f32`, dimensionless.
    pub const TM_C_33: FieldInfo = FieldInfo {
        icd_name: "Matrix for soft iron correction",
        unit: Some(Unit::One),
        doc: "Soft-iron matrix Tm_c row 3 column 3.",
        ..FieldInfo::new("tm_c_33", field::TM_C_33, FieldKind::Float)
    };

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_X: FieldInfo = FieldInfo {
        icd_name: "Matrix for hard iron correction",
        unit: Some(Unit::Adc),
        doc: "Hard-iron vector Hm_0 component 1.",
        ..FieldInfo::new("hm_0_x", field::HM_0_X, FieldKind::Float)
    };

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Y: FieldInfo = FieldInfo {
        icd_name: "Matrix for hard iron correction",
        unit: Some(Unit::Adc),
        doc: "Hard-iron vector Hm_0 component 2.",
        ..FieldInfo::new("hm_0_y", field::HM_0_Y, FieldKind::Float)
    };

    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the ICD).
    pub const HM_0_Z: FieldInfo = FieldInfo {
        icd_name: "Matrix for hard iron correction",
        unit: Some(Unit::Adc),
        doc: "Hard-iron vector Hm_0 component 3.",
        ..FieldInfo::new("hm_0_z", field::HM_0_Z, FieldKind::Float)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 16] = [
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
/// [`CalibrationResult::new_checked`] checks the size once; the accessors never panic, even
/// on a view made by [`CalibrationResult::new_unchecked`] over a short buffer (missing
/// bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationResult<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationResult<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationResult<T> {
        CalibrationResult { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
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
        wire::get(self.buffer.as_ref(), field::CALIBRATION_TYPE)
    }

    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    pub fn runs_used(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::RUNS_USED)
    }

    /// Percent of used data points, `u8`, percent: Percent of data points used (2D and 3D
    /// calibrations only).
    pub fn data_used(&self) -> u8 {
        wire::get(self.buffer.as_ref(), field::DATA_USED)
    }

    /// Calibration success, `u8`: 0: not successful; 1..254: predicted 3-sigma heading
    /// error in deg*10; 255: successful without an estimate.
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

    /// Type of calibration as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationType> {
        CalibrationType::from_raw(self.calibration_type())
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationResult<T> {
    /// Sets [`Self::calibration_type`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_calibration_type(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::CALIBRATION_TYPE, value);
    }

    /// Sets [`Self::runs_used`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_runs_used(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::RUNS_USED, value);
    }

    /// Sets [`Self::data_used`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_data_used(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::DATA_USED, value);
    }

    /// Sets [`Self::success`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_success(&mut self, value: u8) {
        wire::set(self.buffer.as_mut(), field::SUCCESS, value);
    }

    /// Sets [`Self::tm_c_11`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_11(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_11, value);
    }

    /// Sets [`Self::tm_c_12`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_12(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_12, value);
    }

    /// Sets [`Self::tm_c_13`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_13(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_13, value);
    }

    /// Sets [`Self::tm_c_21`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_21(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_21, value);
    }

    /// Sets [`Self::tm_c_22`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_22(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_22, value);
    }

    /// Sets [`Self::tm_c_23`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_23(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_23, value);
    }

    /// Sets [`Self::tm_c_31`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_31(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_31, value);
    }

    /// Sets [`Self::tm_c_32`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_32(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_32, value);
    }

    /// Sets [`Self::tm_c_33`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_tm_c_33(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::TM_C_33, value);
    }

    /// Sets [`Self::hm_0_x`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_hm_0_x(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::HM_0_X, value);
    }

    /// Sets [`Self::hm_0_y`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_hm_0_y(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::HM_0_Y, value);
    }

    /// Sets [`Self::hm_0_z`] (raw, unchecked: [`CalibrationResultRepr::build`] checks ranges).
    pub fn set_hm_0_z(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::HM_0_Z, value);
    }
}

/// Table 6.14, Calibration result: the payload as a value, with raw field values.
///
/// [`CalibrationResultRepr::parse`] and [`CalibrationResultRepr::build`] are exact
/// inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same bytes
/// when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationResultRepr {
    /// Type of calibration, `u8`: 1 for 2D, 2 for 2D-2T, 3 for 3D calibration.
    pub calibration_type: u8,
    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    pub runs_used: u8,
    /// Percent of used data points, `u8`, percent: Percent of data points used (2D and 3D
    /// calibrations only).
    pub data_used: u8,
    /// Calibration success, `u8`: 0: not successful; 1..254: predicted 3-sigma heading
    /// error in deg*10; 255: successful without an estimate.
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

impl CalibrationResultRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
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

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`CalibrationResultRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationResultRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
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

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`CalibrationResultRepr::build`].
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
            Raw::value(self.data_used),
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
            2 => self.data_used = Raw::from_value(&info::DATA_USED, value)?,
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

impl Table for CalibrationResultRepr {
    fn validate(&self) -> Result<()> {
        CalibrationResultRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationResultRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationResultRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        CalibrationResultRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        CalibrationResultRepr::set_value(self, index, value)
    }
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
