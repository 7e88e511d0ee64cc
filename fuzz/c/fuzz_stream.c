/*
 * libFuzzer target: the stream decoder.
 *
 * The input is decoded three ways: in one piece, in chunks whose sizes come from the input
 * itself, and one byte at a time. All three must hand out the same messages and discard the
 * same number of bytes; every byte belongs to exactly one message or is discarded; every
 * accepted frame must decode on its own and re-build to the same bytes; every accepted sentence
 * must decode on its own, and its re-built text must decode to the same values.
 *
 * The same three ways run again with the strict option (E42): they must agree, and every data
 * frame they accept must carry the reserved byte the AHRS sends. Last, the input is fed in its
 * chunks with the line idle after each one (E41): that must equal decoding each chunk on its own
 * with a fresh decoder, since no message spans an idle line.
 *
 * `make test` fails unless its short run (fuzz/run.py check) reaches every function this line names:
 * fuzz-must-reach: ilahrs_frame_build ilahrs_pahr_build verify_frame verify_sentence
 * fuzz-must-reach: ilahrs_frame_parse_strict ilahrs_stream_idle
 */
#include "ilahrs.h"

#include <stdlib.h>
#include <string.h>

#define MAX_EVENTS 65536

typedef struct {
    bool strict;
    size_t count;
    size_t bytes;
    uint64_t discarded;
    uint32_t sizes[MAX_EVENTS];
    uint8_t kinds[MAX_EVENTS];
    uint64_t hash; /* of every message's bytes, in order */
} events_t;

static void check(int ok)
{
    if (!ok) {
        abort();
    }
}

/* (noinline: libFuzzer's coverage report names them) */
static __attribute__((noinline)) void verify_frame(const ilahrs_message_t *msg, bool strict)
{
    ilahrs_frame_t frame;
    uint8_t again[ILAHRS_FRAME_MAX_SIZE];
    check(ilahrs_frame_parse(msg->data, msg->size, &frame, NULL));
    check(ilahrs_frame_parse_strict(msg->data, msg->size, &frame, NULL) || !strict);
    check(frame.payload_size == msg->frame.payload_size && frame.message_type == msg->frame.message_type
          && frame.reserved == msg->frame.reserved && memcmp(frame.payload, msg->frame.payload, frame.payload_size) == 0);
    check(ilahrs_frame_build(&frame, again, sizeof again, NULL) == msg->size);
    check(memcmp(again, msg->data, msg->size) == 0);
}

static __attribute__((noinline)) void verify_sentence(const ilahrs_message_t *msg)
{
    ilahrs_pahr_t s;
    ilahrs_pahr_t t;
    char text[ILAHRS_PAHR_MAX_LENGTH + 1];
    size_t n;
    size_t k;
    check(msg->kind == ILAHRS_MESSAGE_SENTENCE);
    check(ilahrs_pahr_parse((const char *)msg->data, msg->size, &s, NULL));
    check(memcmp(&s, &msg->sentence, sizeof s) == 0);
    n = ilahrs_pahr_build(&s, text, sizeof text, NULL);
    check(n > 0 && ilahrs_pahr_parse(text, n, &t, NULL));
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        check(ilahrs_pahr_field_get(&s, k) == ilahrs_pahr_field_get(&t, k));
    }
}

static void verify(const ilahrs_message_t *msg, bool strict)
{
    if (msg->kind == ILAHRS_MESSAGE_FRAME) {
        verify_frame(msg, strict);
    } else {
        verify_sentence(msg);
    }
}

static void add(events_t *ev, const ilahrs_message_t *msg)
{
    size_t i;
    check(ev->count < MAX_EVENTS);
    ev->sizes[ev->count] = (uint32_t)msg->size;
    ev->kinds[ev->count] = (uint8_t)msg->kind;
    ev->count++;
    ev->bytes += msg->size;
    for (i = 0; i < msg->size; i++) {
        ev->hash = (ev->hash ^ msg->data[i]) * 0x100000001B3ULL;
    }
    verify(msg, ev->strict);
}

/* The size of the next chunk: from the input itself, so the fuzzer steers the cuts. */
static size_t next_chunk(const uint8_t *data, size_t size, size_t fed, size_t *turn)
{
    size_t chunk = 1 + data[(*turn)++ % size] % 97u;
    return chunk > size - fed ? size - fed : chunk;
}

static void start(events_t *ev, bool strict)
{
    memset(ev, 0, sizeof *ev);
    ev->strict = strict;
    ev->hash = 0xCBF29CE484222325ULL;
}

/* mode 0: in one piece; 1: in chunks; 2: a byte at a time; 3: in chunks, the line idle after each.
 * Adds to `ev` (call start() first). */
static void decode(const uint8_t *data, size_t size, int mode, events_t *ev)
{
    ilahrs_stream_t s;
    ilahrs_message_t msg;
    size_t fed = 0;
    size_t turn = 0;
    ilahrs_stream_init(&s);
    s.strict = ev->strict;
    while (fed < size) {
        size_t chunk = mode == 1 || mode == 3 ? next_chunk(data, size, fed, &turn) : size - fed;
        if (mode == 2) {
            if (ilahrs_stream_push(&s, data[fed], &msg)) {
                do {
                    add(ev, &msg);
                } while (ilahrs_stream_poll(&s, &msg));
            }
            fed++;
            continue;
        }
        {
            /* a copy per chunk: pointers past it are caught by AddressSanitizer */
            uint8_t *copy = (uint8_t *)malloc(chunk);
            const uint8_t *p = copy;
            size_t n = chunk;
            memcpy(copy, data + fed, chunk);
            while (ilahrs_stream_next(&s, &p, &n, &msg)) {
                check(msg.size > 0);
                add(ev, &msg);
            }
            check(n == 0);
            free(copy);
        }
        fed += chunk;
        if (mode == 3) {
            check(!ilahrs_stream_idle(&s, ILAHRS_IDLE_TIMEOUT_US - 1u, &msg));
            while (ilahrs_stream_idle(&s, ILAHRS_IDLE_TIMEOUT_US, &msg)) {
                add(ev, &msg);
            }
            check(s.count == 0);
        }
    }
    while (ilahrs_stream_finish(&s, &msg)) {
        add(ev, &msg);
    }
    check(s.count == 0);
    ev->discarded += s.discarded;
}

/* What mode 3 must give: each chunk decoded on its own by a fresh decoder (E41). */
static void decode_segments(const uint8_t *data, size_t size, events_t *ev)
{
    size_t fed = 0;
    size_t turn = 0;
    while (fed < size) {
        size_t chunk = next_chunk(data, size, fed, &turn);
        decode(data + fed, chunk, 0, ev);
        fed += chunk;
    }
}

static void same(const events_t *a, const events_t *b)
{
    check(a->count == b->count && a->discarded == b->discarded && a->hash == b->hash);
    check(memcmp(a->sizes, b->sizes, a->count * sizeof a->sizes[0]) == 0);
    check(memcmp(a->kinds, b->kinds, a->count) == 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static events_t a;
    static events_t b;
    static events_t c;
    int strict;
    if (size > 1 << 16) {
        return 0;
    }
    for (strict = 0; strict < 2; strict++) {
        start(&a, strict != 0);
        start(&b, strict != 0);
        start(&c, strict != 0);
        decode(data, size, 0, &a);
        decode(data, size, 1, &b);
        decode(data, size, 2, &c);
        check(a.bytes + a.discarded == size);
        same(&a, &b);
        same(&a, &c);
    }
    if (size > 0) {
        start(&a, (data[0] & 1) != 0);
        start(&b, (data[0] & 1) != 0);
        decode(data, size, 3, &a);
        decode_segments(data, size, &b);
        same(&a, &b);
    }
    return 0;
}
