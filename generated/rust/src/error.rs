// Copied from generator/targets/rust/runtime/crate/error.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! Errors: one list of kinds for every binding (`errors` in the spec), carried with the byte
//! offset of the problem, the field's name where one applies, and the detail behind it (the
//! value, the bound, the name that was not found).
//!
//! [`Error`] implements [`core::error::Error`], with or without the `std` feature, so `?` turns
//! it into a `Box<dyn Error>`:
//!
//! ```
//! use ilahrs::{frame, Command};
//!
//! fn build(buf: &mut [u8]) -> Result<usize, Box<dyn core::error::Error>> {
//!     Ok(Command::ALL[0].build(buf)?)
//! }
//!
//! let error = build(&mut [0u8; 4]).unwrap_err();
//! let needed = frame::OVERHEAD + 1;
//! assert_eq!(error.to_string(), format!("buffer_too_small: 4 bytes, needs {needed}"));
//! ```

use core::fmt;

mod kind;

pub use kind::ErrorKind;

impl ErrorKind {
    /// The kind whose spec name is `name`, if any.
    pub fn from_name(name: &str) -> Option<ErrorKind> {
        ErrorKind::ALL.into_iter().find(|kind| kind.name() == name)
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An input refused or a value that cannot be built: what (`kind`), where (`offset`, a byte
/// offset into the input or into the message being built), which field, where one applies, and
/// the detail behind it, where one is known.
///
/// `Display` writes all four on one line: `out_of_range at byte 4 (field update_rate): 0
/// outside 1..=1000`. Two errors are equal when all four are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Error {
    kind: ErrorKind,
    offset: Option<usize>,
    field: Option<&'static str>,
    detail: Option<Detail>,
}

impl Error {
    /// An error of `kind` with no offset, field or detail.
    pub const fn new(kind: ErrorKind) -> Error {
        Error {
            kind,
            offset: None,
            field: None,
            detail: None,
        }
    }

    /// An error of `kind` at byte `offset` (bytes from the start of the input).
    pub const fn at(kind: ErrorKind, offset: usize) -> Error {
        Error {
            kind,
            offset: Some(offset),
            field: None,
            detail: None,
        }
    }

    /// The same error, naming the field (the spec's field name).
    pub const fn with_field(self, field: &'static str) -> Error {
        Error {
            field: Some(field),
            ..self
        }
    }

    /// The same error, with `detail` saying what exactly was wrong.
    pub const fn with_detail(self, detail: Detail) -> Error {
        Error {
            detail: Some(detail),
            ..self
        }
    }

    /// The same error, moved `by` bytes further (for an error inside an enclosing message).
    pub const fn shifted(self, by: usize) -> Error {
        Error {
            offset: match self.offset {
                Some(offset) => Some(offset.saturating_add(by)),
                None => None,
            },
            ..self
        }
    }

    /// What went wrong.
    pub const fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// Where: a byte offset (bytes), or `None` when no position applies.
    pub const fn offset(&self) -> Option<usize> {
        self.offset
    }

    /// Which field (its spec name), or `None` when no field applies.
    pub const fn field(&self) -> Option<&'static str> {
        self.field
    }

    /// What exactly was wrong (the value, the bound, the name), or `None` when nothing more
    /// than the kind is known.
    pub const fn detail(&self) -> Option<Detail> {
        self.detail
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.kind.name())?;
        if let Some(offset) = self.offset {
            write!(f, " at byte {offset}")?;
        }
        if let Some(field) = self.field {
            write!(f, " (field {field})")?;
        }
        if let Some(detail) = &self.detail {
            write!(f, ": {detail}")?;
        }
        Ok(())
    }
}

impl core::error::Error for Error {}

/// The result of every fallible operation of this crate.
pub type Result<T> = core::result::Result<T, Error>;

/// What exactly was wrong behind an [`Error`]: the value, the bound, the name. Numbers are
/// kept as numbers and names as they are, in the error itself (nothing is allocated); the
/// error's `Display` writes the detail after the kind, offset and field.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Detail {
    /// An integer outside the bounds the spec allows: `value` is not in `min..=max`
    /// (`70 outside 7..=58`). For payload fields, raw values.
    Range {
        /// The value refused.
        value: i64,
        /// The least value allowed.
        min: i64,
        /// The greatest value allowed.
        max: i64,
    },
    /// A float outside the bounds the spec allows, or not finite: `value` is not in
    /// `min..=max` (`inf outside -180.0..=180.0`).
    FloatRange {
        /// The value refused.
        value: Float,
        /// The least value allowed.
        min: Float,
        /// The greatest value allowed.
        max: Float,
    },
    /// `size` bytes where `expected` are needed: input that ends early or runs on, a payload
    /// of the wrong size, a buffer too small (`60 bytes, needs 67`).
    Size {
        /// The bytes there are.
        size: usize,
        /// The bytes needed.
        expected: usize,
    },
    /// `size` bytes where at most `max` fit: text longer than its field, a sentence longer
    /// than the longest one (`95 bytes, at most 90`).
    Limit {
        /// The bytes there are.
        size: usize,
        /// The most bytes that fit.
        max: usize,
    },
    /// `count` fields where a sentence has `expected` (`12 fields, expected 13`).
    Fields {
        /// The fields found.
        count: usize,
        /// The fields a sentence has.
        expected: usize,
    },
    /// The byte `found` where a fixed one (a header byte) is `expected`.
    Byte {
        /// The byte received.
        found: u8,
        /// The byte the protocol puts there.
        expected: u8,
    },
    /// A checksum that does not match: `sent` in the message, `computed` over its bytes.
    Checksum {
        /// The checksum the message carries.
        sent: u16,
        /// The checksum of the bytes received.
        computed: u16,
    },
    /// A code the spec defines nothing for: a message type, a command code.
    Code(u8),
    /// A name nothing is called (a command name), as it was given.
    Name(Name),
    /// What the input lacks or should be where the error is (`*CC before CR LF`).
    Expected(&'static str),
}

impl fmt::Display for Detail {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Detail::Range { value, min, max } => write!(f, "{value} outside {min}..={max}"),
            Detail::FloatRange { value, min, max } => write!(f, "{value} outside {min}..={max}"),
            Detail::Size { size, expected } if size < expected => {
                write!(f, "{}, needs {expected}", Bytes(*size))
            }
            Detail::Size { size, expected } => write!(f, "{}, expected {expected}", Bytes(*size)),
            Detail::Limit { size, max } => write!(f, "{}, at most {max}", Bytes(*size)),
            Detail::Fields { count, expected } => write!(f, "{count} fields, expected {expected}"),
            Detail::Byte { found, expected } => {
                write!(f, "byte {found:#04x}, expected {expected:#04x}")
            }
            Detail::Checksum { sent, computed } => {
                write!(f, "sent {sent:#06x}, computed {computed:#06x}")
            }
            Detail::Code(code) => write!(f, "code {code:#04x}"),
            Detail::Name(name) => write!(f, "no such name {name}"),
            Detail::Expected(what) => write!(f, "expected {what}"),
        }
    }
}

/// A number of bytes, singular or plural.
struct Bytes(usize);

impl fmt::Display for Bytes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            1 => f.write_str("1 byte"),
            size => write!(f, "{size} bytes"),
        }
    }
}

/// A double in a [`Detail`], compared and hashed by its bits (so that [`Error`] stays `Eq` and
/// `Hash`, NaN included), written as Rust writes a double with `{:?}` (`1e40`, `NaN`, `0.5`).
#[derive(Debug, Clone, Copy)]
pub struct Float(pub f64);

impl PartialEq for Float {
    fn eq(&self, other: &Float) -> bool {
        self.0.to_bits() == other.0.to_bits()
    }
}

impl Eq for Float {}

impl core::hash::Hash for Float {
    fn hash<H: core::hash::Hasher>(&self, state: &mut H) {
        self.0.to_bits().hash(state);
    }
}

impl fmt::Display for Float {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&self.0, f)
    }
}

/// A name as it was given, kept in the error without allocating: its first
/// [`Name::CAPACITY`] bytes at most, cut at a character boundary.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Name {
    bytes: [u8; Name::CAPACITY],
    len: u8,
    cut: bool,
}

impl Name {
    /// The most bytes of a name kept (bytes).
    pub const CAPACITY: usize = 29;

    /// `name`, cut to at most [`Name::CAPACITY`] bytes.
    pub fn new(name: &str) -> Name {
        let mut len = name.len().min(Name::CAPACITY);
        while !name.is_char_boundary(len) {
            len -= 1;
        }
        let mut bytes = [0; Name::CAPACITY];
        for (slot, byte) in bytes.iter_mut().zip(name.bytes().take(len)) {
            *slot = byte;
        }
        Name {
            bytes,
            len: len as u8,
            cut: len < name.len(),
        }
    }

    /// The name kept (all of it unless [`Name::is_cut`]).
    pub fn as_str(&self) -> &str {
        let kept = self.bytes.get(..usize::from(self.len)).unwrap_or(&[]);
        core::str::from_utf8(kept).unwrap_or("")
    }

    /// True when the name was longer than [`Name::CAPACITY`] bytes and only its start is
    /// kept.
    pub const fn is_cut(&self) -> bool {
        self.cut
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// The name quoted as Rust quotes a string, `...` after a name that was cut.
impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)?;
        if self.cut {
            f.write_str("...")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use std::boxed::Box;
    use std::string::ToString;

    use super::{Detail, Error, ErrorKind, Float, Name};

    #[test]
    fn every_detail_is_written_with_its_values() {
        let cut = Name::new("AHRSContinuousOutputOfEverything");
        let cases = [
            (
                Detail::Range {
                    value: 70,
                    min: 7,
                    max: 58,
                },
                "70 outside 7..=58",
            ),
            (
                Detail::Range {
                    value: -1,
                    min: 0,
                    max: 255,
                },
                "-1 outside 0..=255",
            ),
            (
                Detail::FloatRange {
                    value: Float(f64::INFINITY),
                    min: Float(-180.0),
                    max: Float(180.0),
                },
                "inf outside -180.0..=180.0",
            ),
            (
                Detail::FloatRange {
                    value: Float(1e40),
                    min: Float(-(f32::MAX as f64)),
                    max: Float(0.5),
                },
                "1e40 outside -3.4028234663852886e38..=0.5",
            ),
            (
                Detail::Size {
                    size: 60,
                    expected: 67,
                },
                "60 bytes, needs 67",
            ),
            (
                Detail::Size {
                    size: 1,
                    expected: 9,
                },
                "1 byte, needs 9",
            ),
            (
                Detail::Size {
                    size: 14,
                    expected: 12,
                },
                "14 bytes, expected 12",
            ),
            (Detail::Limit { size: 95, max: 90 }, "95 bytes, at most 90"),
            (
                Detail::Fields {
                    count: 12,
                    expected: 13,
                },
                "12 fields, expected 13",
            ),
            (
                Detail::Byte {
                    found: 0x12,
                    expected: 0xAA,
                },
                "byte 0x12, expected 0xaa",
            ),
            (
                Detail::Checksum {
                    sent: 0x1234,
                    computed: 0xBEEF,
                },
                "sent 0x1234, computed 0xbeef",
            ),
            (Detail::Code(0x42), "code 0x42"),
            (
                Detail::Name(Name::new("AHRSCont3")),
                "no such name \"AHRSCont3\"",
            ),
            (
                Detail::Name(cut),
                "no such name \"AHRSContinuousOutputOfEveryth\"...",
            ),
            (
                Detail::Expected("*CC before CR LF"),
                "expected *CC before CR LF",
            ),
        ];
        for (detail, text) in cases {
            assert_eq!(detail.to_string(), text);
        }
    }

    #[test]
    fn an_error_is_written_kind_offset_field_detail() {
        let error = Error::at(ErrorKind::BadLength, 4).with_field("message_length");
        assert_eq!(
            error.to_string(),
            "bad_length at byte 4 (field message_length)"
        );
        let detail = Detail::Range {
            value: 70,
            min: 7,
            max: 58,
        };
        let error = error.with_detail(detail);
        assert_eq!(
            error.to_string(),
            "bad_length at byte 4 (field message_length): 70 outside 7..=58"
        );
        assert_eq!(error.detail(), Some(detail));
        assert_eq!(error.shifted(2).offset(), Some(6));
        assert_eq!(error.shifted(2).detail(), Some(detail));
        let name = Detail::Name(Name::new("x"));
        let error = Error::new(ErrorKind::UnknownCommand).with_detail(name);
        assert_eq!(error.to_string(), "unknown_command: no such name \"x\"");
        assert_eq!(Error::new(ErrorKind::Timeout).to_string(), "timeout");
    }

    #[test]
    fn names_are_cut_at_a_character_boundary() {
        let long = "é".repeat(20);
        let name = Name::new(&long);
        assert!(name.is_cut());
        assert_eq!(name.as_str(), "é".repeat(Name::CAPACITY / 2));
        let name = Name::new("LoadAHRSPar");
        assert!(!name.is_cut());
        assert_eq!(name.as_str(), "LoadAHRSPar");
        assert_eq!(Name::new(""), Name::new(""));
        assert_ne!(Name::new("a"), Name::new("b"));
    }

    #[test]
    fn floats_compare_by_their_bits() {
        assert_eq!(Float(f64::NAN), Float(f64::NAN));
        assert_ne!(Float(0.0), Float(-0.0));
        assert_eq!(Float(f64::NAN).to_string(), "NaN");
    }

    #[test]
    fn errors_go_into_a_boxed_core_error_with_question_mark() {
        fn build(name: &str) -> Result<usize, Box<dyn core::error::Error>> {
            let mut buf = [0u8; crate::frame::MAX_FRAME_SIZE];
            Ok(crate::build_command(name, &mut buf)?)
        }
        let error = build("NoSuchCommand").unwrap_err();
        assert_eq!(
            error.to_string(),
            "unknown_command: no such name \"NoSuchCommand\""
        );
        let error = error.downcast_ref::<Error>().unwrap();
        assert_eq!(error.kind(), ErrorKind::UnknownCommand);
        assert!(build(crate::Command::ALL[0].name()).is_ok());
    }
}
