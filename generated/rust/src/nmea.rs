// Generated from spec/ilahrs.yaml, spec hash b29217e2acd36b99c3446f15c5c54dd170e9aaaecfe9535ae7c08a1ac85716ef.
// Do not edit: change the spec or the generator and run `make generate`.

//! The $PAHR sentence (Table 6.7, section 6.2): `$PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC<CR><LF>`.
//!
//! Values are held as integers scaled by 10^decimals (roll 12.34 degrees is 1234), so parsing
//! and building are exact and need no floating point. Building zero-pads each decimal field's
//! integer part to its template width, the sign counting as one character, and writes hex in
//! upper case; parsing accepts any number of integer digits, 1 to `decimals` fraction digits
//! and either hex case. Neither allocates: [`PahrSentence::build`] writes into a caller's buffer.
//!
//! ```
//! use ilahrs::PahrSentence;
//!
//! let sentence = PahrSentence {
//!     roll: 9000,
//!     pitch: 4500,
//!     heading: 17999,
//!     temperature: 4999,
//!     vdd: 499,
//!     usw: 32767,
//! };
//! let mut buf = [0u8; ilahrs::nmea::MAX_LENGTH];
//! let n = sentence.build(&mut buf)?;
//! assert_eq!(PahrSentence::parse(&buf[..n])?, sentence);
//! # Ok::<(), ilahrs::Error>(())
//! ```

use crate::error::{Error, ErrorKind, Result};

/// The identifier after `$`.
pub const IDENTIFIER: &[u8] = b"PAHR";
/// What every sentence starts with: `$`, the identifier and a comma.
pub const PREFIX: &[u8] = b"$PAHR,";
/// The longest sentence, `$` through CR LF (bytes).
pub const MAX_LENGTH: usize = 82;
/// The most sentences the AHRS sends per second (Hz).
pub const MAX_RATE_HZ: u32 = 50;
/// The number of fields.
pub const FIELD_COUNT: usize = 6;
/// `*`, two checksum digits, CR, LF (bytes).
const TAIL: usize = 5;

/// How a field is written.
#[derive(Clone, Copy)]
enum Format {
    /// An optional `-`, digits, and up to `decimals` fraction digits; the value is scaled by
    /// 10^decimals.
    Decimal { width: usize, decimals: u32 },
    /// 1 to `width` hex digits.
    Hex { width: usize },
}

/// What a field is and which values it takes.
#[derive(Clone, Copy)]
struct FieldSpec {
    name: &'static str,
    format: Format,
    min: i64,
    max: i64,
}

/// The fields, in sentence order.
const FIELDS: [FieldSpec; FIELD_COUNT] = [
    FieldSpec {
        name: "roll",
        format: Format::Decimal {
            width: 4,
            decimals: 2,
        },
        min: -18000,
        max: 18000,
    },
    FieldSpec {
        name: "pitch",
        format: Format::Decimal {
            width: 3,
            decimals: 2,
        },
        min: -9000,
        max: 9000,
    },
    FieldSpec {
        name: "heading",
        format: Format::Decimal {
            width: 3,
            decimals: 2,
        },
        min: 0,
        max: 35999,
    },
    FieldSpec {
        name: "temperature",
        format: Format::Decimal {
            width: 3,
            decimals: 1,
        },
        min: -999,
        max: 9999,
    },
    FieldSpec {
        name: "vdd",
        format: Format::Decimal {
            width: 1,
            decimals: 2,
        },
        min: 0,
        max: 999,
    },
    FieldSpec {
        name: "usw",
        format: Format::Hex { width: 4 },
        min: 0,
        max: 65535,
    },
];

/// A $PAHR sentence: every field as a scaled integer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct PahrSentence {
    /// `RRRR.rr`: Roll, hundredths of a degree. Scaled by 100, -18000 to 18000.
    pub roll: i32,
    /// `PPP.pp`: Pitch, hundredths of a degree. Scaled by 100, -9000 to 9000.
    pub pitch: i32,
    /// `HHH.hh`: Heading, hundredths of a degree. Scaled by 100, 0 to 35999.
    pub heading: i32,
    /// `TTT.t`: Average accelerometer temperature, tenths of a degree Celsius. Scaled by 10, -999 to 9999.
    pub temperature: i32,
    /// `V.vv`: AHRS input voltage, hundredths of a volt. Scaled by 100, 0 to 999.
    pub vdd: i32,
    /// `SSSS`: Unit Status Word (section 6.5), four hex digits., 0 to 65535.
    pub usw: u16,
}

/// The sentence checksum of `body`: the XOR of its bytes.
pub fn checksum(body: &[u8]) -> u8 {
    body.iter().fold(0, |sum, byte| sum ^ byte)
}

impl PahrSentence {
    /// Decodes exactly one sentence, `$` through CR LF.
    ///
    /// Checks, in order: `$` (`bad_header` at 0), the identifier and comma (`bad_header` at 1),
    /// the CR LF end (`truncated`, `bad_length` at 82, `trailing_data`), `*` and two hex
    /// digits before it (`malformed`), the checksum (`bad_checksum` at its first digit), the
    /// number of fields (`malformed`), then each field's grammar (`malformed`) and range
    /// (`out_of_range`), naming the field, at its offset.
    pub fn parse(data: &[u8]) -> Result<PahrSentence> {
        let size = data.len();
        match data.first() {
            None => return Err(Error::at(ErrorKind::Truncated, 0)),
            Some(first) if Some(first) != PREFIX.first() => {
                return Err(Error::at(ErrorKind::BadHeader, 0));
            }
            Some(_) => {}
        }
        if !PREFIX.starts_with(data.get(..PREFIX.len()).unwrap_or(data)) {
            return Err(Error::at(ErrorKind::BadHeader, 1));
        }
        if size < PREFIX.len() {
            return Err(Error::at(ErrorKind::Truncated, size));
        }
        let Some(crlf) = data.windows(2).position(|pair| pair == b"\r\n") else {
            if size > MAX_LENGTH {
                return Err(Error::at(ErrorKind::BadLength, MAX_LENGTH));
            }
            return Err(Error::at(ErrorKind::Truncated, size));
        };
        let end = crlf + 2;
        if end > MAX_LENGTH {
            return Err(Error::at(ErrorKind::BadLength, MAX_LENGTH));
        }
        if end < size {
            return Err(Error::at(ErrorKind::TrailingData, end));
        }
        let star = match end.checked_sub(TAIL) {
            Some(star) if star >= PREFIX.len() && data.get(star) == Some(&b'*') => star,
            Some(star) => return Err(Error::at(ErrorKind::Malformed, star)),
            None => return Err(Error::at(ErrorKind::Malformed, 0)),
        };
        let sent = match data.get(star + 1..star + 3) {
            Some(&[high, low]) => match (hex_digit(high), hex_digit(low)) {
                (Some(high), Some(low)) => high << 4 | low,
                _ => return Err(Error::at(ErrorKind::Malformed, star + 1)),
            },
            _ => return Err(Error::at(ErrorKind::Malformed, star + 1)),
        };
        if checksum(data.get(1..star).unwrap_or(&[])) != sent {
            return Err(Error::at(ErrorKind::BadChecksum, star + 1));
        }
        let body = data.get(PREFIX.len()..star).unwrap_or(&[]);
        // One pass over the body: where each field starts and ends (offsets into `data`).
        let mut spans = [(0usize, 0usize); FIELD_COUNT];
        let mut count = 0;
        let mut start = PREFIX.len();
        for part in body.split(|byte| *byte == b',') {
            if let Some(span) = spans.get_mut(count) {
                *span = (start, start + part.len());
            }
            count += 1;
            start += part.len() + 1;
        }
        if count != FIELD_COUNT {
            return Err(Error::at(ErrorKind::Malformed, PREFIX.len()));
        }
        let mut values = [0i64; FIELD_COUNT];
        for ((spec, &(from, to)), slot) in FIELDS.iter().zip(&spans).zip(&mut values) {
            let part = data.get(from..to).unwrap_or(&[]);
            let error = |kind| Error::at(kind, from).with_field(spec.name);
            let value = match spec.format {
                Format::Decimal { decimals, .. } => parse_decimal(part, decimals),
                Format::Hex { width } => parse_hex(part, width),
            };
            let value = value.ok_or(error(ErrorKind::Malformed))?;
            if value < spec.min || value > spec.max {
                return Err(error(ErrorKind::OutOfRange));
            }
            *slot = value;
        }
        PahrSentence::from_scaled(values)
    }

    /// The sentence with these scaled values (sentence order), checked against the ranges.
    fn from_scaled(values: [i64; FIELD_COUNT]) -> Result<PahrSentence> {
        let roll = i32::try_from(values[0]);
        let pitch = i32::try_from(values[1]);
        let heading = i32::try_from(values[2]);
        let temperature = i32::try_from(values[3]);
        let vdd = i32::try_from(values[4]);
        let usw = u16::try_from(values[5]);
        let sentence = PahrSentence {
            roll: roll.map_err(|_| refuse(0))?,
            pitch: pitch.map_err(|_| refuse(1))?,
            heading: heading.map_err(|_| refuse(2))?,
            temperature: temperature.map_err(|_| refuse(3))?,
            vdd: vdd.map_err(|_| refuse(4))?,
            usw: usw.map_err(|_| refuse(5))?,
        };
        sentence.validate()?;
        Ok(sentence)
    }

    /// The scaled values, in sentence order.
    fn scaled(&self) -> [i64; FIELD_COUNT] {
        [
            i64::from(self.roll),
            i64::from(self.pitch),
            i64::from(self.heading),
            i64::from(self.temperature),
            i64::from(self.vdd),
            i64::from(self.usw),
        ]
    }

    /// Checks every field against its range, in sentence order: `out_of_range` naming the
    /// field (no offset).
    pub fn validate(&self) -> Result<()> {
        for (index, (value, spec)) in self.scaled().into_iter().zip(FIELDS.iter()).enumerate() {
            if value < spec.min || value > spec.max {
                return Err(refuse(index));
            }
        }
        Ok(())
    }

    /// The sentence from engineering values, each rounded half away from zero to its
    /// resolution. Errors: `out_of_range` naming the first field that is not finite or is
    /// outside its range.
    pub fn from_engineering(
        roll_deg: f64,
        pitch_deg: f64,
        heading_deg: f64,
        temperature_degc: f64,
        vdd_v: f64,
        usw: u16,
    ) -> Result<PahrSentence> {
        let values = [
            scale_round(roll_deg, 100.0).ok_or(refuse(0))?,
            scale_round(pitch_deg, 100.0).ok_or(refuse(1))?,
            scale_round(heading_deg, 100.0).ok_or(refuse(2))?,
            scale_round(temperature_degc, 10.0).ok_or(refuse(3))?,
            scale_round(vdd_v, 100.0).ok_or(refuse(4))?,
            i64::from(usw),
        ];
        PahrSentence::from_scaled(values)
    }

    /// `RRRR.rr` in degrees.
    pub fn roll_deg(&self) -> f64 {
        f64::from(self.roll) / 100.0
    }

    /// `PPP.pp` in degrees.
    pub fn pitch_deg(&self) -> f64 {
        f64::from(self.pitch) / 100.0
    }

    /// `HHH.hh` in degrees.
    pub fn heading_deg(&self) -> f64 {
        f64::from(self.heading) / 100.0
    }

    /// `TTT.t` in degrees Celsius.
    pub fn temperature_degc(&self) -> f64 {
        f64::from(self.temperature) / 10.0
    }

    /// `V.vv` in volts DC.
    pub fn vdd_v(&self) -> f64 {
        f64::from(self.vdd) / 100.0
    }

    /// The size of the sentence [`PahrSentence::build`] writes, `$` through CR LF (bytes).
    pub fn buffer_len(&self) -> usize {
        let mut scratch = [0u8; MAX_LENGTH];
        let mut out = Cursor::new(&mut scratch);
        self.write(&mut out);
        out.len
    }

    /// Checks the ranges ([`PahrSentence::validate`]) and writes the sentence, `$` through
    /// CR LF, into `buf`; returns its size (bytes). Errors: `out_of_range`, `bad_length` if
    /// the sentence would exceed 82 bytes, `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let mut scratch = [0u8; MAX_LENGTH];
        let mut out = Cursor::new(&mut scratch);
        self.write(&mut out);
        let size = out.len;
        if size > MAX_LENGTH {
            return Err(Error::new(ErrorKind::BadLength));
        }
        let target = buf
            .get_mut(..size)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
        for (slot, byte) in target.iter_mut().zip(scratch.iter()) {
            *slot = *byte;
        }
        Ok(size)
    }

    /// Writes the sentence into `out` (which counts bytes past its end).
    fn write(&self, out: &mut Cursor<'_>) {
        for byte in PREFIX {
            out.push(*byte);
        }
        for (index, (value, spec)) in self.scaled().into_iter().zip(FIELDS.iter()).enumerate() {
            if index > 0 {
                out.push(b',');
            }
            match spec.format {
                Format::Decimal { width, decimals } => out.decimal(value, width, decimals),
                Format::Hex { width } => out.hex(value.unsigned_abs(), width),
            }
        }
        let star = out.len;
        let sum = checksum(out.buf.get(1..star).unwrap_or(&[]));
        out.push(b'*');
        out.hex(u64::from(sum), 2);
        out.push(b'\r');
        out.push(b'\n');
    }
}

/// The error for a bad value of field `index`.
fn refuse(index: usize) -> Error {
    match FIELDS.get(index) {
        Some(spec) => Error::new(ErrorKind::OutOfRange).with_field(spec.name),
        None => Error::new(ErrorKind::OutOfRange),
    }
}

/// `value` x `scale`, rounded half away from zero; `None` if not finite or too large.
fn scale_round(value: f64, scale: f64) -> Option<i64> {
    let scaled = value * scale;
    if !(scaled > -9.0e18 && scaled < 9.0e18) {
        return None;
    }
    if scaled >= 0.0 {
        Some((scaled + 0.5) as i64)
    } else {
        Some(-((-scaled + 0.5) as i64))
    }
}

/// The value of a hex digit, either case.
fn hex_digit(byte: u8) -> Option<u8> {
    match byte {
        b'0'..=b'9' => Some(byte - b'0'),
        b'a'..=b'f' => Some(byte - b'a' + 10),
        b'A'..=b'F' => Some(byte - b'A' + 10),
        _ => None,
    }
}

/// A decimal field scaled by 10^decimals (saturating for absurdly long numbers, which then
/// fail the range check), or `None` when it does not follow the grammar: an optional `-`, one
/// or more digits, and optionally `.` with 1 to `decimals` digits.
fn parse_decimal(text: &[u8], decimals: u32) -> Option<i64> {
    let (negative, body) = match text {
        [b'-', rest @ ..] => (true, rest),
        _ => (false, text),
    };
    let mut value: i64 = 0;
    let mut whole_digits = 0usize;
    let mut fraction_digits: Option<u32> = None;
    for &byte in body {
        match (byte, fraction_digits) {
            (b'0'..=b'9', None) => whole_digits += 1,
            (b'0'..=b'9', Some(count)) if count < decimals => fraction_digits = Some(count + 1),
            (b'.', None) => {
                fraction_digits = Some(0);
                continue;
            }
            _ => return None,
        }
        value = value.saturating_mul(10).saturating_add(digit_value(byte));
    }
    if whole_digits == 0 || fraction_digits == Some(0) {
        return None;
    }
    let places = decimals.saturating_sub(fraction_digits.unwrap_or(0));
    value = value.saturating_mul(10i64.saturating_pow(places));
    Some(if negative { -value } else { value })
}

/// The value of a decimal digit (0 for any other byte).
fn digit_value(byte: u8) -> i64 {
    i64::from(byte.saturating_sub(b'0'))
}

/// A hex field of 1 to `width` digits, either case, or `None`.
fn parse_hex(text: &[u8], width: usize) -> Option<i64> {
    if text.is_empty() || text.len() > width {
        return None;
    }
    let mut value: i64 = 0;
    for byte in text {
        let digit = i64::from(hex_digit(*byte)?);
        value = value.saturating_mul(16).saturating_add(digit);
    }
    Some(value)
}

/// Writes bytes into a buffer, counting (but dropping) what does not fit.
struct Cursor<'a> {
    buf: &'a mut [u8],
    len: usize,
}

impl<'a> Cursor<'a> {
    fn new(buf: &'a mut [u8]) -> Cursor<'a> {
        Cursor { buf, len: 0 }
    }

    fn push(&mut self, byte: u8) {
        if let Some(slot) = self.buf.get_mut(self.len) {
            *slot = byte;
        }
        self.len += 1;
    }

    /// `value` in base `radix`, upper case, zero-padded to `width` digits.
    fn digits(&mut self, value: u64, radix: u64, width: usize) {
        let mut scratch = [b'0'; 20];
        let mut count = 0;
        let mut rest = value;
        while rest > 0 || count == 0 {
            if let Some(slot) = scratch.get_mut(count) {
                let digit = b"0123456789ABCDEF".get((rest % radix) as usize);
                *slot = digit.copied().unwrap_or(b'0');
            }
            rest /= radix;
            count += 1;
        }
        for _ in count..width {
            self.push(b'0');
        }
        for index in (0..count).rev() {
            self.push(scratch.get(index).copied().unwrap_or(b'0'));
        }
    }

    fn hex(&mut self, value: u64, width: usize) {
        self.digits(value, 16, width);
    }

    /// A scaled decimal: the integer part zero-padded to `width` characters, the sign counting
    /// as one, then `.` and `decimals` fraction digits.
    fn decimal(&mut self, value: i64, width: usize, decimals: u32) {
        let scale = 10u64.saturating_pow(decimals);
        let magnitude = value.unsigned_abs();
        let mut width = width;
        if value < 0 {
            self.push(b'-');
            width = width.saturating_sub(1);
        }
        self.digits(magnitude / scale, 10, width);
        if decimals > 0 {
            self.push(b'.');
            self.digits(magnitude % scale, 10, decimals as usize);
        }
    }
}
