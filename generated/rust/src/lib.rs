// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Inertial Labs AHRS Interface Control Document, revision 1.7 (2014-03-11): frames,
//! commands, payload tables, $PAHR sentences and a stream decoder, generated from the spec
//! `spec/ilahrs.yaml` (spec version 1.0.0).
//!
//! `no_std`, no allocation, no dependencies, no `unsafe`, and no panic reachable from any
//! input. The `std` feature adds `std::error::Error` for [`Error`] and
//! `io::Messages`, an iterator over the messages of a `std::io::Read`.
//!
//! | module | what |
//! |---|---|
//! | [`frame`] | the binary frame: [`Frame`] (view) and [`FrameRepr`] (value), [`checksum`], [`ack_for`] |
//! | [`command`] | [`Command`]: every command of Table C.1, builders, [`decode_command`] |
//! | [`payload`] | one module per payload table: view, value, field positions and descriptions |
//! | [`nmea`] | [`PahrSentence`]: the $PAHR sentence, parsed and built without allocation |
//! | [`stream`] | [`StreamDecoder`]: frames and sentences out of a byte stream |
//! | [`state_machine`] | the device's states and transitions as a table, [`state_machine::Device`] |
//! | [`status`], [`encoding`], [`variant`] | the Unit Status Word, value encodings, device variants |
//! | [`error`] | [`Error`] and [`ErrorKind`], the one list of error kinds |
//!
//! ```
//! use ilahrs::{Command, StreamDecoder};
//!
//! // Build a command frame into a caller's buffer.
//! let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
//! let n = Command::AhrsCont1.build(&mut buf)?;
//!
//! // Decode a byte stream, garbage included, in chunks of any size.
//! let mut decoder = StreamDecoder::new();
//! let mut frames = 0;
//! for chunk in [&[0x00, 0x13][..], &buf[..n]] {
//!     decoder.feed(chunk, |event| {
//!         if event.frame().is_some() {
//!             frames += 1;
//!         }
//!     });
//! }
//! assert_eq!((frames, decoder.discarded()), (1, 2));
//! # Ok::<(), ilahrs::Error>(())
//! ```

#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

#[cfg(feature = "std")]
extern crate std;

pub mod command;
pub mod encoding;
pub mod error;
pub mod frame;
#[cfg(feature = "std")]
pub mod io;
pub mod nmea;
pub mod payload;
pub mod state_machine;
pub mod status;
pub mod stream;
pub mod variant;
mod wire;

#[cfg(test)]
mod tests;

pub use command::{build_command, decode_command, Command};
pub use error::{Error, ErrorKind, Result};
pub use frame::{ack_for, checksum, Frame, FrameRepr, MessageType};
pub use nmea::PahrSentence;
pub use payload::{AnyPayload, PayloadKind};
pub use status::StatusWord;
pub use stream::{Event, StreamDecoder};
pub use variant::Variant;
pub use wire::Field;

/// The version of the spec this crate was generated from.
pub const SPEC_VERSION: &str = "1.0.0";
/// The SHA-256 of the spec file this crate was generated from.
pub const SPEC_HASH: &str = "af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f";
/// The longest message the stream decoder holds: a frame or a sentence (bytes).
pub const MAX_MESSAGE_SIZE: usize = 82;
/// True when numbers are sent most significant byte first (the spec's `byte_order`).
const BIG_ENDIAN: bool = false;
