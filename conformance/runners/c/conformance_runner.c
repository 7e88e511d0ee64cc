/*
 * Conformance runner for the C binding (generated/c): the line protocol of
 * conformance/README.md, nothing else. It parses a request, calls the library, and formats
 * its answer or its error. Every protocol fact comes from the library (payload, field,
 * command, variant and sentence-field tables reached through its reflection functions);
 * the runner knows only the request grammar. All test logic lives in conformance/harness.py.
 *
 * Implements every kind. `session` steps the library's state machine (ilahrs_transition_on()).
 * `stream` makes the idle calls of `idle=AFTER:US,...` (ilahrs_stream_idle()); `strict` decodes
 * strictly (ilahrs_frame_parse_strict(), ilahrs_stream_t.strict); any other option is refused.
 *
 * `--bytewise`: the stream kind feeds the decoder one byte at a time through
 * ilahrs_stream_push()/ilahrs_stream_poll() instead of ilahrs_stream_next() on whole chunks.
 */
#include "ilahrs.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int bytewise;

/* ---- Output ------------------------------------------------------------------------- */

typedef struct {
    char *data;
    size_t len;
    size_t cap;
} text_t;

static void out_reserve(text_t *t, size_t more)
{
    if (t->len + more + 1 > t->cap) {
        size_t cap = (t->len + more + 1) * 2;
        char *data = (char *)realloc(t->data, cap);
        if (data == NULL) {
            fputs("out of memory\n", stderr);
            exit(1);
        }
        t->data = data;
        t->cap = cap;
    }
}

static void out_str(text_t *t, const char *s)
{
    size_t n = strlen(s);
    out_reserve(t, n);
    memcpy(t->data + t->len, s, n + 1);
    t->len += n;
}

static void out_fmt(text_t *t, const char *fmt, long long value)
{
    char buf[64];
    snprintf(buf, sizeof buf, fmt, value);
    out_str(t, buf);
}

static void out_hex(text_t *t, const uint8_t *data, size_t n)
{
    static const char digits[] = "0123456789ABCDEF";
    size_t i;
    if (n == 0) {
        out_str(t, "-");
        return;
    }
    out_reserve(t, 2 * n);
    for (i = 0; i < n; i++) {
        t->data[t->len++] = digits[data[i] >> 4];
        t->data[t->len++] = digits[data[i] & 15];
    }
    t->data[t->len] = '\0';
}

static void out_text(text_t *t, const uint8_t *data, size_t n)
{
    size_t i;
    char buf[4];
    for (i = 0; i < n; i++) {
        uint8_t c = data[i];
        if (c >= 0x21 && c <= 0x7E && c != '%' && c != ',' && c != '=') {
            buf[0] = (char)c;
            buf[1] = '\0';
        } else {
            snprintf(buf, sizeof buf, "%%%02X", c);
        }
        out_str(t, buf);
    }
}

/* The shortest decimal text that reads back to the same double (like Python's repr). */
static void out_num(text_t *t, double value)
{
    char buf[64];
    int precision;
    if (isnan(value)) {
        out_str(t, "nan");
        return;
    }
    if (isinf(value)) {
        out_str(t, value > 0 ? "inf" : "-inf");
        return;
    }
    for (precision = 1; precision <= 17; precision++) {
        snprintf(buf, sizeof buf, "%.*g", precision, value);
        if (strtod(buf, NULL) == value) {
            break;
        }
    }
    out_str(t, buf);
}

static void out_error(text_t *t, const ilahrs_error_t *err)
{
    t->len = 0;
    out_str(t, "error ");
    out_str(t, ilahrs_error_kind_name(err->kind));
    if (err->offset == ILAHRS_NO_OFFSET) {
        out_str(t, " -");
    } else {
        out_fmt(t, " %lld", (long long)err->offset);
    }
    out_str(t, " ");
    out_str(t, err->field != NULL ? err->field : "-");
}

/* ---- Input tokens ------------------------------------------------------------------- */

typedef struct {
    uint8_t *data;
    size_t len;
} bytes_t;

static int hex_digit(int c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

/* HEX token ("-" for none); false if it is not hex. `out->data` is malloc'ed (never NULL). */
static int read_hex(const char *token, bytes_t *out)
{
    size_t n = strcmp(token, "-") == 0 ? 0 : strlen(token);
    size_t i;
    out->data = (uint8_t *)malloc(n / 2 + 1);
    out->len = 0;
    if (out->data == NULL || n % 2 != 0) {
        return 0;
    }
    for (i = 0; i < n; i += 2) {
        int hi = hex_digit(token[i]);
        int lo = hex_digit(token[i + 1]);
        if (hi < 0 || lo < 0) {
            return 0;
        }
        out->data[out->len++] = (uint8_t)(hi * 16 + lo);
    }
    return 1;
}

/* TEXT token: percent-decoding. */
static int read_text(const char *token, bytes_t *out)
{
    size_t n = strlen(token);
    size_t i;
    out->data = (uint8_t *)malloc(n + 1);
    out->len = 0;
    if (out->data == NULL) {
        return 0;
    }
    for (i = 0; i < n; i++) {
        if (token[i] == '%') {
            int hi = i + 1 < n ? hex_digit(token[i + 1]) : -1;
            int lo = i + 2 < n ? hex_digit(token[i + 2]) : -1;
            if (hi < 0 || lo < 0) {
                return 0;
            }
            out->data[out->len++] = (uint8_t)(hi * 16 + lo);
            i += 2;
        } else {
            out->data[out->len++] = (uint8_t)token[i];
        }
    }
    return 1;
}

/* INT token, saturating at the long long range (still refused by any field). */
static int read_int(const char *token, long long *value)
{
    char *end;
    errno = 0;
    *value = strtoll(token, &end, 10);
    return end != token && *end == '\0';
}

/* NUM token: a decimal number, nan, inf or -inf. */
static int read_num(const char *token, double *value)
{
    char *end;
    *value = strtod(token, &end);
    return end != token && *end == '\0';
}

static char *value_of(char *token, const char *key)
{
    size_t n = strlen(key);
    return strncmp(token, key, n) == 0 && token[n] == '=' ? token + n + 1 : NULL;
}

/* ---- Requests ----------------------------------------------------------------------- */

static void bad_request(text_t *t)
{
    t->len = 0;
    out_str(t, "invalid request");
}

/* The decoder options a request ends with (`strict`); false for any other token, so that a vector
 * with an option this runner does not know fails. */
static int read_options(char **args, int first, int nargs, bool *strict)
{
    int a;
    *strict = false;
    for (a = first; a < nargs; a++) {
        if (strcmp(args[a], "strict") != 0) {
            return 0;
        }
        *strict = true;
    }
    return 1;
}

static void do_checksum(text_t *t, char **args, int nargs)
{
    bytes_t b = { NULL, 0 };
    if (nargs != 1 || !read_hex(args[0], &b)) {
        bad_request(t);
    } else {
        out_fmt(t, "ok %lld", (long long)ilahrs_checksum(b.data, b.len));
    }
    free(b.data);
}

static void do_frame_decode(text_t *t, char **args, int nargs)
{
    bytes_t b = { NULL, 0 };
    ilahrs_frame_t frame;
    ilahrs_error_t err;
    bool strict;
    if (nargs < 1 || !read_options(args, 1, nargs, &strict) || !read_hex(args[0], &b)) {
        bad_request(t);
    } else if (!(strict ? ilahrs_frame_parse_strict : ilahrs_frame_parse)(b.data, b.len, &frame, &err)) {
        out_error(t, &err);
    } else {
        out_fmt(t, "ok message_type=%lld", (long long)frame.message_type);
        out_fmt(t, " reserved=%lld payload=", (long long)frame.reserved);
        out_hex(t, frame.payload, frame.payload_size);
    }
    free(b.data);
}

static void do_frame_encode(text_t *t, char **args, int nargs)
{
    bytes_t payload = { NULL, 0 };
    long long type = 0;
    long long reserved = 0;
    ilahrs_frame_t frame;
    ilahrs_error_t err;
    uint8_t out[ILAHRS_FRAME_MAX_SIZE];
    size_t n;
    if (nargs < 2 || nargs > 3 || !read_int(args[0], &type) || !read_hex(args[1], &payload)
        || (nargs == 3 && !read_int(args[2], &reserved))) {
        bad_request(t);
        return;
    }
    frame.payload = payload.data;
    frame.payload_size = payload.len;
    frame.reserved = 0;
    frame.message_type = (uint8_t)type;
    if (type < 0 || type > 0xFF) {
        /* Not even a byte: refused like any invalid type, so let the builder refuse one. */
        int v;
        for (v = 0; v <= 0xFF; v++) {
            frame.message_type = (uint8_t)v;
            if (ilahrs_frame_build(&frame, out, sizeof out, &err) == 0 && err.kind == ILAHRS_ERR_BAD_MESSAGE_TYPE) {
                break;
            }
        }
        out_error(t, &err);
    } else if (reserved < 0 || reserved > 0xFF) {
        /* The builder checks the type before the reserved byte. */
        if (ilahrs_frame_build(&frame, out, sizeof out, &err) == 0 && err.kind == ILAHRS_ERR_BAD_MESSAGE_TYPE) {
            out_error(t, &err);
        } else {
            err.kind = ILAHRS_ERR_OUT_OF_RANGE;
            err.offset = ILAHRS_NO_OFFSET;
            err.field = ILAHRS_FRAME_RESERVED_NAME;
            out_error(t, &err);
        }
    } else {
        frame.reserved = (uint8_t)reserved;
        n = ilahrs_frame_build(&frame, out, sizeof out, &err);
        if (n == 0) {
            out_error(t, &err);
        } else {
            out_str(t, "ok ");
            out_hex(t, out, n);
        }
    }
    free(payload.data);
}

static void do_command_encode(text_t *t, char **args, int nargs)
{
    ilahrs_command_t command;
    ilahrs_error_t err;
    uint8_t out[ILAHRS_FRAME_MAX_SIZE];
    size_t n;
    if (nargs != 1) {
        bad_request(t);
    } else if (!ilahrs_command_by_name(args[0], strlen(args[0]), &command, &err)
               || (n = ilahrs_command_build(command, out, sizeof out, &err)) == 0) {
        out_error(t, &err);
    } else {
        out_str(t, "ok ");
        out_hex(t, out, n);
    }
}

static void do_command_decode(text_t *t, char **args, int nargs)
{
    bytes_t b = { NULL, 0 };
    ilahrs_command_match_t match;
    ilahrs_error_t err;
    unsigned i;
    if (nargs != 1 || !read_hex(args[0], &b)) {
        bad_request(t);
    } else if (!ilahrs_command_decode(b.data, b.len, &match, &err)) {
        out_error(t, &err);
    } else {
        out_fmt(t, "ok code=%lld names=", (long long)match.code);
        for (i = 0; i < match.count; i++) {
            if (i > 0) {
                out_str(t, ",");
            }
            out_str(t, ilahrs_command_name(match.commands[i]));
        }
    }
    free(b.data);
}

static void do_ack(text_t *t, char **args, int nargs)
{
    bytes_t b = { NULL, 0 };
    ilahrs_error_t err;
    uint8_t out[ILAHRS_FRAME_MAX_SIZE];
    size_t n;
    if (nargs != 1 || !read_hex(args[0], &b)) {
        bad_request(t);
    } else if ((n = ilahrs_ack_build(b.data, b.len, out, sizeof out, &err)) == 0) {
        out_error(t, &err);
    } else {
        out_str(t, "ok ");
        out_hex(t, out, n);
    }
    free(b.data);
}

static int find_payload(const char *name, ilahrs_payload_t *payload)
{
    return ilahrs_payload_by_name(name, strlen(name), payload);
}

static void do_payload_decode(text_t *t, char **args, int nargs)
{
    ilahrs_payload_t payload;
    ilahrs_variant_t variant = ILAHRS_VARIANT_NONE;
    ilahrs_error_t err;
    bytes_t b = { NULL, 0 };
    void *value;
    size_t i;
    if (nargs < 2 || nargs > 3 || !find_payload(args[0], &payload) || !read_hex(args[1], &b)) {
        bad_request(t);
        return;
    }
    if (nargs == 3 && !ilahrs_variant_by_name(args[2], strlen(args[2]), &variant)) {
        bad_request(t);
        free(b.data);
        return;
    }
    value = calloc(1, ilahrs_payload_struct_size(payload));
    if (!ilahrs_payload_parse(payload, b.data, b.len, value, &err)) {
        out_error(t, &err);
    } else {
        out_str(t, "ok");
        for (i = 0; i < ilahrs_payload_field_count(payload); i++) {
            const ilahrs_field_info_t *f = ilahrs_payload_field(payload, i);
            const uint8_t *member = (const uint8_t *)ilahrs_field_member_const(f, value);
            size_t size = ilahrs_field_size(f);
            out_str(t, " f.");
            out_str(t, ilahrs_field_name(f));
            out_str(t, "=");
            switch (ilahrs_field_kind(f)) {
            case ILAHRS_KIND_UNSIGNED:
            case ILAHRS_KIND_SIGNED:
                out_fmt(t, "%lld", (long long)ilahrs_field_get_int(f, value));
                break;
            case ILAHRS_KIND_FLOAT:
                out_num(t, (double)ilahrs_field_get_float(f, value));
                break;
            case ILAHRS_KIND_CHAR:
                while (size > 0 && member[size - 1] == 0) {
                    size--;
                }
                out_text(t, member, size);
                break;
            case ILAHRS_KIND_RESERVED:
            default:
                out_hex(t, member, size);
                break;
            }
        }
        for (i = 0; i < ilahrs_payload_field_count(payload); i++) {
            const ilahrs_field_info_t *f = ilahrs_payload_field(payload, i);
            int32_t multiplier;
            int32_t divisor;
            double raw;
            if (!ilahrs_field_scale(f, variant, &multiplier, &divisor)) {
                continue;
            }
            raw = ilahrs_field_kind(f) == ILAHRS_KIND_FLOAT ? (double)ilahrs_field_get_float(f, value)
                                                            : (double)ilahrs_field_get_int(f, value);
            out_str(t, " v.");
            out_str(t, ilahrs_field_name(f));
            out_str(t, "=");
            out_num(t, raw * (double)multiplier / (double)divisor);
        }
    }
    free(value);
    free(b.data);
}

/*
 * A value the request gives that the field's C type cannot hold (an integer beyond the type,
 * a number outside the field's range before float32 rounding, text longer than the field,
 * reserved bytes of the wrong length) is refused as the builder would refuse it, at the same
 * place in table order: the earliest refused field wins.
 */
static void do_payload_encode(text_t *t, char **args, int nargs)
{
    ilahrs_payload_t payload;
    ilahrs_error_t early = { ILAHRS_OK, ILAHRS_NO_OFFSET, NULL };
    ilahrs_error_t err = { ILAHRS_OK, ILAHRS_NO_OFFSET, NULL };
    size_t early_index = (size_t)-1;
    size_t count;
    void *value;
    uint8_t *out;
    size_t size;
    size_t n;
    int a;
    if (nargs < 2 || !find_payload(args[0], &payload)) {
        bad_request(t);
        return;
    }
    count = ilahrs_payload_field_count(payload);
    size = ilahrs_payload_size(payload);
    value = calloc(1, ilahrs_payload_struct_size(payload));
    out = (uint8_t *)malloc(size);
    ilahrs_payload_defaults(payload, value);
    for (a = 2; a < nargs; a++) {
        char *eq = strchr(args[a], '=');
        const ilahrs_field_info_t *f = NULL;
        size_t i;
        int refused = 0;
        if (eq == NULL) {
            bad_request(t);
            goto done;
        }
        *eq = '\0';
        for (i = 0; i < count; i++) {
            if (strcmp(ilahrs_field_name(ilahrs_payload_field(payload, i)), args[a]) == 0) {
                f = ilahrs_payload_field(payload, i);
                break;
            }
        }
        if (f == NULL) {
            err.kind = ILAHRS_ERR_MALFORMED;
            err.offset = ILAHRS_NO_OFFSET;
            err.field = args[a];
            out_error(t, &err);
            goto done;
        }
        switch (ilahrs_field_kind(f)) {
        case ILAHRS_KIND_UNSIGNED:
        case ILAHRS_KIND_SIGNED: {
            long long v;
            if (!read_int(eq + 1, &v)) {
                bad_request(t);
                goto done;
            }
            refused = !ilahrs_field_set_int(f, value, (int64_t)v, &err);
            break;
        }
        case ILAHRS_KIND_FLOAT: {
            double v;
            if (!read_num(eq + 1, &v)) {
                bad_request(t);
                goto done;
            }
            refused = !ilahrs_field_check(f, v, &err);
            if (v > FLT_MAX) {
                v = (double)INFINITY;
            } else if (v < -FLT_MAX) {
                v = -(double)INFINITY;
            }
            (void)ilahrs_field_set_float(f, value, (float)v, NULL);
            break;
        }
        case ILAHRS_KIND_CHAR:
        case ILAHRS_KIND_RESERVED:
        default: {
            bytes_t b = { NULL, 0 };
            int ok = ilahrs_field_kind(f) == ILAHRS_KIND_CHAR ? read_text(eq + 1, &b) : read_hex(eq + 1, &b);
            uint8_t *member = (uint8_t *)ilahrs_field_member(f, value);
            if (!ok) {
                free(b.data);
                bad_request(t);
                goto done;
            }
            if (ilahrs_field_kind(f) == ILAHRS_KIND_CHAR ? b.len > ilahrs_field_size(f) : b.len != ilahrs_field_size(f)) {
                refused = 1;
                err.kind = ILAHRS_ERR_OUT_OF_RANGE;
                err.offset = ilahrs_field_offset(f);
                err.field = ilahrs_field_name(f);
            } else {
                memset(member, 0, ilahrs_field_size(f));
                memcpy(member, b.data, b.len);
            }
            free(b.data);
            break;
        }
        }
        if (refused && i < early_index) {
            early_index = i;
            early = err;
        }
    }
    n = ilahrs_payload_build(payload, value, out, size, &err);
    if (n == 0 || early_index != (size_t)-1) {
        size_t i;
        size_t built_index = count;
        for (i = 0; n == 0 && i < count; i++) {
            const ilahrs_field_info_t *f = ilahrs_payload_field(payload, i);
            if (err.field != NULL && strcmp(err.field, ilahrs_field_name(f)) == 0) {
                built_index = i;
                break;
            }
        }
        out_error(t, n == 0 && built_index < early_index ? &err : &early);
    } else {
        out_str(t, "ok ");
        out_hex(t, out, n);
    }
done:
    free(out);
    free(value);
}

static void do_nmea_decode(text_t *t, char **args, int nargs)
{
    bytes_t b = { NULL, 0 };
    ilahrs_pahr_t s;
    ilahrs_error_t err;
    size_t k;
    if (nargs != 1 || !read_text(args[0], &b)) {
        bad_request(t);
    } else if (!ilahrs_pahr_parse((const char *)b.data, b.len, &s, &err)) {
        out_error(t, &err);
    } else {
        out_str(t, "ok");
        for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
            uint32_t divisor = ilahrs_pahr_field_divisor(k);
            out_str(t, " ");
            out_str(t, ilahrs_pahr_field_name(k));
            out_str(t, "=");
            if (divisor == 0) {
                out_fmt(t, "%lld", (long long)ilahrs_pahr_field_get(&s, k));
            } else {
                out_num(t, (double)ilahrs_pahr_field_get(&s, k) / (double)divisor);
            }
        }
    }
    free(b.data);
}

static void do_nmea_encode(text_t *t, char **args, int nargs)
{
    double values[ILAHRS_PAHR_FIELD_COUNT];
    ilahrs_pahr_t s;
    ilahrs_error_t err;
    char out[ILAHRS_PAHR_MAX_LENGTH + 1];
    size_t n;
    size_t k;
    int a;
    for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
        values[k] = 0.0;
    }
    for (a = 0; a < nargs; a++) {
        int found = 0;
        for (k = 0; k < ILAHRS_PAHR_FIELD_COUNT; k++) {
            char *v = value_of(args[a], ilahrs_pahr_field_name(k));
            if (v != NULL) {
                found = read_num(v, &values[k]);
                break;
            }
        }
        if (!found) {
            bad_request(t);
            return;
        }
    }
    if (!ilahrs_pahr_from_array(values, &s, &err) || (n = ilahrs_pahr_build(&s, out, sizeof out, &err)) == 0) {
        out_error(t, &err);
    } else {
        out_str(t, "ok ");
        out_text(t, (const uint8_t *)out, n);
    }
}

static void add_event(text_t *events, const ilahrs_message_t *msg, size_t *count)
{
    if (*count > 0) {
        out_str(events, ",");
    }
    (*count)++;
    if (msg->kind == ILAHRS_MESSAGE_FRAME) {
        out_str(events, "F:");
        out_hex(events, msg->data, msg->size);
    } else {
        out_str(events, "N:");
        out_text(events, msg->data, msg->size);
    }
}

/* The idle calls of a stream request, `idle=AFTER:US,...`: after chunk AFTER, US microseconds of
 * quiet line. */
typedef struct {
    unsigned long long after;
    unsigned long long us;
} idle_t;

static int read_idle(char *token, idle_t *idle, size_t cap, size_t *count)
{
    const char *p = value_of(token, "idle");
    *count = 0;
    while (p != NULL && *count < cap) {
        char *end;
        if (*p < '0' || *p > '9') {
            return 0;
        }
        idle[*count].after = strtoull(p, &end, 10);
        if (*end != ':' || end[1] < '0' || end[1] > '9') {
            return 0;
        }
        errno = 0;
        idle[*count].us = strtoull(end + 1, &end, 10);
        if (errno != 0 || idle[*count].us > UINT32_MAX || (*end != ',' && *end != '\0')) {
            return 0;
        }
        (*count)++;
        if (*end == '\0') {
            return 1;
        }
        p = end + 1;
    }
    return 0;
}

static void do_stream(text_t *t, char **args, int nargs)
{
    ilahrs_stream_t decoder;
    ilahrs_message_t msg;
    text_t events = { NULL, 0, 0 };
    size_t count = 0;
    char *chunk;
    idle_t idle[64];
    size_t idles = 0;
    size_t index;
    bool strict;
    int options = nargs >= 2 && strncmp(args[1], "idle=", 5) == 0 ? 2 : 1;
    if (nargs < 1 || (options == 2 && !read_idle(args[1], idle, sizeof idle / sizeof idle[0], &idles))
        || !read_options(args, options, nargs, &strict)) {
        bad_request(t);
        return;
    }
    ilahrs_stream_init(&decoder);
    decoder.strict = strict;
    out_str(&events, "");
    for (chunk = strtok(args[0], ","), index = 0; chunk != NULL; chunk = strtok(NULL, ","), index++) {
        bytes_t b = { NULL, 0 };
        size_t k;
        if (!read_hex(chunk, &b)) {
            free(b.data);
            free(events.data);
            bad_request(t);
            return;
        }
        if (bytewise) {
            size_t i;
            for (i = 0; i < b.len; i++) {
                if (ilahrs_stream_push(&decoder, b.data[i], &msg)) {
                    do {
                        add_event(&events, &msg, &count);
                    } while (ilahrs_stream_poll(&decoder, &msg));
                }
            }
        } else {
            const uint8_t *p = b.data;
            size_t n = b.len;
            while (ilahrs_stream_next(&decoder, &p, &n, &msg)) {
                add_event(&events, &msg, &count);
            }
        }
        free(b.data);
        for (k = 0; k < idles; k++) {
            if (idle[k].after == index) {
                while (ilahrs_stream_idle(&decoder, (uint32_t)idle[k].us, &msg)) {
                    add_event(&events, &msg, &count);
                }
            }
        }
    }
    while (ilahrs_stream_finish(&decoder, &msg)) {
        add_event(&events, &msg, &count);
    }
    for (; idles > 0; idles--) {
        if (idle[idles - 1].after >= index) { /* after no chunk */
            free(events.data);
            bad_request(t);
            return;
        }
    }
    out_fmt(t, "ok discarded=%lld events=", (long long)decoder.discarded);
    out_str(t, count > 0 ? events.data : "-");
    free(events.data);
}

/* One session input: `C:HH` (a command frame with code 0xHH), `D:N` (a data message with an
 * N-byte payload) or `E:NAME` (another event), as the table's event in `state`. */
static int session_event(const char *token, ilahrs_state_t state, ilahrs_event_t *event)
{
    long long number;
    if (strncmp(token, "C:", 2) == 0) {
        bytes_t b = { NULL, 0 };
        int ok = read_hex(token + 2, &b) && b.len == 1;
        if (ok) {
            *event = ilahrs_event_for_code(state, b.data[0]);
        }
        free(b.data);
        return ok;
    }
    if (strncmp(token, "D:", 2) == 0) {
        if (!read_int(token + 2, &number) || number < 0) {
            return 0;
        }
        *event = ilahrs_event_for_data(state, (size_t)number);
        return 1;
    }
    return strncmp(token, "E:", 2) == 0 && ilahrs_event_by_name(token + 2, strlen(token + 2), event);
}

static void do_session(text_t *t, char **args, int nargs)
{
    ilahrs_firmware_t firmware;
    ilahrs_error_t err;
    const ilahrs_firmware_t *version = NULL;
    ilahrs_state_t state = ILAHRS_STATE_INITIAL;
    size_t count = 0;
    char *token;
    if (nargs != 2) {
        bad_request(t);
        return;
    }
    if (strcmp(args[0], "-") != 0) {
        if (!ilahrs_firmware_parse(args[0], strlen(args[0]), &firmware, &err)) {
            out_error(t, &err);
            return;
        }
        version = &firmware;
    }
    out_str(t, "ok steps=");
    for (token = strtok(args[1], ","); token != NULL; token = strtok(NULL, ",")) {
        ilahrs_event_t event;
        ilahrs_step_t step;
        uint8_t i;
        if (!session_event(token, state, &event)) {
            bad_request(t);
            return;
        }
        (void)ilahrs_transition_on(state, event, version, &step);
        state = step.to;
        out_str(t, count++ > 0 ? "," : "");
        out_str(t, ilahrs_event_name(event));
        out_str(t, ">");
        out_str(t, ilahrs_state_name(state));
        out_str(t, ">");
        for (i = 0; i < step.send_count; i++) {
            out_str(t, i > 0 ? "+" : "");
            out_str(t, ilahrs_answer_name(step.send[i]));
        }
        out_str(t, step.send_count == 0 ? "-" : "");
    }
}

typedef struct {
    const char *kind;
    void (*run)(text_t *, char **, int);
} handler_t;

static const handler_t handlers[] = {
    { "checksum", do_checksum },           { "frame_decode", do_frame_decode },
    { "frame_encode", do_frame_encode },   { "command_encode", do_command_encode },
    { "command_decode", do_command_decode }, { "ack", do_ack },
    { "payload_decode", do_payload_decode }, { "payload_encode", do_payload_encode },
    { "nmea_decode", do_nmea_decode },     { "nmea_encode", do_nmea_encode },
    { "stream", do_stream },               { "session", do_session },
};

/* One request line (modified in place) -> one answer. */
static void answer(char *line, text_t *t)
{
    char *args[4096];
    int nargs = 0;
    char *kind = line;
    char *p = strchr(line, ' ');
    size_t i;
    if (p != NULL) {
        *p++ = '\0';
        while (p != NULL && nargs < (int)(sizeof args / sizeof args[0])) {
            args[nargs++] = p;
            p = strchr(p, ' ');
            if (p != NULL) {
                *p++ = '\0';
            }
        }
    }
    for (i = 0; i < sizeof handlers / sizeof handlers[0]; i++) {
        if (strcmp(kind, handlers[i].kind) == 0) {
            handlers[i].run(t, args, nargs);
            return;
        }
    }
    out_str(t, "unsupported");
}

int main(int argc, char **argv)
{
    text_t line = { NULL, 0, 0 };
    text_t reply = { NULL, 0, 0 };
    int c;
    bytewise = argc > 1 && strcmp(argv[1], "--bytewise") == 0;
    for (;;) {
        line.len = 0;
        out_str(&line, "");
        while ((c = getchar()) != EOF && c != '\n') {
            out_reserve(&line, 1);
            line.data[line.len++] = (char)c;
            line.data[line.len] = '\0';
        }
        if (c == EOF && line.len == 0) {
            break;
        }
        if (line.len > 0 && line.data[line.len - 1] == '\r') {
            line.data[--line.len] = '\0';
        }
        reply.len = 0;
        out_str(&reply, "");
        answer(line.data, &reply);
        fputs(reply.data, stdout);
        fputc('\n', stdout);
        fflush(stdout);
    }
    free(line.data);
    free(reply.data);
    return 0;
}
