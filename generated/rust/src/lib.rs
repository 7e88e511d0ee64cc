// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

#![doc = include_str!("../README.md")]
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
pub const SPEC_HASH: &str = "509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d";
/// What a device and a host must agree on (codes, payload layouts, frame, state-machine answers; not
/// docs or names), hashed to 64 bits: two builds with equal fingerprints speak the same bytes.
pub const WIRE_FINGERPRINT: u64 = 0x0d3ab4a6e6f066a7;
/// The longest message the stream decoder holds: a frame or a sentence (bytes).
pub const MAX_MESSAGE_SIZE: usize = 82;
/// How long the line may be quiet inside a message, in byte times at 115200 baud and
/// 10 bits a byte (the spec's `serial_line.idle_byte_times`, E41).
pub const IDLE_BYTE_TIMES: u32 = 1152;
/// [`IDLE_BYTE_TIMES`] as a time (100000 µs): a stream decoder told that the line has
/// been quiet this long gives up the message it waits for ([`StreamDecoder::idle`]).
pub const IDLE_TIMEOUT: core::time::Duration = core::time::Duration::from_micros(100000);
/// True when numbers are sent most significant byte first (the spec's `byte_order`).
const BIG_ENDIAN: bool = false;
