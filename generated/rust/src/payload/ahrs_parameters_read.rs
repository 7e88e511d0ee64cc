// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.10, Parameters read (50 bytes).
//!
//! The AHRS answer to ReadAHRSPar (6.3.7).

use crate::encoding::Date;
use crate::encoding::Declination;
use crate::error::Result;
use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Unit, Value};

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
    use super::*;

    /// Measurement rate, `u16`, hertz.
    pub const UPDATE_RATE: FieldInfo = FieldInfo {
        icd_name: "Measurement rate",
        min: 1.0,
        max: 100.0,
        default: Value::Int(1),
        unit: Some(Unit::Hz),
        doc: "Output data rate.",
        ..FieldInfo::new("update_rate", field::UPDATE_RATE, FieldKind::Unsigned)
    };

    /// Initial alignment time, `u16`, seconds.
    pub const ALIGNMENT_TIME: FieldInfo = FieldInfo {
        icd_name: "Initial alignment time",
        min: 1.0,
        max: 65535.0,
        default: Value::Int(1),
        unit: Some(Unit::S),
        doc: "Initial alignment duration.",
        ..FieldInfo::new("alignment_time", field::ALIGNMENT_TIME, FieldKind::Unsigned)
    };

    /// Magnetic declination, `f32`, degrees.
    pub const DECLINATION: FieldInfo = FieldInfo {
        icd_name: "Magnetic declination",
        unit: Some(Unit::Deg),
        encoding: Some(Encoding::Declination),
        doc: "Magnetic declination; a value above 360 means the AHRS computes it.",
        ..FieldInfo::new("declination", field::DECLINATION, FieldKind::Float)
    };

    /// Latitude, `f32`, degrees.
    pub const LATITUDE: FieldInfo = crate::payload::ahrs_parameters_load::info::LATITUDE;

    /// Longitude, `f32`, degrees.
    pub const LONGITUDE: FieldInfo = crate::payload::ahrs_parameters_load::info::LONGITUDE;

    /// Altitude, `f32`, metres.
    pub const ALTITUDE: FieldInfo = crate::payload::ahrs_parameters_load::info::ALTITUDE;

    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`.
    pub const DATE: FieldInfo = crate::payload::ahrs_parameters_load::info::DATE;

    /// Alignment angle A1, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A1: FieldInfo = FieldInfo {
        icd_name: "Alignment angle A1",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Mounting angle 1 (Appendix B).",
        ..FieldInfo::new(
            "alignment_angle_a1",
            field::ALIGNMENT_ANGLE_A1,
            FieldKind::Float,
        )
    };

    /// Alignment angle A2, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A2: FieldInfo = FieldInfo {
        icd_name: "Alignment angle A2",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Mounting angle 2 (Appendix B).",
        ..FieldInfo::new(
            "alignment_angle_a2",
            field::ALIGNMENT_ANGLE_A2,
            FieldKind::Float,
        )
    };

    /// Alignment angle A3, `f32`, degrees.
    pub const ALIGNMENT_ANGLE_A3: FieldInfo = FieldInfo {
        icd_name: "Alignment angle A3",
        min: -360.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Mounting angle 3 (Appendix B).",
        ..FieldInfo::new(
            "alignment_angle_a3",
            field::ALIGNMENT_ANGLE_A3,
            FieldKind::Float,
        )
    };

    /// Device ID, `char[8]`.
    pub const DEVICE_ID: FieldInfo = FieldInfo {
        icd_name: "Device ID",
        doc: "Device identifier (read only).",
        ..FieldInfo::new("device_id", field::DEVICE_ID, FieldKind::Char)
    };

    /// Reserved, `reserved[6]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 6]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 12] = [
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

payload_table! {
    /// Table 6.10, Parameters read: a zero-copy view over a payload.
    ///
    /// \[`AhrsParametersRead::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`AhrsParametersRead::new_unchecked`\] over a short
    /// buffer (missing bytes read as zero).
    view AhrsParametersRead;
    /// Table 6.10, Parameters read: the payload as a value, with raw field values.
    ///
    /// \[`AhrsParametersReadRepr::parse`\] and \[`AhrsParametersReadRepr::build`\] are
    /// exact inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the
    /// same bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq)]
    repr AhrsParametersReadRepr;
    count 12;
    /// Measurement rate, `u16`, hertz: Output data rate.
    0 number update_rate set_update_rate UPDATE_RATE: u16;
    /// Initial alignment time, `u16`, seconds: Initial alignment duration.
    1 number alignment_time set_alignment_time ALIGNMENT_TIME: u16;
    /// Magnetic declination, `f32`, degrees: Magnetic declination; a value above 360 means
    /// the AHRS computes it.
    2 number declination set_declination DECLINATION: f32;
    /// Latitude, `f32`, degrees: Latitude.
    3 number latitude set_latitude LATITUDE: f32;
    /// Longitude, `f32`, degrees: Longitude.
    4 number longitude set_longitude LONGITUDE: f32;
    /// Altitude, `f32`, metres: Altitude.
    5 number altitude set_altitude ALTITUDE: f32;
    /// Date (Year, Month, Day), `f32`, fractional year, see encoding `date`: Date as Year +
    /// (Month - 1)/12 + Day/365.
    6 number date set_date DATE: f32;
    /// Alignment angle A1, `f32`, degrees: Mounting angle 1 (Appendix B).
    7 number alignment_angle_a1 set_alignment_angle_a1 ALIGNMENT_ANGLE_A1: f32;
    /// Alignment angle A2, `f32`, degrees: Mounting angle 2 (Appendix B).
    8 number alignment_angle_a2 set_alignment_angle_a2 ALIGNMENT_ANGLE_A2: f32;
    /// Alignment angle A3, `f32`, degrees: Mounting angle 3 (Appendix B).
    9 number alignment_angle_a3 set_alignment_angle_a3 ALIGNMENT_ANGLE_A3: f32;
    /// Device ID, `char\[8\]`: Device identifier (read only).
    10 text device_id set_device_id DEVICE_ID: [u8; 8];
    /// Reserved, `reserved\[6\]`:
    11 reserved reserved set_reserved RESERVED: [u8; 6];
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

impl<T: AsRef<[u8]>> AhrsParametersRead<T> {
    /// Magnetic declination: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination())
    }

    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date())
    }
}

impl AhrsParametersReadRepr {
    /// Magnetic declination: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination)
    }

    /// Sets Magnetic declination. Error: `out_of_range` for degrees outside the range.
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

    /// Device ID: the bytes up to the trailing NULs (Latin-1).
    pub fn device_id_text(&self) -> &[u8] {
        crate::wire::trim_nul(&self.device_id)
    }

    /// Sets Device ID: `value` padded with NULs. Error: `out_of_range` when longer
    /// than 8 bytes.
    pub fn set_device_id_text(&mut self, value: &[u8]) -> Result<()> {
        self.device_id = info::DEVICE_ID.array(Value::Bytes(value))?;
        Ok(())
    }
}
