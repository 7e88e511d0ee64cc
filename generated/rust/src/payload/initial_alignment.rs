// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.8, Initial alignment data (50 bytes, E21).
//!
//! Sent once when initial alignment completes, before continuous / on-request output or a
//! calibration run starts (6.3.1 - 6.3.3, 6.4). Note the ICD order: heading, roll, pitch.

use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Unit};
use crate::status::StatusWord;

/// Size of the payload (bytes).
pub const SIZE: usize = 50;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_X: Field = 0..4;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Y: Field = 4..8;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Z: Field = 8..12;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_X: Field = 12..16;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Y: Field = 16..20;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Z: Field = 20..24;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_X: Field = 24..28;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Y: Field = 28..32;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Z: Field = 32..36;
    /// Initial Heading, `f32`, degrees.
    pub const INITIAL_HEADING: Field = 36..40;
    /// Initial Roll, `f32`, degrees.
    pub const INITIAL_ROLL: Field = 40..44;
    /// Initial Pitch, `f32`, degrees.
    pub const INITIAL_PITCH: Field = 44..48;
    /// USW, `u16`.
    pub const USW: Field = 48..50;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_X: FieldInfo = FieldInfo {
        icd_name: "Gyros bias",
        unit: Some(Unit::Adc),
        doc: "Gyro X bias.",
        ..FieldInfo::new("gyro_bias_x", field::GYRO_BIAS_X, FieldKind::Float)
    };

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Y: FieldInfo = FieldInfo {
        icd_name: "Gyros bias",
        unit: Some(Unit::Adc),
        doc: "Gyro Y bias.",
        ..FieldInfo::new("gyro_bias_y", field::GYRO_BIAS_Y, FieldKind::Float)
    };

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Z: FieldInfo = FieldInfo {
        icd_name: "Gyros bias",
        unit: Some(Unit::Adc),
        doc: "Gyro Z bias.",
        ..FieldInfo::new("gyro_bias_z", field::GYRO_BIAS_Z, FieldKind::Float)
    };

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_X: FieldInfo = FieldInfo {
        icd_name: "Average acceleration",
        unit: Some(Unit::Adc),
        doc: "Average acceleration along X.",
        ..FieldInfo::new("average_acc_x", field::AVERAGE_ACC_X, FieldKind::Float)
    };

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Y: FieldInfo = FieldInfo {
        icd_name: "Average acceleration",
        unit: Some(Unit::Adc),
        doc: "Average acceleration along Y.",
        ..FieldInfo::new("average_acc_y", field::AVERAGE_ACC_Y, FieldKind::Float)
    };

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Z: FieldInfo = FieldInfo {
        icd_name: "Average acceleration",
        unit: Some(Unit::Adc),
        doc: "Average acceleration along Z.",
        ..FieldInfo::new("average_acc_z", field::AVERAGE_ACC_Z, FieldKind::Float)
    };

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_X: FieldInfo = FieldInfo {
        icd_name: "Average magn. field",
        unit: Some(Unit::Adc),
        doc: "Average magnetic field along X.",
        ..FieldInfo::new("average_mag_x", field::AVERAGE_MAG_X, FieldKind::Float)
    };

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Y: FieldInfo = FieldInfo {
        icd_name: "Average magn. field",
        unit: Some(Unit::Adc),
        doc: "Average magnetic field along Y.",
        ..FieldInfo::new("average_mag_y", field::AVERAGE_MAG_Y, FieldKind::Float)
    };

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Z: FieldInfo = FieldInfo {
        icd_name: "Average magn. field",
        unit: Some(Unit::Adc),
        doc: "Average magnetic field along Z.",
        ..FieldInfo::new("average_mag_z", field::AVERAGE_MAG_Z, FieldKind::Float)
    };

    /// Initial Heading, `f32`, degrees.
    pub const INITIAL_HEADING: FieldInfo = FieldInfo {
        icd_name: "Initial Heading",
        min: 0.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Heading at the end of alignment.",
        ..FieldInfo::new("initial_heading", field::INITIAL_HEADING, FieldKind::Float)
    };

    /// Initial Roll, `f32`, degrees.
    pub const INITIAL_ROLL: FieldInfo = FieldInfo {
        icd_name: "Initial Roll",
        min: -180.0,
        max: 180.0,
        unit: Some(Unit::Deg),
        doc: "Roll at the end of alignment.",
        ..FieldInfo::new("initial_roll", field::INITIAL_ROLL, FieldKind::Float)
    };

    /// Initial Pitch, `f32`, degrees.
    pub const INITIAL_PITCH: FieldInfo = FieldInfo {
        icd_name: "Initial Pitch",
        min: -90.0,
        max: 90.0,
        unit: Some(Unit::Deg),
        doc: "Pitch at the end of alignment.",
        ..FieldInfo::new("initial_pitch", field::INITIAL_PITCH, FieldKind::Float)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        icd_name: "USW",
        encoding: Some(Encoding::Usw),
        doc: "Unit Status Word: 0 after a successful alignment, non-zero otherwise.",
        ..FieldInfo::new("usw", field::USW, FieldKind::Unsigned)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 13] = [
    info::GYRO_BIAS_X,
    info::GYRO_BIAS_Y,
    info::GYRO_BIAS_Z,
    info::AVERAGE_ACC_X,
    info::AVERAGE_ACC_Y,
    info::AVERAGE_ACC_Z,
    info::AVERAGE_MAG_X,
    info::AVERAGE_MAG_Y,
    info::AVERAGE_MAG_Z,
    info::INITIAL_HEADING,
    info::INITIAL_ROLL,
    info::INITIAL_PITCH,
    info::USW,
];

payload_table! {
    /// Table 6.8, Initial alignment data: a zero-copy view over a payload.
    ///
    /// \[`InitialAlignment::new_checked`\] checks the size once; the accessors never panic,
    /// even on a view made by \[`InitialAlignment::new_unchecked`\] over a short buffer
    /// (missing bytes read as zero).
    view InitialAlignment;
    /// Table 6.8, Initial alignment data: the payload as a value, with raw field values.
    ///
    /// \[`InitialAlignmentRepr::parse`\] and \[`InitialAlignmentRepr::build`\] are exact
    /// inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the same
    /// bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr InitialAlignmentRepr;
    count 13;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro X bias.
    0 number gyro_bias_x set_gyro_bias_x GYRO_BIAS_X: f32;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro Y bias.
    1 number gyro_bias_y set_gyro_bias_y GYRO_BIAS_Y: f32;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro Z bias.
    2 number gyro_bias_z set_gyro_bias_z GYRO_BIAS_Z: f32;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along X.
    3 number average_acc_x set_average_acc_x AVERAGE_ACC_X: f32;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along Y.
    4 number average_acc_y set_average_acc_y AVERAGE_ACC_Y: f32;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along Z.
    5 number average_acc_z set_average_acc_z AVERAGE_ACC_Z: f32;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along X.
    6 number average_mag_x set_average_mag_x AVERAGE_MAG_X: f32;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along Y.
    7 number average_mag_y set_average_mag_y AVERAGE_MAG_Y: f32;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along Z.
    8 number average_mag_z set_average_mag_z AVERAGE_MAG_Z: f32;
    /// Initial Heading, `f32`, degrees: Heading at the end of alignment.
    9 number initial_heading set_initial_heading INITIAL_HEADING: f32;
    /// Initial Roll, `f32`, degrees: Roll at the end of alignment.
    10 number initial_roll set_initial_roll INITIAL_ROLL: f32;
    /// Initial Pitch, `f32`, degrees: Pitch at the end of alignment.
    11 number initial_pitch set_initial_pitch INITIAL_PITCH: f32;
    /// USW, `u16`: Unit Status Word: 0 after a successful alignment, non-zero otherwise.
    12 number usw set_usw USW: u16;
}

impl<T: AsRef<[u8]>> InitialAlignment<T> {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl InitialAlignmentRepr {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}
