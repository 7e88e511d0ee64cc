// Copied from conformance/runners/rust/main.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runner source and run `make generate`.
//! The conformance runner of the `ilahrs` crate: reads requests on standard input, one per
//! line, and answers each on one line (conformance/README.md, "The runner protocol"). It holds
//! no test logic and no protocol knowledge beyond what the crate exposes.

#![forbid(unsafe_code)]

use std::io::{self, BufRead, Write};
use std::time::Duration;

use ilahrs::payload::{AnyPayload, FieldKind, PayloadKind, Value};
use ilahrs::{Error, ErrorKind, FrameRepr, MessageType, StreamDecoder, Variant};

mod nmea;
mod session;

/// An answer line, or the error to report.
type Answer = Result<String, Refusal>;

/// Why a request was refused.
enum Refusal {
    /// The crate refused the input.
    Crate(Error),
    /// A refusal with a field name that is not a spec name (an unknown field).
    Named(ErrorKind, String),
    /// The request does not follow the protocol.
    Unsupported,
}

impl From<Error> for Refusal {
    fn from(error: Error) -> Refusal {
        Refusal::Crate(error)
    }
}

fn main() -> io::Result<()> {
    let stdin = io::stdin();
    let stdout = io::stdout();
    let mut out = stdout.lock();
    for line in stdin.lock().lines() {
        let line = line?;
        let reply = match answer(line.trim_end_matches(['\r', '\n'])) {
            Ok(text) => text,
            Err(Refusal::Crate(error)) => {
                let offset = error.offset().map_or("-".to_string(), |at| at.to_string());
                let field = error.field().unwrap_or("-");
                format!("error {} {offset} {field}", error.kind().name())
            }
            Err(Refusal::Named(kind, field)) => format!("error {} - {field}", kind.name()),
            Err(Refusal::Unsupported) => "unsupported".to_string(),
        };
        writeln!(out, "{reply}")?;
        out.flush()?;
    }
    Ok(())
}

fn answer(line: &str) -> Answer {
    let mut tokens = line.split(' ');
    let kind = tokens.next().unwrap_or("");
    let args: Vec<&str> = tokens.collect();
    let arg = |index: usize| args.get(index).copied().ok_or(Refusal::Unsupported);
    match kind {
        "checksum" => Ok(format!("ok {}", ilahrs::checksum(&read_hex(arg(0)?)?))),
        "frame_decode" => {
            let options = read_options(args.get(1..).unwrap_or(&[]), false)?;
            frame_decode(&read_hex(arg(0)?)?, &options)
        }
        "frame_encode" => frame_encode(arg(0)?, &read_hex(arg(1)?)?, args.get(2).copied()),
        "command_encode" => {
            let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
            let n = ilahrs::build_command(arg(0)?, &mut buf)?;
            Ok(format!("ok {}", write_hex(&buf[..n])))
        }
        "command_decode" => {
            let (code, commands) = ilahrs::decode_command(&read_hex(arg(0)?)?)?;
            let names: Vec<&str> = commands.iter().map(|command| command.name()).collect();
            Ok(format!("ok code={code} names={}", names.join(",")))
        }
        "ack" => {
            let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
            let n = ilahrs::ack_for(&read_hex(arg(0)?)?, &mut buf)?;
            Ok(format!("ok {}", write_hex(&buf[..n])))
        }
        "payload_decode" => payload_decode(arg(0)?, &read_hex(arg(1)?)?, args.get(2).copied()),
        "payload_encode" => payload_encode(arg(0)?, args.get(2..).unwrap_or(&[])),
        "nmea_decode" => nmea::decode(&read_text(arg(0)?)?),
        "nmea_encode" => nmea::encode(&args),
        "stream" => {
            let options = read_options(args.get(1..).unwrap_or(&[]), true)?;
            stream(args.first().copied().unwrap_or(""), &options)
        }
        "session" => session::run(arg(0)?, arg(1)?),
        _ => Err(Refusal::Unsupported),
    }
}

/// What follows a request's arguments: the stream's idle gaps and the vector's options.
#[derive(Default)]
struct Options {
    /// The strict option (E42).
    strict: bool,
    /// (chunk index, quiet microseconds): the idle call made after that chunk (E41).
    idle: Vec<(usize, u64)>,
}

/// `idle=AFTER:US,...` (when `idle` is allowed) and the `strict` option; anything else, an
/// option this runner does not know among them, is refused.
fn read_options(tokens: &[&str], idle: bool) -> Result<Options, Refusal> {
    let mut options = Options::default();
    for token in tokens {
        if *token == "strict" {
            options.strict = true;
            continue;
        }
        match token.split_once('=').ok_or(Refusal::Unsupported)? {
            ("idle", gaps) if idle => {
                for gap in gaps.split(',') {
                    let (after, us) = gap.split_once(':').ok_or(Refusal::Unsupported)?;
                    let after = after.parse().map_err(|_| Refusal::Unsupported)?;
                    let us = us.parse().map_err(|_| Refusal::Unsupported)?;
                    options.idle.push((after, us));
                }
            }
            _ => return Err(Refusal::Unsupported),
        }
    }
    Ok(options)
}

fn frame_decode(data: &[u8], options: &Options) -> Answer {
    let frame = if options.strict {
        FrameRepr::parse_strict(data)?
    } else {
        FrameRepr::parse(data)?
    };
    Ok(format!(
        "ok message_type={} reserved={} payload={}",
        frame.message_type.raw(),
        frame.reserved,
        write_hex(frame.payload)
    ))
}

fn frame_encode(message_type: &str, payload: &[u8], reserved: Option<&str>) -> Answer {
    let message_type = match message_type.parse::<u8>() {
        Ok(raw) => MessageType::try_from(raw)?,
        Err(_) => {
            let field = "message_type".to_string();
            return Err(Refusal::Named(ErrorKind::BadMessageType, field));
        }
    };
    let reserved = match reserved {
        Some(text) => text.parse::<u8>().map_err(|_| {
            let field = "reserved".to_string();
            Refusal::Named(ErrorKind::OutOfRange, field)
        })?,
        None => 0,
    };
    let repr = FrameRepr {
        message_type,
        reserved,
        payload,
    };
    let mut buf = [0u8; ilahrs::frame::MAX_FRAME_SIZE];
    let n = repr.build(&mut buf)?;
    Ok(format!("ok {}", write_hex(&buf[..n])))
}

fn payload_kind(name: &str) -> Result<PayloadKind, Refusal> {
    PayloadKind::from_name(name).ok_or(Refusal::Unsupported)
}

fn payload_decode(name: &str, data: &[u8], variant: Option<&str>) -> Answer {
    let kind = payload_kind(name)?;
    let variant = match variant {
        None | Some("-") => None,
        Some(name) => Some(Variant::from_name(name).ok_or(Refusal::Unsupported)?),
    };
    let payload = AnyPayload::parse(kind, data)?;
    let mut text = String::from("ok");
    for (index, info) in kind.fields().iter().enumerate() {
        let value = payload.value(index).ok_or(Refusal::Unsupported)?;
        let shown = match (info.kind, value) {
            (_, Value::Int(raw)) => raw.to_string(),
            (_, Value::Float(raw)) => write_num(f64::from(raw as f32), true),
            (FieldKind::Char, Value::Bytes(bytes)) => write_text(bytes),
            (_, Value::Bytes(bytes)) => write_hex(bytes),
        };
        text += &format!(" f.{}={shown}", info.name);
    }
    for (index, info) in kind.fields().iter().enumerate() {
        if let Some(value) = payload.engineering(index, variant) {
            text += &format!(" v.{}={}", info.name, write_num(value, false));
        }
    }
    Ok(text)
}

fn payload_encode(name: &str, pairs: &[&str]) -> Answer {
    let kind = payload_kind(name)?;
    let mut given: Vec<Option<&str>> = vec![None; kind.fields().len()];
    for pair in pairs {
        let (key, token) = pair.split_once('=').ok_or(Refusal::Unsupported)?;
        match kind.field_index(key) {
            Some(index) => given[index] = Some(token),
            None => return Err(Refusal::Named(ErrorKind::Malformed, key.to_string())),
        }
    }
    let mut payload = AnyPayload::new(kind);
    for (index, info) in kind.fields().iter().enumerate() {
        let bytes;
        let value = match given[index] {
            None => info.default,
            Some(token) => match info.kind {
                FieldKind::Unsigned | FieldKind::Signed => Value::Int(read_int(token)),
                FieldKind::Float => Value::Float(token.parse().unwrap_or(f64::NAN)),
                FieldKind::Char => {
                    bytes = read_text(token)?;
                    Value::Bytes(&bytes)
                }
                FieldKind::Reserved => {
                    bytes = read_hex(token).unwrap_or_default();
                    Value::Bytes(&bytes)
                }
            },
        };
        payload.set_value(index, value)?;
    }
    let mut buf = [0u8; ilahrs::frame::MAX_PAYLOAD];
    let n = payload.build(&mut buf)?;
    Ok(format!("ok {}", write_hex(&buf[..n])))
}

fn stream(chunks: &str, options: &Options) -> Answer {
    let mut decoder = StreamDecoder::new().with_strict(options.strict);
    let mut events: Vec<String> = Vec::new();
    let mut record = |event: ilahrs::Event<'_>| {
        let token = match event.sentence() {
            Some(_) => format!("N:{}", write_text(event.as_bytes())),
            None => format!("F:{}", write_hex(event.as_bytes())),
        };
        events.push(token);
    };
    let chunks: Vec<&str> = chunks
        .split(',')
        .filter(|chunk| !chunk.is_empty())
        .collect();
    if options.idle.iter().any(|(after, _)| *after >= chunks.len()) {
        return Err(Refusal::Unsupported);
    }
    for (index, chunk) in chunks.iter().enumerate() {
        decoder.feed(&read_hex(chunk)?, &mut record);
        for (_, us) in options.idle.iter().filter(|(after, _)| *after == index) {
            decoder.idle(Duration::from_micros(*us), &mut record);
        }
    }
    decoder.finish(&mut record);
    let listed = if events.is_empty() {
        "-".to_string()
    } else {
        events.join(",")
    };
    Ok(format!(
        "ok discarded={} events={listed}",
        decoder.discarded()
    ))
}

/// `NAME=VALUE` tokens, and a lookup of the value named `name` (unsupported when absent).
fn read_pairs<'a>(pairs: &[&'a str]) -> Result<impl Fn(&str) -> Result<&'a str, Refusal>, Refusal> {
    let mut values: Vec<(&str, &str)> = Vec::new();
    for pair in pairs {
        values.push(pair.split_once('=').ok_or(Refusal::Unsupported)?);
    }
    Ok(move |name: &str| {
        values
            .iter()
            .find(|(key, _)| *key == name)
            .map(|(_, token)| *token)
            .ok_or(Refusal::Unsupported)
    })
}

/// An INT token; one beyond 64 bits (or not a number) saturates, so that range checks refuse it.
fn read_int(token: &str) -> i64 {
    match token.parse::<i64>() {
        Ok(value) => value,
        Err(_) if token.starts_with('-') => i64::MIN,
        Err(_) => i64::MAX,
    }
}

fn read_hex(token: &str) -> Result<Vec<u8>, Refusal> {
    if token == "-" {
        return Ok(Vec::new());
    }
    let digits = token.as_bytes();
    if !digits.len().is_multiple_of(2) {
        return Err(Refusal::Unsupported);
    }
    digits
        .chunks(2)
        .map(|pair| {
            let text = std::str::from_utf8(pair).map_err(|_| Refusal::Unsupported)?;
            u8::from_str_radix(text, 16).map_err(|_| Refusal::Unsupported)
        })
        .collect()
}

fn write_hex(data: &[u8]) -> String {
    if data.is_empty() {
        return "-".to_string();
    }
    data.iter().map(|byte| format!("{byte:02X}")).collect()
}

fn read_text(token: &str) -> Result<Vec<u8>, Refusal> {
    let bytes = token.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut index = 0;
    while let Some(&byte) = bytes.get(index) {
        if byte == b'%' {
            let pair = bytes.get(index + 1..index + 3);
            let pair = pair.ok_or(Refusal::Unsupported)?;
            let text = std::str::from_utf8(pair).map_err(|_| Refusal::Unsupported)?;
            out.push(u8::from_str_radix(text, 16).map_err(|_| Refusal::Unsupported)?);
            index += 3;
        } else {
            out.push(byte);
            index += 1;
        }
    }
    Ok(out)
}

fn write_text(data: &[u8]) -> String {
    data.iter()
        .map(|&byte| match byte {
            b'%' | b',' | b'=' => format!("%{byte:02X}"),
            0x21..=0x7E => char::from(byte).to_string(),
            _ => format!("%{byte:02X}"),
        })
        .collect()
}

/// A number: `nan`, `inf`, `-inf`, or the shortest decimal that reads back to the same value
/// (as a float32 when `single`).
fn write_num(value: f64, single: bool) -> String {
    if value.is_nan() {
        "nan".to_string()
    } else if value.is_infinite() {
        if value > 0.0 { "inf" } else { "-inf" }.to_string()
    } else if single {
        format!("{}", value as f32)
    } else {
        format!("{value}")
    }
}
