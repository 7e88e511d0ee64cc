/*
 * bench_stream: the C stream decoder's throughput on the benchmark capture (capture.h, 64 MiB,
 * built in memory), next to a plain loop that only sums every byte of the same buffer, in the
 * same run. Prints `name: X MiB/s` lines; the best of several runs counts.
 *
 *   bench_stream [--size BYTES] [--seed N]
 */
#define _POSIX_C_SOURCE 200809L
#include "capture.h"

#include "ilahrs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef BENCH_BUILD
#define BENCH_BUILD "unknown flags"
#endif

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static volatile uint64_t sink;

/* The reference: touch every byte once, nothing else. */
static uint64_t sum_bytes(const uint8_t *p, size_t n)
{
    uint64_t sum = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        sum += p[i];
    }
    return sum;
}

typedef struct {
    uint64_t frames;
    uint64_t sentences;
    uint64_t bytes;
    uint64_t discarded;
} tally_t;

static void count(tally_t *t, const ilahrs_message_t *msg)
{
    if (msg->kind == ILAHRS_MESSAGE_FRAME) {
        t->frames++;
    } else {
        t->sentences++;
    }
    t->bytes += msg->size;
}

/* The whole buffer as one chunk: the zero-copy path. */
static tally_t decode_whole(const uint8_t *buf, size_t size)
{
    tally_t t = { 0, 0, 0, 0 };
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

/* 4 KiB chunks, as a DMA ring or read() would deliver them. */
static tally_t decode_chunks(const uint8_t *buf, size_t size, size_t chunk)
{
    tally_t t = { 0, 0, 0, 0 };
    ilahrs_stream_t s;
    ilahrs_message_t msg;
    size_t at;
    ilahrs_stream_init(&s);
    for (at = 0; at < size; at += chunk) {
        const uint8_t *p = buf + at;
        size_t n = size - at < chunk ? size - at : chunk;
        while (ilahrs_stream_next(&s, &p, &n, &msg)) {
            count(&t, &msg);
        }
    }
    while (ilahrs_stream_finish(&s, &msg)) {
        count(&t, &msg);
    }
    t.discarded = s.discarded;
    return t;
}

/* One byte at a time, as a UART interrupt handler would. */
static tally_t decode_bytes(const uint8_t *buf, size_t size)
{
    tally_t t = { 0, 0, 0, 0 };
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

static double mib_per_s(size_t bytes, double seconds)
{
    return (double)bytes / (1024.0 * 1024.0) / seconds;
}

static int same(const tally_t *a, const tally_t *b)
{
    return a->frames == b->frames && a->sentences == b->sentences && a->bytes == b->bytes && a->discarded == b->discarded;
}

int main(int argc, char **argv)
{
    size_t size = (size_t)64 << 20;
    unsigned long long seed = 1;
    uint8_t *buf;
    capture_stats_t st;
    tally_t whole = { 0, 0, 0, 0 };
    tally_t chunks = { 0, 0, 0, 0 };
    tally_t bytes = { 0, 0, 0, 0 };
    double best_sum = 1e9;
    double best_whole = 1e9;
    double best_chunks = 1e9;
    double best_bytes = 1e9;
    int run;
    int i;
    for (i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--size") == 0) {
            size = (size_t)strtoull(argv[i + 1], NULL, 0);
        } else if (strcmp(argv[i], "--seed") == 0) {
            seed = strtoull(argv[i + 1], NULL, 0);
        }
    }
    buf = (uint8_t *)malloc(size);
    if (buf == NULL) {
        return 1;
    }
    capture_fill(buf, size, seed, &st);
    printf("build: %s (decoder and summing loop alike)\n", BENCH_BUILD);
    printf("capture: %lu bytes (%.0f MiB), seed %llu: %llu frames, %llu sentences, %llu garbage bytes (%.2f%%)\n",
           (unsigned long)size, (double)size / 1048576.0, seed, (unsigned long long)st.frames,
           (unsigned long long)st.sentences, (unsigned long long)st.garbage, 100.0 * (double)st.garbage / (double)size);
    for (run = 0; run < 7; run++) {
        double t0 = now();
        double t1;
        sink += sum_bytes(buf, size);
        t1 = now();
        if (t1 - t0 < best_sum) {
            best_sum = t1 - t0;
        }
        t0 = now();
        whole = decode_whole(buf, size);
        t1 = now();
        if (t1 - t0 < best_whole) {
            best_whole = t1 - t0;
        }
        t0 = now();
        chunks = decode_chunks(buf, size, 4096);
        t1 = now();
        if (t1 - t0 < best_chunks) {
            best_chunks = t1 - t0;
        }
    }
    for (run = 0; run < 2; run++) {
        double t0 = now();
        double t1;
        bytes = decode_bytes(buf, size);
        t1 = now();
        if (t1 - t0 < best_bytes) {
            best_bytes = t1 - t0;
        }
    }
    printf("decoded: %llu frames, %llu sentences, %llu bytes discarded\n", (unsigned long long)whole.frames,
           (unsigned long long)whole.sentences, (unsigned long long)whole.discarded);
    if (!same(&whole, &chunks) || !same(&whole, &bytes) || whole.bytes + whole.discarded != size) {
        fprintf(stderr, "bench_stream: the decoding modes disagree\n");
        return 1;
    }
    printf("c_sum_bytes: %.0f MiB/s\n", mib_per_s(size, best_sum));
    printf("c_stream_next: %.0f MiB/s\n", mib_per_s(size, best_whole));
    printf("c_stream_next_4k_chunks: %.0f MiB/s\n", mib_per_s(size, best_chunks));
    printf("c_stream_push_bytewise: %.0f MiB/s\n", mib_per_s(size, best_bytes));
    printf("c_stream_next / c_sum_bytes: %.2f (target >= 0.50)\n", best_sum / best_whole);
    printf("c_stream_next: %.1f M messages/s\n", (double)(whole.frames + whole.sentences) / best_whole / 1e6);
    free(buf);
    return 0;
}
