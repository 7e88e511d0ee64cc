// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.16, Calibration run parameters (6 bytes).
//!
//! The data message the host sends right after StartClbRun (6.4.6); its 6 bytes do not
//! influence 2D-2T calibration and may be any, e.g. zeros.

use crate::payload::codec::payload_table;
use crate::payload::{FieldInfo, FieldKind, Value};

/// Size of the payload (bytes).
pub const SIZE: usize = 6;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Reserved, `reserved[6]`.
    pub const RESERVED: Field = 0..6;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Reserved, `reserved[6]`.
    pub const RESERVED: FieldInfo = FieldInfo {
        icd_name: "Reserved",
        default: Value::Bytes(&[0; 6]),
        ..FieldInfo::new("reserved", field::RESERVED, FieldKind::Reserved)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 1] = [info::RESERVED];

payload_table! {
    /// Table 6.16, Calibration run parameters: a zero-copy view over a payload.
    ///
    /// \[`CalibrationRunParameters::new_checked`\] checks the size once; the accessors
    /// never panic, even on a view made by \[`CalibrationRunParameters::new_unchecked`\]
    /// over a short buffer (missing bytes read as zero).
    view CalibrationRunParameters;
    /// Table 6.16, Calibration run parameters: the payload as a value, with raw field
    /// values.
    ///
    /// \[`CalibrationRunParametersRepr::parse`\] and
    /// \[`CalibrationRunParametersRepr::build`\] are exact inverses: every byte string of
    /// \[`SIZE`\] bytes parses, and builds back to the same bytes when its values are in
    /// range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr CalibrationRunParametersRepr;
    count 1;
    /// Reserved, `reserved\[6\]`:
    0 reserved reserved set_reserved RESERVED: [u8; 6];
}
