/*
 * bench_mavlink: our stream decoder and MAVLink's mavlink_parse_char() on captures of the same
 * length and the same share of garbage (mix.h), each in its own protocol, in the same process.
 * Both captures are built in memory from the same seed. Prints `key: value` lines for
 * bench/mavlink/compare.py:
 *
 *   bench_mavlink [--size BYTES] [--seed N] [--runs N]
 *       throughput of each decoder fed whole and one byte at a time (best of N runs, interleaved)
 *   bench_mavlink --measure ours-whole|ours-bytes|theirs-whole|theirs-bytes [--size BYTES]
 *       one decoding run inside measured(), for valgrind --tool=callgrind --toggle-collect=measured
 *
 * Fed whole: ours is ilahrs_stream_next() over the buffer (then ilahrs_stream_finish()); theirs is
 * the buffer in a loop over mavlink_parse_char() (theirs_decode). One byte at a time: one call
 * per byte into the other translation unit, ilahrs_stream_push() (with ilahrs_stream_poll()) or
 * theirs_push(), as a UART interrupt handler calls a decoder.
 */
#define _POSIX_C_SOURCE 200809L
#include "ilahrs.h"
#include "mix.h"
#include "ours.h"
#include "theirs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef BENCH_BUILD
#define BENCH_BUILD "unknown flags"
#endif

typedef struct {
    uint64_t messages;
    uint64_t bytes;
    uint64_t discarded;
} tally_t;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void count(tally_t *t, const ilahrs_message_t *msg)
{
    t->messages++;
    t->bytes += msg->size;
}

static tally_t ours_whole(const uint8_t *buf, size_t size)
{
    tally_t t = { 0, 0, 0 };
    ilahrs_stream_t s;
    ilahrs_message_t msg;
    const uint8_t *p = buf;
    size_t n = size;
    ilahrs_stream_init(&s);
    while (ilahrs_stream_next(&s, &p, &n, &msg)) {
        count(&t, &msg);
    }
    while (ilahrs_stream_finish(&s, &msg)) {
        count(&t, &msg);
    }
    t.discarded = s.discarded;
    return t;
}

static tally_t ours_bytes(const uint8_t *buf, size_t size)
{
    tally_t t = { 0, 0, 0 };
    ilahrs_stream_t s;
    ilahrs_message_t msg;
    size_t i;
    ilahrs_stream_init(&s);
    for (i = 0; i < size; i++) {
        if (ilahrs_stream_push(&s, buf[i], &msg)) {
            do {
                count(&t, &msg);
            } while (ilahrs_stream_poll(&s, &msg));
        }
    }
    while (ilahrs_stream_finish(&s, &msg)) {
        count(&t, &msg);
    }
    t.discarded = s.discarded;
    return t;
}

static tally_t theirs_whole(const uint8_t *buf, size_t size)
{
    theirs_tally_t tt = { 0, 0 };
    tally_t t;
    theirs_init();
    theirs_decode(buf, size, &tt);
    t.messages = tt.messages;
    t.bytes = tt.bytes;
    t.discarded = size - tt.bytes;
    return t;
}

static tally_t theirs_bytes(const uint8_t *buf, size_t size)
{
    theirs_tally_t tt = { 0, 0 };
    tally_t t;
    size_t i;
    theirs_init();
    for (i = 0; i < size; i++) {
        (void)theirs_push(buf[i], &tt);
    }
    t.messages = tt.messages;
    t.bytes = tt.bytes;
    t.discarded = size - tt.bytes;
    return t;
}

typedef tally_t (*decoder_fn)(const uint8_t *buf, size_t size);

typedef struct {
    const char *name;
    decoder_fn decode;
    int theirs;
} decoder_t;

static const decoder_t decoders[4] = {
    { "ours-whole", ours_whole, 0 },
    { "ours-bytes", ours_bytes, 0 },
    { "theirs-whole", theirs_whole, 1 },
    { "theirs-bytes", theirs_bytes, 1 },
};

/* The only code callgrind counts in --measure runs (--toggle-collect=measured). */
__attribute__((noinline, noclone)) static tally_t measured(decoder_fn decode, const uint8_t *buf, size_t size)
{
    return decode(buf, size);
}

static uint64_t fnv1a(const uint8_t *p, size_t n)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    size_t i;
    for (i = 0; i < n; i++) {
        h = (h ^ p[i]) * 0x100000001B3ULL;
    }
    return h;
}

static void describe(const char *side, const uint8_t *buf, size_t size, const mix_stats_t *st)
{
    printf("%s_capture: %lu bytes, %llu messages, %.1f bytes per message, %llu garbage bytes (%.3f%%), "
           "%llu false headers, fnv1a %016llx\n",
           side, (unsigned long)size, (unsigned long long)st->messages,
           (double)st->message_bytes / (double)st->messages, (unsigned long long)st->garbage,
           100.0 * (double)st->garbage / (double)size, (unsigned long long)st->false_headers,
           (unsigned long long)fnv1a(buf, size));
}

static int same(const tally_t *a, const tally_t *b)
{
    return a->messages == b->messages && a->bytes == b->bytes && a->discarded == b->discarded;
}

int main(int argc, char **argv)
{
    size_t size = (size_t)16 << 20;
    unsigned long long seed = 1;
    int runs = 5;
    const char *measure = NULL;
    uint8_t *bufs[2];
    mix_stats_t stats[2];
    tally_t tallies[4];
    double best[4] = { 1e9, 1e9, 1e9, 1e9 };
    int run;
    int i;
    for (i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--size") == 0) {
            size = (size_t)strtoull(argv[i + 1], NULL, 0);
        } else if (strcmp(argv[i], "--seed") == 0) {
            seed = strtoull(argv[i + 1], NULL, 0);
        } else if (strcmp(argv[i], "--runs") == 0) {
            runs = atoi(argv[i + 1]);
        } else if (strcmp(argv[i], "--measure") == 0) {
            measure = argv[i + 1];
        } else {
            fprintf(stderr, "bench_mavlink: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    bufs[0] = (uint8_t *)malloc(size);
    bufs[1] = (uint8_t *)malloc(size);
    if (bufs[0] == NULL || bufs[1] == NULL || size < 4096) {
        return 1;
    }
    mix_fill(bufs[0], size, seed, ours_message, ours_false_header, &stats[0]);
    mix_fill(bufs[1], size, seed, theirs_message, theirs_false_header, &stats[1]);
    if (measure != NULL) {
        for (i = 0; i < 4; i++) {
            if (strcmp(measure, decoders[i].name) == 0) {
                tally_t t = measured(decoders[i].decode, bufs[decoders[i].theirs], size);
                printf("%s: %llu messages, %llu bytes, %lu bytes measured\n", measure,
                       (unsigned long long)t.messages, (unsigned long long)t.bytes, (unsigned long)size);
                return 0;
            }
        }
        fprintf(stderr, "bench_mavlink: --measure %s: no such decoder\n", measure);
        return 2;
    }
    printf("build: %s\n", BENCH_BUILD);
    describe("ours", bufs[0], size, &stats[0]);
    describe("theirs", bufs[1], size, &stats[1]);
    for (run = 0; run < runs; run++) {
        for (i = 0; i < 4; i++) {
            double t0 = now();
            double t1;
            tallies[i] = decoders[i].decode(bufs[decoders[i].theirs], size);
            t1 = now();
            if (t1 - t0 < best[i]) {
                best[i] = t1 - t0;
            }
        }
    }
    if (!same(&tallies[0], &tallies[1]) || !same(&tallies[2], &tallies[3])) {
        fprintf(stderr, "bench_mavlink: whole and bytewise decoding disagree\n");
        return 1;
    }
    for (i = 0; i < 4; i += 2) {
        const char *side = i == 0 ? "ours" : "theirs";
        const mix_stats_t *st = &stats[i / 2];
        printf("%s_decoded: %llu of %llu messages (%llu lost), %llu bytes outside messages\n", side,
               (unsigned long long)tallies[i].messages, (unsigned long long)st->messages,
               (unsigned long long)(st->messages - (tallies[i].messages < st->messages ? tallies[i].messages : st->messages)),
               (unsigned long long)tallies[i].discarded);
    }
    for (i = 0; i < 4; i++) {
        printf("%s: %.1f MiB/s, %.2f M messages/s\n", decoders[i].name, (double)size / 1048576.0 / best[i],
               (double)tallies[i].messages / best[i] / 1e6);
    }
    free(bufs[0]);
    free(bufs[1]);
    return 0;
}
