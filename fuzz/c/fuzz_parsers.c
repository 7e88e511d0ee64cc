/*
 * libFuzzer target: the one-message decoders and the payload codec.
 *
 * The first byte picks a payload table; the rest is decoded as that payload (padded or cut to
 * its size), as a frame, as a command frame, as an acknowledged message and as a $PAHR
 * sentence. Nothing may crash; a decoded payload must re-build to the same bytes unless a
 * field is out of its range, and then the builder must name the first such field; a decoded
 * frame must re-build to the same bytes; a decoded sentence must re-build to text that decodes
 * to the same values.
 *
 * Each round trip is a function of its own, so that libFuzzer's coverage report names it: `make
 * test` fails unless its short run (fuzz/run.py check, from the seeds fuzz/seeds.py makes) reaches
 * every function this line names.
 *
 * fuzz-must-reach: ilahrs_frame_build ilahrs_command_build ilahrs_pahr_build ilahrs_payload_build
 * fuzz-must-reach: payload_round_trip payload_out_of_range frame_round_trip command_round_trip
 * fuzz-must-reach: sentence_in_stream sentence_round_trip
 */
#include "ilahrs.h"

#include <stdlib.h>
#include <string.h>

#define ROUND_TRIP static __attribute__((noinline)) void

static void check(int ok)
{
    if (!ok) {
        abort();
    }
}

static double raw_value(const ilahrs_field_info_t *f, const void *value)
{
    return ilahrs_field_kind(f) == ILAHRS_KIND_FLOAT ? (double)ilahrs_field_get_float(f, value)
                                                     : (double)ilahrs_field_get_int(f, value);
}

/* A payload that builds re-builds to its bytes. */
ROUND_TRIP payload_round_trip(const uint8_t *in, const uint8_t *out, size_t size)
{
    check(memcmp(in, out, size) == 0);
}

/* A payload that does not build names its first field out of range. */
ROUND_TRIP payload_out_of_range(ilahrs_payload_t p, const void *value, size_t n, const ilahrs_error_t *err)
{
    const ilahrs_field_info_t *first = NULL;
    size_t i;
    check(n == 0 && err->kind == ILAHRS_ERR_OUT_OF_RANGE);
    for (i = 0; i < ilahrs_payload_field_count(p) && first == NULL; i++) {
        const ilahrs_field_info_t *f = ilahrs_payload_field(p, i);
        ilahrs_kind_t kind = ilahrs_field_kind(f);
        if (kind != ILAHRS_KIND_CHAR && kind != ILAHRS_KIND_RESERVED && !ilahrs_field_check(f, raw_value(f, value), NULL)) {
            first = f;
        }
    }
    check(first != NULL && err->offset == ilahrs_field_offset(first) && strcmp(err->field, ilahrs_field_name(first)) == 0);
}

static void payload(ilahrs_payload_t p, const uint8_t *data, size_t len)
{
    uint8_t in[256];
    uint8_t out[256];
    size_t size = ilahrs_payload_size(p);
    void *value = malloc(ilahrs_payload_struct_size(p));
    ilahrs_error_t err;
    size_t n;
    check(size <= sizeof in);
    /* the exact input first: accepted if and only if it has the table's size */
    check(ilahrs_payload_parse(p, data, len, value, &err) == (len == size));
    memset(in, 0, sizeof in);
    memcpy(in, data, len < size ? len : size);
    check(ilahrs_payload_parse(p, in, size, value, &err));
    n = ilahrs_payload_build(p, value, out, size, &err);
    if (n == size) {
        payload_round_trip(in, out, size);
    } else {
        payload_out_of_range(p, value, n, &err);
    }
    free(value);
}

/* A frame that decodes re-builds to its bytes and is acknowledged. */
ROUND_TRIP frame_round_trip(const ilahrs_frame_t *frame, const uint8_t *data, size_t len)
{
    uint8_t out[ILAHRS_FRAME_MAX_SIZE];
    ilahrs_error_t err;
    check(ilahrs_frame_build(frame, out, sizeof out, &err) == len && memcmp(out, data, len) == 0);
    check(ilahrs_ack_build(data, len, out, sizeof out, &err) > 0);
}

/* A command that decodes re-builds to a frame of its length with its code. */
ROUND_TRIP command_round_trip(const ilahrs_command_match_t *match, const uint8_t *data, size_t len)
{
    uint8_t out[ILAHRS_FRAME_MAX_SIZE];
    ilahrs_error_t err;
    check(match->count > 0 && ilahrs_command_build(match->commands[0], out, sizeof out, &err) == len);
    check(out[ILAHRS_FRAME_PAYLOAD_OFFSET] == data[ILAHRS_FRAME_PAYLOAD_OFFSET] && match->code == data[ILAHRS_FRAME_PAYLOAD_OFFSET]);
}

/* A sentence the stream decoder takes whole has the values the sentence parser reads. */
ROUND_TRIP sentence_in_stream(const ilahrs_pahr_t *parsed, const ilahrs_pahr_t *streamed)
{
    size_t k;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        check(ilahrs_pahr_field_get(parsed, k) == ilahrs_pahr_field_get(streamed, k));
    }
}

/* A sentence that decodes re-builds to text that decodes to the same values. */
ROUND_TRIP sentence_round_trip(const ilahrs_pahr_t *s)
{
    char text[ILAHRS_PAHR_MAX_LENGTH + 1];
    ilahrs_pahr_t t;
    ilahrs_error_t err;
    size_t k;
    size_t n = ilahrs_pahr_build(s, text, sizeof text, &err);
    check(n > 0 && ilahrs_pahr_parse(text, n, &t, &err));
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        check(ilahrs_pahr_field_get(s, k) == ilahrs_pahr_field_get(&t, k));
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ilahrs_frame_t frame;
    ilahrs_command_match_t match;
    ilahrs_pahr_t s;
    ilahrs_error_t err;
    uint8_t out[ILAHRS_FRAME_MAX_SIZE];
    const uint8_t *rest = data + (size > 0);
    size_t len = size > 0 ? size - 1 : 0;
    if (size > 4096) {
        return 0;
    }
    if (size > 0) {
        payload((ilahrs_payload_t)(data[0] % ILAHRS_PAYLOAD_COUNT), rest, len);
    }
    if (ilahrs_frame_parse(rest, len, &frame, &err)) {
        frame_round_trip(&frame, rest, len);
    } else {
        check(err.kind != ILAHRS_OK && (err.offset == ILAHRS_NO_OFFSET || err.offset <= len));
        check(ilahrs_ack_build(rest, len, out, sizeof out, &err) == 0);
    }
    if (ilahrs_command_decode(rest, len, &match, &err)) {
        command_round_trip(&match, rest, len);
    }
    /* The stream decoder takes the input as one sentence exactly when the sentence parser does
     * (both end in the one sentence scanner, after their own search for the end), with the same
     * values. */
    {
        ilahrs_stream_t decoder = { 0 };
        ilahrs_message_t msg;
        const uint8_t *p = rest;
        size_t n = len;
        bool whole = ilahrs_stream_next(&decoder, &p, &n, &msg) && decoder.discarded == 0
                  && msg.kind == ILAHRS_MESSAGE_SENTENCE && msg.size == len;
        bool parsed = ilahrs_pahr_parse((const char *)rest, len, &s, &err);
        check(whole == parsed);
        if (whole) {
            sentence_in_stream(&s, &msg.sentence);
        }
    }
    if (ilahrs_pahr_parse((const char *)rest, len, &s, &err)) {
        sentence_round_trip(&s);
    } else {
        check(err.kind != ILAHRS_OK && (err.offset == ILAHRS_NO_OFFSET || err.offset <= len || err.offset == ILAHRS_PAHR_MAX_LENGTH));
    }
    return 0;
}
