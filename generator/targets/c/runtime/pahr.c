/* On its own (an editor, `make lint-c`), this file includes what precedes it in ilahrs.c:
 * the helpers and the double codec. ilahrs.c holds it without this include. */
#include "values.c"

/* ---- $PAHR sentences ------------------------------------------------------------------- */

/* The sentence grammar of NMEA 0183 (spec/README.md): "$", the identifier and "," (PAHR_PREFIX),
 * fields separated by ",", then "*", two hex digits, CR LF. */
#define PAHR_START '$'
#define PAHR_SEPARATOR ','
#define PAHR_STAR '*'
#define PAHR_CR '\r'
#define PAHR_LF '\n'
#define PAHR_PREFIX_LENGTH (sizeof PAHR_PREFIX - 1u)
#define PAHR_TAIL 5u                /* "*", two checksum digits, CR, LF */
#define PAHR_HUGE 10000000000000ull /* magnitudes saturate here: above every 32-bit range */

/* Field k's struct member (its offset) and its size: from its row, or, where the rows leave them
 * out (every member the same size, PAHR_MEMBER_SIZE, in the order of the fields; compiled for
 * size), from k. */
#if PAHR_ROW_MEMBERS
#define PAHR_MEMBER(k) ilahrs_pahr_fields[k].member
#define PAHR_SIZE(k) ilahrs_pahr_fields[k].size
#else
#define PAHR_MEMBER(k) ((size_t)(k) * PAHR_MEMBER_SIZE)
#define PAHR_SIZE(k) PAHR_MEMBER_SIZE
#endif

/* 10^decimals of field k. */
static uint32_t pahr_divisor(size_t k)
{
    uint32_t divisor = 1;
    unsigned i;
    for (i = 0; i < ilahrs_pahr_fields[k].decimals; i++) {
        divisor *= 10u;
    }
    return divisor;
}

#if ILAHRS_NAMES
const char *ilahrs_pahr_field_name(size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT ? SENTENCE_NAME(ilahrs_pahr_fields[index].name) : NULL;
}
#endif

bool ilahrs_pahr_field_range(size_t index, int32_t *min, int32_t *max)
{
    if (index >= ILAHRS_PAHR_FIELD_COUNT) {
        return false;
    }
    *min = ilahrs_pahr_fields[index].min;
    *max = ilahrs_pahr_fields[index].max;
    return true;
}

uint32_t ilahrs_pahr_field_divisor(size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT && !ilahrs_pahr_fields[index].hex ? pahr_divisor(index) : 0;
}

static int32_t pahr_get(const ilahrs_pahr_t *in, size_t k)
{
    uint32_t bits = load_bits((const uint8_t *)in + PAHR_MEMBER(k), PAHR_SIZE(k));
    return ilahrs_pahr_fields[k].min < 0 ? sign_extend(bits, PAHR_SIZE(k)) : (int32_t)bits;
}

int32_t ilahrs_pahr_field_get(const ilahrs_pahr_t *sentence, size_t index)
{
    return index < ILAHRS_PAHR_FIELD_COUNT ? pahr_get(sentence, index) : 0;
}

/* The character classes of the grammar: a hex digit's value (0..15, either case), NOT_DIGIT for
 * any other character. Decimal fields take the values below 10. */
#define NOT_DIGIT 0x100u

static unsigned digit_value(uint8_t c)
{
    unsigned letter = (unsigned)(c | 0x20u) - 'a';
    if ((unsigned)(c - '0') <= 9u) {
        return (unsigned)(c - '0');
    }
    return letter <= 5u ? letter + 10u : NOT_DIGIT;
}

/*
 * The field at *at, described by f, in one pass: its grammar, its value scaled to an integer, its
 * range; the characters it takes are XORed into *sum. Returns ILAHRS_OK with the value stored in
 * *out, ILAHRS_ERR_MALFORMED (also when the number is not followed by a separator or by the star,
 * star being the sentence's "*") or ILAHRS_ERR_OUT_OF_RANGE, and leaves *at where the number ends.
 * Magnitudes stop growing at SATURATED, above every range: m * 16 + 15 cannot overflow from below
 * it, so any number of digits reads without a wider type or a division.
 */
#if FAST
/* The digits of a number in base 10 or 16 from q, with at most one point among them: its
 * magnitude in *m (stopping at SATURATED), the point in *point (NULL without one), the characters
 * XORed into *sum. Returns where the number ends: at the star at the latest, which is no digit. */
static inline const uint8_t *pahr_digits(const uint8_t *q, const uint8_t *star, unsigned base, uint32_t *m,
                                         const uint8_t **point, unsigned *sum)
{
    unsigned x = *sum;
    uint32_t v = 0;
    for (; q < star; q++) {
        unsigned c = *q;
        unsigned d = c - '0';
        if (d > 9u) {
            d = (c | 0x20u) - ('a' - 10u); /* a hex letter, either case: 10..15 */
            if (d < 10u || d >= base) {
                if (c != '.' || *point != NULL) {
                    break;
                }
                *point = q; /* in a hex field, a point is followed by a fraction it cannot have */
                x ^= c;
                continue;
            }
        }
        x ^= c;
        if (v < SATURATED) {
            v = v * base + d;
        }
    }
    *m = v;
    *sum = x;
    return q;
}

static ilahrs_error_kind_t pahr_field(const uint8_t **at, const uint8_t *star, const pahr_field_t *f,
                                      ilahrs_pahr_t *out, unsigned *sum)
{
    const uint8_t *q = *at;
    const uint8_t *digits;
    const uint8_t *point = NULL;
    bool negative = !f->hex && *q == '-';
    uint32_t m;
    size_t whole;
    size_t fraction = 0;
    int32_t value;
    *sum ^= negative ? (unsigned)'-' : 0u;
    digits = q + negative;
    /* The base as a constant: a multiplication by 10 or 16 is a shift and an add. */
    q = f->hex ? pahr_digits(digits, star, 16u, &m, &point, sum) : pahr_digits(digits, star, 10u, &m, &point, sum);
    *at = q;
    whole = (size_t)((point != NULL ? point : q) - digits);
    if (point != NULL) {
        fraction = (size_t)(q - point) - 1u;
    }
    if (whole == 0 || (f->hex && whole > f->width) || (point != NULL && (fraction == 0 || fraction > f->decimals))
        || (q != star && *q != PAHR_SEPARATOR)) {
        return ILAHRS_ERR_MALFORMED;
    }
    for (; fraction < f->decimals; fraction++) {
        if (m < SATURATED) {
            m *= 10u;
        }
    }
    value = negative ? -(int32_t)m : (int32_t)m;
    if (value < f->min || value > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + f->member, (uint32_t)value, f->size);
    return ILAHRS_OK;
}
#else
/* (A field's digits leave room for more fraction digits than any field has.) */
typedef char pahr_check_room[PAHR_MAX_DECIMALS < PAHR_PREFIX_LENGTH + PAHR_TAIL ? 1 : -1];
/* Compiled for size, the same checks with the same answers in less code, for field k: pahr_body()
 * has summed the characters already, reads *at only after a good field, and reports any bad one
 * at its start, so a check may answer as soon as it fails. `room` counts the digits the
 * part being read may still take: a hex field's width of whole digits (a decimal field's, as many
 * as a sentence has characters, are not limited: a field holds fewer, and room stays above the
 * fraction digits), then after a point the fraction digits, which leave room of them missing. So
 * a point has been read if room is at most the fraction digits (or, in a hex field, which takes no
 * point, the width is used up: then a point ends the number as a second point does, and either is
 * malformed), and the value lacks the smaller of the two: read as zero digits at the end. */
static ilahrs_error_kind_t pahr_field(const uint8_t **at, const uint8_t *star, size_t k, ilahrs_pahr_t *out)
{
    const pahr_field_t *f = &ilahrs_pahr_fields[k];
    const uint8_t *q = *at;
    const uint8_t *part; /* the first digit of the part being read: whole, then fraction */
    unsigned base = f->hex ? 16u : 10u;
    /* Every read of the field below the star (pahr_body() never starts one past it, but Frama-C's
     * EVA cannot tell: the separators it counted are what stop a field short of the star). */
    bool negative = base == 10u && q < star && *q == '-';
    unsigned room = f->hex ? f->width : ILAHRS_PAHR_MAX_LENGTH;
    uint32_t m = 0;
    int32_t value;
    for (part = q += negative;; q++) {
        unsigned c = q < star ? *q : PAHR_SEPARATOR; /* the star ends the last field as a separator */
        unsigned d = c - '0';
        if (d > 9u) {
            d = (c | 0x20u) - ('a' - 10u); /* a hex letter, either case: 10..15 */
            if (d < 10u || d >= base) {
                if (c != '.' || room <= f->decimals || q == part) {
                    if (c != PAHR_SEPARATOR || q == part) {
                        return ILAHRS_ERR_MALFORMED; /* the number ends at a separator or at the star */
                    }
                    /* The fraction digits missing, read as zeros (without a point, all of them),
                     * the end read again after each. */
                    room = room < f->decimals ? room : f->decimals;
                    if (room == 0) {
                        break;
                    }
                    d = 0;
                    q--;
                } else {
                    part = q + 1; /* in a hex field, a point is followed by a fraction it cannot have */
                    room = f->decimals;
                    continue;
                }
            }
        }
        if (room-- == 0) {
            return ILAHRS_ERR_MALFORMED; /* a digit too many */
        }
        if (m < SATURATED) {
            m = m * base + d;
        }
    }
    *at = q;
    value = negative ? -(int32_t)m : (int32_t)m;
    if (value < f->min || value > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + PAHR_MEMBER(k), (uint32_t)value, PAHR_SIZE(k));
    return ILAHRS_OK;
}
#endif

#if FAST
/* Compiled for speed, a decimal field has a path of its own, with the same answers as pahr_field():
 * the whole digits, then the fraction digits after a point, each in a loop of its own; the missing
 * fraction digits scale the magnitude in one multiplication (10^decimals < 2^11, checked by the
 * generator), and the sign and the range in 64 bits. */
static const uint16_t pahr_scale[4] = { 1u, 10u, 100u, 1000u };

/* The XOR of the characters in [q, end), 8 at a time: the field paths below leave it to this. */
static unsigned pahr_xor(const uint8_t *q, const uint8_t *end)
{
    uint64_t x = 0;
    uint64_t w;
    size_t n = (size_t)(end - q);
    if (n < 8u) {
        for (; q < end; q++) {
            x ^= *q;
        }
        return (unsigned)x;
    }
    for (; n > 8u; n -= 8u, q += 8) {
        memcpy(&w, q, 8);
        x ^= w;
    }
    {
        /* The last 8 characters, of which the first 8 - n are counted already. */
        const uint16_t one = 1;
        uint8_t little; /* the host's byte order: 1 if little-endian */
        unsigned drop = 8u * (8u - (unsigned)n);
        memcpy(&little, &one, 1);
        memcpy(&w, end - 8, 8);
        x ^= little ? w >> drop : w << drop;
    }
    x ^= x >> 32;
    x ^= x >> 16;
    x ^= x >> 8;
    return (unsigned)x & 0xFFu;
}

static ilahrs_error_kind_t pahr_decimal(const uint8_t **at, const uint8_t *star, const pahr_field_t *f,
                                        ilahrs_pahr_t *out, unsigned *sum)
{
    const uint8_t *q = *at;
    const uint8_t *digits;
    unsigned negative = *q == '-';
    unsigned scale = f->decimals;
    uint32_t v = 0;
    unsigned d;
    bool bad;
    int64_t value;
    q += negative;
    digits = q;
    /* Each loop stops at the star, which is no digit, and says so in its condition too: every read
     * is then below the star or at it, which Frama-C's EVA can tell (prove/README.md). */
    for (; q < star && (d = (unsigned)*q - '0') <= 9u; q++) {
        v = v * 10u + d;
    }
    if (q - digits > 6) {
        return pahr_field(at, star, f, out, sum); /* v could wrap: the long way, which saturates */
    }
    bad = q == digits;
    if (*q == '.') {
        const uint8_t *point = q++;
        unsigned i;
        /* At most the field's fraction digits (a loop the same length every time); a digit after
         * them is one too many. */
        for (i = 0; i < scale && q < star && (d = (unsigned)*q - '0') <= 9u; i++, q++) {
            v = v * 10u + d;
        }
        bad |= q == point + 1 || (unsigned)*q - '0' <= 9u;
        scale -= i;
    }
    *at = q;
    if (bad || (q != star && *q != PAHR_SEPARATOR)) {
        return ILAHRS_ERR_MALFORMED;
    }
    value = (int64_t)((uint64_t)v * pahr_scale[scale]); /* below 10^6 * 10^3 */
    value = negative ? -value : value;
    if (value < f->min || value > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + f->member, (uint32_t)value, f->size);
    return ILAHRS_OK;
}

/* And a hex field: 1 to 8 digits, no sign and no point (pahr_field() decides the rest). */
static ilahrs_error_kind_t pahr_hex(const uint8_t **at, const uint8_t *star, const pahr_field_t *f, ilahrs_pahr_t *out,
                                    unsigned *sum)
{
    const uint8_t *q = *at;
    uint32_t v = 0;
    size_t whole;
    for (; q < star; q++) {
        unsigned c = *q;
        unsigned d = c - '0';
        if (d > 9u) {
            d = (c | 0x20u) - ('a' - 10u); /* a hex letter, either case: 10..15 */
            if (d - 10u > 5u) {
                break;
            }
        }
        v = v * 16u + d;
    }
    whole = (size_t)(q - *at);
    if (*q == '.' || whole > 8u) {
        return pahr_field(at, star, f, out, sum);
    }
    *at = q;
    if (whole == 0 || whole > f->width || (q != star && *q != PAHR_SEPARATOR)) {
        return ILAHRS_ERR_MALFORMED;
    }
    if ((int64_t)v < f->min || (int64_t)v > f->max) {
        return ILAHRS_ERR_OUT_OF_RANGE;
    }
    store_bits((uint8_t *)out + f->member, v, f->size);
    return ILAHRS_OK;
}
#endif

/* pahr_body()'s answer to an error, in one word, which the stream decoder only compares with 0
 * (ILAHRS_OK): its kind, and where it lies: the index of the field at fault (the error is at the
 * field's first character, after as many separators as fields precede it), or for an error outside
 * the fields, at the prefix's end (the field count), at the star, or at the checksum's first digit.
 * ilahrs_pahr_parse() turns that into the offset. */
#define PAHR_ERROR(kind, where) ((uint32_t)(kind) | (uint32_t)(where) << 4)
#define PAHR_AT_PREFIX ILAHRS_PAHR_FIELD_COUNT
#define PAHR_AT_STAR (ILAHRS_PAHR_FIELD_COUNT + 1u)
#define PAHR_AT_CHECKSUM (ILAHRS_PAHR_FIELD_COUNT + 2u)
#define PAHR_ERROR_KIND(answer) ((ilahrs_error_kind_t)((answer) & 0xFu))
#define PAHR_ERROR_WHERE(answer) ((size_t)((answer) >> 4))
/* (The kinds it answers fit in 4 bits: the answers before the fields fit in one byte.) */
typedef char
    pahr_check_kinds[(ILAHRS_ERR_MALFORMED | ILAHRS_ERR_OUT_OF_RANGE | ILAHRS_ERR_BAD_CHECKSUM) <= 0xF ? 1 : -1];

/*
 * The sentence scanner, for ilahrs_pahr_parse() and the stream decoder alike: everything after the
 * CR LF search. `end` is the sentence length, LF its last character (the stream decoder leaves the
 * CR before it to this, with the star), and p[0..PAHR_PREFIX_LENGTH) the prefix. Returns ILAHRS_OK
 * (0) or the first error in the order of spec/README.md as PAHR_ERROR(kind, field index or
 * PAHR_AT_*).
 */
static uint32_t pahr_body(const uint8_t *p, size_t end, ilahrs_pahr_t *out)
{
    const uint8_t *star = p + end - PAHR_TAIL; /* end > PAHR_PREFIX_LENGTH: an LF follows the prefix */
    const uint8_t *q = p + PAHR_PREFIX_LENGTH;
    size_t k = 0;
#if FAST
    size_t error_field = 0;
#endif
    ilahrs_error_kind_t field_error = ILAHRS_OK;
    unsigned checksum;
    unsigned sum = 0;
    if (star < q || *star != PAHR_STAR || star[PAHR_TAIL - 2u] != PAHR_CR) {
        return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_STAR);
    }
    checksum = 0;
    for (k = 1; k <= 2u; k++) {
        unsigned d = digit_value(star[k]);
        OPAQUE(k); /* a loop, not two copies */
        if (d > 0xFu) {
            return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_CHECKSUM);
        }
        checksum = checksum << 4 | d;
    }
    for (k = 1; k < PAHR_PREFIX_LENGTH; k++) {
        sum ^= (uint8_t)PAHR_PREFIX[k]; /* p[k], which the callers checked */
    }
#if FAST
    /* Fields, counted; the first bad one is remembered and reported after the checksum. */
    k = 0;
    /* Compiled for speed, the fields go by while they are good, each ending at a separator or at
     * the star; the loop below takes over from the first bad one or from a field too many. */
#if defined(__GNUC__)
#pragma GCC unroll 64 /* each field's row then folds into its code */
#endif
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        const pahr_field_t *f = &ilahrs_pahr_fields[k];
        field_error = f->hex ? pahr_hex(&q, star, f, out, &sum) : pahr_decimal(&q, star, f, out, &sum);
        if (field_error != ILAHRS_OK) {
            error_field = k;
            break;
        }
        if (q >= star) {
            goto counted;
        }
        q++; /* the separator */
    }
    for (;; k++) {
        if (k < ILAHRS_PAHR_FIELD_COUNT && field_error == ILAHRS_OK) {
            error_field = k;
            field_error = pahr_field(&q, star, &ilahrs_pahr_fields[k], out, &sum);
        }
        for (; q < star && *q != PAHR_SEPARATOR; q++) {
        }
        if (q >= star) {
            break;
        }
        q++; /* the separator */
    }
counted:
    sum = pahr_xor(p + 1, star); /* the field paths leave it out */
    if (sum != checksum) {
        return PAHR_ERROR(ILAHRS_ERR_BAD_CHECKSUM, PAHR_AT_CHECKSUM);
    }
    if (k + 1 != ILAHRS_PAHR_FIELD_COUNT) {
        return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_PREFIX);
    }
    return field_error == ILAHRS_OK ? ILAHRS_OK : PAHR_ERROR(field_error, error_field);
#else
    /* Compiled for size, the checksum and the field count first, in one pass over the characters
     * (the separators: the fields and their count), then the fields up to the first bad one. */
    k = 0;
    for (; q < star; q++) {
        sum ^= *q;
        k += *q == PAHR_SEPARATOR;
    }
    if (sum != checksum) {
        return PAHR_ERROR(ILAHRS_ERR_BAD_CHECKSUM, PAHR_AT_CHECKSUM);
    }
    if (k + 1 != ILAHRS_PAHR_FIELD_COUNT) {
        return PAHR_ERROR(ILAHRS_ERR_MALFORMED, PAHR_AT_PREFIX);
    }
    /* Each field but the last ends at a separator (as many as fields follow it), or is bad. */
    q = p + PAHR_PREFIX_LENGTH;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        field_error = pahr_field(&q, star, k, out);
        if (field_error != ILAHRS_OK) {
            return PAHR_ERROR(field_error, k);
        }
        q++; /* the separator, or past the star after the last field */
    }
    return ILAHRS_OK;
#endif
}

bool ilahrs_pahr_parse(const char *text, size_t len, ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    const uint8_t *p = (const uint8_t *)text;
    size_t i;
    size_t end;
    size_t where;
    size_t at;
    uint32_t answer;
    /* "$" (a wrong one at 0), then the identifier and "," (a wrong one at 1), as far as they go. */
    for (i = 0; i < PAHR_PREFIX_LENGTH && i < len; i++) {
        if (p[i] != (uint8_t)PAHR_PREFIX[i]) {
            return fail(err, ILAHRS_ERR_BAD_HEADER, i != 0, NULL);
        }
    }
    if (len < PAHR_PREFIX_LENGTH) {
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    /* The first CR LF. */
    for (i = PAHR_PREFIX_LENGTH; i + 1 < len && !(p[i] == PAHR_CR && p[i + 1] == PAHR_LF); i++) {
    }
    if (i + 1 >= len) {
        if (len > ILAHRS_PAHR_MAX_LENGTH) {
            return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_PAHR_MAX_LENGTH, NULL);
        }
        return fail(err, ILAHRS_ERR_TRUNCATED, len, NULL);
    }
    end = i + 2;
    if (end > ILAHRS_PAHR_MAX_LENGTH) {
        return fail(err, ILAHRS_ERR_BAD_LENGTH, ILAHRS_PAHR_MAX_LENGTH, NULL);
    }
    if (end < len) {
        return fail(err, ILAHRS_ERR_TRAILING_DATA, end, NULL);
    }
    answer = pahr_body(p, end, out);
    where = PAHR_ERROR_WHERE(answer);
    at = PAHR_PREFIX_LENGTH;
    for (i = where < ILAHRS_PAHR_FIELD_COUNT ? where : 0; i != 0 && at < end; at++) {
        i -= p[at] == PAHR_SEPARATOR; /* the field's first character follows its i-th separator */
    }
    if (where > PAHR_AT_PREFIX) {
        at = end - PAHR_TAIL + (where - PAHR_AT_STAR);
    }
    return answer == ILAHRS_OK
           || fail(err, PAHR_ERROR_KIND(answer), at,
                   where < ILAHRS_PAHR_FIELD_COUNT ? SENTENCE_NAME(ilahrs_pahr_fields[where].name) : NULL);
}

static const char ilahrs_hex_digits[16] = { '0', '1', '2', '3', '4', '5', '6', '7',
                                            '8', '9', 'A', 'B', 'C', 'D', 'E', 'F' };

/*
 * Every field is range-checked before it is written, and the longest sentence of in-range values
 * is at most ILAHRS_PAHR_MAX_LENGTH characters (the generator checks it), so the sentence is built
 * without length checks. Each number is written from its last digit: at least the template width
 * (the sign counting as one character) and all its digits.
 */
size_t ilahrs_pahr_build(const ilahrs_pahr_t *in, char *text, size_t cap, ilahrs_error_t *err)
{
    /* Cleared first, though every byte up to `at` is written before it is read: a static analysis
     * (Frama-C EVA, prove/) joins fields of different lengths and cannot follow which bytes were
     * written; cleared, no byte of the sentence is ever uninitialised. */
    uint8_t buf[ILAHRS_PAHR_MAX_LENGTH] = { 0 };
    size_t at = PAHR_PREFIX_LENGTH;
    size_t k;
    uint8_t sum = 0;
    copy_forward(buf, (const uint8_t *)PAHR_PREFIX, PAHR_PREFIX_LENGTH);
    /* (For Frama-C: each field, and each digit count below, analysed on its own.) */
    /*@ loop unroll ILAHRS_PAHR_FIELD_COUNT; */
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        const pahr_field_t *f = &ilahrs_pahr_fields[k];
        int32_t value = pahr_get(in, k);
        uint32_t m = value < 0 ? 0u - (uint32_t)value : (uint32_t)value;
        unsigned base = f->hex ? 16u : 10u;
        unsigned n = f->width > 1u ? f->width : 1u; /* digits before the point, at least */
        unsigned i;
        uint32_t rest;
        uint8_t *w;
        if (value < f->min || value > f->max) {
            return fail_size(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, SENTENCE_NAME(f->name));
        }
        if (value < 0) {
            buf[at++] = '-';
            n -= n > 1u;
        }
        n += f->decimals;
        /*@ loop unroll 10; */ /* a 32-bit magnitude has at most 10 digits */
        for (i = 1, rest = m / base; rest != 0; rest /= base) {
            i++; /* digits of m */
        }
        n = i > n ? i : n;
        at += n + (f->decimals != 0);
        w = buf + at;
        for (i = 0; i < n; i++) {
            if (i == f->decimals && i != 0) {
                *--w = '.';
            }
            *--w = (uint8_t)ilahrs_hex_digits[m % base];
            m /= base;
        }
        buf[at++] = k + 1 < ILAHRS_PAHR_FIELD_COUNT ? PAHR_SEPARATOR : PAHR_STAR;
    }
    for (k = 1; k + 1 < at; k++) {
        sum ^= buf[k];
    }
    buf[at++] = (uint8_t)ilahrs_hex_digits[sum >> 4];
    buf[at++] = (uint8_t)ilahrs_hex_digits[sum & 0xFu];
    buf[at++] = PAHR_CR;
    buf[at++] = PAHR_LF;
    if (text == NULL || cap < at) {
        return fail_size(err, ILAHRS_ERR_BUFFER_TOO_SMALL, ILAHRS_NO_OFFSET, NULL);
    }
    copy_forward((uint8_t *)text, buf, at);
    if (cap > at) {
        text[at] = '\0';
    }
    return at;
}

/* |value| * divisor rounded half away from zero, as the double code computed it: s = |value| *
 * divisor rounded to a double (to nearest, ties to even), then floor(s + 0.5) with s + 0.5 rounded
 * to a double too. For a hex field (whole, divisor 1): |value| if it is an integer. PAHR_HUGE,
 * beyond every range like the 1e15 the double code saturated at, for s >= 2^52 (infinities and
 * NaNs too) and for a hex field's fraction.
 *
 * Why this is exact: |value| is m * 2^e with m < 2^53, and m * divisor < 2^64 (the generator
 * refuses a divisor from 2^11), so the product is exact; shifting it to 53 bits with a round and a
 * sticky bit rounds it as the double multiplication does (a product below the normal range rounds
 * differently, but stays far below 1/2). Shifting s to the binary point leaves floor(s), and the
 * round bit adds the 0.5. Rounding s + 0.5 to a double changes its floor only for s = 0.5 - 2^-54,
 * whose sum rounds up to 1.0: below 1/2 the sum lies in [1/2, 1), and from 1/2 to 2^52 it is a
 * multiple of s's ulp (at most 1/2), exact unless it just crossed a power of two, where it rounds
 * to a neighbour with the same integer part. */
static uint64_t pahr_magnitude(uint64_t bits, uint32_t divisor, bool whole)
{
    uint64_t m = bits & (DOUBLE_ONE - 1u);
    int exponent = (int)((bits >> 52) & 0x7FFu);
    unsigned round = 0;  /* the last bit shifted out of m */
    unsigned sticky = 0; /* whether any bit before it was 1 */
    if (exponent != 0) {
        m |= DOUBLE_ONE;
    } else {
        exponent = 1; /* subnormal */
    }
    exponent -= 1075;
    m *= divisor;
    while (m >= 2 * DOUBLE_ONE) { /* round to 53 bits, to nearest even */
        sticky |= round;
        round = (unsigned)m & 1u;
        m >>= 1;
        exponent++;
    }
    m += round & (sticky | (unsigned)m) & 1u;
    if (exponent >= 0) {
        return PAHR_HUGE; /* m >= 2^52 here: s >= 2^52 */
    }
    if (m == 2 * DOUBLE_ONE - 1u && exponent == -54) {
        m++; /* 0.49999999999999994 + 0.5 rounds to 1.0, as 0.5 + 0.5 */
    }
    if (exponent < -60) { /* s <= 2^-8: keep only whether it is 0 */
        m = m != 0 ? 1u : 0u;
        exponent = -60;
    }
    round = 0;
    sticky = 0;
    while (exponent < 0) { /* floor(s + 0.5): the integer part, plus 1 if the first bit after it is */
        sticky |= round;
        round = (unsigned)m & 1u;
        m >>= 1;
        exponent++;
    }
    if (whole && (round | sticky) != 0) {
        return PAHR_HUGE; /* a fraction: not an integer */
    }
    return m + round;
}

bool ilahrs_pahr_from_array(const double values[ILAHRS_PAHR_FIELD_COUNT], ilahrs_pahr_t *out, ilahrs_error_t *err)
{
    ilahrs_pahr_t sentence; /* written to *out only if every field is in range */
    size_t k;
    /* A NaN or an infinity in a decimal field is reported before any field out of range. */
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        if (!ilahrs_pahr_fields[k].hex && ((double_bits(values[k]) >> 52) & 0x7FFu) == 0x7FFu) {
            goto out_of_range;
        }
    }
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        uint64_t bits = double_bits(values[k]);
        bool hex = ilahrs_pahr_fields[k].hex != 0;
        uint64_t magnitude = pahr_magnitude(bits, hex ? 1u : pahr_divisor(k), hex);
        int32_t scaled;
        if (magnitude >= SATURATED) {
            goto out_of_range; /* every range lies below SATURATED (checked by the generator) */
        }
        scaled = (bits & DOUBLE_SIGN) != 0 ? -(int32_t)magnitude : (int32_t)magnitude;
        if (scaled < ilahrs_pahr_fields[k].min || scaled > ilahrs_pahr_fields[k].max) {
            goto out_of_range;
        }
        store_bits((uint8_t *)&sentence + PAHR_MEMBER(k), (uint32_t)scaled, PAHR_SIZE(k));
    }
    *out = sentence;
    return true;
out_of_range:
    return fail(err, ILAHRS_ERR_OUT_OF_RANGE, ILAHRS_NO_OFFSET, SENTENCE_NAME(ilahrs_pahr_fields[k].name));
}

#if PAHR_HEX_FIELDS
/* (double)n without floating-point code, for |n| < 2^53: for the hex fields of
 * ilahrs_pahr_from_values(). */
static double int_double(int64_t n)
{
    int64_t key = int_key(n);
    uint64_t bits = key < 0 ? DOUBLE_SIGN | (0u - (uint64_t)key) : (uint64_t)key;
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}
#endif
