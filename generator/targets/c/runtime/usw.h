
/** A decoded Unit Status Word. */
typedef struct ilahrs_usw {
    uint16_t flags;         /**< The flag bits that are set (ILAHRS_USW_FLAGS_MASK). */
    uint8_t failure;        /**< The failure byte, as sent. */
    uint8_t warning;        /**< The warning byte, as sent. */
    ilahrs_usw_mode_t mode; /**< The mode bits, decoded. */
} ilahrs_usw_t;

/** Split a USW into flags, failure and warning bytes and mode. */
static inline ilahrs_usw_t ilahrs_usw_decode(uint16_t usw)
{
    ilahrs_usw_t out;
    out.flags = (uint16_t)(usw & ILAHRS_USW_FLAGS_MASK);
    /* A byte of the word is its bits divided by its mask's lowest bit. */
    out.failure =
        (uint8_t)((usw & ILAHRS_USW_FAILURE_MASK) / (ILAHRS_USW_FAILURE_MASK & (0u - ILAHRS_USW_FAILURE_MASK)));
    out.warning =
        (uint8_t)((usw & ILAHRS_USW_WARNING_MASK) / (ILAHRS_USW_WARNING_MASK & (0u - ILAHRS_USW_WARNING_MASK)));
    out.mode = ilahrs_usw_mode(usw);
    return out;
}

/** True if any failure flag is set. */
static inline bool ilahrs_usw_has_failure(uint16_t usw)
{
    return (usw & ILAHRS_USW_FLAGS_MASK & ILAHRS_USW_FAILURE_MASK) != 0;
}

#if ILAHRS_NAMES
/** The spec name of the flag at bit `bit` ("gyro_failure"); NULL for a bit that is no flag. */
const char *ilahrs_usw_flag_name(unsigned bit);
#endif
