// Copied from generator/targets/rust/runtime/crate/tests.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! Unit tests drawn from the spec: every command, every payload table, every error of a frame
//! decode in order, sentences and the stream decoder, byte by byte.

extern crate std;

use std::format;
use std::string::ToString;

use crate::command::{decode_command, Command};
use crate::error::{Detail, ErrorKind, Float, Name};
use core::time::Duration;

use crate::frame::{self, checksum, Frame, FrameRepr, MessageType, Strict};
use crate::nmea::{PahrSentence, MAX_LENGTH, PREFIX};
use crate::payload::{AnyPayload, FieldKind, PayloadKind, Value};
use crate::stream::{find_any, Event, StreamDecoder};
use crate::IDLE_TIMEOUT;

/// Builds a frame of `payload` into an array.
fn frame_of(message_type: MessageType, payload: &[u8]) -> ([u8; frame::MAX_FRAME_SIZE], usize) {
    let mut buf = [0u8; frame::MAX_FRAME_SIZE];
    let n = FrameRepr::new(message_type, payload)
        .build(&mut buf)
        .unwrap();
    (buf, n)
}

#[test]
fn every_command_round_trips() {
    for command in Command::ALL {
        let mut buf = [0u8; frame::MAX_FRAME_SIZE];
        let n = command.build(&mut buf).unwrap();
        assert_eq!(n, frame::OVERHEAD + 1);
        let (code, names) = decode_command(&buf[..n]).unwrap();
        assert_eq!(code, command.code());
        assert!(names.contains(&command));
        assert!(names.windows(2).all(|pair| pair[0].name() < pair[1].name()));
        assert_eq!(Command::from_name(command.name()), Some(command));
    }
}

#[test]
fn unknown_codes_and_names_are_refused() {
    for code in 0..=255u8 {
        if Command::with_code(code).is_empty() {
            let (buf, n) = frame_of(MessageType::Command, &[code]);
            let error = decode_command(&buf[..n]).unwrap_err();
            assert_eq!(error.kind(), ErrorKind::UnknownCommand);
            assert_eq!(error.offset(), Some(frame::field::PAYLOAD_START));
        }
    }
    let error = crate::build_command("NoSuchCommand", &mut [0u8; 16]).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::UnknownCommand);
}

#[test]
fn frame_checks_run_in_order() {
    let (good, n) = frame_of(MessageType::Data, &[1, 2, 3]);
    let good = &good[..n];
    assert!(Frame::new_checked(good).is_ok());
    let error = |data: &[u8]| Frame::new_checked(data).unwrap_err();
    assert_eq!(error(&[]).kind(), ErrorKind::Truncated);
    assert_eq!(error(&[0x00]).kind(), ErrorKind::BadHeader);
    assert_eq!(error(&good[..1]).offset(), Some(1));
    let mut bad = [0u8; frame::MAX_FRAME_SIZE];
    bad[..n].copy_from_slice(good);
    bad[1] ^= 0xFF;
    assert_eq!(error(&bad[..n]).offset(), Some(1));
    assert_eq!(
        error(&good[..frame::field::PAYLOAD_START - 1]).kind(),
        ErrorKind::Truncated
    );
    bad[..n].copy_from_slice(good);
    bad[frame::field::MESSAGE_TYPE.start] = 0xFF;
    assert_eq!(error(&bad[..n]).kind(), ErrorKind::BadMessageType);
    bad[..n].copy_from_slice(good);
    bad[frame::field::MESSAGE_LENGTH.start] = 0xFF;
    assert_eq!(error(&bad[..n]).kind(), ErrorKind::BadLength);
    assert_eq!(error(&good[..n - 1]).kind(), ErrorKind::Truncated);
    bad[..n].copy_from_slice(good);
    bad[frame::field::PAYLOAD_START] ^= 1;
    assert_eq!(error(&bad[..n]).kind(), ErrorKind::BadChecksum);
    assert_eq!(error(&bad[..n]).offset(), Some(n - frame::CHECKSUM_SIZE));
    bad[..n].copy_from_slice(good);
    assert_eq!(error(&bad[..n + 1]).kind(), ErrorKind::TrailingData);
    assert_eq!(error(&bad[..n + 1]).offset(), Some(n));
}

#[test]
fn frame_builder_refuses_bad_payload_sizes_and_small_buffers() {
    let payload = [0u8; frame::MAX_PAYLOAD + 1];
    let mut buf = [0u8; frame::MAX_FRAME_SIZE + 1];
    let empty = FrameRepr::new(MessageType::Data, &[]);
    assert_eq!(
        empty.build(&mut buf).unwrap_err().kind(),
        ErrorKind::BadLength
    );
    let long = FrameRepr::new(MessageType::Data, &payload);
    assert_eq!(
        long.build(&mut buf).unwrap_err().kind(),
        ErrorKind::BadLength
    );
    let small = FrameRepr::new(MessageType::Data, &payload[..1]);
    let error = small.build(&mut buf[..frame::OVERHEAD]).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::BufferTooSmall);
}

#[test]
fn unchecked_views_never_panic() {
    for len in 0..frame::MAX_FRAME_SIZE {
        let data = [0xFFu8; frame::MAX_FRAME_SIZE];
        let view = Frame::new_unchecked(&data[..len]);
        let _ = (
            view.payload(),
            view.checksum(),
            view.compute_checksum(),
            view.as_bytes(),
        );
    }
}

#[test]
fn checksum_is_the_sum_modulo_2_16() {
    assert_eq!(checksum(&[]), 0);
    assert_eq!(checksum(&[0xFF; 300]), (0xFF * 300 % 0x10000) as u16);
}

#[test]
fn every_payload_parses_and_builds_its_defaults() {
    for kind in PayloadKind::ALL {
        let value = AnyPayload::new(kind);
        let mut buf = [0u8; frame::MAX_PAYLOAD + 1];
        match value.build(&mut buf) {
            Ok(n) => {
                assert_eq!(n, kind.size());
                assert_eq!(AnyPayload::parse(kind, &buf[..n]).unwrap(), value);
            }
            // A default outside a field's range (a field with no default) is refused, at
            // that field.
            Err(error) => {
                assert_eq!(error.kind(), ErrorKind::OutOfRange);
                let info = kind
                    .fields()
                    .iter()
                    .find(|info| Some(info.name) == error.field());
                assert_eq!(error.offset(), info.map(|info| info.offset));
            }
        }
        let short = AnyPayload::parse(kind, &buf[..kind.size() - 1]).unwrap_err();
        assert_eq!(
            (short.kind(), short.offset()),
            (ErrorKind::Truncated, Some(kind.size() - 1))
        );
        let long = AnyPayload::parse(kind, &buf[..kind.size() + 1]).unwrap_err();
        assert_eq!(
            (long.kind(), long.offset()),
            (ErrorKind::TrailingData, Some(kind.size()))
        );
    }
}

/// Equal values, NaNs included (compared bit for bit).
fn same(a: Value<'_>, b: Value<'_>) -> bool {
    match (a, b) {
        (Value::Float(a), Value::Float(b)) => a.to_bits() == b.to_bits(),
        _ => a == b,
    }
}

#[test]
fn every_byte_string_of_the_right_size_parses() {
    for kind in PayloadKind::ALL {
        for fill in [0x00u8, 0x7F, 0x80, 0xFF] {
            let data = [fill; frame::MAX_PAYLOAD];
            let value = AnyPayload::parse(kind, &data[..kind.size()]).unwrap();
            for (index, info) in kind.fields().iter().enumerate() {
                let read = info.read(&data[..kind.size()]);
                assert!(same(value.value(index).unwrap(), read), "{}", info.name);
            }
        }
    }
}

#[test]
fn field_positions_tile_each_payload() {
    for kind in PayloadKind::ALL {
        let mut next = 0;
        for info in kind.fields() {
            assert_eq!(info.offset, next);
            next = info.offset + info.size;
        }
        assert_eq!(next, kind.size());
    }
}

#[test]
fn builders_refuse_out_of_range_values_at_the_field() {
    for kind in PayloadKind::ALL {
        for (index, info) in kind.fields().iter().enumerate() {
            let mut value = AnyPayload::new(kind);
            let bad = match info.kind {
                crate::payload::FieldKind::Float => Value::Float(f64::NAN),
                crate::payload::FieldKind::Char | crate::payload::FieldKind::Reserved => {
                    Value::Bytes(&[0; frame::MAX_PAYLOAD + 1])
                }
                _ => Value::Int(info.max as i64 + 1),
            };
            let error = value.set_value(index, bad).unwrap_err();
            assert_eq!(error.kind(), ErrorKind::OutOfRange);
            assert_eq!(error.offset(), Some(info.offset));
            assert_eq!(error.field(), Some(info.name));
        }
    }
}

#[test]
fn frame_errors_say_what_was_found_and_expected() {
    let (good, n) = frame_of(MessageType::Data, &[1, 2, 3]);
    let detail = |data: &[u8]| Frame::new_checked(data).unwrap_err().detail();
    let size = |size, expected| Some(Detail::Size { size, expected });
    assert_eq!(detail(&[]), size(0, frame::MIN_FRAME_SIZE));
    assert_eq!(detail(&good[..n - 1]), size(n - 1, n));
    assert_eq!(detail(&good[..n + 1]), size(n + 1, n));
    let mut bad = good;
    bad[1] ^= 0xFF;
    let (found, expected) = (bad[1], frame::HEADER[1]);
    assert_eq!(detail(&bad[..n]), Some(Detail::Byte { found, expected }));
    bad = good;
    bad[frame::field::MESSAGE_TYPE.start] = 0xFF;
    assert_eq!(detail(&bad[..n]), Some(Detail::Code(0xFF)));
    bad = good;
    bad[frame::field::PAYLOAD_START] ^= 1;
    let view = Frame::new_unchecked(&bad[..n]);
    let (sent, computed) = (view.checksum(), view.compute_checksum());
    assert_eq!(detail(&bad[..n]), Some(Detail::Checksum { sent, computed }));
    bad = good;
    bad[frame::field::MESSAGE_LENGTH.start] = 0xFF;
    let (min, max) = (frame::MIN_MESSAGE_LENGTH, frame::MAX_MESSAGE_LENGTH);
    let value = i64::from(Frame::new_unchecked(&bad[..n]).message_length());
    let range = Detail::Range {
        value,
        min: i64::from(min),
        max: i64::from(max),
    };
    assert_eq!(detail(&bad[..n]), Some(range));
    let error = Frame::new_checked(&bad[..n]).unwrap_err();
    let text = format!(
        "bad_length at byte {} (field message_length): {value} outside {min}..={max}",
        frame::field::MESSAGE_LENGTH.start
    );
    assert_eq!(error.to_string(), text);

    let empty = FrameRepr::new(MessageType::Data, &[]);
    let range = Detail::Range {
        value: 0,
        min: frame::MIN_PAYLOAD as i64,
        max: frame::MAX_PAYLOAD as i64,
    };
    let mut buf = [0u8; frame::MAX_FRAME_SIZE];
    assert_eq!(empty.build(&mut buf).unwrap_err().detail(), Some(range));
    let error = Command::ALL[0].build(&mut buf[..2]).unwrap_err();
    assert_eq!(error.detail(), size(2, frame::OVERHEAD + 1));
}

#[test]
fn command_errors_say_what_was_found() {
    let code = (0..=255u8).find(|code| Command::with_code(*code).is_empty());
    if let Some(code) = code {
        let (buf, n) = frame_of(MessageType::Command, &[code]);
        let error = decode_command(&buf[..n]).unwrap_err();
        assert_eq!(error.detail(), Some(Detail::Code(code)));
    }
    let (buf, n) = frame_of(MessageType::Command, &[0, 0]);
    let error = decode_command(&buf[..n]).unwrap_err();
    assert_eq!(
        error.detail(),
        Some(Detail::Size {
            size: 2,
            expected: 1
        })
    );
    let error = crate::build_command("NoSuchCommand", &mut [0u8; 16]).unwrap_err();
    let name = Detail::Name(Name::new("NoSuchCommand"));
    assert_eq!(error.detail(), Some(name));
}

#[test]
fn payload_errors_give_the_value_and_what_the_field_takes() {
    for kind in PayloadKind::ALL {
        let data = [0u8; frame::MAX_PAYLOAD + 1];
        let size = kind.size();
        let short = AnyPayload::parse(kind, &data[..size - 1]).unwrap_err();
        let expected = Some(Detail::Size {
            size: size - 1,
            expected: size,
        });
        assert_eq!(short.detail(), expected);
        for (index, info) in kind.fields().iter().enumerate() {
            let mut value = AnyPayload::new(kind);
            let too_long = [0u8; frame::MAX_PAYLOAD + 1];
            let (bad, expected) = match info.kind {
                FieldKind::Float => {
                    let (value, min, max) = (Float(f64::NAN), Float(info.min), Float(info.max));
                    (
                        Value::Float(f64::NAN),
                        Detail::FloatRange { value, min, max },
                    )
                }
                FieldKind::Char => (
                    Value::Bytes(&too_long),
                    Detail::Limit {
                        size: too_long.len(),
                        max: info.size,
                    },
                ),
                FieldKind::Reserved => (
                    Value::Bytes(&too_long),
                    Detail::Size {
                        size: too_long.len(),
                        expected: info.size,
                    },
                ),
                _ => {
                    let (min, max) = (info.min as i64, info.max as i64);
                    let value = max + 1;
                    (Value::Int(value), Detail::Range { value, min, max })
                }
            };
            let error = value.set_value(index, bad).unwrap_err();
            assert_eq!(error.detail(), Some(expected), "{}", info.name);
        }
        let count = kind.fields().len();
        let error = AnyPayload::new(kind)
            .set_value(count, Value::Int(0))
            .unwrap_err();
        let range = Detail::Range {
            value: count as i64,
            min: 0,
            max: count as i64 - 1,
        };
        assert_eq!(error.detail(), Some(range));
    }
}

#[test]
fn sentence_errors_say_what_was_found_and_expected() {
    let mut buf = [0u8; MAX_LENGTH + 8];
    let n = PahrSentence::default().build(&mut buf).unwrap();
    let detail = |data: &[u8]| PahrSentence::parse(data).unwrap_err().detail();
    let prefix = core::str::from_utf8(PREFIX).unwrap();
    assert_eq!(detail(&[]), Some(Detail::Expected(prefix)));
    let found = b'X';
    let expected = PREFIX[0];
    assert_eq!(detail(b"X"), Some(Detail::Byte { found, expected }));
    assert_eq!(detail(&buf[..n - 2]), Some(Detail::Expected("CR LF")));
    let mut bad = buf;
    bad[n - 3] = if bad[n - 3] == b'0' { b'1' } else { b'0' };
    match detail(&bad[..n]) {
        Some(Detail::Checksum { sent, computed }) => assert_ne!(sent, computed),
        other => panic!("{other:?}"),
    }
    bad = buf;
    bad[n - 5] = b'#';
    let star = Some(Detail::Expected("*CC before CR LF"));
    assert_eq!(detail(&bad[..n]), star);
    let mut long = [b' '; MAX_LENGTH + 8];
    long[..PREFIX.len()].copy_from_slice(PREFIX);
    let limit = Some(Detail::Limit {
        size: long.len(),
        max: MAX_LENGTH,
    });
    assert_eq!(detail(&long), limit);
    let trailing = Some(Detail::Size {
        size: n + 1,
        expected: n,
    });
    assert_eq!(detail(&buf[..n + 1]), trailing);
}

#[test]
fn stream_decoder_finds_messages_byte_by_byte() {
    let mut input = [0u8; 256];
    let mut n = 0;
    for command in Command::ALL {
        input[n] = frame::HEADER[0];
        n += 1;
        n += command.build(&mut input[n..]).unwrap();
        if n > 200 {
            break;
        }
    }
    let mut whole = 0;
    let mut decoder = StreamDecoder::new();
    decoder.feed(&input[..n], |_| whole += 1);
    decoder.finish(|_| whole += 1);
    let mut split = 0;
    let mut bytewise = StreamDecoder::new();
    for byte in &input[..n] {
        bytewise.feed(core::slice::from_ref(byte), |_| split += 1);
    }
    bytewise.finish(|_| split += 1);
    assert_eq!(whole, split);
    assert_eq!(decoder.discarded(), bytewise.discarded());
    assert_eq!(
        whole as u64 * (frame::OVERHEAD as u64 + 1) + decoder.discarded(),
        n as u64
    );
}

#[test]
fn word_scan_finds_the_first_byte_at_every_position() {
    // Neighbours that differ from the byte by one bit or by a borrow must not match.
    for byte in [b'\n', 0x00, 0x80, 0xFF] {
        for len in 0..40 {
            for at in 0..=len {
                let mut data = [byte ^ 0x01; 40];
                for (index, slot) in data.iter_mut().enumerate().take(len) {
                    *slot = if index % 3 == 0 {
                        byte.wrapping_add(1)
                    } else {
                        byte ^ 0x80
                    };
                }
                if at < len {
                    data[at] = byte;
                    if at + 1 < len {
                        data[at + 1] = byte;
                    }
                }
                let expected = data[..len].iter().position(|candidate| *candidate == byte);
                assert_eq!(
                    find_any(&data[..len], [byte]),
                    expected,
                    "{byte} {len} {at}"
                );
                let other = byte.wrapping_add(1);
                let either = data[..len].iter().position(|c| *c == byte || *c == other);
                assert_eq!(find_any(&data[..len], [byte, other]), either);
            }
        }
    }
}

/// The start of a data frame whose length field is plausible and whose rest never came (a host
/// cut off mid-write): header through length, the longest message length.
fn stale_start() -> [u8; frame::field::PAYLOAD_START] {
    let mut start = [0u8; frame::field::PAYLOAD_START];
    let mut view = Frame::new_unchecked(&mut start[..]);
    view.set_header();
    view.set_message_type(MessageType::Data.raw());
    view.set_message_length(frame::MAX_MESSAGE_LENGTH);
    start
}

/// Every event's bytes.
type Events = std::vec::Vec<std::vec::Vec<u8>>;

#[test]
fn idle_below_the_timeout_changes_nothing_and_from_it_gives_up() {
    let stale = stale_start();
    let (command, n) = frame_of(MessageType::Command, &[Command::ALL[0].code()]);
    let just_below = IDLE_TIMEOUT - Duration::from_nanos(1);
    for (quiet, gives_up) in [
        (Duration::ZERO, false),
        (just_below, false),
        (IDLE_TIMEOUT, true),
        (IDLE_TIMEOUT.saturating_add(Duration::from_nanos(1)), true),
        (Duration::MAX, true),
    ] {
        let mut decoder = StreamDecoder::new();
        decoder.feed(&stale, |_| panic!("no message yet"));
        let mut events = 0;
        decoder.idle(quiet, |_| events += 1);
        assert_eq!(events, 0);
        let expected = if gives_up { (0, 6) } else { (6, 0) };
        assert_eq!(
            (decoder.pending(), decoder.discarded()),
            expected,
            "{quiet:?}"
        );
        assert!(decoder.idle_next(just_below).is_none());
        let mut frames = Events::new();
        decoder.feed(&command[..n], |event| frames.push(event.as_bytes().into()));
        if gives_up {
            assert_eq!(frames, [&command[..n]], "{quiet:?}");
        } else {
            // The command is read as the rest of the stale frame.
            assert!(frames.is_empty(), "{quiet:?}");
            assert_eq!(decoder.pending(), stale.len() + n);
        }
    }
}

#[test]
fn idle_after_bytewise_feeding_gives_the_messages_behind_the_stale_bytes() {
    let stale = stale_start();
    let (command, n) = frame_of(MessageType::Command, &[Command::ALL[0].code()]);
    let input = [&stale[..], &command[..n]].concat();
    for bytewise in [false, true] {
        let mut decoder = StreamDecoder::new();
        let mut early = 0;
        if bytewise {
            for byte in &input {
                decoder.feed(core::slice::from_ref(byte), |_| early += 1);
            }
        } else {
            decoder.feed(&input, |_| early += 1);
        }
        assert_eq!((early, decoder.pending()), (0, input.len()));
        let first = decoder
            .idle_next(IDLE_TIMEOUT)
            .map(|event| event.as_bytes().to_vec());
        assert_eq!(first.as_deref(), Some(&command[..n]));
        assert!(decoder.idle_next(IDLE_TIMEOUT).is_none());
        assert_eq!(
            (decoder.pending(), decoder.discarded()),
            (0, stale.len() as u64)
        );
        // The decoder goes on with the next bytes fed.
        let mut after = Events::new();
        for byte in &command[..n] {
            decoder.feed(core::slice::from_ref(byte), |event| {
                after.push(event.as_bytes().into())
            });
        }
        assert_eq!(after, [&command[..n]]);
    }
}

#[test]
fn idle_with_nothing_held_does_nothing() {
    let (command, n) = frame_of(MessageType::Command, &[Command::ALL[0].code()]);
    let mut decoder = StreamDecoder::new();
    assert!(decoder.idle_next(Duration::MAX).is_none());
    let mut events = 0;
    decoder.feed(&[0x00, 0x01], |_| events += 1);
    decoder.feed(&command[..n], |_| events += 1);
    decoder.idle(Duration::MAX, |_| events += 1);
    assert!(decoder.idle_next(IDLE_TIMEOUT).is_none());
    assert_eq!((events, decoder.pending(), decoder.discarded()), (1, 0, 2));
}

/// A frame of the strict rule's message type whose reserved byte is another than the rule's.
fn off_rule_frame(rule: Strict) -> ([u8; frame::MAX_FRAME_SIZE], usize) {
    let mut buf = [0u8; frame::MAX_FRAME_SIZE];
    let repr = FrameRepr {
        message_type: rule.message_type,
        reserved: rule.reserved ^ 0x3C,
        payload: &[1, 2, 3],
    };
    let n = repr.build(&mut buf).unwrap();
    (buf, n)
}

#[test]
fn strict_frame_parse_refuses_a_reserved_byte_the_device_never_sends() {
    let Some(rule) = frame::STRICT else { return };
    let (bad, n) = off_rule_frame(rule);
    assert!(FrameRepr::parse(&bad[..n]).is_ok());
    let error = FrameRepr::parse_strict(&bad[..n]).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::BadReserved);
    assert_eq!(error.offset(), Some(frame::field::RESERVED.start));
    assert_eq!(error.field(), Some("reserved"));
    let found = rule.reserved ^ 0x3C;
    let expected = rule.reserved;
    assert_eq!(error.detail(), Some(Detail::Byte { found, expected }));
    assert!(Frame::new_checked_strict(&bad[..n]).is_err());
    // Every other check comes first.
    let mut worse = bad;
    worse[n - 1] ^= 1;
    let kind = |data: &[u8]| FrameRepr::parse_strict(data).unwrap_err().kind();
    assert_eq!(kind(&worse[..n]), ErrorKind::BadChecksum);
    assert_eq!(kind(&bad[..n + 1]), ErrorKind::TrailingData);
    assert_eq!(kind(&bad[..n - 1]), ErrorKind::Truncated);
    // The rule's reserved byte, and other message types with any reserved byte, pass.
    let good = FrameRepr {
        reserved: rule.reserved,
        ..FrameRepr::parse(&bad[..n]).unwrap()
    };
    let mut buf = [0u8; frame::MAX_FRAME_SIZE];
    let m = good.build(&mut buf).unwrap();
    assert_eq!(FrameRepr::parse_strict(&buf[..m]), Ok(good));
    for raw in 0..=u8::MAX {
        let Some(other) = MessageType::from_raw(raw).filter(|t| *t != rule.message_type) else {
            continue;
        };
        let repr = FrameRepr {
            message_type: other,
            ..FrameRepr::parse(&bad[..n]).unwrap()
        };
        let m = repr.build(&mut buf).unwrap();
        assert_eq!(FrameRepr::parse_strict(&buf[..m]), Ok(repr));
    }
}

#[test]
fn strict_stream_refuses_what_the_lenient_one_accepts() {
    const STRICT_DECODER: StreamDecoder = StreamDecoder::strict();
    let Some(rule) = frame::STRICT else { return };
    let (bad, n) = off_rule_frame(rule);
    let (command, m) = frame_of(MessageType::Command, &[Command::ALL[0].code()]);
    let input = [&bad[..n], &command[..m]].concat();
    assert!(!StreamDecoder::new().is_strict() && !StreamDecoder::default().is_strict());
    assert!(STRICT_DECODER.is_strict());
    for (decoder, accepted) in [
        (StreamDecoder::new(), 2),
        (StreamDecoder::strict().with_strict(false), 2),
        (STRICT_DECODER, 1),
        (StreamDecoder::new().with_strict(true), 1),
    ] {
        for bytewise in [false, true] {
            let mut decoder = decoder.clone();
            let mut events = Events::new();
            let mut record = |event: Event<'_>| events.push(event.as_bytes().into());
            if bytewise {
                for byte in &input {
                    decoder.feed(core::slice::from_ref(byte), &mut record);
                }
            } else {
                decoder.feed(&input, &mut record);
            }
            decoder.finish(&mut record);
            assert_eq!(events.len(), accepted);
            assert_eq!(events.last().map(|e| &e[..]), Some(&command[..m]));
            let discarded = if accepted == 1 { n as u64 } else { 0 };
            assert_eq!(decoder.discarded(), discarded);
        }
    }
}

#[cfg(feature = "std")]
#[test]
fn the_reader_adapter_passes_strict_and_idle_on() {
    use std::io::{self, Read};

    /// Reads its chunks in turn; an empty chunk, and every read after the last, is a read that
    /// timed out (the line never ends).
    struct Line(std::vec::Vec<std::vec::Vec<u8>>);

    impl Read for Line {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            let chunk = if self.0.is_empty() {
                std::vec![]
            } else {
                self.0.remove(0)
            };
            if chunk.is_empty() {
                return Err(io::ErrorKind::TimedOut.into());
            }
            buf[..chunk.len()].copy_from_slice(&chunk);
            Ok(chunk.len())
        }
    }

    let Some(rule) = frame::STRICT else { return };
    let (bad, n) = off_rule_frame(rule);
    let (command, m) = frame_of(MessageType::Command, &[Command::ALL[0].code()]);
    let first = [&bad[..n], &command[..m], &stale_start()[..]].concat();
    for idle in [false, true] {
        let line = Line(std::vec![first.clone(), std::vec![], command[..m].to_vec()]);
        let mut messages = crate::io::Messages::with_decoder(line, StreamDecoder::strict());
        let mut read = Events::new();
        for _ in 0..8 {
            match messages.next() {
                Some(Ok(event)) => read.push(event.as_bytes().into()),
                Some(Err(error)) if error.kind() == io::ErrorKind::TimedOut => {
                    assert!(messages.idle_next(IDLE_TIMEOUT / 2).is_none());
                    let quiet = if idle { IDLE_TIMEOUT } else { Duration::ZERO };
                    while let Some(event) = messages.idle_next(quiet) {
                        read.push(event.as_bytes().into());
                    }
                }
                Some(Err(error)) => panic!("{error}"),
                None => panic!("the line never ends"),
            }
        }
        // Without the idle call, the command after the gap is read as the stale frame's rest.
        let expected: &[&[u8]] = if idle {
            &[&command[..m], &command[..m]]
        } else {
            &[&command[..m]]
        };
        assert_eq!(read, expected);
    }
}
