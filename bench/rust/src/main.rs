//! bench-rust: decodes the benchmark capture (build/bench/capture.bin, written by the C
//! benchmark's capture tool; when it is missing, a capture made here with the same recipe) with
//! the Rust stream decoder, whole, in 4 KiB chunks and one byte at a time (its first 4 MiB),
//! next to a loop that only sums every byte; and 16 MiB of seeded random bytes (all garbage).
//! Prints `name: X MiB/s` lines; the best of several runs counts.
//!
//!   ilahrs-bench [CAPTURE] [--size BYTES]

use std::hint::black_box;
use std::time::Instant;

use ilahrs::payload::{AnyPayload, FieldKind, PayloadKind, Value};
use ilahrs::{Command, PahrSentence, StreamDecoder};

const RUNS: usize = 7;

/// xorshift64*, seeded: the same capture on every machine.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

/// A capture made with the crate's builders: every payload table as a data frame, commands,
/// acknowledgements, $PAHR sentences, and about 1% garbage (random bytes and false headers).
fn make_capture(size: usize, seed: u64) -> Vec<u8> {
    let mut rng = Rng(seed.max(1));
    let mut out = Vec::with_capacity(size + 128);
    let mut buf = [0u8; ilahrs::MAX_MESSAGE_SIZE];
    let mut garbage = 0usize;
    while out.len() < size {
        if garbage * 100 < out.len() {
            let header = ilahrs::frame::HEADER;
            let before = out.len();
            match rng.below(3) {
                0 => out.extend_from_slice(&header),
                1 => out.extend_from_slice(&[header[0], header[1], 0x01, 0x00, 0xFF, 0x7F]),
                _ => out.extend((0..1 + rng.below(8)).map(|_| rng.next() as u8)),
            }
            garbage += out.len() - before;
        }
        let n = match rng.below(6) {
            0 => {
                let command = Command::ALL[rng.below(Command::ALL.len() as u64) as usize];
                command.build(&mut buf).unwrap_or(0)
            }
            1 => {
                let mut command = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
                let size = Command::ALL[0].build(&mut command).unwrap_or(0);
                ilahrs::ack_for(&command[..size], &mut buf).unwrap_or(0)
            }
            2 => {
                let sentence = PahrSentence {
                    roll: rng.below(1000) as i32,
                    pitch: rng.below(1000) as i32,
                    heading: rng.below(1000) as i32,
                    temperature: rng.below(1000) as i32,
                    vdd: rng.below(1000) as i32,
                    usw: rng.next() as u16,
                };
                sentence.build(&mut buf).unwrap_or(0)
            }
            _ => {
                let kind = PayloadKind::ALL[rng.below(PayloadKind::ALL.len() as u64) as usize];
                let mut payload = AnyPayload::new(kind);
                for (index, info) in kind.fields().iter().enumerate() {
                    if matches!(info.kind, FieldKind::Unsigned | FieldKind::Signed) {
                        let span = (info.max - info.min) as u64 + 1;
                        let value = info.min as i64 + rng.below(span) as i64;
                        let _ = payload.set_value(index, Value::Int(value));
                    }
                }
                payload.build_frame(&mut buf).unwrap_or(0)
            }
        };
        out.extend_from_slice(&buf[..n]);
    }
    out.truncate(size);
    out
}

fn mib_per_s(bytes: usize, seconds: f64) -> f64 {
    bytes as f64 / (1024.0 * 1024.0) / seconds
}

/// The best time of `RUNS` runs of `f`, and its last result.
fn best<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::MAX;
    let mut result = None;
    for _ in 0..RUNS {
        let start = Instant::now();
        let value = black_box(f());
        best = best.min(start.elapsed().as_secs_f64());
        result = Some(value);
    }
    (best, result.expect("at least one run"))
}

/// (frames, sentences, discarded) of the decoder fed `data` in chunks of `chunk` bytes.
fn decode(data: &[u8], chunk: usize) -> (u64, u64, u64) {
    let mut decoder = StreamDecoder::new();
    let (mut frames, mut sentences) = (0u64, 0u64);
    let mut count = |event: ilahrs::Event<'_>| match event {
        ilahrs::Event::Frame(_) => frames += 1,
        ilahrs::Event::Sentence(..) => sentences += 1,
    };
    for piece in data.chunks(chunk) {
        decoder.feed(black_box(piece), &mut count);
    }
    decoder.finish(&mut count);
    (frames, sentences, decoder.discarded())
}

fn sum_bytes(data: &[u8]) -> u64 {
    data.iter().map(|byte| u64::from(*byte)).sum()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|arg| arg == "--sizes") {
        // The decoder's whole state; 32-bit targets hold two usize of 4 bytes instead of 8.
        let state = std::mem::size_of::<StreamDecoder>();
        println!("rust_stream_decoder_state: {state} bytes (this host)");
        return;
    }
    let mut path = "build/bench/capture.bin".to_string();
    let mut size = 64usize << 20;
    let mut index = 0;
    while let Some(arg) = args.get(index) {
        if arg == "--size" {
            size = args
                .get(index + 1)
                .and_then(|s| s.parse().ok())
                .unwrap_or(size);
            index += 2;
        } else {
            path = arg.clone();
            index += 1;
        }
    }
    let data = match std::fs::read(&path) {
        Ok(data) => {
            println!("capture: {path}, {} bytes", data.len());
            data
        }
        Err(_) => {
            let data = make_capture(size, 1);
            println!(
                "capture: {path} not found; made {} bytes here (seed 1)",
                data.len()
            );
            data
        }
    };
    // Seeded random bytes: nothing but false starts and garbage to scan.
    let mut rng = Rng(7);
    let garbage: Vec<u8> = (0..16usize << 20).map(|_| rng.next() as u8).collect();
    let (garbage_time, _) = best(|| decode(&garbage, garbage.len()));
    // One byte at a time, as a UART interrupt handler would feed it (the first 4 MiB).
    let head = &data[..data.len().min(4 << 20)];
    let (bytewise_time, _) = best(|| decode(head, 1));
    let (sum_time, _) = best(|| sum_bytes(&data));
    let (whole_time, whole) = best(|| decode(&data, data.len().max(1)));
    let (chunk_time, chunks) = best(|| decode(&data, 4096));
    assert_eq!(whole, chunks, "chunking changed the result");
    println!(
        "decoded: {} frames, {} sentences, {} bytes discarded",
        whole.0, whole.1, whole.2
    );
    println!(
        "rust_sum_bytes: {:.0} MiB/s",
        mib_per_s(data.len(), sum_time)
    );
    println!(
        "rust_stream: {:.0} MiB/s",
        mib_per_s(data.len(), whole_time)
    );
    println!(
        "rust_stream_4k_chunks: {:.0} MiB/s",
        mib_per_s(data.len(), chunk_time)
    );
    println!(
        "rust_stream_bytewise: {:.0} MiB/s",
        mib_per_s(head.len(), bytewise_time)
    );
    println!(
        "rust_stream_random_bytes: {:.0} MiB/s",
        mib_per_s(garbage.len(), garbage_time)
    );
    println!("rust_stream / rust_sum_bytes: {:.2}", sum_time / whole_time);
    println!(
        "rust_stream: {:.1} M messages/s",
        (whole.0 + whole.1) as f64 / whole_time / 1e6
    );
}
