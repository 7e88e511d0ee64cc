/*
 * capture: write the benchmark capture (capture.h) to a file, or a fuzzing seed corpus.
 *
 *   capture [--size BYTES] [--seed N] --out FILE      one capture (default 64 MiB, seed 1)
 *   capture --corpus DIR --count K [--size BYTES]     K small captures, seeds 1..K
 *
 * With --out it also prints what the C stream decoder finds in the capture, so that another
 * binding's benchmark can check it decodes the same messages.
 */
#include "capture.h"

#include "ilahrs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        perror(path);
        return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    size_t size = (size_t)64 << 20;
    unsigned long long seed = 1;
    const char *out = NULL;
    const char *corpus = NULL;
    unsigned long count = 0;
    uint8_t *buf;
    int i;
    for (i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--size") == 0) {
            size = (size_t)strtoull(argv[i + 1], NULL, 0);
        } else if (strcmp(argv[i], "--seed") == 0) {
            seed = strtoull(argv[i + 1], NULL, 0);
        } else if (strcmp(argv[i], "--out") == 0) {
            out = argv[i + 1];
        } else if (strcmp(argv[i], "--corpus") == 0) {
            corpus = argv[i + 1];
        } else if (strcmp(argv[i], "--count") == 0) {
            count = strtoul(argv[i + 1], NULL, 0);
        } else {
            break;
        }
    }
    if (i != argc || (out == NULL) == (corpus == NULL)) {
        fprintf(stderr, "usage: %s [--size BYTES] [--seed N] --out FILE | --corpus DIR --count K [--size BYTES]\n", argv[0]);
        return 2;
    }
    buf = (uint8_t *)malloc(size);
    if (buf == NULL) {
        fprintf(stderr, "cannot allocate %lu bytes\n", (unsigned long)size);
        return 1;
    }
    if (corpus != NULL) {
        unsigned long k;
        for (k = 1; k <= count; k++) {
            char path[4096];
            capture_fill(buf, size, k, NULL);
            snprintf(path, sizeof path, "%s/seed-%04lu", corpus, k);
            if (!write_file(path, buf, size)) {
                return 1;
            }
        }
    } else {
        capture_stats_t st;
        ilahrs_stream_t s;
        ilahrs_message_t msg;
        const uint8_t *p = buf;
        size_t n = size;
        unsigned long long frames = 0;
        unsigned long long sentences = 0;
        capture_fill(buf, size, seed, &st);
        if (!write_file(out, buf, size)) {
            return 1;
        }
        ilahrs_stream_init(&s);
        while (ilahrs_stream_next(&s, &p, &n, &msg) || ilahrs_stream_finish(&s, &msg)) {
            if (msg.kind == ILAHRS_MESSAGE_FRAME) {
                frames++;
            } else {
                sentences++;
            }
        }
        printf("%s: %lu bytes, seed %llu: written %llu frames, %llu sentences, %llu garbage bytes; "
               "decoded %llu frames, %llu sentences, %llu bytes discarded\n",
               out, (unsigned long)size, seed, (unsigned long long)st.frames, (unsigned long long)st.sentences,
               (unsigned long long)st.garbage, frames, sentences, (unsigned long long)s.discarded);
    }
    free(buf);
    return 0;
}
