
/* ======================================================================================== */
/* Dates                                                                                    */
/* ======================================================================================== */

/** A calendar date. */
typedef struct ilahrs_date {
    int16_t year;  /**< ILAHRS_DATE_YEAR_MIN..ILAHRS_DATE_YEAR_MAX. */
    uint8_t month; /**< 1..12. */
    uint8_t day;   /**< 1..31. */
} ilahrs_date_t;

/**
 * The date float of a calendar date (the encoding above). Refuses (`out_of_range`, field "date")
 * a date that is not a real calendar date within ILAHRS_DATE_YEAR_MIN..ILAHRS_DATE_YEAR_MAX.
 */
bool ilahrs_date_encode(int year, int month, int day, float *value, ilahrs_error_t *err);

/**
 * The calendar date whose encoding is nearest `value` (E15: not floor arithmetic, which is
 * wrong for day 31). False (`out_of_range`, field "date") for NaN, infinities and values
 * outside the years ILAHRS_DATE_YEAR_MIN..ILAHRS_DATE_YEAR_MAX.
 */
bool ilahrs_date_decode(float value, ilahrs_date_t *date, ilahrs_error_t *err);
