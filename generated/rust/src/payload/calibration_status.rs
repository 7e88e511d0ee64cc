// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.17, Calibration results read back (52 bytes, E2).
//!
//! The AHRS answer to GetClbRes (6.4.10).

use crate::encoding::CalibrationStatusType;
use crate::encoding::CalibrationSuccess;
use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Value};

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

payload_table! {
    /// Table 6.17, Calibration results read back: a zero-copy view over a payload.
    ///
    /// \[`CalibrationStatus::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`CalibrationStatus::new_unchecked`\] over a short
    /// buffer (missing bytes read as zero).
    view CalibrationStatus;
    /// Table 6.17, Calibration results read back: the payload as a value, with raw field
    /// values.
    ///
    /// \[`CalibrationStatusRepr::parse`\] and \[`CalibrationStatusRepr::build`\] are exact
    /// inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the same
    /// bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr CalibrationStatusRepr;
    count 16;
    /// Type of calibration performed, `u8`: 0: not calibrated; 1: 2D; 2: 2D-2T; 3: 3D;
    /// above 0x80: parameters loaded by other software.
    0 number calibration_type set_calibration_type CALIBRATION_TYPE: u8;
    /// Number of used calibration runs, `u8`: Number of calibration runs used.
    1 number runs_used set_runs_used RUNS_USED: u8;
    /// Reserved, `reserved\[1\]`:
    2 reserved reserved set_reserved RESERVED: [u8; 1];
    /// Calibration success, `u8`: 0: not successful; 1..254: predicted heading error in
    /// deg*10; 255: successful without an estimate.
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

impl<T: AsRef<[u8]>> CalibrationStatus<T> {
    /// Type of calibration performed as a named value, or `None` for a code the ICD does not name.
    pub fn calibration_type_decoded(&self) -> Option<CalibrationStatusType> {
        CalibrationStatusType::from_raw(self.calibration_type())
    }

    /// Calibration success: failed, succeeded with an accuracy estimate, or without one.
    pub fn success_decoded(&self) -> CalibrationSuccess {
        CalibrationSuccess::decode(self.success())
    }
}

impl CalibrationStatusRepr {
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
