// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Errors: one list of kinds for every binding (`errors` in the spec), carried with the byte
//! offset of the problem and, where one applies, the field's name.

use core::fmt;

/// What went wrong. The spec's one list of error kinds, shared with every other binding.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// The input ends before the frame, payload or sentence does.
    Truncated,
    /// The frame does not start with AA 55, or a sentence does not start with the $PAHR
    /// identifier.
    BadHeader,
    /// The message type byte is neither 0 (command) nor 1 (data) (Table 6.2).
    BadMessageType,
    /// The message length is outside the bounds the spec accepts, or a payload is not the
    /// size its table defines.
    BadLength,
    /// The transmitted checksum does not match the one computed over the received bytes.
    BadChecksum,
    /// Bytes follow the end of a complete frame, payload or sentence where none are
    /// allowed.
    TrailingData,
    /// A command code or command name that Table C.1 does not define.
    UnknownCommand,
    /// A value outside the range the spec allows for its field (refused by builders, never
    /// wrapped or truncated).
    OutOfRange,
    /// Text that does not follow the sentence grammar (missing or extra fields, a bad
    /// number).
    Malformed,
    /// The caller's output buffer cannot hold the message being built.
    BufferTooSmall,
    /// The peer sent a message that the protocol state does not allow (host session and
    /// device model).
    UnexpectedMessage,
    /// An answer the protocol requires did not arrive in time (host session).
    Timeout,
}

impl ErrorKind {
    /// Every kind, in the spec's order.
    pub const ALL: [ErrorKind; 12] = [
        ErrorKind::Truncated,
        ErrorKind::BadHeader,
        ErrorKind::BadMessageType,
        ErrorKind::BadLength,
        ErrorKind::BadChecksum,
        ErrorKind::TrailingData,
        ErrorKind::UnknownCommand,
        ErrorKind::OutOfRange,
        ErrorKind::Malformed,
        ErrorKind::BufferTooSmall,
        ErrorKind::UnexpectedMessage,
        ErrorKind::Timeout,
    ];

    /// The kind's name in the spec (`bad_checksum`), the same in every binding.
    pub const fn name(self) -> &'static str {
        match self {
            ErrorKind::Truncated => "truncated",
            ErrorKind::BadHeader => "bad_header",
            ErrorKind::BadMessageType => "bad_message_type",
            ErrorKind::BadLength => "bad_length",
            ErrorKind::BadChecksum => "bad_checksum",
            ErrorKind::TrailingData => "trailing_data",
            ErrorKind::UnknownCommand => "unknown_command",
            ErrorKind::OutOfRange => "out_of_range",
            ErrorKind::Malformed => "malformed",
            ErrorKind::BufferTooSmall => "buffer_too_small",
            ErrorKind::UnexpectedMessage => "unexpected_message",
            ErrorKind::Timeout => "timeout",
        }
    }

    /// The kind whose spec name is `name`, if any.
    pub fn from_name(name: &str) -> Option<ErrorKind> {
        match name {
            "truncated" => Some(ErrorKind::Truncated),
            "bad_header" => Some(ErrorKind::BadHeader),
            "bad_message_type" => Some(ErrorKind::BadMessageType),
            "bad_length" => Some(ErrorKind::BadLength),
            "bad_checksum" => Some(ErrorKind::BadChecksum),
            "trailing_data" => Some(ErrorKind::TrailingData),
            "unknown_command" => Some(ErrorKind::UnknownCommand),
            "out_of_range" => Some(ErrorKind::OutOfRange),
            "malformed" => Some(ErrorKind::Malformed),
            "buffer_too_small" => Some(ErrorKind::BufferTooSmall),
            "unexpected_message" => Some(ErrorKind::UnexpectedMessage),
            "timeout" => Some(ErrorKind::Timeout),
            _ => None,
        }
    }

    /// One sentence saying what the kind means.
    pub const fn doc(self) -> &'static str {
        match self {
            ErrorKind::Truncated => "The input ends before the frame, payload or sentence does.",
            ErrorKind::BadHeader => {
                "The frame does not start with AA 55, or a sentence does not start with the $PAHR identifier."
            }
            ErrorKind::BadMessageType => {
                "The message type byte is neither 0 (command) nor 1 (data) (Table 6.2)."
            }
            ErrorKind::BadLength => {
                "The message length is outside the bounds the spec accepts, or a payload is not the size its table defines."
            }
            ErrorKind::BadChecksum => {
                "The transmitted checksum does not match the one computed over the received bytes."
            }
            ErrorKind::TrailingData => {
                "Bytes follow the end of a complete frame, payload or sentence where none are allowed."
            }
            ErrorKind::UnknownCommand => {
                "A command code or command name that Table C.1 does not define."
            }
            ErrorKind::OutOfRange => {
                "A value outside the range the spec allows for its field (refused by builders, never wrapped or truncated)."
            }
            ErrorKind::Malformed => {
                "Text that does not follow the sentence grammar (missing or extra fields, a bad number)."
            }
            ErrorKind::BufferTooSmall => {
                "The caller's output buffer cannot hold the message being built."
            }
            ErrorKind::UnexpectedMessage => {
                "The peer sent a message that the protocol state does not allow (host session and device model)."
            }
            ErrorKind::Timeout => {
                "An answer the protocol requires did not arrive in time (host session)."
            }
        }
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
