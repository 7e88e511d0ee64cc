// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.5, Quaternion of Orientation (34 bytes).
//!
//! Output block after AHRScont2 / AHRSreq2.

use crate::payload::codec::payload_table;
use crate::payload::{FieldInfo, FieldKind, Scale, Unit, Value};
use crate::status::StatusWord;

/// Size of the payload (bytes).
pub const SIZE: usize = 34;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Heading, `u16`, raw x 1 / 100 = degrees.
    pub const HEADING: Field = 0..2;
    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: Field = 2..4;
    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: Field = 4..6;
    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK0: Field = 6..8;
    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK1: Field = 8..10;
    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK2: Field = 10..12;
    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK3: Field = 12..14;
    /// Reserved, `reserved[14]`.
    pub const RESERVED: Field = 14..28;
    /// USW, `u16`.
    pub const USW: Field = 28..30;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: Field = 30..32;
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: Field = 32..34;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Heading, `u16`, raw x 1 / 100 = degrees.
    pub const HEADING: FieldInfo = crate::payload::full_output::info::HEADING;

    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: FieldInfo = crate::payload::full_output::info::PITCH;

    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: FieldInfo = crate::payload::full_output::info::ROLL;

    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK0: FieldInfo = FieldInfo {
        icd_name: "Lk0",
        min: -10000.0,
        max: 10000.0,
        scale: Some(Scale::fixed(1, 10000)),
        unit: Some(Unit::One),
        doc: "Quaternion of orientation, scalar component.",
        ..FieldInfo::new("lk0", field::LK0, FieldKind::Signed)
    };

    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK1: FieldInfo = FieldInfo {
        icd_name: "Lk1",
        min: -10000.0,
        max: 10000.0,
        scale: Some(Scale::fixed(1, 10000)),
        unit: Some(Unit::One),
        doc: "Quaternion of orientation, first vector component.",
        ..FieldInfo::new("lk1", field::LK1, FieldKind::Signed)
    };

    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK2: FieldInfo = FieldInfo {
        icd_name: "Lk2",
        min: -10000.0,
        max: 10000.0,
        scale: Some(Scale::fixed(1, 10000)),
        unit: Some(Unit::One),
        doc: "Quaternion of orientation, second vector component.",
        ..FieldInfo::new("lk2", field::LK2, FieldKind::Signed)
    };

    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK3: FieldInfo = FieldInfo {
        icd_name: "Lk3",
        min: -10000.0,
        max: 10000.0,
        scale: Some(Scale::fixed(1, 10000)),
        unit: Some(Unit::One),
        doc: "Quaternion of orientation, third vector component.",
        ..FieldInfo::new("lk3", field::LK3, FieldKind::Signed)
    };

    /// Reserved, `reserved[14]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 14]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = crate::payload::full_output::info::USW;

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: FieldInfo = FieldInfo {
        icd_name: "Vdd",
        scale: Some(Scale::fixed(1, 1000)),
        unit: Some(Unit::V),
        doc: "AHRS input voltage.",
        ..FieldInfo::new("vdd", field::VDD, FieldKind::Unsigned)
    };

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: FieldInfo = FieldInfo {
        icd_name: "Utermo",
        scale: Some(Scale::fixed(1, 10)),
        unit: Some(Unit::Degc),
        doc: "Average temperature of the 3 accelerometers.",
        ..FieldInfo::new("utermo", field::UTERMO, FieldKind::Signed)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 11] = [
    info::HEADING,
    info::PITCH,
    info::ROLL,
    info::LK0,
    info::LK1,
    info::LK2,
    info::LK3,
    info::RESERVED,
    info::USW,
    info::VDD,
    info::UTERMO,
];

payload_table! {
    /// Table 6.5, Quaternion of Orientation: a zero-copy view over a payload.
    ///
    /// \[`Quaternion::new_checked`\] checks the size once; the accessors never panic, even
    /// on a view made by \[`Quaternion::new_unchecked`\] over a short buffer (missing bytes
    /// read as zero).
    view Quaternion;
    /// Table 6.5, Quaternion of Orientation: the payload as a value, with raw field values.
    ///
    /// \[`QuaternionRepr::parse`\] and \[`QuaternionRepr::build`\] are exact inverses:
    /// every byte string of \[`SIZE`\] bytes parses, and builds back to the same bytes when
    /// its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr QuaternionRepr;
    count 11;
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    0 number heading set_heading HEADING: u16,
        /// Heading (degrees): Heading angle.
        in heading_deg set_heading_deg;
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    1 number pitch set_pitch PITCH: i16,
        /// Pitch (degrees): Pitch angle.
        in pitch_deg set_pitch_deg;
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    2 number roll set_roll ROLL: i16,
        /// Roll (degrees): Roll angle.
        in roll_deg set_roll_deg;
    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, scalar
    /// component.
    3 number lk0 set_lk0 LK0: i16,
        /// Lk0 (dimensionless): Quaternion of orientation, scalar component.
        in lk0_value set_lk0_value;
    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, first vector
    /// component.
    4 number lk1 set_lk1 LK1: i16,
        /// Lk1 (dimensionless): Quaternion of orientation, first vector component.
        in lk1_value set_lk1_value;
    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, second
    /// vector component.
    5 number lk2 set_lk2 LK2: i16,
        /// Lk2 (dimensionless): Quaternion of orientation, second vector component.
        in lk2_value set_lk2_value;
    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, third vector
    /// component.
    6 number lk3 set_lk3 LK3: i16,
        /// Lk3 (dimensionless): Quaternion of orientation, third vector component.
        in lk3_value set_lk3_value;
    /// Reserved, `reserved\[14\]`:
    7 reserved reserved set_reserved RESERVED: [u8; 14];
    /// USW, `u16`: Unit Status Word (section 6.5).
    8 number usw set_usw USW: u16;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    9 number vdd set_vdd VDD: u16,
        /// Vdd (volts DC): AHRS input voltage.
        in vdd_v set_vdd_v;
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3
    /// accelerometers.
    10 number utermo set_utermo UTERMO: i16,
        /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
        in utermo_degc set_utermo_degc;
}

impl<T: AsRef<[u8]>> Quaternion<T> {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl QuaternionRepr {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}
