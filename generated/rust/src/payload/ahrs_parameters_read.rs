// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.10, Parameters read (50 bytes).
//!
//! The AHRS answer to ReadAHRSPar (6.3.7).

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

    /// Measurement rate, `u16`, hertz.
    pub const UPDATE_RATE: Field = 0..2;

    /// Initial alignment time, `u16`, seconds.
    pub const ALIGNMENT_TIME: Field = 2..4;

    /// Magnetic declination, `f32`, degrees.
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

    /// Device ID, `char[8]`.
    pub const DEVICE_ID: Field = 36..44;

    /// Reserved, `reserved[6]`.
    pub const RESERVED: Field = 44..50;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::field;
    use crate::payload::{FieldInfo, FieldKind, Value};

    /// Measurement rate, `u16`, hertz.
    pub const UPDATE_RATE: FieldInfo = FieldInfo {
        name: "update_rate",
        icd_name: "Measurement rate",
        offset: field::UPDATE_RATE.start,
        size: 2,
        kind: FieldKind::Unsigned,
        min: 1.0,
        max: 100.0,
        default: Value::Int(1),
        scale: None,
        unit: Some(crate::payload::Unit::Hz),
        encoding: None,
        doc: "Output data rate.",
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
        default: Value::Int(1),
        scale: None,
        unit: Some(crate::payload::Unit::S),
        encoding: None,
        doc: "Initial alignment duration.",
    };

    /// Magnetic declination, `f32`, degrees.
    pub const DECLINATION: FieldInfo = FieldInfo {
        name: "declination",
        icd_name: "Magnetic declination",
        offset: field::DECLINATION.start,
        size: 4,
        kind: FieldKind::Float,
        min: -crate::payload::F32_MAX,
        max: crate::payload::F32_MAX,
        default: Value::Float(0.0),
        scale: None,
        unit: Some(crate::payload::Unit::Deg),
        encoding: Some(crate::payload::Encoding::Declination),
        doc: "Magnetic declination; a value above 360 means the AHRS computes it.",
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
        doc: "Mounting angle 1 (Appendix B).",
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
        doc: "Mounting angle 2 (Appendix B).",
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
        doc: "Mounting angle 3 (Appendix B).",
    };

    /// Device ID, `char[8]`.
    pub const DEVICE_ID: FieldInfo = FieldInfo {
        name: "device_id",
        icd_name: "Device ID",
        offset: field::DEVICE_ID.start,
        size: 8,
        kind: FieldKind::Char,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(b""),
        scale: None,
        unit: None,
        encoding: None,
        doc: "Device identifier (read only).",
    };

    /// Reserved, `reserved[6]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        name: "reserved",
        icd_name: "Reserved",
        offset: field::RESERVED.start,
        size: 6,
        kind: FieldKind::Reserved,
        min: 0.0,
        max: 0.0,
        default: Value::Bytes(&[0; 6]),
        scale: None,
        unit: None,
        encoding: None,
        doc: "",
    };
}

/// Every field, in wire order.
pub static FIELDS: [crate::payload::FieldInfo; 12] = [
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
    info::DEVICE_ID,
    info::RESERVED,
];

/// Table 6.10, Parameters read: a zero-copy view over a payload.
///
/// [`AhrsParametersRead::new_checked`] checks the size once; the accessors never panic, even on a
/// view made by [`AhrsParametersRead::new_unchecked`] over a short buffer (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AhrsParametersRead<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> AhrsParametersRead<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> AhrsParametersRead<T> {
        AhrsParametersRead { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its length
    /// when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<AhrsParametersRead<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(AhrsParametersRead { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Measurement rate, `u16`, hertz: Output data rate.
    pub fn update_rate(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::UPDATE_RATE)
    }

    /// Initial alignment time, `u16`, seconds: Initial alignment duration.
    pub fn alignment_time(&self) -> u16 {
        wire::get_u16(self.buffer.as_ref(), field::ALIGNMENT_TIME)
    }

    /// Magnetic declination, `f32`, degrees: Magnetic declination; a value above 360 means the AHRS computes it.
    pub fn declination(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::DECLINATION)
    }

    /// Magnetic declination: degrees, or a request that the AHRS compute it.
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

    /// Alignment angle A1, `f32`, degrees: Mounting angle 1 (Appendix B).
    pub fn alignment_angle_a1(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A1)
    }

    /// Alignment angle A2, `f32`, degrees: Mounting angle 2 (Appendix B).
    pub fn alignment_angle_a2(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A2)
    }

    /// Alignment angle A3, `f32`, degrees: Mounting angle 3 (Appendix B).
    pub fn alignment_angle_a3(&self) -> f32 {
        wire::get_f32(self.buffer.as_ref(), field::ALIGNMENT_ANGLE_A3)
    }

    /// Device ID, `char\[8\]`: Device identifier (read only).
    /// The bytes up to the trailing NULs (Latin-1).
    pub fn device_id(&self) -> &[u8] {
        wire::trim_nul(wire::bytes(self.buffer.as_ref(), field::DEVICE_ID))
    }

    /// Reserved, `reserved\[6\]`:
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> AhrsParametersRead<T> {
    /// Sets Measurement rate (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_update_rate(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::UPDATE_RATE, value);
    }

    /// Sets Initial alignment time (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_alignment_time(&mut self, value: u16) {
        wire::set_u16(self.buffer.as_mut(), field::ALIGNMENT_TIME, value);
    }

    /// Sets Magnetic declination (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_declination(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::DECLINATION, value);
    }

    /// Sets Latitude (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_latitude(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::LATITUDE, value);
    }

    /// Sets Longitude (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_longitude(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::LONGITUDE, value);
    }

    /// Sets Altitude (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_altitude(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALTITUDE, value);
    }

    /// Sets Date (Year, Month, Day) (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_date(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::DATE, value);
    }

    /// Sets Alignment angle A1 (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a1(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A1, value);
    }

    /// Sets Alignment angle A2 (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a2(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A2, value);
    }

    /// Sets Alignment angle A3 (raw, unchecked: [`AhrsParametersReadRepr::build`] checks ranges).
    pub fn set_alignment_angle_a3(&mut self, value: f32) {
        wire::set_f32(self.buffer.as_mut(), field::ALIGNMENT_ANGLE_A3, value);
    }

    /// Sets Device ID: `value` padded with NULs. Error: `out_of_range` when longer
    /// than 8 bytes.
    pub fn set_device_id(&mut self, value: &[u8]) -> Result<()> {
        info::DEVICE_ID.check(Value::Bytes(value))?;
        wire::set_padded(self.buffer.as_mut(), field::DEVICE_ID, value);
        Ok(())
    }

    /// Sets Reserved (6 bytes, kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 6]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }
}

/// Table 6.10, Parameters read: the payload as a value, with raw field values.
///
/// [`AhrsParametersReadRepr::parse`] and [`AhrsParametersReadRepr::build`] are exact inverses: every byte string of
/// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AhrsParametersReadRepr {
    /// Measurement rate, `u16`, hertz: Output data rate.
    pub update_rate: u16,
    /// Initial alignment time, `u16`, seconds: Initial alignment duration.
    pub alignment_time: u16,
    /// Magnetic declination, `f32`, degrees: Magnetic declination; a value above 360 means the AHRS computes it.
    pub declination: f32,
    /// Latitude, `f32`, degrees: Latitude.
    pub latitude: f32,
    /// Longitude, `f32`, degrees: Longitude.
    pub longitude: f32,
    /// Altitude, `f32`, metres: Altitude.
    pub altitude: f32,
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year + (Month - 1)/12 + Day/365.
    pub date: f32,
    /// Alignment angle A1, `f32`, degrees: Mounting angle 1 (Appendix B).
    pub alignment_angle_a1: f32,
    /// Alignment angle A2, `f32`, degrees: Mounting angle 2 (Appendix B).
    pub alignment_angle_a2: f32,
    /// Alignment angle A3, `f32`, degrees: Mounting angle 3 (Appendix B).
    pub alignment_angle_a3: f32,
    /// Device ID, `char\[8\]`: Device identifier (read only).
    pub device_id: [u8; 8],
    /// Reserved, `reserved\[6\]`:
    pub reserved: [u8; 6],
}

impl Default for AhrsParametersReadRepr {
    /// Every field at its default: update_rate 1, alignment_time 1, date 1900.002685546875, otherwise zero.
    fn default() -> AhrsParametersReadRepr {
        AhrsParametersReadRepr {
            update_rate: 1,
            alignment_time: 1,
            declination: 0.0,
            latitude: 0.0,
            longitude: 0.0,
            altitude: 0.0,
            date: 1900.0027,
            alignment_angle_a1: 0.0,
            alignment_angle_a2: 0.0,
            alignment_angle_a3: 0.0,
            device_id: [0; 8],
            reserved: [0; 6],
        }
    }
}

impl AhrsParametersReadRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise). Decoding
    /// does not check ranges.
    pub fn parse(data: &[u8]) -> Result<AhrsParametersReadRepr> {
        let view = AhrsParametersRead::new_checked(data)?;
        Ok(AhrsParametersReadRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &AhrsParametersRead<T>) -> AhrsParametersReadRepr {
        AhrsParametersReadRepr {
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
            device_id: wire::array(view.as_bytes(), field::DEVICE_ID),
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

    /// The size of the payload [`AhrsParametersReadRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`AhrsParametersReadRepr::validate`]) and writes it into `buf`; returns its
    /// size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = buf
            .get_mut(..SIZE)
            .ok_or(Error::new(ErrorKind::BufferTooSmall))?;
        self.emit(&mut AhrsParametersRead::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut AhrsParametersRead<T>) {
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
        wire::put(view.buffer.as_mut(), field::DEVICE_ID, &self.device_id);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`;
    /// returns its size (bytes). Errors: those of [`AhrsParametersReadRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        FrameRepr::new(MessageType::Data, &payload).build(buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 12] {
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
            Value::Bytes(wire::trim_nul(&self.device_id)),
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
            10 => self.device_id = info::DEVICE_ID.array(value)?,
            11 => self.reserved = info::RESERVED.array(value)?,
            _ => return Err(Error::new(ErrorKind::OutOfRange)),
        }
        Ok(())
    }

    /// Magnetic declination: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination)
    }

    /// Sets Magnetic declination. Error: `out_of_range` for degrees outside the range.
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

    /// Device ID: the bytes up to the trailing NULs (Latin-1).
    pub fn device_id_text(&self) -> &[u8] {
        wire::trim_nul(&self.device_id)
    }

    /// Sets Device ID: `value` padded with NULs. Error: `out_of_range` when longer
    /// than 8 bytes.
    pub fn set_device_id_text(&mut self, value: &[u8]) -> Result<()> {
        self.device_id = info::DEVICE_ID.array(Value::Bytes(value))?;
        Ok(())
    }
}
