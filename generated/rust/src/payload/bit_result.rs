// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.12, Built-in test answer (4 bytes).
//!
//! The AHRS answer to GetBIT (6.3.11).

use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Scale, Unit, Value};
use crate::status::StatusWord;
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 4;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius.
    pub const UTERMO100: Field = 0..2;
    /// USW, `u16`.
    pub const USW: Field = 2..4;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius.
    pub const UTERMO100: FieldInfo = FieldInfo {
        icd_name: "Utermo100",
        scale: Some(Scale::fixed(1, 100)),
        unit: Some(Unit::Degc),
        doc: "AHRS temperature in 1/100 degC.",
        ..FieldInfo::new("utermo100", field::UTERMO100, FieldKind::Signed)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        icd_name: "USW",
        encoding: Some(Encoding::Usw),
        doc: "Unit Status Word (section 6.5).",
        ..FieldInfo::new("usw", field::USW, FieldKind::Unsigned)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 2] = [info::UTERMO100, info::USW];

/// Table 6.12, Built-in test answer: a zero-copy view over a payload.
///
/// [`BitResult::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`BitResult::new_unchecked`] over a short buffer (missing bytes read as
/// zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BitResult<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> BitResult<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> BitResult<T> {
        BitResult { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<BitResult<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(BitResult { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius: AHRS temperature in 1/100 degC.
    pub fn utermo100(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UTERMO100)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::USW)
    }

    /// Utermo100 (degrees Celsius): AHRS temperature in 1/100 degC.
    pub fn utermo100_degc(&self) -> f64 {
        info::UTERMO100.scaled(f64::from(self.utermo100()), None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> BitResult<T> {
    /// Sets [`Self::utermo100`] (raw, unchecked: [`BitResultRepr::build`] checks ranges).
    pub fn set_utermo100(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UTERMO100, value);
    }

    /// Sets [`Self::usw`] (raw, unchecked: [`BitResultRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::USW, value);
    }
}

/// Table 6.12, Built-in test answer: the payload as a value, with raw field values.
///
/// [`BitResultRepr::parse`] and [`BitResultRepr::build`] are exact inverses: every byte
/// string of [`SIZE`] bytes parses, and builds back to the same bytes when its values are
/// in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BitResultRepr {
    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius: AHRS temperature in 1/100 degC.
    pub utermo100: i16,
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
}

impl BitResultRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<BitResultRepr> {
        let view = BitResult::new_checked(data)?;
        Ok(BitResultRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &BitResult<T>) -> BitResultRepr {
        BitResultRepr {
            utermo100: view.utermo100(),
            usw: view.usw(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`BitResultRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`BitResultRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut BitResult::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut BitResult<T>) {
        view.set_utermo100(self.utermo100);
        view.set_usw(self.usw);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`BitResultRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 2] {
        [Raw::value(self.utermo100), Raw::value(self.usw)]
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
            0 => self.utermo100 = Raw::from_value(&info::UTERMO100, value)?,
            1 => self.usw = Raw::from_value(&info::USW, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Utermo100 (degrees Celsius): AHRS temperature in 1/100 degC.
    pub fn utermo100_degc(&self) -> f64 {
        info::UTERMO100.scaled(f64::from(self.utermo100), None)
    }

    /// Sets [`Self::utermo100`] from an engineering value (see
    /// [`Self::utermo100_degc`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_utermo100_degc(&mut self, value: f64) -> Result<()> {
        info::UTERMO100.set_scaled(&mut self.utermo100, value, None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}

impl Table for BitResultRepr {
    fn validate(&self) -> Result<()> {
        BitResultRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        BitResultRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        BitResultRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        BitResultRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        BitResultRepr::set_value(self, index, value)
    }
}
