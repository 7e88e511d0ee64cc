/*
 * The traffic both comparison captures follow (make bench-mavlink): the same message mix and the
 * same share of garbage, each protocol's messages built by its own C library. A capture is
 * messages back to back; after a message, when the garbage so far is below GARBAGE_PERMILLE of
 * the bytes written, a garbage chunk follows one time in four: random bytes (1 to 16), or one
 * time in five a false header (the protocol's start bytes and a plausible length, then the
 * stream goes on). So the share of garbage is the same in both captures to a few bytes, at
 * random places. The last bytes, too few for another message, are random garbage too.
 */
#ifndef ILAHRS_BENCH_MIX_H
#define ILAHRS_BENCH_MIX_H

#include <stddef.h>
#include <stdint.h>

#define GARBAGE_PERMILLE 10

/* The message mix: four in five are the attitude/sensor output a device streams (three formats
 * in turn, as if switched), one in ten a small status or command message, one in ten an
 * acknowledgement. Each protocol maps a kind to its own message of that role. */
typedef enum {
    MIX_OUTPUT_A,
    MIX_OUTPUT_B,
    MIX_OUTPUT_C,
    MIX_SMALL,
    MIX_ACK,
} mix_kind_t;

typedef struct {
    uint64_t messages;      /* messages written */
    uint64_t message_bytes; /* their bytes */
    uint64_t garbage;       /* bytes of garbage, false headers included */
    uint64_t false_headers; /* false headers written */
} mix_stats_t;

/* splitmix64: the random source of both captures. */
uint64_t mix_next(uint64_t *state);
size_t mix_below(uint64_t *state, size_t n);

/* Writes one message of the kind into out (cap bytes); returns its size, 0 if it does not fit. */
typedef size_t (*mix_message_fn)(mix_kind_t kind, uint64_t *rng, uint8_t *out, size_t cap);
/* Writes a false header into out (at least MIX_FALSE_HEADER_MAX bytes); returns its size. */
typedef size_t (*mix_false_header_fn)(uint64_t *rng, uint8_t *out);

#define MIX_FALSE_HEADER_MAX 16
/* No message of either protocol is longer. */
#define MIX_MESSAGE_MAX 280

void mix_fill(uint8_t *out, size_t size, uint64_t seed, mix_message_fn message, mix_false_header_fn false_header,
              mix_stats_t *stats);

#endif
