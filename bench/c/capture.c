/* See capture.h. */
#include "capture.h"

#include "ilahrs.h"

#include <string.h>

static uint64_t next(uint64_t *s)
{
    /* splitmix64 */
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static size_t below(uint64_t *s, size_t n)
{
    return (size_t)(next(s) % n);
}

static double raw_value(const ilahrs_field_info_t *f, const void *value)
{
    return ilahrs_field_kind(f) == ILAHRS_KIND_FLOAT ? (double)ilahrs_field_get_float(f, value)
                                                     : (double)ilahrs_field_get_int(f, value);
}

/* A data frame of table p with random field values the builder accepts. */
static size_t payload_frame(uint64_t *s, ilahrs_payload_t p, uint8_t *out, size_t cap)
{
    union {
        uint8_t bytes[512];
        double align;
    } value;
    uint8_t raw[ILAHRS_FRAME_MAX_PAYLOAD];
    size_t size = ilahrs_payload_size(p);
    size_t i;
    for (i = 0; i < size; i++) {
        raw[i] = (uint8_t)next(s);
    }
    if (ilahrs_payload_struct_size(p) > sizeof value.bytes || !ilahrs_payload_parse(p, raw, size, &value, NULL)) {
        return 0;
    }
    for (i = 0; i < ilahrs_payload_field_count(p); i++) {
        const ilahrs_field_info_t *f = ilahrs_payload_field(p, i);
        ilahrs_kind_t kind = ilahrs_field_kind(f);
        if (kind == ILAHRS_KIND_CHAR || kind == ILAHRS_KIND_RESERVED || ilahrs_field_check(f, raw_value(f, &value), NULL)) {
            continue;
        }
        /* out of range: a small value, else the default */
        if (kind == ILAHRS_KIND_FLOAT) {
            float small = (float)((double)(int64_t)below(s, 2001) / 10.0 - 100.0);
            (void)ilahrs_field_set_float(f, &value, small, NULL);
        } else {
            (void)ilahrs_field_set_int(f, &value, (int64_t)below(s, 100), NULL);
        }
        if (!ilahrs_field_check(f, raw_value(f, &value), NULL)) {
            union {
                uint8_t bytes[512];
                double align;
            } defaults;
            ilahrs_payload_defaults(p, &defaults);
            memcpy(ilahrs_field_member(f, &value), ilahrs_field_member_const(f, &defaults), ilahrs_field_size(f));
        }
    }
    return ilahrs_payload_build_frame(p, &value, out, cap, NULL);
}

static size_t sentence(uint64_t *s, uint8_t *out, size_t cap)
{
    double v[ILAHRS_PAHR_FIELD_COUNT];
    ilahrs_pahr_t pahr;
    size_t k;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        int32_t low;
        int32_t high;
        uint32_t div = ilahrs_pahr_field_divisor(k);
        int32_t r;
        (void)ilahrs_pahr_field_range(k, &low, &high);
        r = low + (int32_t)below(s, (size_t)((int64_t)high - low) + 1);
        v[k] = div == 0 ? (double)r : (double)r / (double)div;
    }
    if (!ilahrs_pahr_from_array(v, &pahr, NULL)) {
        return 0;
    }
    return ilahrs_pahr_build(&pahr, (char *)out, cap, NULL);
}

void capture_fill(uint8_t *out, size_t size, uint64_t seed, capture_stats_t *stats)
{
    uint64_t s = seed;
    size_t n = 0;
    capture_stats_t st;
    memset(&st, 0, sizeof st);
    while (size - n > 2 * ILAHRS_MAX_MESSAGE_SIZE) {
        size_t r = below(&s, 100);
        size_t m = 0;
        int is_sentence = 0;
        if (r < 60) {
            /* the three binary output formats (Tables 6.4-6.6), as the device streams them */
            static const ilahrs_payload_t outputs[3] = { ILAHRS_PAYLOAD_FULL_OUTPUT, ILAHRS_PAYLOAD_QUATERNION,
                                            ILAHRS_PAYLOAD_ORIENTATION_SENSORS };
            m = payload_frame(&s, outputs[r % 3], out + n, size - n);
        } else if (r < 80) {
            m = sentence(&s, out + n, size - n);
            is_sentence = 1;
        } else if (r < 88) {
            m = payload_frame(&s, (ilahrs_payload_t)below(&s, ILAHRS_PAYLOAD_COUNT), out + n, size - n);
        } else if (r < 94) {
            uint8_t command[ILAHRS_FRAME_MAX_SIZE];
            size_t c = ilahrs_command_build((ilahrs_command_t)below(&s, ILAHRS_COMMAND_COUNT), command, sizeof command, NULL);
            m = ilahrs_ack_build(command, c, out + n, size - n, NULL);
        } else {
            m = ilahrs_command_build((ilahrs_command_t)below(&s, ILAHRS_COMMAND_COUNT), out + n, size - n, NULL);
        }
        if (m > 0) {
            n += m;
            st.messages++;
            if (is_sentence) {
                st.sentences++;
            } else {
                st.frames++;
            }
        }
        r = below(&s, 1000);
        if (r < 40) {
            /* random garbage: about 1% of the bytes */
            size_t k = 1 + below(&s, 16);
            while (k-- > 0) {
                out[n++] = (uint8_t)next(&s);
                st.garbage++;
            }
        } else if (r < 50) {
            /* a false header: AA 55, a valid type, any length, then the stream goes on */
            out[n++] = ILAHRS_FRAME_HEADER_0;
            out[n++] = ILAHRS_FRAME_HEADER_1;
            out[n++] = (uint8_t)below(&s, 2);
            out[n++] = 0;
            out[n++] = (uint8_t)below(&s, 256);
            out[n++] = 0;
            st.garbage += 6;
        }
    }
    while (n < size) {
        out[n++] = (uint8_t)next(&s);
        st.garbage++;
    }
    if (stats != NULL) {
        *stats = st;
    }
}
