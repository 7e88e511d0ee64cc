// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.11, Firmware version (50 bytes).
//!
//! The AHRS answer to GetVerFirmware (6.3.10).

use crate::error::Result;
use crate::payload::codec::{self, Table};
use crate::payload::{check_size, FieldInfo, FieldKind, Value};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 50;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Firmware version, `char[50]`.
    pub const VERSION: Field = 0..50;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Firmware version, `char[50]`.
    pub const VERSION: FieldInfo = FieldInfo {
        icd_name: "Firmware version",
        doc: "Firmware version text, NUL-padded.",
        ..FieldInfo::new("version", field::VERSION, FieldKind::Char)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 1] = [info::VERSION];

/// Table 6.11, Firmware version: a zero-copy view over a payload.
///
/// [`FirmwareVersion::new_checked`] checks the size once; the accessors never panic, even
/// on a view made by [`FirmwareVersion::new_unchecked`] over a short buffer (missing bytes
/// read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FirmwareVersion<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> FirmwareVersion<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> FirmwareVersion<T> {
        FirmwareVersion { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<FirmwareVersion<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(FirmwareVersion { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Firmware version, `char[50]`: Firmware version text, NUL-padded.
    ///
    /// The bytes up to the trailing NULs (Latin-1).
    pub fn version(&self) -> &[u8] {
        wire::trim_nul(wire::bytes(self.buffer.as_ref(), field::VERSION))
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> FirmwareVersion<T> {
    /// Sets [`Self::version`]: `value` padded with NULs. Error:
    /// `out_of_range` when longer than the field.
    pub fn set_version(&mut self, value: &[u8]) -> Result<()> {
        info::VERSION.check(Value::Bytes(value))?;
        wire::set_padded(self.buffer.as_mut(), field::VERSION, value);
        Ok(())
    }
}

/// Table 6.11, Firmware version: the payload as a value, with raw field values.
///
/// [`FirmwareVersionRepr::parse`] and [`FirmwareVersionRepr::build`] are exact inverses:
/// every byte string of [`SIZE`] bytes parses, and builds back to the same bytes when its
/// values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FirmwareVersionRepr {
    /// Firmware version, `char[50]`: Firmware version text, NUL-padded.
    pub version: [u8; 50],
}

impl FirmwareVersionRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<FirmwareVersionRepr> {
        let view = FirmwareVersion::new_checked(data)?;
        Ok(FirmwareVersionRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &FirmwareVersion<T>) -> FirmwareVersionRepr {
        FirmwareVersionRepr {
            version: wire::array(view.as_bytes(), field::VERSION),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`FirmwareVersionRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`FirmwareVersionRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut FirmwareVersion::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut FirmwareVersion<T>) {
        wire::put(view.buffer.as_mut(), field::VERSION, &self.version);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`FirmwareVersionRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 1] {
        [Value::Bytes(wire::trim_nul(&self.version))]
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
            0 => self.version = info::VERSION.array(value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Firmware version: the bytes up to the trailing NULs (Latin-1).
    pub fn version_text(&self) -> &[u8] {
        wire::trim_nul(&self.version)
    }

    /// Sets Firmware version: `value` padded with NULs. Error: `out_of_range` when longer
    /// than 50 bytes.
    pub fn set_version_text(&mut self, value: &[u8]) -> Result<()> {
        self.version = info::VERSION.array(Value::Bytes(value))?;
        Ok(())
    }
}

impl Table for FirmwareVersionRepr {
    fn validate(&self) -> Result<()> {
        FirmwareVersionRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        FirmwareVersionRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        FirmwareVersionRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        FirmwareVersionRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        FirmwareVersionRepr::set_value(self, index, value)
    }
}

impl Default for FirmwareVersionRepr {
    /// Every field at its default: otherwise zero.
    fn default() -> FirmwareVersionRepr {
        FirmwareVersionRepr { version: [0; 50] }
    }
}
