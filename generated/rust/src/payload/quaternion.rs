// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.5, Quaternion of Orientation (34 bytes).
//!
//! Output block after AHRScont2 / AHRSreq2.

use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, FieldInfo, FieldKind, Scale, Unit, Value};
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

/// Table 6.5, Quaternion of Orientation: a zero-copy view over a payload.
///
/// [`Quaternion::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`Quaternion::new_unchecked`] over a short buffer (missing bytes read as
/// zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quaternion<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> Quaternion<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> Quaternion<T> {
        Quaternion { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<Quaternion<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(Quaternion { buffer })
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

    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, scalar
    /// component.
    pub fn lk0(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::LK0)
    }

    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, first vector
    /// component.
    pub fn lk1(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::LK1)
    }

    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, second
    /// vector component.
    pub fn lk2(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::LK2)
    }

    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, third vector
    /// component.
    pub fn lk3(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::LK3)
    }

    /// Reserved, `reserved[14]`.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::USW)
    }

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub fn vdd(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::VDD)
    }

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3
    /// accelerometers.
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

    /// Lk0 (dimensionless): Quaternion of orientation, scalar component.
    pub fn lk0_value(&self) -> f64 {
        info::LK0.scaled(f64::from(self.lk0()), None)
    }

    /// Lk1 (dimensionless): Quaternion of orientation, first vector component.
    pub fn lk1_value(&self) -> f64 {
        info::LK1.scaled(f64::from(self.lk1()), None)
    }

    /// Lk2 (dimensionless): Quaternion of orientation, second vector component.
    pub fn lk2_value(&self) -> f64 {
        info::LK2.scaled(f64::from(self.lk2()), None)
    }

    /// Lk3 (dimensionless): Quaternion of orientation, third vector component.
    pub fn lk3_value(&self) -> f64 {
        info::LK3.scaled(f64::from(self.lk3()), None)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        info::VDD.scaled(f64::from(self.vdd()), None)
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        info::UTERMO.scaled(f64::from(self.utermo()), None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> Quaternion<T> {
    /// Sets [`Self::heading`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_heading(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::HEADING, value);
    }

    /// Sets [`Self::pitch`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_pitch(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::PITCH, value);
    }

    /// Sets [`Self::roll`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_roll(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::ROLL, value);
    }

    /// Sets [`Self::lk0`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk0(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::LK0, value);
    }

    /// Sets [`Self::lk1`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk1(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::LK1, value);
    }

    /// Sets [`Self::lk2`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk2(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::LK2, value);
    }

    /// Sets [`Self::lk3`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk3(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::LK3, value);
    }

    /// Sets [`Self::reserved`] (bytes kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 14]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets [`Self::usw`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::USW, value);
    }

    /// Sets [`Self::vdd`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_vdd(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::VDD, value);
    }

    /// Sets [`Self::utermo`] (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_utermo(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UTERMO, value);
    }
}

/// Table 6.5, Quaternion of Orientation: the payload as a value, with raw field values.
///
/// [`QuaternionRepr::parse`] and [`QuaternionRepr::build`] are exact inverses: every byte
/// string of [`SIZE`] bytes parses, and builds back to the same bytes when its values are
/// in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct QuaternionRepr {
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub heading: u16,
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub pitch: i16,
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub roll: i16,
    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, scalar
    /// component.
    pub lk0: i16,
    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, first vector
    /// component.
    pub lk1: i16,
    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, second
    /// vector component.
    pub lk2: i16,
    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, third vector
    /// component.
    pub lk3: i16,
    /// Reserved, `reserved[14]`.
    pub reserved: [u8; 14],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub vdd: u16,
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3
    /// accelerometers.
    pub utermo: i16,
}

impl QuaternionRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<QuaternionRepr> {
        let view = Quaternion::new_checked(data)?;
        Ok(QuaternionRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &Quaternion<T>) -> QuaternionRepr {
        QuaternionRepr {
            heading: view.heading(),
            pitch: view.pitch(),
            roll: view.roll(),
            lk0: view.lk0(),
            lk1: view.lk1(),
            lk2: view.lk2(),
            lk3: view.lk3(),
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

    /// The size of the payload [`QuaternionRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`QuaternionRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut Quaternion::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut Quaternion<T>) {
        view.set_heading(self.heading);
        view.set_pitch(self.pitch);
        view.set_roll(self.roll);
        view.set_lk0(self.lk0);
        view.set_lk1(self.lk1);
        view.set_lk2(self.lk2);
        view.set_lk3(self.lk3);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
        view.set_usw(self.usw);
        view.set_vdd(self.vdd);
        view.set_utermo(self.utermo);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`QuaternionRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 11] {
        [
            Raw::value(self.heading),
            Raw::value(self.pitch),
            Raw::value(self.roll),
            Raw::value(self.lk0),
            Raw::value(self.lk1),
            Raw::value(self.lk2),
            Raw::value(self.lk3),
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
            3 => self.lk0 = Raw::from_value(&info::LK0, value)?,
            4 => self.lk1 = Raw::from_value(&info::LK1, value)?,
            5 => self.lk2 = Raw::from_value(&info::LK2, value)?,
            6 => self.lk3 = Raw::from_value(&info::LK3, value)?,
            7 => self.reserved = info::RESERVED.array(value)?,
            8 => self.usw = Raw::from_value(&info::USW, value)?,
            9 => self.vdd = Raw::from_value(&info::VDD, value)?,
            10 => self.utermo = Raw::from_value(&info::UTERMO, value)?,
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

    /// Lk0 (dimensionless): Quaternion of orientation, scalar component.
    pub fn lk0_value(&self) -> f64 {
        info::LK0.scaled(f64::from(self.lk0), None)
    }

    /// Sets [`Self::lk0`] from an engineering value (see
    /// [`Self::lk0_value`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_lk0_value(&mut self, value: f64) -> Result<()> {
        info::LK0.set_scaled(&mut self.lk0, value, None)
    }

    /// Lk1 (dimensionless): Quaternion of orientation, first vector component.
    pub fn lk1_value(&self) -> f64 {
        info::LK1.scaled(f64::from(self.lk1), None)
    }

    /// Sets [`Self::lk1`] from an engineering value (see
    /// [`Self::lk1_value`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_lk1_value(&mut self, value: f64) -> Result<()> {
        info::LK1.set_scaled(&mut self.lk1, value, None)
    }

    /// Lk2 (dimensionless): Quaternion of orientation, second vector component.
    pub fn lk2_value(&self) -> f64 {
        info::LK2.scaled(f64::from(self.lk2), None)
    }

    /// Sets [`Self::lk2`] from an engineering value (see
    /// [`Self::lk2_value`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_lk2_value(&mut self, value: f64) -> Result<()> {
        info::LK2.set_scaled(&mut self.lk2, value, None)
    }

    /// Lk3 (dimensionless): Quaternion of orientation, third vector component.
    pub fn lk3_value(&self) -> f64 {
        info::LK3.scaled(f64::from(self.lk3), None)
    }

    /// Sets [`Self::lk3`] from an engineering value (see
    /// [`Self::lk3_value`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_lk3_value(&mut self, value: f64) -> Result<()> {
        info::LK3.set_scaled(&mut self.lk3, value, None)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        info::VDD.scaled(f64::from(self.vdd), None)
    }

    /// Sets [`Self::vdd`] from an engineering value (see
    /// [`Self::vdd_v`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_vdd_v(&mut self, value: f64) -> Result<()> {
        info::VDD.set_scaled(&mut self.vdd, value, None)
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        info::UTERMO.scaled(f64::from(self.utermo), None)
    }

    /// Sets [`Self::utermo`] from an engineering value (see
    /// [`Self::utermo_degc`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_utermo_degc(&mut self, value: f64) -> Result<()> {
        info::UTERMO.set_scaled(&mut self.utermo, value, None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}

impl Table for QuaternionRepr {
    fn validate(&self) -> Result<()> {
        QuaternionRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        QuaternionRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        QuaternionRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        QuaternionRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        QuaternionRepr::set_value(self, index, value)
    }
}
