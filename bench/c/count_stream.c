/*
 * count_stream: the stream decoder on the benchmark capture (capture.h), for an instruction count
 * under valgrind --tool=callgrind (make bench-c): the capture is built first, then decoded fed
 * whole (ilahrs_stream_next on the one buffer) or fed one byte at a time (ilahrs_stream_push and
 * ilahrs_stream_poll). Only decode_whole() and decode_bytes() are meant to be counted
 * (--toggle-collect); each checks that it found what the capture holds.
 *
 *   count_stream whole|bytes [--size BYTES] [--seed N]
 */
#include "capture.h"

#include "ilahrs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

typedef struct {
    uint64_t frames;
    uint64_t sentences;
} tally_t;

static void count(tally_t *t, const ilahrs_message_t *msg)
{
    if (msg->kind == ILAHRS_MESSAGE_FRAME) {
        t->frames++;
    } else {
        t->sentences++;
    }
}

NOINLINE tally_t decode_whole(const uint8_t *buf, size_t size);
NOINLINE tally_t decode_bytes(const uint8_t *buf, size_t size);

NOINLINE tally_t decode_whole(const uint8_t *buf, size_t size)
{
    tally_t t = { 0, 0 };
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
    return t;
}

NOINLINE tally_t decode_bytes(const uint8_t *buf, size_t size)
{
    tally_t t = { 0, 0 };
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
    return t;
}

int main(int argc, char **argv)
{
    size_t size = (size_t)1 << 20;
    unsigned long long seed = 1;
    capture_stats_t st;
    tally_t t;
    uint8_t *buf;
    int i;
    if (argc < 2 || (strcmp(argv[1], "whole") != 0 && strcmp(argv[1], "bytes") != 0)) {
        fprintf(stderr, "usage: count_stream whole|bytes [--size BYTES] [--seed N]\n");
        return 2;
    }
    for (i = 2; i + 1 < argc; i += 2) {
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
    t = strcmp(argv[1], "whole") == 0 ? decode_whole(buf, size) : decode_bytes(buf, size);
    free(buf);
#if defined(ILAHRS_STREAM_SENTENCES) && !ILAHRS_STREAM_SENTENCES
    st.sentences = 0; /* the frames-only decoder counts sentences as discarded bytes */
#endif
    if (t.frames != st.frames || t.sentences != st.sentences) {
        fprintf(stderr, "count_stream: decoded %llu frames and %llu sentences, the capture holds %llu and %llu\n",
                (unsigned long long)t.frames, (unsigned long long)t.sentences, (unsigned long long)st.frames,
                (unsigned long long)st.sentences);
        return 1;
    }
    printf("%lu\n", (unsigned long)size);
    return 0;
}
