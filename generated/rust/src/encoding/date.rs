// Copied from generator/targets/rust/runtime/crate/encoding/date.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! Calendar dates as the ICD sends them: one float of fractional years.

use crate::error::Detail;

/// A calendar date, sent as a float (fractional years, see [`Date::encoded_f64`]).
///
/// Decoding (the spec's `nearest_calendar_date`) returns the valid calendar date whose encoding
/// is nearest the float, because the formula overlaps months and years (day 31 encodes above the
/// next month's day 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Date {
    /// Year (years), [`Date::YEAR_MIN`] to [`Date::YEAR_MAX`].
    pub year: u16,
    /// Month, 1 to 12.
    pub month: u8,
    /// Day of the month, 1 to 31.
    pub day: u8,
}

impl Date {
    /// The date `year`-`month`-`day` if it is a real calendar date inside the year range.
    pub const fn new(year: u16, month: u8, day: u8) -> Option<Date> {
        let date = Date { year, month, day };
        if date.is_valid() {
            Some(date)
        } else {
            None
        }
    }

    /// True if the date exists in the Gregorian calendar and its year is inside the range.
    pub const fn is_valid(self) -> bool {
        self.year >= Self::YEAR_MIN
            && self.year <= Self::YEAR_MAX
            && self.day >= 1
            && self.day <= days_in_month(self.year, self.month)
    }

    /// What [`Date::encode`] refuses in the date: the year outside the range, else the month,
    /// else the day outside its month; `None` for a valid date.
    pub const fn refusal(self) -> Option<Detail> {
        let (value, min, max) = if self.year < Self::YEAR_MIN || self.year > Self::YEAR_MAX {
            (
                self.year as i64,
                Self::YEAR_MIN as i64,
                Self::YEAR_MAX as i64,
            )
        } else if self.month < 1 || self.month > 12 {
            (self.month as i64, 1, 12)
        } else if self.day < 1 || self.day > days_in_month(self.year, self.month) {
            let days = days_in_month(self.year, self.month);
            (self.day as i64, 1, days as i64)
        } else {
            return None;
        };
        Some(Detail::Range { value, min, max })
    }

    /// The float sent on the wire (fractional years), or `None` for an invalid date.
    pub fn encode(self) -> Option<f32> {
        if self.is_valid() {
            Some(self.encoded_f64() as f32)
        } else {
            None
        }
    }

    /// The valid date whose encoding is nearest `value` (fractional years), or `None` when
    /// `value` is not finite or no year of the range is within one year of it.
    pub fn decode(value: f32) -> Option<Date> {
        let value = f64::from(value);
        if !(value > f64::from(Self::YEAR_MIN) - 2.0 && value < f64::from(Self::YEAR_MAX) + 2.0) {
            return None;
        }
        let whole = value as i32;
        let mut best: Option<(f64, Date)> = None;
        for year in (whole - 1)..=(whole + 1) {
            let Ok(year) = u16::try_from(year) else {
                continue;
            };
            for month in 1..=12 {
                for day in 1..=days_in_month(year, month) {
                    let date = Date { year, month, day };
                    if !date.is_valid() {
                        continue;
                    }
                    let distance = date.encoded_f64() - value;
                    let distance = if distance < 0.0 { -distance } else { distance };
                    match best {
                        Some((nearest, _)) if nearest <= distance => {}
                        _ => best = Some((distance, date)),
                    }
                }
            }
        }
        best.map(|(_, date)| date)
    }
}

/// Days in `month` of `year` (Gregorian), 0 for a month outside 1 to 12.
const fn days_in_month(year: u16, month: u8) -> u8 {
    match month {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        2 if (year % 4 == 0 && year % 100 != 0) || year % 400 == 0 => 29,
        2 => 28,
        _ => 0,
    }
}
