//! Helpers for the property tests: a seeded generator and random messages built with the crate.

use ilahrs::payload::{AnyPayload, FieldInfo, FieldKind, PayloadKind, Value};
use ilahrs::{Command, FrameRepr, MessageType, PahrSentence};

/// xorshift64*: small, fast, and the same sequence on every machine.
pub struct Rng(u64);

impl Rng {
    /// A generator; `seed` must not be 0.
    pub fn new(seed: u64) -> Rng {
        Rng(seed.max(1))
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A number in `0..n` (`n` > 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }

    /// A random byte.
    pub fn byte(&mut self) -> u8 {
        self.next_u64() as u8
    }

    /// `count` random bytes.
    pub fn bytes(&mut self, count: usize) -> Vec<u8> {
        (0..count).map(|_| self.byte()).collect()
    }

    /// An integer in `min..=max`.
    pub fn int_in(&mut self, min: i64, max: i64) -> i64 {
        let span = (max - min) as u64 + 1;
        min + self.below(span) as i64
    }

    /// A float in `min..=max` (both ends included sometimes).
    pub fn float_in(&mut self, min: f64, max: f64) -> f64 {
        match self.below(8) {
            0 => min,
            1 => max,
            _ => min + (max - min) * (self.below(1 << 53) as f64 / (1u64 << 53) as f64),
        }
    }
}

/// A random value a builder accepts for `info`.
pub fn valid_value(rng: &mut Rng, info: &FieldInfo, text: &mut Vec<u8>) -> Value<'static> {
    match info.kind {
        FieldKind::Unsigned | FieldKind::Signed => {
            Value::Int(rng.int_in(info.min as i64, info.max as i64))
        }
        FieldKind::Float => loop {
            // Values that float32 holds exactly, so that a round trip compares equal.
            let value = f64::from(rng.float_in(info.min, info.max) as f32);
            if info.check(Value::Float(value)).is_ok() {
                return Value::Float(value);
            }
        },
        FieldKind::Char | FieldKind::Reserved => {
            let len = if info.kind == FieldKind::Char {
                rng.below(info.size as u64 + 1) as usize
            } else {
                info.size
            };
            text.clear();
            text.extend((0..len).map(|_| rng.byte()));
            if info.kind == FieldKind::Char {
                while text.last() == Some(&0) {
                    text.pop();
                }
            }
            Value::Bytes(text.clone().leak())
        }
    }
}

/// A random payload of `kind` whose every field is in range.
pub fn valid_payload(rng: &mut Rng, kind: PayloadKind) -> AnyPayload {
    let mut payload = AnyPayload::new(kind);
    let mut text = Vec::new();
    for (index, info) in kind.fields().iter().enumerate() {
        let value = valid_value(rng, info, &mut text);
        payload
            .set_value(index, value)
            .expect("a value inside the field's range");
    }
    payload
}

/// A random valid message: a command, a data frame of some table, an acknowledgement, a
/// frame with any payload, or a $PAHR sentence.
pub fn message(rng: &mut Rng) -> Vec<u8> {
    let mut buf = vec![0u8; ilahrs::MAX_MESSAGE_SIZE];
    let n = match rng.below(5) {
        0 => {
            let command = Command::ALL[rng.below(Command::ALL.len() as u64) as usize];
            command.build(&mut buf).unwrap()
        }
        1 => {
            let kind = PayloadKind::ALL[rng.below(PayloadKind::ALL.len() as u64) as usize];
            valid_payload(rng, kind).build_frame(&mut buf).unwrap()
        }
        2 => {
            let size = 1 + rng.below(ilahrs::frame::MAX_PAYLOAD as u64) as usize;
            let payload = rng.bytes(size);
            let message_type = if rng.below(2) == 0 {
                MessageType::Command
            } else {
                MessageType::Data
            };
            let mut repr = FrameRepr::new(message_type, &payload);
            repr.reserved = rng.byte();
            repr.build(&mut buf).unwrap()
        }
        3 => {
            let mut command = [0u8; 16];
            let size = Command::ALL[0].build(&mut command).unwrap();
            ilahrs::ack_for(&command[..size], &mut buf).unwrap()
        }
        _ => sentence(rng).build(&mut buf).unwrap(),
    };
    buf.truncate(n);
    buf
}

/// A random valid sentence: small random values, drawn again until the builder accepts them.
pub fn sentence(rng: &mut Rng) -> PahrSentence {
    loop {
        let candidate = PahrSentence {
            roll: rng.int_in(-1000, 1000) as i32,
            pitch: rng.int_in(-1000, 1000) as i32,
            heading: rng.int_in(-1000, 1000) as i32,
            temperature: rng.int_in(-1000, 1000) as i32,
            vdd: rng.int_in(-1000, 1000) as i32,
            usw: rng.next_u64() as u16,
        };
        if candidate.validate().is_ok() {
            return candidate;
        }
    }
}
