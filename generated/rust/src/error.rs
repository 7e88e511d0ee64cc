// Copied from generator/targets/rust/runtime/crate/error.rs for spec/ilahrs.yaml,
// spec hash 38d8054fc9091a0f2db18707b13da0eb865efacbd31314c577a8365c9c4e97c8.
// Do not edit: change the runtime source and run `make generate`.
//! Errors: one list of kinds for every binding (`errors` in the spec), carried with the byte
//! offset of the problem and, where one applies, the field's name.

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
/// offset into the input or into the message being built) and which field, where one applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Error {
    kind: ErrorKind,
    offset: Option<usize>,
    field: Option<&'static str>,
}

impl Error {
    /// An error of `kind` with no offset and no field.
    pub const fn new(kind: ErrorKind) -> Error {
        Error {
            kind,
            offset: None,
            field: None,
        }
    }

    /// An error of `kind` at byte `offset` (bytes from the start of the input).
    pub const fn at(kind: ErrorKind, offset: usize) -> Error {
        Error {
            kind,
            offset: Some(offset),
            field: None,
        }
    }

    /// The same error, naming the field (the spec's field name).
    pub const fn with_field(self, field: &'static str) -> Error {
        Error {
            kind: self.kind,
            offset: self.offset,
            field: Some(field),
        }
    }

    /// The same error, moved `by` bytes further (for an error inside an enclosing message).
    pub const fn shifted(self, by: usize) -> Error {
        Error {
            kind: self.kind,
            offset: match self.offset {
                Some(offset) => Some(offset.saturating_add(by)),
                None => None,
            },
            field: self.field,
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
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.kind.name())?;
        if let Some(offset) = self.offset {
            f.write_str(" at byte ")?;
            fmt::Display::fmt(&offset, f)?;
        }
        if let Some(field) = self.field {
            f.write_str(" (field ")?;
            f.write_str(field)?;
            f.write_str(")")?;
        }
        Ok(())
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}

/// The result of every fallible operation of this crate.
pub type Result<T> = core::result::Result<T, Error>;
