// Copied from generator/targets/rust/runtime/crate/wire.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! Byte-level helpers: fixed-size reads and writes at a field's position that cannot panic,
//! whatever the buffer. Numbers are sent in the spec's `byte_order` ([`crate::BIG_ENDIAN`]).

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

/// The number of type `T` at `field` (0 when the buffer does not hold it).
pub(crate) fn get<T: Number>(data: &[u8], field: Field) -> T {
    T::read(data, field)
}

/// Writes the number `value` at `field`; does nothing when the buffer does not hold the field.
pub(crate) fn set<T: Number>(data: &mut [u8], field: Field, value: T) {
    value.write(data, field);
}

/// A number as it is sent: an integer, or an IEEE 754 float32 kept bit for bit (NaNs included).
pub(crate) trait Number: Copy {
    /// The number at `field` (0 when the buffer does not hold it).
    fn read(data: &[u8], field: Field) -> Self;
    /// Writes the number at `field`; does nothing when the buffer does not hold the field.
    fn write(self, data: &mut [u8], field: Field);
}

/// `bytes` of a little-endian number in the spec's byte order, or the bytes of a number in the
/// spec's byte order as little-endian (the same reordering both ways).
fn spec_order<const N: usize>(mut bytes: [u8; N]) -> [u8; N] {
    if crate::BIG_ENDIAN {
        bytes.reverse();
    }
    bytes
}

impl Number for u8 {
    fn read(data: &[u8], field: Field) -> u8 {
        u8::from_le_bytes(spec_order(array(data, field)))
    }

    fn write(self, data: &mut [u8], field: Field) {
        put(data, field, &spec_order(self.to_le_bytes()));
    }
}

impl Number for i8 {
    fn read(data: &[u8], field: Field) -> i8 {
        i8::from_le_bytes(spec_order(array(data, field)))
    }

    fn write(self, data: &mut [u8], field: Field) {
        put(data, field, &spec_order(self.to_le_bytes()));
    }
}

impl Number for u16 {
    fn read(data: &[u8], field: Field) -> u16 {
        u16::from_le_bytes(spec_order(array(data, field)))
    }

    fn write(self, data: &mut [u8], field: Field) {
        put(data, field, &spec_order(self.to_le_bytes()));
    }
}

impl Number for i16 {
    fn read(data: &[u8], field: Field) -> i16 {
        i16::from_le_bytes(spec_order(array(data, field)))
    }

    fn write(self, data: &mut [u8], field: Field) {
        put(data, field, &spec_order(self.to_le_bytes()));
    }
}

impl Number for u32 {
    fn read(data: &[u8], field: Field) -> u32 {
        u32::from_le_bytes(spec_order(array(data, field)))
    }

    fn write(self, data: &mut [u8], field: Field) {
        put(data, field, &spec_order(self.to_le_bytes()));
    }
}

impl Number for i32 {
    fn read(data: &[u8], field: Field) -> i32 {
        i32::from_le_bytes(spec_order(array(data, field)))
    }

    fn write(self, data: &mut [u8], field: Field) {
        put(data, field, &spec_order(self.to_le_bytes()));
    }
}

impl Number for f32 {
    fn read(data: &[u8], field: Field) -> f32 {
        f32::from_bits(u32::read(data, field))
    }

    fn write(self, data: &mut [u8], field: Field) {
        self.to_bits().write(data, field);
    }
}
