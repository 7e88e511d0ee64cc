// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! Device variants: scale factors that depend on the part number.

/// A scale parameter whose value depends on the device variant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VariantParameter {
    /// `KG`: Gyro scale factor of Table 6.6, LSB per deg/s.
    Kg,
    /// `KA`: Accelerometer scale factor of Table 6.6, LSB per g.
    Ka,
}

impl VariantParameter {
    /// The parameter's name in the spec (`KG`).
    pub const fn name(self) -> &'static str {
        match self {
            VariantParameter::Kg => "KG",
            VariantParameter::Ka => "KA",
        }
    }
}

/// A device variant: the part numbers whose scale parameters differ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Variant {
    /// AHRS-G300-A2-TMGA-C1-V1.1 (Table 6.6 note 1).
    G300A2Tmga,
    /// AHRS-G300-A6-TMGA-C1-V1.1 (Table 6.6 note 1).
    G300A6Tmga,
    /// AHRS s/n 11AC0001 - 11AC0009 (Table 6.6 note 1).
    Sn11ac00010009,
    /// AHRS-G300-A2-TGA-C1-V1.1 (Table 3.1, E11).
    G300A2Tga,
}

impl Variant {
    /// Every variant, in the spec's order.
    pub const ALL: [Variant; 4] = [
        Variant::G300A2Tmga,
        Variant::G300A6Tmga,
        Variant::Sn11ac00010009,
        Variant::G300A2Tga,
    ];

    /// The variant's name in the spec (`g300_a2_tmga`).
    pub const fn name(self) -> &'static str {
        match self {
            Variant::G300A2Tmga => "g300_a2_tmga",
            Variant::G300A6Tmga => "g300_a6_tmga",
            Variant::Sn11ac00010009 => "sn_11ac0001_0009",
            Variant::G300A2Tga => "g300_a2_tga",
        }
    }

    /// The variant whose spec name is `name`, if any.
    pub fn from_name(name: &str) -> Option<Variant> {
        Variant::ALL
            .into_iter()
            .find(|variant| variant.name() == name)
    }

    /// The part number (or serial range) the variant stands for.
    pub const fn part_number(self) -> &'static str {
        match self {
            Variant::G300A2Tmga => "AHRS-G300-A2-TMGA-C1-V1.1",
            Variant::G300A6Tmga => "AHRS-G300-A6-TMGA-C1-V1.1",
            Variant::Sn11ac00010009 => "AHRS s/n 11AC0001 - 11AC0009",
            Variant::G300A2Tga => "AHRS-G300-A2-TGA-C1-V1.1",
        }
    }

    /// The value of a scale parameter for this variant.
    pub const fn parameter(self, parameter: VariantParameter) -> i32 {
        match parameter {
            VariantParameter::Kg => self.kg(),
            VariantParameter::Ka => self.ka(),
        }
    }

    /// `KG`: Gyro scale factor of Table 6.6, LSB per deg/s.
    pub const fn kg(self) -> i32 {
        match self {
            Variant::G300A2Tmga => 100,
            Variant::G300A6Tmga => 100,
            Variant::Sn11ac00010009 => 50,
            Variant::G300A2Tga => 100,
        }
    }

    /// `KA`: Accelerometer scale factor of Table 6.6, LSB per g.
    pub const fn ka(self) -> i32 {
        match self {
            Variant::G300A2Tmga => 10000,
            Variant::G300A6Tmga => 5000,
            Variant::Sn11ac00010009 => 10000,
            Variant::G300A2Tga => 10000,
        }
    }
}
