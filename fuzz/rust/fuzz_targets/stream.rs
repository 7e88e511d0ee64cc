//! The stream decoder on any input, cut into chunks chosen by the input itself: no panic, every
//! event a valid message, the same events however the input is cut, every byte accounted for.
#![no_main]

use ilahrs::{Frame, PahrSentence, StreamDecoder};
use libfuzzer_sys::fuzz_target;

fn run(chunks: &[&[u8]]) -> (Vec<Vec<u8>>, u64) {
    let mut decoder = StreamDecoder::new();
    let mut events = Vec::new();
    let mut check = |event: ilahrs::Event<'_>| {
        let bytes = event.as_bytes().to_vec();
        match event.sentence() {
            Some(sentence) => assert_eq!(PahrSentence::parse(&bytes), Ok(sentence)),
            None => assert!(Frame::new_checked(&bytes[..]).is_ok()),
        }
        events.push(bytes);
    };
    for chunk in chunks {
        decoder.feed(chunk, &mut check);
    }
    decoder.finish(&mut check);
    (events, decoder.discarded())
}

fuzz_target!(|data: &[u8]| {
    let Some((&cut, input)) = data.split_first() else {
        return;
    };
    let whole = run(&[input]);
    let size = usize::from(cut).max(1);
    let chunks: Vec<&[u8]> = input.chunks(size).collect();
    assert_eq!(run(&chunks), whole);
    let kept: usize = whole.0.iter().map(Vec::len).sum();
    assert_eq!(kept as u64 + whole.1, input.len() as u64);
});
