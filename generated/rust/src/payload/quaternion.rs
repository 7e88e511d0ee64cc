// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.5, Quaternion of Orientation (34 bytes).
//!
//! Output block after AHRScont2 / AHRSreq2.

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

    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK0: FieldInfo = FieldInfo {
        name: "lk0",
        icd_name: "Lk0",
        offset: field::LK0.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -10000.0,
        max: 10000.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(10000),
        }),
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Quaternion of orientation, scalar component.",
    };

    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK1: FieldInfo = FieldInfo {
        name: "lk1",
        icd_name: "Lk1",
        offset: field::LK1.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -10000.0,
        max: 10000.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(10000),
        }),
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Quaternion of orientation, first vector component.",
    };

    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK2: FieldInfo = FieldInfo {
        name: "lk2",
        icd_name: "Lk2",
        offset: field::LK2.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -10000.0,
        max: 10000.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(10000),
        }),
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Quaternion of orientation, second vector component.",
    };

    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless.
    pub const LK3: FieldInfo = FieldInfo {
        name: "lk3",
        icd_name: "Lk3",
        offset: field::LK3.start,
        size: 2,
        kind: FieldKind::Signed,
        min: -10000.0,
        max: 10000.0,
        default: Value::Int(0),
        scale: Some(crate::payload::Scale {
            multiplier: 1,
            divisor: crate::payload::Divisor::Fixed(10000),
        }),
        unit: Some(crate::payload::Unit::One),
        encoding: None,
        doc: "Quaternion of orientation, third vector component.",
    };

    /// Reserved, `reserved[14]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        name: "reserved",
        icd_name: "Reserved",
        offset: field::RESERVED.start,
        size: 14,
        kind: FieldKind::Reserved,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(&[0; 14]),
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
pub static FIELDS: [crate::payload::FieldInfo; 11] = [
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
/// view made by [`Quaternion::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quaternion<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> Quaternion<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> Quaternion<T> {
        Quaternion { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
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

    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, scalar component.
    pub fn lk0(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::LK0)
    }

    /// Lk0 (dimensionless): Quaternion of orientation, scalar component.
    pub fn lk0_value(&self) -> f64 {
        f64::from(self.lk0()) / 10000.0
    }

    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, first vector component.
    pub fn lk1(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::LK1)
    }

    /// Lk1 (dimensionless): Quaternion of orientation, first vector component.
    pub fn lk1_value(&self) -> f64 {
        f64::from(self.lk1()) / 10000.0
    }

    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, second vector component.
    pub fn lk2(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::LK2)
    }

    /// Lk2 (dimensionless): Quaternion of orientation, second vector component.
    pub fn lk2_value(&self) -> f64 {
        f64::from(self.lk2()) / 10000.0
    }

    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, third vector component.
    pub fn lk3(&self) -> i16 {
        wire::get_i16(self.buffer.as_ref(), field::LK3)
    }

    /// Lk3 (dimensionless): Quaternion of orientation, third vector component.
    pub fn lk3_value(&self) -> f64 {
        f64::from(self.lk3()) / 10000.0
    }

    /// Reserved, `reserved\[14\]`:
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

impl<T: AsRef<[u8]> + AsMut<[u8]>> Quaternion<T> {
    /// Sets Heading (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_heading(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::HEADING, value);
    }

    /// Sets Pitch (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_pitch(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::PITCH, value);
    }

    /// Sets Roll (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_roll(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::ROLL, value);
    }

    /// Sets Lk0 (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk0(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::LK0, value);
    }

    /// Sets Lk1 (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk1(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::LK1, value);
    }

    /// Sets Lk2 (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk2(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::LK2, value);
    }

    /// Sets Lk3 (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_lk3(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::LK3, value);
    }

    /// Sets Reserved (14 bytes, kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 14]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets USW (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::USW, value);
    }

    /// Sets Vdd (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_vdd(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::VDD, value);
    }

    /// Sets Utermo (raw, unchecked: [`QuaternionRepr::build`] checks ranges).
    pub fn set_utermo(&mut self, value: i16) {
        wire::set_i16(self.buffer.as_mut(), field::UTERMO, value);
    }
}

/// Table 6.5, Quaternion of Orientation: the payload as a value, with raw field values.
///
/// [`QuaternionRepr::parse`] and [`QuaternionRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct QuaternionRepr {
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub heading: u16,
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub pitch: i16,
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub roll: i16,
    /// Lk0, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, scalar component.
    pub lk0: i16,
    /// Lk1, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, first vector component.
    pub lk1: i16,
    /// Lk2, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, second vector component.
    pub lk2: i16,
    /// Lk3, `s16`, raw x 1 / 10000 = dimensionless: Quaternion of orientation, third vector component.
    pub lk3: i16,
    /// Reserved, `reserved\[14\]`:
    pub reserved: [u8; 14],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub vdd: u16,
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3 accelerometers.
    pub utermo: i16,
}

impl QuaternionRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
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

    /// Checks every field in table order, as a builder does; the first bad one is the error:
    /// `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        for (info, value) in FIELDS.iter().zip(self.values()) {
            info.check(value)?;
        }
        Ok(())
    }

    /// The size of the payload [`QuaternionRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`QuaternionRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
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

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`QuaternionRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        FrameRepr::new(MessageType::Data, &payload).build(buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 11] {
        [
            Value::Int(i64::from(self.heading)),
            Value::Int(i64::from(self.pitch)),
            Value::Int(i64::from(self.roll)),
            Value::Int(i64::from(self.lk0)),
            Value::Int(i64::from(self.lk1)),
            Value::Int(i64::from(self.lk2)),
            Value::Int(i64::from(self.lk3)),
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
            3 => self.lk0 = info::LK0.int(value)?,
            4 => self.lk1 = info::LK1.int(value)?,
            5 => self.lk2 = info::LK2.int(value)?,
            6 => self.lk3 = info::LK3.int(value)?,
            7 => self.reserved = info::RESERVED.array(value)?,
            8 => self.usw = info::USW.int(value)?,
            9 => self.vdd = info::VDD.int(value)?,
            10 => self.utermo = info::UTERMO.int(value)?,
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

    /// Lk0 (dimensionless): Quaternion of orientation, scalar component.
    pub fn lk0_value(&self) -> f64 {
        f64::from(self.lk0) / 10000.0
    }

    /// Sets Lk0 from an engineering value (dimensionless), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_lk0_value(&mut self, value: f64) -> Result<()> {
        let raw = info::LK0.raw_from(value, None)?;
        self.lk0 = info::LK0.int(raw)?;
        Ok(())
    }

    /// Lk1 (dimensionless): Quaternion of orientation, first vector component.
    pub fn lk1_value(&self) -> f64 {
        f64::from(self.lk1) / 10000.0
    }

    /// Sets Lk1 from an engineering value (dimensionless), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_lk1_value(&mut self, value: f64) -> Result<()> {
        let raw = info::LK1.raw_from(value, None)?;
        self.lk1 = info::LK1.int(raw)?;
        Ok(())
    }

    /// Lk2 (dimensionless): Quaternion of orientation, second vector component.
    pub fn lk2_value(&self) -> f64 {
        f64::from(self.lk2) / 10000.0
    }

    /// Sets Lk2 from an engineering value (dimensionless), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_lk2_value(&mut self, value: f64) -> Result<()> {
        let raw = info::LK2.raw_from(value, None)?;
        self.lk2 = info::LK2.int(raw)?;
        Ok(())
    }

    /// Lk3 (dimensionless): Quaternion of orientation, third vector component.
    pub fn lk3_value(&self) -> f64 {
        f64::from(self.lk3) / 10000.0
    }

    /// Sets Lk3 from an engineering value (dimensionless), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_lk3_value(&mut self, value: f64) -> Result<()> {
        let raw = info::LK3.raw_from(value, None)?;
        self.lk3 = info::LK3.int(raw)?;
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
