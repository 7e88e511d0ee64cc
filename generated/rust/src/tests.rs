// Copied from generator/targets/rust/runtime/crate/tests.rs for spec/ilahrs.yaml,
// spec hash 38d8054fc9091a0f2db18707b13da0eb865efacbd31314c577a8365c9c4e97c8.
// Do not edit: change the runtime source and run `make generate`.
//! Unit tests drawn from the spec: every command, every payload table, every error of a frame
//! decode in order, sentences and the stream decoder, byte by byte.

use crate::command::{decode_command, Command};
use crate::error::ErrorKind;
use crate::frame::{self, checksum, Frame, FrameRepr, MessageType};
use crate::payload::{AnyPayload, PayloadKind, Value};
use crate::stream::{find_any, StreamDecoder};

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
