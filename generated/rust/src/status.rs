// Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
// Do not edit: change the spec or the generator and run `make generate`.

//! The Unit Status Word (6.5, Table 6.18, Table 6.19): failure flags, warning flags and the mode bits.

mod word;

/// The raw type of a Unit Status Word.
type Word = u16;

/// One flag of the Unit Status Word.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StatusFlag {
    /// Bit 0, failure (Initial Alignment): Unsuccessful initial alignment (AHRS moved or the magnetic field changed).
    InitialAlignmentFailed,
    /// Bit 1, failure (AHRS Parameters): The AHRS parameters are incorrect.
    ParametersIncorrect,
    /// Bit 2, failure (Gyroscope Unit): Gyroscope unit failure detected.
    GyroFailure,
    /// Bit 3, failure (Accelerometer Unit): Accelerometer unit failure detected.
    AccelerometerFailure,
    /// Bit 4, failure (Magnetometer Unit): Magnetometer unit failure detected.
    MagnetometerFailure,
    /// Bit 5, failure (Electronics): Electronics failure detected.
    ElectronicsFailure,
    /// Bit 6, failure (Software): Software failure detected.
    SoftwareFailure,
    /// Bit 8, warning (Incorrect Power Supply): Supply voltage below the minimum level.
    LowSupplyVoltage,
    /// Bit 9, warning (Incorrect Power Supply): Supply voltage above the maximum level.
    HighSupplyVoltage,
    /// Bit 10, warning (Angular Rate Exceeding Detect): X angular rate out of range.
    XRateExceeded,
    /// Bit 11, warning (Angular Rate Exceeding Detect): Y angular rate out of range.
    YRateExceeded,
    /// Bit 12, warning (Angular Rate Exceeding Detect): Z angular rate out of range.
    ZRateExceeded,
    /// Bit 13, warning (Large Magnetic Field Detect): Total magnetic field limit exceeded.
    LargeMagneticField,
    /// Bit 14, warning (Environmental Temperature): Temperature outside the operating range.
    TemperatureOutOfRange,
}

impl StatusFlag {
    /// Every flag, lowest bit first.
    pub const ALL: [StatusFlag; 14] = [
        StatusFlag::InitialAlignmentFailed,
        StatusFlag::ParametersIncorrect,
        StatusFlag::GyroFailure,
        StatusFlag::AccelerometerFailure,
        StatusFlag::MagnetometerFailure,
        StatusFlag::ElectronicsFailure,
        StatusFlag::SoftwareFailure,
        StatusFlag::LowSupplyVoltage,
        StatusFlag::HighSupplyVoltage,
        StatusFlag::XRateExceeded,
        StatusFlag::YRateExceeded,
        StatusFlag::ZRateExceeded,
        StatusFlag::LargeMagneticField,
        StatusFlag::TemperatureOutOfRange,
    ];

    /// The flag's bit number (0 = least significant).
    pub const fn bit(self) -> u32 {
        match self {
            StatusFlag::InitialAlignmentFailed => 0,
            StatusFlag::ParametersIncorrect => 1,
            StatusFlag::GyroFailure => 2,
            StatusFlag::AccelerometerFailure => 3,
            StatusFlag::MagnetometerFailure => 4,
            StatusFlag::ElectronicsFailure => 5,
            StatusFlag::SoftwareFailure => 6,
            StatusFlag::LowSupplyVoltage => 8,
            StatusFlag::HighSupplyVoltage => 9,
            StatusFlag::XRateExceeded => 10,
            StatusFlag::YRateExceeded => 11,
            StatusFlag::ZRateExceeded => 12,
            StatusFlag::LargeMagneticField => 13,
            StatusFlag::TemperatureOutOfRange => 14,
        }
    }

    /// The flag's name in the spec (`initial_alignment_failed`).
    pub const fn name(self) -> &'static str {
        match self {
            StatusFlag::InitialAlignmentFailed => "initial_alignment_failed",
            StatusFlag::ParametersIncorrect => "parameters_incorrect",
            StatusFlag::GyroFailure => "gyro_failure",
            StatusFlag::AccelerometerFailure => "accelerometer_failure",
            StatusFlag::MagnetometerFailure => "magnetometer_failure",
            StatusFlag::ElectronicsFailure => "electronics_failure",
            StatusFlag::SoftwareFailure => "software_failure",
            StatusFlag::LowSupplyVoltage => "low_supply_voltage",
            StatusFlag::HighSupplyVoltage => "high_supply_voltage",
            StatusFlag::XRateExceeded => "x_rate_exceeded",
            StatusFlag::YRateExceeded => "y_rate_exceeded",
            StatusFlag::ZRateExceeded => "z_rate_exceeded",
            StatusFlag::LargeMagneticField => "large_magnetic_field",
            StatusFlag::TemperatureOutOfRange => "temperature_out_of_range",
        }
    }
}

/// What the mode bits (bit 7, bit 15) of a Unit Status Word say.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum UswMode {
    /// Normal operation.
    Readiness,
    /// In the last data block the AHRS sends before it goes to Sleep mode.
    Sleep,
    /// A combination of the mode bits that the ICD does not define; the raw bits stay available.
    Unknown,
}

/// A Unit Status Word (6.5, Table 6.18, Table 6.19).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct StatusWord(pub Word);

impl StatusWord {
    /// The bits of the failure byte.
    pub const FAILURE_MASK: Word = 0x00FF;
    /// The bits of the warning byte.
    pub const WARNING_MASK: Word = 0xFF00;
    /// The mode bits.
    pub const MODE_MASK: Word = 0x8080;
    /// Every flag bit.
    pub const FLAGS_MASK: Word = 0x7F7F;

    /// The mode the mode bits report.
    pub const fn mode(self) -> UswMode {
        match self.0 & Self::MODE_MASK {
            0x0000 => UswMode::Readiness,
            0x8080 => UswMode::Sleep,
            _ => UswMode::Unknown,
        }
    }

    /// Bit 0 (Initial Alignment): Unsuccessful initial alignment (AHRS moved or the magnetic field changed).
    pub const fn initial_alignment_failed(self) -> bool {
        self.contains(StatusFlag::InitialAlignmentFailed)
    }

    /// Bit 1 (AHRS Parameters): The AHRS parameters are incorrect.
    pub const fn parameters_incorrect(self) -> bool {
        self.contains(StatusFlag::ParametersIncorrect)
    }

    /// Bit 2 (Gyroscope Unit): Gyroscope unit failure detected.
    pub const fn gyro_failure(self) -> bool {
        self.contains(StatusFlag::GyroFailure)
    }

    /// Bit 3 (Accelerometer Unit): Accelerometer unit failure detected.
    pub const fn accelerometer_failure(self) -> bool {
        self.contains(StatusFlag::AccelerometerFailure)
    }

    /// Bit 4 (Magnetometer Unit): Magnetometer unit failure detected.
    pub const fn magnetometer_failure(self) -> bool {
        self.contains(StatusFlag::MagnetometerFailure)
    }

    /// Bit 5 (Electronics): Electronics failure detected.
    pub const fn electronics_failure(self) -> bool {
        self.contains(StatusFlag::ElectronicsFailure)
    }

    /// Bit 6 (Software): Software failure detected.
    pub const fn software_failure(self) -> bool {
        self.contains(StatusFlag::SoftwareFailure)
    }

    /// Bit 8 (Incorrect Power Supply): Supply voltage below the minimum level.
    pub const fn low_supply_voltage(self) -> bool {
        self.contains(StatusFlag::LowSupplyVoltage)
    }

    /// Bit 9 (Incorrect Power Supply): Supply voltage above the maximum level.
    pub const fn high_supply_voltage(self) -> bool {
        self.contains(StatusFlag::HighSupplyVoltage)
    }

    /// Bit 10 (Angular Rate Exceeding Detect): X angular rate out of range.
    pub const fn x_rate_exceeded(self) -> bool {
        self.contains(StatusFlag::XRateExceeded)
    }

    /// Bit 11 (Angular Rate Exceeding Detect): Y angular rate out of range.
    pub const fn y_rate_exceeded(self) -> bool {
        self.contains(StatusFlag::YRateExceeded)
    }

    /// Bit 12 (Angular Rate Exceeding Detect): Z angular rate out of range.
    pub const fn z_rate_exceeded(self) -> bool {
        self.contains(StatusFlag::ZRateExceeded)
    }

    /// Bit 13 (Large Magnetic Field Detect): Total magnetic field limit exceeded.
    pub const fn large_magnetic_field(self) -> bool {
        self.contains(StatusFlag::LargeMagneticField)
    }

    /// Bit 14 (Environmental Temperature): Temperature outside the operating range.
    pub const fn temperature_out_of_range(self) -> bool {
        self.contains(StatusFlag::TemperatureOutOfRange)
    }
}
