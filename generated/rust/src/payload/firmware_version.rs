// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! Table 6.11, Firmware version (50 bytes).
//!
//! The AHRS answer to GetVerFirmware (6.3.10).

use crate::error::Result;
use crate::payload::codec::payload_table;
use crate::payload::{FieldInfo, FieldKind, Value};

/// Size of the payload (bytes).
pub const SIZE: usize = 50;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Firmware version, `char[50]`.
    pub const VERSION: Field = 0..50;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Firmware version, `char[50]`.
    pub const VERSION: FieldInfo = FieldInfo {
        icd_name: "Firmware version",
        doc: "Firmware version text, NUL-padded.",
        ..FieldInfo::new("version", field::VERSION, FieldKind::Char)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 1] = [info::VERSION];

payload_table! {
    /// Table 6.11, Firmware version: a zero-copy view over a payload.
    ///
    /// \[`FirmwareVersion::new_checked`\] checks the size once; the accessors never panic,
    /// even on a view made by \[`FirmwareVersion::new_unchecked`\] over a short buffer
    /// (missing bytes read as zero).
    view FirmwareVersion;
    /// Table 6.11, Firmware version: the payload as a value, with raw field values.
    ///
    /// \[`FirmwareVersionRepr::parse`\] and \[`FirmwareVersionRepr::build`\] are exact
    /// inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the same
    /// bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq)]
    repr FirmwareVersionRepr;
    count 1;
    /// Firmware version, `char\[50\]`: Firmware version text, NUL-padded.
    0 text version set_version VERSION: [u8; 50];
}

impl Default for FirmwareVersionRepr {
    /// Every field at its default: otherwise zero.
    fn default() -> FirmwareVersionRepr {
        FirmwareVersionRepr { version: [0; 50] }
    }
}

impl<T: AsRef<[u8]>> FirmwareVersion<T> {}

impl FirmwareVersionRepr {
    /// Firmware version: the bytes up to the trailing NULs (Latin-1).
    pub fn version_text(&self) -> &[u8] {
        crate::wire::trim_nul(&self.version)
    }

    /// Sets Firmware version: `value` padded with NULs. Error: `out_of_range` when longer
    /// than 50 bytes.
    pub fn set_version_text(&mut self, value: &[u8]) -> Result<()> {
        self.version = info::VERSION.array(Value::Bytes(value))?;
        Ok(())
    }
}
