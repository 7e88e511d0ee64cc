// Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
// Do not edit: change the spec or the generator and run `make generate`.

//! 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement (2 bytes).
//!
//! The checksum of the message the AHRS received (E12).

use crate::payload::codec::payload_table;
use crate::payload::{FieldInfo, FieldKind};

/// Size of the payload (bytes).
pub const SIZE: usize = 2;

/// Where each field sits in the payload (byte offsets).
pub mod field {
    use crate::wire::Field;

    /// Check sum, `u16`.
    pub const CHECKSUM: Field = 0..2;
}

/// What each field is and what a builder accepts.
pub mod info {
    use super::*;

    /// Check sum, `u16`.
    pub const CHECKSUM: FieldInfo = FieldInfo {
        icd_name: "Check sum",
        doc: "Checksum of the acknowledged message, message type through payload.",
        ..FieldInfo::new("checksum", field::CHECKSUM, FieldKind::Unsigned)
    };
}

/// Every field, in wire order.
pub static FIELDS: [FieldInfo; 1] = [info::CHECKSUM];

payload_table! {
    /// 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement: a zero-copy view over a
    /// payload.
    ///
    /// \[`Acknowledgement::new_checked`\] checks the size once; the accessors never panic,
    /// even on a view made by \[`Acknowledgement::new_unchecked`\] over a short buffer
    /// (missing bytes read as zero).
    view Acknowledgement;
    /// 6.3.1 (Table 6.2 with a one-word payload), Acknowledgement: the payload as a value,
    /// with raw field values.
    ///
    /// \[`AcknowledgementRepr::parse`\] and \[`AcknowledgementRepr::build`\] are exact
    /// inverses: every byte string of \[`SIZE`\] bytes parses, and builds back to the same
    /// bytes when its values are in range.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    repr AcknowledgementRepr;
    count 1;
    /// Check sum, `u16`: Checksum of the acknowledged message, message type through
    /// payload.
    0 number checksum set_checksum CHECKSUM: u16;
}
