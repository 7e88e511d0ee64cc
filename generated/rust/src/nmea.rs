// Copied from generator/targets/rust/runtime/crate/nmea.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! The $PAHR sentence: `$`, the identifier, comma-separated decimal and hex fields, `*`, two hex
//! checksum digits, CR LF (the spec's `nmea`; its fields in [`PahrSentence`]).
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
//! let sentence = PahrSentence::default();
//! let mut buf = [0u8; ilahrs::nmea::MAX_LENGTH];
//! let n = sentence.build(&mut buf)?;
//! assert_eq!(PahrSentence::parse(&buf[..n])?, sentence);
//! # Ok::<(), ilahrs::Error>(())
//! ```

use crate::error::{Detail, Error, ErrorKind, Float, Result};

mod fields;

use fields::FIELDS;
pub use fields::{PahrSentence, FIELD_COUNT, IDENTIFIER, MAX_LENGTH, MAX_RATE_HZ, PREFIX};

/// `*`, two checksum digits, CR, LF (bytes).
const TAIL: usize = 5;

/// [`PREFIX`] as text, for the detail of an error.
const PREFIX_TEXT: &str = match core::str::from_utf8(PREFIX) {
    Ok(text) => text,
    Err(_) => "the identifier",
};

/// How a field is written.
#[derive(Clone, Copy)]
pub(crate) enum Format {
    /// An optional `-`, digits, and up to `decimals` fraction digits; the value is scaled by
    /// 10^decimals.
    Decimal { width: usize, decimals: u32 },
    /// 1 to `width` hex digits.
    Hex { width: usize },
}

/// What a field is and which values it takes.
#[derive(Clone, Copy)]
pub(crate) struct FieldSpec {
    name: &'static str,
    format: Format,
    min: i64,
    max: i64,
}

impl FieldSpec {
    /// A decimal field: `width` integer characters (the sign counting as one), `decimals`
    /// fraction digits, its scaled value in `min..=max`.
    pub(crate) const fn decimal(
        name: &'static str,
        width: usize,
        decimals: u32,
        min: i64,
        max: i64,
    ) -> FieldSpec {
        let format = Format::Decimal { width, decimals };
        FieldSpec {
            name,
            format,
            min,
            max,
        }
    }

    /// What the field's text must be, for the detail of an error.
    const fn grammar(&self) -> &'static str {
        match self.format {
            Format::Decimal { .. } => "a decimal number",
            Format::Hex { .. } => "hex digits",
        }
    }

    /// The detail of the scaled value `value` outside the field's range.
    const fn outside(&self, value: i64) -> Detail {
        let (min, max) = (self.min, self.max);
        Detail::Range { value, min, max }
    }

    /// A hex field of 1 to `width` digits, its value in `min..=max`.
    pub(crate) const fn hex(name: &'static str, width: usize, min: i64, max: i64) -> FieldSpec {
        let format = Format::Hex { width };
        FieldSpec {
            name,
            format,
            min,
            max,
        }
    }
}

/// The sentence checksum of `body`: the XOR of its bytes.
pub fn checksum(body: &[u8]) -> u8 {
    // Eight bytes at a time, then the lanes folded into one byte.
    let mut words = body.chunks_exact(8);
    let lanes = words.by_ref().fold(0u64, |lanes, word| {
        lanes ^ u64::from_le_bytes(word.try_into().unwrap_or([0; 8]))
    });
    let lanes = lanes ^ (lanes >> 32);
    let lanes = lanes ^ (lanes >> 16);
    let lanes = lanes ^ (lanes >> 8);
    let rest = words.remainder().iter();
    rest.fold((lanes & 0xFF) as u8, |sum, byte| sum ^ byte)
}

impl PahrSentence {
    /// Decodes exactly one sentence, `$` through CR LF.
    ///
    /// Checks, in order: `$` (`bad_header` at 0), the identifier and comma (`bad_header` at 1),
    /// the CR LF end (`truncated`, `bad_length` at [`MAX_LENGTH`], `trailing_data`), `*` and two hex
    /// digits before it (`malformed`), the checksum (`bad_checksum` at its first digit), the
    /// number of fields (`malformed`), then each field's grammar (`malformed`) and range
    /// (`out_of_range`), naming the field, at its offset. Each error's detail says what was
    /// found and what was expected.
    pub fn parse(data: &[u8]) -> Result<PahrSentence> {
        let size = data.len();
        let expected = Detail::Expected(PREFIX_TEXT);
        let truncated = |expected| Error::at(ErrorKind::Truncated, size).with_detail(expected);
        match (data.first(), PREFIX.first()) {
            (None, _) => return Err(truncated(expected)),
            (Some(&found), Some(&start)) if found != start => {
                let detail = Detail::Byte {
                    found,
                    expected: start,
                };
                return Err(Error::at(ErrorKind::BadHeader, 0).with_detail(detail));
            }
            _ => {}
        }
        if !PREFIX.starts_with(data.get(..PREFIX.len()).unwrap_or(data)) {
            return Err(Error::at(ErrorKind::BadHeader, 1).with_detail(expected));
        }
        if size < PREFIX.len() {
            return Err(truncated(expected));
        }
        let too_long = |size| {
            let detail = Detail::Limit {
                size,
                max: MAX_LENGTH,
            };
            Error::at(ErrorKind::BadLength, MAX_LENGTH).with_detail(detail)
        };
        let Some(crlf) = data.windows(2).position(|pair| pair == b"\r\n") else {
            if size > MAX_LENGTH {
                return Err(too_long(size));
            }
            return Err(truncated(Detail::Expected("CR LF")));
        };
        let end = crlf + 2;
        if end > MAX_LENGTH {
            return Err(too_long(end));
        }
        if end < size {
            let detail = Detail::Size {
                size,
                expected: end,
            };
            return Err(Error::at(ErrorKind::TrailingData, end).with_detail(detail));
        }
        parse_body(data)
    }

    /// The sentence with these scaled values (sentence order), checked against the ranges.
    pub(crate) fn from_scaled(values: [i64; FIELD_COUNT]) -> Result<PahrSentence> {
        let sentence = PahrSentence::from_checked(values)?;
        sentence.validate()?;
        Ok(sentence)
    }

    /// Checks every field against its range, in sentence order: `out_of_range` naming the
    /// field (no offset), its detail the scaled value and range.
    pub fn validate(&self) -> Result<()> {
        for (value, spec) in self.scaled().into_iter().zip(FIELDS.iter()) {
            if value < spec.min || value > spec.max {
                let error = Error::new(ErrorKind::OutOfRange).with_field(spec.name);
                return Err(error.with_detail(spec.outside(value)));
            }
        }
        Ok(())
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
    /// the sentence would exceed [`MAX_LENGTH`] bytes, `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let mut scratch = [0u8; MAX_LENGTH];
        let mut out = Cursor::new(&mut scratch);
        self.write(&mut out);
        let size = out.len;
        if size > MAX_LENGTH {
            let detail = Detail::Limit {
                size,
                max: MAX_LENGTH,
            };
            return Err(Error::new(ErrorKind::BadLength).with_detail(detail));
        }
        let available = buf.len();
        let target = buf
            .get_mut(..size)
            .ok_or(crate::frame::too_small(available, size))?;
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

/// Decodes a sentence whose prefix, CR LF end and length are already checked: `data` starts
/// with [`PREFIX`], ends with its first CR LF and holds at most [`MAX_LENGTH`] bytes. The
/// remaining checks of [`PahrSentence::parse`], in its order, in one pass over the fields.
pub(crate) fn parse_body(data: &[u8]) -> Result<PahrSentence> {
    let malformed =
        |at, what| Error::at(ErrorKind::Malformed, at).with_detail(Detail::Expected(what));
    let star = match data.len().checked_sub(TAIL) {
        Some(star) if star >= PREFIX.len() && data.get(star) == Some(&b'*') => star,
        Some(star) => return Err(malformed(star, "*CC before CR LF")),
        None => return Err(malformed(0, "*CC before CR LF")),
    };
    let sent = match data.get(star + 1..star + 3) {
        Some(&[high, low]) => match (hex_digit(high), hex_digit(low)) {
            (Some(high), Some(low)) => high << 4 | low,
            _ => return Err(malformed(star + 1, "two hex digits")),
        },
        _ => return Err(malformed(star + 1, "two hex digits")),
    };
    // The fields run to the star.
    let body = data.get(..star).unwrap_or(&[]);
    let computed = checksum(body.get(1..).unwrap_or(&[]));
    if computed != sent {
        let detail = Detail::Checksum {
            sent: u16::from(sent),
            computed: u16::from(computed),
        };
        return Err(Error::at(ErrorKind::BadChecksum, star + 1).with_detail(detail));
    }
    #[cfg(not(feature = "small"))]
    if data.len() == canonical::LENGTH {
        if let Some(values) = canonical::values(body) {
            return PahrSentence::from_checked(values);
        }
    }
    // Each field in turn; the first bad one is reported once the fields are counted.
    let mut values = [0i64; FIELD_COUNT];
    let mut first_error = None;
    let mut count = 0;
    let mut at = PREFIX.len();
    loop {
        let start = at;
        match (FIELDS.get(count), values.get_mut(count)) {
            (Some(spec), Some(slot)) if first_error.is_none() => {
                let value;
                (value, at) = match spec.format {
                    Format::Decimal { decimals, .. } => read_decimal(body, at, decimals),
                    Format::Hex { width } => read_hex(body, at, width),
                };
                match value {
                    None => {
                        let error = Error::at(ErrorKind::Malformed, start).with_field(spec.name);
                        first_error = Some(error.with_detail(Detail::Expected(spec.grammar())));
                    }
                    Some(value) if value < spec.min || value > spec.max => {
                        let error = Error::at(ErrorKind::OutOfRange, start).with_field(spec.name);
                        first_error = Some(error.with_detail(spec.outside(value)));
                    }
                    Some(value) => *slot = value,
                }
            }
            _ => at = skip_field(body, at),
        }
        count += 1;
        if at >= body.len() {
            break;
        }
        at += 1;
    }
    if count != FIELD_COUNT {
        let detail = Detail::Fields {
            count,
            expected: FIELD_COUNT,
        };
        return Err(Error::at(ErrorKind::Malformed, PREFIX.len()).with_detail(detail));
    }
    if let Some(error) = first_error {
        return Err(error);
    }
    PahrSentence::from_checked(values)
}

/// The fast path for sentences in the layout builders write (E16: every field at its template
/// width, so one length and fixed positions, derived here from the field table): fields read
/// without a branch per character. It accepts only what the general path accepts, with the same
/// values; on anything else it steps aside and the general path decides and names the error.
/// The `small` feature leaves it out.
#[cfg(not(feature = "small"))]
pub(crate) mod canonical {
    use super::{checksum, hex_digit, Format, PahrSentence, FIELDS, FIELD_COUNT, PREFIX, TAIL};

    /// The characters a field takes.
    const fn width(format: Format) -> usize {
        match format {
            Format::Decimal { width, decimals: 0 } | Format::Hex { width } => width,
            Format::Decimal { width, decimals } => width + 1 + decimals as usize,
        }
    }

    /// Where each field starts.
    const STARTS: [usize; FIELD_COUNT] = {
        let mut starts = [0; FIELD_COUNT];
        let mut at = PREFIX.len();
        let mut index = 0;
        while index < FIELD_COUNT {
            starts[index] = at;
            at += width(FIELDS[index].format) + 1;
            index += 1;
        }
        starts
    };

    /// The length of a sentence, `$` through CR LF (bytes).
    pub(crate) const LENGTH: usize =
        STARTS[FIELD_COUNT - 1] + width(FIELDS[FIELD_COUNT - 1].format) + TAIL;

    /// The most characters of a decimal field the fast path reads (more could overflow its
    /// sums; such fields take the general path).
    const MAX_DECIMAL: usize = 18;
    /// The most digits of a hex field the fast path reads.
    const MAX_HEX: usize = 15;

    /// A whole sentence (`$` through CR LF, [`LENGTH`] bytes), or `None`. Every byte is checked,
    /// so such a sentence holds no earlier LF: the stream decoder may take it without looking
    /// for the end first.
    pub(crate) fn parse(data: &[u8]) -> Option<PahrSentence> {
        let star = LENGTH - TAIL;
        let (body, tail) = (data.get(..star)?, data.get(star..)?);
        let [b'*', high, low, b'\r', b'\n'] = *tail else {
            return None;
        };
        let sent = hex_digit(high)? << 4 | hex_digit(low)?;
        if !body.starts_with(PREFIX) || checksum(body.get(1..)?) != sent {
            return None;
        }
        PahrSentence::from_checked(values(body)?).ok()
    }

    /// The fields of `body` (`$` up to the star), in range, or `None`.
    pub(crate) fn values(body: &[u8]) -> Option<[i64; FIELD_COUNT]> {
        let mut ok = true;
        let values = super::fields::canonical_values(body, &STARTS, &mut ok);
        for ((value, spec), &at) in values.iter().zip(&FIELDS).zip(&STARTS) {
            ok &= *value >= spec.min && *value <= spec.max;
            ok &= body.get(at.wrapping_sub(1)) == Some(&b',');
        }
        ok.then_some(values)
    }

    /// A decimal field of `WIDTH` integer characters (a `-` counting as one where a digit
    /// follows it), `.` and `DECIMALS` digits at `body[at..]`, scaled by 10^DECIMALS; clears
    /// `ok` when it is not one.
    #[inline(always)]
    pub(super) fn decimal<const WIDTH: usize, const DECIMALS: u32>(
        body: &[u8],
        at: usize,
        ok: &mut bool,
    ) -> i64 {
        let size = width(Format::Decimal {
            width: WIDTH,
            decimals: DECIMALS,
        });
        let Some(text) = body.get(at..at + size).filter(|_| size <= MAX_DECIMAL) else {
            *ok = false;
            return 0;
        };
        let negative = WIDTH > 1 && text.first() == Some(&b'-');
        let mut magnitude = 0i64;
        for (index, byte) in text.iter().enumerate() {
            if index == WIDTH {
                *ok &= *byte == b'.';
            } else if !(negative && index == 0) {
                let digit = byte.wrapping_sub(b'0');
                *ok &= digit <= 9;
                magnitude = magnitude.wrapping_mul(10).wrapping_add(i64::from(digit));
            }
        }
        if negative {
            -magnitude
        } else {
            magnitude
        }
    }

    /// A hex field of `WIDTH` digits, either case, at `body[at..]`; clears `ok` when it is not
    /// one.
    #[inline(always)]
    pub(super) fn hex<const WIDTH: usize>(body: &[u8], at: usize, ok: &mut bool) -> i64 {
        let Some(text) = body.get(at..at + WIDTH).filter(|_| WIDTH <= MAX_HEX) else {
            *ok = false;
            return 0;
        };
        let mut value = 0i64;
        for byte in text {
            let digit = byte.wrapping_sub(b'0');
            let letter = (byte | 0x20).wrapping_sub(b'a');
            *ok &= digit <= 9 || letter <= 5;
            let digit = if digit <= 9 {
                digit
            } else {
                letter.wrapping_add(10)
            };
            value = value.wrapping_mul(16).wrapping_add(i64::from(digit));
        }
        value
    }
}

/// Magnitudes saturate here, far above every field's range (and far below `i64::MAX`).
const SATURATED: u64 = 1 << 56;

/// The index of the separator or end that closes the field at `at`.
fn skip_field(body: &[u8], at: usize) -> usize {
    let rest = body.get(at..).unwrap_or(&[]);
    at + rest
        .iter()
        .position(|byte| *byte == b',')
        .unwrap_or(rest.len())
}

/// Appends the decimal digits at `body[at..]` to `value`: the new value and where the digits end.
fn digits(body: &[u8], mut at: usize, mut value: u64) -> (u64, usize) {
    while let Some(digit) = body
        .get(at)
        .map(|byte| byte.wrapping_sub(b'0'))
        .filter(|d| *d <= 9)
    {
        value = if value < SATURATED {
            value * 10 + u64::from(digit)
        } else {
            SATURATED
        };
        at += 1;
    }
    (value, at)
}

/// The decimal field at `body[at..]`, scaled by 10^decimals (saturating for absurdly long
/// numbers, which then fail the range check), or `None` when it does not follow the grammar:
/// an optional `-`, one or more digits, and optionally `.` with 1 to `decimals` digits. Also
/// returns where the field ends (its separator, or the end of `body`).
fn read_decimal(body: &[u8], at: usize, decimals: u32) -> (Option<i64>, usize) {
    let negative = body.get(at) == Some(&b'-');
    let first = at + usize::from(negative);
    let (mut value, mut end) = digits(body, first, 0);
    let mut ok = end > first;
    let mut places = decimals;
    if body.get(end) == Some(&b'.') {
        let point = end;
        (value, end) = digits(body, point + 1, value);
        let fraction = end - point - 1;
        ok = ok && fraction >= 1 && fraction <= decimals as usize;
        places = decimals.saturating_sub(fraction as u32);
    }
    for _ in 0..places {
        value = if value < SATURATED {
            value * 10
        } else {
            SATURATED
        };
    }
    if end < body.len() && body.get(end) != Some(&b',') {
        return (None, skip_field(body, end));
    }
    let value = value.min(SATURATED) as i64;
    (ok.then_some(if negative { -value } else { value }), end)
}

/// The hex field of 1 to `width` digits, either case, at `body[at..]`, or `None`; and where the
/// field ends.
fn read_hex(body: &[u8], at: usize, width: usize) -> (Option<i64>, usize) {
    let mut value = 0u64;
    let mut end = at;
    while let Some(digit) = body.get(end).and_then(|byte| hex_digit(*byte)) {
        value = if value < SATURATED {
            value * 16 + u64::from(digit)
        } else {
            SATURATED
        };
        end += 1;
    }
    let ok = end > at && end - at <= width;
    if end < body.len() && body.get(end) != Some(&b',') {
        return (None, skip_field(body, end));
    }
    (ok.then_some(value.min(SATURATED) as i64), end)
}

/// The error for a bad value of field `index`.
pub(crate) fn refuse(index: usize) -> Error {
    match FIELDS.get(index) {
        Some(spec) => Error::new(ErrorKind::OutOfRange).with_field(spec.name),
        None => Error::new(ErrorKind::OutOfRange),
    }
}

/// The error for the engineering value `value` of field `index`, which cannot be scaled (not
/// finite, or far too large): its detail the value and the field's range in the same unit.
pub(crate) fn refuse_engineering(index: usize, value: f64) -> Error {
    match FIELDS.get(index) {
        Some(spec) => {
            let scale = match spec.format {
                Format::Decimal { decimals, .. } => {
                    (0..decimals).fold(1.0, |scale, _| scale * 10.0)
                }
                Format::Hex { .. } => 1.0,
            };
            let detail = Detail::FloatRange {
                value: Float(value),
                min: Float(spec.min as f64 / scale),
                max: Float(spec.max as f64 / scale),
            };
            refuse(index).with_detail(detail)
        }
        None => refuse(index),
    }
}

/// `value` x `scale`, rounded half away from zero; `None` if not finite or too large.
pub(crate) fn scale_round(value: f64, scale: f64) -> Option<i64> {
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
    let digit = byte.wrapping_sub(b'0');
    let letter = (byte | 0x20).wrapping_sub(b'a');
    if digit <= 9 {
        Some(digit)
    } else if letter <= 5 {
        Some(letter + 10)
    } else {
        None
    }
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

#[cfg(test)]
mod tests {
    use super::{PahrSentence, FIELDS, MAX_LENGTH};

    #[test]
    fn sentences_round_trip_at_their_limits() {
        let low = PahrSentence::from_checked(FIELDS.map(|field| field.min)).unwrap();
        let high = PahrSentence::from_checked(FIELDS.map(|field| field.max)).unwrap();
        for sentence in [low, high, PahrSentence::default()] {
            let mut buf = [0u8; MAX_LENGTH];
            let n = sentence.build(&mut buf).unwrap();
            assert_eq!(n, sentence.buffer_len());
            assert_eq!(PahrSentence::parse(&buf[..n]).unwrap(), sentence);
            for cut in 0..n {
                assert!(PahrSentence::parse(&buf[..cut]).is_err());
            }
        }
    }
}
