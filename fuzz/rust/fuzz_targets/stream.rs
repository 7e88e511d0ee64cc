//! The stream decoder on any input, cut into chunks chosen by the input itself: no panic, every
//! event a valid message, the same events however the input is cut, every byte accounted for;
//! lenient and strict (E42, chosen by the cut byte's top bit; a strict decoder's data frames carry
//! the reserved byte the AHRS sends). With the line idle after every chunk (E41), the events are
//! those of each chunk decoded on its own.
#![no_main]

use ilahrs::{Frame, PahrSentence, StreamDecoder, IDLE_TIMEOUT};
use libfuzzer_sys::fuzz_target;

fn run(chunks: &[&[u8]], strict: bool, idle: bool) -> (Vec<Vec<u8>>, u64) {
    let mut decoder = StreamDecoder::new().with_strict(strict);
    let mut events = Vec::new();
    let mut check = |event: ilahrs::Event<'_>| {
        let bytes = event.as_bytes().to_vec();
        match event.sentence() {
            Some(sentence) => assert_eq!(PahrSentence::parse(&bytes), Ok(sentence)),
            None => {
                assert!(Frame::new_checked(&bytes[..]).is_ok());
                assert!(!strict || Frame::new_checked_strict(&bytes[..]).is_ok());
            }
        }
        events.push(bytes);
    };
    for chunk in chunks {
        decoder.feed(chunk, &mut check);
        if idle {
            decoder.idle(IDLE_TIMEOUT, &mut check);
        }
    }
    decoder.finish(&mut check);
    (events, decoder.discarded())
}

fuzz_target!(|data: &[u8]| {
    let Some((&cut, input)) = data.split_first() else {
        return;
    };
    let strict = cut & 0x80 != 0;
    let whole = run(&[input], strict, false);
    let size = usize::from(cut & 0x7F).max(1);
    let chunks: Vec<&[u8]> = input.chunks(size).collect();
    assert_eq!(run(&chunks, strict, false), whole);
    let kept: usize = whole.0.iter().map(Vec::len).sum();
    assert_eq!(kept as u64 + whole.1, input.len() as u64);
    let mut segments = (Vec::new(), 0);
    for chunk in &chunks {
        let (events, discarded) = run(&[chunk], strict, false);
        segments.0.extend(events);
        segments.1 += discarded;
    }
    assert_eq!(run(&chunks, strict, true), segments);
});
