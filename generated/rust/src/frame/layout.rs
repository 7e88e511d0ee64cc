// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! The frame as the spec lays it out (Table 6.2, Table 6.3): sizes, field positions, message types.

/// The bytes every frame starts with.
pub const HEADER: [u8; 2] = [0xAA, 0x55];
/// Size of the header (bytes).
pub const HEADER_SIZE: usize = 2;
/// Size of the checksum (bytes).
pub const CHECKSUM_SIZE: usize = 2;
/// The least message length a decoder accepts (bytes after the header).
pub const MIN_MESSAGE_LENGTH: u16 = 7;
/// The greatest message length a decoder accepts (bytes after the header).
pub const MAX_MESSAGE_LENGTH: u16 = 58;
/// Bytes of a frame besides its payload (bytes).
pub const OVERHEAD: usize = 8;
/// The message length minus the payload size (bytes).
pub const LENGTH_BIAS: usize = 6;
/// The smallest payload a frame carries (bytes).
pub const MIN_PAYLOAD: usize = 1;
/// The largest payload a frame carries (bytes).
pub const MAX_PAYLOAD: usize = 52;
/// The smallest frame (bytes).
pub const MIN_FRAME_SIZE: usize = 9;
/// The largest frame (bytes). A command and the parameter block that follows it need
/// [`crate::command::MAX_COMMAND_WITH_BLOCK_SIZE`].
pub const MAX_FRAME_SIZE: usize = 60;
/// What the AHRS writes in a data frame's reserved byte (E42): a strict decoder
/// refuses a data frame with another value (error `bad_reserved`).
pub const STRICT: Option<super::Strict> = Some(super::Strict {
    message_type: MessageType::Data,
    reserved: 0,
});

/// Where the fields of a frame sit (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// The header, `0xAA` `0x55`.
    pub const HEADER: Field = 0..2;
    /// Message type (u8): 0 for commands, 1 for data. Every AHRS output is data (Table 6.2).
    pub const MESSAGE_TYPE: Field = 2..3;
    /// Reserved (u8): Not defined by rev 1.7. Decoders accept any value and expose it; builders write 0 unless told otherwise (E6). A strict decoder refuses a data frame whose value is not the one the AHRS sends (`strict`, E42).
    pub const RESERVED: Field = 3..4;
    /// Message length (u16): Number of bytes after the 2-byte header, message type through checksum (Table 6.2).
    pub const MESSAGE_LENGTH: Field = 4..6;
    /// Where the payload starts.
    pub const PAYLOAD_START: usize = 6;

    /// The payload of a frame whose message length is `length`.
    pub const fn payload(length: usize) -> Field {
        PAYLOAD_START..checksum(length).start
    }

    /// The checksum of a frame whose message length is `length`.
    pub const fn checksum(length: usize) -> Field {
        let end = length.saturating_add(super::HEADER_SIZE);
        end.saturating_sub(super::CHECKSUM_SIZE)..end
    }
}

/// What a frame carries (Table 6.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MessageType {
    /// 0: A command from the host (one-byte payload holding the command code).
    Command,
    /// 1: Data: every AHRS output, and the parameter blocks the host sends (E5).
    Data,
}

impl MessageType {
    /// The type with code `raw`, if it is one.
    pub const fn from_raw(raw: u8) -> Option<MessageType> {
        match raw {
            0 => Some(MessageType::Command),
            1 => Some(MessageType::Data),
            _ => None,
        }
    }

    /// The code sent on the wire.
    pub const fn raw(self) -> u8 {
        match self {
            MessageType::Command => 0,
            MessageType::Data => 1,
        }
    }

    /// The type's name in the spec.
    pub const fn name(self) -> &'static str {
        match self {
            MessageType::Command => "command",
            MessageType::Data => "data",
        }
    }
}

/// Writes the acknowledgement frame of a message whose checksum is `value` into `buf`.
pub(crate) fn build_ack(value: u16, buf: &mut [u8]) -> crate::Result<usize> {
    let ack = crate::payload::acknowledgement::AcknowledgementRepr { checksum: value };
    ack.build_frame(buf)
}
