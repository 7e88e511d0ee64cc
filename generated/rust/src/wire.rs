// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Byte-level helpers: fixed-size reads and writes at a field's position that cannot panic,
//! whatever the buffer. Multi-byte values are little-endian (the spec's `byte_order`).

use core::ops::Range;

/// A field's position in a message: a range of byte offsets (bytes).
pub type Field = Range<usize>;

/// The `N` bytes at `field`, or zeros when the buffer does not hold them.
pub(crate) fn array<const N: usize>(data: &[u8], field: Field) -> [u8; N] {
    match data.get(field) {
        Some(bytes) => <[u8; N]>::try_from(bytes).unwrap_or([0; N]),
        None => [0; N],
    }
}

/// The bytes at `field`, or none when the buffer does not hold them.
pub(crate) fn bytes(data: &[u8], field: Field) -> &[u8] {
    data.get(field).unwrap_or(&[])
}

/// Writes `value` at `field`; does nothing when the buffer does not hold the field.
pub(crate) fn put(data: &mut [u8], field: Field, value: &[u8]) {
    if let Some(out) = data.get_mut(field) {
        if out.len() == value.len() {
            for (slot, byte) in out.iter_mut().zip(value) {
                *slot = *byte;
            }
        }
    }
}

/// `data` without its trailing NUL bytes.
pub(crate) fn trim_nul(data: &[u8]) -> &[u8] {
    let mut end = data.len();
    while end > 0 && data.get(end - 1) == Some(&0) {
        end -= 1;
    }
    data.get(..end).unwrap_or(&[])
}

/// A `u8` at `field` (0 when absent).
pub(crate) fn get_u8(data: &[u8], field: Field) -> u8 {
    u8::from_le_bytes(array(data, field))
}

/// Writes a `u8` at `field`.
pub(crate) fn set_u8(data: &mut [u8], field: Field, value: u8) {
    put(data, field, &value.to_le_bytes());
}

/// A `u16` at `field` (0 when absent).
pub(crate) fn get_u16(data: &[u8], field: Field) -> u16 {
    u16::from_le_bytes(array(data, field))
}

/// Writes a `u16` at `field`.
pub(crate) fn set_u16(data: &mut [u8], field: Field, value: u16) {
    put(data, field, &value.to_le_bytes());
}

/// A `i16` at `field` (0 when absent).
pub(crate) fn get_i16(data: &[u8], field: Field) -> i16 {
    i16::from_le_bytes(array(data, field))
}

/// Writes a `i16` at `field`.
pub(crate) fn set_i16(data: &mut [u8], field: Field, value: i16) {
    put(data, field, &value.to_le_bytes());
}

/// A `u32` at `field` (0 when absent).
pub(crate) fn get_u32(data: &[u8], field: Field) -> u32 {
    u32::from_le_bytes(array(data, field))
}

/// Writes a `u32` at `field`.
pub(crate) fn set_u32(data: &mut [u8], field: Field, value: u32) {
    put(data, field, &value.to_le_bytes());
}

/// An `f32` at `field` (0.0 when absent); every bit pattern, NaNs included, is kept.
pub(crate) fn get_f32(data: &[u8], field: Field) -> f32 {
    f32::from_bits(get_u32(data, field))
}

/// Writes an `f32` at `field`, bit for bit.
pub(crate) fn set_f32(data: &mut [u8], field: Field, value: f32) {
    set_u32(data, field, value.to_bits());
}

/// Writes `value` at `field`, padded with NUL bytes; does nothing if it is longer than the field.
pub(crate) fn set_padded(data: &mut [u8], field: Field, value: &[u8]) {
    if let Some(out) = data.get_mut(field) {
        if value.len() <= out.len() {
            let mut source = value.iter();
            for slot in out.iter_mut() {
                *slot = source.next().copied().unwrap_or(0);
            }
        }
    }
}

/// `value` rounded half away from zero, or `None` if it is not finite or beyond +-9e18.
pub(crate) fn round_half_away(value: f64) -> Option<i64> {
    if !(value > -9.0e18 && value < 9.0e18) {
        return None;
    }
    let truncated = value as i64;
    let fraction = value - truncated as f64;
    if fraction >= 0.5 {
        Some(truncated + 1)
    } else if fraction <= -0.5 {
        Some(truncated - 1)
    } else {
        Some(truncated)
    }
}
