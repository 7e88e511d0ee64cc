// Copied from generator/targets/rust/runtime/crate/command/frames.rs for spec/ilahrs.yaml,
// spec hash 38d8054fc9091a0f2db18707b13da0eb865efacbd31314c577a8365c9c4e97c8.
// Do not edit: change the runtime source and run `make generate`.
//! Command frames: building one from a command or its name, and decoding one back to the
//! command names that share its code.

use super::Command;
use crate::error::{Error, ErrorKind, Result};
use crate::frame::{self, FrameRepr, MessageType};
use crate::payload::PayloadKind;

/// What the AHRS sends back to a command itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Response {
    /// An acknowledgement frame whose payload is the checksum of the received message.
    Ack,
    /// A data block of one of these payload tables.
    Data(&'static [PayloadKind]),
    /// One block of the current output format.
    Output,
    /// Nothing.
    None,
}

impl Command {
    /// Writes the command frame (a command message, reserved byte 0, the code as the payload)
    /// into `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(self, buf: &mut [u8]) -> Result<usize> {
        FrameRepr::new(MessageType::Command, &[self.code()]).build(buf)
    }
}

/// Writes the command frame of the command whose ICD name is `name` into `buf`; returns its
/// size (bytes). Errors: `unknown_command`, `buffer_too_small`.
pub fn build_command(name: &str, buf: &mut [u8]) -> Result<usize> {
    match Command::from_name(name) {
        Some(command) => command.build(buf),
        None => Err(Error::new(ErrorKind::UnknownCommand)),
    }
}

/// Decodes a command frame: its code and every command with that code, sorted by ICD name.
///
/// `frame` must be exactly one valid frame (errors as for [`frame::Frame::new_checked`]) of
/// type command (`bad_message_type`) with a one-byte payload (`bad_length`) holding a known
/// code (`unknown_command`).
pub fn decode_command(frame: &[u8]) -> Result<(u8, &'static [Command])> {
    let repr = FrameRepr::parse(frame)?;
    if repr.message_type != MessageType::Command {
        let error = Error::at(ErrorKind::BadMessageType, frame::field::MESSAGE_TYPE.start);
        return Err(error.with_field("message_type"));
    }
    let code = match repr.payload {
        [code] => *code,
        _ => {
            let error = Error::at(ErrorKind::BadLength, frame::field::MESSAGE_LENGTH.start);
            return Err(error.with_field("message_length"));
        }
    };
    match Command::with_code(code) {
        [] => {
            let error = Error::at(ErrorKind::UnknownCommand, frame::field::PAYLOAD_START);
            Err(error)
        }
        names => Ok((code, names)),
    }
}

/// Writes `command` and, right after it, its parameter block `parameters` (the payload of a
/// data frame) into `buf`; returns the size of both (bytes).
pub(crate) fn build_with_block(
    command: Command,
    parameters: impl FnOnce(&mut [u8]) -> Result<usize>,
    buf: &mut [u8],
) -> Result<usize> {
    let size = command.build(buf)?;
    let rest = buf.get_mut(size..).unwrap_or(&mut []);
    Ok(size + parameters(rest)?)
}
