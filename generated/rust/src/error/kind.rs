// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! The spec's one list of error kinds (`errors`), shared with every other binding.

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
    /// Strict decoding only - a data frame's reserved byte is not the value the AHRS sends
    /// (E42).
    BadReserved,
}

impl ErrorKind {
    /// Every kind, in the spec's order.
    pub const ALL: [ErrorKind; 13] = [
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
        ErrorKind::BadReserved,
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
            ErrorKind::BadReserved => "bad_reserved",
        }
    }

    /// One sentence saying what the kind means.
    pub const fn doc(self) -> &'static str {
        match self {
ErrorKind::Truncated => "The input ends before the frame, payload or sentence does.",
ErrorKind::BadHeader => "The frame does not start with AA 55, or a sentence does not start with the $PAHR identifier.",
ErrorKind::BadMessageType => "The message type byte is neither 0 (command) nor 1 (data) (Table 6.2).",
ErrorKind::BadLength => "The message length is outside the bounds the spec accepts, or a payload is not the size its table defines.",
ErrorKind::BadChecksum => "The transmitted checksum does not match the one computed over the received bytes.",
ErrorKind::TrailingData => "Bytes follow the end of a complete frame, payload or sentence where none are allowed.",
ErrorKind::UnknownCommand => "A command code or command name that Table C.1 does not define.",
ErrorKind::OutOfRange => "A value outside the range the spec allows for its field (refused by builders, never wrapped or truncated).",
ErrorKind::Malformed => "Text that does not follow the sentence grammar (missing or extra fields, a bad number).",
ErrorKind::BufferTooSmall => "The caller's output buffer cannot hold the message being built.",
ErrorKind::UnexpectedMessage => "The peer sent a message that the protocol state does not allow (host session and device model).",
ErrorKind::Timeout => "An answer the protocol requires did not arrive in time (host session).",
ErrorKind::BadReserved => "Strict decoding only - a data frame's reserved byte is not the value the AHRS sends (E42).",
}
    }
}
