// Copied from generator/targets/rust/runtime/crate/status/word.rs for spec/ilahrs.yaml,
// spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the runtime source and run `make generate`.
//! What every Unit Status Word does with its flags and masks.

use super::{StatusFlag, StatusWord, Word};

impl StatusFlag {
    /// The flag's bit as a mask.
    pub const fn mask(self) -> Word {
        1 << self.bit()
    }

    /// True for a failure flag, false for a warning.
    pub const fn is_failure(self) -> bool {
        self.mask() & StatusWord::FAILURE_MASK != 0
    }
}

impl StatusWord {
    /// The word as sent.
    pub const fn raw(self) -> Word {
        self.0
    }

    /// True if `flag` is set.
    pub const fn contains(self, flag: StatusFlag) -> bool {
        self.0 & flag.mask() != 0
    }

    /// True if any failure flag is set.
    pub const fn has_failure(self) -> bool {
        self.0 & Self::FLAGS_MASK & Self::FAILURE_MASK != 0
    }

    /// True if any warning flag is set.
    pub const fn has_warning(self) -> bool {
        self.0 & Self::FLAGS_MASK & Self::WARNING_MASK != 0
    }

    /// The flags that are set, lowest bit first.
    pub fn flags(self) -> impl Iterator<Item = StatusFlag> {
        StatusFlag::ALL
            .into_iter()
            .filter(move |flag| self.contains(*flag))
    }
}

impl From<Word> for StatusWord {
    fn from(raw: Word) -> StatusWord {
        StatusWord(raw)
    }
}
