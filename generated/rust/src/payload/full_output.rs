// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.4, Full Output Data (34 bytes).
//!
//! Output block after AHRScont1 / AHRSreq1.

use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Scale, Unit, Value};
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

/// Table 6.4, Full Output Data: a zero-copy view over a payload.
///
/// [`FullOutput::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`FullOutput::new_unchecked`] over a short buffer (missing bytes read as
/// zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FullOutput<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> FullOutput<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> FullOutput<T> {
        FullOutput { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
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
        wire::get(self.buffer.as_ref(), field::HEADING)
    }

    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub fn pitch(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::PITCH)
    }

    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub fn roll(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::ROLL)
    }

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro X sensor
    /// data.
    pub fn ugyro_x(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UGYRO_X)
    }

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Y sensor
    /// data.
    pub fn ugyro_y(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UGYRO_Y)
    }

    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Z sensor
    /// data.
    pub fn ugyro_z(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UGYRO_Z)
    }

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer X
    /// sensor data.
    pub fn uacc_x(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UACC_X)
    }

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Y
    /// sensor data.
    pub fn uacc_y(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UACC_Y)
    }

    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Z
    /// sensor data.
    pub fn uacc_z(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UACC_Z)
    }

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer X
    /// sensor data.
    pub fn umag_x(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UMAG_X)
    }

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Y
    /// sensor data.
    pub fn umag_y(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UMAG_Y)
    }

    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Z
    /// sensor data.
    pub fn umag_z(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UMAG_Z)
    }

    /// Reserved, `reserved[4]`.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::USW)
    }

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: Combined voltage: successive frames carry the
    /// AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note
    /// 2). The frame does not say which.
    pub fn vdd(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::VDD)
    }

    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD): ADC code of one of 7
    /// temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does
    /// not say which.
    pub fn utermo(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UTERMO)
    }

    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        info::HEADING.scaled(f64::from(self.heading()), None)
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        info::PITCH.scaled(f64::from(self.pitch()), None)
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        info::ROLL.scaled(f64::from(self.roll()), None)
    }

    /// Vdd (volts DC): Combined voltage: successive frames carry the AHRS input voltage and
    /// the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not
    /// say which.
    pub fn vdd_v(&self) -> f64 {
        info::VDD.scaled(f64::from(self.vdd()), None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> FullOutput<T> {
    /// Sets [`Self::heading`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_heading(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::HEADING, value);
    }

    /// Sets [`Self::pitch`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_pitch(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::PITCH, value);
    }

    /// Sets [`Self::roll`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_roll(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::ROLL, value);
    }

    /// Sets [`Self::ugyro_x`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_ugyro_x(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UGYRO_X, value);
    }

    /// Sets [`Self::ugyro_y`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_ugyro_y(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UGYRO_Y, value);
    }

    /// Sets [`Self::ugyro_z`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_ugyro_z(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UGYRO_Z, value);
    }

    /// Sets [`Self::uacc_x`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_uacc_x(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UACC_X, value);
    }

    /// Sets [`Self::uacc_y`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_uacc_y(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UACC_Y, value);
    }

    /// Sets [`Self::uacc_z`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_uacc_z(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UACC_Z, value);
    }

    /// Sets [`Self::umag_x`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_umag_x(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UMAG_X, value);
    }

    /// Sets [`Self::umag_y`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_umag_y(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UMAG_Y, value);
    }

    /// Sets [`Self::umag_z`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_umag_z(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UMAG_Z, value);
    }

    /// Sets [`Self::reserved`] (bytes kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 4]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets [`Self::usw`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::USW, value);
    }

    /// Sets [`Self::vdd`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_vdd(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::VDD, value);
    }

    /// Sets [`Self::utermo`] (raw, unchecked: [`FullOutputRepr::build`] checks ranges).
    pub fn set_utermo(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UTERMO, value);
    }
}

/// Table 6.4, Full Output Data: the payload as a value, with raw field values.
///
/// [`FullOutputRepr::parse`] and [`FullOutputRepr::build`] are exact inverses: every byte
/// string of [`SIZE`] bytes parses, and builds back to the same bytes when its values are
/// in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FullOutputRepr {
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub heading: u16,
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub pitch: i16,
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub roll: i16,
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro X sensor
    /// data.
    pub ugyro_x: i16,
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Y sensor
    /// data.
    pub ugyro_y: i16,
    /// Ugyro, `s16`, ADC codes (no physical scale given by the ICD): Raw gyro Z sensor
    /// data.
    pub ugyro_z: i16,
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer X
    /// sensor data.
    pub uacc_x: i16,
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Y
    /// sensor data.
    pub uacc_y: i16,
    /// Uacc, `s16`, ADC codes (no physical scale given by the ICD): Raw accelerometer Z
    /// sensor data.
    pub uacc_z: i16,
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer X
    /// sensor data.
    pub umag_x: i16,
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Y
    /// sensor data.
    pub umag_y: i16,
    /// Umag, `s16`, ADC codes (no physical scale given by the ICD): Raw magnetometer Z
    /// sensor data.
    pub umag_z: i16,
    /// Reserved, `reserved[4]`.
    pub reserved: [u8; 4],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: Combined voltage: successive frames carry the
    /// AHRS input voltage and the stabilised sensor supply voltage in turn (Table 6.4 note
    /// 2). The frame does not say which.
    pub vdd: u16,
    /// Utermo, `s16`, ADC codes (no physical scale given by the ICD): ADC code of one of 7
    /// temperature sensors, in turn in successive frames (Table 6.4 note 3). The frame does
    /// not say which.
    pub utermo: i16,
}

impl FullOutputRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
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

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`FullOutputRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`FullOutputRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
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

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`FullOutputRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 16] {
        [
            Raw::value(self.heading),
            Raw::value(self.pitch),
            Raw::value(self.roll),
            Raw::value(self.ugyro_x),
            Raw::value(self.ugyro_y),
            Raw::value(self.ugyro_z),
            Raw::value(self.uacc_x),
            Raw::value(self.uacc_y),
            Raw::value(self.uacc_z),
            Raw::value(self.umag_x),
            Raw::value(self.umag_y),
            Raw::value(self.umag_z),
            Value::Bytes(&self.reserved),
            Raw::value(self.usw),
            Raw::value(self.vdd),
            Raw::value(self.utermo),
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
            0 => self.heading = Raw::from_value(&info::HEADING, value)?,
            1 => self.pitch = Raw::from_value(&info::PITCH, value)?,
            2 => self.roll = Raw::from_value(&info::ROLL, value)?,
            3 => self.ugyro_x = Raw::from_value(&info::UGYRO_X, value)?,
            4 => self.ugyro_y = Raw::from_value(&info::UGYRO_Y, value)?,
            5 => self.ugyro_z = Raw::from_value(&info::UGYRO_Z, value)?,
            6 => self.uacc_x = Raw::from_value(&info::UACC_X, value)?,
            7 => self.uacc_y = Raw::from_value(&info::UACC_Y, value)?,
            8 => self.uacc_z = Raw::from_value(&info::UACC_Z, value)?,
            9 => self.umag_x = Raw::from_value(&info::UMAG_X, value)?,
            10 => self.umag_y = Raw::from_value(&info::UMAG_Y, value)?,
            11 => self.umag_z = Raw::from_value(&info::UMAG_Z, value)?,
            12 => self.reserved = info::RESERVED.array(value)?,
            13 => self.usw = Raw::from_value(&info::USW, value)?,
            14 => self.vdd = Raw::from_value(&info::VDD, value)?,
            15 => self.utermo = Raw::from_value(&info::UTERMO, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        info::HEADING.scaled(f64::from(self.heading), None)
    }

    /// Sets [`Self::heading`] from an engineering value (see
    /// [`Self::heading_deg`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_heading_deg(&mut self, value: f64) -> Result<()> {
        info::HEADING.set_scaled(&mut self.heading, value, None)
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        info::PITCH.scaled(f64::from(self.pitch), None)
    }

    /// Sets [`Self::pitch`] from an engineering value (see
    /// [`Self::pitch_deg`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_pitch_deg(&mut self, value: f64) -> Result<()> {
        info::PITCH.set_scaled(&mut self.pitch, value, None)
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        info::ROLL.scaled(f64::from(self.roll), None)
    }

    /// Sets [`Self::roll`] from an engineering value (see
    /// [`Self::roll_deg`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_roll_deg(&mut self, value: f64) -> Result<()> {
        info::ROLL.set_scaled(&mut self.roll, value, None)
    }

    /// Vdd (volts DC): Combined voltage: successive frames carry the AHRS input voltage and
    /// the stabilised sensor supply voltage in turn (Table 6.4 note 2). The frame does not
    /// say which.
    pub fn vdd_v(&self) -> f64 {
        info::VDD.scaled(f64::from(self.vdd), None)
    }

    /// Sets [`Self::vdd`] from an engineering value (see
    /// [`Self::vdd_v`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_vdd_v(&mut self, value: f64) -> Result<()> {
        info::VDD.set_scaled(&mut self.vdd, value, None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}

impl Table for FullOutputRepr {
    fn validate(&self) -> Result<()> {
        FullOutputRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        FullOutputRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        FullOutputRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        FullOutputRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        FullOutputRepr::set_value(self, index, value)
    }
}
