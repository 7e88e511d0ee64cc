// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.15, 2D-2T calibration run result (30 bytes).
//!
//! Sent after each run of a 2D-2T calibration (6.4.5).

use crate::encoding::CalibrationSuccess;
use crate::encoding::CalibrationType;
use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Unit, Value};
use crate::status::StatusWord;

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

payload_table! {
    /// Table 6.15, 2D-2T calibration run result: a zero-copy view over a payload.
    ///
    /// \[`CalibrationRunResult::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`CalibrationRunResult::new_unchecked`\] over a short
    /// buffer (missing bytes read as zero).
    view CalibrationRunResult;
    /// Table 6.15, 2D-2T calibration run result: the payload as a value, with raw field
    /// values.
    ///
    /// \[`CalibrationRunResultRepr::parse`\] and \[`CalibrationRunResultRepr::build`\] are
    /// exact inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the
    /// same bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq)]
    repr CalibrationRunResultRepr;
    count 9;
    /// Type of calibration, `u8`: 2 for 2D-2T calibration.
    0 number calibration_type set_calibration_type CALIBRATION_TYPE: u8;
    /// Calibration run, `u8`: Number of this run (1, 2, ...).
    1 number run set_run RUN: u8;
    /// Percent of used data points, `u8`, percent: Percent of data points used.
    2 number data_used set_data_used DATA_USED: u8;
    /// Calibration success, `u8`: 0: run not successful (excluded); 1..254: predicted
    /// heading error in deg*10; 255: successful without an estimate.
    3 number success set_success SUCCESS: u8;
    /// Reserved, `reserved\[4\]`:
    4 reserved reserved_1 set_reserved_1 RESERVED_1: [u8; 4];
    /// Average pitch, deg, `f32`, degrees: Average pitch during the run.
    5 number average_pitch set_average_pitch AVERAGE_PITCH: f32;
    /// Average roll, deg, `f32`, degrees: Average roll during the run.
    6 number average_roll set_average_roll AVERAGE_ROLL: f32;
    /// Reserved, `reserved\[12\]`:
    7 reserved reserved_2 set_reserved_2 RESERVED_2: [u8; 12];
    /// USW, `u16`: Unit Status Word (section 6.5).
    8 number usw set_usw USW: u16;
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

impl<T: AsRef<[u8]>> CalibrationRunResult<T> {
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

impl CalibrationRunResultRepr {
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
