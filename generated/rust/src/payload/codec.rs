// Copied from generator/targets/rust/runtime/crate/payload/codec.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! What every payload table shares: field descriptions ([`FieldInfo`]), raw values
//! ([`Value`]), scales, and the steps every table's view and value type take the same way
//! (checking values in table order, framing a payload), which each table file calls.

use core::ops::Range;

use super::{AnyPayload, Encoding, PayloadKind, Unit};
use crate::error::{Detail, Error, ErrorKind, Float, Result};
use crate::frame::{FrameRepr, MessageType};
use crate::variant::{Variant, VariantParameter};
use crate::wire::{self, Field, Number};

/// The greatest finite float32, as a double.
pub const F32_MAX: f64 = f32::MAX as f64;

/// The least finite float32, as a double.
const F32_LOWEST: f64 = -F32_MAX;

/// How a field's bytes are read (numbers in the spec's byte order).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FieldKind {
    /// An unsigned integer.
    Unsigned,
    /// A two's complement signed integer.
    Signed,
    /// An IEEE 754 float32.
    Float,
    /// Text: Latin-1 bytes padded with NULs.
    Char,
    /// Bytes with no meaning, kept verbatim.
    Reserved,
}

/// The divisor of a scale: a number, or a parameter of the device variant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Divisor {
    /// A fixed divisor.
    Fixed(i32),
    /// A divisor that depends on the device variant.
    Parameter(VariantParameter),
}

/// Engineering value = raw x `multiplier` / `divisor`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Scale {
    /// The multiplier.
    pub multiplier: i32,
    /// The divisor.
    pub divisor: Divisor,
}

impl Scale {
    /// raw x `multiplier` / `divisor`.
    pub(crate) const fn fixed(multiplier: i32, divisor: i32) -> Scale {
        let divisor = Divisor::Fixed(divisor);
        Scale {
            multiplier,
            divisor,
        }
    }

    /// raw x `multiplier` / the value of `parameter` for the device variant.
    pub(crate) const fn by(multiplier: i32, parameter: VariantParameter) -> Scale {
        let divisor = Divisor::Parameter(parameter);
        Scale {
            multiplier,
            divisor,
        }
    }

    /// The divisor for `variant`, or `None` when it depends on the variant and none is given.
    pub const fn divisor(&self, variant: Option<Variant>) -> Option<i32> {
        match (self.divisor, variant) {
            (Divisor::Fixed(divisor), _) => Some(divisor),
            (Divisor::Parameter(parameter), Some(variant)) => Some(variant.parameter(parameter)),
            (Divisor::Parameter(_), None) => None,
        }
    }

    /// The engineering value of `raw` (in the field's unit), or `None` when the divisor needs a
    /// variant and none is given.
    pub fn engineering(&self, raw: f64, variant: Option<Variant>) -> Option<f64> {
        let divisor = self.divisor(variant)?;
        Some(raw * f64::from(self.multiplier) / f64::from(divisor))
    }

    /// The raw value for the engineering value `value`, before rounding, or `None` when the
    /// divisor needs a variant and none is given.
    pub fn raw(&self, value: f64, variant: Option<Variant>) -> Option<f64> {
        let divisor = self.divisor(variant)?;
        Some(value * f64::from(divisor) / f64::from(self.multiplier))
    }
}

/// A raw field value of any type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value<'a> {
    /// An integer field's value.
    Int(i64),
    /// A float field's value (builders take any double and refuse what float32 cannot hold).
    Float(f64),
    /// A char field's bytes (Latin-1, trailing NULs removed) or a reserved field's bytes.
    Bytes(&'a [u8]),
}

/// What a field is: name, position, type, what a builder accepts and how to scale it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldInfo {
    /// The spec's name of the field.
    pub name: &'static str,
    /// The ICD's name of the field.
    pub icd_name: &'static str,
    /// Where the field starts in its payload (bytes).
    pub offset: usize,
    /// The field's size (bytes).
    pub size: usize,
    /// How the field's bytes are read.
    pub kind: FieldKind,
    /// The least raw value a builder accepts (numeric fields).
    pub min: f64,
    /// The greatest raw value a builder accepts (numeric fields).
    pub max: f64,
    /// The value a builder uses when none is given.
    pub default: Value<'static>,
    /// How to turn the raw value into an engineering value, if the field has a scale.
    pub scale: Option<Scale>,
    /// The unit of the engineering value (or of the raw value when there is no scale).
    pub unit: Option<Unit>,
    /// A value encoding the field follows, if any.
    pub encoding: Option<Encoding>,
    /// What the field means.
    pub doc: &'static str,
}

impl FieldInfo {
    /// The field `name` of `kind` at `position`, with nothing else said: the range of its type
    /// (numbers), a zero default, no scale, unit, encoding or doc. Each table starts its fields
    /// from here and fills in what the spec says.
    pub(crate) const fn new(name: &'static str, position: Field, kind: FieldKind) -> FieldInfo {
        let Range { start, end } = position;
        let size = end.saturating_sub(start);
        let (min, max) = match (kind, size) {
            (FieldKind::Unsigned, 1) => (0.0, 255.0),
            (FieldKind::Unsigned, 2) => (0.0, 65535.0),
            (FieldKind::Unsigned, 4) => (0.0, 4294967295.0),
            (FieldKind::Signed, 1) => (-128.0, 127.0),
            (FieldKind::Signed, 2) => (-32768.0, 32767.0),
            (FieldKind::Signed, 4) => (-2147483648.0, 2147483647.0),
            (FieldKind::Float, _) => (F32_LOWEST, F32_MAX),
            _ => (0.0, 0.0),
        };
        let default = match kind {
            FieldKind::Float => Value::Float(0.0),
            FieldKind::Unsigned | FieldKind::Signed => Value::Int(0),
            FieldKind::Char | FieldKind::Reserved => Value::Bytes(&[]),
        };
        FieldInfo {
            name,
            icd_name: "",
            offset: start,
            size,
            kind,
            min,
            max,
            default,
            scale: None,
            unit: None,
            encoding: None,
            doc: "",
        }
    }

    /// The field's position in its payload (byte offsets).
    pub const fn position(&self) -> Field {
        self.offset..self.offset + self.size
    }

    /// The error a builder gives for a bad value of this field.
    pub const fn refuse(&self) -> Error {
        Error::at(ErrorKind::OutOfRange, self.offset).with_field(self.name)
    }

    /// [`FieldInfo::refuse`] with `detail`, where one is known.
    pub fn refuse_because(&self, detail: Option<Detail>) -> Error {
        match detail {
            Some(detail) => self.refuse().with_detail(detail),
            None => self.refuse(),
        }
    }

    /// The error a builder gives for the bad value `value` of this field: [`FieldInfo::refuse`]
    /// with the value and what the field takes.
    pub fn refuse_value(&self, value: Value<'_>) -> Error {
        let detail = match (self.kind, value) {
            (FieldKind::Unsigned | FieldKind::Signed, Value::Int(value)) => Detail::Range {
                value,
                min: self.min as i64,
                max: self.max as i64,
            },
            (FieldKind::Unsigned | FieldKind::Signed, _) => Detail::Expected("an integer"),
            (FieldKind::Float, Value::Int(raw)) => {
                return self.refuse_value(Value::Float(raw as f64))
            }
            (FieldKind::Float, Value::Float(raw)) => {
                let encoding = crate::encoding::refuses(self.encoding, raw);
                match encoding {
                    Some(detail) if (self.min..=self.max).contains(&raw) => detail,
                    _ => Detail::FloatRange {
                        value: Float(raw),
                        min: Float(self.min),
                        max: Float(self.max),
                    },
                }
            }
            (FieldKind::Float, Value::Bytes(_)) => Detail::Expected("a number"),
            (FieldKind::Char, Value::Bytes(text)) => Detail::Limit {
                size: text.len(),
                max: self.size,
            },
            (FieldKind::Char, _) => Detail::Expected("text"),
            (FieldKind::Reserved, Value::Bytes(bytes)) => Detail::Size {
                size: bytes.len(),
                expected: self.size,
            },
            (FieldKind::Reserved, _) => Detail::Expected("bytes"),
        };
        self.refuse().with_detail(detail)
    }

    /// The field's raw value in `payload` (a whole payload of the field's table).
    pub fn read<'a>(&self, payload: &'a [u8]) -> Value<'a> {
        let at = self.position();
        match (self.kind, self.size) {
            (FieldKind::Unsigned, 1) => u8::read(payload, at).value(),
            (FieldKind::Unsigned, 2) => u16::read(payload, at).value(),
            (FieldKind::Unsigned, 4) => u32::read(payload, at).value(),
            (FieldKind::Signed, 1) => i8::read(payload, at).value(),
            (FieldKind::Signed, 2) => i16::read(payload, at).value(),
            (FieldKind::Signed, 4) => i32::read(payload, at).value(),
            (FieldKind::Float, 4) => f32::read(payload, at).value(),
            (FieldKind::Char, _) => Value::Bytes(wire::trim_nul(wire::bytes(payload, at))),
            _ => Value::Bytes(wire::bytes(payload, at)),
        }
    }

    /// Checks `value` the way a builder does: an integer inside the field's range, a finite
    /// float inside its range (and float32), text no longer than the field, reserved bytes of
    /// exactly its size, plus the rules of the field's encoding. Error: `out_of_range` at the
    /// field's offset, naming the field, with the value and what the field takes
    /// ([`FieldInfo::refuse_value`]).
    pub fn check(&self, value: Value<'_>) -> Result<()> {
        let ok = match (self.kind, value) {
            (FieldKind::Unsigned | FieldKind::Signed, Value::Int(raw)) => {
                (self.min..=self.max).contains(&(raw as f64))
            }
            (FieldKind::Float, Value::Float(raw)) => {
                let inside = (self.min..=self.max).contains(&raw);
                let encoding = crate::encoding::refuses(self.encoding, raw);
                raw.is_finite() && inside && encoding.is_none()
            }
            (FieldKind::Float, Value::Int(raw)) => return self.check(Value::Float(raw as f64)),
            (FieldKind::Char, Value::Bytes(text)) => text.len() <= self.size,
            (FieldKind::Reserved, Value::Bytes(bytes)) => bytes.len() == self.size,
            _ => false,
        };
        if ok {
            Ok(())
        } else {
            Err(self.refuse_value(value))
        }
    }

    /// Checks `value` (see [`FieldInfo::check`]) and writes it into `payload`.
    pub fn write(&self, payload: &mut [u8], value: Value<'_>) -> Result<()> {
        self.check(value)?;
        let at = self.position();
        match (self.kind, self.size, value) {
            (FieldKind::Unsigned, 1, _) => u8::from_value(self, value)?.write(payload, at),
            (FieldKind::Unsigned, 2, _) => u16::from_value(self, value)?.write(payload, at),
            (FieldKind::Unsigned, 4, _) => u32::from_value(self, value)?.write(payload, at),
            (FieldKind::Signed, 1, _) => i8::from_value(self, value)?.write(payload, at),
            (FieldKind::Signed, 2, _) => i16::from_value(self, value)?.write(payload, at),
            (FieldKind::Signed, 4, _) => i32::from_value(self, value)?.write(payload, at),
            (FieldKind::Float, 4, _) => f32::from_value(self, value)?.write(payload, at),
            (FieldKind::Char, _, Value::Bytes(text)) => wire::set_padded(payload, at, text),
            (FieldKind::Reserved, _, Value::Bytes(bytes)) => wire::put(payload, at, bytes),
            _ => return Err(self.refuse_value(value)),
        }
        Ok(())
    }

    /// `value` checked and converted to the field's integer type.
    pub fn int<T: TryFrom<i64>>(&self, value: Value<'_>) -> Result<T> {
        self.check(value)?;
        match value {
            Value::Int(raw) => T::try_from(raw).map_err(|_| self.refuse_value(value)),
            _ => Err(self.refuse_value(value)),
        }
    }

    /// `value` checked and converted to float32.
    pub fn float(&self, value: Value<'_>) -> Result<f32> {
        self.check(value)?;
        match value {
            Value::Float(raw) => Ok(raw as f32),
            Value::Int(raw) => Ok(raw as f32),
            Value::Bytes(_) => Err(self.refuse_value(value)),
        }
    }

    /// `value` checked and copied into the field's bytes (text padded with NULs).
    pub fn array<const N: usize>(&self, value: Value<'_>) -> Result<[u8; N]> {
        self.check(value)?;
        match value {
            Value::Bytes(bytes) if bytes.len() <= N => {
                let mut out = [0; N];
                wire::put(&mut out, 0..bytes.len(), bytes);
                Ok(out)
            }
            _ => Err(self.refuse_value(value)),
        }
    }

    /// The raw value for the engineering value `value`: scaled, rounded half away from zero for
    /// integer fields, and checked. Errors: `out_of_range` for a value the field cannot hold
    /// (its detail the raw value and the raw bounds), or a variant-dependent scale without a
    /// variant.
    pub fn raw_from(&self, value: f64, variant: Option<Variant>) -> Result<Value<'static>> {
        let raw = match self.scale {
            Some(scale) => {
                let no_variant = self
                    .refuse()
                    .with_detail(Detail::Expected("a device variant"));
                scale.raw(value, variant).ok_or(no_variant)?
            }
            None => value,
        };
        let raw = match self.kind {
            FieldKind::Unsigned | FieldKind::Signed => match wire::round_half_away(raw) {
                Some(raw) => Value::Int(raw),
                None => {
                    let detail = Detail::FloatRange {
                        value: Float(raw),
                        min: Float(self.min),
                        max: Float(self.max),
                    };
                    return Err(self.refuse().with_detail(detail));
                }
            },
            _ => Value::Float(raw),
        };
        self.check(raw)?;
        Ok(raw)
    }

    /// The engineering value of the raw value `raw` of this scaled field, the divisor taken from
    /// `variant` when it depends on one (what a table's engineering getters return).
    pub(crate) fn scaled(&self, raw: f64, variant: Option<Variant>) -> f64 {
        match self.scale {
            Some(scale) => scale.engineering(raw, variant).unwrap_or(f64::NAN),
            None => raw,
        }
    }

    /// Sets `slot` from the engineering value `value`: scaled, rounded and checked as
    /// [`FieldInfo::raw_from`] does (what a table's engineering setters do).
    pub(crate) fn set_scaled<T: Raw>(
        &self,
        slot: &mut T,
        value: f64,
        variant: Option<Variant>,
    ) -> Result<()> {
        let raw = self.raw_from(value, variant)?;
        *slot = T::from_value(self, raw)?;
        Ok(())
    }

    /// The engineering value of `value` (in the field's unit), or `None` for a field without a
    /// scale, a non-numeric value, or a variant-dependent scale without a variant.
    pub fn engineering(&self, value: Value<'_>, variant: Option<Variant>) -> Option<f64> {
        let raw = match value {
            Value::Int(raw) => raw as f64,
            Value::Float(raw) => raw,
            Value::Bytes(_) => return None,
        };
        self.scale?.engineering(raw, variant)
    }
}

/// Checks that a payload of `len` bytes has exactly `size` bytes: `truncated` at `len` when
/// shorter, `trailing_data` at `size` when longer (the detail both sizes).
pub const fn check_size(len: usize, size: usize) -> Result<()> {
    let detail = Detail::Size {
        size: len,
        expected: size,
    };
    if len < size {
        Err(Error::at(ErrorKind::Truncated, len).with_detail(detail))
    } else if len > size {
        Err(Error::at(ErrorKind::TrailingData, size).with_detail(detail))
    } else {
        Ok(())
    }
}

/// A number field's raw value as a [`Value`], and back (checked as a builder checks it).
pub(crate) trait Raw: Number {
    /// The value.
    fn value(self) -> Value<'static>;
    /// `value` checked against `info` and converted.
    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<Self>;
}

impl Raw for u8 {
    fn value(self) -> Value<'static> {
        Value::Int(i64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<u8> {
        info.int(value)
    }
}

impl Raw for i8 {
    fn value(self) -> Value<'static> {
        Value::Int(i64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<i8> {
        info.int(value)
    }
}

impl Raw for u16 {
    fn value(self) -> Value<'static> {
        Value::Int(i64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<u16> {
        info.int(value)
    }
}

impl Raw for i16 {
    fn value(self) -> Value<'static> {
        Value::Int(i64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<i16> {
        info.int(value)
    }
}

impl Raw for u32 {
    fn value(self) -> Value<'static> {
        Value::Int(i64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<u32> {
        info.int(value)
    }
}

impl Raw for i32 {
    fn value(self) -> Value<'static> {
        Value::Int(i64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<i32> {
        info.int(value)
    }
}

impl Raw for f32 {
    fn value(self) -> Value<'static> {
        Value::Float(f64::from(self))
    }

    fn from_value(info: &FieldInfo, value: Value<'_>) -> Result<f32> {
        info.float(value)
    }
}

/// What [`AnyPayload`] does with the value of any table (each table's `...Repr`).
pub(crate) trait Table {
    /// See the table's `Repr::validate`.
    fn validate(&self) -> Result<()>;
    /// See the table's `Repr::build`.
    fn build(&self, buf: &mut [u8]) -> Result<usize>;
    /// See the table's `Repr::build_frame`.
    fn build_frame(&self, buf: &mut [u8]) -> Result<usize>;
    /// See the table's `Repr::value`.
    fn value(&self, index: usize) -> Option<Value<'_>>;
    /// See the table's `Repr::set_value`.
    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()>;
}

impl PayloadKind {
    /// The index of the field named `name`, if the table has one.
    pub fn field_index(self, name: &str) -> Option<usize> {
        self.fields().iter().position(|info| info.name == name)
    }

    /// True if an engineering value of some field needs the device variant.
    pub fn variant_dependent(self) -> bool {
        self.fields().iter().any(|info| match info.scale {
            Some(scale) => matches!(scale.divisor, Divisor::Parameter(_)),
            None => false,
        })
    }
}

impl AnyPayload {
    /// The size of the payload [`AnyPayload::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        self.kind().size()
    }

    /// Checks every field in table order (see the table's `Repr::validate`).
    pub fn validate(&self) -> Result<()> {
        self.table().validate()
    }

    /// Writes the payload into `buf` (see the table's `Repr::build`); returns its size (bytes).
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.table().build(buf)
    }

    /// Writes a data frame carrying the payload into `buf`; returns its size (bytes).
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        self.table().build_frame(buf)
    }

    /// The raw value of field `index` (table order), or `None` past the last field.
    pub fn value(&self, index: usize) -> Option<Value<'_>> {
        self.table().value(index)
    }

    /// Every raw value, in table order (`Value::Int(0)` past the table's last field).
    pub fn values(&self) -> [Value<'_>; super::MAX_FIELDS] {
        let mut out = [Value::Int(0); super::MAX_FIELDS];
        for (index, slot) in out.iter_mut().enumerate() {
            if let Some(value) = self.value(index) {
                *slot = value;
            }
        }
        out
    }

    /// Sets field `index` (table order) after checking `value` (see [`FieldInfo::check`]).
    /// Errors: `out_of_range` naming the field, or with no field for an index past the last.
    pub fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        self.table_mut().set_value(index, value)
    }

    /// The engineering value of field `index` (see [`FieldInfo::engineering`]).
    pub fn engineering(&self, index: usize, variant: Option<Variant>) -> Option<f64> {
        let info = self.kind().fields().get(index)?;
        info.engineering(self.value(index)?, variant)
    }
}

/// Checks `values` against `fields`, in table order, as a builder does: the first bad one is
/// the error (see [`FieldInfo::check`]).
pub(crate) fn validate(fields: &[FieldInfo], values: &[Value<'_>]) -> Result<()> {
    for (info, value) in fields.iter().zip(values) {
        info.check(*value)?;
    }
    Ok(())
}

/// The first `size` bytes of `buf`, where a builder writes a payload of `size` bytes, or
/// `buffer_too_small`.
pub(crate) fn payload_buffer(buf: &mut [u8], size: usize) -> Result<&mut [u8]> {
    let available = buf.len();
    buf.get_mut(..size)
        .ok_or(crate::frame::too_small(available, size))
}

/// Writes a data frame (reserved byte 0) carrying `payload` into `buf`; returns its size
/// (bytes).
pub(crate) fn data_frame(payload: &[u8], buf: &mut [u8]) -> Result<usize> {
    FrameRepr::new(MessageType::Data, payload).build(buf)
}

/// The error of a table's `set_value` for `index`, past the last of its `count` fields:
/// `out_of_range`, with no field, the detail the index and the valid ones.
pub(crate) fn no_field(index: usize, count: usize) -> Error {
    let detail = Detail::Range {
        value: i64::try_from(index).unwrap_or(i64::MAX),
        min: 0,
        max: i64::try_from(count).unwrap_or(i64::MAX).saturating_sub(1),
    };
    Error::new(ErrorKind::OutOfRange).with_detail(detail)
}
