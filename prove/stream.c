/* The stream decoder, lenient and strict: `len` unknown bytes fed whole (ilahrs_stream_next()), in
 * two chunks cut anywhere, or a byte at a time (ilahrs_stream_push() and ilahrs_stream_poll()),
 * then the end of the input (ilahrs_stream_idle(), ilahrs_stream_finish()). The decoder starts from
 * ilahrs_stream_init(), which leaves its buffer unwritten: a read of a held byte the decoder has not
 * written is an alarm. */
#include "input.h"

#ifndef MAX
#define MAX 16
#endif

int main(void)
{
    ilahrs_stream_t s;
    ilahrs_message_t msg;
    size_t len = prove_length(MAX);
    int how = Frama_C_interval(0, 2);
    const uint8_t *p;
    size_t n;
    //@ split len;
    ilahrs_stream_init(&s);
    s.strict = Frama_C_nondet(0, 1);
    p = PROVE_DATA(len);
    if (how == 0) {
        n = len;
        while (ilahrs_stream_next(&s, &p, &n, &msg)) {
        }
    } else if (how == 1) {
        size_t cut = Frama_C_size_t_interval(0, len);
        n = cut;
        while (ilahrs_stream_next(&s, &p, &n, &msg)) {
        }
        n = len - cut;
        while (ilahrs_stream_next(&s, &p, &n, &msg)) {
        }
    } else {
        for (n = 0; n < len; n++) {
            if (ilahrs_stream_push(&s, p[n], &msg)) {
                while (ilahrs_stream_poll(&s, &msg)) {
                }
            }
        }
    }
    while (ilahrs_stream_idle(&s, Frama_C_unsigned_int_interval(0, UINT32_MAX), &msg)) {
    }
    while (ilahrs_stream_finish(&s, &msg)) {
    }
    return 0;
}
