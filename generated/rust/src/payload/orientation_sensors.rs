// Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.6, Orientation + Sensor Outputs (34 bytes).
//!
//! Output block after AHRScont3 / AHRSreq3 (the default format, section 6.2).

use crate::error::Result;
use crate::payload::codec::payload_table;
use crate::payload::{Divisor, Encoding, FieldInfo, FieldKind, Scale, Unit, Value};
use crate::status::StatusWord;
use crate::variant::{Variant, VariantParameter};

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
    pub const HEADING: FieldInfo = FieldInfo {
        icd_name: "Heading",
        min: 0.0,
        max: 35999.0,
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Fixed(100),
        }),
        unit: Some(Unit::Deg),
        doc: "Heading angle.",
        ..FieldInfo::new("heading", field::HEADING, FieldKind::Unsigned)
    };

    /// Pitch, `s16`, raw x 1 / 100 = degrees.
    pub const PITCH: FieldInfo = FieldInfo {
        icd_name: "Pitch",
        min: -9000.0,
        max: 9000.0,
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Fixed(100),
        }),
        unit: Some(Unit::Deg),
        doc: "Pitch angle.",
        ..FieldInfo::new("pitch", field::PITCH, FieldKind::Signed)
    };

    /// Roll, `s16`, raw x 1 / 100 = degrees.
    pub const ROLL: FieldInfo = FieldInfo {
        icd_name: "Roll",
        min: -18000.0,
        max: 18000.0,
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Fixed(100),
        }),
        unit: Some(Unit::Deg),
        doc: "Roll angle.",
        ..FieldInfo::new("roll", field::ROLL, FieldKind::Signed)
    };

    /// GyroX, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_X: FieldInfo = FieldInfo {
        icd_name: "GyroX",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Parameter(VariantParameter::Kg),
        }),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about X (lateral axis).",
        ..FieldInfo::new("gyro_x", field::GYRO_X, FieldKind::Signed)
    };

    /// GyroY, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Y: FieldInfo = FieldInfo {
        icd_name: "GyroY",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Parameter(VariantParameter::Kg),
        }),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about Y (longitudinal axis).",
        ..FieldInfo::new("gyro_y", field::GYRO_Y, FieldKind::Signed)
    };

    /// GyroZ, `s16`, raw x 1 / KG = degrees per second.
    pub const GYRO_Z: FieldInfo = FieldInfo {
        icd_name: "GyroZ",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Parameter(VariantParameter::Kg),
        }),
        unit: Some(Unit::DegPerS),
        doc: "Angular rate about Z (vertical axis).",
        ..FieldInfo::new("gyro_z", field::GYRO_Z, FieldKind::Signed)
    };

    /// AccX, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_X: FieldInfo = FieldInfo {
        icd_name: "AccX",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Parameter(VariantParameter::Ka),
        }),
        unit: Some(Unit::G),
        doc: "Linear acceleration along X.",
        ..FieldInfo::new("acc_x", field::ACC_X, FieldKind::Signed)
    };

    /// AccY, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Y: FieldInfo = FieldInfo {
        icd_name: "AccY",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Parameter(VariantParameter::Ka),
        }),
        unit: Some(Unit::G),
        doc: "Linear acceleration along Y.",
        ..FieldInfo::new("acc_y", field::ACC_Y, FieldKind::Signed)
    };

    /// AccZ, `s16`, raw x 1 / KA = standard gravity.
    pub const ACC_Z: FieldInfo = FieldInfo {
        icd_name: "AccZ",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Parameter(VariantParameter::Ka),
        }),
        unit: Some(Unit::G),
        doc: "Linear acceleration along Z.",
        ..FieldInfo::new("acc_z", field::ACC_Z, FieldKind::Signed)
    };

    /// MagX, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_X: FieldInfo = FieldInfo {
        icd_name: "MagX",
        scale: Some(Scale {
            multiplier: 10,
            divisor: Divisor::Fixed(1),
        }),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along X.",
        ..FieldInfo::new("mag_x", field::MAG_X, FieldKind::Signed)
    };

    /// MagY, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Y: FieldInfo = FieldInfo {
        icd_name: "MagY",
        scale: Some(Scale {
            multiplier: 10,
            divisor: Divisor::Fixed(1),
        }),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along Y.",
        ..FieldInfo::new("mag_y", field::MAG_Y, FieldKind::Signed)
    };

    /// MagZ, `s16`, raw x 10 / 1 = nanotesla.
    pub const MAG_Z: FieldInfo = FieldInfo {
        icd_name: "MagZ",
        scale: Some(Scale {
            multiplier: 10,
            divisor: Divisor::Fixed(1),
        }),
        unit: Some(Unit::Nt),
        doc: "Magnetic field along Z.",
        ..FieldInfo::new("mag_z", field::MAG_Z, FieldKind::Signed)
    };

    /// Reserved, `reserved[4]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 4]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        icd_name: "USW",
        encoding: Some(Encoding::Usw),
        doc: "Unit Status Word (section 6.5).",
        ..FieldInfo::new("usw", field::USW, FieldKind::Unsigned)
    };

    /// Vdd, `u16`, raw x 1 / 1000 = volts DC.
    pub const VDD: FieldInfo = FieldInfo {
        icd_name: "Vdd",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Fixed(1000),
        }),
        unit: Some(Unit::V),
        doc: "AHRS input voltage.",
        ..FieldInfo::new("vdd", field::VDD, FieldKind::Unsigned)
    };

    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius.
    pub const UTERMO: FieldInfo = FieldInfo {
        icd_name: "Utermo",
        scale: Some(Scale {
            multiplier: 1,
            divisor: Divisor::Fixed(10),
        }),
        unit: Some(Unit::Degc),
        doc: "Average temperature of the 3 accelerometers.",
        ..FieldInfo::new("utermo", field::UTERMO, FieldKind::Signed)
    };
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

payload_table! {
    /// Table 6.6, Orientation + Sensor Outputs: a zero-copy view over a payload.
    ///
    /// [`OrientationSensors::new_checked`] checks the size once; the accessors never panic, even on a
    /// view made by [`OrientationSensors::new_unchecked`] over a short buffer (missing bytes read as zero).
    view OrientationSensors;
    /// Table 6.6, Orientation + Sensor Outputs: the payload as a value, with raw field values.
    ///
    /// [`OrientationSensorsRepr::parse`] and [`OrientationSensorsRepr::build`] are exact inverses: every byte string of
    /// [`SIZE`] bytes parses, and builds back to the same bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr OrientationSensorsRepr;
    count 16;
    /// Heading, `u16`, raw x 1 / 100 = degrees: Heading angle.
    0 number heading set_heading HEADING: u16;
    /// Pitch, `s16`, raw x 1 / 100 = degrees: Pitch angle.
    1 number pitch set_pitch PITCH: i16;
    /// Roll, `s16`, raw x 1 / 100 = degrees: Roll angle.
    2 number roll set_roll ROLL: i16;
    /// GyroX, `s16`, raw x 1 / KG = degrees per second: Angular rate about X (lateral axis).
    3 number gyro_x set_gyro_x GYRO_X: i16;
    /// GyroY, `s16`, raw x 1 / KG = degrees per second: Angular rate about Y (longitudinal axis).
    4 number gyro_y set_gyro_y GYRO_Y: i16;
    /// GyroZ, `s16`, raw x 1 / KG = degrees per second: Angular rate about Z (vertical axis).
    5 number gyro_z set_gyro_z GYRO_Z: i16;
    /// AccX, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along X.
    6 number acc_x set_acc_x ACC_X: i16;
    /// AccY, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Y.
    7 number acc_y set_acc_y ACC_Y: i16;
    /// AccZ, `s16`, raw x 1 / KA = standard gravity: Linear acceleration along Z.
    8 number acc_z set_acc_z ACC_Z: i16;
    /// MagX, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along X.
    9 number mag_x set_mag_x MAG_X: i16;
    /// MagY, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Y.
    10 number mag_y set_mag_y MAG_Y: i16;
    /// MagZ, `s16`, raw x 10 / 1 = nanotesla: Magnetic field along Z.
    11 number mag_z set_mag_z MAG_Z: i16;
    /// Reserved, `reserved\[4\]`:
    12 reserved reserved set_reserved RESERVED: [u8; 4];
    /// USW, `u16`: Unit Status Word (section 6.5).
    13 number usw set_usw USW: u16;
    /// Vdd, `u16`, raw x 1 / 1000 = volts DC: AHRS input voltage.
    14 number vdd set_vdd VDD: u16;
    /// Utermo, `s16`, raw x 1 / 10 = degrees Celsius: Average temperature of the 3 accelerometers.
    15 number utermo set_utermo UTERMO: i16;
}

impl<T: AsRef<[u8]>> OrientationSensors<T> {
    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        f64::from(self.heading()) / 100.0
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        f64::from(self.pitch()) / 100.0
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        f64::from(self.roll()) / 100.0
    }

    /// GyroX (degrees per second) for the device `variant`: Angular rate about X (lateral axis).
    pub fn gyro_x_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_x()) / f64::from(variant.kg())
    }

    /// GyroY (degrees per second) for the device `variant`: Angular rate about Y (longitudinal axis).
    pub fn gyro_y_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_y()) / f64::from(variant.kg())
    }

    /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z (vertical axis).
    pub fn gyro_z_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_z()) / f64::from(variant.kg())
    }

    /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
    pub fn acc_x_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_x()) / f64::from(variant.ka())
    }

    /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
    pub fn acc_y_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_y()) / f64::from(variant.ka())
    }

    /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
    pub fn acc_z_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_z()) / f64::from(variant.ka())
    }

    /// MagX (nanotesla): Magnetic field along X.
    pub fn mag_x_nt(&self) -> f64 {
        f64::from(self.mag_x()) * 10.0
    }

    /// MagY (nanotesla): Magnetic field along Y.
    pub fn mag_y_nt(&self) -> f64 {
        f64::from(self.mag_y()) * 10.0
    }

    /// MagZ (nanotesla): Magnetic field along Z.
    pub fn mag_z_nt(&self) -> f64 {
        f64::from(self.mag_z()) * 10.0
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        f64::from(self.vdd()) / 1000.0
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        f64::from(self.utermo()) / 10.0
    }
}

impl OrientationSensorsRepr {
    /// Heading (degrees): Heading angle.
    pub fn heading_deg(&self) -> f64 {
        f64::from(self.heading) / 100.0
    }

    /// Sets Heading from an engineering value (degrees), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_heading_deg(&mut self, value: f64) -> Result<()> {
        let raw = info::HEADING.raw_from(value, None)?;
        self.heading = info::HEADING.int(raw)?;
        Ok(())
    }

    /// Pitch (degrees): Pitch angle.
    pub fn pitch_deg(&self) -> f64 {
        f64::from(self.pitch) / 100.0
    }

    /// Sets Pitch from an engineering value (degrees), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_pitch_deg(&mut self, value: f64) -> Result<()> {
        let raw = info::PITCH.raw_from(value, None)?;
        self.pitch = info::PITCH.int(raw)?;
        Ok(())
    }

    /// Roll (degrees): Roll angle.
    pub fn roll_deg(&self) -> f64 {
        f64::from(self.roll) / 100.0
    }

    /// Sets Roll from an engineering value (degrees), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_roll_deg(&mut self, value: f64) -> Result<()> {
        let raw = info::ROLL.raw_from(value, None)?;
        self.roll = info::ROLL.int(raw)?;
        Ok(())
    }

    /// GyroX (degrees per second) for the device `variant`: Angular rate about X (lateral axis).
    pub fn gyro_x_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_x) / f64::from(variant.kg())
    }

    /// Sets GyroX from an engineering value (degrees per second), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_x_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::GYRO_X.raw_from(value, Some(variant))?;
        self.gyro_x = info::GYRO_X.int(raw)?;
        Ok(())
    }

    /// GyroY (degrees per second) for the device `variant`: Angular rate about Y (longitudinal axis).
    pub fn gyro_y_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_y) / f64::from(variant.kg())
    }

    /// Sets GyroY from an engineering value (degrees per second), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_y_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::GYRO_Y.raw_from(value, Some(variant))?;
        self.gyro_y = info::GYRO_Y.int(raw)?;
        Ok(())
    }

    /// GyroZ (degrees per second) for the device `variant`: Angular rate about Z (vertical axis).
    pub fn gyro_z_dps(&self, variant: Variant) -> f64 {
        f64::from(self.gyro_z) / f64::from(variant.kg())
    }

    /// Sets GyroZ from an engineering value (degrees per second), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_gyro_z_dps(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::GYRO_Z.raw_from(value, Some(variant))?;
        self.gyro_z = info::GYRO_Z.int(raw)?;
        Ok(())
    }

    /// AccX (standard gravity) for the device `variant`: Linear acceleration along X.
    pub fn acc_x_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_x) / f64::from(variant.ka())
    }

    /// Sets AccX from an engineering value (standard gravity), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_x_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::ACC_X.raw_from(value, Some(variant))?;
        self.acc_x = info::ACC_X.int(raw)?;
        Ok(())
    }

    /// AccY (standard gravity) for the device `variant`: Linear acceleration along Y.
    pub fn acc_y_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_y) / f64::from(variant.ka())
    }

    /// Sets AccY from an engineering value (standard gravity), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_y_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::ACC_Y.raw_from(value, Some(variant))?;
        self.acc_y = info::ACC_Y.int(raw)?;
        Ok(())
    }

    /// AccZ (standard gravity) for the device `variant`: Linear acceleration along Z.
    pub fn acc_z_g(&self, variant: Variant) -> f64 {
        f64::from(self.acc_z) / f64::from(variant.ka())
    }

    /// Sets AccZ from an engineering value (standard gravity), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_acc_z_g(&mut self, variant: Variant, value: f64) -> Result<()> {
        let raw = info::ACC_Z.raw_from(value, Some(variant))?;
        self.acc_z = info::ACC_Z.int(raw)?;
        Ok(())
    }

    /// MagX (nanotesla): Magnetic field along X.
    pub fn mag_x_nt(&self) -> f64 {
        f64::from(self.mag_x) * 10.0
    }

    /// Sets MagX from an engineering value (nanotesla), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_mag_x_nt(&mut self, value: f64) -> Result<()> {
        let raw = info::MAG_X.raw_from(value, None)?;
        self.mag_x = info::MAG_X.int(raw)?;
        Ok(())
    }

    /// MagY (nanotesla): Magnetic field along Y.
    pub fn mag_y_nt(&self) -> f64 {
        f64::from(self.mag_y) * 10.0
    }

    /// Sets MagY from an engineering value (nanotesla), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_mag_y_nt(&mut self, value: f64) -> Result<()> {
        let raw = info::MAG_Y.raw_from(value, None)?;
        self.mag_y = info::MAG_Y.int(raw)?;
        Ok(())
    }

    /// MagZ (nanotesla): Magnetic field along Z.
    pub fn mag_z_nt(&self) -> f64 {
        f64::from(self.mag_z) * 10.0
    }

    /// Sets MagZ from an engineering value (nanotesla), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_mag_z_nt(&mut self, value: f64) -> Result<()> {
        let raw = info::MAG_Z.raw_from(value, None)?;
        self.mag_z = info::MAG_Z.int(raw)?;
        Ok(())
    }

    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }

    /// Vdd (volts DC): AHRS input voltage.
    pub fn vdd_v(&self) -> f64 {
        f64::from(self.vdd) / 1000.0
    }

    /// Sets Vdd from an engineering value (volts DC), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_vdd_v(&mut self, value: f64) -> Result<()> {
        let raw = info::VDD.raw_from(value, None)?;
        self.vdd = info::VDD.int(raw)?;
        Ok(())
    }

    /// Utermo (degrees Celsius): Average temperature of the 3 accelerometers.
    pub fn utermo_degc(&self) -> f64 {
        f64::from(self.utermo) / 10.0
    }

    /// Sets Utermo from an engineering value (degrees Celsius), rounded half away
    /// from zero. Error: `out_of_range` naming the field.
    pub fn set_utermo_degc(&mut self, value: f64) -> Result<()> {
        let raw = info::UTERMO.raw_from(value, None)?;
        self.utermo = info::UTERMO.int(raw)?;
        Ok(())
    }
}
