//! Properties of the generated crate, over seeded random inputs: payload round trips, and a
//! stream decoder that loses no message to garbage or to the way the input is cut, reads input
//! cut by idle lines as separate streams, and in strict mode refuses only what breaks the rule.

use std::time::Duration;

use ilahrs::payload::{AnyPayload, PayloadKind, Value};
use ilahrs::{FrameRepr, StreamDecoder, IDLE_TIMEOUT};
use ilahrs_properties::{message, valid_payload, Rng};

const ROUNDS: usize = 2000;

/// Equal values, NaNs included (compared bit for bit).
fn same(a: Value<'_>, b: Value<'_>) -> bool {
    match (a, b) {
        (Value::Float(a), Value::Float(b)) => a.to_bits() == b.to_bits(),
        _ => a == b,
    }
}

#[test]
fn parse_inverts_build_for_every_payload() {
    let mut rng = Rng::new(0x1A4_5EED);
    for kind in PayloadKind::ALL {
        for _ in 0..ROUNDS {
            let value = valid_payload(&mut rng, kind);
            let mut buf = [0u8; ilahrs::frame::MAX_PAYLOAD];
            let n = value.build(&mut buf).unwrap();
            assert_eq!(n, kind.size());
            let back = AnyPayload::parse(kind, &buf[..n]).unwrap();
            for index in 0..kind.fields().len() {
                assert!(
                    same(back.value(index).unwrap(), value.value(index).unwrap()),
                    "{} field {}",
                    kind.name(),
                    kind.fields()[index].name
                );
            }
        }
    }
}

#[test]
fn build_inverts_parse_for_every_payload_in_range() {
    let mut rng = Rng::new(0xB17E5);
    for kind in PayloadKind::ALL {
        let mut accepted = 0;
        for round in 0..ROUNDS {
            // Half the rounds from random bytes, half from valid values' bytes.
            let data = if round % 2 == 0 {
                rng.bytes(kind.size())
            } else {
                let mut buf = vec![0u8; kind.size()];
                valid_payload(&mut rng, kind).build(&mut buf).unwrap();
                buf
            };
            let value = AnyPayload::parse(kind, &data).unwrap();
            let mut out = vec![0u8; kind.size()];
            match value.build(&mut out) {
                Ok(n) => {
                    assert_eq!(&out[..n], &data[..], "{}", kind.name());
                    accepted += 1;
                }
                Err(error) => {
                    // Refused: a value out of range, at the field that holds it.
                    let info = kind.fields().iter().find(|f| Some(f.name) == error.field());
                    assert_eq!(error.offset(), info.map(|f| f.offset), "{}", kind.name());
                }
            }
        }
        assert!(accepted >= ROUNDS / 2, "{}", kind.name());
    }
}

/// Random garbage that likes to look like the start of a message.
fn garbage(rng: &mut Rng) -> Vec<u8> {
    let mut out = Vec::new();
    for _ in 0..rng.below(4) {
        match rng.below(6) {
            0 => {
                let size = rng.below(20) as usize;
                out.extend(rng.bytes(size));
            }
            1 => out.extend([0xAA, 0x55]),
            2 => out.extend([0xAA, 0x55, 0x01, 0x00, 0xFF, 0xFF]),
            3 => out.extend(b"$PAHR,1"),
            4 => {
                // A truncated good message.
                let whole = message(rng);
                let cut = rng.below(whole.len() as u64) as usize;
                out.extend(&whole[..cut]);
            }
            _ => {
                // A corrupted good message.
                let mut whole = message(rng);
                let at = rng.below(whole.len() as u64) as usize;
                whole[at] ^= 1 << rng.below(8);
                out.extend(whole);
            }
        }
    }
    out
}

/// Every event of a decoder fed `chunks`, then finished, and its discarded count.
fn decode(chunks: &[&[u8]]) -> (Vec<Vec<u8>>, u64) {
    decode_with(StreamDecoder::new(), chunks)
}

/// [`decode`] with `decoder`.
fn decode_with(mut decoder: StreamDecoder, chunks: &[&[u8]]) -> (Vec<Vec<u8>>, u64) {
    let mut events = Vec::new();
    for chunk in chunks {
        decoder.feed(chunk, |event| events.push(event.as_bytes().to_vec()));
    }
    decoder.finish(|event| events.push(event.as_bytes().to_vec()));
    (events, decoder.discarded())
}

#[test]
fn garbage_between_messages_never_loses_one() {
    let mut rng = Rng::new(0x5_7EA4);
    let mut lost = 0;
    for _ in 0..ROUNDS / 4 {
        let mut input = Vec::new();
        let mut sent = Vec::new();
        for _ in 0..1 + rng.below(8) {
            input.extend(garbage(&mut rng));
            let good = message(&mut rng);
            input.extend(&good);
            sent.push(good);
        }
        input.extend(garbage(&mut rng));
        let (events, discarded) = decode(&[&input]);
        // Every message sent comes out, in order (garbage may add messages of its own).
        let mut next = sent.iter().peekable();
        for event in &events {
            if next.peek() == Some(&event) {
                next.next();
            }
        }
        lost += next.count();
        let kept: usize = events.iter().map(Vec::len).sum();
        assert_eq!(kept as u64 + discarded, input.len() as u64);
    }
    assert_eq!(lost, 0);
}

#[test]
fn chunking_never_changes_the_result() {
    let mut rng = Rng::new(0xC4_0C5);
    for _ in 0..ROUNDS / 4 {
        let mut input = Vec::new();
        for _ in 0..rng.below(10) {
            input.extend(garbage(&mut rng));
            input.extend(message(&mut rng));
        }
        let whole = decode(&[&input]);
        let mut chunks: Vec<&[u8]> = Vec::new();
        let mut rest = &input[..];
        while !rest.is_empty() {
            let size = 1 + rng.below(rest.len().min(100) as u64) as usize;
            chunks.push(&rest[..size]);
            rest = &rest[size..];
        }
        assert_eq!(decode(&chunks), whole);
        let bytes: Vec<&[u8]> = input.chunks(1).collect();
        assert_eq!(decode(&bytes), whole);
    }
}

#[test]
fn the_reader_adapter_gives_the_same_messages() {
    let mut rng = Rng::new(0x10);
    let mut input = Vec::new();
    for _ in 0..500 {
        input.extend(garbage(&mut rng));
        input.extend(message(&mut rng));
    }
    let (events, discarded) = decode(&[&input]);
    let mut messages = ilahrs::io::Messages::new(&input[..]);
    let mut read = Vec::new();
    for message in messages.by_ref() {
        read.push(message.unwrap().as_bytes().to_vec());
    }
    assert_eq!(read, events);
    assert_eq!(messages.decoder().discarded(), discarded);
}

#[test]
fn an_idle_line_cuts_the_input_into_streams_of_their_own() {
    let mut rng = Rng::new(0x1D1E);
    let below = IDLE_TIMEOUT - Duration::from_micros(1);
    for _ in 0..ROUNDS / 4 {
        let mut segments: Vec<Vec<u8>> = Vec::new();
        for _ in 0..1 + rng.below(4) {
            let mut segment = Vec::new();
            for _ in 0..rng.below(4) {
                segment.extend(garbage(&mut rng));
                segment.extend(message(&mut rng));
            }
            segment.extend(garbage(&mut rng));
            segments.push(segment);
        }
        // Each segment decoded alone, as if the input ended there.
        let mut expected = (Vec::new(), 0);
        for segment in &segments {
            let (events, discarded) = decode(&[segment]);
            expected.0.extend(events);
            expected.1 += discarded;
        }
        // One decoder, fed in random chunks, told of each gap; shorter quiet times in between
        // change nothing.
        let mut decoder = StreamDecoder::new();
        let mut events = Vec::new();
        for segment in &segments {
            let mut rest = &segment[..];
            while !rest.is_empty() {
                let size = 1 + rng.below(rest.len().min(40) as u64) as usize;
                decoder.feed(&rest[..size], |event| {
                    events.push(event.as_bytes().to_vec())
                });
                decoder.idle(below, |_| panic!("a quiet time below the timeout"));
                rest = &rest[size..];
            }
            let quiet = [IDLE_TIMEOUT, Duration::MAX][rng.below(2) as usize];
            while let Some(event) = decoder.idle_next(quiet) {
                events.push(event.as_bytes().to_vec());
            }
            assert_eq!(decoder.pending(), 0);
        }
        decoder.finish(|_| panic!("nothing is held after an idle line"));
        assert_eq!((events, decoder.discarded()), expected);
    }
}

/// True if `message` is a frame (not a sentence).
fn is_frame(message: &[u8]) -> bool {
    message.first() == Some(&ilahrs::frame::HEADER[0])
}

#[test]
fn strict_decoding_refuses_only_frames_that_break_the_rule() {
    let Some(rule) = ilahrs::frame::STRICT else {
        return;
    };
    let mut rng = Rng::new(0x57_1C7);
    for _ in 0..ROUNDS / 4 {
        let mut sent = Vec::new();
        let mut input = Vec::new();
        for _ in 0..rng.below(8) {
            input.extend(garbage(&mut rng));
            let good = message(&mut rng);
            input.extend(&good);
            if !is_frame(&good) || FrameRepr::parse_strict(&good).is_ok() {
                sent.extend(good);
            }
        }
        let strict = decode_with(StreamDecoder::strict(), &[&input]);
        for event in &strict.0 {
            if is_frame(event) {
                assert!(FrameRepr::parse_strict(event).is_ok());
            }
        }
        // What the AHRS sends (frames that keep the rule, sentences) is decoded alike.
        let lenient = decode(&[&sent]);
        assert_eq!(decode_with(StreamDecoder::strict(), &[&sent]), lenient);
        // A frame that breaks the rule is refused; the message behind it is not lost.
        let mut frame = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
        let size = 1 + rng.below(20) as usize;
        let payload = rng.bytes(size);
        let repr = FrameRepr {
            message_type: rule.message_type,
            reserved: rule.reserved.wrapping_add(1 + rng.byte() % 255),
            payload: &payload,
        };
        let n = repr.build(&mut frame).unwrap();
        let next = loop {
            let next = message(&mut rng);
            if !is_frame(&next) || FrameRepr::parse_strict(&next).is_ok() {
                break next;
            }
        };
        let both = [&frame[..n], &next[..]].concat();
        let (events, discarded) = decode_with(StreamDecoder::strict(), &[&both]);
        assert_eq!((events, discarded), (vec![next], n as u64));
    }
}
