// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! The $PAHR sentence as the spec writes it (Table 6.7, section 6.2): `$PAHR,RRRR.rr,PPP.pp,HHH.hh,TTT.t,V.vv,SSSS*CC<CR><LF>`.

use super::{refuse, refuse_engineering, scale_round, FieldSpec};
use crate::error::Result;

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

/// The fields, in sentence order: name, template width, decimals, least and greatest scaled value.
pub(super) const FIELDS: [FieldSpec; FIELD_COUNT] = [
    FieldSpec::decimal("roll", 4, 2, -18000, 18000),
    FieldSpec::decimal("pitch", 3, 2, -9000, 9000),
    FieldSpec::decimal("heading", 3, 2, 0, 35999),
    FieldSpec::decimal("temperature", 3, 1, -999, 9999),
    FieldSpec::decimal("vdd", 1, 2, 0, 999),
    FieldSpec::hex("usw", 4, 0, 65535),
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

impl PahrSentence {
    /// The sentence with these scaled values (sentence order), already checked against the
    /// ranges.
    pub(super) fn from_checked(values: [i64; FIELD_COUNT]) -> Result<PahrSentence> {
        let [roll, pitch, heading, temperature, vdd, usw] = values;
        Ok(PahrSentence {
            roll: roll.try_into().map_err(|_| refuse(0))?,
            pitch: pitch.try_into().map_err(|_| refuse(1))?,
            heading: heading.try_into().map_err(|_| refuse(2))?,
            temperature: temperature.try_into().map_err(|_| refuse(3))?,
            vdd: vdd.try_into().map_err(|_| refuse(4))?,
            usw: usw.try_into().map_err(|_| refuse(5))?,
        })
    }

    /// The scaled values, in sentence order.
    pub(super) fn scaled(&self) -> [i64; FIELD_COUNT] {
        [
            i64::from(self.roll),
            i64::from(self.pitch),
            i64::from(self.heading),
            i64::from(self.temperature),
            i64::from(self.vdd),
            i64::from(self.usw),
        ]
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
            scale_round(roll_deg, 100.0).ok_or_else(|| refuse_engineering(0, roll_deg))?,
            scale_round(pitch_deg, 100.0).ok_or_else(|| refuse_engineering(1, pitch_deg))?,
            scale_round(heading_deg, 100.0).ok_or_else(|| refuse_engineering(2, heading_deg))?,
            scale_round(temperature_degc, 10.0)
                .ok_or_else(|| refuse_engineering(3, temperature_degc))?,
            scale_round(vdd_v, 100.0).ok_or_else(|| refuse_engineering(4, vdd_v))?,
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
}

/// The fields of a sentence in the builders' layout, each read at its start in `starts` by the
/// fast path's readers (which clear `ok` on a character out of place).
#[cfg(not(feature = "small"))]
#[inline(always)]
pub(super) fn canonical_values(
    body: &[u8],
    starts: &[usize; FIELD_COUNT],
    ok: &mut bool,
) -> [i64; FIELD_COUNT] {
    use super::canonical::{decimal, hex};
    [
        decimal::<4, 2>(body, starts[0], ok),
        decimal::<3, 2>(body, starts[1], ok),
        decimal::<3, 2>(body, starts[2], ok),
        decimal::<3, 1>(body, starts[3], ok),
        decimal::<1, 2>(body, starts[4], ok),
        hex::<4>(body, starts[5], ok),
    ]
}
