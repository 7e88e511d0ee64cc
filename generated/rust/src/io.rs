// Copied from generator/targets/rust/runtime/crate/io.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! Adapters over [`std::io::Read`] (feature `std`): the messages of a byte source, one at a
//! time, through a [`StreamDecoder`].
//!
//! ```
//! use ilahrs::io::Messages;
//!
//! let capture: &[u8] = &[0x00, 0x01, 0x02];
//! let mut messages = Messages::new(capture);
//! assert!(messages.next().is_none());
//! assert_eq!(messages.decoder().discarded(), 3);
//! ```

use core::time::Duration;
use std::boxed::Box;
use std::io::{self, Read};

use crate::stream::{OwnedEvent, StreamDecoder};

/// The size of the read buffer (bytes).
const READ_SIZE: usize = 8192;

/// An iterator over the messages (frames and sentences) of a reader, in order.
///
/// Reads in blocks of 8 KiB; at the end of the input it decides on the bytes still held, as
/// [`StreamDecoder::finish`] does. Read errors are returned once, then the iteration goes on
/// (an `Interrupted` read is retried).
///
/// A reader with a timeout (a serial port's `TimedOut` or `WouldBlock`) tells how long the line
/// has been quiet: pass that on with [`Messages::idle_next`] (E41). A strict decoder comes in
/// through [`Messages::with_decoder`].
#[derive(Debug)]
pub struct Messages<R: Read> {
    reader: R,
    decoder: StreamDecoder,
    buffer: Box<[u8; READ_SIZE]>,
    start: usize,
    end: usize,
    finished: bool,
}

impl<R: Read> Messages<R> {
    /// Messages of `reader`, decoded by a new [`StreamDecoder`].
    pub fn new(reader: R) -> Messages<R> {
        Messages::with_decoder(reader, StreamDecoder::new())
    }

    /// Messages of `reader`, decoded by `decoder` (for one made by [`StreamDecoder::strict`]).
    pub fn with_decoder(reader: R, decoder: StreamDecoder) -> Messages<R> {
        Messages {
            reader,
            decoder,
            buffer: Box::new([0; READ_SIZE]),
            start: 0,
            end: 0,
            finished: false,
        }
    }

    /// The decoder (for its discarded count).
    pub fn decoder(&self) -> &StreamDecoder {
        &self.decoder
    }

    /// The reader.
    pub fn into_inner(self) -> R {
        self.reader
    }

    /// The line has been quiet for `quiet` since the last byte read (E41). From
    /// [`crate::IDLE_TIMEOUT`] on, the bytes already read are decoded, then the decoder gives up
    /// what it waits for ([`StreamDecoder::idle_next`]); returns the next message this gives
    /// (call until it returns `None`, then go on reading). A shorter quiet time changes nothing.
    pub fn idle_next(&mut self, quiet: Duration) -> Option<OwnedEvent> {
        if quiet < crate::IDLE_TIMEOUT {
            return None;
        }
        if let Some(event) = self.decode_read() {
            return Some(event);
        }
        let event = self.decoder.idle_next(quiet);
        event.map(|event| event.to_owned_event())
    }

    /// Decodes the bytes read and not decoded yet, up to the next message.
    fn decode_read(&mut self) -> Option<OwnedEvent> {
        while self.start < self.end {
            let input = self.buffer.get(self.start..self.end).unwrap_or(&[]);
            let (used, event) = self.decoder.decode(input);
            let event = event.map(|event| event.to_owned_event());
            self.start += used;
            if event.is_some() {
                return event;
            }
        }
        None
    }

    /// The next message, `Ok(None)` at the end of the input, or a read error.
    pub fn next_message(&mut self) -> io::Result<Option<OwnedEvent>> {
        loop {
            if self.finished {
                let event = self.decoder.finish_next();
                return Ok(event.map(|event| event.to_owned_event()));
            }
            if let Some(event) = self.decode_read() {
                return Ok(Some(event));
            }
            match self.reader.read(self.buffer.as_mut_slice()) {
                Ok(0) => self.finished = true,
                Ok(count) => {
                    self.start = 0;
                    self.end = count.min(READ_SIZE);
                }
                Err(error) if error.kind() == io::ErrorKind::Interrupted => {}
                Err(error) => return Err(error),
            }
        }
    }
}

impl<R: Read> Iterator for Messages<R> {
    type Item = io::Result<OwnedEvent>;

    fn next(&mut self) -> Option<io::Result<OwnedEvent>> {
        self.next_message().transpose()
    }
}
