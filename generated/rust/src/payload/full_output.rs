// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.4, Full Output Data (34 bytes).
//!
//! Output block after AHRScont1 / AHRSreq1.

use crate::error::{Error, ErrorKind, Result};
use crate::frame::{FrameRepr, MessageType};
use crate::payload::{check_size, Value};
use crate::status::StatusWord;
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

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_X: FieldInfo = FieldInfo {
        name: "ugyro_x",
        icd_name: "Ugyro",
        offset: field::UGYRO_X.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw gyro X sensor data.",
    };

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_Y: FieldInfo = FieldInfo {
        name: "ugyro_y",
        icd_name: "Ugyro",
        offset: field::UGYRO_Y.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw gyro Y sensor data.",
    };

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UGYRO_Z: FieldInfo = FieldInfo {
        name: "ugyro_z",
        icd_name: "Ugyro",
        offset: field::UGYRO_Z.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw gyro Z sensor data.",
    };

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_X: FieldInfo = FieldInfo {
        name: "uacc_x",
        icd_name: "Uacc",
        offset: field::UACC_X.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw accelerometer X sensor data.",
    };

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_Y: FieldInfo = FieldInfo {
        name: "uacc_y",
        icd_name: "Uacc",
        offset: field::UACC_Y.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw accelerometer Y sensor data.",
    };

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UACC_Z: FieldInfo = FieldInfo {
        name: "uacc_z",
        icd_name: "Uacc",
        offset: field::UACC_Z.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw accelerometer Z sensor data.",
    };

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_X: FieldInfo = FieldInfo {
        name: "umag_x",
        icd_name: "Umag",
        offset: field::UMAG_X.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw magnetometer X sensor data.",
    };

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_Y: FieldInfo = FieldInfo {
        name: "umag_y",
        icd_name: "Umag",
        offset: field::UMAG_Y.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw magnetometer Y sensor data.",
    };

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UMAG_Z: FieldInfo = FieldInfo {
        name: "umag_z",
        icd_name: "Umag",
        offset: field::UMAG_Z.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc: "Raw magnetometer Z sensor data.",
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
        doc:
            "Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which.",
    };

    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD).
    pub const UTERMO: FieldInfo = FieldInfo {
        name: "utermo",
        icd_name: "Utermo",
        offset: field::UTERMO.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -32768.0,
        max: 32767.0,
        default: Value::Int(0),
        scale: None,
        unit: Some(crate::payload::Unit::Adc),
        encoding: None,
        doc:
            "ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does not say which.",
    };
}

/// Every field, in wire order.
pub static FIELDS: [crate::payload::FieldInfo; 16] = [
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

/// Table 6.4, Full Output Data: a zero-copy view over a payload.
///
/// [`FullOutput::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`FullOutput::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FullOutput<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> FullOutput<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> FullOutput<T> {
        FullOutput { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<FullOutput<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(FullOutput { buffer })
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

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro X sensor data.
    pub fn ugyro_x(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UGYRO_X)
    }

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Y sensor data.
    pub fn ugyro_y(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UGYRO_Y)
    }

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Z sensor data.
    pub fn ugyro_z(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UGYRO_Z)
    }

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer X sensor data.
    pub fn uacc_x(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UACC_X)
    }

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Y sensor data.
    pub fn uacc_y(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UACC_Y)
    }

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Z sensor data.
    pub fn uacc_z(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UACC_Z)
    }

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer X sensor data.
    pub fn umag_x(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UMAG_X)
    }

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Y sensor data.
    pub fn umag_y(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UMAG_Y)
    }

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Z sensor data.
    pub fn umag_z(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UMAG_Z)
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

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which.
    pub fn vdd(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::VDD)
    }

    /// Vdd (volts DC): Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which.
    pub fn vdd_v(&self) -> f64 {
        f64::from(self.vdd()) / 1000.0
    }

    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD): ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does not say which.
    pub fn utermo(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::UTERMO)
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> FullOutput<T> {
    /// Sets Heading (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_heading(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::HEADING, value);
    }

    /// Sets Pitch (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_pitch(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::PITCH, value);
    }

    /// Sets Roll (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_roll(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::ROLL, value);
    }

    /// Sets Ugyro (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_ugyro_x(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UGYRO_X, value);
    }

    /// Sets Ugyro (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_ugyro_y(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UGYRO_Y, value);
    }

    /// Sets Ugyro (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_ugyro_z(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UGYRO_Z, value);
    }

    /// Sets Uacc (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_uacc_x(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UACC_X, value);
    }

    /// Sets Uacc (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_uacc_y(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UACC_Y, value);
    }

    /// Sets Uacc (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_uacc_z(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UACC_Z, value);
    }

    /// Sets Umag (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_umag_x(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UMAG_X, value);
    }

    /// Sets Umag (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_umag_y(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UMAG_Y, value);
    }

    /// Sets Umag (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_umag_z(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UMAG_Z, value);
    }

    /// Sets Reserved (4 bytes, kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 4]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets USW (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::USW, value);
    }

    /// Sets Vdd (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_vdd(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::VDD, value);
    }

    /// Sets Utermo (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_utermo(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UTERMO, value);
    }
}

/// Table 6.4, Full Output Data: the payload as a value, with raw field values.
///
/// [`FullOutputRepr::parse`] and [`FullOutputRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FullOutputRepr {
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub heading: u16,
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub pitch: i16,
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub roll: i16,
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro X sensor data.
    pub ugyro_x: i16,
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Y sensor data.
    pub ugyro_y: i16,
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Z sensor data.
    pub ugyro_z: i16,
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer X sensor data.
    pub uacc_x: i16,
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Y sensor data.
    pub uacc_y: i16,
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Z sensor data.
    pub uacc_z: i16,
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer X sensor data.
    pub umag_x: i16,
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Y sensor data.
    pub umag_y: i16,
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Z sensor data.
    pub umag_z: i16,
    /// Reserved, `reserved\[4\]`:
    pub reserved: [u8; 4],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which.
    pub vdd: u16,
    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD): ADC code of one of 7 temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does not say which.
    pub utermo: i16,
}

impl FullOutputRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
    pub fn parse(data: &[u8]) -> Result<FullOutputRepr> {
        let view = FullOutput::new_checked(data)?;
        Ok(FullOutputRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &FullOutput<T>) -> FullOutputRepr {
        FullOutputRepr {
            heading: view.heading(),
            pitch: view.pitch(),
            roll: view.roll(),
            ugyro_x: view.ugyro_x(),
            ugyro_y: view.ugyro_y(),
            ugyro_z: view.ugyro_z(),
            uacc_x: view.uacc_x(),
            uacc_y: view.uacc_y(),
            uacc_z: view.uacc_z(),
            umag_x: view.umag_x(),
            umag_y: view.umag_y(),
            umag_z: view.umag_z(),
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

    /// The size of the payload [`FullOutputRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`FullOutputRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
        self.emit(&mut FullOutput::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut FullOutput<T>) {
        view.set_heading(self.heading);
        view.set_pitch(self.pitch);
        view.set_roll(self.roll);
        view.set_ugyro_x(self.ugyro_x);
        view.set_ugyro_y(self.ugyro_y);
        view.set_ugyro_z(self.ugyro_z);
        view.set_uacc_x(self.uacc_x);
        view.set_uacc_y(self.uacc_y);
        view.set_uacc_z(self.uacc_z);
        view.set_umag_x(self.umag_x);
        view.set_umag_y(self.umag_y);
        view.set_umag_z(self.umag_z);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
        view.set_usw(self.usw);
        view.set_vdd(self.vdd);
        view.set_utermo(self.utermo);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`FullOutputRepr::build`].
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
            Value::Int(i64::from(self.ugyro_x)),
            Value::Int(i64::from(self.ugyro_y)),
            Value::Int(i64::from(self.ugyro_z)),
            Value::Int(i64::from(self.uacc_x)),
            Value::Int(i64::from(self.uacc_y)),
            Value::Int(i64::from(self.uacc_z)),
            Value::Int(i64::from(self.umag_x)),
            Value::Int(i64::from(self.umag_y)),
            Value::Int(i64::from(self.umag_z)),
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
            3 => self.ugyro_x = info::UGYRO_X.int(value)?,
            4 => self.ugyro_y = info::UGYRO_Y.int(value)?,
            5 => self.ugyro_z = info::UGYRO_Z.int(value)?,
            6 => self.uacc_x = info::UACC_X.int(value)?,
            7 => self.uacc_y = info::UACC_Y.int(value)?,
            8 => self.uacc_z = info::UACC_Z.int(value)?,
            9 => self.umag_x = info::UMAG_X.int(value)?,
            10 => self.umag_y = info::UMAG_Y.int(value)?,
            11 => self.umag_z = info::UMAG_Z.int(value)?,
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

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }

    /// Vdd (volts DC): Combined voltage: successive frames carry the AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not say which.
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
}
