
/** True if the calibration (or run) succeeded. */
static inline bool ilahrs_calibration_succeeded(uint8_t success)
{
    return success != ILAHRS_CALIBRATION_FAILED;
}

/** The predicted 3-sigma heading error in degrees; false if failed or without an estimate. */
static inline bool ilahrs_calibration_accuracy_deg(uint8_t success, float *degrees)
{
    if (success == ILAHRS_CALIBRATION_FAILED || success == ILAHRS_CALIBRATION_NO_ESTIMATE) {
        return false;
    }
    *degrees = (float)success / (float)ILAHRS_CALIBRATION_ACCURACY_DIVISOR;
    return true;
}
