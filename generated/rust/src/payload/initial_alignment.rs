// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.8, Initial alignment data (50 bytes, E21).
//!
//! Sent once when initial alignment completes, before continuous / on-request output or a
//! calibration run starts (6.3.1 - 6.3.3, 6.4). Note the ICD order: heading, roll, pitch.

use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, Encoding, FieldInfo, FieldKind, Unit, Value};
use crate::status::StatusWord;
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 50;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_X: Field = 0..4;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Y: Field = 4..8;
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Z: Field = 8..12;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_X: Field = 12..16;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Y: Field = 16..20;
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Z: Field = 20..24;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_X: Field = 24..28;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Y: Field = 28..32;
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Z: Field = 32..36;
    /// Initial Heading, `f32`, degrees.
    pub const INITIAL_HEADING: Field = 36..40;
    /// Initial Roll, `f32`, degrees.
    pub const INITIAL_ROLL: Field = 40..44;
    /// Initial Pitch, `f32`, degrees.
    pub const INITIAL_PITCH: Field = 44..48;
    /// USW, `u16`.
    pub const USW: Field = 48..50;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_X: FieldInfo = FieldInfo {
        icd_name: "Gyros bias",
        unit: Some(Unit::Adc),
        doc: "Gyro X bias.",
        ..FieldInfo::new("gyro_bias_x", field::GYRO_BIAS_X, FieldKind::Float)
    };

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Y: FieldInfo = FieldInfo {
        icd_name: "Gyros bias",
        unit: Some(Unit::Adc),
        doc: "Gyro Y bias.",
        ..FieldInfo::new("gyro_bias_y", field::GYRO_BIAS_Y, FieldKind::Float)
    };

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD).
    pub const GYRO_BIAS_Z: FieldInfo = FieldInfo {
        icd_name: "Gyros bias",
        unit: Some(Unit::Adc),
        doc: "Gyro Z bias.",
        ..FieldInfo::new("gyro_bias_z", field::GYRO_BIAS_Z, FieldKind::Float)
    };

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_X: FieldInfo = FieldInfo {
        icd_name: "Average acceleration",
        unit: Some(Unit::Adc),
        doc: "Average acceleration along X.",
        ..FieldInfo::new("average_acc_x", field::AVERAGE_ACC_X, FieldKind::Float)
    };

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Y: FieldInfo = FieldInfo {
        icd_name: "Average acceleration",
        unit: Some(Unit::Adc),
        doc: "Average acceleration along Y.",
        ..FieldInfo::new("average_acc_y", field::AVERAGE_ACC_Y, FieldKind::Float)
    };

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_ACC_Z: FieldInfo = FieldInfo {
        icd_name: "Average acceleration",
        unit: Some(Unit::Adc),
        doc: "Average acceleration along Z.",
        ..FieldInfo::new("average_acc_z", field::AVERAGE_ACC_Z, FieldKind::Float)
    };

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_X: FieldInfo = FieldInfo {
        icd_name: "Average magn. field",
        unit: Some(Unit::Adc),
        doc: "Average magnetic field along X.",
        ..FieldInfo::new("average_mag_x", field::AVERAGE_MAG_X, FieldKind::Float)
    };

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Y: FieldInfo = FieldInfo {
        icd_name: "Average magn. field",
        unit: Some(Unit::Adc),
        doc: "Average magnetic field along Y.",
        ..FieldInfo::new("average_mag_y", field::AVERAGE_MAG_Y, FieldKind::Float)
    };

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD).
    pub const AVERAGE_MAG_Z: FieldInfo = FieldInfo {
        icd_name: "Average magn. field",
        unit: Some(Unit::Adc),
        doc: "Average magnetic field along Z.",
        ..FieldInfo::new("average_mag_z", field::AVERAGE_MAG_Z, FieldKind::Float)
    };

    /// Initial Heading, `f32`, degrees.
    pub const INITIAL_HEADING: FieldInfo = FieldInfo {
        icd_name: "Initial Heading",
        min: 0.0,
        max: 360.0,
        unit: Some(Unit::Deg),
        doc: "Heading at the end of alignment.",
        ..FieldInfo::new("initial_heading", field::INITIAL_HEADING, FieldKind::Float)
    };

    /// Initial Roll, `f32`, degrees.
    pub const INITIAL_ROLL: FieldInfo = FieldInfo {
        icd_name: "Initial Roll",
        min: -180.0,
        max: 180.0,
        unit: Some(Unit::Deg),
        doc: "Roll at the end of alignment.",
        ..FieldInfo::new("initial_roll", field::INITIAL_ROLL, FieldKind::Float)
    };

    /// Initial Pitch, `f32`, degrees.
    pub const INITIAL_PITCH: FieldInfo = FieldInfo {
        icd_name: "Initial Pitch",
        min: -90.0,
        max: 90.0,
        unit: Some(Unit::Deg),
        doc: "Pitch at the end of alignment.",
        ..FieldInfo::new("initial_pitch", field::INITIAL_PITCH, FieldKind::Float)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        icd_name: "USW",
        encoding: Some(Encoding::Usw),
        doc: "Unit Status Word: 0 after a successful alignment, non-zero otherwise.",
        ..FieldInfo::new("usw", field::USW, FieldKind::Unsigned)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 13] = [
    info::GYRO_BIAS_X,
    info::GYRO_BIAS_Y,
    info::GYRO_BIAS_Z,
    info::AVERAGE_ACC_X,
    info::AVERAGE_ACC_Y,
    info::AVERAGE_ACC_Z,
    info::AVERAGE_MAG_X,
    info::AVERAGE_MAG_Y,
    info::AVERAGE_MAG_Z,
    info::INITIAL_HEADING,
    info::INITIAL_ROLL,
    info::INITIAL_PITCH,
    info::USW,
];

/// Table 6.8, Initial alignment data: a zero-copy view over a payload.
///
/// [`InitialAlignment::new_checked`] checks the size once; the accessors never panic, even
/// on a view made by [`InitialAlignment::new_unchecked`] over a short buffer (missing bytes
/// read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct InitialAlignment<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> InitialAlignment<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> InitialAlignment<T> {
        InitialAlignment { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<InitialAlignment<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(InitialAlignment { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro X bias.
    pub fn gyro_bias_x(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::GYRO_BIAS_X)
    }

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro Y bias.
    pub fn gyro_bias_y(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::GYRO_BIAS_Y)
    }

    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro Z bias.
    pub fn gyro_bias_z(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::GYRO_BIAS_Z)
    }

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along X.
    pub fn average_acc_x(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_ACC_X)
    }

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along Y.
    pub fn average_acc_y(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_ACC_Y)
    }

    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along Z.
    pub fn average_acc_z(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_ACC_Z)
    }

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along X.
    pub fn average_mag_x(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_MAG_X)
    }

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along Y.
    pub fn average_mag_y(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_MAG_Y)
    }

    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along Z.
    pub fn average_mag_z(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::AVERAGE_MAG_Z)
    }

    /// Initial Heading, `f32`, degrees: Heading at the end of alignment.
    pub fn initial_heading(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::INITIAL_HEADING)
    }

    /// Initial Roll, `f32`, degrees: Roll at the end of alignment.
    pub fn initial_roll(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::INITIAL_ROLL)
    }

    /// Initial Pitch, `f32`, degrees: Pitch at the end of alignment.
    pub fn initial_pitch(&self) -> f32 {
        wire::get(self.buffer.as_ref(), field::INITIAL_PITCH)
    }

    /// USW, `u16`: Unit Status Word: 0 after a successful alignment, non-zero otherwise.
    pub fn usw(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::USW)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> InitialAlignment<T> {
    /// Sets [`Self::gyro_bias_x`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_gyro_bias_x(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::GYRO_BIAS_X, value);
    }

    /// Sets [`Self::gyro_bias_y`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_gyro_bias_y(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::GYRO_BIAS_Y, value);
    }

    /// Sets [`Self::gyro_bias_z`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_gyro_bias_z(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::GYRO_BIAS_Z, value);
    }

    /// Sets [`Self::average_acc_x`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_average_acc_x(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_ACC_X, value);
    }

    /// Sets [`Self::average_acc_y`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_average_acc_y(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_ACC_Y, value);
    }

    /// Sets [`Self::average_acc_z`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_average_acc_z(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_ACC_Z, value);
    }

    /// Sets [`Self::average_mag_x`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_average_mag_x(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_MAG_X, value);
    }

    /// Sets [`Self::average_mag_y`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_average_mag_y(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_MAG_Y, value);
    }

    /// Sets [`Self::average_mag_z`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_average_mag_z(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::AVERAGE_MAG_Z, value);
    }

    /// Sets [`Self::initial_heading`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_initial_heading(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::INITIAL_HEADING, value);
    }

    /// Sets [`Self::initial_roll`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_initial_roll(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::INITIAL_ROLL, value);
    }

    /// Sets [`Self::initial_pitch`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_initial_pitch(&mut self, value: f32) {
        wire::set(self.buffer.as_mut(), field::INITIAL_PITCH, value);
    }

    /// Sets [`Self::usw`] (raw, unchecked: [`InitialAlignmentRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::USW, value);
    }
}

/// Table 6.8, Initial alignment data: the payload as a value, with raw field values.
///
/// [`InitialAlignmentRepr::parse`] and [`InitialAlignmentRepr::build`] are exact inverses:
/// every byte string of [`SIZE`] bytes parses, and builds back to the same bytes when its
/// values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct InitialAlignmentRepr {
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro X bias.
    pub gyro_bias_x: f32,
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro Y bias.
    pub gyro_bias_y: f32,
    /// Gyros bias, `f32`, ADC codes (no physical scale given by the ICD): Gyro Z bias.
    pub gyro_bias_z: f32,
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along X.
    pub average_acc_x: f32,
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along Y.
    pub average_acc_y: f32,
    /// Average acceleration, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// acceleration along Z.
    pub average_acc_z: f32,
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along X.
    pub average_mag_x: f32,
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along Y.
    pub average_mag_y: f32,
    /// Average magn. field, `f32`, ADC codes (no physical scale given by the ICD): Average
    /// magnetic field along Z.
    pub average_mag_z: f32,
    /// Initial Heading, `f32`, degrees: Heading at the end of alignment.
    pub initial_heading: f32,
    /// Initial Roll, `f32`, degrees: Roll at the end of alignment.
    pub initial_roll: f32,
    /// Initial Pitch, `f32`, degrees: Pitch at the end of alignment.
    pub initial_pitch: f32,
    /// USW, `u16`: Unit Status Word: 0 after a successful alignment, non-zero otherwise.
    pub usw: u16,
}

impl InitialAlignmentRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<InitialAlignmentRepr> {
        let view = InitialAlignment::new_checked(data)?;
        Ok(InitialAlignmentRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &InitialAlignment<T>) -> InitialAlignmentRepr {
        InitialAlignmentRepr {
            gyro_bias_x: view.gyro_bias_x(),
            gyro_bias_y: view.gyro_bias_y(),
            gyro_bias_z: view.gyro_bias_z(),
            average_acc_x: view.average_acc_x(),
            average_acc_y: view.average_acc_y(),
            average_acc_z: view.average_acc_z(),
            average_mag_x: view.average_mag_x(),
            average_mag_y: view.average_mag_y(),
            average_mag_z: view.average_mag_z(),
            initial_heading: view.initial_heading(),
            initial_roll: view.initial_roll(),
            initial_pitch: view.initial_pitch(),
            usw: view.usw(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`InitialAlignmentRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`InitialAlignmentRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut InitialAlignment::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut InitialAlignment<T>) {
        view.set_gyro_bias_x(self.gyro_bias_x);
        view.set_gyro_bias_y(self.gyro_bias_y);
        view.set_gyro_bias_z(self.gyro_bias_z);
        view.set_average_acc_x(self.average_acc_x);
        view.set_average_acc_y(self.average_acc_y);
        view.set_average_acc_z(self.average_acc_z);
        view.set_average_mag_x(self.average_mag_x);
        view.set_average_mag_y(self.average_mag_y);
        view.set_average_mag_z(self.average_mag_z);
        view.set_initial_heading(self.initial_heading);
        view.set_initial_roll(self.initial_roll);
        view.set_initial_pitch(self.initial_pitch);
        view.set_usw(self.usw);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`InitialAlignmentRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 13] {
        [
            Raw::value(self.gyro_bias_x),
            Raw::value(self.gyro_bias_y),
            Raw::value(self.gyro_bias_z),
            Raw::value(self.average_acc_x),
            Raw::value(self.average_acc_y),
            Raw::value(self.average_acc_z),
            Raw::value(self.average_mag_x),
            Raw::value(self.average_mag_y),
            Raw::value(self.average_mag_z),
            Raw::value(self.initial_heading),
            Raw::value(self.initial_roll),
            Raw::value(self.initial_pitch),
            Raw::value(self.usw),
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
            0 => self.gyro_bias_x = Raw::from_value(&info::GYRO_BIAS_X, value)?,
            1 => self.gyro_bias_y = Raw::from_value(&info::GYRO_BIAS_Y, value)?,
            2 => self.gyro_bias_z = Raw::from_value(&info::GYRO_BIAS_Z, value)?,
            3 => self.average_acc_x = Raw::from_value(&info::AVERAGE_ACC_X, value)?,
            4 => self.average_acc_y = Raw::from_value(&info::AVERAGE_ACC_Y, value)?,
            5 => self.average_acc_z = Raw::from_value(&info::AVERAGE_ACC_Z, value)?,
            6 => self.average_mag_x = Raw::from_value(&info::AVERAGE_MAG_X, value)?,
            7 => self.average_mag_y = Raw::from_value(&info::AVERAGE_MAG_Y, value)?,
            8 => self.average_mag_z = Raw::from_value(&info::AVERAGE_MAG_Z, value)?,
            9 => self.initial_heading = Raw::from_value(&info::INITIAL_HEADING, value)?,
            10 => self.initial_roll = Raw::from_value(&info::INITIAL_ROLL, value)?,
            11 => self.initial_pitch = Raw::from_value(&info::INITIAL_PITCH, value)?,
            12 => self.usw = Raw::from_value(&info::USW, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}

impl Table for InitialAlignmentRepr {
    fn validate(&self) -> Result<()> {
        InitialAlignmentRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        InitialAlignmentRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        InitialAlignmentRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        InitialAlignmentRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        InitialAlignmentRepr::set_value(self, index, value)
    }
}
