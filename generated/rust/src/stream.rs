// Copied from generator/targets/rust/runtime/crate/stream.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! A stream decoder: bytes in, frames and $PAHR sentences out ("leftmost valid message").
//!
//! At each position a valid frame or a valid sentence is accepted and consumed; otherwise one
//! byte is discarded and scanning resumes at the next byte, so a false header, an absurd length
//! or a corrupted frame never costs a following good message. The decoder holds at most
//! [`MAX_MESSAGE_SIZE`] bytes in a fixed array: no allocation. It does no I/O: push bytes in
//! chunks of any size with [`StreamDecoder::feed`] (events to a closure) or
//! [`StreamDecoder::decode`] (one event at a time), and call [`StreamDecoder::finish`] when the
//! input ends.
//!
//! A message never spans an idle line (E41): tell the decoder how long the line has been quiet
//! with [`StreamDecoder::idle`] (or [`StreamDecoder::idle_next`]); from [`crate::IDLE_TIMEOUT`]
//! on it gives up what it waits for, as at the end of the input, so the start of a message whose
//! rest never came costs only its own bytes. [`StreamDecoder::strict`] makes a decoder that also
//! refuses data frames whose reserved byte is not what the AHRS writes
//! ([`crate::frame::STRICT`], E42).
//!
//! ```
//! use ilahrs::frame::HEADER;
//! use ilahrs::stream::{Event, StreamDecoder};
//!
//! // A header with nothing behind it, between two stray bytes.
//! let bytes = [&[0x00][..], &HEADER, &[0x00]].concat();
//! let mut decoder = StreamDecoder::new();
//! let mut input = &bytes[..];
//! while !input.is_empty() {
//!     let (used, event) = decoder.decode(input);
//!     if let Some(Event::Frame(frame)) = event {
//!         let _ = frame.payload();
//!     }
//!     input = &input[used..];
//! }
//! decoder.finish(|_event| {});
//! assert_eq!(decoder.discarded(), bytes.len() as u64);
//! ```

use core::time::Duration;

use crate::frame::{check_frame, field, strict_passes, Frame, HEADER, HEADER_SIZE};
#[cfg(not(feature = "small"))]
use crate::nmea::canonical;
use crate::nmea::{parse_body, PahrSentence, MAX_LENGTH as MAX_SENTENCE_LENGTH, PREFIX};
use crate::wire;

/// The most bytes the decoder holds: the longest frame or sentence (bytes).
pub const MAX_MESSAGE_SIZE: usize = crate::MAX_MESSAGE_SIZE;

/// The byte a frame starts with.
const FRAME_START: u8 = HEADER[0];
/// The byte a sentence starts with.
const SENTENCE_START: u8 = PREFIX[0];

/// An accepted message, borrowed from the input or from the decoder.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Event<'a> {
    /// A valid frame (header through checksum).
    Frame(Frame<&'a [u8]>),
    /// A valid sentence (`$` through CR LF, as received) and its decoded value.
    Sentence(&'a [u8], PahrSentence),
}

impl<'a> Event<'a> {
    /// The message's bytes, as received.
    pub fn as_bytes(&self) -> &'a [u8] {
        match self {
            Event::Frame(frame) => frame.into_inner(),
            Event::Sentence(raw, _) => raw,
        }
    }

    /// The frame, if the message is one.
    pub fn frame(&self) -> Option<Frame<&'a [u8]>> {
        match self {
            Event::Frame(frame) => Some(*frame),
            Event::Sentence(..) => None,
        }
    }

    /// The sentence, if the message is one.
    pub fn sentence(&self) -> Option<PahrSentence> {
        match self {
            Event::Frame(_) => None,
            Event::Sentence(_, sentence) => Some(*sentence),
        }
    }

    /// A copy that does not borrow.
    pub fn to_owned_event(&self) -> OwnedEvent {
        let raw = self.as_bytes();
        let mut bytes = [0u8; MAX_MESSAGE_SIZE];
        for (slot, byte) in bytes.iter_mut().zip(raw) {
            *slot = *byte;
        }
        OwnedEvent {
            bytes,
            len: raw.len().min(MAX_MESSAGE_SIZE),
            sentence: self.sentence(),
        }
    }
}

/// An accepted message copied into a fixed array ([`MAX_MESSAGE_SIZE`] bytes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OwnedEvent {
    bytes: [u8; MAX_MESSAGE_SIZE],
    len: usize,
    sentence: Option<PahrSentence>,
}

impl OwnedEvent {
    /// The message's bytes, as received.
    pub fn as_bytes(&self) -> &[u8] {
        self.bytes.get(..self.len).unwrap_or(&self.bytes)
    }

    /// The borrowed form.
    pub fn event(&self) -> Event<'_> {
        match self.sentence {
            Some(sentence) => Event::Sentence(self.as_bytes(), sentence),
            None => Event::Frame(Frame::new_unchecked(self.as_bytes())),
        }
    }

    /// The frame, if the message is one.
    pub fn frame(&self) -> Option<Frame<&[u8]>> {
        self.event().frame()
    }

    /// The sentence, if the message is one.
    pub fn sentence(&self) -> Option<PahrSentence> {
        self.sentence
    }
}

/// What to do with the candidate at the front.
enum Decision<'a> {
    /// A valid message of this many bytes.
    Accept(usize, Event<'a>),
    /// Not a message here: discard one byte.
    Reject,
    /// The decision needs bytes that have not arrived.
    NeedMore,
}

/// Decides on the candidate message at the start of `data` (which starts with a frame or
/// sentence start byte). `data` holds every byte available; `strict` adds the strict check.
fn decide(data: &[u8], strict: bool) -> Decision<'_> {
    match data.first() {
        Some(&FRAME_START) => decide_frame(data, strict),
        Some(&SENTENCE_START) => decide_sentence(data),
        _ => Decision::Reject,
    }
}

/// Decides on a frame candidate: the checks of a frame decode (with `strict`, the strict one
/// too).
fn decide_frame(data: &[u8], strict: bool) -> Decision<'_> {
    match check_frame(data) {
        Ok(_) if strict && !strict_passes(data) => Decision::Reject,
        Ok(size) => match data.get(..size) {
            Some(bytes) => Decision::Accept(size, Event::Frame(Frame::new_unchecked(bytes))),
            None => Decision::Reject,
        },
        Err(error) if error.kind() == crate::ErrorKind::Truncated => Decision::NeedMore,
        Err(_) => Decision::Reject,
    }
}

/// Decides on a sentence candidate: it runs to the first LF within the longest sentence.
fn decide_sentence(data: &[u8]) -> Decision<'_> {
    // A sentence in the builders' layout needs no search for its end.
    #[cfg(not(feature = "small"))]
    if let Some(raw) = data.get(..canonical::LENGTH) {
        if let Some(sentence) = canonical::parse(raw) {
            return Decision::Accept(raw.len(), Event::Sentence(raw, sentence));
        }
    }
    let window = data.get(..MAX_SENTENCE_LENGTH).unwrap_or(data);
    match find_any(window, [b'\n']) {
        Some(lf) => {
            // The first LF ends the candidate, so the only CR LF it can hold is its last two
            // bytes: what `PahrSentence::parse` checks before the rest.
            let raw = window.get(..=lf).unwrap_or(window);
            if !raw.starts_with(PREFIX) || raw.get(lf.wrapping_sub(1)) != Some(&b'\r') {
                return Decision::Reject;
            }
            match parse_body(raw) {
                Ok(sentence) => Decision::Accept(raw.len(), Event::Sentence(raw, sentence)),
                Err(_) => Decision::Reject,
            }
        }
        None if window.len() >= MAX_SENTENCE_LENGTH => Decision::Reject,
        None => {
            // Reject early what can never become a sentence: a wrong identifier, or a byte
            // that is not printable (CR only as the last byte so far). Waiting would give the
            // same answer.
            let head = window.get(..PREFIX.len()).unwrap_or(window);
            if !PREFIX.starts_with(head) {
                return Decision::Reject;
            }
            let last = window.len().saturating_sub(1);
            let printable = window.iter().enumerate().skip(1).all(|(index, byte)| {
                (0x20..=0x7E).contains(byte) || (*byte == b'\r' && index == last)
            });
            if printable {
                Decision::NeedMore
            } else {
                Decision::Reject
            }
        }
    }
}

/// The index of the first byte of `data` equal to one of `bytes`, looked for eight bytes at a
/// time.
#[cfg(not(feature = "small"))]
pub(crate) fn find_any<const N: usize>(data: &[u8], bytes: [u8; N]) -> Option<usize> {
    const ONES: u64 = u64::from_ne_bytes([0x01; 8]);
    const HIGHS: u64 = u64::from_ne_bytes([0x80; 8]);
    let mut words = data.chunks_exact(8);
    let mut at = 0;
    for word in words.by_ref() {
        let word = u64::from_le_bytes(word.try_into().unwrap_or([0; 8]));
        // A zero byte of `word ^ pattern` is a match; for each pattern the lowest flagged byte
        // is a true one, so the lowest of all flags is the first match.
        let found = bytes.iter().fold(0, |found, byte| {
            let word = word ^ (ONES * u64::from(*byte));
            found | (word.wrapping_sub(ONES) & !word & HIGHS)
        });
        if found != 0 {
            return Some(at + (found.trailing_zeros() / 8) as usize);
        }
        at += 8;
    }
    let mut rest = words.remainder().iter();
    rest.position(|candidate| bytes.contains(candidate))
        .map(|index| at + index)
}

/// The index of the first byte of `data` equal to one of `bytes` (the `small` feature: byte by
/// byte).
#[cfg(feature = "small")]
pub(crate) fn find_any<const N: usize>(data: &[u8], bytes: [u8; N]) -> Option<usize> {
    data.iter().position(|candidate| bytes.contains(candidate))
}

/// The index of the first byte of `data` that may start a message, or its length.
fn next_start(data: &[u8]) -> usize {
    match data.first() {
        Some(&FRAME_START | &SENTENCE_START) => 0,
        _ => find_any(data, [FRAME_START, SENTENCE_START]).unwrap_or(data.len()),
    }
}

/// The stream decoder: feed it bytes, get frames and sentences back in order.
///
/// It holds at most [`MAX_MESSAGE_SIZE`] bytes: the start of a message whose end has not
/// arrived. Bytes that belong to no accepted message are counted by
/// [`StreamDecoder::discarded`].
///
/// Lenient by default: any reserved byte is accepted (E6). [`StreamDecoder::strict`] (or
/// [`StreamDecoder::with_strict`]) refuses data frames whose reserved byte is not what the AHRS
/// writes (E42): such a candidate is no message, one byte is discarded and scanning goes on.
#[derive(Debug, Clone)]
pub struct StreamDecoder {
    buffer: [u8; MAX_MESSAGE_SIZE],
    start: usize,
    end: usize,
    discarded: u64,
    waiting: Waiting,
    strict: bool,
}

impl Default for StreamDecoder {
    fn default() -> StreamDecoder {
        StreamDecoder::new()
    }
}

impl StreamDecoder {
    /// An empty decoder, lenient (any reserved byte is accepted, E6).
    pub const fn new() -> StreamDecoder {
        StreamDecoder {
            buffer: [0; MAX_MESSAGE_SIZE],
            start: 0,
            end: 0,
            discarded: 0,
            waiting: Waiting::Any,
            strict: false,
        }
    }

    /// An empty strict decoder: a frame that breaks [`crate::frame::STRICT`] (a data frame whose
    /// reserved byte is not what the AHRS writes, E42) is no message.
    ///
    /// ```
    /// use ilahrs::frame::{FrameRepr, STRICT};
    /// use ilahrs::StreamDecoder;
    ///
    /// let Some(rule) = STRICT else { return Ok(()) }; // the spec's rule
    /// let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
    /// let mut repr = FrameRepr::new(rule.message_type, &[1, 2, 3]);
    /// repr.reserved = rule.reserved ^ 0x3C; // not what the AHRS writes
    /// let n = repr.build(&mut buf)?;
    /// let (mut lenient, mut strict) = (0, 0);
    /// StreamDecoder::new().feed(&buf[..n], |_| lenient += 1);
    /// StreamDecoder::strict().feed(&buf[..n], |_| strict += 1);
    /// assert_eq!((lenient, strict), (1, 0));
    /// # Ok::<(), ilahrs::Error>(())
    /// ```
    pub const fn strict() -> StreamDecoder {
        StreamDecoder::new().with_strict(true)
    }

    /// The same decoder, strict or lenient (see [`StreamDecoder::strict`]).
    #[must_use]
    pub const fn with_strict(mut self, strict: bool) -> StreamDecoder {
        self.strict = strict;
        self
    }

    /// True if the decoder is strict (see [`StreamDecoder::strict`]).
    pub const fn is_strict(&self) -> bool {
        self.strict
    }

    /// Input bytes that belong to no accepted message, so far (bytes).
    pub const fn discarded(&self) -> u64 {
        self.discarded
    }

    /// Bytes held while waiting to decide on a possible message (bytes).
    pub const fn pending(&self) -> usize {
        self.end - self.start
    }

    /// Takes bytes from `input` until a message is complete; returns how many bytes it took
    /// and the message, if any. Call it again with the rest of the input (`&input[used..]`);
    /// when it returns no message it has taken all of `input`.
    pub fn decode<'s>(&'s mut self, input: &'s [u8]) -> (usize, Option<Event<'s>>) {
        let mut used = 0;
        if self.start < self.end {
            // Bytes that cannot change the decision are taken without deciding again.
            if self.waiting.still(self.end - self.start, input) {
                self.compact();
                if let Some(target) = self.buffer.get_mut(self.end..self.end + input.len()) {
                    target.copy_from_slice(input);
                    self.end += input.len();
                    return (input.len(), None);
                }
            }
            self.waiting = Waiting::Any;
            // A candidate is waiting: top the buffer up and decide on what it holds.
            loop {
                self.compact();
                let room = MAX_MESSAGE_SIZE - self.end;
                let take = room.min(input.len() - used);
                let source = input.get(used..used + take).unwrap_or(&[]);
                if let Some(target) = self.buffer.get_mut(self.end..self.end + take) {
                    target.copy_from_slice(source);
                }
                self.end += take;
                used += take;
                match self.step(false) {
                    Step::Accepted(message) => {
                        // Give back the bytes held behind the message when they all came
                        // from this input, so that the next call scans them where they lie.
                        let behind = self.end - self.start;
                        if behind <= used {
                            used -= behind;
                            self.start = self.end;
                        }
                        return (used, message.event(&self.buffer));
                    }
                    Step::Empty => break,
                    Step::Waiting if used == input.len() => {
                        let held = self.buffer.get(self.start..self.end).unwrap_or(&[]);
                        self.waiting = Waiting::of(held);
                        return (used, None);
                    }
                    Step::Waiting if take == 0 => {
                        // Unreachable (no decision needs more than the buffer holds); never
                        // loop on it.
                        self.discarded += 1;
                        self.start += 1;
                    }
                    Step::Waiting => {}
                }
            }
        }
        // Nothing is held: scan the input where it lies.
        let mut position = used;
        while let Some(rest) = input.get(position..) {
            let skip = next_start(rest);
            self.discarded += skip as u64;
            position += skip;
            let Some(candidate) = input.get(position..).filter(|rest| !rest.is_empty()) else {
                break;
            };
            match decide(candidate, self.strict) {
                Decision::Accept(size, event) => return (position + size, Some(event)),
                Decision::Reject => {
                    self.discarded += 1;
                    position += 1;
                }
                Decision::NeedMore => {
                    let target = self.buffer.get_mut(..candidate.len()).unwrap_or(&mut []);
                    for (slot, byte) in target.iter_mut().zip(candidate) {
                        *slot = *byte;
                    }
                    self.start = 0;
                    self.end = candidate.len().min(MAX_MESSAGE_SIZE);
                    self.waiting = Waiting::of(candidate);
                    return (input.len(), None);
                }
            }
        }
        (input.len(), None)
    }

    /// Feeds `input` whole, calling `on_event` for every message it completes, in order.
    pub fn feed<F: FnMut(Event<'_>)>(&mut self, input: &[u8], mut on_event: F) {
        let mut rest = input;
        while !rest.is_empty() {
            let (used, event) = self.decode(rest);
            if let Some(event) = event {
                on_event(event);
            }
            rest = rest.get(used..).unwrap_or(&[]);
        }
    }

    /// The input has ended: decides on every byte held, discarding candidates that wait for
    /// more, and returns the next message behind them (call until it returns `None`).
    pub fn finish_next(&mut self) -> Option<Event<'_>> {
        self.waiting = Waiting::Any;
        match self.step(true) {
            Step::Accepted(message) => message.event(&self.buffer),
            Step::Empty | Step::Waiting => None,
        }
    }

    /// The input has ended: calls `on_event` for every message still held, in order, and
    /// leaves the decoder empty (ready for a new stream; the discarded count is kept).
    pub fn finish<F: FnMut(Event<'_>)>(&mut self, mut on_event: F) {
        while let Some(event) = self.finish_next() {
            on_event(event);
        }
        self.start = 0;
        self.end = 0;
    }

    /// The line has been quiet for `quiet` since the last byte fed (E41). From
    /// [`crate::IDLE_TIMEOUT`] on, decides on every byte held as [`StreamDecoder::finish_next`]
    /// does: candidates that wait for more are discarded one byte at a time, and the next
    /// message behind them is returned (call until it returns `None`; the decoder then holds
    /// nothing and goes on with the next bytes fed). A shorter quiet time changes nothing and
    /// returns `None`. `Duration::MAX` says that the line is idle, however long.
    ///
    /// ```
    /// use core::time::Duration;
    /// use ilahrs::frame::HEADER;
    /// use ilahrs::{Command, StreamDecoder, IDLE_TIMEOUT};
    ///
    /// // The start of a frame from a host cut off mid-write: a plausible length, no more.
    /// let mut decoder = StreamDecoder::new();
    /// decoder.feed(&[HEADER[0], HEADER[1], 0x01, 0x00, 0x3A, 0x00], |_| {});
    /// assert!(decoder.idle_next(IDLE_TIMEOUT - Duration::from_micros(1)).is_none());
    /// assert_eq!(decoder.pending(), 6);
    /// // Quiet long enough: the stale bytes are given up, and a command that follows is
    /// // decoded at once instead of being read as the rest of them.
    /// assert!(decoder.idle_next(IDLE_TIMEOUT).is_none());
    /// assert_eq!((decoder.pending(), decoder.discarded()), (0, 6));
    /// let mut command = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
    /// let n = Command::ALL[0].build(&mut command)?;
    /// let mut events = 0;
    /// decoder.feed(&command[..n], |_| events += 1);
    /// assert_eq!(events, 1);
    /// # Ok::<(), ilahrs::Error>(())
    /// ```
    pub fn idle_next(&mut self, quiet: Duration) -> Option<Event<'_>> {
        if quiet < crate::IDLE_TIMEOUT {
            return None;
        }
        self.finish_next()
    }

    /// The line has been quiet for `quiet` (E41): from [`crate::IDLE_TIMEOUT`] on, calls
    /// `on_event` for every message still held, in order, and leaves the decoder empty, as
    /// [`StreamDecoder::finish`] does (see [`StreamDecoder::idle_next`]); a shorter quiet time
    /// changes nothing.
    pub fn idle<F: FnMut(Event<'_>)>(&mut self, quiet: Duration, on_event: F) {
        if quiet >= crate::IDLE_TIMEOUT {
            self.finish(on_event);
        }
    }

    /// Moves the held bytes to the front of the buffer.
    fn compact(&mut self) {
        if self.start > 0 {
            self.buffer.copy_within(self.start..self.end, 0);
            self.end -= self.start;
            self.start = 0;
        }
    }

    /// Decides on the held bytes until a message is accepted, the buffer is empty, or a
    /// candidate waits for more (with `at_end`, waiting candidates are discarded instead).
    fn step(&mut self, at_end: bool) -> Step {
        while self.start < self.end {
            let held = self.buffer.get(self.start..self.end).unwrap_or(&[]);
            let skip = next_start(held);
            if skip > 0 {
                self.discarded += skip as u64;
                self.start += skip;
                continue;
            }
            match decide(held, self.strict) {
                Decision::Accept(size, event) => {
                    let message = Found {
                        from: self.start,
                        size,
                        sentence: event.sentence(),
                    };
                    self.start += size;
                    return Step::Accepted(message);
                }
                Decision::NeedMore if !at_end => return Step::Waiting,
                Decision::Reject | Decision::NeedMore => {
                    self.discarded += 1;
                    self.start += 1;
                }
            }
        }
        self.start = 0;
        self.end = 0;
        Step::Empty
    }
}

/// What the held candidate waits for: bytes that cannot change the decision are taken without
/// deciding again, so a message fed byte by byte costs each byte once.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Waiting {
    /// Decide again on any byte.
    Any,
    /// A frame whose header is held: nothing is decided until it holds this many bytes.
    Frame(usize),
    /// A sentence past its identifier, not ending in CR: printable bytes decide nothing until
    /// the longest sentence.
    Sentence,
}

impl Waiting {
    /// What `held`, a candidate that waits for more bytes, waits for.
    fn of(held: &[u8]) -> Waiting {
        match held.first() {
            Some(&FRAME_START) if held.len() < HEADER_SIZE => Waiting::Any,
            Some(&FRAME_START) if held.len() < field::PAYLOAD_START => {
                Waiting::Frame(field::PAYLOAD_START)
            }
            Some(&FRAME_START) => {
                let length = wire::get::<u16>(held, field::MESSAGE_LENGTH);
                Waiting::Frame(field::checksum(usize::from(length)).end)
            }
            Some(&SENTENCE_START) if held.len() >= PREFIX.len() && held.last() != Some(&b'\r') => {
                Waiting::Sentence
            }
            _ => Waiting::Any,
        }
    }

    /// True if `more` bytes after `held` ones leave the candidate waiting.
    fn still(self, held: usize, more: &[u8]) -> bool {
        let total = held + more.len();
        match self {
            Waiting::Any => false,
            Waiting::Frame(until) => total < until,
            Waiting::Sentence => {
                total < MAX_SENTENCE_LENGTH && more.iter().all(|byte| (0x20..=0x7E).contains(byte))
            }
        }
    }
}

/// What [`StreamDecoder::step`] found.
enum Step {
    /// A message in the buffer, with what its event needs (it is not decided again).
    Accepted(Found),
    /// Nothing held any more.
    Empty,
    /// A candidate waits for more bytes.
    Waiting,
}

/// A message accepted in the decoder's buffer: where it lies, and the sentence decoded from it
/// when it is one (a frame's event is its bytes). It does not borrow the buffer, which the
/// decoder goes on filling while the decision is made.
#[derive(Debug, Clone, Copy)]
struct Found {
    /// Where the message starts in the buffer.
    from: usize,
    /// Its size (bytes).
    size: usize,
    /// Its decoded value, if it is a sentence.
    sentence: Option<PahrSentence>,
}

impl Found {
    /// The message's event, borrowed from `buffer` (the decoder's, unchanged since the
    /// decision).
    fn event(self, buffer: &[u8]) -> Option<Event<'_>> {
        let bytes = buffer.get(self.from..self.from + self.size)?;
        Some(match self.sentence {
            Some(sentence) => Event::Sentence(bytes, sentence),
            None => Event::Frame(Frame::new_unchecked(bytes)),
        })
    }
}
