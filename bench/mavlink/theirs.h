/*
 * MAVLink's side of the comparison, in C files compiled against the library mavgen generates
 * (build/mavlink/c): messages of the mix (mix.h) built with its pack functions, and its
 * decoder, mavlink_parse_char() on channel 0, fed a whole buffer or one byte per call.
 */
#ifndef ILAHRS_BENCH_THEIRS_H
#define ILAHRS_BENCH_THEIRS_H

#include "mix.h"

#include <stdbool.h>

size_t theirs_message(mix_kind_t kind, uint64_t *rng, uint8_t *out, size_t cap);
size_t theirs_false_header(uint64_t *rng, uint8_t *out);

typedef struct {
    uint64_t messages; /* messages with a good checksum */
    uint64_t bytes;    /* their bytes on the wire */
} theirs_tally_t;

/* Empty channel 0's parser state. */
void theirs_init(void);
/* Every byte of data through mavlink_parse_char(), in a loop in the library's translation unit. */
void theirs_decode(const uint8_t *data, size_t len, theirs_tally_t *tally);
/* One byte through mavlink_parse_char(), one call per byte as from a UART interrupt. */
bool theirs_push(uint8_t byte, theirs_tally_t *tally);

#endif
