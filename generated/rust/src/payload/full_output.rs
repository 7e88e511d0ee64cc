// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.4, Full Output Data (34 bytes).
//!
//! Output block after AHRScont1 / AHRSreq1.

use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Scale, Unit, Value};
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
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_X: Field = 6..8;
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_Y: Field = 8..10;
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_Z: Field = 10..12;
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_X: Field = 12..14;
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_Y: Field = 14..16;
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_Z: Field = 16..18;
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_X: Field = 18..20;
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_Y: Field = 20..22;
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_Z: Field = 22..24;
    /// Reserved, `reserved[4]`.
    pub const RESERVED: Field = 24..28;
    /// USW, `u16`.
    pub const USW: Field = 28..30;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: Field = 30..32;
    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UTERMO: Field = 32..34;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Heading, `u16`, raw x 1 / 100 = degrees.
    pub const HEADING: FieldInfo = FieldInfo {
        icd_name: "Heading",
        min: 0.0,
        max: 35999.0,
        scale: Some(Scale::fixed(1, 100)),
        unit: Some(Unit::Deg),
        doc: "Heading angle.",
        ..FieldInfo::new("heading", field::HEADING, FieldKind::Unsigned)
    };

    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: FieldInfo = FieldInfo {
        icd_name: "Pitch",
        min: -9000.0,
        max: 9000.0,
        scale: Some(Scale::fixed(1, 100)),
        unit: Some(Unit::Deg),
        doc: "Pitch angle.",
        ..FieldInfo::new("pitch", field::PITCH, FieldKind::Signed)
    };

    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: FieldInfo = FieldInfo {
        icd_name: "Roll",
        min: -18000.0,
        max: 18000.0,
        scale: Some(Scale::fixed(1, 100)),
        unit: Some(Unit::Deg),
        doc: "Roll angle.",
        ..FieldInfo::new("roll", field::ROLL, FieldKind::Signed)
    };

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_X: FieldInfo = FieldInfo {
        icd_name: "Ugyro",
        unit: Some(Unit::Adc),
        doc: "Raw gyro X sensor data.",
        ..FieldInfo::new("ugyro_x", field::UGYRO_X, FieldKind::Signed)
    };

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_Y: FieldInfo = FieldInfo {
        icd_name: "Ugyro",
        unit: Some(Unit::Adc),
        doc: "Raw gyro Y sensor data.",
        ..FieldInfo::new("ugyro_y", field::UGYRO_Y, FieldKind::Signed)
    };

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_Z: FieldInfo = FieldInfo {
        icd_name: "Ugyro",
        unit: Some(Unit::Adc),
        doc: "Raw gyro Z sensor data.",
        ..FieldInfo::new("ugyro_z", field::UGYRO_Z, FieldKind::Signed)
    };

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_X: FieldInfo = FieldInfo {
        icd_name: "Uacc",
        unit: Some(Unit::Adc),
        doc: "Raw accelerometer X sensor data.",
        ..FieldInfo::new("uacc_x", field::UACC_X, FieldKind::Signed)
    };

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_Y: FieldInfo = FieldInfo {
        icd_name: "Uacc",
        unit: Some(Unit::Adc),
        doc: "Raw accelerometer Y sensor data.",
        ..FieldInfo::new("uacc_y", field::UACC_Y, FieldKind::Signed)
    };

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_Z: FieldInfo = FieldInfo {
        icd_name: "Uacc",
        unit: Some(Unit::Adc),
        doc: "Raw accelerometer Z sensor data.",
        ..FieldInfo::new("uacc_z", field::UACC_Z, FieldKind::Signed)
    };

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_X: FieldInfo = FieldInfo {
        icd_name: "Umag",
        unit: Some(Unit::Adc),
        doc: "Raw magnetometer X sensor data.",
        ..FieldInfo::new("umag_x", field::UMAG_X, FieldKind::Signed)
    };

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_Y: FieldInfo = FieldInfo {
        icd_name: "Umag",
        unit: Some(Unit::Adc),
        doc: "Raw magnetometer Y sensor data.",
        ..FieldInfo::new("umag_y", field::UMAG_Y, FieldKind::Signed)
    };

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_Z: FieldInfo = FieldInfo {
        icd_name: "Umag",
        unit: Some(Unit::Adc),
        doc: "Raw magnetometer Z sensor data.",
        ..FieldInfo::new("umag_z", field::UMAG_Z, FieldKind::Signed)
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 4]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        icd_name: "USW",
        encoding: Some(Encoding::Usw),
        doc: "Unit Status Word (section 6.5).",
        ..FieldInfo::new("usw", field::USW, FieldKind::Unsigned)
    };

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: FieldInfo = FieldInfo {
        icd_name: "Vdd",
        scale: Some(Scale::fixed(1, 1000)),
        unit: Some(Unit::V),
        doc: "Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which.",
        ..FieldInfo::new("vdd", field::VDD, FieldKind::Unsigned)
    };

    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UTERMO: FieldInfo = FieldInfo {
        icd_name: "Utermo",
        unit: Some(Unit::Adc),
        doc: "ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does not say which.",
        ..FieldInfo::new("utermo", field::UTERMO, FieldKind::Signed)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 16] = [
    info::HEADING,
    info::PITCH,
    info::ROLL,
    info::UGYRO_X,
    info::UGYRO_Y,
    info::UGYRO_Z,
    info::UACC_X,
    info::UACC_Y,
    info::UACC_Z,
    info::UMAG_X,
    info::UMAG_Y,
    info::UMAG_Z,
    info::RESERVED,
    info::USW,
    info::VDD,
    info::UTERMO,
];

payload_table! {
    /// Table 6.4, Full Output Data: a zero-copy view over a payload.
    ///
    /// \[`FullOutput::new_checked`\] checks the size once; the accessors never panic, even
    /// on a view made by \[`FullOutput::new_unchecked`\] over a short buffer (missing bytes
    /// read as zero).
    view FullOutput;
    /// Table 6.4, Full Output Data: the payload as a value, with raw field values.
    ///
    /// \[`FullOutputRepr::parse`\] and \[`FullOutputRepr::build`\] are exact inverses:
    /// every byte string of \[`SIZE`\] bytes parses, and builds back to the same bytes when
    /// its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr FullOutputRepr;
    count 16;
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
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro X sensor
    /// data.
    3 number ugyro_x set_ugyro_x UGYRO_X: i16;
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Y sensor
    /// data.
    4 number ugyro_y set_ugyro_y UGYRO_Y: i16;
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Z sensor
    /// data.
    5 number ugyro_z set_ugyro_z UGYRO_Z: i16;
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer X
    /// sensor data.
    6 number uacc_x set_uacc_x UACC_X: i16;
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Y
    /// sensor data.
    7 number uacc_y set_uacc_y UACC_Y: i16;
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Z
    /// sensor data.
    8 number uacc_z set_uacc_z UACC_Z: i16;
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer X
    /// sensor data.
    9 number umag_x set_umag_x UMAG_X: i16;
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Y
    /// sensor data.
    10 number umag_y set_umag_y UMAG_Y: i16;
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Z
    /// sensor data.
    11 number umag_z set_umag_z UMAG_Z: i16;
    /// Reserved, `reserved\[4\]`:
    12 reserved reserved set_reserved RESERVED: [u8; 4];
    /// USW, `u16`: Unit Status Word (section 6.5).
    13 number usw set_usw USW: u16;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: Combined voltage: successive frames carry the
    /// AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note
    /// 2). The frame does not say which.
    14 number vdd set_vdd VDD: u16,
        /// Vdd (volts DC): Combined voltage: successive frames carry the AHRS input voltage
        /// and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame
        /// does not say which.
        in vdd_v set_vdd_v;
    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD): ADC code of one of 7
    /// temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does
    /// not say which.
    15 number utermo set_utermo UTERMO: i16;
}

impl<T: AsRef<[u8]>> FullOutput<T> {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl FullOutputRepr {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}
