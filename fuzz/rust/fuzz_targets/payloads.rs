//! Every payload parser, the frame parser and the $PAHR parser on any input: no panic; what
//! parses and is in range builds back to the same bytes.
#![no_main]

use ilahrs::payload::{AnyPayload, PayloadKind};
use ilahrs::{FrameRepr, PahrSentence};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, input)) = data.split_first() else {
        return;
    };
    let kind = PayloadKind::ALL[usize::from(selector) % PayloadKind::ALL.len()];
    if let Ok(value) = AnyPayload::parse(kind, input) {
        let mut out = [0u8; ilahrs::frame::MAX_PAYLOAD];
        if let Ok(n) = value.build(&mut out) {
            assert_eq!(&out[..n], input);
        }
        for index in 0..kind.fields().len() {
            let _ = value.engineering(index, ilahrs::Variant::ALL.first().copied());
        }
    }
    if let Ok(frame) = FrameRepr::parse(input) {
        let mut out = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
        let n = frame.build(&mut out).expect("a parsed frame builds");
        assert_eq!(&out[..n], input);
    }
    if let Ok(sentence) = PahrSentence::parse(input) {
        let mut out = [0u8; ilahrs::nmea::MAX_LENGTH];
        let n = sentence.build(&mut out).expect("a parsed sentence builds");
        assert_eq!(PahrSentence::parse(&out[..n]), Ok(sentence));
    }
});
