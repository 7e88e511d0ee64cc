// Copied from generator/targets/rust/runtime/crate/encoding/declination.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! The magnetic declination field: degrees, or a value above a threshold that asks the AHRS to
//! compute the declination itself.

use crate::error::{Detail, Float};

/// The magnetic declination field: degrees, or a request that the AHRS compute it (the limits
/// are the constants of [`Declination`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Declination {
    /// A declination (degrees), [`Declination::MIN`] to [`Declination::MAX`].
    Degrees(f32),
    /// Any value above [`Declination::COMPUTE_ABOVE`]: the AHRS computes the declination from
    /// position and date.
    Computed,
}

impl Declination {
    /// What a raw field value (degrees) means.
    pub fn decode(raw: f32) -> Declination {
        if f64::from(raw) > Self::COMPUTE_ABOVE {
            Declination::Computed
        } else {
            Declination::Degrees(raw)
        }
    }

    /// What [`Declination::encode`] refuses in the value (degrees outside the range), or
    /// `None`.
    pub fn refusal(self) -> Option<Detail> {
        match self {
            Declination::Computed => None,
            Declination::Degrees(degrees) => Self::refuses(f64::from(degrees)),
        }
    }

    /// The raw value to send (degrees), or `None` for degrees outside the range.
    pub fn encode(self) -> Option<f32> {
        match self {
            Declination::Computed => Some(Self::COMPUTE_VALUE),
            Declination::Degrees(degrees) if Self::accepts(f64::from(degrees)) => Some(degrees),
            Declination::Degrees(_) => None,
        }
    }

    /// True if a builder accepts `raw` (degrees): inside the range, or above the threshold.
    pub fn accepts(raw: f64) -> bool {
        (Self::MIN..=Self::MAX).contains(&raw) || raw > Self::COMPUTE_ABOVE
    }

    /// What a builder refuses in `raw` (degrees outside the range), or `None` when it accepts
    /// it ([`Declination::accepts`]).
    pub fn refuses(raw: f64) -> Option<Detail> {
        let detail = Detail::FloatRange {
            value: Float(raw),
            min: Float(Self::MIN),
            max: Float(Self::MAX),
        };
        (!Self::accepts(raw)).then_some(detail)
    }
}
