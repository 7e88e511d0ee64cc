// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.9, Parameters to load (50 bytes).
//!
//! The data message the host sends right after LoadAHRSPar (6.3.6). Read the block first
//! (ReadAHRSPar), change it, send it back.

use crate::encoding::Date;
use crate::encoding::Declination;
use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Unit, Value};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 50;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Update rate, `u16`, hertz.
    pub const UPDATE_RATE: Field = 0..2;
    /// Initial alignment time, `u16`, seconds.
    pub const ALIGNMENT_TIME: Field = 2..4;
    /// Magnetic declination, Mdec, `f32`, degrees.
    pub const DECLINATION: Field = 4..8;
    /// Latitude, `f32`, degrees.
    pub const LATITUDE: Field = 8..12;
    /// Longitude, `f32`, degrees.
    pub const LONGITUDE: Field = 12..16;
    /// Altitude, `f32`, metres.
    pub const ALTITUDE: Field = 16..20;
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`.
    pub const DATE: Field = 20..24;
    /// Alignment angle A1, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A1: Field = 24..28;
    /// Alignment angle A2, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A2: Field = 28..32;
    /// Alignment angle A3, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A3: Field = 32..36;
    /// Reserved, `reserved[14]`.
    pub const RESERVED: Field = 36..50;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Update rate, `u16`, hertz.
    pub const UPDATE_RATE: FieldInfo = FieldInfo {
        icd_name: "Update rate",
        min: 1.0,
        max: 100.0,
        default: Value::Int(100),
        unit: Some(Unit::Hz),
        doc: "Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz).",
        ..FieldInfo::new("update_rate", field::UPDATE_RATE, FieldKind::Unsigned)
    };

    /// Initial alignment time, `u16`, seconds.
    pub const ALIGNMENT_TIME: FieldInfo = FieldInfo {
        icd_name: "Initial alignment time",
        min: 1.0,
        max: 65535.0,
        default: Value::Int(30),
        unit: Some(Unit::S),
        doc:
            "Initial alignment duration; default 30 s, change only in agreement with Inertial Labs.",
        ..FieldInfo::new("alignment_time", field::ALIGNMENT_TIME, FieldKind::Unsigned)
    };

    /// Magnetic declination, Mdec, `f32`, degrees.
    pub const DECLINATION: FieldInfo = FieldInfo {
        icd_name: "Magnetic declination, Mdec",
        unit: Some(Unit::Deg),
        encoding: Some(Encoding::Declination),
        doc: "Magnetic declination; a value above 360 asks the AHRS to compute it from position and date.",
        ..FieldInfo::new("declination", field::DECLINATION, FieldKind::Float)
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

    /// Alignment angle A1, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A1: FieldInfo = FieldInfo {
        icd_name: "Alignment angle A1",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).",
        ..FieldInfo::new("alignment_angle_a1", field::ALIGNMENT_ANGLE_A1, FieldKind::Float)
    };

    /// Alignment angle A2, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A2: FieldInfo = FieldInfo {
        icd_name: "Alignment angle A2",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up positive (Appendix B).",
        ..FieldInfo::new("alignment_angle_a2", field::ALIGNMENT_ANGLE_A2, FieldKind::Float)
    };

    /// Alignment angle A3, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A3: FieldInfo = FieldInfo {
        icd_name: "Alignment angle A3",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive (Appendix B).",
        ..FieldInfo::new("alignment_angle_a3", field::ALIGNMENT_ANGLE_A3, FieldKind::Float)
    };

    /// Reserved, `reserved[14]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 14]),
        doc: "Should be all zeros.",
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 11] = [
    info::UPDATE_RATE,
    info::ALIGNMENT_TIME,
    info::DECLINATION,
    info::LATITUDE,
    info::LONGITUDE,
    info::ALTITUDE,
    info::DATE,
    info::ALIGNMENT_ANGLE_A1,
    info::ALIGNMENT_ANGLE_A2,
    info::ALIGNMENT_ANGLE_A3,
    info::RESERVED,
];

/// Table 6.9, Parameters to load: a zero-copy view over a payload.
///
/// [`AhrsParametersLoad::new_checked`] checks the size once; the accessors never panic,
/// even on a view made by [`AhrsParametersLoad::new_unchecked`] over a short buffer
/// (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AhrsParametersLoad<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> AhrsParametersLoad<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> AhrsParametersLoad<T> {
        AhrsParametersLoad { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<AhrsParametersLoad<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(AhrsParametersLoad { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Update rate, `u16`, hertz: Output data rate, 1 to 100 Hz (the AHRS limits NMEA
    /// output to 50 Hz).
    pub fn update_rate(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::UPDATE_RATE)
    }

    /// Initial alignment time, `u16`, seconds: Initial alignment duration; default 30 s,
    /// change only in agreement with Inertial Labs.
    pub fn alignment_time(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::ALIGNMENT_TIME)
    }

    /// Magnetic declination, Mdec, `f32`, degrees: Magnetic declination; a value above 360
    /// asks the AHRS to compute it from position and date.
    pub fn declination(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::DECLINATION)
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

    /// Alignment angle A1, `f32`, degrees: Mounting angle 1: AHRS Y axis relative to the
    /// object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).
    pub fn alignment_angle_a1(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A1)
    }

    /// Alignment angle A2, `f32`, degrees: Mounting angle 2: inclination of the AHRS Y axis
    /// to the object's horizontal plane, up positive (Appendix B).
    pub fn alignment_angle_a2(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A2)
    }

    /// Alignment angle A3, `f32`, degrees: Mounting angle 3: inclination of the AHRS X axis
    /// about its Y axis, X down positive (Appendix B).
    pub fn alignment_angle_a3(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A3)
    }

    /// Reserved, `reserved[14]`: Should be all zeros.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }

    /// Magnetic declination, Mdec: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination())
    }

    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> AhrsParametersLoad<T> {
    /// Sets [`Self::update_rate`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_update_rate(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::UPDATE_RATE, value);
    }

    /// Sets [`Self::alignment_time`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_time(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::ALIGNMENT_TIME, value);
    }

    /// Sets [`Self::declination`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_declination(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::DECLINATION, value);
    }

    /// Sets [`Self::latitude`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_latitude(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::LATITUDE, value);
    }

    /// Sets [`Self::longitude`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_longitude(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::LONGITUDE, value);
    }

    /// Sets [`Self::altitude`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_altitude(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::ALTITUDE, value);
    }

    /// Sets [`Self::date`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_date(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::DATE, value);
    }

    /// Sets [`Self::alignment_angle_a1`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a1(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A1, value);
    }

    /// Sets [`Self::alignment_angle_a2`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a2(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A2, value);
    }

    /// Sets [`Self::alignment_angle_a3`] (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a3(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A3, value);
    }

    /// Sets [`Self::reserved`] (bytes kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 14]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }
}

/// Table 6.9, Parameters to load: the payload as a value, with raw field values.
///
/// [`AhrsParametersLoadRepr::parse`] and [`AhrsParametersLoadRepr::build`] are exact
/// inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same bytes
/// when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AhrsParametersLoadRepr {
    /// Update rate, `u16`, hertz: Output data rate, 1 to 100 Hz (the AHRS limits NMEA
    /// output to 50 Hz).
    pub update_rate: u16,
    /// Initial alignment time, `u16`, seconds: Initial alignment duration; default 30 s,
    /// change only in agreement with Inertial Labs.
    pub alignment_time: u16,
    /// Magnetic declination, Mdec, `f32`, degrees: Magnetic declination; a value above 360
    /// asks the AHRS to compute it from position and date.
    pub declination: f32,
    /// Latitude, `f32`, degrees: Latitude.
    pub latitude: f32,
    /// Longitude, `f32`, degrees: Longitude.
    pub longitude: f32,
    /// Altitude, `f32`, metres: Altitude.
    pub altitude: f32,
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year +
    /// (Month - 1)/12 + Day/365.
    pub date: f32,
    /// Alignment angle A1, `f32`, degrees: Mounting angle 1: AHRS Y axis relative to the
    /// object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).
    pub alignment_angle_a1: f32,
    /// Alignment angle A2, `f32`, degrees: Mounting angle 2: inclination of the AHRS Y axis
    /// to the object's horizontal plane, up positive (Appendix B).
    pub alignment_angle_a2: f32,
    /// Alignment angle A3, `f32`, degrees: Mounting angle 3: inclination of the AHRS X axis
    /// about its Y axis, X down positive (Appendix B).
    pub alignment_angle_a3: f32,
    /// Reserved, `reserved[14]`: Should be all zeros.
    pub reserved: [u8; 14],
}

impl AhrsParametersLoadRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<AhrsParametersLoadRepr> {
        let view = AhrsParametersLoad::new_checked(data)?;
        Ok(AhrsParametersLoadRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &AhrsParametersLoad<T>) -> AhrsParametersLoadRepr {
        AhrsParametersLoadRepr {
            update_rate: view.update_rate(),
            alignment_time: view.alignment_time(),
            declination: view.declination(),
            latitude: view.latitude(),
            longitude: view.longitude(),
            altitude: view.altitude(),
            date: view.date(),
            alignment_angle_a1: view.alignment_angle_a1(),
            alignment_angle_a2: view.alignment_angle_a2(),
            alignment_angle_a3: view.alignment_angle_a3(),
            reserved: wire::array(view.as_bytes(), field::RESERVED),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`AhrsParametersLoadRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`AhrsParametersLoadRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut AhrsParametersLoad::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut AhrsParametersLoad<T>) {
        view.set_update_rate(self.update_rate);
        view.set_alignment_time(self.alignment_time);
        view.set_declination(self.declination);
        view.set_latitude(self.latitude);
        view.set_longitude(self.longitude);
        view.set_altitude(self.altitude);
        view.set_date(self.date);
        view.set_alignment_angle_a1(self.alignment_angle_a1);
        view.set_alignment_angle_a2(self.alignment_angle_a2);
        view.set_alignment_angle_a3(self.alignment_angle_a3);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`AhrsParametersLoadRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 11] {
        [
            Raw::value(self.update_rate),
            Raw::value(self.alignment_time),
            Raw::value(self.declination),
            Raw::value(self.latitude),
            Raw::value(self.longitude),
            Raw::value(self.altitude),
            Raw::value(self.date),
            Raw::value(self.alignment_angle_a1),
            Raw::value(self.alignment_angle_a2),
            Raw::value(self.alignment_angle_a3),
            Value::Bytes(&self.reserved),
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
            0 => self.update_rate = Raw::from_value(&info::UPDATE_RATE, value)?,
            1 => self.alignment_time = Raw::from_value(&info::ALIGNMENT_TIME, value)?,
            2 => self.declination = Raw::from_value(&info::DECLINATION, value)?,
            3 => self.latitude = Raw::from_value(&info::LATITUDE, value)?,
            4 => self.longitude = Raw::from_value(&info::LONGITUDE, value)?,
            5 => self.altitude = Raw::from_value(&info::ALTITUDE, value)?,
            6 => self.date = Raw::from_value(&info::DATE, value)?,
            7 => self.alignment_angle_a1 = Raw::from_value(&info::ALIGNMENT_ANGLE_A1, value)?,
            8 => self.alignment_angle_a2 = Raw::from_value(&info::ALIGNMENT_ANGLE_A2, value)?,
            9 => self.alignment_angle_a3 = Raw::from_value(&info::ALIGNMENT_ANGLE_A3, value)?,
            10 => self.reserved = info::RESERVED.array(value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Magnetic declination, Mdec: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination)
    }

    /// Sets Magnetic declination, Mdec. Error: `out_of_range` for degrees outside the range.
    pub fn set_declination_decoded(&mut self, value: Declination) -> Result<()> {
        let refused = info::DECLINATION.refuse_because(value.refusal());
        self.declination = value.encode().ok_or(refused)?;
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

impl Table for AhrsParametersLoadRepr {
    fn validate(&self) -> Result<()> {
        AhrsParametersLoadRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        AhrsParametersLoadRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        AhrsParametersLoadRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        AhrsParametersLoadRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        AhrsParametersLoadRepr::set_value(self, index, value)
    }
}

impl Default for AhrsParametersLoadRepr {
    /// Every field at its default: update_rate 100, alignment_time 30, date 1900.002685546875, otherwise zero.
    fn default() -> AhrsParametersLoadRepr {
        AhrsParametersLoadRepr {
            update_rate: 100,
            alignment_time: 30,
            declination: 0.0,
            latitude: 0.0,
            longitude: 0.0,
            altitude: 0.0,
            date: 1900.0027,
            alignment_angle_a1: 0.0,
            alignment_angle_a2: 0.0,
            alignment_angle_a3: 0.0,
            reserved: [0; 14],
        }
    }
}
