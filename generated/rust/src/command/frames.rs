// Copied from generator/targets/rust/runtime/crate/command/frames.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! Command frames: building one from a command or its name, and decoding one back to the
//! command names that share its code.

use super::Command;
use crate::error::{Detail, Error, ErrorKind, Name, Result};
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
/// size (bytes). Errors: `unknown_command` (its detail the name given), `buffer_too_small`.
pub fn build_command(name: &str, buf: &mut [u8]) -> Result<usize> {
    match Command::from_name(name) {
        Some(command) => command.build(buf),
        None => {
            let error = Error::new(ErrorKind::UnknownCommand);
            Err(error.with_detail(Detail::Name(Name::new(name))))
        }
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
        let detail = Detail::Expected("a command frame");
        return Err(error.with_field("message_type").with_detail(detail));
    }
    let code = match repr.payload {
        [code] => *code,
        payload => {
            let error = Error::at(ErrorKind::BadLength, frame::field::MESSAGE_LENGTH.start);
            let detail = Detail::Size {
                size: payload.len(),
                expected: 1,
            };
            return Err(error.with_field("message_length").with_detail(detail));
        }
    };
    match Command::with_code(code) {
        [] => {
            let error = Error::at(ErrorKind::UnknownCommand, frame::field::PAYLOAD_START);
            Err(error.with_detail(Detail::Code(code)))
        }
        names => Ok((code, names)),
    }
}

/// Writes `command` and, right after it, its parameter block `parameters` (the payload of a
/// data frame) into `buf`; returns the size of both (bytes). The errors come in that order,
/// and a `buffer_too_small` says what both frames need.
pub(crate) fn build_with_block(
    command: Command,
    parameters: impl FnOnce(&mut [u8]) -> Result<usize>,
    buf: &mut [u8],
) -> Result<usize> {
    let total = buf.len();
    let size = match command.build(buf) {
        Ok(size) => size,
        Err(error) if error.kind() == ErrorKind::BufferTooSmall => {
            // The size both need, when the block can be built.
            let mut scratch = [0u8; frame::MAX_FRAME_SIZE];
            let needed = command.build(&mut scratch).and_then(|size| {
                let block = parameters(&mut scratch)?;
                Ok(size + block)
            });
            return Err(needed.map_or(error, |needed| frame::too_small(total, needed)));
        }
        Err(error) => return Err(error),
    };
    let rest = buf.get_mut(size..).unwrap_or(&mut []);
    parameters(rest).map(|block| size + block).map_err(|error| {
        match (error.kind(), error.detail()) {
            (ErrorKind::BufferTooSmall, Some(Detail::Size { expected, .. })) => {
                frame::too_small(total, size + expected)
            }
            _ => error,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::{build_with_block, Command};
    use crate::command::MAX_COMMAND_WITH_BLOCK_SIZE;
    use crate::error::{Detail, ErrorKind};
    use crate::frame::{self, FrameRepr, MessageType};

    #[test]
    fn every_command_with_its_block_fits_max_command_with_block_size() {
        let mut largest = 0;
        for command in Command::ALL {
            let Some(kind) = command.parameter_block() else {
                continue;
            };
            let block = [0u8; frame::MAX_PAYLOAD];
            let write = |buf: &mut [u8]| {
                let payload = &block[..kind.size()];
                let frame = FrameRepr::new(MessageType::Data, payload);
                build_with_block(command, |rest| frame.build(rest), buf)
            };
            let mut buf = [0u8; MAX_COMMAND_WITH_BLOCK_SIZE];
            let n = write(&mut buf).unwrap();
            assert_eq!(n, 2 * frame::OVERHEAD + 1 + kind.size());
            largest = largest.max(n);
            // A buffer too small for the block, or for the command itself, says what both need.
            for size in [n - 1, 1] {
                let error = write(&mut buf[..size]).unwrap_err();
                assert_eq!(error.kind(), ErrorKind::BufferTooSmall);
                assert_eq!(error.detail(), Some(Detail::Size { size, expected: n }));
            }
        }
        assert_eq!(
            largest.max(frame::OVERHEAD + 1),
            MAX_COMMAND_WITH_BLOCK_SIZE
        );
    }
}
