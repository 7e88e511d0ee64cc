/* On its own (an editor, `make lint-c`), this file includes what precedes it in ilahrs.c:
 * the helpers. ilahrs.c holds it without this include. */
#include "core.c"

/* ---- Engineering values as doubles ------------------------------------------------------ */

/* These take doubles but compute on their IEEE 754 binary64 bits with integers only (no
 * floating-point code linked), and give for every double the answers of the double-precision
 * expressions they replace, quoted below. A double is a sign, an 11-bit exponent e and a 52-bit
 * fraction: (2^52 + fraction) * 2^(e - 1075), or fraction * 2^-1074 if e is 0. */

#define DOUBLE_SIGN ((uint64_t)1 << 63)
#define DOUBLE_ONE ((uint64_t)1 << 52) /* the implicit leading bit */

static uint64_t double_bits(double value)
{
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

/* float_key() for a double: the magnitude bits, negated if the sign is set. Doubles order like
 * their keys, -0.0 and 0.0 are both 0, and NaNs lie beyond the infinities, outside every range. */
static int64_t double_key(uint64_t bits)
{
    int64_t magnitude = (int64_t)(bits & ~DOUBLE_SIGN);
    return (bits & DOUBLE_SIGN) != 0 ? -magnitude : magnitude;
}

/* double_key() of (double)n, exact for |n| < 2^53 (every integer bound and C type limit here). */
static int64_t int_key(int64_t n)
{
    uint64_t m = n < 0 ? 0u - (uint64_t)n : (uint64_t)n;
    uint64_t exponent = 1074; /* 2^52's (1075), less the 1 that m's leading bit adds below */
    int64_t magnitude;
    if (m == 0) {
        return 0;
    }
    while (m < DOUBLE_ONE) {
        m <<= 1;
        exponent--;
    }
    magnitude = (int64_t)((exponent << 52) + m);
    return n < 0 ? -magnitude : magnitude;
}

/* value >= low && value <= high with the field's bounds (float fields: ilahrs_exact_bounds, the
 * exact bounds as double keys; integer fields: their int bounds or their C type's range, exact as
 * doubles), then the declination rule, as compares of keys. */
bool ilahrs_field_check(const ilahrs_field_info_t *field, double value, ilahrs_error_t *err)
{
    int64_t key = double_key(double_bits(value));
    int64_t low;
    int64_t high;
    bool ok;
    switch (FIELD_KIND(field)) {
    case ILAHRS_KIND_FLOAT:
        low = ilahrs_exact_bounds[FIELD_BOUNDS(field)][0];
        high = ilahrs_exact_bounds[FIELD_BOUNDS(field)][1];
        break;
    case ILAHRS_KIND_UNSIGNED:
    case ILAHRS_KIND_SIGNED: {
        bool is_signed = FIELD_KIND(field) == ILAHRS_KIND_SIGNED;
        uint32_t top = 0xFFFFFFFFu >> (32 - 8 * FIELD_NUMBER_SIZE(field) + is_signed); /* the C type's maximum */
        low = FIELD_BOUNDS(field) != 0 ? ilahrs_int_bounds[FIELD_BOUNDS(field)][0] : is_signed ? -(int64_t)top - 1 : 0;
        high = FIELD_BOUNDS(field) != 0 ? ilahrs_int_bounds[FIELD_BOUNDS(field)][1] : (int64_t)top;
        low = int_key(low);
        high = int_key(high);
        break;
    }
    default:
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
    }
    ok = key >= low && key <= high;
#ifdef ILAHRS_DECLINATION_MIN
    if (ok && FIELD_ENCODING(field) == ENCODING_DECLINATION) {
        ok = (key >= DECLINATION_MIN_DKEY && key <= DECLINATION_MAX_DKEY) || key > DECLINATION_COMPUTE_ABOVE_DKEY;
    }
#endif
    return ok || fail(err, ILAHRS_ERR_OUT_OF_RANGE, FIELD_OFFSET(field), FIELD_NAME(FIELD_NAME_AT(field)));
}
