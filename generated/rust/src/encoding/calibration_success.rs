// Copied from generator/targets/rust/runtime/crate/encoding/calibration_success.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! The calibration success field: failed, succeeded with a predicted heading error, or
//! succeeded without an estimate.

use super::CalibrationSuccessRaw;

/// The calibration success field.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CalibrationSuccess {
    /// The spec's `failed` code: the calibration did not succeed.
    Failed,
    /// Success, with the predicted heading error in tenths of the accuracy unit (raw value).
    Accuracy(CalibrationSuccessRaw),
    /// The spec's `no_estimate` code: success, without an accuracy estimate.
    NoEstimate,
}

impl CalibrationSuccess {
    /// What a raw field value means.
    pub const fn decode(raw: CalibrationSuccessRaw) -> CalibrationSuccess {
        match raw {
            Self::FAILED => CalibrationSuccess::Failed,
            Self::NO_ESTIMATE => CalibrationSuccess::NoEstimate,
            accuracy => CalibrationSuccess::Accuracy(accuracy),
        }
    }

    /// The raw field value.
    pub const fn encode(self) -> CalibrationSuccessRaw {
        match self {
            CalibrationSuccess::Failed => Self::FAILED,
            CalibrationSuccess::NoEstimate => Self::NO_ESTIMATE,
            CalibrationSuccess::Accuracy(accuracy) => accuracy,
        }
    }

    /// True unless the calibration failed.
    pub const fn is_success(self) -> bool {
        match self {
            CalibrationSuccess::Failed => false,
            CalibrationSuccess::Accuracy(_) | CalibrationSuccess::NoEstimate => true,
        }
    }

    /// The predicted heading error (degrees), when the device sent one.
    pub fn accuracy_deg(self) -> Option<f64> {
        match self {
            CalibrationSuccess::Accuracy(accuracy) => {
                Some(f64::from(accuracy) / Self::ACCURACY_DIVISOR)
            }
            _ => None,
        }
    }
}
