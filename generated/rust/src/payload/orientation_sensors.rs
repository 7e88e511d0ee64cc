// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.6, Orientation + Sensor Outputs (34 bytes).
//!
//! Output block after AHRScont3 / AHRSreq3 (the default format, section 6.2).

use crate::error::Result;
use crate::payload::codec::{self, Raw, Table};
use crate::payload::{check_size, FieldInfo, FieldKind, Scale, Unit, Value};
use crate::status::StatusWord;
use crate::variant::{Variant, VariantParameter};
use crate::wire;

/// Size of the payload (bytes).
pub const SIZE: usize = 34;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Heading, `u16`, raw x 1 / 100 = degrees.
    pub const HEADING: Field = 0..2;
    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: Field = 2..4;
    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: Field = 4..6;
    /// GyroX, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_X: Field = 6..8;
    /// GyroY, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Y: Field = 8..10;
    /// GyroZ, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Z: Field = 10..12;
    /// AccX, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_X: Field = 12..14;
    /// AccY, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Y: Field = 14..16;
    /// AccZ, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Z: Field = 16..18;
    /// MagX, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_X: Field = 18..20;
    /// MagY, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Y: Field = 20..22;
    /// MagZ, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Z: Field = 22..24;
    /// Reserved, `reserved[4]`.
    pub const RESERVED: Field = 24..28;
    /// USW, `u16`.
    pub const USW: Field = 28..30;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: Field = 30..32;
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: Field = 32..34;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Heading, `u16`, raw x 1 / 100 = degrees.
    pub const HEADING: FieldInfo = crate::payload::full_output::info::HEADING;

    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: FieldInfo = crate::payload::full_output::info::PITCH;

    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: FieldInfo = crate::payload::full_output::info::ROLL;

    /// GyroX, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_X: FieldInfo = FieldInfo {
        icd_name: "GyroX",
        scale: Some(Scale::by(1, VariantParameter::Kg)),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about X (lateral axis).",
        ..FieldInfo::new("gyro_x", field::GYRO_X, FieldKind::Signed)
    };

    /// GyroY, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Y: FieldInfo = FieldInfo {
        icd_name: "GyroY",
        scale: Some(Scale::by(1, VariantParameter::Kg)),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about Y (longitudinal axis).",
        ..FieldInfo::new("gyro_y", field::GYRO_Y, FieldKind::Signed)
    };

    /// GyroZ, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Z: FieldInfo = FieldInfo {
        icd_name: "GyroZ",
        scale: Some(Scale::by(1, VariantParameter::Kg)),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about Z (vertical axis).",
        ..FieldInfo::new("gyro_z", field::GYRO_Z, FieldKind::Signed)
    };

    /// AccX, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_X: FieldInfo = FieldInfo {
        icd_name: "AccX",
        scale: Some(Scale::by(1, VariantParameter::Ka)),
        unit: Some(Unit::G),
        doc: "Linear acceleration along X.",
        ..FieldInfo::new("acc_x", field::ACC_X, FieldKind::Signed)
    };

    /// AccY, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Y: FieldInfo = FieldInfo {
        icd_name: "AccY",
        scale: Some(Scale::by(1, VariantParameter::Ka)),
        unit: Some(Unit::G),
        doc: "Linear acceleration along Y.",
        ..FieldInfo::new("acc_y", field::ACC_Y, FieldKind::Signed)
    };

    /// AccZ, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Z: FieldInfo = FieldInfo {
        icd_name: "AccZ",
        scale: Some(Scale::by(1, VariantParameter::Ka)),
        unit: Some(Unit::G),
        doc: "Linear acceleration along Z.",
        ..FieldInfo::new("acc_z", field::ACC_Z, FieldKind::Signed)
    };

    /// MagX, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_X: FieldInfo = FieldInfo {
        icd_name: "MagX",
        scale: Some(Scale::fixed(10, 1)),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along X.",
        ..FieldInfo::new("mag_x", field::MAG_X, FieldKind::Signed)
    };

    /// MagY, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Y: FieldInfo = FieldInfo {
        icd_name: "MagY",
        scale: Some(Scale::fixed(10, 1)),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along Y.",
        ..FieldInfo::new("mag_y", field::MAG_Y, FieldKind::Signed)
    };

    /// MagZ, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Z: FieldInfo = FieldInfo {
        icd_name: "MagZ",
        scale: Some(Scale::fixed(10, 1)),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along Z.",
        ..FieldInfo::new("mag_z", field::MAG_Z, FieldKind::Signed)
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED: FieldInfo = crate::payload::full_output::info::RESERVED;

    /// USW, `u16`.
    pub const USW: FieldInfo = crate::payload::full_output::info::USW;

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: FieldInfo = crate::payload::quaternion::info::VDD;

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: FieldInfo = crate::payload::quaternion::info::UTERMO;
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 16] = [
    info::HEADING,
    info::PITCH,
    info::ROLL,
    info::GYRO_X,
    info::GYRO_Y,
    info::GYRO_Z,
    info::ACC_X,
    info::ACC_Y,
    info::ACC_Z,
    info::MAG_X,
    info::MAG_Y,
    info::MAG_Z,
    info::RESERVED,
    info::USW,
    info::VDD,
    info::UTERMO,
];

/// Table 6.6, Orientation + Sensor Outputs: a zero-copy view over a payload.
///
/// [`OrientationSensors::new_checked`] checks the size once; the accessors never panic,
/// even on a view made by [`OrientationSensors::new_unchecked`] over a short buffer
/// (missing bytes read as zero).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OrientationSensors<T: AsRef<[u8]>> {
    buffer: T,
}

impl<T: AsRef<[u8]>> OrientationSensors<T> {
    /// A view over `buffer` without any check.
    pub const fn new_unchecked(buffer: T) -> OrientationSensors<T> {
        OrientationSensors { buffer }
    }

    /// A view over `buffer`, which must be exactly [`SIZE`] bytes: `truncated` at its
    /// length when shorter, `trailing_data` at [`SIZE`] when longer.
    pub fn new_checked(buffer: T) -> Result<OrientationSensors<T>> {
        check_size(buffer.as_ref().len(), SIZE)?;
        Ok(OrientationSensors { buffer })
    }

    /// The buffer.
    pub fn into_inner(self) -> T {
        self.buffer
    }

    /// The payload's bytes.
    pub fn as_bytes(&self) -> &[u8] {
        self.buffer.as_ref()
    }

    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub fn heading(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::HEADING)
    }

    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub fn pitch(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::PITCH)
    }

    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub fn roll(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::ROLL)
    }

    /// GyroX, `s16`, raw x 1 / KG = degrees per second: Angular rate about X (lateral
    /// axis).
    pub fn gyro_x(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::GYRO_X)
    }

    /// GyroY, `s16`, raw x 1 / KG = degrees per second: Angular rate about Y (longitudinal
    /// axis).
    pub fn gyro_y(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::GYRO_Y)
    }

    /// GyroZ, `s16`, raw x 1 / KG = degrees per second: Angular rate about Z (vertical
    /// axis).
    pub fn gyro_z(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::GYRO_Z)
    }

    /// AccX, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along X.
    pub fn acc_x(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::ACC_X)
    }

    /// AccY, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Y.
    pub fn acc_y(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::ACC_Y)
    }

    /// AccZ, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Z.
    pub fn acc_z(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::ACC_Z)
    }

    /// MagX, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along X.
    pub fn mag_x(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::MAG_X)
    }

    /// MagY, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Y.
    pub fn mag_y(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::MAG_Y)
    }

    /// MagZ, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Z.
    pub fn mag_z(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::MAG_Z)
    }

    /// Reserved, `reserved[4]`.
    pub fn reserved(&self) -> &[u8] {
        wire::bytes(self.buffer.as_ref(), field::RESERVED)
    }

    /// USW, `u16`: Unit Status Word (section 6.5).
    pub fn usw(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::USW)
    }

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub fn vdd(&self) -> u16 {
        wire::get(self.buffer.as_ref(), field::VDD)
    }

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3
    /// accelerometers.
    pub fn utermo(&self) -> i16 {
        wire::get(self.buffer.as_ref(), field::UTERMO)
    }

    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        info::HEADING.scaled(f64::from(self.heading()), None)
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        info::PITCH.scaled(f64::from(self.pitch()), None)
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        info::ROLL.scaled(f64::from(self.roll()), None)
    }

    /// GyroX (degrees per second) for the device `variant`: Angular rate about X (lateral
    /// axis).
    pub fn gyro_x_dps(&self, variant: Variant) -> f64 {
        info::GYRO_X.scaled(f64::from(self.gyro_x()), Some(variant))
    }

    /// GyroY (degrees per second) for the device `variant`: Angular rate about Y
    /// (longitudinal axis).
    pub fn gyro_y_dps(&self, variant: Variant) -> f64 {
        info::GYRO_Y.scaled(f64::from(self.gyro_y()), Some(variant))
    }

    /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z (vertical
    /// axis).
    pub fn gyro_z_dps(&self, variant: Variant) -> f64 {
        info::GYRO_Z.scaled(f64::from(self.gyro_z()), Some(variant))
    }

    /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
    pub fn acc_x_g(&self, variant: Variant) -> f64 {
        info::ACC_X.scaled(f64::from(self.acc_x()), Some(variant))
    }

    /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
    pub fn acc_y_g(&self, variant: Variant) -> f64 {
        info::ACC_Y.scaled(f64::from(self.acc_y()), Some(variant))
    }

    /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
    pub fn acc_z_g(&self, variant: Variant) -> f64 {
        info::ACC_Z.scaled(f64::from(self.acc_z()), Some(variant))
    }

    /// MagX (nanotesla): Magnetic field along X.
    pub fn mag_x_nt(&self) -> f64 {
        info::MAG_X.scaled(f64::from(self.mag_x()), None)
    }

    /// MagY (nanotesla): Magnetic field along Y.
    pub fn mag_y_nt(&self) -> f64 {
        info::MAG_Y.scaled(f64::from(self.mag_y()), None)
    }

    /// MagZ (nanotesla): Magnetic field along Z.
    pub fn mag_z_nt(&self) -> f64 {
        info::MAG_Z.scaled(f64::from(self.mag_z()), None)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        info::VDD.scaled(f64::from(self.vdd()), None)
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        info::UTERMO.scaled(f64::from(self.utermo()), None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl<T: AsRef<[u8]> + AsMut<[u8]>> OrientationSensors<T> {
    /// Sets [`Self::heading`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_heading(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::HEADING, value);
    }

    /// Sets [`Self::pitch`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_pitch(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::PITCH, value);
    }

    /// Sets [`Self::roll`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_roll(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::ROLL, value);
    }

    /// Sets [`Self::gyro_x`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_gyro_x(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::GYRO_X, value);
    }

    /// Sets [`Self::gyro_y`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_gyro_y(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::GYRO_Y, value);
    }

    /// Sets [`Self::gyro_z`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_gyro_z(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::GYRO_Z, value);
    }

    /// Sets [`Self::acc_x`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_acc_x(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::ACC_X, value);
    }

    /// Sets [`Self::acc_y`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_acc_y(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::ACC_Y, value);
    }

    /// Sets [`Self::acc_z`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_acc_z(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::ACC_Z, value);
    }

    /// Sets [`Self::mag_x`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_mag_x(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::MAG_X, value);
    }

    /// Sets [`Self::mag_y`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_mag_y(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::MAG_Y, value);
    }

    /// Sets [`Self::mag_z`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_mag_z(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::MAG_Z, value);
    }

    /// Sets [`Self::reserved`] (bytes kept verbatim).
    pub fn set_reserved(&mut self, value: &[u8; 4]) {
        wire::put(self.buffer.as_mut(), field::RESERVED, value);
    }

    /// Sets [`Self::usw`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_usw(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::USW, value);
    }

    /// Sets [`Self::vdd`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_vdd(&mut self, value: u16) {
        wire::set(self.buffer.as_mut(), field::VDD, value);
    }

    /// Sets [`Self::utermo`] (raw, unchecked: [`OrientationSensorsRepr::build`] checks ranges).
    pub fn set_utermo(&mut self, value: i16) {
        wire::set(self.buffer.as_mut(), field::UTERMO, value);
    }
}

/// Table 6.6, Orientation + Sensor Outputs: the payload as a value, with raw field values.
///
/// [`OrientationSensorsRepr::parse`] and [`OrientationSensorsRepr::build`] are exact
/// inverses: every byte string of [`SIZE`] bytes parses, and builds back to the same bytes
/// when its values are in range.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OrientationSensorsRepr {
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    pub heading: u16,
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    pub pitch: i16,
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    pub roll: i16,
    /// GyroX, `s16`, raw x 1 / KG = degrees per second: Angular rate about X (lateral
    /// axis).
    pub gyro_x: i16,
    /// GyroY, `s16`, raw x 1 / KG = degrees per second: Angular rate about Y (longitudinal
    /// axis).
    pub gyro_y: i16,
    /// GyroZ, `s16`, raw x 1 / KG = degrees per second: Angular rate about Z (vertical
    /// axis).
    pub gyro_z: i16,
    /// AccX, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along X.
    pub acc_x: i16,
    /// AccY, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Y.
    pub acc_y: i16,
    /// AccZ, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Z.
    pub acc_z: i16,
    /// MagX, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along X.
    pub mag_x: i16,
    /// MagY, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Y.
    pub mag_y: i16,
    /// MagZ, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Z.
    pub mag_z: i16,
    /// Reserved, `reserved[4]`.
    pub reserved: [u8; 4],
    /// USW, `u16`: Unit Status Word (section 6.5).
    pub usw: u16,
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    pub vdd: u16,
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3
    /// accelerometers.
    pub utermo: i16,
}

impl OrientationSensorsRepr {
    /// Decodes exactly [`SIZE`] bytes (`truncated` or `trailing_data` otherwise).
    /// Decoding does not check ranges.
    pub fn parse(data: &[u8]) -> Result<OrientationSensorsRepr> {
        let view = OrientationSensors::new_checked(data)?;
        Ok(OrientationSensorsRepr::from_view(&view))
    }

    /// The value of a view.
    pub fn from_view<T: AsRef<[u8]>>(view: &OrientationSensors<T>) -> OrientationSensorsRepr {
        OrientationSensorsRepr {
            heading: view.heading(),
            pitch: view.pitch(),
            roll: view.roll(),
            gyro_x: view.gyro_x(),
            gyro_y: view.gyro_y(),
            gyro_z: view.gyro_z(),
            acc_x: view.acc_x(),
            acc_y: view.acc_y(),
            acc_z: view.acc_z(),
            mag_x: view.mag_x(),
            mag_y: view.mag_y(),
            mag_z: view.mag_z(),
            reserved: wire::array(view.as_bytes(), field::RESERVED),
            usw: view.usw(),
            vdd: view.vdd(),
            utermo: view.utermo(),
        }
    }

    /// Checks every field in table order, as a builder does; the first bad one is the
    /// error: `out_of_range` at the field's offset, naming the field.
    pub fn validate(&self) -> Result<()> {
        codec::validate(&FIELDS, &self.values())
    }

    /// The size of the payload [`OrientationSensorsRepr::build`] writes (bytes).
    pub const fn buffer_len(&self) -> usize {
        SIZE
    }

    /// Checks the value ([`OrientationSensorsRepr::validate`]) and writes it into
    /// `buf`; returns its size (bytes), or `buffer_too_small`.
    pub fn build(&self, buf: &mut [u8]) -> Result<usize> {
        self.validate()?;
        let out = codec::payload_buffer(buf, SIZE)?;
        self.emit(&mut OrientationSensors::new_unchecked(out));
        Ok(SIZE)
    }

    /// Writes the value into a view without checking it.
    pub fn emit<T: AsRef<[u8]> + AsMut<[u8]>>(&self, view: &mut OrientationSensors<T>) {
        view.set_heading(self.heading);
        view.set_pitch(self.pitch);
        view.set_roll(self.roll);
        view.set_gyro_x(self.gyro_x);
        view.set_gyro_y(self.gyro_y);
        view.set_gyro_z(self.gyro_z);
        view.set_acc_x(self.acc_x);
        view.set_acc_y(self.acc_y);
        view.set_acc_z(self.acc_z);
        view.set_mag_x(self.mag_x);
        view.set_mag_y(self.mag_y);
        view.set_mag_z(self.mag_z);
        wire::put(view.buffer.as_mut(), field::RESERVED, &self.reserved);
        view.set_usw(self.usw);
        view.set_vdd(self.vdd);
        view.set_utermo(self.utermo);
    }

    /// Writes a data frame (reserved byte 0) carrying the payload into `buf`; returns its
    /// size (bytes). Errors: those of [`OrientationSensorsRepr::build`].
    pub fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        let mut payload = [0; SIZE];
        self.build(&mut payload)?;
        codec::data_frame(&payload, buf)
    }

    /// Every raw value, in table order (text without its trailing NULs).
    pub fn values(&self) -> [Value<'_>; 16] {
        [
            Raw::value(self.heading),
            Raw::value(self.pitch),
            Raw::value(self.roll),
            Raw::value(self.gyro_x),
            Raw::value(self.gyro_y),
            Raw::value(self.gyro_z),
            Raw::value(self.acc_x),
            Raw::value(self.acc_y),
            Raw::value(self.acc_z),
            Raw::value(self.mag_x),
            Raw::value(self.mag_y),
            Raw::value(self.mag_z),
            Value::Bytes(&self.reserved),
            Raw::value(self.usw),
            Raw::value(self.vdd),
            Raw::value(self.utermo),
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
            0 => self.heading = Raw::from_value(&info::HEADING, value)?,
            1 => self.pitch = Raw::from_value(&info::PITCH, value)?,
            2 => self.roll = Raw::from_value(&info::ROLL, value)?,
            3 => self.gyro_x = Raw::from_value(&info::GYRO_X, value)?,
            4 => self.gyro_y = Raw::from_value(&info::GYRO_Y, value)?,
            5 => self.gyro_z = Raw::from_value(&info::GYRO_Z, value)?,
            6 => self.acc_x = Raw::from_value(&info::ACC_X, value)?,
            7 => self.acc_y = Raw::from_value(&info::ACC_Y, value)?,
            8 => self.acc_z = Raw::from_value(&info::ACC_Z, value)?,
            9 => self.mag_x = Raw::from_value(&info::MAG_X, value)?,
            10 => self.mag_y = Raw::from_value(&info::MAG_Y, value)?,
            11 => self.mag_z = Raw::from_value(&info::MAG_Z, value)?,
            12 => self.reserved = info::RESERVED.array(value)?,
            13 => self.usw = Raw::from_value(&info::USW, value)?,
            14 => self.vdd = Raw::from_value(&info::VDD, value)?,
            15 => self.utermo = Raw::from_value(&info::UTERMO, value)?,
            _ => return Err(codec::no_field(index, FIELDS.len())),
        }
        Ok(())
    }

    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        info::HEADING.scaled(f64::from(self.heading), None)
    }

    /// Sets [`Self::heading`] from an engineering value (see
    /// [`Self::heading_deg`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_heading_deg(&mut self, value: f64) -> Result<()> {
        info::HEADING.set_scaled(&mut self.heading, value, None)
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        info::PITCH.scaled(f64::from(self.pitch), None)
    }

    /// Sets [`Self::pitch`] from an engineering value (see
    /// [`Self::pitch_deg`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_pitch_deg(&mut self, value: f64) -> Result<()> {
        info::PITCH.set_scaled(&mut self.pitch, value, None)
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        info::ROLL.scaled(f64::from(self.roll), None)
    }

    /// Sets [`Self::roll`] from an engineering value (see
    /// [`Self::roll_deg`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_roll_deg(&mut self, value: f64) -> Result<()> {
        info::ROLL.set_scaled(&mut self.roll, value, None)
    }

    /// GyroX (degrees per second) for the device `variant`: Angular rate about X (lateral
    /// axis).
    pub fn gyro_x_dps(&self, variant: Variant) -> f64 {
        info::GYRO_X.scaled(f64::from(self.gyro_x), Some(variant))
    }

    /// Sets [`Self::gyro_x`] from an engineering value (see
    /// [`Self::gyro_x_dps`]) for the device `variant`, rounded half
    /// away from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_x_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        info::GYRO_X.set_scaled(&mut self.gyro_x, value, Some(variant))
    }

    /// GyroY (degrees per second) for the device `variant`: Angular rate about Y
    /// (longitudinal axis).
    pub fn gyro_y_dps(&self, variant: Variant) -> f64 {
        info::GYRO_Y.scaled(f64::from(self.gyro_y), Some(variant))
    }

    /// Sets [`Self::gyro_y`] from an engineering value (see
    /// [`Self::gyro_y_dps`]) for the device `variant`, rounded half
    /// away from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_y_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        info::GYRO_Y.set_scaled(&mut self.gyro_y, value, Some(variant))
    }

    /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z (vertical
    /// axis).
    pub fn gyro_z_dps(&self, variant: Variant) -> f64 {
        info::GYRO_Z.scaled(f64::from(self.gyro_z), Some(variant))
    }

    /// Sets [`Self::gyro_z`] from an engineering value (see
    /// [`Self::gyro_z_dps`]) for the device `variant`, rounded half
    /// away from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_z_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        info::GYRO_Z.set_scaled(&mut self.gyro_z, value, Some(variant))
    }

    /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
    pub fn acc_x_g(&self, variant: Variant) -> f64 {
        info::ACC_X.scaled(f64::from(self.acc_x), Some(variant))
    }

    /// Sets [`Self::acc_x`] from an engineering value (see
    /// [`Self::acc_x_g`]) for the device `variant`, rounded half
    /// away from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_x_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        info::ACC_X.set_scaled(&mut self.acc_x, value, Some(variant))
    }

    /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
    pub fn acc_y_g(&self, variant: Variant) -> f64 {
        info::ACC_Y.scaled(f64::from(self.acc_y), Some(variant))
    }

    /// Sets [`Self::acc_y`] from an engineering value (see
    /// [`Self::acc_y_g`]) for the device `variant`, rounded half
    /// away from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_y_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        info::ACC_Y.set_scaled(&mut self.acc_y, value, Some(variant))
    }

    /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
    pub fn acc_z_g(&self, variant: Variant) -> f64 {
        info::ACC_Z.scaled(f64::from(self.acc_z), Some(variant))
    }

    /// Sets [`Self::acc_z`] from an engineering value (see
    /// [`Self::acc_z_g`]) for the device `variant`, rounded half
    /// away from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_z_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        info::ACC_Z.set_scaled(&mut self.acc_z, value, Some(variant))
    }

    /// MagX (nanotesla): Magnetic field along X.
    pub fn mag_x_nt(&self) -> f64 {
        info::MAG_X.scaled(f64::from(self.mag_x), None)
    }

    /// Sets [`Self::mag_x`] from an engineering value (see
    /// [`Self::mag_x_nt`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_mag_x_nt(&mut self, value: f64) -> Result<()> {
        info::MAG_X.set_scaled(&mut self.mag_x, value, None)
    }

    /// MagY (nanotesla): Magnetic field along Y.
    pub fn mag_y_nt(&self) -> f64 {
        info::MAG_Y.scaled(f64::from(self.mag_y), None)
    }

    /// Sets [`Self::mag_y`] from an engineering value (see
    /// [`Self::mag_y_nt`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_mag_y_nt(&mut self, value: f64) -> Result<()> {
        info::MAG_Y.set_scaled(&mut self.mag_y, value, None)
    }

    /// MagZ (nanotesla): Magnetic field along Z.
    pub fn mag_z_nt(&self) -> f64 {
        info::MAG_Z.scaled(f64::from(self.mag_z), None)
    }

    /// Sets [`Self::mag_z`] from an engineering value (see
    /// [`Self::mag_z_nt`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_mag_z_nt(&mut self, value: f64) -> Result<()> {
        info::MAG_Z.set_scaled(&mut self.mag_z, value, None)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        info::VDD.scaled(f64::from(self.vdd), None)
    }

    /// Sets [`Self::vdd`] from an engineering value (see
    /// [`Self::vdd_v`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_vdd_v(&mut self, value: f64) -> Result<()> {
        info::VDD.set_scaled(&mut self.vdd, value, None)
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        info::UTERMO.scaled(f64::from(self.utermo), None)
    }

    /// Sets [`Self::utermo`] from an engineering value (see
    /// [`Self::utermo_degc`]), rounded half away from zero. Error:
    /// `out_of_range` naming the field.
    pub fn set_utermo_degc(&mut self, value: f64) -> Result<()> {
        info::UTERMO.set_scaled(&mut self.utermo, value, None)
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}

impl Table for OrientationSensorsRepr {
    fn validate(&self) -> Result<()> {
        OrientationSensorsRepr::validate(self)
    }

    fn build(&self, buf: &mut [u8]) -> Result<usize> {
        OrientationSensorsRepr::build(self, buf)
    }

    fn build_frame(&self, buf: &mut [u8]) -> Result<usize> {
        OrientationSensorsRepr::build_frame(self, buf)
    }

    fn value(&self, index: usize) -> Option<Value<'_>> {
        OrientationSensorsRepr::value(self, index)
    }

    fn set_value(&mut self, index: usize, value: Value<'_>) -> Result<()> {
        OrientationSensorsRepr::set_value(self, index, value)
    }
}
