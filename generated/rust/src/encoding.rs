// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Value encodings the ICD defines (the calendar date, the magnetic declination, calibration
//! success) and the named values of enumerated fields.

/// Named values of `calibration_type` fields (Table 6.14, Table 6.15).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CalibrationType {
    /// 1: 2D calibration.
    TwoD,
    /// 2: 2D-2T calibration.
    TwoDTwoT,
    /// 3: 3D calibration.
    ThreeD,
}

impl CalibrationType {
    /// Every named value, in the spec's order.
    pub const ALL: [CalibrationType; 3] = [
        CalibrationType::TwoD,
        CalibrationType::TwoDTwoT,
        CalibrationType::ThreeD,
    ];

    /// The value with raw code `raw`, if it is a named one.
    pub const fn from_raw(raw: u8) -> Option<CalibrationType> {
        match raw {
            1 => Some(CalibrationType::TwoD),
            2 => Some(CalibrationType::TwoDTwoT),
            3 => Some(CalibrationType::ThreeD),
            _ => None,
        }
    }

    /// The raw code sent on the wire.
    pub const fn raw(self) -> u8 {
        match self {
            CalibrationType::TwoD => 1,
            CalibrationType::TwoDTwoT => 2,
            CalibrationType::ThreeD => 3,
        }
    }

    /// The value's name in the spec.
    pub const fn name(self) -> &'static str {
        match self {
            CalibrationType::TwoD => "two_d",
            CalibrationType::TwoDTwoT => "two_d_two_t",
            CalibrationType::ThreeD => "three_d",
        }
    }
}

/// Named values of `calibration_status_type` fields (Table 6.17).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CalibrationStatusType {
    /// 0: The AHRS is not calibrated.
    NotCalibrated,
    /// 1: 2D calibration.
    TwoD,
    /// 2: 2D-2T calibration.
    TwoDTwoT,
    /// 3: 3D calibration.
    ThreeD,
}

impl CalibrationStatusType {
    /// Every named value, in the spec's order.
    pub const ALL: [CalibrationStatusType; 4] = [
        CalibrationStatusType::NotCalibrated,
        CalibrationStatusType::TwoD,
        CalibrationStatusType::TwoDTwoT,
        CalibrationStatusType::ThreeD,
    ];
    /// Raw values above this one mean "parameters loaded by other software" (Table 6.17).
    pub const EXTERNAL_ABOVE: u8 = 0x80;

    /// The value with raw code `raw`, if it is a named one.
    pub const fn from_raw(raw: u8) -> Option<CalibrationStatusType> {
        match raw {
            0 => Some(CalibrationStatusType::NotCalibrated),
            1 => Some(CalibrationStatusType::TwoD),
            2 => Some(CalibrationStatusType::TwoDTwoT),
            3 => Some(CalibrationStatusType::ThreeD),
            _ => None,
        }
    }

    /// The raw code sent on the wire.
    pub const fn raw(self) -> u8 {
        match self {
            CalibrationStatusType::NotCalibrated => 0,
            CalibrationStatusType::TwoD => 1,
            CalibrationStatusType::TwoDTwoT => 2,
            CalibrationStatusType::ThreeD => 3,
        }
    }

    /// The value's name in the spec.
    pub const fn name(self) -> &'static str {
        match self {
            CalibrationStatusType::NotCalibrated => "not_calibrated",
            CalibrationStatusType::TwoD => "two_d",
            CalibrationStatusType::TwoDTwoT => "two_d_two_t",
            CalibrationStatusType::ThreeD => "three_d",
        }
    }

    /// True if `raw` is above [`Self::EXTERNAL_ABOVE`].
    pub const fn is_external(raw: u8) -> bool {
        raw > Self::EXTERNAL_ABOVE
    }
}

/// A calendar date, sent as a float: Year + (Month - 1)/12 + Day/365, as a float. (Table 6.9, Table 6.10, Table 6.13).
///
/// Decoding (`nearest_calendar_date`) returns the valid calendar date whose encoding is nearest
/// the float, because the formula overlaps months and years (day 31 encodes above the next month's
/// day 0, E15).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Date {
    /// Year (years), 1900 to 2199.
    pub year: u16,
    /// Month, 1 to 12.
    pub month: u8,
    /// Day of the month, 1 to 31.
    pub day: u8,
}

impl Date {
    /// The first year a date may have (years).
    pub const YEAR_MIN: u16 = 1900;
    /// The last year a date may have (years).
    pub const YEAR_MAX: u16 = 2199;

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

    /// The encoding as a double, before rounding to float32 (fractional years).
    pub fn encoded_f64(self) -> f64 {
        let mut value = 0.0;
        value += f64::from(self.year);
        value += f64::from(i32::from(self.month) + (-1)) / 12.0;
        value += f64::from(self.day) / 365.0;
        value
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

/// The magnetic declination field (Table 6.9): Magnetic declination in degrees; any value greater than 360 asks the AHRS to compute it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Declination {
    /// A declination (degrees), -180 to 180.
    Degrees(f32),
    /// Any value above 360: the AHRS computes the declination from position and date.
    Computed,
}

impl Declination {
    /// The least declination a builder accepts (degrees).
    pub const MIN: f64 = -180.0;
    /// The greatest declination a builder accepts (degrees).
    pub const MAX: f64 = 180.0;
    /// Values above this ask the AHRS to compute the declination (degrees).
    pub const COMPUTE_ABOVE: f64 = 360.0;
    /// The value builders send for [`Declination::Computed`] (degrees).
    pub const COMPUTE_VALUE: f32 = 999.0;

    /// What a raw field value (degrees) means.
    pub fn decode(raw: f32) -> Declination {
        if f64::from(raw) > Self::COMPUTE_ABOVE {
            Declination::Computed
        } else {
            Declination::Degrees(raw)
        }
    }

    /// The raw value to send (degrees), or `None` for degrees outside the range.
    pub fn encode(self) -> Option<f32> {
        match self {
            Declination::Computed => Some(Self::COMPUTE_VALUE),
            Declination::Degrees(degrees) if Self::accepts(f64::from(degrees)) => Some(degrees),
            Declination::Degrees(_) => None,
        }
    }

    /// True if a builder accepts `raw` (degrees): inside the range, or above the threshold.
    pub fn accepts(raw: f64) -> bool {
        (Self::MIN..=Self::MAX).contains(&raw) || raw > Self::COMPUTE_ABOVE
    }
}

/// The calibration success field (Tables 6.14, 6.15, 6.17 and the notes below them): 0: not successful; 1..254: predicted maximum (3 sigma) heading error, deg*10 (since firmware 4.9.9.0); 255: successful, no estimate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CalibrationSuccess {
    /// 0: the calibration did not succeed.
    Failed,
    /// Success, with the predicted heading error in tenths of the accuracy unit (raw value).
    Accuracy(u8),
    /// 255: success, without an accuracy estimate.
    NoEstimate,
}

impl CalibrationSuccess {
    /// What a raw field value means.
    pub const fn decode(raw: u8) -> CalibrationSuccess {
        match raw {
            0 => CalibrationSuccess::Failed,
            255 => CalibrationSuccess::NoEstimate,
            accuracy => CalibrationSuccess::Accuracy(accuracy),
        }
    }

    /// The raw field value.
    pub const fn encode(self) -> u8 {
        match self {
            CalibrationSuccess::Failed => 0,
            CalibrationSuccess::NoEstimate => 255,
            CalibrationSuccess::Accuracy(accuracy) => accuracy,
        }
    }

    /// True unless the calibration failed.
    pub const fn is_success(self) -> bool {
        match self {
            CalibrationSuccess::Failed => false,
            CalibrationSuccess::Accuracy(_) | CalibrationSuccess::NoEstimate => true,
        }
    }

    /// The predicted heading error (degrees), when the device sent one.
    pub fn accuracy_deg(self) -> Option<f64> {
        match self {
            CalibrationSuccess::Accuracy(accuracy) => Some(f64::from(accuracy) / 10.0),
            _ => None,
        }
    }
}
