/*
 * libFuzzer target: the one-message decoders and the payload codec.
 *
 * The first byte picks a payload table; the rest is decoded as that payload (padded or cut to
 * its size), as a frame, as a command frame, as an acknowledged message and as a $PAHR
 * sentence. Nothing may crash; a decoded payload must re-build to the same bytes unless a
 * field is out of its range, and then the builder must name the first such field; a decoded
 * frame must re-build to the same bytes; a decoded sentence must re-build to text that decodes
 * to the same values.
 */
#include "ilahrs.h"

#include <stdlib.h>
#include <string.h>

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

static void payload(ilahrs_payload_t p, const uint8_t *data, size_t len)
{
    uint8_t in[256];
    uint8_t out[256];
    size_t size = ilahrs_payload_size(p);
    void *value = malloc(ilahrs_payload_struct_size(p));
    ilahrs_error_t err;
    size_t n;
    size_t i;
    check(size <= sizeof in);
    /* the exact input first: accepted if and only if it has the table's size */
    check(ilahrs_payload_parse(p, data, len, value, &err) == (len == size));
    memset(in, 0, sizeof in);
    memcpy(in, data, len < size ? len : size);
    check(ilahrs_payload_parse(p, in, size, value, &err));
    n = ilahrs_payload_build(p, value, out, size, &err);
    if (n == size) {
        check(memcmp(in, out, size) == 0);
    } else {
        const ilahrs_field_info_t *first = NULL;
        check(n == 0 && err.kind == ILAHRS_ERR_OUT_OF_RANGE);
        for (i = 0; i < ilahrs_payload_field_count(p) && first == NULL; i++) {
            const ilahrs_field_info_t *f = ilahrs_payload_field(p, i);
            ilahrs_kind_t kind = ilahrs_field_kind(f);
            if (kind != ILAHRS_KIND_CHAR && kind != ILAHRS_KIND_RESERVED && !ilahrs_field_check(f, raw_value(f, value), NULL)) {
                first = f;
            }
        }
        check(first != NULL && err.offset == ilahrs_field_offset(first) && strcmp(err.field, ilahrs_field_name(first)) == 0);
    }
    free(value);
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
        check(ilahrs_frame_build(&frame, out, sizeof out, &err) == len && memcmp(out, rest, len) == 0);
        check(ilahrs_ack_build(rest, len, out, sizeof out, &err) > 0);
    } else {
        check(err.kind != ILAHRS_OK && (err.offset == ILAHRS_NO_OFFSET || err.offset <= len));
        check(ilahrs_ack_build(rest, len, out, sizeof out, &err) == 0);
    }
    if (ilahrs_command_decode(rest, len, &match, &err)) {
        check(match.count > 0 && ilahrs_command_build(match.commands[0], out, sizeof out, &err) == len);
        check(out[ILAHRS_FRAME_PAYLOAD_OFFSET] == rest[ILAHRS_FRAME_PAYLOAD_OFFSET] && match.code == rest[ILAHRS_FRAME_PAYLOAD_OFFSET]);
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
        size_t k;
        check(whole == parsed);
        for (k = 0; whole && k < ILAHRS_PAHR_FIELD_COUNT; k++) {
            check(ilahrs_pahr_field_get(&s, k) == ilahrs_pahr_field_get(&msg.sentence, k));
        }
    }
    if (ilahrs_pahr_parse((const char *)rest, len, &s, &err)) {
        char text[ILAHRS_PAHR_MAX_LENGTH + 1];
        ilahrs_pahr_t t;
        size_t k;
        size_t n = ilahrs_pahr_build(&s, text, sizeof text, &err);
        check(n > 0 && ilahrs_pahr_parse(text, n, &t, &err));
        for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
            check(ilahrs_pahr_field_get(&s, k) == ilahrs_pahr_field_get(&t, k));
        }
    } else {
        check(err.kind != ILAHRS_OK && (err.offset == ILAHRS_NO_OFFSET || err.offset <= len || err.offset == ILAHRS_PAHR_MAX_LENGTH));
    }
    return 0;
}
