// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.16, Calibration run parameters (6 bytes).
//!
//! The data message the host sends right after StartClbRun (6.4.6); its 6 bytes do not
//! influence 2D-2T calibration and may be any, e.g. zeros.

use crate::error::Result;
use crate::payload::codec::{self, Table};
use crate::payload::{check_size, FieldInfo, FieldKind, Value};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 6;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Reserved, `reserved[6]`.
    pub const RESERVED: Field = 0..6;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Reserved, `reserved[6]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 6]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 1] = [info::RESERVED];

/// Table 6.16, Calibration run parameters: a zero-copy view over a payload.
///
/// [`CalibrationRunParameters::new_checked`] checks the size once; the accessors never
/// panic, even on a view made by [`CalibrationRunParameters::new_unchecked`] over a short
/// buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationRunParameters<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationRunParameters<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationRunParameters<T> {
        CalibrationRunParameters { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<CalibrationRunParameters<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(CalibrationRunParameters { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Reserved, `reserved[6]`.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationRunParameters<T> {
    /// Sets [`Self::reserved`] (bytes kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 6]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }
}

/// Table 6.16, Calibration run parameters: the payload as a value, with raw field values.
///
/// [`CalibrationRunParametersRepr::parse`] and [`CalibrationRunParametersRepr::build`] are
/// exact inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same
/// bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CalibrationRunParametersRepr {
    /// Reserved, `reserved[6]`.
    pub reserved: [u8; 6],
}

impl CalibrationRunParametersRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<CalibrationRunParametersRepr> {
        let view = CalibrationRunParameters::new_checked(data)?;
        Ok(CalibrationRunParametersRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(
        view: &CalibrationRunParameters<T>,
    ) -> CalibrationRunParametersRepr {
        CalibrationRunParametersRepr {
            reserved: wire::array(view.as_bytes(), field::RESERVED),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`CalibrationRunParametersRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationRunParametersRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut CalibrationRunParameters::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut CalibrationRunParameters<T>) {
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`CalibrationRunParametersRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 1] {
        [Value::Bytes(&self.reserved)]
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
            0 => self.reserved = info::RESERVED.array(value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }
}

impl Table for CalibrationRunParametersRepr {
    fn validate(&self) -> Result<()> {
        CalibrationRunParametersRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationRunParametersRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationRunParametersRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        CalibrationRunParametersRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        CalibrationRunParametersRepr::set_value(self, index, value)
    }
}
