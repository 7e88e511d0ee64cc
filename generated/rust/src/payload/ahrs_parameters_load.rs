// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.9, Parameters to load (50 bytes).
//!
//! The data message the host sends right after LoadAHRSPar (6.3.6). Read the block first
//! (ReadAHRSPar), change it, send it back.

use crate::encoding::Date;
use crate::encoding::Declination;
use crate::error::{Error, ErrorKind, Result};
use crate::frame::{FrameRepr, MessageType};
use crate::payload::{check_size, Value};
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
    use super::field;
    use crate::payload::{FieldInfo, FieldKind, Value};

    /// Update rate, `u16`, hertz.
    pub const UPDATE_RATE: FieldInfo = FieldInfo {
        name: "update_rate",
        icd_name: "Update rate",
        offset: field::UPDATE_RATE.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 1.0,
        max: 100.0,
        default: Value::Int(100),
        scale: None,
        unit: Some(crate::payload::Unit::Hz),
        encoding: None,
        doc: "Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz).",
    };

    /// Initial alignment time, `u16`, seconds.
    pub const ALIGNMENT_TIME: FieldInfo = FieldInfo {
        name: "alignment_time",
        icd_name: "Initial alignment time",
        offset: field::ALIGNMENT_TIME.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 1.0,
        max: 65535.0,
        default: Value::Int(30),
        scale: None,
        unit: Some(crate::payload::Unit::S),
        encoding: None,
        doc:
            "Initial alignment duration; default 30 s, change only in agreement with Inertial Labs.",
    };

    /// Magnetic declination, Mdec, `f32`, degrees.
    pub const DECLINATION: FieldInfo = FieldInfo {
        name: "declination",
        icd_name: "Magnetic declination, Mdec",
        offset: field::DECLINATION.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: Some(crate::payload::Encoding::Declination),
        doc:
            "Magnetic declination; a value above 360 asks the AHRS to compute it from position and date.",
    };

    /// Latitude, `f32`, degrees.
    pub const LATITUDE: FieldInfo = FieldInfo {
        name: "latitude",
        icd_name: "Latitude",
        offset: field::LATITUDE.start,
        size: 4,
        kind: FieldKind::Float,
        min: -90.0,
        max: 90.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Latitude.",
    };

    /// Longitude, `f32`, degrees.
    pub const LONGITUDE: FieldInfo = FieldInfo {
        name: "longitude",
        icd_name: "Longitude",
        offset: field::LONGITUDE.start,
        size: 4,
        kind: FieldKind::Float,
        min: -180.0,
        max: 180.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc: "Longitude.",
    };

    /// Altitude, `f32`, metres.
    pub const ALTITUDE: FieldInfo = FieldInfo {
        name: "altitude",
        icd_name: "Altitude",
        offset: field::ALTITUDE.start,
        size: 4,
        kind: FieldKind::Float,
        min: -20000.0,
        max: 100000.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::M),
        encoding: None,
        doc: "Altitude.",
    };

    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`.
    pub const DATE: FieldInfo = FieldInfo {
        name: "date",
        icd_name: "Date (Year, Month, Day)",
        offset: field::DATE.start,
        size: 4,
        kind: FieldKind::Float,
        min: 1900.002685546875,
        max: 2200.001708984375,
        default: Value::Float(1900.002685546875),
        scale: None,
        unit: Some(crate::payload::Unit::Year),
        encoding: Some(crate::payload::Encoding::Date),
        doc: "Date as Year + (Month - 1)/12 + Day/365.",
    };

    /// Alignment angle A1, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A1: FieldInfo = FieldInfo {
        name: "alignment_angle_a1",
        icd_name: "Alignment angle A1",
        offset: field::ALIGNMENT_ANGLE_A1.start,
        size: 4,
        kind: FieldKind::Float,
        min: -360.0,
        max: 360.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc:
            "Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).",
    };

    /// Alignment angle A2, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A2: FieldInfo = FieldInfo {
        name: "alignment_angle_a2",
        icd_name: "Alignment angle A2",
        offset: field::ALIGNMENT_ANGLE_A2.start,
        size: 4,
        kind: FieldKind::Float,
        min: -360.0,
        max: 360.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc:
            "Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up positive (Appendix B).",
    };

    /// Alignment angle A3, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A3: FieldInfo = FieldInfo {
        name: "alignment_angle_a3",
        icd_name: "Alignment angle A3",
        offset: field::ALIGNMENT_ANGLE_A3.start,
        size: 4,
        kind: FieldKind::Float,
        min: -360.0,
        max: 360.0,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: None,
        doc:
            "Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive (Appendix B).",
    };

    /// Reserved, `reserved[14]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        name: "reserved",
        icd_name: "Reserved",
        offset: field::RESERVED.start,
        size: 14,
        kind: FieldKind::Reserved,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(&[0; 14]),
        scale: None,
        unit: None,
        encoding: None,
        doc: "Should be all zeros.",
    };
}

/// Every field, in wire order.
pub static FIELDS: [crate::payload::FieldInfo; 11] = [
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
/// [`AhrsParametersLoad::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`AhrsParametersLoad::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AhrsParametersLoad<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> AhrsParametersLoad<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> AhrsParametersLoad<T> {
        AhrsParametersLoad { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
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

    /// Update rate, `u16`, hertz: Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz).
    pub fn update_rate(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::UPDATE_RATE)
    }

    /// Initial alignment time, `u16`, seconds: Initial alignment duration; default 30 s, change only in agreement with Inertial Labs.
    pub fn alignment_time(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::ALIGNMENT_TIME)
    }

    /// Magnetic declination, Mdec, `f32`, degrees: Magnetic declination; a value above 360 asks the AHRS to compute it from position and date.
    pub fn declination(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::DECLINATION)
    }

    /// Magnetic declination, Mdec: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination())
    }

    /// Latitude, `f32`, degrees: Latitude.
    pub fn latitude(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::LATITUDE)
    }

    /// Longitude, `f32`, degrees: Longitude.
    pub fn longitude(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::LONGITUDE)
    }

    /// Altitude, `f32`, metres: Altitude.
    pub fn altitude(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALTITUDE)
    }

    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year + (Month - 1)/12 + Day/365.
    pub fn date(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::DATE)
    }

    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date())
    }

    /// Alignment angle A1, `f32`, degrees: Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).
    pub fn alignment_angle_a1(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A1)
    }

    /// Alignment angle A2, `f32`, degrees: Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up positive (Appendix B).
    pub fn alignment_angle_a2(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A2)
    }

    /// Alignment angle A3, `f32`, degrees: Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive (Appendix B).
    pub fn alignment_angle_a3(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A3)
    }

    /// Reserved, `reserved\[14\]`: Should be all zeros.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> AhrsParametersLoad<T> {
    /// Sets Update rate (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_update_rate(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::UPDATE_RATE, value);
    }

    /// Sets Initial alignment time (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_time(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::ALIGNMENT_TIME, value);
    }

    /// Sets Magnetic declination, Mdec (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_declination(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::DECLINATION, value);
    }

    /// Sets Latitude (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_latitude(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::LATITUDE, value);
    }

    /// Sets Longitude (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_longitude(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::LONGITUDE, value);
    }

    /// Sets Altitude (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_altitude(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALTITUDE, value);
    }

    /// Sets Date (Year, Month, Day) (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_date(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::DATE, value);
    }

    /// Sets Alignment angle A1 (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a1(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A1, value);
    }

    /// Sets Alignment angle A2 (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a2(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A2, value);
    }

    /// Sets Alignment angle A3 (raw, unchecked: [`AhrsParametersLoadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a3(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A3, value);
    }

    /// Sets Reserved (14 bytes, kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 14]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }
}

/// Table 6.9, Parameters to load: the payload as a value, with raw field values.
///
/// [`AhrsParametersLoadRepr::parse`] and [`AhrsParametersLoadRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AhrsParametersLoadRepr {
    /// Update rate, `u16`, hertz: Output data rate, 1 to 100 Hz (the AHRS limits NMEA output to 50 Hz).
    pub update_rate: u16,
    /// Initial alignment time, `u16`, seconds: Initial alignment duration; default 30 s, change only in agreement with Inertial Labs.
    pub alignment_time: u16,
    /// Magnetic declination, Mdec, `f32`, degrees: Magnetic declination; a value above 360 asks the AHRS to compute it from position and date.
    pub declination: f32,
    /// Latitude, `f32`, degrees: Latitude.
    pub latitude: f32,
    /// Longitude, `f32`, degrees: Longitude.
    pub longitude: f32,
    /// Altitude, `f32`, metres: Altitude.
    pub altitude: f32,
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year + (Month - 1)/12 + Day/365.
    pub date: f32,
    /// Alignment angle A1, `f32`, degrees: Mounting angle 1: AHRS Y axis relative to the object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).
    pub alignment_angle_a1: f32,
    /// Alignment angle A2, `f32`, degrees: Mounting angle 2: inclination of the AHRS Y axis to the object's horizontal plane, up positive (Appendix B).
    pub alignment_angle_a2: f32,
    /// Alignment angle A3, `f32`, degrees: Mounting angle 3: inclination of the AHRS X axis about its Y axis, X down positive (Appendix B).
    pub alignment_angle_a3: f32,
    /// Reserved, `reserved\[14\]`: Should be all zeros.
    pub reserved: [u8; 14],
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

impl AhrsParametersLoadRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
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

    /// Checks every field in table order, as a builder does; the first bad one is the error:
    /// `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        for (info, value) in FIELDS.iter().zip(self.values()) {
            info.check(value)?;
        }
        Ok(())
    }

    /// The size of the payload [`AhrsParametersLoadRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`AhrsParametersLoadRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
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

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`AhrsParametersLoadRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        FrameRepr::new(MessageType::Data, &payload).build(buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 11] {
        [
            Value::Int(i64::from(self.update_rate)),
            Value::Int(i64::from(self.alignment_time)),
            Value::Float(f64::from(self.declination)),
            Value::Float(f64::from(self.latitude)),
            Value::Float(f64::from(self.longitude)),
            Value::Float(f64::from(self.altitude)),
            Value::Float(f64::from(self.date)),
            Value::Float(f64::from(self.alignment_angle_a1)),
            Value::Float(f64::from(self.alignment_angle_a2)),
            Value::Float(f64::from(self.alignment_angle_a3)),
            Value::Bytes(&self.reserved),
        ]
    }

    /// The raw value of field `index` (table order), or `None` past the last field.
    pub fn value(&self, index: usize) -> Option<Value<'_>> {
        self.values().get(index).copied()
    }

    /// Sets field `index` (table order) after checking `value` as a builder does. Errors:
    /// `out_of_range` naming the field, or with no field for an index past the last.
    pub fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        match index {
            0 => self.update_rate = info::UPDATE_RATE.int(value)?,
            1 => self.alignment_time = info::ALIGNMENT_TIME.int(value)?,
            2 => self.declination = info::DECLINATION.float(value)?,
            3 => self.latitude = info::LATITUDE.float(value)?,
            4 => self.longitude = info::LONGITUDE.float(value)?,
            5 => self.altitude = info::ALTITUDE.float(value)?,
            6 => self.date = info::DATE.float(value)?,
            7 => self.alignment_angle_a1 = info::ALIGNMENT_ANGLE_A1.float(value)?,
            8 => self.alignment_angle_a2 = info::ALIGNMENT_ANGLE_A2.float(value)?,
            9 => self.alignment_angle_a3 = info::ALIGNMENT_ANGLE_A3.float(value)?,
            10 => self.reserved = info::RESERVED.array(value)?,
            _ => return Err(Error::new(ErrorKind::OutOfRange)),
        }
        Ok(())
    }

    /// Magnetic declination, Mdec: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination)
    }

    /// Sets Magnetic declination, Mdec. Error: `out_of_range` for degrees outside the range.
    pub fn set_declination_decoded(&mut self, value: Declination) -> Result<()> {
        self.declination = value.encode().ok_or(info::DECLINATION.refuse())?;
        Ok(())
    }

    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date)
    }

    /// Sets Date (Year, Month, Day) from a calendar date. Error: `out_of_range` for a date that does
    /// not exist or lies outside the year range.
    pub fn set_date_decoded(&mut self, date: Date) -> Result<()> {
        self.date = date.encode().ok_or(info::DATE.refuse())?;
        Ok(())
    }
}
