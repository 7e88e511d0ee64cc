// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.14, Calibration result (52 bytes, E1).
//!
//! Sent when a calibration completes (after the accumulation time, StopClbRun, or FinishClb).

use crate::encoding::CalibrationSuccess;
use crate::encoding::CalibrationType;
use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Unit, Value};

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

payload_table! {
    /// Table 6.14, Calibration result: a zero-copy view over a payload.
    ///
    /// \[`CalibrationResult::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`CalibrationResult::new_unchecked`\] over a short
    /// buffer (missing bytes read as zero).
    view CalibrationResult;
    /// Table 6.14, Calibration result: the payload as a value, with raw field values.
    ///
    /// \[`CalibrationResultRepr::parse`\] and \[`CalibrationResultRepr::build`\] are exact
    /// inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the same
    /// bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq)]
    repr CalibrationResultRepr;
    count 16;
    /// Type of calibration, `u8`: 1 for 2D, 2 for 2D-2T, 3 for 3D calibration.
    0 number calibration_type set_calibration_type CALIBRATION_TYPE: u8;
    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    1 number runs_used set_runs_used RUNS_USED: u8;
    /// Percent of used data points, `u8`, percent: Percent of data points used (2D and 3D
    /// calibrations only).
    2 number data_used set_data_used DATA_USED: u8;
    /// Calibration success, `u8`: 0: not successful; 1..254: predicted 3-sigma heading
    /// error in deg*10; 255: successful without an estimate.
    3 number success set_success SUCCESS: u8;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 1.
    4 number tm_c_11 set_tm_c_11 TM_C_11: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 2.
    5 number tm_c_12 set_tm_c_12 TM_C_12: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 1
    /// column 3.
    6 number tm_c_13 set_tm_c_13 TM_C_13: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 1.
    7 number tm_c_21 set_tm_c_21 TM_C_21: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 2.
    8 number tm_c_22 set_tm_c_22 TM_C_22: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 2
    /// column 3.
    9 number tm_c_23 set_tm_c_23 TM_C_23: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 1.
    10 number tm_c_31 set_tm_c_31 TM_C_31: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 2.
    11 number tm_c_32 set_tm_c_32 TM_C_32: f32;
    /// Matrix for soft iron correction, `f32`, dimensionless: Soft-iron matrix Tm_c row 3
    /// column 3.
    12 number tm_c_33 set_tm_c_33 TM_C_33: f32;
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 1.
    13 number hm_0_x set_hm_0_x HM_0_X: f32;
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 2.
    14 number hm_0_y set_hm_0_y HM_0_Y: f32;
    /// Matrix for hard iron correction, `f32`, ADC codes (no physical scale given by the
    /// ICD): Hard-iron vector Hm_0 component 3.
    15 number hm_0_z set_hm_0_z HM_0_Z: f32;
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

impl<T: AsRef<[u8]>> CalibrationResult<T> {
    /// Type of calibration as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationType> {
        CalibrationType::from_raw(self.calibration_type())
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }
}

impl CalibrationResultRepr {
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
