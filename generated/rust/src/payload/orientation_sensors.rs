// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.6, Orientation + Sensor Outputs (34 bytes).
//!
//! Output block after AHRScont3 / AHRSreq3 (the default format, section 6.2).

use crate::error::{Error, ErrorKind, Result};
use crate::frame::{FrameRepr, MessageType};
use crate::payload::{check_size, Value};
use crate::status::StatusWord;
use crate::variant::Variant;
use crate::wire;

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
    use super::field;
    use crate::payload::{FieldInfo, FieldKind, Value};

    /// Heading, `u16`, raw x 1 / 100 = degrees.
    pub const HEADING: FieldInfo = FieldInfo {
        name: "heading",
        icd_name: "Heading",
        offset: field::HEADING.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 35999.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(100),
        }),
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Heading angle.",
    };

    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: FieldInfo = FieldInfo {
        name: "pitch",
        icd_name: "Pitch",
        offset: field::PITCH.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -9000.0,
        max: 9000.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(100),
        }),
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Pitch angle.",
    };

    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: FieldInfo = FieldInfo {
        name: "roll",
        icd_name: "Roll",
        offset: field::ROLL.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -18000.0,
        max: 18000.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(100),
        }),
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Roll angle.",
    };

    /// GyroX, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_X: FieldInfo = FieldInfo {
        name: "gyro_x",
        icd_name: "GyroX",
        offset: field::GYRO_X.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Parameter(crate::variant::VariantParameter::Kg),
        }),
        unit: Some(crate::payload::Unit::DegPerS),
        encoding: None,
        doc: "Angular rate about X (lateral axis).",
    };

    /// GyroY, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Y: FieldInfo = FieldInfo {
        name: "gyro_y",
        icd_name: "GyroY",
        offset: field::GYRO_Y.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Parameter(crate::variant::VariantParameter::Kg),
        }),
        unit: Some(crate::payload::Unit::DegPerS),
        encoding: None,
        doc: "Angular rate about Y (longitudinal axis).",
    };

    /// GyroZ, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Z: FieldInfo = FieldInfo {
        name: "gyro_z",
        icd_name: "GyroZ",
        offset: field::GYRO_Z.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Parameter(crate::variant::VariantParameter::Kg),
        }),
        unit: Some(crate::payload::Unit::DegPerS),
        encoding: None,
        doc: "Angular rate about Z (vertical axis).",
    };

    /// AccX, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_X: FieldInfo = FieldInfo {
        name: "acc_x",
        icd_name: "AccX",
        offset: field::ACC_X.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Parameter(crate::variant::VariantParameter::Ka),
        }),
        unit: Some(crate::payload::Unit::G),
        encoding: None,
        doc: "Linear acceleration along X.",
    };

    /// AccY, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Y: FieldInfo = FieldInfo {
        name: "acc_y",
        icd_name: "AccY",
        offset: field::ACC_Y.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Parameter(crate::variant::VariantParameter::Ka),
        }),
        unit: Some(crate::payload::Unit::G),
        encoding: None,
        doc: "Linear acceleration along Y.",
    };

    /// AccZ, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Z: FieldInfo = FieldInfo {
        name: "acc_z",
        icd_name: "AccZ",
        offset: field::ACC_Z.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Parameter(crate::variant::VariantParameter::Ka),
        }),
        unit: Some(crate::payload::Unit::G),
        encoding: None,
        doc: "Linear acceleration along Z.",
    };

    /// MagX, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_X: FieldInfo = FieldInfo {
        name: "mag_x",
        icd_name: "MagX",
        offset: field::MAG_X.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 10,
            divisor: crate::payload::Divisor::Fixed(1),
        }),
        unit: Some(crate::payload::Unit::Nt),
        encoding: None,
        doc: "Magnetic field along X.",
    };

    /// MagY, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Y: FieldInfo = FieldInfo {
        name: "mag_y",
        icd_name: "MagY",
        offset: field::MAG_Y.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 10,
            divisor: crate::payload::Divisor::Fixed(1),
        }),
        unit: Some(crate::payload::Unit::Nt),
        encoding: None,
        doc: "Magnetic field along Y.",
    };

    /// MagZ, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Z: FieldInfo = FieldInfo {
        name: "mag_z",
        icd_name: "MagZ",
        offset: field::MAG_Z.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 10,
            divisor: crate::payload::Divisor::Fixed(1),
        }),
        unit: Some(crate::payload::Unit::Nt),
        encoding: None,
        doc: "Magnetic field along Z.",
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        name: "reserved",
        icd_name: "Reserved",
        offset: field::RESERVED.start,
        size: 4,
        kind: FieldKind::Reserved,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(&[0; 4]),
        scale: None,
        unit: None,
        encoding: None,
        doc: "",
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        name: "usw",
        icd_name: "USW",
        offset: field::USW.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 65535.0,
        default: Value::Int(0),
        scale: None,
        unit: None,
        encoding: Some(crate::payload::Encoding::Usw),
        doc: "Unit Status Word (section 6.5).",
    };

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: FieldInfo = FieldInfo {
        name: "vdd",
        icd_name: "Vdd",
        offset: field::VDD.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 0.0,
        max: 65535.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(1000),
        }),
        unit: Some(crate::payload::Unit::V),
        encoding: None,
        doc: "AHRS input voltage.",
    };

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: FieldInfo = FieldInfo {
        name: "utermo",
        icd_name: "Utermo",
        offset: field::UTERMO.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(10),
        }),
        unit: Some(crate::payload::Unit::Degc),
        encoding: None,
        doc: "Average temperature of the 3 accelerometers.",
    };
}

/// Every field, in wire order.
pub static FIELDS: [crate::payload::FieldInfo; 16] = [
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

/// Table 6.6, Orientation + Sensor Outputs: a zero-copy view over a payload.
///
/// [`OrientationSensors::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`OrientationSensors::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OrientationSensors<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> OrientationSensors<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> OrientationSensors<T> {
        OrientationSensors { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<OrientationSensors<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(OrientationSensors { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub fn heading(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::HEADING)
    }

    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        f64::from(self.heading()) / 100.0
    }

    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub fn pitch(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::PITCH)
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        f64::from(self.pitch()) / 100.0
    }

    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub fn roll(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::ROLL)
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        f64::from(self.roll()) / 100.0
    }

    /// GyroX, `s16`, raw x 1 / KG = degrees per second: Angular rate about X (lateral axis).
    pub fn gyro_x(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::GYRO_X)
    }

    /// GyroX (degrees per second) for the device `variant`: Angular rate about X (lateral axis).
    pub fn gyro_x_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_x()) / f64::from(variant.kg())
    }

    /// GyroY, `s16`, raw x 1 / KG = degrees per second: Angular rate about Y (longitudinal axis).
    pub fn gyro_y(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::GYRO_Y)
    }

    /// GyroY (degrees per second) for the device `variant`: Angular rate about Y (longitudinal axis).
    pub fn gyro_y_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_y()) / f64::from(variant.kg())
    }

    /// GyroZ, `s16`, raw x 1 / KG = degrees per second: Angular rate about Z (vertical axis).
    pub fn gyro_z(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::GYRO_Z)
    }

    /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z (vertical axis).
    pub fn gyro_z_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_z()) / f64::from(variant.kg())
    }

    /// AccX, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along X.
    pub fn acc_x(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::ACC_X)
    }

    /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
    pub fn acc_x_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_x()) / f64::from(variant.ka())
    }

    /// AccY, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Y.
    pub fn acc_y(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::ACC_Y)
    }

    /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
    pub fn acc_y_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_y()) / f64::from(variant.ka())
    }

    /// AccZ, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Z.
    pub fn acc_z(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::ACC_Z)
    }

    /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
    pub fn acc_z_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_z()) / f64::from(variant.ka())
    }

    /// MagX, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along X.
    pub fn mag_x(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::MAG_X)
    }

    /// MagX (nanotesla): Magnetic field along X.
    pub fn mag_x_nt(&self) -> f64 {
        f64::from(self.mag_x()) * 10.0
    }

    /// MagY, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Y.
    pub fn mag_y(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::MAG_Y)
    }

    /// MagY (nanotesla): Magnetic field along Y.
    pub fn mag_y_nt(&self) -> f64 {
        f64::from(self.mag_y()) * 10.0
    }

    /// MagZ, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Z.
    pub fn mag_z(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::MAG_Z)
    }

    /// MagZ (nanotesla): Magnetic field along Z.
    pub fn mag_z_nt(&self) -> f64 {
        f64::from(self.mag_z()) * 10.0
    }

    /// Reserved, `reserved\[4\]`:
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::USW)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub fn vdd(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::VDD)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        f64::from(self.vdd()) / 1000.0
    }

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3 accelerometers.
    pub fn utermo(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UTERMO)
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        f64::from(self.utermo()) / 10.0
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> OrientationSensors<T> {
    /// Sets Heading (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_heading(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::HEADING, value);
    }

    /// Sets Pitch (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_pitch(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::PITCH, value);
    }

    /// Sets Roll (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_roll(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::ROLL, value);
    }

    /// Sets GyroX (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_gyro_x(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::GYRO_X, value);
    }

    /// Sets GyroY (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_gyro_y(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::GYRO_Y, value);
    }

    /// Sets GyroZ (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_gyro_z(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::GYRO_Z, value);
    }

    /// Sets AccX (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_acc_x(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::ACC_X, value);
    }

    /// Sets AccY (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_acc_y(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::ACC_Y, value);
    }

    /// Sets AccZ (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_acc_z(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::ACC_Z, value);
    }

    /// Sets MagX (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_mag_x(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::MAG_X, value);
    }

    /// Sets MagY (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_mag_y(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::MAG_Y, value);
    }

    /// Sets MagZ (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_mag_z(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::MAG_Z, value);
    }

    /// Sets Reserved (4 bytes, kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 4]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets USW (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::USW, value);
    }

    /// Sets Vdd (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_vdd(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::VDD, value);
    }

    /// Sets Utermo (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_utermo(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UTERMO, value);
    }
}

/// Table 6.6, Orientation + Sensor Outputs: the payload as a value, with raw field values.
///
/// [`OrientationSensorsRepr::parse`] and [`OrientationSensorsRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OrientationSensorsRepr {
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub heading: u16,
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub pitch: i16,
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub roll: i16,
    /// GyroX, `s16`, raw x 1 / KG = degrees per second: Angular rate about X (lateral axis).
    pub gyro_x: i16,
    /// GyroY, `s16`, raw x 1 / KG = degrees per second: Angular rate about Y (longitudinal axis).
    pub gyro_y: i16,
    /// GyroZ, `s16`, raw x 1 / KG = degrees per second: Angular rate about Z (vertical axis).
    pub gyro_z: i16,
    /// AccX, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along X.
    pub acc_x: i16,
    /// AccY, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Y.
    pub acc_y: i16,
    /// AccZ, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Z.
    pub acc_z: i16,
    /// MagX, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along X.
    pub mag_x: i16,
    /// MagY, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Y.
    pub mag_y: i16,
    /// MagZ, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Z.
    pub mag_z: i16,
    /// Reserved, `reserved\[4\]`:
    pub reserved: [u8; 4],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub vdd: u16,
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3 accelerometers.
    pub utermo: i16,
}

impl OrientationSensorsRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
    pub fn parse(data: &[u8]) -> Result<OrientationSensorsRepr> {
        let view = OrientationSensors::new_checked(data)?;
        Ok(OrientationSensorsRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &OrientationSensors<T>) -> OrientationSensorsRepr {
        OrientationSensorsRepr {
            heading: view.heading(),
            pitch: view.pitch(),
            roll: view.roll(),
            gyro_x: view.gyro_x(),
            gyro_y: view.gyro_y(),
            gyro_z: view.gyro_z(),
            acc_x: view.acc_x(),
            acc_y: view.acc_y(),
            acc_z: view.acc_z(),
            mag_x: view.mag_x(),
            mag_y: view.mag_y(),
            mag_z: view.mag_z(),
            reserved: wire::array(view.as_bytes(), field::RESERVED),
            usw: view.usw(),
            vdd: view.vdd(),
            utermo: view.utermo(),
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

    /// The size of the payload [`OrientationSensorsRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`OrientationSensorsRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
        self.emit(&mut OrientationSensors::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut OrientationSensors<T>) {
        view.set_heading(self.heading);
        view.set_pitch(self.pitch);
        view.set_roll(self.roll);
        view.set_gyro_x(self.gyro_x);
        view.set_gyro_y(self.gyro_y);
        view.set_gyro_z(self.gyro_z);
        view.set_acc_x(self.acc_x);
        view.set_acc_y(self.acc_y);
        view.set_acc_z(self.acc_z);
        view.set_mag_x(self.mag_x);
        view.set_mag_y(self.mag_y);
        view.set_mag_z(self.mag_z);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
        view.set_usw(self.usw);
        view.set_vdd(self.vdd);
        view.set_utermo(self.utermo);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`OrientationSensorsRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        FrameRepr::new(MessageType::Data, &payload).build(buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 16] {
        [
            Value::Int(i64::from(self.heading)),
            Value::Int(i64::from(self.pitch)),
            Value::Int(i64::from(self.roll)),
            Value::Int(i64::from(self.gyro_x)),
            Value::Int(i64::from(self.gyro_y)),
            Value::Int(i64::from(self.gyro_z)),
            Value::Int(i64::from(self.acc_x)),
            Value::Int(i64::from(self.acc_y)),
            Value::Int(i64::from(self.acc_z)),
            Value::Int(i64::from(self.mag_x)),
            Value::Int(i64::from(self.mag_y)),
            Value::Int(i64::from(self.mag_z)),
            Value::Bytes(&self.reserved),
            Value::Int(i64::from(self.usw)),
            Value::Int(i64::from(self.vdd)),
            Value::Int(i64::from(self.utermo)),
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
            0 => self.heading = info::HEADING.int(value)?,
            1 => self.pitch = info::PITCH.int(value)?,
            2 => self.roll = info::ROLL.int(value)?,
            3 => self.gyro_x = info::GYRO_X.int(value)?,
            4 => self.gyro_y = info::GYRO_Y.int(value)?,
            5 => self.gyro_z = info::GYRO_Z.int(value)?,
            6 => self.acc_x = info::ACC_X.int(value)?,
            7 => self.acc_y = info::ACC_Y.int(value)?,
            8 => self.acc_z = info::ACC_Z.int(value)?,
            9 => self.mag_x = info::MAG_X.int(value)?,
            10 => self.mag_y = info::MAG_Y.int(value)?,
            11 => self.mag_z = info::MAG_Z.int(value)?,
            12 => self.reserved = info::RESERVED.array(value)?,
            13 => self.usw = info::USW.int(value)?,
            14 => self.vdd = info::VDD.int(value)?,
            15 => self.utermo = info::UTERMO.int(value)?,
            _ => return Err(Error::new(ErrorKind::OutOfRange)),
        }
        Ok(())
    }

    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        f64::from(self.heading) / 100.0
    }

    /// Sets Heading from an engineering value (degrees), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_heading_deg(&mut self, value: f64) -> Result<()> {
        let raw = info::HEADING.raw_from(value, None)?;
        self.heading = info::HEADING.int(raw)?;
        Ok(())
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        f64::from(self.pitch) / 100.0
    }

    /// Sets Pitch from an engineering value (degrees), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_pitch_deg(&mut self, value: f64) -> Result<()> {
        let raw = info::PITCH.raw_from(value, None)?;
        self.pitch = info::PITCH.int(raw)?;
        Ok(())
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        f64::from(self.roll) / 100.0
    }

    /// Sets Roll from an engineering value (degrees), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_roll_deg(&mut self, value: f64) -> Result<()> {
        let raw = info::ROLL.raw_from(value, None)?;
        self.roll = info::ROLL.int(raw)?;
        Ok(())
    }

    /// GyroX (degrees per second) for the device `variant`: Angular rate about X (lateral axis).
    pub fn gyro_x_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_x) / f64::from(variant.kg())
    }

    /// Sets GyroX from an engineering value (degrees per second), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_x_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::GYRO_X.raw_from(value, Some(variant))?;
        self.gyro_x = info::GYRO_X.int(raw)?;
        Ok(())
    }

    /// GyroY (degrees per second) for the device `variant`: Angular rate about Y (longitudinal axis).
    pub fn gyro_y_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_y) / f64::from(variant.kg())
    }

    /// Sets GyroY from an engineering value (degrees per second), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_y_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::GYRO_Y.raw_from(value, Some(variant))?;
        self.gyro_y = info::GYRO_Y.int(raw)?;
        Ok(())
    }

    /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z (vertical axis).
    pub fn gyro_z_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_z) / f64::from(variant.kg())
    }

    /// Sets GyroZ from an engineering value (degrees per second), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_z_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::GYRO_Z.raw_from(value, Some(variant))?;
        self.gyro_z = info::GYRO_Z.int(raw)?;
        Ok(())
    }

    /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
    pub fn acc_x_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_x) / f64::from(variant.ka())
    }

    /// Sets AccX from an engineering value (standard gravity), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_x_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::ACC_X.raw_from(value, Some(variant))?;
        self.acc_x = info::ACC_X.int(raw)?;
        Ok(())
    }

    /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
    pub fn acc_y_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_y) / f64::from(variant.ka())
    }

    /// Sets AccY from an engineering value (standard gravity), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_y_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::ACC_Y.raw_from(value, Some(variant))?;
        self.acc_y = info::ACC_Y.int(raw)?;
        Ok(())
    }

    /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
    pub fn acc_z_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_z) / f64::from(variant.ka())
    }

    /// Sets AccZ from an engineering value (standard gravity), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_z_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::ACC_Z.raw_from(value, Some(variant))?;
        self.acc_z = info::ACC_Z.int(raw)?;
        Ok(())
    }

    /// MagX (nanotesla): Magnetic field along X.
    pub fn mag_x_nt(&self) -> f64 {
        f64::from(self.mag_x) * 10.0
    }

    /// Sets MagX from an engineering value (nanotesla), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_mag_x_nt(&mut self, value: f64) -> Result<()> {
        let raw = info::MAG_X.raw_from(value, None)?;
        self.mag_x = info::MAG_X.int(raw)?;
        Ok(())
    }

    /// MagY (nanotesla): Magnetic field along Y.
    pub fn mag_y_nt(&self) -> f64 {
        f64::from(self.mag_y) * 10.0
    }

    /// Sets MagY from an engineering value (nanotesla), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_mag_y_nt(&mut self, value: f64) -> Result<()> {
        let raw = info::MAG_Y.raw_from(value, None)?;
        self.mag_y = info::MAG_Y.int(raw)?;
        Ok(())
    }

    /// MagZ (nanotesla): Magnetic field along Z.
    pub fn mag_z_nt(&self) -> f64 {
        f64::from(self.mag_z) * 10.0
    }

    /// Sets MagZ from an engineering value (nanotesla), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_mag_z_nt(&mut self, value: f64) -> Result<()> {
        let raw = info::MAG_Z.raw_from(value, None)?;
        self.mag_z = info::MAG_Z.int(raw)?;
        Ok(())
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        f64::from(self.vdd) / 1000.0
    }

    /// Sets Vdd from an engineering value (volts DC), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_vdd_v(&mut self, value: f64) -> Result<()> {
        let raw = info::VDD.raw_from(value, None)?;
        self.vdd = info::VDD.int(raw)?;
        Ok(())
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        f64::from(self.utermo) / 10.0
    }

    /// Sets Utermo from an engineering value (degrees Celsius), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_utermo_degc(&mut self, value: f64) -> Result<()> {
        let raw = info::UTERMO.raw_from(value, None)?;
        self.utermo = info::UTERMO.int(raw)?;
        Ok(())
    }
}
