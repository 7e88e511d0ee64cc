/*
 * A deterministic capture of AHRS traffic for benchmarks, fuzz seeds and other bindings'
 * benchmarks: every payload table and output format, $PAHR sentences, acknowledgements and
 * commands, with about 1% random garbage and false frame headers in between. Everything is
 * built with the generated library from its own tables; the same seed gives the same bytes.
 */
#ifndef ILAHRS_BENCH_CAPTURE_H
#define ILAHRS_BENCH_CAPTURE_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint64_t messages;  /* messages written (frames and sentences) */
    uint64_t frames;    /* of which frames */
    uint64_t sentences; /* of which sentences */
    uint64_t garbage;   /* bytes of random garbage and false headers */
} capture_stats_t;

/* Fill out[0..size) with a capture; stats may be NULL. */
void capture_fill(uint8_t *out, size_t size, uint64_t seed, capture_stats_t *stats);

#endif
