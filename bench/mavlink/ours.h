/* Our side of the comparison: messages of the mix (mix.h) built with the ilahrs C library. */
#ifndef ILAHRS_BENCH_OURS_H
#define ILAHRS_BENCH_OURS_H

#include "mix.h"

size_t ours_message(mix_kind_t kind, uint64_t *rng, uint8_t *out, size_t cap);
size_t ours_false_header(uint64_t *rng, uint8_t *out);

#endif
