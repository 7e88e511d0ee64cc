// Copied from generator/targets/rust/runtime/crate/frame.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! The binary frame: header, message type, reserved byte, message length, payload and checksum
//! (the spec's `frame`; positions and sizes in [`field`] and the constants below).
//!
//! [`Frame`] is a zero-copy view over bytes, checked once by [`Frame::new_checked`];
//! [`FrameRepr`] is the same frame as a value, with [`FrameRepr::parse`] and
//! [`FrameRepr::build`]. The builder fills the length and the checksum.
//!
//! The 16-bit sum lets some damage through: two bytes moved by opposite amounts leave it
//! unchanged. [`Frame::new_checked_strict`] and [`FrameRepr::parse_strict`] also refuse a frame
//! whose reserved byte is not what the AHRS writes there ([`STRICT`], E42), the commonest case.
//!
//! ```
//! use ilahrs::frame::{FrameRepr, MessageType};
//!
//! let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
//! let repr = FrameRepr::new(MessageType::Data, &[1, 2, 3]);
//! let n = repr.build(&mut buf)?;
//! assert_eq!(FrameRepr::parse(&buf[..n])?, repr);
//! # Ok::<(), ilahrs::Error>(())
//! ```

use crate::error::{Detail, Error, ErrorKind, Result};
use crate::wire;

mod layout;

pub use layout::{
    field, MessageType, CHECKSUM_SIZE, HEADER, HEADER_SIZE, LENGTH_BIAS, MAX_FRAME_SIZE,
    MAX_MESSAGE_LENGTH, MAX_PAYLOAD, MIN_FRAME_SIZE, MIN_MESSAGE_LENGTH, MIN_PAYLOAD, OVERHEAD,
    STRICT,
};

/// What the AHRS itself writes in a frame's header: frames of `message_type` carry `reserved`
/// (see [`STRICT`]). Decoders accept any reserved byte by default (E6); asked to be strict,
/// they refuse frames of that type with another one (error `bad_reserved`, E42).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Strict {
    /// The message type the rule covers.
    pub message_type: MessageType,
    /// The reserved byte such frames carry.
    pub reserved: u8,
}

impl TryFrom<u8> for MessageType {
    type Error = Error;

    /// The type with code `raw`, or `bad_message_type` naming the field and the code.
    fn try_from(raw: u8) -> Result<MessageType> {
        let error = Error::new(ErrorKind::BadMessageType).with_field("message_type");
        MessageType::from_raw(raw).ok_or(error.with_detail(Detail::Code(raw)))
    }
}

/// The checksum of `data` (the spec's `sum16`): the sum of its bytes, modulo 2^16. A frame's
/// checksum covers its message type through its last payload byte.
///
/// ```
/// assert_eq!(ilahrs::checksum(&[0xFF, 0xFF, 0x02]), 0x0200);
/// ```
pub fn checksum(data: &[u8]) -> u16 {
    // Summed in 32 bits (wrapping keeps the sum modulo 2^16 right) so that it vectorises.
    let sum = data
        .iter()
        .fold(0u32, |sum, byte| sum.wrapping_add(u32::from(*byte)));
    (sum & 0xFFFF) as u16
}

/// Checks that `data` starts with a whole frame and returns the frame's size (bytes).
///
/// Runs the checks of a frame decode in order, except the one for trailing bytes: header,
/// enough bytes for the fixed fields, message type, message length, enough bytes for the
/// message, checksum. The first failure is the error, at its offset in `data`, with its
/// detail: the byte, code, length or checksum found and what was expected (a frame cut short
/// before its length is known needs [`MIN_FRAME_SIZE`] bytes at least).
pub fn check_frame(data: &[u8]) -> Result<usize> {
    let truncated = |expected| {
        let size = data.len();
        Error::at(ErrorKind::Truncated, size).with_detail(Detail::Size { size, expected })
    };
    for (index, expected) in HEADER.iter().enumerate() {
        match data.get(index) {
            None => return Err(truncated(MIN_FRAME_SIZE)),
            Some(&found) if found != *expected => {
                let error = Error::at(ErrorKind::BadHeader, index).with_field("header");
                let expected = *expected;
                return Err(error.with_detail(Detail::Byte { found, expected }));
            }
            Some(_) => {}
        }
    }
    if data.len() < field::PAYLOAD_START {
        return Err(truncated(MIN_FRAME_SIZE));
    }
    let code = wire::get::<u8>(data, field::MESSAGE_TYPE);
    if MessageType::from_raw(code).is_none() {
        let error = Error::at(ErrorKind::BadMessageType, field::MESSAGE_TYPE.start);
        return Err(error
            .with_field("message_type")
            .with_detail(Detail::Code(code)));
    }
    let length = wire::get::<u16>(data, field::MESSAGE_LENGTH);
    if !(MIN_MESSAGE_LENGTH..=MAX_MESSAGE_LENGTH).contains(&length) {
        let error = Error::at(ErrorKind::BadLength, field::MESSAGE_LENGTH.start);
        let detail = Detail::Range {
            value: i64::from(length),
            min: i64::from(MIN_MESSAGE_LENGTH),
            max: i64::from(MAX_MESSAGE_LENGTH),
        };
        return Err(error.with_field("message_length").with_detail(detail));
    }
    let sum = field::checksum(usize::from(length));
    if data.len() < sum.end {
        return Err(truncated(sum.end));
    }
    let computed = checksum(wire::bytes(data, HEADER_SIZE..sum.start));
    let sent = wire::get::<u16>(data, sum.clone());
    if computed != sent {
        let error = Error::at(ErrorKind::BadChecksum, sum.start).with_field("checksum");
        return Err(error.with_detail(Detail::Checksum { sent, computed }));
    }
    Ok(sum.end)
}

/// Checks the reserved byte of the frame at the start of `data` against [`STRICT`] (the strict
/// option's check, made after every other one): `bad_reserved` at the reserved byte's offset,
/// with the byte found and the one expected, when the frame's message type is the rule's and
/// its reserved byte is another. Always `Ok` when the spec has no strict rule.
pub fn check_strict(data: &[u8]) -> Result<()> {
    match STRICT {
        Some(rule) if !passes(rule, data) => {
            let found = wire::get::<u8>(data, field::RESERVED);
            let error = Error::at(ErrorKind::BadReserved, field::RESERVED.start);
            let expected = rule.reserved;
            Err(error
                .with_field("reserved")
                .with_detail(Detail::Byte { found, expected }))
        }
        _ => Ok(()),
    }
}

/// True unless the frame at the start of `data` breaks [`STRICT`].
pub(crate) fn strict_passes(data: &[u8]) -> bool {
    match STRICT {
        Some(rule) => passes(rule, data),
        None => true,
    }
}

/// True unless the frame at the start of `data` breaks `rule`.
fn passes(rule: Strict, data: &[u8]) -> bool {
    wire::get::<u8>(data, field::MESSAGE_TYPE) != rule.message_type.raw()
        || wire::get::<u8>(data, field::RESERVED) == rule.reserved
}

/// A zero-copy view of one frame over a buffer.
///
/// Made by [`Frame::new_checked`], which validates the whole frame once; the accessors never
/// panic, even on a view made by [`Frame::new_unchecked`] over a short buffer (they read
/// missing bytes as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Frame<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> Frame<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> Frame<T> {
        Frame { buffer }
    }

    /// A view over `buffer`, which must hold exactly one valid frame.
    ///
    /// Errors, at their byte offset in `buffer`: `truncated`, `bad_header`,
    /// `bad_message_type`, `bad_length`, `bad_checksum`, `trailing_data`.
    pub fn new_checked(buffer: T) -> Result<Frame<T>> {
        let frame = Frame::new_unchecked(buffer);
        frame.check_len()?;
        Ok(frame)
    }

    /// A view over `buffer`, which must hold exactly one valid frame that also passes the strict
    /// check ([`check_strict`], E42): the errors of [`Frame::new_checked`], then `bad_reserved`.
    ///
    /// ```
    /// use ilahrs::frame::{Frame, FrameRepr, STRICT};
    /// use ilahrs::ErrorKind;
    ///
    /// let Some(rule) = STRICT else { return Ok(()) }; // the spec's rule
    /// let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
    /// let mut repr = FrameRepr::new(rule.message_type, &[1, 2, 3]);
    /// repr.reserved = rule.reserved ^ 0x3C; // not what the AHRS writes
    /// let n = repr.build(&mut buf)?;
    /// assert!(Frame::new_checked(&buf[..n]).is_ok());
    /// let error = Frame::new_checked_strict(&buf[..n]).unwrap_err();
    /// assert_eq!(error.kind(), ErrorKind::BadReserved);
    /// assert_eq!(error.offset(), Some(3));
    /// # Ok::<(), ilahrs::Error>(())
    /// ```
    pub fn new_checked_strict(buffer: T) -> Result<Frame<T>> {
        let frame = Frame::new_checked(buffer)?;
        check_strict(frame.buffer.as_ref())?;
        Ok(frame)
    }

    /// Checks that the buffer holds exactly one valid frame (see [`Frame::new_checked`]).
    pub fn check_len(&self) -> Result<()> {
        let data = self.buffer.as_ref();
        let size = check_frame(data)?;
        if data.len() > size {
            let detail = Detail::Size {
                size: data.len(),
                expected: size,
            };
            return Err(Error::at(ErrorKind::TrailingData, size).with_detail(detail));
        }
        Ok(())
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The frame's bytes: header through checksum (empty for an unchecked view whose buffer
    /// is too short).
    pub fn as_bytes(&self) -> &[u8] {
        let data = self.buffer.as_ref();
        data.get(..self.total_len()).unwrap_or(data)
    }

    /// The message type byte, raw (see [`MessageType`]).
    pub fn message_type(&self) -> u8 {
        wire::get::<u8>(self.buffer.as_ref(), field::MESSAGE_TYPE)
    }

    /// The message type as a [`MessageType`], or `None` for an unknown code.
    pub fn message_type_decoded(&self) -> Option<MessageType> {
        MessageType::from_raw(self.message_type())
    }

    /// The reserved byte, as received (see [`field::RESERVED`]).
    pub fn reserved(&self) -> u8 {
        wire::get::<u8>(self.buffer.as_ref(), field::RESERVED)
    }

    /// The message length: bytes after the header, message type through checksum (bytes).
    pub fn message_length(&self) -> u16 {
        wire::get::<u16>(self.buffer.as_ref(), field::MESSAGE_LENGTH)
    }

    /// The size of the whole frame, header through checksum, by its length field (bytes).
    pub fn total_len(&self) -> usize {
        field::checksum(usize::from(self.message_length())).end
    }

    /// The payload (bytes).
    pub fn payload(&self) -> &[u8] {
        let length = usize::from(self.message_length());
        wire::bytes(self.buffer.as_ref(), field::payload(length))
    }

    /// The checksum the frame carries.
    pub fn checksum(&self) -> u16 {
        let length = usize::from(self.message_length());
        wire::get::<u16>(self.buffer.as_ref(), field::checksum(length))
    }

    /// The checksum computed over the frame's bytes (message type through payload).
    pub fn compute_checksum(&self) -> u16 {
        let length = usize::from(self.message_length());
        let covered = HEADER_SIZE..field::checksum(length).start;
        checksum(wire::bytes(self.buffer.as_ref(), covered))
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> Frame<T> {
    /// Writes the header bytes.
    pub fn set_header(&mut self) {
        wire::put(self.buffer.as_mut(), field::HEADER, &HEADER);
    }

    /// Sets the message type byte (raw).
    pub fn set_message_type(&mut self, value: u8) {
        wire::set::<u8>(self.buffer.as_mut(), field::MESSAGE_TYPE, value);
    }

    /// Sets the reserved byte.
    pub fn set_reserved(&mut self, value: u8) {
        wire::set::<u8>(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets the message length (bytes after the header).
    pub fn set_message_length(&mut self, value: u16) {
        wire::set::<u16>(self.buffer.as_mut(), field::MESSAGE_LENGTH, value);
    }

    /// The payload, for writing (its size follows the length field).
    pub fn payload_mut(&mut self) -> &mut [u8] {
        let length = usize::from(self.message_length());
        let payload = self.buffer.as_mut().get_mut(field::payload(length));
        payload.unwrap_or(&mut [])
    }

    /// Computes the checksum and writes it.
    pub fn fill_checksum(&mut self) {
        let value = self.compute_checksum();
        let length = usize::from(self.message_length());
        wire::set::<u16>(self.buffer.as_mut(), field::checksum(length), value);
    }
}

/// One frame as a value: message type, reserved byte and a borrowed payload.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameRepr<'a> {
    /// What the frame carries.
    pub message_type: MessageType,
    /// The reserved byte (see [`field::RESERVED`]).
    pub reserved: u8,
    /// The payload ([`MIN_PAYLOAD`] to [`MAX_PAYLOAD`] bytes).
    pub payload: &'a [u8],
}

impl<'a> FrameRepr<'a> {
    /// A frame of `message_type` carrying `payload`, with the reserved byte 0.
    pub const fn new(message_type: MessageType, payload: &'a [u8]) -> FrameRepr<'a> {
        FrameRepr {
            message_type,
            reserved: 0,
            payload,
        }
    }

    /// Decodes exactly one frame (see [`Frame::new_checked`] for the errors).
    pub fn parse(data: &'a [u8]) -> Result<FrameRepr<'a>> {
        let frame = Frame::new_checked(data)?;
        Ok(FrameRepr::from_view(&frame))
    }

    /// Decodes exactly one frame with the strict check (see [`Frame::new_checked_strict`]).
    pub fn parse_strict(data: &'a [u8]) -> Result<FrameRepr<'a>> {
        let frame = Frame::new_checked_strict(data)?;
        Ok(FrameRepr::from_view(&frame))
    }

    /// The value of a view (a view made by [`Frame::new_checked`] always has a known type;
    /// an unchecked one with an unknown type reads as [`MessageType::Command`]).
    pub fn from_view(frame: &Frame<&'a [u8]>) -> FrameRepr<'a> {
        let data: &'a [u8] = frame.buffer;
        let length = usize::from(frame.message_length());
        FrameRepr {
            message_type: frame.message_type_decoded().unwrap_or(MessageType::Command),
            reserved: frame.reserved(),
            payload: wire::bytes(data, field::payload(length)),
        }
    }

    /// The size of the frame [`FrameRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        self.payload.len() + OVERHEAD
    }

    /// Writes the frame into `buf`, filling length and checksum; returns its size (bytes).
    ///
    /// Errors: `bad_length` (field `payload`) for a payload outside [`MIN_PAYLOAD`] to
    /// [`MAX_PAYLOAD`] bytes, `buffer_too_small` when `buf` cannot hold the frame (its detail
    /// says how many bytes it needs).
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        let bad_length = Error::new(ErrorKind::BadLength)
            .with_field("payload")
            .with_detail(Detail::Range {
                value: i64::try_from(self.payload.len()).unwrap_or(i64::MAX),
                min: MIN_PAYLOAD as i64,
                max: MAX_PAYLOAD as i64,
            });
        if !(MIN_PAYLOAD..=MAX_PAYLOAD).contains(&self.payload.len()) {
            return Err(bad_length);
        }
        let size = self.buffer_len();
        let length = u16::try_from(self.payload.len() + LENGTH_BIAS).map_err(|_| bad_length)?;
        let available = buf.len();
        let out = buf.get_mut(..size).ok_or(too_small(available, size))?;
        let mut frame = Frame::new_unchecked(out);
        frame.set_header();
        frame.set_message_type(self.message_type.raw());
        frame.set_reserved(self.reserved);
        frame.set_message_length(length);
        wire::put(frame.payload_mut(), 0..self.payload.len(), self.payload);
        frame.fill_checksum();
        Ok(size)
    }
}

/// `buffer_too_small`: a buffer of `size` bytes where `expected` are needed.
pub(crate) const fn too_small(size: usize, expected: usize) -> Error {
    Error::new(ErrorKind::BufferTooSmall).with_detail(Detail::Size { size, expected })
}

/// Writes the acknowledgement of the host message `message` into `buf` and returns its size
/// (bytes): a data frame whose payload (the spec's acknowledgement table) is the checksum of the
/// message received, the value of that message's own checksum field.
///
/// `message` must be exactly one valid frame (errors as for [`Frame::new_checked`]);
/// `buffer_too_small` when `buf` cannot hold the answer.
///
/// ```
/// use ilahrs::command::Command;
///
/// let mut command = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
/// let n = Command::ALL[0].build(&mut command)?;
/// let mut ack = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
/// let m = ilahrs::ack_for(&command[..n], &mut ack)?;
/// assert!(ilahrs::FrameRepr::parse(&ack[..m]).is_ok());
/// # Ok::<(), ilahrs::Error>(())
/// ```
pub fn ack_for(message: &[u8], buf: &mut [u8]) -> Result<usize> {
    let frame = Frame::new_checked(message)?;
    layout::build_ack(frame.checksum(), buf)
}
