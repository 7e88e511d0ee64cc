/* On its own (an editor, `make lint-c`), this file includes what precedes it in ilahrs.c:
 * the helpers. ilahrs.c holds it without this include. */
#include "core.c"

/* ---- Date ------------------------------------------------------------------------------ */

/* Month 1..12 of a year (Gregorian). Bit m of 0x15AA is set for the months of 31 days; a year
 * divisible by 100 is leap when also by 16 (then by 400). */
static int days_in_month(int year, int month)
{
    if (month == 2) {
        return (year & 3) == 0 && (year % 100 != 0 || (year & 15) == 0) ? 29 : 28;
    }
    return 30 + (int)((0x15AAu >> month) & 1u);
}

/* The float32 nearest n / DATE_SCALE (ties to even), in integers: the quotient's bits one at a
 * time until it has 24, then rounded by the remainder. A date scaled by DATE_SCALE (date_scaled())
 * is an integer below 2^24: exact in a float32, and decoding compares integers. */
static float date_float(uint32_t n)
{
    uint32_t m = n / DATE_SCALE;
    uint32_t r = n % DATE_SCALE;
    uint32_t exponent = 150u;
    uint32_t bits;
    float value;
    while (m < 0x800000u) {
        r <<= 1;
        m <<= 1;
        if (r >= DATE_SCALE) {
            r -= DATE_SCALE;
            m |= 1u;
        }
        exponent--;
    }
    if (2u * r > DATE_SCALE || (2u * r == DATE_SCALE && (m & 1u) != 0)) {
        m++; /* 2^24 carries into the exponent, as it should */
    }
    bits = (exponent << 23) + m - 0x800000u;
    memcpy(&value, &bits, sizeof value);
    return value;
}

bool ilahrs_date_encode(int year, int month, int day, float *value, ilahrs_error_t *err)
{
    if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX || month < 1 || month > 12 || day < 1
        || day > days_in_month(year, month)) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    /* The generator checked that this equals the double-precision formula rounded to float32. */
    *value = date_float((uint32_t)date_scaled(year, month, day));
    return true;
}

/* Date floats a decoder accepts, as float keys (DATE_DECODE_MIN_KEY..DATE_DECODE_MAX_KEY): from
 * the year ILAHRS_DATE_YEAR_MIN to below ILAHRS_DATE_YEAR_MAX + 2, the floats whose candidate years
 * (below) hold a valid date. DATE_EXPONENT is the biased exponent of the smallest. */
#define DATE_FRACTION_BITS (150u - DATE_EXPONENT)
#define DATE_FRACTION_MASK ((1u << DATE_FRACTION_BITS) - 1u)

bool ilahrs_date_decode(float value, ilahrs_date_t *date, ilahrs_error_t *err)
{
    uint32_t bits;
    uint32_t fixed;
    int32_t target;
    uint32_t best = 0xFFFFFFFFu;
    int base;
    int year;
    memcpy(&bits, &value, sizeof bits);
    if (float_key(bits) < DATE_DECODE_MIN_KEY || float_key(bits) > DATE_DECODE_MAX_KEY) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    /* value = mantissa * 2^(exponent - 150): in units of 2^-DATE_FRACTION_BITS it is the integer
     * `fixed`. Distances are measured from the year `base` in units of 1 / (DATE_SCALE *
     * 2^DATE_FRACTION_BITS), where value and every date are integers (the generator checked that
     * they fit an int32). */
    fixed = ((bits & 0x7FFFFFu) | 0x800000u) << (((bits >> 23) & 0xFFu) - DATE_EXPONENT);
    base = (int)(fixed >> DATE_FRACTION_BITS); /* floor(value) */
    target = (int32_t)(fixed & DATE_FRACTION_MASK) * (int32_t)DATE_SCALE;
    for (year = base - 1; year <= base; year++) {
        int month;
        if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX) {
            continue;
        }
        for (month = 1; month <= 12; month++) {
            int day;
            for (day = 1; day <= days_in_month(year, month); day++) {
                int32_t at =
                    (date_scaled(year, month, day) - base * (int32_t)DATE_SCALE) * (int32_t)(DATE_FRACTION_MASK + 1u);
                uint32_t distance = at > target ? (uint32_t)(at - target) : (uint32_t)(target - at);
                if (distance < best) {
                    best = distance;
                    date->year = (int16_t)year;
                    date->month = (uint8_t)month;
                    date->day = (uint8_t)day;
                }
            }
        }
    }
    return true;
}
