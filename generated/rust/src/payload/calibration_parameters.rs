// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.13, Calibration parameters (22 bytes).
//!
//! The data message the host sends right after Start3DClb, Start2D2TClb or Start2DClb (6.4.1,
//! 6.4.5, 6.4.8).

use crate::encoding::Date;
use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Unit, Value};
use crate::wire;

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

/// Table 6.13, Calibration parameters: a zero-copy view over a payload.
///
/// [`CalibrationParameters::new_checked`] checks the size once; the accessors never panic,
/// even on a view made by [`CalibrationParameters::new_unchecked`] over a short buffer
/// (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CalibrationParameters<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> CalibrationParameters<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> CalibrationParameters<T> {
        CalibrationParameters { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<CalibrationParameters<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(CalibrationParameters { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Reserved, `f32`, degrees: Reference azimuth (6.4.8); no influence on 2D calibration.
    pub fn reference_azimuth(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::REFERENCE_AZIMUTH)
    }

    /// Time of data accumulation in one run, `u16`, seconds: Data accumulation time of one
    /// run.
    pub fn accumulation_time(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::ACCUMULATION_TIME)
    }

    /// Latitude, `f32`, degrees: Latitude.
    pub fn latitude(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::LATITUDE)
    }

    /// Longitude, `f32`, degrees: Longitude.
    pub fn longitude(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::LONGITUDE)
    }

    /// Altitude, `f32`, metres: Altitude.
    pub fn altitude(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::ALTITUDE)
    }

    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year +
    /// (Month - 1)/12 + Day/365.
    pub fn date(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::DATE)
    }

    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> CalibrationParameters<T> {
    /// Sets [`Self::reference_azimuth`] (raw, unchecked: [`CalibrationParametersRepr::build`] checks ranges).
    pub fn set_reference_azimuth(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::REFERENCE_AZIMUTH, value);
    }

    /// Sets [`Self::accumulation_time`] (raw, unchecked: [`CalibrationParametersRepr::build`] checks ranges).
    pub fn set_accumulation_time(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::ACCUMULATION_TIME, value);
    }

    /// Sets [`Self::latitude`] (raw, unchecked: [`CalibrationParametersRepr::build`] checks ranges).
    pub fn set_latitude(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::LATITUDE, value);
    }

    /// Sets [`Self::longitude`] (raw, unchecked: [`CalibrationParametersRepr::build`] checks ranges).
    pub fn set_longitude(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::LONGITUDE, value);
    }

    /// Sets [`Self::altitude`] (raw, unchecked: [`CalibrationParametersRepr::build`] checks ranges).
    pub fn set_altitude(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::ALTITUDE, value);
    }

    /// Sets [`Self::date`] (raw, unchecked: [`CalibrationParametersRepr::build`] checks ranges).
    pub fn set_date(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::DATE, value);
    }
}

/// Table 6.13, Calibration parameters: the payload as a value, with raw field values.
///
/// [`CalibrationParametersRepr::parse`] and [`CalibrationParametersRepr::build`] are exact
/// inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same bytes
/// when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationParametersRepr {
    /// Reserved, `f32`, degrees: Reference azimuth (6.4.8); no influence on 2D calibration.
    pub reference_azimuth: f32,
    /// Time of data accumulation in one run, `u16`, seconds: Data accumulation time of one
    /// run.
    pub accumulation_time: u16,
    /// Latitude, `f32`, degrees: Latitude.
    pub latitude: f32,
    /// Longitude, `f32`, degrees: Longitude.
    pub longitude: f32,
    /// Altitude, `f32`, metres: Altitude.
    pub altitude: f32,
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year +
    /// (Month - 1)/12 + Day/365.
    pub date: f32,
}

impl CalibrationParametersRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<CalibrationParametersRepr> {
        let view = CalibrationParameters::new_checked(data)?;
        Ok(CalibrationParametersRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &CalibrationParameters<T>) -> CalibrationParametersRepr {
        CalibrationParametersRepr {
            reference_azimuth: view.reference_azimuth(),
            accumulation_time: view.accumulation_time(),
            latitude: view.latitude(),
            longitude: view.longitude(),
            altitude: view.altitude(),
            date: view.date(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`CalibrationParametersRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`CalibrationParametersRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut CalibrationParameters::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut CalibrationParameters<T>) {
        view.set_reference_azimuth(self.reference_azimuth);
        view.set_accumulation_time(self.accumulation_time);
        view.set_latitude(self.latitude);
        view.set_longitude(self.longitude);
        view.set_altitude(self.altitude);
        view.set_date(self.date);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`CalibrationParametersRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 6] {
        [
            Raw::value(self.reference_azimuth),
            Raw::value(self.accumulation_time),
            Raw::value(self.latitude),
            Raw::value(self.longitude),
            Raw::value(self.altitude),
            Raw::value(self.date),
        ]
    }

    /// The raw value of field `index` (table order), or `None` past the last field.
    pub fn value(&self, index: usize) -> Option<Value<'_>> {
        self.values().get(index).copied()
    }

    /// Sets field `index` (table order) after checking `value` as a builder does.
    /// Errors: `out_of_range` naming the field, or with no field for an index past the
    /// last.
    pub fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        match index {
            0 => self.reference_azimuth = Raw::from_value(&info::REFERENCE_AZIMUTH, value)?,
            1 => self.accumulation_time = Raw::from_value(&info::ACCUMULATION_TIME, value)?,
            2 => self.latitude = Raw::from_value(&info::LATITUDE, value)?,
            3 => self.longitude = Raw::from_value(&info::LONGITUDE, value)?,
            4 => self.altitude = Raw::from_value(&info::ALTITUDE, value)?,
            5 => self.date = Raw::from_value(&info::DATE, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

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

impl Table for CalibrationParametersRepr {
    fn validate(&self) -> Result<()> {
        CalibrationParametersRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationParametersRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        CalibrationParametersRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        CalibrationParametersRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        CalibrationParametersRepr::set_value(self, index, value)
    }
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
