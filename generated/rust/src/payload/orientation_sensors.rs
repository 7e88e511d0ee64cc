// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.6, Orientation + Sensor Outputs (34 bytes).
//!
//! Output block after AHRScont3 / AHRSreq3 (the default format, section 6.2).

use crate::payload::codec::payload_table;
use crate::payload::{FieldInfo, FieldKind, Scale, Unit};
use crate::status::StatusWord;
use crate::variant::VariantParameter;

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
    /// GyroX, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_X: Field = 6..8;
    /// GyroY, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Y: Field = 8..10;
    /// GyroZ, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Z: Field = 10..12;
    /// AccX, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_X: Field = 12..14;
    /// AccY, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Y: Field = 14..16;
    /// AccZ, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Z: Field = 16..18;
    /// MagX, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_X: Field = 18..20;
    /// MagY, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Y: Field = 20..22;
    /// MagZ, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Z: Field = 22..24;
    /// Reserved, `reserved[4]`.
    pub const RESERVED: Field = 24..28;
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

    /// GyroX, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_X: FieldInfo = FieldInfo {
        icd_name: "GyroX",
        scale: Some(Scale::by(1, VariantParameter::Kg)),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about X (lateral axis).",
        ..FieldInfo::new("gyro_x", field::GYRO_X, FieldKind::Signed)
    };

    /// GyroY, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Y: FieldInfo = FieldInfo {
        icd_name: "GyroY",
        scale: Some(Scale::by(1, VariantParameter::Kg)),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about Y (longitudinal axis).",
        ..FieldInfo::new("gyro_y", field::GYRO_Y, FieldKind::Signed)
    };

    /// GyroZ, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Z: FieldInfo = FieldInfo {
        icd_name: "GyroZ",
        scale: Some(Scale::by(1, VariantParameter::Kg)),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about Z (vertical axis).",
        ..FieldInfo::new("gyro_z", field::GYRO_Z, FieldKind::Signed)
    };

    /// AccX, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_X: FieldInfo = FieldInfo {
        icd_name: "AccX",
        scale: Some(Scale::by(1, VariantParameter::Ka)),
        unit: Some(Unit::G),
        doc: "Linear acceleration along X.",
        ..FieldInfo::new("acc_x", field::ACC_X, FieldKind::Signed)
    };

    /// AccY, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Y: FieldInfo = FieldInfo {
        icd_name: "AccY",
        scale: Some(Scale::by(1, VariantParameter::Ka)),
        unit: Some(Unit::G),
        doc: "Linear acceleration along Y.",
        ..FieldInfo::new("acc_y", field::ACC_Y, FieldKind::Signed)
    };

    /// AccZ, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Z: FieldInfo = FieldInfo {
        icd_name: "AccZ",
        scale: Some(Scale::by(1, VariantParameter::Ka)),
        unit: Some(Unit::G),
        doc: "Linear acceleration along Z.",
        ..FieldInfo::new("acc_z", field::ACC_Z, FieldKind::Signed)
    };

    /// MagX, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_X: FieldInfo = FieldInfo {
        icd_name: "MagX",
        scale: Some(Scale::fixed(10, 1)),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along X.",
        ..FieldInfo::new("mag_x", field::MAG_X, FieldKind::Signed)
    };

    /// MagY, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Y: FieldInfo = FieldInfo {
        icd_name: "MagY",
        scale: Some(Scale::fixed(10, 1)),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along Y.",
        ..FieldInfo::new("mag_y", field::MAG_Y, FieldKind::Signed)
    };

    /// MagZ, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Z: FieldInfo = FieldInfo {
        icd_name: "MagZ",
        scale: Some(Scale::fixed(10, 1)),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along Z.",
        ..FieldInfo::new("mag_z", field::MAG_Z, FieldKind::Signed)
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED: FieldInfo = crate::payload::full_output::info::RESERVED;

    /// USW, `u16`.
    pub const USW: FieldInfo = crate::payload::full_output::info::USW;

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: FieldInfo = crate::payload::quaternion::info::VDD;

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: FieldInfo = crate::payload::quaternion::info::UTERMO;
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 16] = [
    info::HEADING,
    info::PITCH,
    info::ROLL,
    info::GYRO_X,
    info::GYRO_Y,
    info::GYRO_Z,
    info::ACC_X,
    info::ACC_Y,
    info::ACC_Z,
    info::MAG_X,
    info::MAG_Y,
    info::MAG_Z,
    info::RESERVED,
    info::USW,
    info::VDD,
    info::UTERMO,
];

payload_table! {
    /// Table 6.6, Orientation + Sensor Outputs: a zero-copy view over a payload.
    ///
    /// \[`OrientationSensors::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`OrientationSensors::new_unchecked`\] over a short
    /// buffer (missing bytes read as zero).
    view OrientationSensors;
    /// Table 6.6, Orientation + Sensor Outputs: the payload as a value, with raw field
    /// values.
    ///
    /// \[`OrientationSensorsRepr::parse`\] and \[`OrientationSensorsRepr::build`\] are
    /// exact inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the
    /// same bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr OrientationSensorsRepr;
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
    /// GyroX, `s16`, raw x 1 / KG = degrees per second: Angular rate about X (lateral
    /// axis).
    3 number gyro_x set_gyro_x GYRO_X: i16,
        /// GyroX (degrees per second) for the device `variant`: Angular rate about X
        /// (lateral axis).
        in gyro_x_dps set_gyro_x_dps by variant;
    /// GyroY, `s16`, raw x 1 / KG = degrees per second: Angular rate about Y (longitudinal
    /// axis).
    4 number gyro_y set_gyro_y GYRO_Y: i16,
        /// GyroY (degrees per second) for the device `variant`: Angular rate about Y
        /// (longitudinal axis).
        in gyro_y_dps set_gyro_y_dps by variant;
    /// GyroZ, `s16`, raw x 1 / KG = degrees per second: Angular rate about Z (vertical
    /// axis).
    5 number gyro_z set_gyro_z GYRO_Z: i16,
        /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z
        /// (vertical axis).
        in gyro_z_dps set_gyro_z_dps by variant;
    /// AccX, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along X.
    6 number acc_x set_acc_x ACC_X: i16,
        /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
        in acc_x_g set_acc_x_g by variant;
    /// AccY, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Y.
    7 number acc_y set_acc_y ACC_Y: i16,
        /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
        in acc_y_g set_acc_y_g by variant;
    /// AccZ, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Z.
    8 number acc_z set_acc_z ACC_Z: i16,
        /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
        in acc_z_g set_acc_z_g by variant;
    /// MagX, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along X.
    9 number mag_x set_mag_x MAG_X: i16,
        /// MagX (nanotesla): Magnetic field along X.
        in mag_x_nt set_mag_x_nt;
    /// MagY, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Y.
    10 number mag_y set_mag_y MAG_Y: i16,
        /// MagY (nanotesla): Magnetic field along Y.
        in mag_y_nt set_mag_y_nt;
    /// MagZ, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Z.
    11 number mag_z set_mag_z MAG_Z: i16,
        /// MagZ (nanotesla): Magnetic field along Z.
        in mag_z_nt set_mag_z_nt;
    /// Reserved, `reserved\[4\]`:
    12 reserved reserved set_reserved RESERVED: [u8; 4];
    /// USW, `u16`: Unit Status Word (section 6.5).
    13 number usw set_usw USW: u16;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    14 number vdd set_vdd VDD: u16,
        /// Vdd (volts DC): AHRS input voltage.
        in vdd_v set_vdd_v;
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3
    /// accelerometers.
    15 number utermo set_utermo UTERMO: i16,
        /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
        in utermo_degc set_utermo_degc;
}

impl<T: AsRef<[u8]>> OrientationSensors<T> {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl OrientationSensorsRepr {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}
