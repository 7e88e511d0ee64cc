// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.13, Calibration parameters (22 bytes).
//!
//! The data message the host sends right after Start3DClb, Start2D2TClb or Start2DClb (6.4.1,
//! 6.4.5, 6.4.8).

use crate::encoding::Date;
use crate::error::Result;
use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Unit, Value};

/// Size of the payload (bytes).
pub const SIZE: usize = 22;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Reserved, `f32`, degrees.
    pub const REFERENCE_AZIMUTH: Field = 0..4;
    /// Time of data accumulation in one run, `u16`, seconds.
    pub const ACCUMULATION_TIME: Field = 4..6;
    /// Latitude, `f32`, degrees.
    pub const LATITUDE: Field = 6..10;
    /// Longitude, `f32`, degrees.
    pub const LONGITUDE: Field = 10..14;
    /// Altitude, `f32`, metres.
    pub const ALTITUDE: Field = 14..18;
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`.
    pub const DATE: Field = 18..22;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Reserved, `f32`, degrees.
    pub const REFERENCE_AZIMUTH: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Reference azimuth (6.4.8); no influence on 2D calibration.",
        ..FieldInfo::new(
            "reference_azimuth",
            field::REFERENCE_AZIMUTH,
            FieldKind::Float,
        )
    };

    /// Time of data accumulation in one run, `u16`, seconds.
    pub const ACCUMULATION_TIME: FieldInfo = FieldInfo {
        icd_name: "Time of data accumulation in one run",
        min: 1.0,
        max: 65535.0,
        default: Value::Int(1),
        unit: Some(Unit::S),
        doc: "Data accumulation time of one run.",
        ..FieldInfo::new(
            "accumulation_time",
            field::ACCUMULATION_TIME,
            FieldKind::Unsigned,
        )
    };

    /// Latitude, `f32`, degrees.
    pub const LATITUDE: FieldInfo = FieldInfo {
        icd_name: "Latitude",
        min: -90.0,
        max: 90.0,
        unit: Some(Unit::Deg),
        doc: "Latitude.",
        ..FieldInfo::new("latitude", field::LATITUDE, FieldKind::Float)
    };

    /// Longitude, `f32`, degrees.
    pub const LONGITUDE: FieldInfo = FieldInfo {
        icd_name: "Longitude",
        min: -180.0,
        max: 180.0,
        unit: Some(Unit::Deg),
        doc: "Longitude.",
        ..FieldInfo::new("longitude", field::LONGITUDE, FieldKind::Float)
    };

    /// Altitude, `f32`, metres.
    pub const ALTITUDE: FieldInfo = FieldInfo {
        icd_name: "Altitude",
        min: -20000.0,
        max: 100000.0,
        unit: Some(Unit::M),
        doc: "Altitude.",
        ..FieldInfo::new("altitude", field::ALTITUDE, FieldKind::Float)
    };

    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`.
    pub const DATE: FieldInfo = FieldInfo {
        icd_name: "Date (Year, Month, Day)",
        min: 1900.002685546875,
        max: 2200.001708984375,
        default: Value::Float(1900.002685546875),
        unit: Some(Unit::Year),
        encoding: Some(Encoding::Date),
        doc: "Date as Year + (Month - 1)/12 + Day/365.",
        ..FieldInfo::new("date", field::DATE, FieldKind::Float)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 6] = [
    info::REFERENCE_AZIMUTH,
    info::ACCUMULATION_TIME,
    info::LATITUDE,
    info::LONGITUDE,
    info::ALTITUDE,
    info::DATE,
];

payload_table! {
    /// Table 6.13, Calibration parameters: a zero-copy view over a payload.
    ///
    /// \[`CalibrationParameters::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`CalibrationParameters::new_unchecked`\] over a
    /// short buffer (missing bytes read as zero).
    view CalibrationParameters;
    /// Table 6.13, Calibration parameters: the payload as a value, with raw field values.
    ///
    /// \[`CalibrationParametersRepr::parse`\] and \[`CalibrationParametersRepr::build`\]
    /// are exact inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to
    /// the same bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq)]
    repr CalibrationParametersRepr;
    count 6;
    /// Reserved, `f32`, degrees: Reference azimuth (6.4.8); no influence on 2D calibration.
    0 number reference_azimuth set_reference_azimuth REFERENCE_AZIMUTH: f32;
    /// Time of data accumulation in one run, `u16`, seconds: Data accumulation time of one
    /// run.
    1 number accumulation_time set_accumulation_time ACCUMULATION_TIME: u16;
    /// Latitude, `f32`, degrees: Latitude.
    2 number latitude set_latitude LATITUDE: f32;
    /// Longitude, `f32`, degrees: Longitude.
    3 number longitude set_longitude LONGITUDE: f32;
    /// Altitude, `f32`, metres: Altitude.
    4 number altitude set_altitude ALTITUDE: f32;
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year +
    /// (Month - 1)/12 + Day/365.
    5 number date set_date DATE: f32;
}

impl Default for CalibrationParametersRepr {
    /// Every field at its default: accumulation_time 1, date 1900.002685546875, otherwise zero.
    fn default() -> CalibrationParametersRepr {
        CalibrationParametersRepr {
            reference_azimuth: 0.0,
            accumulation_time: 1,
            latitude: 0.0,
            longitude: 0.0,
            altitude: 0.0,
            date: 1900.0027,
        }
    }
}

impl<T: AsRef<[u8]>> CalibrationParameters<T> {
    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date())
    }
}

impl CalibrationParametersRepr {
    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date)
    }

    /// Sets Date (Year, Month, Day) from a calendar date. Error: `out_of_range` for a date that does not exist or lies outside the year range.
    pub fn set_date_decoded(&mut self, date: Date) -> Result<()> {
        let refused = info::DATE.refuse_because(date.refusal());
        self.date = date.encode().ok_or(refused)?;
        Ok(())
    }
}
