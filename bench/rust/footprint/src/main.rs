//! A firmware-shaped program for the footprint measurement: decodes bytes it cannot predict
//! (black_box) and builds answers, so that nothing is optimised away.

#![no_std]
#![no_main]

use core::hint::black_box;
use core::panic::PanicInfo;

use ilahrs::payload::OrientationSensorsRepr;
use ilahrs::{Command, Event, PahrSentence, StreamDecoder};

fn keep(value: u32) {
    black_box(value);
}

/// The entry point named by link.x.
#[no_mangle]
pub extern "C" fn reset() -> ! {
    let mut decoder = StreamDecoder::new();
    let mut out = [0u8; ilahrs::MAX_MESSAGE_SIZE];
    loop {
        let input: [u8; 64] = black_box([0; 64]);
        decoder.feed(&input, |event| match event {
            Event::Frame(frame) => {
                if let Ok(block) = OrientationSensorsRepr::parse(frame.payload()) {
                    keep(u32::from(block.heading));
                }
            }
            Event::Sentence(_, sentence) => keep(sentence.usw.into()),
        });
        let command = Command::ALL[black_box(0)];
        keep(command.build(&mut out).unwrap_or(0) as u32);
        let sentence = PahrSentence::default();
        keep(sentence.build(&mut out).unwrap_or(0) as u32);
        keep(decoder.discarded() as u32);
    }
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    loop {}
}
