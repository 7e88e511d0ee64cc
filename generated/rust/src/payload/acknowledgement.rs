// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement (2 bytes).
//!
//! The checksum of the message the AHRS received (E12).

use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, FieldInfo, FieldKind, Value};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 2;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Check sum, `u16`.
    pub const CHECKSUM: Field = 0..2;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Check sum, `u16`.
    pub const CHECKSUM: FieldInfo = FieldInfo {
        icd_name: "Check sum",
        doc: "Checksum of the acknowledged message, message type through payload.",
        ..FieldInfo::new("checksum", field::CHECKSUM, FieldKind::Unsigned)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 1] = [info::CHECKSUM];

/// 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement: a zero-copy view over a
/// payload.
///
/// [`Acknowledgement::new_checked`] checks the size once; the accessors never panic, even
/// on a view made by [`Acknowledgement::new_unchecked`] over a short buffer (missing bytes
/// read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Acknowledgement<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> Acknowledgement<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> Acknowledgement<T> {
        Acknowledgement { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<Acknowledgement<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(Acknowledgement { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Check sum, `u16`: Checksum of the acknowledged message, message type through
    /// payload.
    pub fn checksum(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::CHECKSUM)
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> Acknowledgement<T> {
    /// Sets [`Self::checksum`] (raw, unchecked: [`AcknowledgementRepr::build`] checks ranges).
    pub fn set_checksum(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::CHECKSUM, value);
    }
}

/// 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement: the payload as a value, with
/// raw field values.
///
/// [`AcknowledgementRepr::parse`] and [`AcknowledgementRepr::build`] are exact inverses:
/// every byte string of [`SIZE`] bytes parses, and builds back to the same bytes when its
/// values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AcknowledgementRepr {
    /// Check sum, `u16`: Checksum of the acknowledged message, message type through
    /// payload.
    pub checksum: u16,
}

impl AcknowledgementRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<AcknowledgementRepr> {
        let view = Acknowledgement::new_checked(data)?;
        Ok(AcknowledgementRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &Acknowledgement<T>) -> AcknowledgementRepr {
        AcknowledgementRepr {
            checksum: view.checksum(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`AcknowledgementRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`AcknowledgementRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut Acknowledgement::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut Acknowledgement<T>) {
        view.set_checksum(self.checksum);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`AcknowledgementRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 1] {
        [Raw::value(self.checksum)]
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
            0 => self.checksum = Raw::from_value(&info::CHECKSUM, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }
}

impl Table for AcknowledgementRepr {
    fn validate(&self) -> Result<()> {
        AcknowledgementRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        AcknowledgementRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        AcknowledgementRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        AcknowledgementRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        AcknowledgementRepr::set_value(self, index, value)
    }
}
