/* See mix.h. */
#include "mix.h"

uint64_t mix_next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

size_t mix_below(uint64_t *state, size_t n)
{
    return (size_t)(mix_next(state) % n);
}

static mix_kind_t pick(uint64_t *rng)
{
    size_t r = mix_below(rng, 10);
    if (r < 8) {
        return (mix_kind_t)(MIX_OUTPUT_A + mix_below(rng, 3));
    }
    return r == 8 ? MIX_SMALL : MIX_ACK;
}

void mix_fill(uint8_t *out, size_t size, uint64_t seed, mix_message_fn message, mix_false_header_fn false_header,
              mix_stats_t *stats)
{
    /* One stream decides what comes next, another fills the messages' contents. */
    uint64_t script = seed;
    uint64_t content = seed ^ 0x5DEECE66DULL;
    size_t n = 0;
    mix_stats_t st = { 0, 0, 0, 0 };
    while (size - n > MIX_MESSAGE_MAX + MIX_FALSE_HEADER_MAX + 16) {
        size_t m = message(pick(&script), &content, out + n, size - n);
        n += m;
        st.messages += m > 0;
        st.message_bytes += m;
        if (st.garbage * 1000 < (uint64_t)GARBAGE_PERMILLE * n && mix_below(&script, 4) == 0) {
            size_t k;
            if (mix_below(&script, 5) == 0) {
                k = false_header(&content, out + n);
                st.false_headers++;
            } else {
                size_t i;
                k = 1 + mix_below(&script, 16);
                for (i = 0; i < k; i++) {
                    out[n + i] = (uint8_t)mix_next(&content);
                }
            }
            n += k;
            st.garbage += k;
        }
    }
    while (n < size) {
        out[n++] = (uint8_t)mix_next(&content);
        st.garbage++;
    }
    if (stats != NULL) {
        *stats = st;
    }
}
