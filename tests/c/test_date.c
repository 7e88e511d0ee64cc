/*
 * ilahrs_date_decode() and ilahrs_date_encode() against a copy of the code as it was at 550522e
 * (a rewrite must keep every answer): the return value, the date or float written, error kind,
 * offset and field, for every float from the year ILAHRS_DATE_YEAR_MIN - 2 to
 * ILAHRS_DATE_YEAR_MAX + 3 and for a seeded sample of all other bit patterns; the encoder for
 * every year, month and day around the valid ones. A mismatch prints the input.
 *
 * It includes ilahrs.c, to copy that code with the library's own helpers and the spec's
 * constants (DATE_SCALE, date_scaled(), DATE_EXPONENT).
 *
 *   test_date [SEED]           every float in the date range, then the sample
 *   test_date --sample [SEED]  the sample and every 61st float of the range (fast enough for
 *                              sanitizers and qemu)
 */
#include "ilahrs.c"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>

#define RANDOM_PATTERNS 1000000ul
#define SAMPLE_PATTERNS 100000ul
#define SAMPLE_STRIDE 61u

static unsigned long compared;
static unsigned long mismatches;

/* ---- The code as it was (ilahrs.c.j2 at 550522e) ------------------------------------------- */

static int ref_days_in_month(int year, int month)
{
    static const uint8_t days[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
    bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return month == 2 && leap ? 29 : days[month - 1];
}

static float ref_date_float(uint32_t n)
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
        m++;
    }
    bits = (exponent << 23) + m - 0x800000u;
    memcpy(&value, &bits, sizeof value);
    return value;
}

static bool ref_date_encode(int year, int month, int day, float *value, ilahrs_error_t *err)
{
    if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX || month < 1 || month > 12 || day < 1
        || day > ref_days_in_month(year, month)) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    *value = ref_date_float((uint32_t)date_scaled(year, month, day));
    return true;
}

static uint32_t float_bits(float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

/* The old bounds: the years ILAHRS_DATE_YEAR_MIN - 1 .. ILAHRS_DATE_YEAR_MAX + 2 as float keys. */
static int32_t ref_min_key;
static int32_t ref_max_key;

static bool ref_date_decode(float value, ilahrs_date_t *date, ilahrs_error_t *err)
{
    uint32_t bits;
    uint32_t fixed;
    int32_t target;
    uint32_t best = 0xFFFFFFFFu;
    int base;
    int year;
    memcpy(&bits, &value, sizeof bits);
    if (float_key(bits) < ref_min_key || float_key(bits) > ref_max_key) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    fixed = ((bits & 0x7FFFFFu) | 0x800000u) << (((bits >> 23) & 0xFFu) - DATE_EXPONENT);
    base = (int)(fixed >> DATE_FRACTION_BITS);
    target = (int32_t)(fixed & DATE_FRACTION_MASK) * (int32_t)DATE_SCALE;
    for (year = base - 1; year <= base; year++) {
        int month;
        if (year < ILAHRS_DATE_YEAR_MIN || year > ILAHRS_DATE_YEAR_MAX) {
            continue;
        }
        for (month = 1; month <= 12; month++) {
            int day;
            for (day = 1; day <= ref_days_in_month(year, month); day++) {
                int32_t at = (date_scaled(year, month, day) - base * (int32_t)DATE_SCALE) * (int32_t)(DATE_FRACTION_MASK + 1u);
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
    if (best == 0xFFFFFFFFu) {
        return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, NAME_DATE);
    }
    return true;
}

/* ---- Comparison --------------------------------------------------------------------------- */

static const ilahrs_error_t ERR_UNSET = { (ilahrs_error_kind_t)0x55, 0x5555u, "unset" };
static const ilahrs_date_t DATE_UNSET = { 0x5555, 0x55u, 0x55u };

static bool same_err(const ilahrs_error_t *a, const ilahrs_error_t *b)
{
    return a->kind == b->kind && a->offset == b->offset && a->field == b->field;
}

static void mismatch(const char *what)
{
    if (++mismatches <= 20) {
        printf("MISMATCH %s\n", what);
    }
}

static void check_decode(uint32_t bits)
{
    float value;
    ilahrs_date_t got = DATE_UNSET, want = DATE_UNSET;
    ilahrs_error_t got_err = ERR_UNSET, want_err = ERR_UNSET;
    bool got_ok, want_ok;
    memcpy(&value, &bits, sizeof value);
    got_ok = ilahrs_date_decode(value, &got, &got_err);
    want_ok = ref_date_decode(value, &want, &want_err);
    compared++;
    if (got_ok != want_ok || got.year != want.year || got.month != want.month || got.day != want.day
        || !same_err(&got_err, &want_err)) {
        char text[160];
        snprintf(text, sizeof text, "decode 0x%08lX (%.9g): %d %d-%d-%d, want %d %d-%d-%d", (unsigned long)bits,
                 (double)value, got_ok, got.year, got.month, got.day, want_ok, want.year, want.month, want.day);
        mismatch(text);
    }
}

static void check_encode(int year, int month, int day)
{
    float got = -1.0f, want = -1.0f;
    ilahrs_error_t got_err = ERR_UNSET, want_err = ERR_UNSET;
    bool got_ok = ilahrs_date_encode(year, month, day, &got, &got_err);
    bool want_ok = ref_date_encode(year, month, day, &want, &want_err);
    compared++;
    if (got_ok != want_ok || float_bits(got) != float_bits(want) || !same_err(&got_err, &want_err)) {
        char text[160];
        snprintf(text, sizeof text, "encode %d-%d-%d: %d 0x%08lX, want %d 0x%08lX", year, month, day, got_ok,
                 (unsigned long)float_bits(got), want_ok, (unsigned long)float_bits(want));
        mismatch(text);
    }
}

/* xorshift32: the sample is the same on every run and host. */
static uint32_t next_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

int main(int argc, char **argv)
{
    static const int extremes[] = { INT_MIN, INT_MIN + 1, -1, 0, INT_MAX - 1, INT_MAX };
    int arg = 1;
    bool sample = argc > arg && strcmp(argv[arg], "--sample") == 0;
    uint32_t state;
    uint32_t stride;
    uint32_t low, high, bits;
    unsigned long i;
    int year, month, day;
    size_t a, b, c;
    if (sample) {
        arg++;
    }
    state = argc > arg ? (uint32_t)strtoul(argv[arg], NULL, 0) : 0x0DA7Eu;
    if (state == 0) {
        state = 1;
    }
    stride = sample ? SAMPLE_STRIDE : 1u;
    ref_min_key = float_key(float_bits((float)(ILAHRS_DATE_YEAR_MIN - 1)));
    ref_max_key = float_key(float_bits((float)(ILAHRS_DATE_YEAR_MAX + 2)));

    /* Every float from year MIN - 2 to MAX + 3 (positive floats: bits and keys agree). */
    low = float_bits((float)(ILAHRS_DATE_YEAR_MIN - 2));
    high = float_bits((float)(ILAHRS_DATE_YEAR_MAX + 3));
    for (bits = low; bits <= high; bits += stride) {
        check_decode(bits);
    }
    for (bits = low; bits <= low + 4u * (DATE_FRACTION_MASK + 1u); bits++) { /* the first years in full */
        check_decode(bits);
    }
    for (bits = high - 4u * (DATE_FRACTION_MASK + 1u); bits <= high; bits++) { /* the last years in full */
        check_decode(bits);
    }
    /* Zeros, infinities, NaNs, the extremes, then the sample. */
    {
        static const uint32_t special[] = { 0x00000000u, 0x80000000u, 0x7F800000u, 0xFF800000u, 0x7FC00000u,
                                            0xFFC00000u, 0x7F800001u, 0x7FFFFFFFu, 0xFFFFFFFFu, 0x00000001u,
                                            0x7F7FFFFFu, 0xFF7FFFFFu, 0x3F800000u };
        for (a = 0; a < sizeof special / sizeof special[0]; a++) {
            check_decode(special[a]);
            check_decode(special[a] ^ 0x80000000u);
        }
    }
    for (i = 0; i < (sample ? SAMPLE_PATTERNS : RANDOM_PATTERNS); i++) {
        uint32_t r = next_random(&state);
        check_decode(r);
        check_decode(low + r % (high - low + 1u)); /* also a random float in the date range */
    }

    /* The encoder: every year, month and day around the valid ones, and the int extremes. */
    for (year = ILAHRS_DATE_YEAR_MIN - 2; year <= ILAHRS_DATE_YEAR_MAX + 2; year++) {
        for (month = -1; month <= 14; month++) {
            for (day = -1; day <= 33; day++) {
                check_encode(year, month, day);
            }
        }
    }
    for (a = 0; a < sizeof extremes / sizeof extremes[0]; a++) {
        for (b = 0; b < sizeof extremes / sizeof extremes[0]; b++) {
            for (c = 0; c < sizeof extremes / sizeof extremes[0]; c++) {
                check_encode(extremes[a], extremes[b], extremes[c]);
            }
            check_encode(2000, extremes[a], extremes[b]);
            check_encode(extremes[a], 2, extremes[b]);
            check_encode(extremes[a], extremes[b], 1);
        }
    }

    printf("test_date: %lu comparisons%s, %lu mismatches\n", compared, sample ? " (sample)" : "", mismatches);
    return mismatches == 0 ? 0 : 1;
}
