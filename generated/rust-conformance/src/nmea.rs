// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! The `nmea_decode` and `nmea_encode` requests: the $PAHR sentence's fields, by name.

use ilahrs::{ErrorKind, PahrSentence};

use crate::{read_int, read_pairs, write_num, write_text, Answer, Refusal};

/// Decodes a sentence and lists its fields: engineering values, hex fields as integers.
pub(crate) fn decode(text: &[u8]) -> Answer {
    let sentence = PahrSentence::parse(text)?;
    Ok(format!(
        "ok roll={} pitch={} heading={} temperature={} vdd={} usw={}",
        write_num(sentence.roll_deg(), false),
        write_num(sentence.pitch_deg(), false),
        write_num(sentence.heading_deg(), false),
        write_num(sentence.temperature_degc(), false),
        write_num(sentence.vdd_v(), false),
        sentence.usw,
    ))
}

/// Builds a sentence from `NAME=VALUE` pairs (every field given).
pub(crate) fn encode(pairs: &[&str]) -> Answer {
    let get = read_pairs(pairs)?;
    let roll: f64 = get("roll")?.parse().unwrap_or(f64::NAN);
    let pitch: f64 = get("pitch")?.parse().unwrap_or(f64::NAN);
    let heading: f64 = get("heading")?.parse().unwrap_or(f64::NAN);
    let temperature: f64 = get("temperature")?.parse().unwrap_or(f64::NAN);
    let vdd: f64 = get("vdd")?.parse().unwrap_or(f64::NAN);
    let usw_raw = read_int(get("usw")?);
    let usw = u16::try_from(usw_raw).unwrap_or_default();
    let sentence = PahrSentence::from_engineering(roll, pitch, heading, temperature, vdd, usw)?;
    if u16::try_from(usw_raw).is_err() {
        return Err(Refusal::Named(ErrorKind::OutOfRange, "usw".to_string()));
    }
    let mut buf = [0u8; ilahrs::nmea::MAX_LENGTH];
    let n = sentence.build(&mut buf)?;
    Ok(format!("ok {}", write_text(&buf[..n])))
}
