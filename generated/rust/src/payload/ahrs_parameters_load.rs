// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.9, Parameters to load (50 bytes).
//!
//! The data message the host sends right after LoadAHRSPar (6.3.6). Read the block first
//! (ReadAHRSPar), change it, send it back.

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

payload_table! {
    /// Table 6.9, Parameters to load: a zero-copy view over a payload.
    ///
    /// \[`AhrsParametersLoad::new_checked`\] checks the size once; the accessors never
    /// panic, even on a view made by \[`AhrsParametersLoad::new_unchecked`\] over a short
    /// buffer (missing bytes read as zero).
    view AhrsParametersLoad;
    /// Table 6.9, Parameters to load: the payload as a value, with raw field values.
    ///
    /// \[`AhrsParametersLoadRepr::parse`\] and \[`AhrsParametersLoadRepr::build`\] are
    /// exact inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the
    /// same bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq)]
    repr AhrsParametersLoadRepr;
    count 11;
    /// Update rate, `u16`, hertz: Output data rate, 1 to 100 Hz (the AHRS limits NMEA
    /// output to 50 Hz).
    0 number update_rate set_update_rate UPDATE_RATE: u16;
    /// Initial alignment time, `u16`, seconds: Initial alignment duration; default 30 s,
    /// change only in agreement with Inertial Labs.
    1 number alignment_time set_alignment_time ALIGNMENT_TIME: u16;
    /// Magnetic declination, Mdec, `f32`, degrees: Magnetic declination; a value above 360
    /// asks the AHRS to compute it from position and date.
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
    /// Alignment angle A1, `f32`, degrees: Mounting angle 1: AHRS Y axis relative to the
    /// object's longitudinal axis in its horizontal plane, clockwise positive (Appendix B).
    7 number alignment_angle_a1 set_alignment_angle_a1 ALIGNMENT_ANGLE_A1: f32;
    /// Alignment angle A2, `f32`, degrees: Mounting angle 2: inclination of the AHRS Y axis
    /// to the object's horizontal plane, up positive (Appendix B).
    8 number alignment_angle_a2 set_alignment_angle_a2 ALIGNMENT_ANGLE_A2: f32;
    /// Alignment angle A3, `f32`, degrees: Mounting angle 3: inclination of the AHRS X axis
    /// about its Y axis, X down positive (Appendix B).
    9 number alignment_angle_a3 set_alignment_angle_a3 ALIGNMENT_ANGLE_A3: f32;
    /// Reserved, `reserved\[14\]`: Should be all zeros.
    10 reserved reserved set_reserved RESERVED: [u8; 14];
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

impl<T: AsRef<[u8]>> AhrsParametersLoad<T> {
    /// Magnetic declination, Mdec: degrees, or a request that the AHRS compute it.
    pub fn declination_decoded(&self) -> Declination {
        Declination::decode(self.declination())
    }

    /// Date (Year, Month, Day) as the nearest calendar date, or `None` (see [`Date::decode`]).
    pub fn date_decoded(&self) -> Option<Date> {
        Date::decode(self.date())
    }
}

impl AhrsParametersLoadRepr {
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
