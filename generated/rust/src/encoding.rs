// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Value encodings the ICD defines (the calendar date, the magnetic declination, calibration
//! success) and the named values of enumerated fields.

mod calibration_success;
mod date;
mod declination;

pub use calibration_success::CalibrationSuccess;
pub use date::Date;
pub use declination::Declination;

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

    /// True if `raw` is above [`Self::EXTERNAL_ABOVE`].
    pub const fn is_external(raw: u8) -> bool {
        raw > Self::EXTERNAL_ABOVE
    }

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
}

impl Date {
    /// The first year a date may have (years).
    pub const YEAR_MIN: u16 = 1900;
    /// The last year a date may have (years).
    pub const YEAR_MAX: u16 = 2199;

    /// The encoding as a double, before rounding to float32 (fractional years): Year + (Month - 1)/12 + Day/365, as a float. (Table 6.9, Table 6.10, Table 6.13, E15).
    pub fn encoded_f64(self) -> f64 {
        let mut value = 0.0;
        value += f64::from(self.year);
        value += f64::from(i32::from(self.month) + (-1)) / 12.0;
        value += f64::from(self.day) / 365.0;
        value
    }
}

/// The declination field (Table 6.9): Magnetic declination in degrees; any value greater than 360 asks the AHRS to compute it.
impl Declination {
    /// The least declination a builder accepts (degrees).
    pub const MIN: f64 = -180.0;
    /// The greatest declination a builder accepts (degrees).
    pub const MAX: f64 = 180.0;
    /// Values above this ask the AHRS to compute the declination (degrees).
    pub const COMPUTE_ABOVE: f64 = 360.0;
    /// The value builders send for [`Declination::Computed`] (degrees).
    pub const COMPUTE_VALUE: f32 = 999.0;
}

/// The raw type of a calibration success field.
type CalibrationSuccessRaw = u8;

/// The calibration success field (Tables 6.14, 6.15, 6.17 and the notes below them): 0: not successful; 1..254: predicted maximum (3 sigma) heading error, deg*10 (since firmware 4.9.9.0); 255: successful, no estimate.
impl CalibrationSuccess {
    /// The code of a calibration that did not succeed.
    const FAILED: CalibrationSuccessRaw = 0;
    /// The code of a success without an accuracy estimate.
    const NO_ESTIMATE: CalibrationSuccessRaw = 255;
    /// Tenths: the raw accuracy divided by this is degrees.
    const ACCURACY_DIVISOR: f64 = 10.0;
}

/// What the encoding of a float field refuses in the raw value `raw`, or `None`.
pub(crate) fn refuses(
    encoding: Option<crate::payload::Encoding>,
    raw: f64,
) -> Option<crate::error::Detail> {
    match encoding {
        Some(crate::payload::Encoding::Declination) => Declination::refuses(raw),
        _ => {
            let _ = raw;
            None
        }
    }
}
