// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.12, Built-in test answer (4 bytes).
//!
//! The AHRS answer to GetBIT (6.3.11).

use crate::payload::codec::payload_table;
use crate::payload::{Encoding, FieldInfo, FieldKind, Scale, Unit};
use crate::status::StatusWord;

/// Size of the payload (bytes).
pub const SIZE: usize = 4;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius.
    pub const UTERMO100: Field = 0..2;
    /// USW, `u16`.
    pub const USW: Field = 2..4;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius.
    pub const UTERMO100: FieldInfo = FieldInfo {
        icd_name: "Utermo100",
        scale: Some(Scale::fixed(1, 100)),
        unit: Some(Unit::Degc),
        doc: "AHRS temperature in 1/100 degC.",
        ..FieldInfo::new("utermo100", field::UTERMO100, FieldKind::Signed)
    };

    /// USW, `u16`.
    pub const USW: FieldInfo = FieldInfo {
        icd_name: "USW",
        encoding: Some(Encoding::Usw),
        doc: "Unit Status Word (section 6.5).",
        ..FieldInfo::new("usw", field::USW, FieldKind::Unsigned)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 2] = [info::UTERMO100, info::USW];

payload_table! {
    /// Table 6.12, Built-in test answer: a zero-copy view over a payload.
    ///
    /// \[`BitResult::new_checked`\] checks the size once; the accessors never panic, even
    /// on a view made by \[`BitResult::new_unchecked`\] over a short buffer (missing bytes
    /// read as zero).
    view BitResult;
    /// Table 6.12, Built-in test answer: the payload as a value, with raw field values.
    ///
    /// \[`BitResultRepr::parse`\] and \[`BitResultRepr::build`\] are exact inverses: every
    /// byte string of \[`SIZE`\] bytes parses, and builds back to the same bytes when its
    /// values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr BitResultRepr;
    count 2;
    /// Utermo100, `s16`, raw x 1 / 100 = degrees Celsius: AHRS temperature in 1/100 degC.
    0 number utermo100 set_utermo100 UTERMO100: i16,
        /// Utermo100 (degrees Celsius): AHRS temperature in 1/100 degC.
        in utermo100_degc set_utermo100_degc;
    /// USW, `u16`: Unit Status Word (section 6.5).
    1 number usw set_usw USW: u16;
}

impl<T: AsRef<[u8]>> BitResult<T> {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw())
    }
}

impl BitResultRepr {
    /// USW as a Unit Status Word (flags and mode).
    pub fn usw_decoded(&self) -> StatusWord {
        StatusWord(self.usw)
    }
}
