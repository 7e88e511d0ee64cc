//! The `session` request, for a spec without a state machine: unsupported.

use crate::{Answer, Refusal};

/// Refuses every session: the crate has no state machine.
pub(crate) fn run(_firmware: &str, _events: &str) -> Answer {
    Err(Refusal::Unsupported)
}
